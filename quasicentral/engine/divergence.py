"""Divergent printed forms, seen in a few evaluations: an integral whose integrand is not
integrable at an end of its path, a series whose terms grow, a two-sided limit whose one-sided
limits differ.  Each returns a
:class:`~quasicentral.engine.reasons.Reason` (or None where no divergence is seen)."""

from __future__ import annotations

import mpmath
import sympy as sp

from quasicentral.engine.reasons import Code, Reason
from quasicentral.notation import bridge
from quasicentral.notation.quadrature import mass_scale
from quasicentral.notation.timelimit import TimeLimitExceeded, time_limit

#: the growth order q in |f| ~ |x − e|^(−q) from which an end is not integrable (1, less a margin)
NOT_INTEGRABLE = 1 - 1e-3
#: ... and at an infinite end, |f| ~ |x|^(−q) with q at most this is not integrable
NOT_DECAYING = 1 + 1e-3
_ERRORS = (ValueError, ZeroDivisionError, TypeError, OverflowError, ArithmeticError, AttributeError)


#: the distances 10^(−d) from a finite end at which the integrand's growth is read, and how far the
#: two orders they give may differ (relative) for a power law |x − e|^(−q)
NEAR, POWER_SPREAD = (10, 20, 30), 0.1
#: where an infinite end is probed: x = 10^10 … 10^19 (an oscillating integrand changes sign there)
FAR = tuple(10 ** k for k in range(10, 20))


def _decay(f, values, sign) -> object | None:
    """The decay order q of |f| ~ |x|^(−q) far out (None unless it is at most
    :data:`NOT_DECAYING` at every probe of :data:`FAR`, with one sign throughout and
    |f|·|x|^NOT_DECAYING never falling: a tail that is not integrable)."""
    # far from the integrand's own scale (a Planck spectrum in hertz peaks at 10¹⁴: 10¹⁰ is not far out)
    scale = mass_scale(lambda x: f(x, *values), mpmath.mpf(0), [sign])
    xs = [sign * scale * mpmath.mpf(x) for x in FAR]
    fs = [f(x, *values) for x in xs]
    if not all(isinstance(v, mpmath.mpf) and mpmath.isfinite(v) and v != 0 for v in fs):
        return None
    if len({v > 0 for v in fs}) != 1:
        return None
    weighted = [abs(v) * abs(x) ** NOT_DECAYING for v, x in zip(fs, xs)]
    if any(b < a for a, b in zip(weighted, weighted[1:])):
        return None
    return mpmath.log(abs(fs[0]) / abs(fs[-1])) / mpmath.log(abs(xs[-1] / xs[0]))


def integral_divergence(expr: sp.Expr, pt: dict) -> Reason | None:
    """Why an integral of ``expr`` diverges at the point ``pt`` (None if none is seen): at a
    finite end where the integrand is unbounded, its growth order q in |f| ~ |x − e|^(−q) is
    estimated from the distances 1e-10 and 1e-20 at 40 digits, q ≥ 1 − 1e-3 not being
    integrable, where the distances 1e-20 and 1e-30 give the same order; at an infinite end,
    from |f| at 1e10 … 1e19 times the integrand's scale: a decay no faster than 1/x is not
    integrable."""
    for integral in expr.atoms(sp.Integral):
        if len(integral.limits) != 1 or len(integral.limits[0]) != 3:
            continue
        x, a, b = integral.limits[0]
        outer = tuple(sorted(integral.function.free_symbols - {x}, key=str))
        if any(s not in pt for s in outer):
            continue
        try:
            with mpmath.workdps(40):
                found = _integral_end(integral.function, x, outer, [sp.sympify(e).xreplace(pt) for e in (a, b)], pt)
        except _ERRORS:
            continue
        if found is not None:
            return found
    return None


def _integral_end(function, x, outer, ends, pt) -> Reason | None:
    # compiled once for every point (mp_function remembers it), the point's values as arguments
    f = bridge.mp_function(function, (x,) + outer)
    values = [bridge.mp_value(pt[s], 40) for s in outer]
    finite = [bridge.mp_value(e, 40) if e not in (sp.oo, -sp.oo) else None for e in ends]
    for i, (end, inward) in enumerate(((ends[0], 1), (ends[1], -1))):
        if end in (sp.oo, -sp.oo):
            q = _decay(f, values, 1 if end is sp.oo else -1)
            if q is not None:
                return Reason.of(Code.INTEGRAND_GROWS, variable=str(x), end=("∞" if end is sp.oo else "−∞"),
                                 order=mpmath.nstr(-q, 3))
            continue
        e = finite[i]
        if mpmath.im(e) != 0:
            continue
        other = finite[1 - i]
        direction = inward if other is None or other >= e else -inward
        if other is None:
            direction = 1 if ends[1 - i] is sp.oo else -1
        g1, g2, g3 = (abs(f(e + direction * mpmath.mpf(10) ** -d, *values)) for d in NEAR)
        if not all(mpmath.isfinite(g) for g in (g1, g2, g3)) or g1 == 0 or g2 <= g1:
            continue
        q = mpmath.log(g2 / g1) / mpmath.log(mpmath.mpf(10) ** 10)
        q_nearer = mpmath.log(g3 / g2) / mpmath.log(mpmath.mpf(10) ** 10)
        # a power law holds at both decades (1/x: 1 and 1); a narrow bump beside the end is no
        # growth (e^(−p²/2mkT), width 10⁻²³: "orders" 10²³ and 10³)
        if q >= NOT_INTEGRABLE and abs(q - q_nearer) <= POWER_SPREAD * q:
            return Reason.of(Code.INTEGRAND_GROWS, variable=str(x), end=mpmath.nstr(e, 8), order=mpmath.nstr(q, 3))
    return None


