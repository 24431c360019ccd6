"""Rendering in the paper's notation: a LaTeX printer and the
preparation of the catalog's verbatim LaTeX for a display.

Rendering is separate from derivation (sympy's ``LatexPrinter`` subclassed, as
``VectorLatexPrinter`` does for mechanics):

* :class:`PaperLatexPrinter` writes functions of t without "(t)", time derivatives with
  Newton's dots (ẋ, ẍ), ρ as ϱ (``\\varrho``), φ as φ (``\\varphi``), the elliptic integrals in
  the paper's Jacobi form F(k, ζ), E(k, ζ), K, E (``elliptic_f(asin(ζ), k**2)`` is F(k, ζ):
  sympy takes the *parameter* m = k² and the amplitude, the paper the *modulus* k and ζ = sin of
  the amplitude), ``π/2 − atan a`` as arccotg a, and the checker's jet symbols (``phi_t1``) as
  the derivatives they stand for, so nothing of the machinery shows.
* prose with Unicode mathematics is :mod:`quasicentral.documents.prosetex`'s;
* :func:`display_rows` splits a catalog entry's printed LaTeX into the rows of one display and
  balances ``\\left``/``\\right`` pairs that the print splits over lines, so that every entry
  compiles as printed.

>>> import sympy as sp
>>> from quasicentral.notation.symbols import D, Fj
>>> t, k, zeta = sp.symbols("t k zeta")
>>> rho, psi = sp.Function("rho")(t), sp.Function("psi")(t)
>>> with using(Notation({"rho": r"\\varrho"}, {"rho": r"\\varrho"}, frozenset({t}), frozenset({t}))):
...     paper_latex(rho**2 * D(psi))
'\\\\varrho^{2} \\\\dot{\\\\psi}'
>>> paper_latex(Fj(k, zeta))
'F\\\\left(k, \\\\zeta\\\\right)'
"""

from __future__ import annotations

import re
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, field
from types import MappingProxyType

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.printing.latex import LatexPrinter

from quasicentral.notation.bridge import is_jet, jet_of

# --- the printer ------------------------------------------------------------------------------

@dataclass(frozen=True)
class Notation:
    """How a text writes its symbols: each name's LaTeX (its ``text.toml``), the variables whose
    derivatives are Newton's dots (time), and the independent variables (a function of one of
    them prints without its argument: ϱ, not ϱ(t))."""

    names: dict = field(default_factory=dict)  # symbol name -> LaTeX
    functions: dict = field(default_factory=dict)  # function name -> LaTeX
    dotted: frozenset = frozenset()
    variables: frozenset = frozenset()

    @staticmethod
    def of(table, symbols: dict | None = None, functions: dict | None = None) -> "Notation":
        """The notation of a text's symbol table, with extra names (its report.toml)."""
        names = {s.name: s.latex for s in table.specs if s.variable is None}
        funcs = {s.name: s.latex for s in table.specs if s.variable is not None}
        return Notation({**names, **(symbols or {})}, {**funcs, **(functions or {})}, table.dotted, table.variables)


_NOTATION: ContextVar[Notation] = ContextVar("notation", default=Notation())


@contextmanager
def using(notation: Notation):
    """Print in ``notation`` within the block (the documents of one text)."""
    token = _NOTATION.set(notation)
    try:
        yield notation
    finally:
        _NOTATION.reset(token)


def notation() -> Notation:
    """The notation in force (see :func:`using`)."""
    return _NOTATION.get()



#: sympy functions defined by the derivations, by class name -> LaTeX (a text adds its own: the
#: ``[notation] functions`` of its report.toml, passed to the printer as ``function_names``).
NAMED_FUNCTIONS: dict[str, str] = MappingProxyType({})

_DOTS = MappingProxyType({1: r"\dot", 2: r"\ddot", 3: r"\dddot", 4: r"\ddddot"})


