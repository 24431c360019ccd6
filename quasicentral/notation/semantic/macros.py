"""DLMF's semantic macros and the names their transcriptions use.

A macro is written ``\\name{p1}…{pm}@{a1}…{an}``: *parameters* before the ``@`` (the index of
θ_j, the kind of Bulirsch's el_j, the order of a hypergeometric function), *arguments* after.
:data:`MACROS` gives, per macro, the function it stands for, how many parameters and
arguments it takes, and — where DLMF's text lets one be suppressed — the arguments a bare use
implies (``\\ccompellintKk`` alone is K′(k)).  A macro whose reading is more than a function
call (Carlson's R with its lists, the generalized hypergeometric function, generic Jacobi
functions pq) names a *form* the parser handles.

The names are the contract of the special functions (modulus k, Π's parameter α², Carlson's
R_{−a} as ``CarlsonR(a, Tuple(b…), Tuple(z…))``) and sympy's own.

>>> MACROS[r"\\incellintFk"].func, MACROS[r"\\incellintFk"].args
('EllipticF', 2)
"""

from __future__ import annotations

from types import MappingProxyType
from dataclasses import dataclass


@dataclass(frozen=True)
class Macro:
    func: str                   # the function (or, with a form, the family's stem)
    args: int = 1               # brace arguments after the @
    params: int = 0             # brace parameters before the @
    form: str = ""              # a reading other than func(args): see the parser
    implied: tuple[str, ...] = ()  # the arguments of a bare use (DLMF suppresses the modulus)


#: The twelve Jacobian elliptic functions by their two letters.
JACOBI_LETTERS = ("sn", "cn", "dn", "ns", "nc", "nd", "sc", "sd", "cs", "cd", "ds", "dc")
JACOBI = MappingProxyType({pq: f"Jacobi{pq.upper()}" for pq in JACOBI_LETTERS})
#: Neville's/Jacobi's theta index of each letter (DLMF 22.2.11: s, c, d, n ↔ 1, 2, 3, 4).
THETA_INDEX = MappingProxyType({"s": "1", "c": "2", "d": "3", "n": "4"})

MACROS: dict[str, Macro] = MappingProxyType({
    # Legendre's integrals (DLMF 19.2), modulus k
    r"\compellintKk": Macro("EllipticK", 1, implied=("k",)),
    r"\compellintEk": Macro("EllipticE", 1, implied=("k",)),
    r"\compellintDk": Macro("EllipticD", 1, implied=("k",)),
    r"\compellintPik": Macro("EllipticPi", 2),
    r"\ccompellintKk": Macro("EllipticKp", 1, implied=("k",)),
    r"\ccompellintEk": Macro("EllipticEp", 1, implied=("k",)),
    r"\incellintFk": Macro("EllipticF", 2),
    r"\incellintEk": Macro("EllipticE", 2),
    r"\incellintDk": Macro("EllipticD", 2),
    r"\incellintPik": Macro("EllipticPi", 3),
    # Carlson's integrals (DLMF 19.16)
    r"\CarlsonellintRC": Macro("CarlsonRC", 2),
    r"\CarlsonsymellintRF": Macro("CarlsonRF", 3),
    r"\CarlsonsymellintRD": Macro("CarlsonRD", 3),
    r"\CarlsonsymellintRG": Macro("CarlsonRG", 3),
    r"\CarlsonsymellintRJ": Macro("CarlsonRJ", 4),
    r"\Carlsonmultivarhyper": Macro("CarlsonR", 2, params=1, form="carlson"),
    # Bulirsch's integrals (DLMF 19.2(iii))
    r"\Bulirschcompellintcel": Macro("BulirschCel", 4),
    r"\Bulirschincellintel": Macro("BulirschEl", 0, params=1, form="bulirsch"),
    r"\AGM": Macro("AGM", 2),
    # Jacobian functions (DLMF 22)
    **{rf"\Jacobiell{pq}k": Macro(JACOBI[pq], 2) for pq in JACOBI_LETTERS},
    **{rf"\aJacobiell{pq}k": Macro(f"JacobiArc{pq.upper()}", 2) for pq in JACOBI_LETTERS},
    r"\genJacobiellk": Macro("Jacobi", 2, params=2, form="jacobi"),
    r"\agenJacobiellk": Macro("JacobiArc", 2, params=2, form="jacobi"),
    r"\Jacobiamk": Macro("JacobiAM", 2),
    r"\JacobiEpsilonk": Macro("JacobiEpsilon", 2),
    r"\JacobiZetak": Macro("JacobiZ", 2),
    r"\Jacobithetaq": Macro("JacobiTheta", 2, params=1, form="theta"),
    r"\Jacobithetatau": Macro("JacobiTheta", 2, params=1, form="theta_tau"),
    # Weierstrass (DLMF 23.2), the lattice read as its half-periods ω1, ω3
    r"\Weierstrassplatt": Macro("WeierstrassP", 2, form="lattice"),
    r"\Weierstrasszetalatt": Macro("WeierstrassZeta", 2, form="lattice"),
    r"\Weierstrasssigmalatt": Macro("WeierstrassSigma", 2, form="lattice"),
    r"\Weierstrasselatt": Macro("WeierstrassP", 1, params=1, form="lattice_root"),
    # other special functions
    r"\EulerGamma": Macro("gamma", 1),
    r"\EulerBeta": Macro("beta", 2),
    r"\digamma": Macro("digamma", 1),
    r"\Pochhammersym": Macro("rf", 2, form="noat"),
    r"\genhyperF": Macro("hyper", 3, params=2, form="hyper"),
    r"\AppellF": Macro("appellf1", 6, params=1, form="appell"),
    r"\binom": Macro("binomial", 2, form="noat"),
    # elementary functions (semantic \sin@@{x}; a bare \sin x reads its next factor)
    **{rf"\{f}": Macro(f) for f in ("sin", "cos", "tan", "cot", "sec", "csc", "sinh", "cosh",
                                     "tanh", "coth", "sech", "csch", "exp")},
    r"\ln": Macro("log"), r"\log": Macro("log"),
    r"\asin": Macro("asin"), r"\acos": Macro("acos"), r"\atan": Macro("atan"),
    r"\acot": Macro("acot"), r"\asinh": Macro("asinh"), r"\acosh": Macro("acosh"),
    r"\atanh": Macro("atanh"),
    r"\Asin": Macro("asin", form="general_value"), r"\Acos": Macro("acos", form="general_value"),
    r"\Gudermannian": Macro("gd", form="gudermannian"),
    r"\aGudermannian": Macro("agd", form="gudermannian"),
    r"\phase": Macro("arg"), r"\realpart": Macro("re"), r"\imagpart": Macro("im"),
    r"\sign": Macro("sign"), r"\sqrt": Macro("sqrt", form="sqrt"),
    r"\min": Macro("Min", 0, form="list"), r"\max": Macro("Max", 0, form="list"),
})

