"""Physical dimensions of a text's symbols: the seven SI base dimensions, read from what a
physicist writes — a formula in the base letters (``"L^2/T"``, ``"M*L/T^2"``, ``"Theta"``) or
units by name (``"K"``, ``"J/K"``, ``"m/s^2"``, ``"mol"``, ``"A"``, ``"1"``), read by pint.

A dimension is a sympy monomial in base symbols of its own (``[L]``, ``[T]``, ``[M]``,
``[Θ]``, ``[I]``, ``[N]``, ``[J]``), so a text may also name a symbol L, T or M.  The letter
formula knows L (length), T (time), M (mass) and Θ or Theta (temperature); every other name
is a unit (``"T"`` is time here, write ``"tesla"`` for the unit), and a dimension in pint's own
spelling (``"[length]/[time]"``, ``"[current]"``, ``"[substance]"``, ``"[luminosity]"``) is read
too.  pint is loaded only when a unit is named (it takes half a second).

>>> parse_dim("L^2/T")
[L]**2/[T]
>>> parse_dim("J/K") == parse_dim("M*L^2/(T^2*Theta)")
True
>>> dim_text(parse_dim("W/(m*K)"))
'L*M/(T^3*Θ)'
"""

from __future__ import annotations

import re
from functools import lru_cache
from types import MappingProxyType

import sympy as sp

DIM_L, DIM_T, DIM_M, DIM_THETA, DIM_I, DIM_N, DIM_J = sp.symbols("[L] [T] [M] [Θ] [I] [N] [J]", positive=True)
DIMENSIONLESS = sp.Integer(1)
#: the letters of a dimension formula
LETTERS = MappingProxyType({"L": DIM_L, "T": DIM_T, "M": DIM_M, "Theta": DIM_THETA, "Θ": DIM_THETA})
#: pint's base dimensions
PINT_BASE = MappingProxyType({"[length]": DIM_L, "[time]": DIM_T, "[mass]": DIM_M, "[temperature]": DIM_THETA,
                              "[current]": DIM_I, "[substance]": DIM_N, "[luminosity]": DIM_J})
MAX_LENGTH = 200  # characters of a dimension string: more is not a dimension


class UnitError(ValueError):
    """A dimension string that cannot be read (the message says what to write)."""


_FORMULA = re.compile(r"(?:\s*(?:L|T|M|Theta|Θ|[0-9.]+|[*/^()+-])\s*)+")


@lru_cache(maxsize=512)  # a text spells a few dimensions hundreds of times
def parse_dim(text: str) -> sp.Expr:
    """The dimension ``text`` names, as a monomial in the base dimensions (see the module)."""
    text = str(text).strip()
    if not text:
        raise UnitError("an empty dimension: write '1' for a dimensionless quantity")
    if len(text) > MAX_LENGTH:
        raise UnitError(f"a dimension of {len(text)} characters: at most {MAX_LENGTH}")
    if _FORMULA.fullmatch(text):
        return _formula(text)
    return _units(text)


def _formula(text: str) -> sp.Expr:
    """A product of powers of the base letters with rational exponents."""
    from sympy.parsing.sympy_parser import parse_expr

    spelled = text.replace("^", "**").replace("Θ", "Theta")
    if re.search(r"\*\*\s*\(?\s*-?\s*[0-9.]*[A-Za-z]", spelled):
        raise UnitError(f"dimension {text!r}: an exponent is a number")
    try:
        out = parse_expr(spelled, local_dict={"L": DIM_L, "T": DIM_T, "M": DIM_M, "Theta": DIM_THETA},
                         global_dict={"__builtins__": {}, "Integer": sp.Integer, "Float": sp.Float,
                                      "Rational": sp.Rational}, evaluate=True)
    except Exception as exc:  # noqa: BLE001 - any parse failure is a malformed dimension
        raise UnitError(f"dimension {text!r}: {type(exc).__name__}: {exc}") from None
    return _monomial(sp.nsimplify(out, rational=True), text)