class _Arccotg(sp.Function):
    """Placeholder for printing π/2 − atan a as the paper's arccotg a (values in (0, π))."""

    nargs = 1


class PaperLatexPrinter(LatexPrinter):
    """sympy's LaTeX printer speaking the paper's notation (see the module docstring)."""

    _default_settings = {**LatexPrinter._default_settings, "ln_notation": True, "fold_func_brackets": True,
                         "inv_trig_style": "full"}

    def __init__(self, settings=None, names: dict[str, str] | None = None,
                 function_names: dict[str, str] | None = None, notation: Notation | None = None):
        super().__init__(settings)
        self.notation = notation if notation is not None else _NOTATION.get()
        #: symbol name -> LaTeX (the text's, unless replaced)
        self.names = {**self.notation.names} if names is None else names
        self.function_names = {**self.notation.functions, **NAMED_FUNCTIONS, **(function_names or {})}

    def _plain(self, f) -> bool:
        """A function of one of the text's independent variables: printed without its argument."""
        return isinstance(f, AppliedUndef) and len(f.args) == 1 and f.args[0] in self.notation.variables

    # names
    def _print_Symbol(self, expr, style="plain"):
        if is_jet(expr):
            f, order = jet_of(expr)
            base = self.function_names.get(f.func.__name__, self._deal_with_super_sub(f.func.__name__))
            return self._derivative_of(base, f.args[0], order)
        if expr.name in self.names:
            return self.names[expr.name]
        return super()._print_Symbol(expr, style=style)

    def _derivative_of(self, base: str, var, order: int) -> str:
        if order == 0:
            return base
        if var in self.notation.dotted:
            return f"{_DOTS[order]}{{{base}}}" if order in _DOTS else f"{base}^{{({order})}}"
        v = self._print(var)
        return (rf"\frac{{d{base}}}{{d{v}}}" if order == 1
                else rf"\frac{{d^{{{order}}}{base}}}{{d{v}^{{{order}}}}}")

    def _print_Function(self, expr, exp=None):
        if isinstance(expr, AppliedUndef):
            name = expr.func.__name__
            base = self.function_names.get(name, self._deal_with_super_sub(name))
            if self._plain(expr):
                return base if exp is None else f"{base}^{{{exp}}}"
            args = ", ".join(self._print(a) for a in expr.args)
            tex = f"{base}\\left({args}\\right)"
            return tex if exp is None else f"{tex}^{{{exp}}}"
        name = type(expr).__name__
        if name in self.function_names:
            args = ", ".join(self._print(a) for a in expr.args)
            head = self.function_names[name] if exp is None else f"{self.function_names[name]}^{{{exp}}}"
            return f"{head}\\left({args}\\right)"
        return super()._print_Function(expr, exp)

    def _needs_function_brackets(self, expr) -> bool:
        # cos φ, not cos(φ): a function of t prints as a single letter
        if self._plain(expr):
            return False
        return super()._needs_function_brackets(expr)

    def _foldable(self, a) -> bool:
        """An argument that needs no brackets after an operator name: a symbol, a function of
        t, or a fraction (the paper writes ln A, arccotg (v0/R0ω)·…)."""
        if self._plain(a):
            return True
        if isinstance(a, sp.Mul) and a.as_numer_denom()[1] != 1 and not a.could_extract_minus_sign():
            return True
        return a.is_Atom

    def _operator(self, name: str, a, exp=None) -> str:
        arg = self._print(a)
        if not self._foldable(a):
            arg = rf"\left({arg}\right)"
        head = name if exp is None else rf"{name}^{{{exp}}}"
        return f"{head} {arg}"

    def _print__Arccotg(self, expr, exp=None):
        return self._operator(r"\arccotg", expr.args[0], exp)

    def _print_log(self, expr, exp=None):
        return self._operator(r"\ln", expr.args[0], exp)

    # derivatives
    def _is_time_derivative(self, expr) -> bool:
        return all(v in self.notation.dotted for v, _ in expr.variable_count)

    def _print_Derivative(self, expr):
        f, variables = expr.expr, {v for v, _ in expr.variable_count}
        if self._plain(f) and variables == {f.args[0]}:
            return self._derivative_of(self._print(f), f.args[0], expr.derivative_count)
        if not self._is_time_derivative(expr):
            return super()._print_Derivative(expr)
        order, (var,) = expr.derivative_count, variables
        v = self._print(var)
        op = rf"\frac{{d}}{{d{v}}}" if order == 1 else rf"\frac{{d^{{{order}}}}}{{d{v}^{{{order}}}}}"
        return rf"{op} \left[{self._print(f)}\right]"

    def _print_Subs(self, subs):
        expr, old, new = subs.args
        if isinstance(expr, sp.Derivative) and len(old) == 1 and old[0] in self.notation.dotted \
                and self._is_time_derivative(expr):
            return rf"{self._print(expr)}\left({self._print(new[0])}\right)"
        return super()._print_Subs(subs)

    # the order of a sum: the highest time derivative first, as a text writes an equation of
    # motion (ϱ̈ − ϱψ̇², not −ϱψ̇² + ϱ̈); positive terms before negative ones; sympy's order else
    def _as_ordered_terms(self, expr, order=None):
        terms = super()._as_ordered_terms(expr, order=order)
        if order not in (None, "lex") or self._settings.get("order") not in (None, "lex"):
            return terms
        order_in = self.notation.dotted | self.notation.variables
        return sorted(terms, key=lambda term: (-_time_order(term, order_in), term.could_extract_minus_sign()))

    # the paper's arccotg
    def _print_Add(self, expr, order=None):
        half_pi = sp.pi / 2
        args = list(expr.args)
        if half_pi in args:
            for a in args:
                if isinstance(a, sp.Mul) and len(a.args) == 2 and a.args[0] == -1 and isinstance(a.args[1], sp.atan):
                    rest = [b for b in args if b is not a and b != half_pi]
                    new = _Arccotg(a.args[1].args[0])
                    if not rest:
                        return self._print(new)
                    return super()._print_Add(sp.Add(*rest, new, evaluate=False), order)
        return super()._print_Add(expr, order)

    # the paper's elliptic notation: modulus k, sine of the amplitude ζ
    def _modulus(self, m):
        if isinstance(m, sp.Pow) and m.exp == 2:
            return m.base
        return sp.sqrt(m)

    def _complete(self, letter: str, m, exp=None) -> str:
        """K, E of the text's modulus (a single symbol: K, not K(k)); K(…) of another one."""
        k = self._modulus(m)
        head = letter if exp is None else f"{letter}^{{{exp}}}"
        return head if isinstance(k, sp.Symbol) else rf"{head}\left({self._print(k)}\right)"

    def _incomplete(self, letter: str, phi, m, exp=None) -> str:
        if phi == sp.pi / 2:
            return self._complete("K" if letter == "F" else "E", m, exp)
        zeta = phi.args[0] if isinstance(phi, sp.asin) else sp.sin(phi)
        head = letter if exp is None else f"{letter}^{{{exp}}}"
        return rf"{head}\left({self._print(self._modulus(m))}, {self._print(zeta)}\right)"

    def _print_elliptic_k(self, expr, exp=None):
        return self._complete("K", expr.args[0], exp)

    def _print_elliptic_f(self, expr, exp=None):
        return self._incomplete("F", expr.args[0], expr.args[1], exp)

    def _print_elliptic_e(self, expr, exp=None):
        if len(expr.args) == 1:
            return self._complete("E", expr.args[0], exp)
        return self._incomplete("E", expr.args[0], expr.args[1], exp)


