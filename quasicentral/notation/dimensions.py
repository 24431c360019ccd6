"""Dimensional analysis of transcriptions: lengths L, times T, masses M.

``dimension(expr, dims)`` returns the dimension monomial of ``expr`` or raises
:class:`DimensionError` naming the offending sub-expression: a sum of unlike terms, a
transcendental function of a dimensional argument, an exponent with dimensions.
"""

from __future__ import annotations

import sympy as sp

from dataclasses import dataclass
from enum import Enum

from quasicentral.notation.symbols import DIMENSIONLESS, dim_text


class DimensionError(ValueError):
    """The expression mixes dimensions: a definite inconsistency."""


class DimensionUnknown(DimensionError):
    """A symbol or function without a declared dimension: nothing can be concluded."""


_TRANSCENDENTAL = (sp.sin, sp.cos, sp.tan, sp.exp, sp.log, sp.asin, sp.acos, sp.atan, sp.acot,
                   sp.sinh, sp.cosh, sp.elliptic_k, sp.elliptic_f, sp.elliptic_e, sp.factorial,
                   sp.factorial2, sp.gamma)


def dimension(e: sp.Basic, dims: dict, log_ok: bool = False) -> sp.Expr:  # noqa: C901 - one dispatch table
    """Dimension of ``e``.  ``log_ok``: a logarithm of a dimensional quantity is allowed (inside
    a derivative, d/dt ln X = Ẋ/X is free of X's unit)."""
    if e in dims:
        return dims[e]
    if e.is_number:
        return DIMENSIONLESS
    if isinstance(e, sp.Symbol):
        raise DimensionUnknown(f"no dimension declared for symbol {e}")
    if isinstance(e, sp.Subs):  # f(t) at t = 0 has the dimension of f
        return dimension(e.expr, dims, log_ok)
    if isinstance(e, sp.core.function.AppliedUndef):
        for key, d in dims.items():  # x(0) is a value of x(t)
            if isinstance(key, sp.core.function.AppliedUndef) and key.func == e.func:
                return d
        for key, d in dims.items():  # A(t) of a variation of constants has the dimension of A
            if isinstance(key, sp.Symbol) and key.name == e.func.__name__:
                return d
        raise DimensionUnknown(f"no dimension declared for {e}")
    if isinstance(e, sp.Add):
        ds = [dimension(a, dims) for a in e.args]
        first = ds[0]
        for a, d in zip(e.args[1:], ds[1:]):
            if sp.simplify(d / first) != 1:
                raise DimensionError(f"adds [{_fmt(first)}] to [{_fmt(d)}] in {sp.sstr(e)}: term {sp.sstr(a)}")
        return first
    if isinstance(e, sp.Mul):
        out = sp.Integer(1)
        for a in e.args:
            out *= dimension(a, dims)
        return out
    if isinstance(e, sp.Pow):
        base = dimension(e.base, dims)
        if dimension(e.exp, dims) != 1:
            raise DimensionError(f"exponent with dimension in {sp.sstr(e)}")
        if base == 1:
            return DIMENSIONLESS
        if not e.exp.is_number:
            raise DimensionError(f"symbolic power of a dimensional quantity in {sp.sstr(e)}")
        return sp.powsimp(base**e.exp, force=True)
    if isinstance(e, sp.Abs):
        return dimension(e.args[0], dims)
    if isinstance(e, sp.log) and log_ok:
        dimension(e.args[0], dims)
        return DIMENSIONLESS
    if isinstance(e, sp.Derivative):
        out = dimension(e.expr, dims, log_ok=True)
        for var, count in e.variable_count:
            out /= dimension(var, dims) ** count
        return out
    if isinstance(e, sp.Integral):
        out = dimension(e.function, dims)
        for lim in e.limits:
            var = lim[0]
            dv = dimension(var, dims)
            for end in lim[1:]:
                de = dimension(end, dims)
                if end != 0 and sp.simplify(de / dv) != 1:
                    raise DimensionError(f"limit {sp.sstr(end)} [{_fmt(de)}] of d{var} [{_fmt(dv)}]")
            out *= dv
        return out
    if isinstance(e, sp.Sum):
        return dimension(e.function, {**dims, **{lim[0]: DIMENSIONLESS for lim in e.limits}})
    if isinstance(e, (sp.Eq, sp.Tuple)):
        raise DimensionError("relation inside an expression")
    if isinstance(e, _TRANSCENDENTAL) or callable(getattr(e, "func", None)):
        for a in e.args:
            d = dimension(a, dims)
            if d != 1:
                raise DimensionError(f"{e.func.__name__} of [{_fmt(d)}] argument {sp.sstr(a)}")
        return DIMENSIONLESS
    raise DimensionUnknown(f"cannot take the dimension of {sp.sstr(e)}")


class DimensionStatus(Enum):
    CONSISTENT = "consistent"
    INCONSISTENT = "inconsistent"
    UNDETERMINED = "undetermined"  # a dimension is not declared: nothing can be concluded


@dataclass(frozen=True)
class DimensionCheck:
    """The dimensional verdict on one relation, with the reason when it is not consistent."""

    status: DimensionStatus
    reason: str = ""

    @property
    def inconsistent(self) -> bool:
        return self.status is DimensionStatus.INCONSISTENT

    @property
    def undetermined(self) -> bool:
        return self.status is DimensionStatus.UNDETERMINED

    def __str__(self) -> str:
        return self.status.value + (f": {self.reason}" if self.reason else "")


CONSISTENT = DimensionCheck(DimensionStatus.CONSISTENT)


def check_relation(rel: sp.Basic, dims: dict) -> DimensionCheck:
    """Whether ``rel`` is dimensionally consistent; *undetermined* when a dimension is not
    declared (which proves nothing).  An equation compares its two sides; where it has
    logarithms of dimensional quantities (ln L = −2κt + ln A), they are combined first
    (ln(L/A)), so only their ratio needs to be dimensionless."""
    try:
        if isinstance(rel, sp.Eq) and any(a.args[0].free_symbols for a in rel.atoms(sp.log)):
            dimension(sp.logcombine(rel.lhs - rel.rhs, force=True), dims)
        elif isinstance(rel, sp.Eq):
            dl, dr = dimension(rel.lhs, dims), dimension(rel.rhs, dims)
            if rel.lhs != 0 and rel.rhs != 0 and sp.simplify(dl / dr) != 1:
                return DimensionCheck(DimensionStatus.INCONSISTENT,
                                      f"left side [{_fmt(dl)}], right side [{_fmt(dr)}]")
        else:
            dimension(rel, dims)
    except DimensionUnknown as exc:
        return DimensionCheck(DimensionStatus.UNDETERMINED, str(exc))
    except DimensionError as exc:
        return DimensionCheck(DimensionStatus.INCONSISTENT, str(exc))
    return CONSISTENT


def _fmt(d: sp.Expr) -> str:
    return dim_text(d)
