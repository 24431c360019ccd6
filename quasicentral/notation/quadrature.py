"""Quadrature in mpmath at the working precision: tanh–sinh with guard digits, cut into pieces
where its error estimate asks for it, quadosc for an oscillating integrand on an unbounded path,
and what the integrand's form tells about its path (its jumps, its frequency).  Precision is
whatever local ``mpmath.workdps`` the caller opens.
"""

from __future__ import annotations

import mpmath
import sympy as sp


QUAD_MAX_PIECES = 64  # the most pieces mpmath's quadrature cuts a path into
QUAD_PIECES_GAIN = 100  # ... and the least gain in its error estimate for which it cuts further


#: the decades :func:`mass_scale` reads an integrand's mass at (10^j for j from −SCALE_REACH: SI
#: units span 10⁻³⁴ … 10²⁶), and its step; a scale within SCALE_KEPT decades of 1 is left as it is,
#: and so is one whose mass exceeds the mass near 1 by less than the factor SCALE_CLOSE
SCALE_REACH, SCALE_STEP, SCALE_KEPT, SCALE_CLOSE = 120, 3, 2, 10


def mass_scale(f, c, directions) -> "mpmath.mpf":
    """The power of ten s at which |f(c ± x)|·x, the integrand's mass per decade of x, is largest
    along an unbounded path from c — 1 where the mass near x = 1 is within :data:`SCALE_CLOSE`
    of that largest (a flat mass, K₁(x)·x → 1 at 0, moves nothing), where the largest lies within
    SCALE_KEPT decades of 1, or where the integrand cannot be read."""
    mass = {}
    with mpmath.workdps(15):
        for j in range(-SCALE_REACH, SCALE_REACH + 1, SCALE_STEP):
            x = mpmath.mpf(10) ** j
            for d in directions:
                try:
                    v = abs(f(c + d * x)) * x
                except (ValueError, ZeroDivisionError, TypeError, OverflowError, ArithmeticError):
                    continue
                if mpmath.isfinite(v) and v > mass.get(j, 0):
                    mass[j] = v
    if not mass:
        return mpmath.mpf(1)
    at = max(mass, key=lambda j: (mass[j], -abs(j)))
    near_one = max((mass.get(j, 0) for j in range(-SCALE_KEPT, SCALE_KEPT + 1)), default=0)
    if abs(at) <= SCALE_KEPT or near_one * SCALE_CLOSE >= mass[at]:
        return mpmath.mpf(1)
    return mpmath.mpf(10) ** at