def _time_order(expr, variables) -> int:
    """The highest order of a derivative in one of ``variables`` in ``expr`` (Derivative or jet)."""
    best = 0
    for d in expr.atoms(sp.Derivative):
        if all(v in variables for v, _ in d.variable_count):
            best = max(best, d.derivative_count)
    for sym in expr.free_symbols:
        if isinstance(sym, sp.Symbol) and is_jet(sym):
            f, order = jet_of(sym)
            if f.args[0] in variables:
                best = max(best, order)
    return best


def paper_latex(expr, names: dict[str, str] | None = None, functions: dict[str, str] | None = None,
                **settings) -> str:
    """``expr`` in the paper's notation (see :class:`PaperLatexPrinter`); ``names`` replaces
    the symbol -> LaTeX mapping of the notation in force, ``functions`` adds function names."""
    return PaperLatexPrinter(settings, names=names, function_names=functions).doprint(expr)


#: Letters with two forms in LaTeX: the printer follows the form a printed display uses.
VARIANTS = ((r"\varrho", r"\rho"), (r"\varphi", r"\phi"), (r"\vartheta", r"\theta"),
            (r"\varepsilon", r"\epsilon"))


def names_as_printed(printed_latex: str, names: dict[str, str] | None = None) -> dict[str, str]:
    r"""The symbol names of ``names`` (default: the notation in force) with each two-form letter
    in the form that ``printed_latex`` uses (ρ stays ρ where the text prints ρ, ϱ stays ϱ).

    >>> print(names_as_printed(r"\rho \frac{d\psi}{dt}", {"rho": r"\varrho"})["rho"])
    \rho
    >>> print(names_as_printed(r"\varrho^2", {"rho": r"\varrho"})["rho"])
    \varrho
    """
    out = dict(notation().names if names is None else names)
    for one, other in VARIANTS:
        uses_other = re.search(re.escape(other) + r"(?![A-Za-z])", printed_latex)
        uses_one = re.search(re.escape(one) + r"(?![A-Za-z])", printed_latex)
        for name, tex in out.items():
            if uses_other and not uses_one and tex == one:
                out[name] = other
            elif uses_one and not uses_other and tex == other:
                out[name] = one
    return out


