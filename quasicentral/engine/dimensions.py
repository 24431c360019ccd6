"""Dimensional analysis of transcriptions, in the seven SI base dimensions
(:mod:`quasicentral.notation.units`).

:func:`dimension` returns the dimension monomial of an expression or raises
:class:`DimensionError` with a typed :class:`~quasicentral.engine.reasons.Reason` naming the
offending sub-expression: a sum of unlike terms, a transcendental function of a dimensional
argument, an exponent with dimensions.

The arguments of exp, log, the trigonometric and every other transcendental function must be
dimensionless — the argument itself, never a rewritten form; a coefficient in front of a
logarithm is fine (t·ln(1 + kt) has the dimension of t).  Logarithms of dimensional quantities
may appear only in sums where their units cancel, with numbers as coefficients: ln L − ln A,
ln L = −2κt + ln A (only L/A need be dimensionless); and inside a derivative (d/dt ln X =
Ẋ/X).  Nothing is combined or rewritten before it is checked.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

import sympy as sp

from quasicentral.engine.reasons import Code, Reason
from quasicentral.notation.symbols import Landau
from quasicentral.notation.units import DIMENSIONLESS, dim_text


class DimensionError(ValueError):
    """The expression mixes dimensions: a definite inconsistency (``reason`` says where)."""

    def __init__(self, reason: Reason):
        super().__init__(reason.code.value)
        self.reason = reason


class DimensionUnknown(DimensionError):
    """A symbol or function without a declared dimension: nothing can be concluded."""


def _expr(e) -> str:
    return sp.sstr(e)


#: functions whose result has the dimension of their (common) argument
_SAME_DIMENSION = (sp.Abs, sp.re, sp.im, sp.conjugate, sp.Min, sp.Max)
#: functions of any argument whose value is a pure number (a step, a sign)
_ANY_ARGUMENT = (sp.Heaviside, sp.sign)


def _same(a: sp.Expr, b: sp.Expr) -> bool:
    return a == b or sp.simplify(a / b) == 1


def dimension(e: sp.Basic, dims: dict, log_ok: bool = False) -> sp.Expr:  # noqa: C901 - one dispatch table
    """Dimension of ``e``.  ``log_ok``: a logarithm of a dimensional quantity is allowed (inside
    a derivative, d/dt ln X = Ẋ/X is free of X's unit)."""
    if e in dims:
        return dims[e]
    # a number, but not an integral or a sum over a bound variable (∫₀^∞ v f(v) dv has no free
    # symbol and the dimension of a speed)
    if e.is_number and not e.atoms(sp.Symbol, sp.core.function.AppliedUndef):
        return DIMENSIONLESS
    if isinstance(e, sp.Symbol):
        raise DimensionUnknown(Reason.of(Code.DIM_UNDECLARED_SYMBOL, symbol=str(e)))
    if isinstance(e, sp.Subs):  # f(t) at t = 0 has the dimension of f
        return dimension(e.expr, dims, log_ok)
    if isinstance(e, sp.core.function.AppliedUndef):
        return _applied(e, dims)
    if isinstance(e, sp.Add):
        return _sum(e, list(e.args), dims, log_ok)
    if isinstance(e, sp.Mul):
        out = sp.Integer(1)
        for a in e.args:
            out *= dimension(a, dims, log_ok)
        return out
    if isinstance(e, sp.Pow):
        return _power(e, dims)
    if isinstance(e, _SAME_DIMENSION):
        ds = [dimension(a, dims) for a in e.args]
        for a, d in zip(e.args[1:], ds[1:]):
            if not _same(d, ds[0]):
                raise DimensionError(Reason.of(Code.DIM_ADDS, first=dim_text(ds[0]), other=dim_text(d), sum=_expr(e),
                                               term=_expr(a)))
        return ds[0]
    if isinstance(e, (sp.atan2, sp.Mod)):  # atan2(y, x), y mod x: a ratio of like quantities
        ds = [dimension(a, dims) for a in e.args]
        if not _same(ds[0], ds[1]):
            raise DimensionError(Reason.of(Code.DIM_ADDS, first=dim_text(ds[0]), other=dim_text(ds[1]), sum=_expr(e),
                                           term=_expr(e.args[1])))
        return DIMENSIONLESS if isinstance(e, sp.atan2) else ds[0]
    if isinstance(e, _ANY_ARGUMENT):
        for a in e.args:
            dimension(a, dims)
        return DIMENSIONLESS
    if isinstance(e, sp.DiracDelta):
        return 1 / dimension(e.args[0], dims)
    if isinstance(e, sp.log):
        inner = dimension(e.args[0], dims)
        if inner != 1 and not log_ok:
            raise DimensionError(Reason.of(Code.DIM_ARGUMENT, function="log", dimension=dim_text(inner),
                                           argument=_expr(e.args[0])))
        return DIMENSIONLESS
    if isinstance(e, sp.Derivative):
        out = dimension(e.expr, dims, log_ok=True)
        for var, count in e.variable_count:
            out /= dimension(var, dims) ** count
        return out
    if isinstance(e, sp.Integral):
        return _integral(e, dims)
    if isinstance(e, (sp.Sum, sp.Product)):
        inner = dimension(e.function, {**dims, **{lim[0]: DIMENSIONLESS for lim in e.limits}})
        if isinstance(e, sp.Product) and inner != 1:
            raise DimensionUnknown(Reason.of(Code.DIM_CANNOT, expression=_expr(e)))
        return inner
    if isinstance(e, sp.Limit):
        return dimension(e.args[0], dims, log_ok)
    if isinstance(e, sp.Piecewise):
        return _piecewise(e, dims)
    if isinstance(e, (sp.Eq, sp.Tuple, sp.core.relational.Relational)):
        raise DimensionError(Reason.of(Code.DIM_RELATION_INSIDE))
    if isinstance(e, sp.Order):
        return dimension(e.expr, dims, log_ok)
    if isinstance(e, sp.Function):
        for a in e.args:
            if isinstance(a, sp.Tuple):
                for x in a:
                    _dimensionless_argument(e, x, dims)
            else:
                _dimensionless_argument(e, a, dims)
        return DIMENSIONLESS
    raise DimensionUnknown(Reason.of(Code.DIM_CANNOT, expression=_expr(e)))


def _dimensionless_argument(f: sp.Basic, a: sp.Basic, dims: dict) -> None:
    d = dimension(a, dims)
    if d != 1:
        raise DimensionError(Reason.of(Code.DIM_ARGUMENT, function=type(f).__name__, dimension=dim_text(d),
                                       argument=_expr(a)))


def _applied(e: sp.Basic, dims: dict) -> sp.Expr:
    for key, d in dims.items():  # x(0) is a value of x(t); u(nu, T0) of u(nu, T)
        if isinstance(key, sp.core.function.AppliedUndef) and key.func == e.func:
            return d
    for key, d in dims.items():  # A(t) of a variation of constants has the dimension of A
        if isinstance(key, sp.Symbol) and key.name == e.func.__name__:
            return d
    raise DimensionUnknown(Reason.of(Code.DIM_UNDECLARED, expression=_expr(e)))


def _log_term(a: sp.Basic):
    """(c, X) for a term c·ln X with a rational number c; else None."""
    c, rest = a.as_coeff_Mul()
    if isinstance(rest, sp.log) and c.is_Rational:
        return c, rest.args[0]
    return None


def _sum(e: sp.Basic, terms: list, dims: dict, log_ok: bool) -> sp.Expr:
    """A sum's dimension: every term alike; logarithms with rational coefficients together
    (Σ cᵢ ln Xᵢ = ln Π Xᵢ^cᵢ: only the product need be dimensionless)."""
    logs = [(t, lt) for t in terms if (lt := _log_term(t)) is not None]
    if logs and not log_ok and any(dimension(x, dims) != 1 for _, (_, x) in logs):
        product = sp.Mul(*[x ** c for _, (c, x) in logs])
        d = dimension(product, dims)
        if d != 1:
            raise DimensionError(Reason.of(Code.DIM_ARGUMENT, function="log", dimension=dim_text(d),
                                           argument=_expr(product)))
        terms = [t for t in terms if _log_term(t) is None] + [sp.Integer(0)]  # the logs: a pure number
    ds = [dimension(a, dims, log_ok) if a != 0 else None for a in terms]
    known = [(a, d) for a, d in zip(terms, ds) if d is not None]
    if not known:
        return DIMENSIONLESS
    if any(d is None for d in ds):  # the logarithms' group is a pure number
        known.insert(0, (sp.Integer(0), DIMENSIONLESS))
    first = known[0][1]
    for a, d in known[1:]:
        if not _same(d, first):
            raise DimensionError(Reason.of(Code.DIM_ADDS, first=dim_text(first), other=dim_text(d), sum=_expr(e),
                                           term=_expr(a)))
    return first


def _power(e: sp.Pow, dims: dict) -> sp.Expr:
    base = dimension(e.base, dims)
    if dimension(e.exp, dims) != 1:
        raise DimensionError(Reason.of(Code.DIM_EXPONENT, power=_expr(e)))
    if base == 1:
        return DIMENSIONLESS
    # a symbolic exponent (p·V^κ) makes a dimension with that exponent: like terms still match
    return sp.powsimp(base**e.exp, force=True)


def _integral(e: sp.Integral, dims: dict) -> sp.Expr:
    out = dimension(e.function, dims)
    for lim in e.limits:
        var = lim[0]
        dv = dimension(var, dims)
        for end in lim[1:]:
            if end in (0, sp.oo, -sp.oo):  # zero and infinity have every dimension
                continue
            de = dimension(end, dims)
            if not _same(de, dv):
                raise DimensionError(Reason.of(Code.DIM_LIMIT, limit=_expr(end), dimension=dim_text(de),
                                               variable=str(var), variable_dimension=dim_text(dv)))
        out *= dv
    return out


def _piecewise(e: sp.Piecewise, dims: dict) -> sp.Expr:
    ds = []
    for value, cond in e.args:
        ds.append(dimension(value, dims))
        for rel in cond.atoms(sp.core.relational.Relational):
            check = check_relation(rel, dims)
            if check.inconsistent:
                raise DimensionError(check.problem)
    nonzero = [(v, d) for (v, _), d in zip(e.args, ds) if v != 0]
    for v, d in nonzero[1:]:
        if not _same(d, nonzero[0][1]):
            raise DimensionError(Reason.of(Code.DIM_ADDS, first=dim_text(nonzero[0][1]), other=dim_text(d),
                                           sum=_expr(e), term=_expr(v)))
    return nonzero[0][1] if nonzero else DIMENSIONLESS


class DimensionStatus(Enum):
    CONSISTENT = "consistent"
    INCONSISTENT = "inconsistent"
    UNDETERMINED = "undetermined"  # a dimension is not declared: nothing can be concluded


@dataclass(frozen=True)
class DimensionCheck:
    """The dimensional verdict on one relation, with the reason when it is not consistent."""

    status: DimensionStatus
    problem: Reason | None = None

    @property
    def inconsistent(self) -> bool:
        return self.status is DimensionStatus.INCONSISTENT

    @property
    def undetermined(self) -> bool:
        return self.status is DimensionStatus.UNDETERMINED

    def to_json(self) -> dict:
        return {"status": self.status.value, "problem": self.problem.to_json() if self.problem else None}

    @staticmethod
    def from_json(d: dict) -> "DimensionCheck":
        return DimensionCheck(DimensionStatus(d["status"]), Reason.from_json(d["problem"]) if d.get("problem") else None)


CONSISTENT = DimensionCheck(DimensionStatus.CONSISTENT)


def _sides(rel: sp.Basic) -> list:
    """The terms of lhs − rhs, as written (no term of one side merged with one of the other)."""
    return list(sp.Add.make_args(rel.lhs)) + [-t for t in sp.Add.make_args(rel.rhs)]


def check_relation(rel: sp.Basic, dims: dict) -> DimensionCheck:
    """Whether ``rel`` is dimensionally consistent; *undetermined* when a dimension is not
    declared (which proves nothing).  A relation compares its two sides (a side that is 0 or
    ±∞ matches any); where a side holds logarithms whose units cancel only against the other
    side's (ln L = −2κt + ln A), the two sides are checked as one sum, term by term.  An O-term
    has no dimension of its own (O(ν³) is "at most a constant times |ν³|", the constant taking
    whatever unit the sum needs): it is left out of the check."""
    if isinstance(rel, sp.Basic) and rel.has(Landau):
        rel = rel.replace(lambda a: isinstance(a, Landau), lambda a: sp.Integer(0))
    try:
        if isinstance(rel, sp.core.relational.Relational):
            try:
                dl, dr = dimension(rel.lhs, dims), dimension(rel.rhs, dims)
            except DimensionUnknown:
                raise
            except DimensionError as exc:
                if not (exc.reason.code is Code.DIM_ARGUMENT and exc.reason["function"] == "log"):
                    raise
                _sum(rel, _sides(rel), dims, False)  # the logarithms' units cancel across the sides
                return CONSISTENT
            if all(side not in (0, sp.oo, -sp.oo) for side in (rel.lhs, rel.rhs)) and not _same(dl, dr):
                return DimensionCheck(DimensionStatus.INCONSISTENT,
                                      Reason.of(Code.DIM_SIDES, left=dim_text(dl), right=dim_text(dr)))
        else:
            dimension(rel, dims)
    except DimensionUnknown as exc:
        return DimensionCheck(DimensionStatus.UNDETERMINED, exc.reason)
    except DimensionError as exc:
        return DimensionCheck(DimensionStatus.INCONSISTENT, exc.reason)
    return CONSISTENT


def summary(checks: tuple[DimensionCheck, ...]) -> str:
    """The findings on a verdict's relations as one line (the JSON's ``dimensions``):
    'consistent', 'inconsistent: …; …' (the inconsistent ones), or the undetermined ones."""
    from quasicentral.engine.wording import render

    bad = [c for c in checks if c.inconsistent]
    if bad:
        return "inconsistent: " + "; ".join(render(c.problem) for c in bad)
    unknown = [c for c in checks if c.undetermined]
    return "; ".join(f"undetermined: {render(c.problem)}" for c in unknown) if unknown else "consistent"
