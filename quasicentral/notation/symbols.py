"""Symbols of a text: a table the text declares, and the functions every text may use.

A text (``text.toml`` in its folder) declares each symbol it writes — its name in the
transcriptions, its LaTeX, its dimension, where it is sampled and its assumptions — and each
function of one independent variable (``x(t)``, ``u(theta)``).  :class:`SymbolTable` holds them;
a transcription is read in the table's namespace, where an unknown name is an error.

The notation shared by all texts:

* ``D(f)`` is df/dv and ``D(f, 2)`` d²f/dv² in the function's own variable v, unevaluated (a
  transcription keeps what was printed); ``D(f, 1, v)`` names the variable where an
  expression has several.
* Elliptic integrals in Jacobi's form take the **modulus** k and the *sine* of the amplitude ζ:
  ``Fj(k, zeta) = F(asin ζ | k²)``, ``Ej(k, zeta) = E(asin ζ | k²)``; complete ones
  ``Kc(k) = K(k²)``, ``Ec(k) = E(k²)``.  sympy, mpmath, scipy and python-flint take the
  **parameter** m = k², which these wrappers pass on.
* ``arccotg`` is the Czech arccotangent with values in (0, π): arccotg x = π/2 − atan x.
* Dimensions are monomials in the base dimensions L (length), T (time), M (mass), written
  ``"L^2/T"``; they are sympy symbols of their own, so a text may also name a symbol L, T or M.
"""

from __future__ import annotations

import keyword
import re
from dataclasses import dataclass, field
from functools import lru_cache

import sympy as sp

# --- base dimensions (symbols no transcription can name) ----------------------------------------
DIM_L, DIM_T, DIM_M = sp.symbols("[L] [T] [M]", positive=True)
DIMENSIONLESS = sp.Integer(1)
_DIM_NAMES = {"L": DIM_L, "T": DIM_T, "M": DIM_M}


class SymbolError(ValueError):
    """A symbol table, a dimension or a transcription that cannot be read."""


@lru_cache(maxsize=512)  # a text spells a few dimensions hundreds of times; sympify costs ~0.3 ms each
def parse_dim(text: str) -> sp.Expr:
    """``'L^2/T'`` → L²/T in the base dimensions; ``'1'`` → 1.

    >>> parse_dim("L^2/T")
    [L]**2/[T]
    """
    text = str(text).strip()
    if not re.fullmatch(r"[LTM0-9^*/() .+-]+", text):
        raise SymbolError(f"dimension {text!r}: write a monomial in L, T, M such as 'L^2/T' or '1'")
    try:
        out = sp.sympify(text.replace("^", "**"), locals=dict(_DIM_NAMES))
    except (sp.SympifyError, SyntaxError, TypeError) as exc:
        raise SymbolError(f"dimension {text!r}: {exc}") from None
    if not isinstance(out, sp.Expr) or out.free_symbols - set(_DIM_NAMES.values()):
        raise SymbolError(f"dimension {text!r}: write a monomial in L, T, M")
    return out


def dim_text(d: sp.Expr) -> str:
    """The inverse of :func:`parse_dim`, for messages: L²/T → ``'L^2/T'``."""
    return sp.sstr(d).replace("**", "^").replace("[", "").replace("]", "")


# --- notation shared by every text ---------------------------------------------------------------
def D(f, order: int = 1, var=None):
    """d^order f / dv^order, unevaluated; v is f's own variable unless given."""
    if var is None:
        variables = {a.args[0] for a in sp.sympify(f).atoms(sp.core.function.AppliedUndef)
                     if len(a.args) == 1 and isinstance(a.args[0], sp.Symbol)}
        if len(variables) != 1:
            raise SymbolError(f"D({f}): name the variable, D(f, order, v), where it is not one function's")
        var = variables.pop()
    return sp.Derivative(f, (var, order))


def Fj(kk, zz):
    """F(k, ζ) = ∫₀^ζ dζ/√((1−ζ²)(1−k²ζ²)) = F(asin ζ | m = k²)  (Jacobi form, modulus k)."""
    return sp.elliptic_f(sp.asin(zz), kk**2)


