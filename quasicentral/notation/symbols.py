"""Symbols of a text: a table the text declares, and the functions every text may use.

A text (``text.toml`` in its folder) declares each symbol it writes — its name in the
transcriptions, its LaTeX, its dimension, where it is sampled and its assumptions — and each
function of one or more independent variables (``x(t)``, ``u(nu, T)``).  :class:`SymbolTable`
holds them; a transcription is read in the table's namespace by the safe reader of
:mod:`quasicentral.notation.transcription`, where an unknown name is an error.

The notation shared by all texts:

* ``D(f)`` is df/dv and ``D(f, 2)`` d²f/dv² in the function's own variable v, unevaluated (a
  transcription keeps what was printed); ``D(f, 1, v)`` names the variable where an
  expression has several (a function of several variables: its partial derivative).
* Elliptic integrals in Jacobi's form take the **modulus** k and the *sine* of the amplitude ζ:
  ``Fj(k, zeta) = F(asin ζ | k²)``, ``Ej(k, zeta) = E(asin ζ | k²)``; complete ones
  ``Kc(k) = K(k²)``, ``Ec(k) = E(k²)``.  sympy, mpmath, scipy and python-flint take the
  **parameter** m = k², which these wrappers pass on.
* ``arccotg`` is the Czech arccotangent with values in (0, π): arccotg x = π/2 − atan x.
* ``Approx(x, 4.965114)`` is a printed rounding: it holds when x rounds to the digits shown.
* Dimensions (:mod:`quasicentral.notation.units`) are monomials in the seven SI base
  dimensions, symbols of their own, so a text may also name a symbol L, T or M.
"""

from __future__ import annotations

import keyword
import re
from dataclasses import dataclass, field
from types import MappingProxyType

import sympy as sp

from quasicentral.notation import transcription
from quasicentral.notation.special import FUNCTIONS as SPECIAL_FUNCTIONS
from quasicentral.notation.roots import Root
from quasicentral.notation.units import DIMENSIONLESS, UnitError, dim_text, parse_dim  # noqa: F401 - re-exported


class SymbolError(ValueError):
    """A symbol table, a dimension or a transcription that cannot be read."""


# --- notation shared by every text ---------------------------------------------------------------
def D(f, order: int = 1, var=None):
    """d^order f / dv^order, unevaluated; v is f's own variable unless given."""
    if var is None:
        variables = {x for a in sp.sympify(f).atoms(sp.core.function.AppliedUndef) for x in a.args
                     if isinstance(x, sp.Symbol)}
        if len(variables) != 1:
            raise SymbolError(f"D({f}): name the variable, D(f, order, v), where it is not one function's")
        var = variables.pop()
    if not (isinstance(order, (int, sp.Integer)) and 0 <= int(order) <= 20):
        raise SymbolError(f"D({f}, {order}): the order is a whole number from 0 to 20")
    return sp.Derivative(f, (var, int(order)))


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


class Approx(sp.Function):
    """A printed rounding: ``Approx(x, value, places)`` holds when x rounds to ``value`` at
    ``places`` decimal places (a transcription writes ``Approx(x, 4.965114)``: the places are
    the digits printed).  A formula with printed decimals, ``Approx(theta, 1.22*lam/D)``, has
    for ``places`` a tuple of (decimal, places) pairs: it holds where x lies within what
    rounding those decimals allows (:meth:`window`)."""

    nargs = 3

    @property
    def is_formula(self) -> bool:
        """A formula with printed decimals (not one printed number)."""
        return isinstance(self.args[2], sp.Tuple)

    def equation(self) -> sp.Eq:
        """x = value, as printed (its dimensions are the rounding's)."""
        return sp.Eq(self.args[0], self.args[1], evaluate=False)

    def window(self) -> tuple[sp.Expr, sp.Expr]:
        """A formula's rounding as (|x − value|, Σᵢ hᵢ·|∂value/∂cᵢ|): cᵢ each decimal printed,
        hᵢ half a unit of its last place (1.22: 0.005) — x must lie where the value lands when
        each decimal moves within its rounding (to first order, which is exact for a decimal
        coefficient).  A decimal sympy folded with another number (2·0.443 is 0.886) is no
        longer found in the value: there its relative half-unit is taken of the whole value."""
        x, value, places = self.args
        allowed = sp.Integer(0)
        for c, p in places:
            half = sp.Rational(1, 2) / sp.Integer(10) ** int(p)
            atom = sp.Dummy("c")
            # moved where it stands alone only: 2.0·x² holds the 2 twice, and the exponent's
            # derivative would widen the allowance (the whole value's relative half-unit then)
            swapped = value.xreplace({c: atom}) if c != 0 and value.count(c) == 1 else value
            if atom in swapped.free_symbols:
                allowed += half * sp.Abs(sp.diff(swapped, atom).xreplace({atom: c}))
            else:
                allowed += half / abs(c) * sp.Abs(value) if c != 0 else half
        return sp.Abs(x - value), allowed

    def _latex(self, printer):
        return rf"{printer._print(self.args[0])} \approx {printer._print(self.args[1])}"