_BREAK = "\x00"


#: Commands typeset as words (their width is their length); others count as one glyph.
_WORDS_WIDE = frozenset({"sin", "cos", "tan", "cot", "ln", "log", "exp", "arccotg", "arcsin", "arccos", "arctan",
               "operatorname", "text", "lfloor", "rfloor"})
_SPACES = MappingProxyType({"quad": 2.0, "qquad": 4.0, ",": 0.3, ";": 0.5, ":": 0.4, "!": 0.0, " ": 0.4})


def visible_width(tex: str) -> float:
    """An estimate of the width of ``tex`` in display style, in glyphs: a fraction is as wide as
    its wider part, scripts are smaller, a binary operator or relation counts its spacing."""
    return _width(tex, 0, len(tex))[0]


def _group(tex: str, i: int, end: int) -> tuple[float, int]:
    """The width of the argument at tex[i] (a {...} group or a single token) and the index after."""
    while i < end and tex[i] == " ":
        i += 1
    if i < end and tex[i] == "{":
        depth, j = 0, i
        while j < end:
            if tex[j] == "\\":
                j += 2
                continue
            depth += tex[j] == "{"
            depth -= tex[j] == "}"
            if depth == 0:
                return _width(tex, i + 1, j)[0], j + 1
            j += 1
        return _width(tex, i + 1, end)[0], end
    if i < end and tex[i] == "\\":
        m = re.match(r"\\([A-Za-z]+|.)", tex[i:end])
        return 1.0, i + (len(m.group(0)) if m else 1)
    return (1.0, i + 1) if i < end else (0.0, i)