#: the first terms of a sum or product (and the last of a finite one) tested for a pole
TERMS_TESTED = 8


def undefined_term(expr: sp.Expr, pt: dict) -> Reason | None:
    """A sum or product of ``expr`` with a term at a pole at ``pt`` (sympy's exact value of the
    term is ∞ or undefined: 1/(j(j − 1)) at j = 1): the printed form has no value.  The first
    and the last :data:`TERMS_TESTED` terms are tested, exactly."""
    for sm in expr.atoms(sp.Sum, sp.Product):
        if len(sm.limits) != 1:
            continue
        var, lo, hi = sm.limits[0]
        term = sm.function.xreplace(pt)
        lo, hi = sp.sympify(lo).xreplace(pt), sp.sympify(hi).xreplace(pt)
        if term.free_symbols - {var} or not (lo.is_integer or lo.is_infinite) or not (hi.is_integer or hi.is_infinite):
            continue
        indices = []
        if lo.is_finite:
            indices += [lo + i for i in range(TERMS_TESTED)]
        if hi.is_finite:
            indices += [hi - i for i in range(TERMS_TESTED)]
        if lo.is_finite and hi.is_finite:
            indices = [k for k in indices if lo <= k <= hi]
        for k in sorted(set(indices)):
            try:
                with time_limit(1.0) as limit:
                    value = term.subs(var, k)
            except TimeLimitExceeded as exc:
                if limit is None or not limit.owns(exc):
                    raise
                break
            except _ERRORS:
                continue
            if value.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
                return Reason.of(Code.UNDEFINED_TERM, variable=str(var), index=str(k))
    return None


def series_divergence(expr: sp.Expr, pt: dict) -> Reason | None:
    """Why an infinite series of ``expr`` diverges at ``pt`` (None if none is seen): the ratio
    test, |a(n+1)/a(n)| at n = 100 and 200 (30 digits), both above 1 + 1e-3 and not falling."""
    for sm in expr.atoms(sp.Sum):
        if len(sm.limits) != 1 or sm.limits[0][2] is not sp.oo:
            continue
        var = sm.limits[0][0]
        term = sm.function.xreplace(pt)
        if term.free_symbols - {var}:
            continue
        try:
            with time_limit(2.0) as limit:
                r = [abs(sp.N(term.subs(var, k + 1) / term.subs(var, k), 30)) for k in (100, 200)]
        except TimeLimitExceeded as exc:
            if limit is None or not limit.owns(exc):
                raise
            continue
        except _ERRORS:
            continue
        if all(x.is_number and x.is_finite for x in r) and r[0] > 1 + 1e-3 and r[1] >= r[0] * (1 - 1e-6):
            return Reason.of(Code.TERMS_GROW, variable=str(var), ratio100=str(sp.N(r[0], 4)),
                             ratio200=str(sp.N(r[1], 4)))
    return None


#: one-sided limits that differ by more than this (relative to max(1, their size)) are different
SIDES_APART = 1e-12


def limit_nonexistent(expr: sp.Expr, pt: dict) -> Reason | None:
    """Why a two-sided limit of ``expr`` does not exist at ``pt`` (None if it is not seen): its
    limits from the left and from the right, each where two sequences agree on it (30 digits),
    differ.  A jump (atan(1/y) at 0) leaves the two-sided limit without a value, and a printed
    value for it is false."""
    for lim in expr.atoms(sp.Limit):
        body, var, at, side = lim.args
        if str(side) != "+-":
            continue
        outer = tuple(sorted(lim.free_symbols, key=str))
        if any(s not in pt for s in outer):
            continue
        try:
            with mpmath.workdps(30):
                values = [bridge.mp_value(pt[s], 30) for s in outer]
                left, right = (bridge.mp_function(sp.Limit(body, var, at, d), outer)(*values) for d in "-+")
        except _ERRORS:
            continue
        if not (mpmath.isfinite(left) and mpmath.isfinite(right)):
            continue
        if abs(left - right) > SIDES_APART * max(1, abs(left), abs(right)):
            return Reason.of(Code.NO_LIMIT, variable=str(var), point=sp.sstr(at.xreplace(pt)),
                             left=mpmath.nstr(left, 6), right=mpmath.nstr(right, 6))
    return None