def _approx(expr, value, places=None):
    """``Approx`` as a transcription writes it: the printed decimal's places are counted by the
    reader (:data:`APPROX_PLACES`)."""
    if places is None:
        raise SymbolError("Approx(x, value): value is a printed decimal such as 4.965114, or a formula "
                          "with one such as 1.22*lam/D")
    return Approx(expr, value, places)


_approx.places_of = 1  # the reader passes the decimal places printed in the second argument


class Landau(sp.Function):
    """An O-term as printed: ``Landau(g, x, x0)`` is "a quantity bounded by a constant times |g|
    as x → x0".  Kept verbatim — sympy's own ``Order`` absorbs the terms of a sum it thinks
    smaller (and asks every function for its leading term), which would change what the text
    states; the checker decides a relation with O-terms along a sequence x → x0."""

    nargs = 3

    def _latex(self, printer):
        return rf"O\left({printer._print(self.args[0])}\right)"


def _landau(expr, *passage):
    """``O(g, (x, x0))`` as a transcription writes it (sympy's spelling); ``O(g)`` alone is the
    passage to 0 of g's one symbol."""
    if len(passage) == 1 and isinstance(passage[0], sp.Tuple) and len(passage[0]) == 2:
        var, point = passage[0]
    elif not passage and len(sp.sympify(expr).free_symbols) == 1:
        (var,), point = sp.sympify(expr).free_symbols, sp.Integer(0)
    else:
        raise SymbolError("O(g, (x, x0)): an O-term names its variable and the point it tends to")
    if not isinstance(var, sp.Symbol):
        raise SymbolError(f"O(g, (x, x0)): {var} is not a symbol")
    return Landau(expr, var, point)


def _limit(expr, var, point, dir="+-"):  # noqa: A002 - sympy's own keyword
    """``Limit(f, x, x0)`` as a physicist writes it: **two-sided** (sympy's own default is from
    the right); ``Limit(f, x, x0, "+")`` or ``"-"`` is one-sided, as written.  Towards ±∞ the
    side is the only one there is."""
    if str(dir) not in ("+", "-", "+-"):
        raise SymbolError(f"Limit(f, x, x0, side): the side is '+', '-' or '+-', not {dir!r}")
    return sp.Limit(expr, var, point, dir=str(dir))