def _width(tex: str, i: int, end: int) -> tuple[float, int]:
    w = 0.0
    while i < end:
        ch = tex[i]
        if ch == "\\":
            m = re.match(r"\\([A-Za-z]+|.)", tex[i:end])
            name = m.group(1) if m else ""
            i += len(m.group(0)) if m else 1
            if name == "frac" or name == "dfrac" or name == "tfrac":
                a, i = _group(tex, i, end)
                b, i = _group(tex, i, end)
                w += max(a, b) * (0.7 if name == "tfrac" else 1.0) + 0.4
            elif name in ("left", "right", "big", "Big", "bigg", "Bigg", "displaystyle", "mid"):
                if name == "mid":
                    w += 1
                continue
            elif name == "sqrt":
                a, i = _group(tex, i, end)
                w += a + 1.2
            elif name in _SPACES:
                w += _SPACES[name]
            elif name in _WORDS_WIDE:
                w += len(name) * 0.9 if name not in ("operatorname", "text") else 0.0
            elif name in ("cdot", "pm", "mp", "times", "rightarrow", "mapsto", "le", "ge", "doteq", "approx"):
                w += 2.0
            else:
                w += 1.0
        elif ch in "^_":
            a, i = _group(tex, i + 1, end)
            w += 0.7 * a
        elif ch in "{}":
            i += 1
        elif ch in "+-=<>":
            w += 2.0
            i += 1
        elif ch in " &\n\t":
            i += 1
        else:
            w += 1.0
            i += 1
    return w, i


class _BreakingPrinter(PaperLatexPrinter):
    """Marks the places where a long sum may be broken: before the + and − of a top-level sum
    and of a sum that is a factor of a top-level product (printed as coefficient × (sum))."""

    def __init__(self, width: int, names: dict[str, str] | None = None, functions: dict[str, str] | None = None):
        super().__init__(names=names, function_names=functions)
        self._width = width

    def _long(self, expr) -> bool:
        return visible_width(self._print(expr)) > self._width

    def breakable(self, expr) -> str:
        if isinstance(expr, sp.Add) and self._long(expr):
            return self._add_broken(expr)
        if isinstance(expr, sp.Mul) and self._long(expr):
            return self._mul_broken(expr)
        return self._print(expr)

    def _add_broken(self, expr) -> str:
        tex = ""
        for i, term in enumerate(self._as_ordered_terms(expr)):
            if i > 0:
                if term.could_extract_minus_sign():
                    tex += _BREAK + " - "
                    term = -term
                else:
                    tex += _BREAK + " + "
            piece = self.breakable(term)
            if self._needs_add_brackets(term):
                piece = rf"\left({piece}\right)"
            tex += piece
        return tex

    def _mul_broken(self, expr) -> str:
        sums = [f for f in expr.args if isinstance(f, sp.Add)]
        if not sums:
            return self._print(expr)
        big = max(sums, key=lambda a: (visible_width(self._print(a)), sp.default_sort_key(a)))
        rest = sp.Mul(*[f for f in expr.args if f is not big])
        if rest == 1:
            head = ""
        elif rest == -1:
            head = "- "
        elif rest.could_extract_minus_sign():
            head = "- " + self._print(-rest) + " "
        else:
            head = self._print(rest) + " "
        return head + r"\left(" + self._add_broken(big) + r"\right)"


def broken_lines(expr, width: int = 70, names: dict[str, str] | None = None,
                 functions: dict[str, str] | None = None) -> list[str]:
    """``expr`` in the paper's notation, broken into lines of about ``width`` glyphs; each line
    has its ``\\left``/``\\right`` pairs closed so that it typesets on its own."""
    tex = _BreakingPrinter(width, names, functions).breakable(expr)
    return [balance(line) for line in fill_lines(tex.split(_BREAK), width)]


def fill_lines(pieces, width: int) -> list[str]:
    """Greedy line filling: the pieces in order, a new line where the next would pass ``width``
    (the one place it is done, for expressions and for printed rows)."""
    lines, cur = [], ""
    for piece in pieces:
        if cur and visible_width(cur) + visible_width(piece) > width:
            lines.append(cur)
            cur = piece
        else:
            cur += piece
    lines.append(cur)
    return lines