def Ej(kk, zz):
    """E(k, ζ) = ∫₀^ζ √((1−k²ζ²)/(1−ζ²)) dζ = E(asin ζ | m = k²)."""
    return sp.elliptic_e(sp.asin(zz), kk**2)


def Kc(kk):
    """K = F(k, 1) = K(m = k²), the complete integral of the first kind, modulus k."""
    return sp.elliptic_k(kk**2)


def Ec(kk):
    """E = E(k, 1) = E(m = k²), the complete integral of the second kind, modulus k."""
    return sp.elliptic_e(kk**2)


def arccotg(a):
    """Czech arccotg with values in (0, π): π/2 − atan a."""
    return sp.pi / 2 - sp.atan(a)


def printed_eq(lhs, rhs, evaluate: bool = False):
    """An equation as printed: sympy does not decide it (``Eq`` would ask whether lhs − rhs is
    zero — an assumption query on the whole difference, about 6 % of a verification's function
    calls — and turn x = x into True).  Two sides that are one expression, or two numbers, are
    still decided where the comparison begins (:func:`quasicentral.engine.checker.decided`)."""
    return sp.Eq(lhs, rhs, evaluate=evaluate)


#: Functions and constants every transcription may use (a text's symbols come on top).
FUNCTIONS: dict[str, object] = {
    "D": D, "Fj": Fj, "Ej": Ej, "Kc": Kc, "Ec": Ec, "arccotg": arccotg,
    "Eq": printed_eq, "Integral": sp.Integral, "Derivative": sp.Derivative, "Sum": sp.Sum,
    "sqrt": sp.sqrt, "sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "cot": sp.cot, "exp": sp.exp,
    "log": sp.log, "ln": sp.log, "asin": sp.asin, "acos": sp.acos, "atan": sp.atan,
    "sinh": sp.sinh, "cosh": sp.cosh, "tanh": sp.tanh, "pi": sp.pi, "oo": sp.oo, "I": sp.I,
    "Rational": sp.Rational, "factorial": sp.factorial, "factorial2": sp.factorial2,
    "elliptic_k": sp.elliptic_k, "elliptic_f": sp.elliptic_f, "elliptic_e": sp.elliptic_e,
    "Abs": sp.Abs,
}
ASSUMPTIONS = ("positive", "nonnegative", "negative", "nonpositive", "real", "integer", "complex")


@dataclass(frozen=True)
class SymbolSpec:
    """One declared name: a symbol, or a function of one variable (``variable`` set)."""

    name: str
    obj: sp.Basic  # the Symbol, or the applied function f(v)
    latex: str
    dimension: sp.Expr | None  # None: not declared (dimension checks are then inconclusive)
    range: tuple[sp.Expr, sp.Expr] | None = None
    definition: sp.Expr | None = None
    dots: bool = False  # derivatives in this variable print as Newton dots
    variable: str | None = None
    meaning: str = ""