def _monomial(out, text: str) -> sp.Expr:
    if not isinstance(out, sp.Expr) or out.free_symbols - set(PINT_BASE.values()):
        raise UnitError(f"dimension {text!r}: a product of powers of L, T, M, Theta")
    for factor in sp.Mul.make_args(out):
        base, ex = factor.as_base_exp()
        if factor.is_number and factor != 1 or not (base.is_Symbol or base == 1) or not ex.is_Rational:
            raise UnitError(f"dimension {text!r}: a product of powers of L, T, M, Theta (not a sum, no factor)")
    return out


@lru_cache(maxsize=1)
def _registry():
    import pint

    return pint.UnitRegistry()


def _units(text: str) -> sp.Expr:
    """Units by name (pint), or pint's bracketed dimension names."""
    try:
        import pint
    except ImportError:  # pragma: no cover - pint is a dependency
        raise UnitError(f"dimension {text!r}: units by name need pint") from None
    ureg = _registry()
    spelled = text.replace("^", "**")
    try:
        if "[" in spelled:
            dims = ureg.get_dimensionality(spelled)
        else:
            dims = ureg.parse_expression(spelled).dimensionality
    except (pint.errors.PintError, AttributeError, TypeError, ValueError, SyntaxError, KeyError) as exc:
        raise UnitError(f"dimension {text!r}: neither a formula in L, T, M, Theta nor units pint knows "
                        f"({type(exc).__name__}: {str(exc)[:80]})") from None
    out = sp.Integer(1)
    for name, power in dict(dims).items():
        if name not in PINT_BASE:
            raise UnitError(f"dimension {text!r}: the base dimension {name} is not one of SI's seven")
        out *= PINT_BASE[name] ** sp.nsimplify(power, rational=True)
    return out


def unit_latex(text: str) -> str:
    r"""The units a dimension string names, in LaTeX for a value beside them (a witness's
    T₀ = 254.5 K), or '' where it names none (a letter formula such as "L/T", "1", a pint
    dimension in brackets): upright symbols, powers as exponents, in pint's order.

    >>> print(unit_latex("W/(m K)"))
    \mathrm{W}\,\mathrm{m}^{-1}\,\mathrm{K}^{-1}
    >>> unit_latex("L^2/T"), unit_latex("1"), unit_latex("[length]")
    ('', '', '')
    """
    text = str(text).strip()
    if not text or text == "1" or "[" in text or _FORMULA.fullmatch(text):
        return ""
    try:
        ureg = _registry()
        units = ureg.parse_expression(text.replace("^", "**"))
        items = list(getattr(units, "_units", {}).items()) if not isinstance(units, (int, float)) else []
        symbols = [(ureg.get_symbol(name), power) for name, power in items]
    except Exception:  # noqa: BLE001 - a string parse_dim accepted: at worst no units are shown
        return ""
    out = []
    for sym, power in symbols:
        if not re.fullmatch(r"[A-Za-zΩµμ]+", sym):  # °C, a symbol LaTeX would need escaped
            return ""
        sym = sym.replace("Ω", r"\Omega").replace("µ", r"\mu ").replace("μ", r"\mu ")
        p = sp.nsimplify(power, rational=True)
        out.append(rf"\mathrm{{{sym}}}" + ("" if p == 1 else f"^{{{p}}}"))
    return r"\,".join(out)


def dim_text(d: sp.Expr) -> str:
    """The inverse of :func:`parse_dim`, for messages: L²/T → ``'L^2/T'``, T^(3/2)/L^(1/2)
    (every power written as one, never a root: the text is read back by :func:`parse_dim`)."""
    d = sp.sympify(d)
    if d == 1:
        return "1"

    def power(base, exp) -> str:
        name = str(base).strip("[]")
        return name if exp == 1 else (f"{name}^{exp}" if exp.is_Integer else f"{name}^({exp})")

    factors = sorted(d.as_powers_dict().items(), key=lambda kv: str(kv[0]))
    num = [power(b, e) for b, e in factors if e > 0]
    den = [power(b, -e) for b, e in factors if e < 0]
    out = "*".join(num) or "1"
    if den:
        out += "/" + (den[0] if len(den) == 1 else "(" + "*".join(den) + ")")
    return out