def relation_lines(rel, width: int = 70, names: dict[str, str] | None = None,
                   functions: dict[str, str] | None = None) -> list[str]:
    """A derived relation (``Eq``, expression, or a (symbol, value) pair of a model) as the rows
    of an ``aligned`` display: ``lhs &= …`` then ``&\\quad …``, broken where a long sum allows."""
    if isinstance(rel, tuple):
        lhs, rhs, rel_sym = rel[0], rel[1], r"\mapsto"
    elif isinstance(rel, sp.Eq):
        lhs, rhs, rel_sym = rel.lhs, rel.rhs, "="
    else:
        lhs, rhs, rel_sym = None, rel, ""
    left = paper_latex(lhs, names, functions) if lhs is not None else ""
    lines = broken_lines(rhs, width, names, functions)
    out = [f"{left} &{rel_sym} {lines[0]}".strip()]
    out += [rf"&\quad {line}" for line in lines[1:]]
    return out


# --- the catalog's printed LaTeX, ready for a display ------------------------------------------
_LEFT = re.compile(r"\\left(?![A-Za-z])")
_RIGHT = re.compile(r"\\right(?![A-Za-z])")
_ENV = re.compile(r"\\(begin|end)\{([A-Za-z*]+)\}")


def _split_top(s: str, seps: tuple[str, ...], newline: bool) -> list[str]:
    """Split ``s`` at ``seps`` (and newlines) that are outside braces and environments."""
    parts, cur, depth, env, i = [], [], 0, 0, 0
    while i < len(s):
        m = _ENV.match(s, i)
        if m:
            env += 1 if m.group(1) == "begin" else -1
            cur.append(m.group(0))
            i = m.end()
            continue
        ch = s[i]
        if ch == "\\" and i + 1 < len(s) and s[i + 1] in "{}\\&":
            if s[i + 1] == "\\" and depth == 0 and env == 0 and "\\\\" in seps:
                parts.append("".join(cur))
                cur = []
                i += 2
                continue
            cur.append(s[i:i + 2])
            i += 2
            continue
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        elif depth == 0 and env == 0 and ((ch == "\n" and newline) or ch in seps):
            parts.append("".join(cur))
            cur = []
            i += 1
            continue
        cur.append(ch)
        i += 1
    parts.append("".join(cur))
    return parts


def balance(row: str) -> str:
    """Close a ``\\left`` that the print closes on a later line (and open the ``\\right`` it
    opened on an earlier one) with invisible delimiters, so the row typesets on its own."""
    masked = _mask_nested(row)
    lefts, rights = len(_LEFT.findall(masked)), len(_RIGHT.findall(masked))
    # a \right before any \left at the same level needs an opening \left. in front
    opening = 0
    depth = 0
    for m in re.finditer(r"\\left(?![A-Za-z])|\\right(?![A-Za-z])", masked):
        if m.group(0) == r"\left":
            depth += 1
        else:
            depth -= 1
            if depth < 0:
                opening += 1
                depth = 0
    closing = lefts + opening - rights
    return (r"\left. " * opening) + row.strip() + (r" \right." * max(closing, 0))


def _mask_nested(s: str) -> str:
    """``s`` with everything inside braces and environments blanked out."""
    out, depth, env, i = [], 0, 0, 0
    while i < len(s):
        m = _ENV.match(s, i)
        if m:
            env += 1 if m.group(1) == "begin" else -1
            out.append(" " * len(m.group(0)))
            i = m.end()
            continue
        ch = s[i]
        if ch == "\\" and i + 1 < len(s) and s[i + 1] in "{}":
            out.append(s[i:i + 2] if depth == 0 and env == 0 else "  ")
            i += 2
            continue
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        out.append(ch if depth == 0 and env == 0 and ch not in "{}" else " ")
        i += 1
    return "".join(out)