@dataclass(frozen=True, eq=False)
class SymbolTable:
    """The symbols a text declares, in declaration order.

    ``table.rho`` is the object declared as ``rho``; ``table("x y t")`` a tuple of several.
    """

    specs: tuple[SymbolSpec, ...]
    by_name: dict[str, SymbolSpec] = field(default_factory=dict, repr=False)

    def __post_init__(self):
        self.by_name.update({s.name: s for s in self.specs})

    def __getattr__(self, name: str):
        spec = self.__dict__.get("by_name", {}).get(name)
        if spec is None:
            raise AttributeError(f"no symbol {name!r} is declared")
        return spec.obj

    def __call__(self, names: str) -> tuple:
        return tuple(getattr(self, n) for n in names.replace(",", " ").split())

    def __contains__(self, name: str) -> bool:
        return name in self.by_name

    @property
    def namespace(self) -> dict[str, object]:
        return {**FUNCTIONS, **{s.name: s.obj for s in self.specs}}

    @property
    def dims(self) -> dict[sp.Basic, sp.Expr]:
        return {s.obj: s.dimension for s in self.specs if s.dimension is not None}

    @property
    def ranges(self) -> dict[sp.Basic, tuple[sp.Expr, sp.Expr]]:
        return {s.obj: s.range for s in self.specs if s.range is not None}

    @property
    def definitions(self) -> dict[sp.Basic, sp.Expr]:
        return {s.obj: s.definition for s in self.specs if s.definition is not None}

    @property
    def latex_names(self) -> dict[sp.Basic, str]:
        """Symbol (or function head's name) → its declared LaTeX."""
        out: dict = {}
        for s in self.specs:
            out[s.obj] = s.latex
            if s.variable is not None:
                out[s.obj.func] = s.latex
        return out

    @property
    def dotted(self) -> frozenset:
        """The variables whose derivatives print as Newton dots (time)."""
        return frozenset(s.obj for s in self.specs if s.dots)

    @property
    def variables(self) -> frozenset:
        """The independent variables of the declared functions."""
        return frozenset(s.obj.args[0] for s in self.specs if s.variable is not None)

    def names_of(self, objs) -> list[str]:
        rev = {s.obj: s.name for s in self.specs}
        return [rev.get(o, str(o)) for o in objs]

    def check_names(self, text: str) -> None:
        """Refuse a transcription that uses a name this table does not declare."""
        unknown = _unknown_names(text, self.namespace)
        if unknown:
            raise SymbolError(f"unknown name{'s' if len(unknown) > 1 else ''} {', '.join(unknown)} "
                              "(declare it in text.toml)")

    def parse(self, text: str) -> sp.Basic:
        """Read a transcription (sympy syntax) in this table's namespace, without evaluation
        of derivatives or integrals; an unknown name is an error, not a fresh symbol."""
        from sympy.parsing.sympy_parser import auto_number, parse_expr

        self.check_names(text)
        return parse_expr(text, local_dict=self.namespace, transformations=(auto_number,),
                          global_dict={"__builtins__": {}, **_GLOBALS}, evaluate=True)


_GLOBALS = {"Integer": sp.Integer, "Float": sp.Float, "Symbol": sp.Symbol, "Rational": sp.Rational,
            "Function": sp.Function}
_KEYWORD_ARGUMENTS = {"evaluate"}  # sin(x, evaluate=False) keeps a printed form


def _unknown_names(text: str, namespace: dict) -> list[str]:
    import io
    import tokenize

    names = []
    previous = None
    try:
        for tok in tokenize.generate_tokens(io.StringIO(text).readline):
            if tok.type == tokenize.NAME and not keyword.iskeyword(tok.string) and previous != ".":
                if (tok.string not in namespace and tok.string not in _GLOBALS
                        and tok.string not in _KEYWORD_ARGUMENTS and tok.string not in names):
                    names.append(tok.string)
            previous = tok.string if tok.type == tokenize.OP else None
    except (tokenize.TokenError, IndentationError, SyntaxError):
        return []  # the parser reports the syntax error itself
    return names


# --- reading a table from text.toml ------------------------------------------------------------
_IDENT = re.compile(r"[A-Za-z][A-Za-z0-9_]*\Z")
_SYMBOL_KEYS = {"latex", "dimension", "assumptions", "range", "definition", "dots", "meaning"}
_FUNCTION_KEYS = {"latex", "dimension", "assumptions", "variable", "meaning"}