def quad(f, interval, singular: bool = False, omega=None):
    """mpmath.quad with guard digits.  An integrand singular at an endpoint (1/√(1 − ζ²))
    loses about half the working digits to cancellation in 1 − ζ next to it, so there
    (``singular``, or a non-finite value at an end) the precision is doubled; elsewhere ten
    guard digits suffice.  On an unbounded path an integrand that oscillates with the angular
    frequency ``omega`` (sin ωt/t, J₀(ωt)) goes to mpmath's ``quadosc``, which sums it period
    by period and extrapolates: tanh–sinh alone returns 5.42 for ∫₀^∞ sin t/t dt = π/2."""
    dps = mpmath.mp.dps
    a, b = interval
    unbounded = not (mpmath.isfinite(a) and mpmath.isfinite(b))
    for end in (a, b):
        if not mpmath.isfinite(end):
            continue
        try:
            with mpmath.workdps(15):
                val = f(end)
            singular = singular or not mpmath.isfinite(val)
        except (ValueError, ZeroDivisionError, TypeError, OverflowError):
            singular = True
    if unbounded:  # tanh–sinh maps a half-line (or the line) itself; no cutting into pieces
        with mpmath.workdps(2 * dps if singular else dps + 10):
            # at the integrand's own scale: x = c + s·u (a Maxwell distribution in momentum,
            # width 10⁻²³ kg m/s, was off in the 11th digit on both rungs of the ladder)
            c = a if mpmath.isfinite(a) else b if mpmath.isfinite(b) else mpmath.mpf(0)
            s = mass_scale(f, c, [d for d, end in ((1, b), (-1, a)) if not mpmath.isfinite(end)] or [1])
            g = (lambda u: s * f(c + s * u)) if s != 1 else f
            lo, hi = ((a - c) / s if mpmath.isfinite(a) else a), ((b - c) / s if mpmath.isfinite(b) else b)
            if omega is not None and mpmath.im(omega) == 0 and mpmath.re(omega) > 0:
                return +mpmath.quadosc(g, [lo, hi], omega=mpmath.re(omega) * s)
            return +mpmath.quad(g, [lo, hi])
    # tanh–sinh on one interval misses oscillations over a long path (∫ sin² z … dz over
    # twenty radians is off in the 10th digit at 30 digits): where its error estimate exceeds
    # the working precision, the path is cut into more pieces — while cutting helps.  Where
    # four times the pieces do not gain QUAD_PIECES_GAIN in the estimate, the trouble is not
    # the path's length but a singularity inside it (a branch point of a root that turns
    # negative): more pieces would only cost time, and the value stands as it is, for the
    # precision ladder to judge
    with mpmath.workdps(2 * dps if singular else dps + 10):
        tol = mpmath.mpf(10) ** -dps
        pieces, before = 1, None
        while True:
            nodes = mpmath.linspace(a, b, pieces + 1) if pieces > 1 else [a, b]
            val, err = mpmath.quad(f, nodes, error=True)
            if err <= tol * max(abs(val), tol) or pieces >= QUAD_MAX_PIECES:
                break
            if before is not None and not err * QUAD_PIECES_GAIN <= before:
                break
            pieces, before = pieces * 4, err
    return +val


#: functions with a jump or a kink where their argument crosses zero
_KINKED = (sp.Abs, sp.sign, sp.Heaviside)


def breaks(f: sp.Expr, var: sp.Symbol) -> list:
    """Where ``f`` has a jump or a kink along its path: the zeros in ``var`` of the arguments of
    |·|, sign and Heaviside that sympy can solve (polynomials of degree ≤ 2 in the variable)."""
    out = []
    for g in f.atoms(*_KINKED):
        arg = g.args[0]
        if var in arg.free_symbols and arg.is_polynomial(var) and sp.degree(arg, var) <= 2:
            out += sp.solve(arg, var)
    return list(dict.fromkeys(out))


#: functions that oscillate in their last argument, with a period 2π/ω for an argument ωt + c
#: (the Bessel functions J, Y asymptotically)
_OSCILLATING = (sp.sin, sp.cos, sp.besselj, sp.bessely)


def frequency(f: sp.Expr, var: sp.Symbol) -> sp.Expr | None:
    """The angular frequency ω with which ``f`` oscillates in ``var`` where every oscillating
    factor has an argument ωt + c with one and the same |ω| (None where there is none, or
    several: tanh–sinh then, and the precision ladder judges)."""
    found = set()
    for g in f.atoms(*_OSCILLATING):
        arg = g.args[-1]
        if var not in arg.free_symbols:
            continue
        if not arg.is_polynomial(var) or sp.degree(arg, var) != 1:
            return None
        found.add(sp.Abs(sp.diff(arg, var)))
    return found.pop() if len(found) == 1 else None


def inside(c, a, b) -> bool:
    """Is the break ``c`` real and strictly between the ends (finite, in either order)?"""
    if not (mpmath.isfinite(c) and mpmath.isfinite(a) and mpmath.isfinite(b)):
        return False
    if abs(mpmath.im(c)) > 0 or mpmath.im(a) != 0 or mpmath.im(b) != 0:
        return False
    lo, hi = sorted((mpmath.re(a), mpmath.re(b)))
    return lo < mpmath.re(c) < hi