def display_rows(latex: str) -> list[str]:
    """The rows of one display for a catalog entry's printed LaTeX.

    The print separates displays by newlines and lines of one display by ``\\\\``; both become
    rows.  Newlines and ``\\\\`` inside an environment (``aligned``) stay where they are.  Each
    row's ``\\left``/``\\right`` pairs are balanced (see :func:`balance`); a row ending in a
    bare operator after a ``\\\\`` keeps it.

    >>> display_rows(r"a = \\left\\{ b + \\right. \\\\ \\left. + c \\right\\}")
    ['a = \\\\left\\\\{ b + \\\\right.', '\\\\left. + c \\\\right\\\\}']
    >>> display_rows("x = 1\\ny = 2")
    ['x = 1', 'y = 2']
    """
    rows = []
    for line in _split_top(latex, ("\\\\",), newline=True):
        if line.strip():
            rows.append(balance(_balance_environments(line.strip())))
    return rows or [""]


def _balance_environments(s: str) -> str:
    """Balance \\left/\\right inside each cell of each environment in ``s`` (recursively)."""
    out, i = [], 0
    while True:
        m = re.search(r"\\begin\{([A-Za-z*]+)\}", s[i:])
        if not m:
            out.append(s[i:])
            return "".join(out)
        start = i + m.start()
        name = m.group(1)
        # find the matching \end
        depth, j = 0, start
        for e in _ENV.finditer(s, start):
            if e.group(2) == name:
                depth += 1 if e.group(1) == "begin" else -1
                if depth == 0:
                    j = e.start()
                    end = e.end()
                    break
        else:
            out.append(s[i:])
            return "".join(out)
        body_start = start + len(m.group(0))
        body = s[body_start:j]
        rows = _split_top(body, ("\\\\",), newline=False)
        new_rows = []
        for row in rows:
            cells = _split_top(row, ("&",), newline=False)
            new_rows.append(" &".join(balance(_balance_environments(c)) if c.strip() else c.strip() for c in cells))
        out.append(s[i:body_start] + " " + " \\\\\n".join(r for r in new_rows) + " " + s[j:end])
        i = end


def _break_points(row: str) -> list[int]:
    """Indices in ``row`` before which a line may break: a binary + or − or a ``\\quad`` at
    brace depth 0, outside environments."""
    out, depth, env, i = [], 0, 0, 0
    while i < len(row):
        m = _ENV.match(row, i)
        if m:
            env += 1 if m.group(1) == "begin" else -1
            i = m.end()
            continue
        ch = row[i]
        if ch == "\\":
            if row.startswith(r"\quad", i) and depth == 0 and env == 0 and i > 0:
                out.append(i)
            j = i + 1
            while j < len(row) and row[j].isalpha():
                j += 1
            i = max(j, i + 2) if j == i + 1 else j
            continue
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        elif ch in "+-" and depth == 0 and env == 0:
            before = row[:i].rstrip()
            binary = bool(before) and (before[-1].isalnum() or before[-1] in "})]|!'") \
                and not re.search(r"\\left\s*\S?$|\\(cdot|quad|qquad|,|;)$", before)
            if binary or (before.endswith(r"\right.")):
                out.append(i)
        i += 1
    return out


def wrap_row(row: str, width: int = 74) -> str:
    """A printed row wider than ``width`` glyphs, broken before top-level + and − into an
    ``aligned`` block (continuation lines indented); each line keeps its \\left/\\right pairs
    closed.  Rows that fit, or that hold an environment, are returned as they are."""
    if visible_width(row) <= width or r"\begin" in row:
        return row
    cuts = [0] + _break_points(row) + [len(row)]
    pieces = [row[a:b] for a, b in zip(cuts, cuts[1:]) if row[a:b].strip()]
    lines = fill_lines(pieces, width)
    if len(lines) == 1:
        return row
    lines = [balance(line) for line in lines]
    return ("\\begin{aligned}\n&" + lines[0] + "".join(" \\\\\n&\\qquad " + line for line in lines[1:])
            + "\n\\end{aligned}")