def table_from_toml(data: dict, where: str) -> SymbolTable:
    """Build the table of ``[symbols.NAME]`` and ``[functions.NAME]`` tables (see
    derivations/FORMAT.md); every error names ``where`` and the key."""
    symbols = data.get("symbols", {})
    functions = data.get("functions", {})
    if not isinstance(symbols, dict) or not isinstance(functions, dict):
        raise SymbolError(f"{where}: [symbols] and [functions] are tables of tables")
    specs: list[SymbolSpec] = []
    objs: dict[str, sp.Basic] = {}
    for name, raw in symbols.items():
        key = f"{where}: symbols.{name}"
        _check_entry(name, raw, _SYMBOL_KEYS, key)
        objs[name] = sp.Symbol(name, **_assumptions(raw.get("assumptions", ["real"]), key))
    for name, raw in functions.items():
        key = f"{where}: functions.{name}"
        _check_entry(name, raw, _FUNCTION_KEYS, key)
        if name in objs:
            raise SymbolError(f"{key}: {name} is declared as a symbol too")
        var = raw.get("variable")
        if not isinstance(var, str) or var not in objs:
            raise SymbolError(f"{key}: 'variable' must name a declared symbol, not {var!r}")
        head = sp.Function(name, **_assumptions(raw.get("assumptions", ["real"]), key))
        objs[name] = head(objs[var])
    ns = {**FUNCTIONS, **objs}
    for name, raw in symbols.items():
        key = f"{where}: symbols.{name}"
        rng = definition = None
        if "range" in raw:
            r = raw["range"]
            if not (isinstance(r, list) and len(r) == 2):
                raise SymbolError(f"{key}.range: a pair [low, high], such as [\"0\", \"1\"]")
            rng = tuple(_expr(str(e), ns, f"{key}.range") for e in r)
        if "definition" in raw:
            if rng is not None:
                raise SymbolError(f"{key}: a defined symbol has no range of its own")
            definition = _expr(str(raw["definition"]), ns, f"{key}.definition")
        specs.append(SymbolSpec(name, objs[name], _latex(raw, name, key), _dimension(raw, key), rng,
                                definition, bool(raw.get("dots", False)), None, str(raw.get("meaning", ""))))
    for name, raw in functions.items():
        key = f"{where}: functions.{name}"
        specs.append(SymbolSpec(name, objs[name], _latex(raw, name, key), _dimension(raw, key),
                                variable=raw["variable"], meaning=str(raw.get("meaning", ""))))
    return SymbolTable(tuple(specs))


def _check_entry(name, raw, allowed, key):
    if not _IDENT.match(name) or keyword.iskeyword(name):
        raise SymbolError(f"{key}: a name is a letter followed by letters, digits or _")
    if name in FUNCTIONS or name in _GLOBALS:
        raise SymbolError(f"{key}: {name} is a function of the notation (choose another name)")
    if not isinstance(raw, dict):
        raise SymbolError(f"{key}: a table such as {{ latex = '...', dimension = 'L' }}")
    unknown = set(raw) - allowed
    if unknown:
        raise SymbolError(f"{key}: unknown key(s) {', '.join(sorted(unknown))}")


def _assumptions(names, key) -> dict:
    if not isinstance(names, list) or any(a not in ASSUMPTIONS for a in names):
        raise SymbolError(f"{key}.assumptions: a list from {', '.join(ASSUMPTIONS)}")
    return {a: True for a in names}


def _latex(raw, name, key) -> str:
    tex = raw.get("latex", name)
    if not isinstance(tex, str) or not tex.strip():
        raise SymbolError(f"{key}.latex: a LaTeX string such as '\\varrho'")
    return tex.strip()


def _dimension(raw, key):
    if "dimension" not in raw:
        return None
    try:
        return parse_dim(str(raw["dimension"]))
    except SymbolError as exc:
        raise SymbolError(f"{key}.dimension: {exc}") from None


def _expr(text: str, ns: dict, key: str) -> sp.Expr:
    from sympy.parsing.sympy_parser import auto_number, parse_expr

    unknown = _unknown_names(text, ns)
    if unknown:
        raise SymbolError(f"{key}: unknown name {unknown[0]}")
    try:
        return parse_expr(text, local_dict=dict(ns), transformations=(auto_number,),
                          global_dict={"__builtins__": {}, **_GLOBALS})
    except Exception as exc:  # noqa: BLE001 - any parse failure is a malformed table
        raise SymbolError(f"{key}: cannot read {text!r}: {exc}") from None
