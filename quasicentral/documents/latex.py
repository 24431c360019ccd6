"""Rendering in the paper's notation: a LaTeX printer (a display that fits the page is
:mod:`quasicentral.documents.breaking`'s).

Rendering is separate from derivation (sympy's ``LatexPrinter`` subclassed, as
``VectorLatexPrinter`` does for mechanics):

* :class:`PaperLatexPrinter` writes functions of t without "(t)", time derivatives with
  Newton's dots (ẋ, ẍ), ρ as ϱ (``\\varrho``), φ as φ (``\\varphi``), the elliptic integrals in
  the paper's Jacobi form F(k, ζ), E(k, ζ), K, E (``elliptic_f(asin(ζ), k**2)`` is F(k, ζ):
  sympy takes the *parameter* m = k² and the amplitude, the paper the *modulus* k and ζ = sin of
  the amplitude), ``π/2 − atan a`` as arccotg a, and the checker's jet symbols (``phi_t1``) as
  the derivatives they stand for, so nothing of the machinery shows.
* prose with Unicode mathematics is :mod:`quasicentral.documents.prosetex`'s;
* :func:`~quasicentral.documents.breaking.display_rows` splits a catalog entry's printed LaTeX
  into the rows of one display and balances ``\\left``/``\\right`` pairs that the print splits
  over lines, so that every entry compiles as printed.

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
from quasicentral.notation.units import unit_latex

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
    units: dict = field(default_factory=dict)  # symbol name -> LaTeX of the units its values are in

    @staticmethod
    def of(table, symbols: dict | None = None, functions: dict | None = None) -> "Notation":
        """The notation of a text's symbol table, with extra names (its report.toml)."""
        names = {s.name: s.latex for s in table.specs if s.variable is None}
        funcs = {s.name: s.latex for s in table.specs if s.variable is not None}
        units = {s.name: u for s in table.specs if s.variable is None and (u := unit_latex(s.units))}
        return Notation({**names, **(symbols or {})}, {**funcs, **(functions or {})}, table.dotted, table.variables,
                        units)


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


#: the significant digits a decimal of a formula is shown in (the checker keeps all of them)
FLOAT_DIGITS = 12


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

    def _print_Float(self, expr):
        """A decimal in at most :data:`FLOAT_DIGITS` significant digits: a display, not the
        number (a root found at 100 digits printed whole filled a line of the re-derived form;
        the checker keeps every digit)."""
        if expr._prec > sp.Float(0, FLOAT_DIGITS)._prec:
            expr = sp.Float(expr, FLOAT_DIGITS)
        return super()._print_Float(expr)

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


#: the checker's name for the n-th time derivative of a function at a witness's point (phi_t1)
_JET_PARAMETER = re.compile(r"^([A-Za-z]+)_t([0-4])$")
_DOT_COMMANDS = ("", r"\dot", r"\ddot", r"\dddot", r"\ddddot")


def parameter_unit(name: str) -> str:
    r"""The units a witness's coordinate is in, as LaTeX after its value (``\,\mathrm{K}``),
    where the text declared them by name; '' else (a letter formula, a derivative's jet)."""
    unit = notation().units.get(name, "")
    return r"\," + unit if unit else ""


def parameter_latex(name: str) -> str:
    """A witness's coordinate in the paper's notation: φ̇ for the checker's phi_t1."""
    jet = _JET_PARAMETER.match(name)
    if jet:
        base, order = paper_latex(sp.Symbol(jet.group(1))), int(jet.group(2))
        return f"{_DOT_COMMANDS[order]}{{{base}}}" if order else base
    return paper_latex(sp.Symbol(name))