#: Letters and constants.  Greek letters keep their names, except where the name is a
#: Python keyword or a function of the notation.
GREEK = MappingProxyType({name: name for name in (
    "alpha", "beta", "gamma", "delta", "epsilon", "varepsilon", "zeta", "eta", "theta",
    "vartheta", "iota", "kappa", "mu", "nu", "xi", "rho", "varrho", "sigma", "tau", "upsilon",
    "phi", "varphi", "chi", "psi", "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi",
    "Sigma", "Upsilon", "Phi", "Psi", "Omega", "ell")} | {"lambda": "lamda"})
#: Names a symbol may not take (functions and constants of the transcriptions).
RESERVED = frozenset({
    "gamma", "beta", "pi", "I", "O", "oo", "exp", "sqrt", "sign", "re", "im",
    "arg", "rf", "binomial", "factorial", "hyper", "digamma", "floor", "Sum", "Product",
    "Integral", "Limit", "Derivative", "Eq", "Ne", "Lt", "Le", "Gt", "Ge", "And", "Or", "Min",
    "Max", "Tuple", "Rational", "Abs", "conjugate", "sin", "cos", "tan", "log", "ln", "Float",
    "Integer", "Symbol", "Function", "D",
})
CONSTANTS = MappingProxyType({r"\cpi": "pi", r"\pi": "pi", r"\iunit": "I", r"\expe": "E", r"\infty": "oo",
             r"\EulerConstant": "EulerGamma"})

#: Commands that only space or style the print.
SPACING = frozenset({r"\,", r"\;", r"\!", r"\ ", r"\:", r"\*", r"\displaystyle", r"\textstyle",
                     r"\nolimits", r"\limits", r"\qquad"})
#: Relations and their sympy heads; "to", "sim", "in" are for the caller to read.
RELATIONS = MappingProxyType({"=": "Eq", "<": "Lt", ">": "Gt", r"\leq": "Le", r"\le": "Le", r"\geq": "Ge",
             r"\ge": "Ge", r"\neq": "Ne", r"\ne": "Ne", r"\to": "to", r"\rightarrow": "to",
             r"\sim": "sim", r"\asympeq": "sim", r"\in": "in"})