def _symbol(name):
    if not (isinstance(name, str) and re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", name)):
        raise SymbolError(f"Symbol({name!r}): a name is a letter followed by letters, digits or _")
    return sp.Symbol(name)


def _function(name):
    if not (isinstance(name, str) and re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", name)):
        raise SymbolError(f"Function({name!r}): a name is a letter followed by letters, digits or _")
    return sp.Function(name)


_ELEMENTARY = ("sqrt", "cbrt", "root", "exp", "log", "sin", "cos", "tan", "cot", "sec", "csc", "asin", "acos",
               "atan", "acot", "asec", "acsc", "atan2", "sinh", "cosh", "tanh", "coth", "sech", "csch", "asinh",
               "acosh", "atanh", "acoth", "Abs", "sign", "floor", "ceiling", "frac", "re", "im", "arg", "conjugate",
               "Min", "Max", "Mod", "Heaviside", "DiracDelta", "KroneckerDelta", "Piecewise", "sinc")
_SPECIAL = ("factorial", "factorial2", "binomial", "gamma", "loggamma", "lowergamma", "uppergamma", "digamma",
            "polygamma", "beta", "RisingFactorial", "FallingFactorial", "rf", "ff", "zeta", "polylog", "lerchphi",
            "dirichlet_eta", "LambertW", "erf", "erfc", "erfi", "erfinv", "erfcinv", "Ei", "expint", "E1", "li",
            "Li", "Si", "Ci", "Shi", "Chi", "fresnels", "fresnelc", "besselj", "bessely", "besseli", "besselk",
            "hankel1", "hankel2", "jn", "yn", "airyai", "airybi", "airyaiprime", "airybiprime", "hyper", "meijerg",
            "appellf1", "legendre", "assoc_legendre", "hermite", "laguerre", "assoc_laguerre", "chebyshevt", "chebyshevu",
            "gegenbauer", "jacobi", "Ynm", "elliptic_k", "elliptic_f", "elliptic_e", "elliptic_pi", "bernoulli",
            "harmonic")
_FORMS = ("Sum", "Product", "Integral", "Derivative", "Limit", "Subs", "Eq", "Ne", "Lt", "Le",
          "Gt", "Ge", "And", "Or", "Not", "Rational", "Integer", "Tuple")
_CONSTANTS = MappingProxyType({"pi": sp.pi, "E": sp.E, "I": sp.I, "oo": sp.oo, "EulerGamma": sp.EulerGamma,
              "GoldenRatio": sp.GoldenRatio, "Catalan": sp.Catalan})

#: Functions and constants every transcription may use (a text's symbols come on top): sympy's
#: own by their sympy names, and the notation's.  Read-only.
FUNCTIONS: MappingProxyType = MappingProxyType({
    **{name: getattr(sp, name) for name in _ELEMENTARY + _SPECIAL + _FORMS},
    **_CONSTANTS,
    "ln": sp.log, "Eq": printed_eq, "Limit": _limit, "O": _landau, "Order": _landau, "Symbol": _symbol, "Function": _function,
    "Approx": _approx,
    "D": D, "Fj": Fj, "Ej": Ej, "Kc": Kc, "Ec": Ec, "arccotg": arccotg,
    **SPECIAL_FUNCTIONS,  # DLMF chapters 19, 20 and 22 in DLMF's notation (modulus k)
})
ASSUMPTIONS = ("positive", "nonnegative", "negative", "nonpositive", "real", "integer", "complex")
#: the names a text may not declare (the forms a transcription is built from); every other
#: name of the vocabulary may be a text's symbol (beta, gamma, E, zeta …), which then hides
#: the function of that name in the text's transcriptions
RESERVED = frozenset({"Fj", "Ej", "Kc", "Ec", "arccotg", "Approx", "Eq", "Ne", "Lt", "Le", "Gt", "Ge", "And",
                      "Or", "Not", "Integral", "Derivative", "Sum", "Product", "Limit", "Subs", "Symbol",
                      "Function", "Rational", "Integer", "Tuple", "Piecewise", "oo", "pi"})


@dataclass(frozen=True)
class SymbolSpec:
    """One declared name: a symbol, or a function of one or more variables (``variables`` set)."""

    name: str
    obj: sp.Basic  # the Symbol, or the applied function f(v) / f(v, w)
    latex: str
    dimension: sp.Expr | None  # None: not declared (dimension checks are then inconclusive)
    range: tuple[sp.Expr, sp.Expr] | None = None
    definition: sp.Expr | None = None
    dots: bool = False  # derivatives in this variable print as Newton dots
    variables: tuple[str, ...] = ()  # a function's variables (empty for a symbol)
    meaning: str = ""
    units: str = ""  # the dimension as declared where it names units ("W/(m K)"): how a value is read
    meanings: tuple[tuple[str, str], ...] = ()  # (language, meaning) from meaning_<lang>

    def meaning_in(self, lang: str) -> str:
        """What the symbol stands for in ``lang``: its ``meaning_<lang>``, else in English its
        ``meaning`` (the unsuffixed wording is English), else ''."""
        return dict(self.meanings).get(lang) or (self.meaning if lang == "en" else "")

    @property
    def variable(self) -> str | None:
        """A function's (first) variable; None for a symbol."""
        return self.variables[0] if self.variables else None


@dataclass(frozen=True, eq=False)
class SymbolTable:
    """The symbols a text declares, in declaration order.

    ``table.rho`` is the object declared as ``rho``; ``table("x y t")`` a tuple of several.
    """

    specs: tuple[SymbolSpec, ...]
    by_name: MappingProxyType = field(default_factory=lambda: MappingProxyType({}), repr=False)

    def __post_init__(self):
        object.__setattr__(self, "by_name", MappingProxyType({s.name: s for s in self.specs}))
        object.__setattr__(self, "_namespace", MappingProxyType({**FUNCTIONS, **{s.name: s.obj for s in self.specs}}))
        object.__setattr__(self, "_calls", MappingProxyType({s.name: s.obj.func for s in self.specs if s.variables}))

    def __getattr__(self, name: str):
        spec = self.__dict__.get("by_name", {}).get(name)
        if spec is None:
            raise AttributeError(f"no symbol {name!r} is declared")
        return spec.obj

    def __call__(self, names: str):
        """The symbols named, as sympy's ``symbols`` gives them: one name its symbol, several
        (or one with a trailing comma) a tuple."""
        found = tuple(getattr(self, n) for n in names.replace(",", " ").split())
        return found[0] if len(found) == 1 and "," not in names else found

    def __contains__(self, name: str) -> bool:
        return name in self.by_name

    @property
    def namespace(self) -> MappingProxyType:
        return self._namespace

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
            if s.variables:
                out[s.obj.func] = s.latex
        return out

    @property
    def dotted(self) -> frozenset:
        """The variables whose derivatives print as Newton dots (time)."""
        return frozenset(s.obj for s in self.specs if s.dots)

    @property
    def variables(self) -> frozenset:
        """The independent variables of the declared functions."""
        return frozenset(a for s in self.specs if s.variables for a in s.obj.args)

    def names_of(self, objs) -> list[str]:
        rev = {s.obj: s.name for s in self.specs}
        return [rev.get(o, str(o)) for o in objs]

    def check_names(self, text: str) -> None:
        """Refuse a transcription that uses a name this table does not declare, or a construct
        the reader does not allow (nothing is built)."""
        try:
            unknown = transcription.check(text, self._namespace)
        except transcription.TranscriptionError as exc:
            raise SymbolError(str(exc)) from None
        if unknown:
            raise SymbolError(f"unknown name{'s' if len(unknown) > 1 else ''} {', '.join(unknown)} "
                              "(declare it in text.toml)")

    def parse(self, text: str) -> sp.Basic:
        """Read a transcription in this table's namespace (:mod:`quasicentral.notation.transcription`:
        a whitelist, nothing executed); an unknown name is an error, not a fresh symbol.  A
        declared function's name called with arguments is its value there (``x(0)``)."""
        try:
            return transcription.parse(text, dict(self._namespace), calls=dict(self._calls))
        except transcription.TranscriptionError as exc:
            raise SymbolError(str(exc)) from None


# --- reading a table from text.toml ------------------------------------------------------------
_IDENT = re.compile(r"[A-Za-z][A-Za-z0-9_]*\Z")
_SYMBOL_KEYS = frozenset({"latex", "dimension", "assumptions", "range", "definition", "solves", "dots", "meaning"})
_FUNCTION_KEYS = frozenset({"latex", "dimension", "assumptions", "variable", "variables", "meaning"})


def table_from_toml(data: dict, where: str) -> SymbolTable:
    """Build the table of ``[symbols.NAME]`` and ``[functions.NAME]`` tables (see
    quasicentral/texts/FORMAT.md); every error names ``where`` and the key."""
    symbols = data.get("symbols", {})
    functions = data.get("functions", {})
    if not isinstance(symbols, dict) or not isinstance(functions, dict):
        raise SymbolError(f"{where}: [symbols] and [functions] are tables of tables")
    objs: dict[str, sp.Basic] = {}
    for name, raw in symbols.items():
        key = f"{where}: symbols.{name}"
        _check_entry(name, raw, _SYMBOL_KEYS, key)
        objs[name] = sp.Symbol(name, **_assumptions(raw.get("assumptions", ["real"]), key))
    variables_of = {}
    for name, raw in functions.items():
        key = f"{where}: functions.{name}"
        _check_entry(name, raw, _FUNCTION_KEYS, key)
        if name in objs:
            raise SymbolError(f"{key}: {name} is declared as a symbol too")
        variables_of[name] = _function_variables(raw, objs, key)
        head = sp.Function(name, **_assumptions(raw.get("assumptions", ["real"]), key))
        objs[name] = head(*[objs[v] for v in variables_of[name]])
    ns = {**FUNCTIONS, **objs}
    specs: list[SymbolSpec] = []
    for name, raw in symbols.items():
        key = f"{where}: symbols.{name}"
        rng, definition = _range_or_definition(raw, ns, key)
        if "solves" in raw:
            rng, definition = None, _solves(raw, ns, key, objs[name], rng)
        if "dots" in raw and not isinstance(raw["dots"], bool):
            raise SymbolError(f"{key}.dots: true or false")
        specs.append(SymbolSpec(name, objs[name], _latex(raw, name, key), _dimension(raw, key), rng,
                                definition, bool(raw.get("dots", False)), (), _meaning(raw, key),
                                str(raw.get("dimension", "")).strip(), _meanings(raw, key)))
    for name, raw in functions.items():
        key = f"{where}: functions.{name}"
        specs.append(SymbolSpec(name, objs[name], _latex(raw, name, key), _dimension(raw, key),
                                variables=variables_of[name], meaning=_meaning(raw, key),
                                units=str(raw.get("dimension", "")).strip(), meanings=_meanings(raw, key)))
    _check_ranges(specs, where)
    return SymbolTable(tuple(specs))


def _check_ranges(specs: list[SymbolSpec], where: str) -> None:
    """Every range a sampler can draw from: its ends numbers (±oo allowed) or expressions in
    other symbols, low below high, no range that depends on itself (through other ranges or
    definitions)."""
    by_obj = {s.obj: s for s in specs}
    for s in specs:
        if s.range is None:
            continue
        key = f"{where}: symbols.{s.name}.range"
        lo, hi = s.range
        for end in (lo, hi):
            if end.has(sp.zoo, sp.nan) or end is sp.zoo or end is sp.nan:
                raise SymbolError(f"{key}: {end} is not a number (an end is a number, ±oo, or an expression)")
        if lo.is_number and hi.is_number:
            if lo.is_real and hi.is_real or lo in (sp.oo, -sp.oo) or hi in (sp.oo, -sp.oo):
                if lo == hi:
                    raise SymbolError(f"{key}: [{lo}, {hi}] is a single point: a range has a width to sample")
                if bool(lo > hi):
                    raise SymbolError(f"{key}: [{lo}, {hi}] is empty (the low end comes first)")
            elif sp.re(lo) == sp.re(hi) and sp.im(lo) == sp.im(hi):
                raise SymbolError(f"{key}: [{lo}, {hi}] is a single point: a box has two distinct corners")

    def depends(s: SymbolSpec) -> set:
        ends = s.range if s.range is not None else ((s.definition,) if s.definition is not None else ())
        return {x for e in ends for x in e.free_symbols if x in by_obj and x != s.obj} | (
            {s.obj} if any(s.obj in e.free_symbols for e in ends) else set())

    def visit(obj, stack):
        if obj in stack:
            cycle = " → ".join(by_obj[o].name for o in stack[stack.index(obj):] + [obj])
            raise SymbolError(f"{where}: symbols.{by_obj[obj].name}.range: the range depends on itself ({cycle})")
        for dep in depends(by_obj[obj]):
            visit(dep, stack + [obj])

    for s in specs:
        if s.range is not None or s.definition is not None:
            visit(s.obj, [])


def _function_variables(raw: dict, objs: dict, key: str) -> tuple[str, ...]:
    if "variable" in raw and "variables" in raw:
        raise SymbolError(f"{key}: give 'variable' or 'variables', not both")
    names = [raw["variable"]] if "variable" in raw else raw.get("variables")
    if not (isinstance(names, list) and names and all(isinstance(v, str) and v in objs for v in names)):
        raise SymbolError(f"{key}: 'variable' (or 'variables', a list) must name declared symbols, "
                          f"not {raw.get('variable', raw.get('variables'))!r}")
    if len(set(names)) != len(names):
        raise SymbolError(f"{key}: a variable is named twice")
    return tuple(names)


def _range_or_definition(raw: dict, ns: dict, key: str):
    rng = definition = None
    if "range" in raw:
        r = raw["range"]
        if not (isinstance(r, list) and len(r) == 2 and all(isinstance(e, (str, int, float)) and not isinstance(e, bool)
                                                              for e in r)):
            raise SymbolError(f"{key}.range: a pair [low, high], such as [\"0\", \"1\"]")
        rng = tuple(_expr(str(e), ns, f"{key}.range") for e in r)
    if "definition" in raw:
        if rng is not None:
            raise SymbolError(f"{key}: a defined symbol has no range of its own")
        if not isinstance(raw["definition"], (str, int, float)) or isinstance(raw["definition"], bool):
            raise SymbolError(f"{key}.definition: an expression in other symbols, as a string")
        definition = _expr(str(raw["definition"]), ns, f"{key}.definition")
    return rng, definition


def _solves(raw: dict, ns: dict, key: str, sym: sp.Symbol, bracket) -> Root:
    """A symbol defined only implicitly, ``solves = "besselj(1, x1)"``: the root of that
    expression in the symbol's range (:class:`~quasicentral.notation.roots.Root`)."""
    if "definition" in raw:
        raise SymbolError(f"{key}: a symbol is defined by a definition or by solves, not both")
    if bracket is None:
        raise SymbolError(f"{key}.solves: give the range in which the root lies, such as range = [\"3\", \"4.5\"]")
    if not isinstance(raw["solves"], str):
        raise SymbolError(f"{key}.solves: an expression in {sym} (and other symbols) that vanishes at its value")
    f = _expr(raw["solves"], ns, f"{key}.solves")
    if sym not in f.free_symbols:
        raise SymbolError(f"{key}.solves: {raw['solves']!r} does not hold {sym}")
    x = sp.Dummy(sym.name)
    return Root(f.xreplace({sym: x}), x, *bracket)


#: a symbol's meaning in another language: meaning_cs …
_MEANING_IN = re.compile(r"meaning_[a-z]{2}")


def _meanings(raw, key) -> tuple[tuple[str, str], ...]:
    out = []
    for k in sorted(raw):
        if _MEANING_IN.fullmatch(k):
            if not isinstance(raw[k], str):
                raise SymbolError(f"{key}.{k}: a string")
            if raw[k].strip():
                out.append((k[len("meaning_"):], raw[k].strip()))
    return tuple(out)


def _meaning(raw, key) -> str:
    m = raw.get("meaning", "")
    if not isinstance(m, str):
        raise SymbolError(f"{key}.meaning: a string")
    return m


def _check_entry(name, raw, allowed, key):
    if not _IDENT.match(name) or keyword.iskeyword(name):
        raise SymbolError(f"{key}: a name is a letter followed by letters, digits or _")
    if name in RESERVED:
        raise SymbolError(f"{key}: {name} is a name of the notation (choose another name)")
    if not isinstance(raw, dict):
        raise SymbolError(f"{key}: a table such as {{ latex = '...', dimension = 'L' }}")
    unknown = {k for k in set(raw) - allowed if not _MEANING_IN.fullmatch(k)}
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
    if not isinstance(raw["dimension"], (str, int)) or isinstance(raw["dimension"], bool):
        raise SymbolError(f"{key}.dimension: a string such as \"L/T^2\" or \"J/K\"")
    try:
        return parse_dim(str(raw["dimension"]))
    except UnitError as exc:
        raise SymbolError(f"{key}.dimension: {exc}") from None


def _expr(text: str, ns: dict, key: str) -> sp.Expr:
    try:
        return transcription.parse(text, ns)
    except transcription.TranscriptionError as exc:
        raise SymbolError(f"{key}: {exc.reason if exc.line == 1 else exc}") from None
