"""The value of a limit lim_{x→x0} g(x) from the numbers alone, at the working precision: g is
an mpmath-callable (compiled by :mod:`quasicentral.notation.mpeval`), x0 finite or ±∞, from
one side or both.  Cheapest first — g(x0) where g is continuous, Richardson's step-halving
where it is smooth on each side, a power law c·h^p (the limit 0, ±∞, or a value approached as
√h) at tiny steps, g far out at powers of two with Aitken's Δ² — and mpmath's two sequences
last, which must agree.  Written here rather than taken from mpmath.limit alone: its sequences
(x0 + 1/n, or 2^n) start a unit away and extrapolate in integer powers, so a limit approached
as t^(−1/2) (erfc(x/(2√(at))) → 1 as t → ∞), a limit 0 or ∞ (no relative agreement) or a
function 10^30 times its limit a unit away never settles.  Precision is whatever local
``mpmath.workdps`` the caller opens.
"""

from __future__ import annotations

import mpmath

#: a series' or a limit's value stands where two ways of computing it agree to this fraction of
#: the working digits (else the point drops out: the precision ladder is not fooled by an
#: extrapolation that is stably wrong, as Richardson's is for a limit in √h)
AGREEMENT_FRACTION = 0.8
#: what evaluating g may raise at a point where it has no value: the method gives up there
_NO_VALUE = (ValueError, ZeroDivisionError, TypeError, OverflowError, ArithmeticError, mpmath.libmp.NoConvergence)


def agreeing(a, b):
    """``a`` where it and ``b`` agree to AGREEMENT_FRACTION of the working digits, else ValueError."""
    tol = mpmath.mpf(10) ** (-AGREEMENT_FRACTION * mpmath.mp.dps)
    if not (mpmath.isfinite(a) and mpmath.isfinite(b)) or abs(a - b) > tol * max(abs(a), abs(b), tol):
        raise ValueError("no value the numbers agree on (a series or a limit that converges too slowly here)")
    return a


def limit_value(g, x0, sides: tuple[int, ...]):
    """lim g at x0 from ``sides`` ((1,): from above, (−1,): from below, (1, −1): both, which
    must agree), or ValueError where no method settles it."""
    direct = _continuous_value(g, x0, sides)
    if direct is None:
        direct = _small_steps(g, x0, sides) if mpmath.isfinite(x0) else _far_out(g, x0)
    if direct is None and mpmath.isfinite(x0):
        direct = _power_law(g, x0, sides)
    if direct is not None:
        return direct
    out = []
    for direction in sides:
        # Richardson's extrapolation (mpmath's default) and the exponential sequence
        # (exp=True) must agree: each alone can be stably wrong
        out.append(agreeing(mpmath.limit(g, x0, direction=direction),
                            mpmath.limit(g, x0, direction=direction, exp=True)))
    return agreeing(out[0], out[-1])


#: the digits beyond a far evaluation's own at which it is repeated: where the two differ, what
#: cancels in g there needs more than it was given (T − p·e^(−2κw) at w = 2⁸ cancels 220 digits)
#: and the evaluation is no evidence at all
STABLE_EXTRA = 20


def _stable(g, x, digits: int, tol):
    """g(x) at ``digits`` where it agrees with g(x) at :data:`STABLE_EXTRA` more to ``tol``
    (relative), else ValueError: a value that only cancellation made (a far-out limit that
    seemed to grow without bound refuted a correct equation)."""
    with mpmath.workdps(digits):
        first = +g(x)
    with mpmath.workdps(digits + STABLE_EXTRA):
        second = +g(x)
    if mpmath.isfinite(first) != mpmath.isfinite(second) or (
            mpmath.isfinite(first) and abs(first - second) > tol * max(abs(first), abs(second))):
        raise ValueError("a value far out that more digits change (cancellation)")
    return first


def _aitken(vals, tol, scale):
    """The limit of a sequence that approaches it geometrically (g − L ~ c·r^n: a power law in
    h or x at steps by a constant factor) by Aitken's Δ² process, L ≈ v₂ − (Δv₂)²/Δ²v₁, where
    the last two estimates agree to ``tol``·``scale``; 0 where that estimate is itself below
    it; None else (a logarithm's growth: Δ² = 0; an oscillation: estimates that wander; a
    sequence whose steps do not shrink, for which Δ² gives the antilimit: x² at x = 2^k → 0)."""
    steps = [abs(b - a) for a, b in zip(vals, vals[1:])]
    if not all(later < earlier for earlier, later in zip(steps, steps[1:])):
        return None
    est = []
    for v0, v1, v2 in zip(vals, vals[1:], vals[2:]):
        second = (v2 - v1) - (v1 - v0)
        if second == 0:
            return None
        est.append(v2 - (v2 - v1) ** 2 / second)
    if len(est) < 2 or not all(mpmath.isfinite(e) for e in est[-2:]) or abs(est[-1] - est[-2]) > tol * scale:
        return None
    return +est[-1] if abs(est[-1]) > tol * scale else mpmath.mpf(0)


def _continuous_value(g, x0, sides):
    """g(x0) where g is continuous there: finite at x0 and, a step h = 10^(−dps/3)·max(1, |x0|)
    away on each side of the limit, within 10^(−dps/4) (relative) of it — three evaluations
    instead of an extrapolation's hundreds (DLMF 22.5.1's limit at K + iK′: 37 s → 4 s for the entry).
    None where g is not evaluable at x0 (0/0, a pole) or jumps there: the sequences decide."""
    if not mpmath.isfinite(x0):
        return None
    dps = mpmath.mp.dps
    try:
        v0 = g(x0)
        if not mpmath.isfinite(v0):
            return None
        h = mpmath.mpf(10) ** (-dps // 3) * max(1, abs(x0))
        near = [g(x0 + side * h) for side in sides]
    except _NO_VALUE:
        return None
    tol = mpmath.mpf(10) ** (-dps // 4) * max(1, abs(v0))
    return v0 if all(mpmath.isfinite(v) and abs(v - v0) <= tol for v in near) else None


#: the step exponents of :func:`_small_steps`: h = 10^(−dps/2 − k)·max(1, |x0|), for each k
SMALL_STEPS = (1, 2)


def _small_steps(g, x0, sides):
    """The limit of g at x0 where g cannot be evaluated at x0 (0/0: sin(ω_d t)/ω_d at ω_d = 0)
    but is smooth on each side: Richardson's step-halving 2g(x0 + h/2) − g(x0 + h), whose error
    is O(h²), from two tiny steps h (:data:`SMALL_STEPS`) at twice the working precision; the
    sides and the steps must agree to :data:`AGREEMENT_FRACTION` of the working digits, else
    None and the sequences decide.  The sequences (x0 + 1/n) start a unit away, where a function
    such as e^(−γt)·cosh(…) is 10^30 times its limit and their extrapolation loses every digit."""
    if not mpmath.isfinite(x0):
        return None
    dps = mpmath.mp.dps
    tol = mpmath.mpf(10) ** (-AGREEMENT_FRACTION * dps)
    try:
        with mpmath.workdps(2 * dps + 10):
            found = []
            for side in sides:
                for k in SMALL_STEPS:
                    h = mpmath.mpf(10) ** (-(dps // 2 + k)) * max(1, abs(x0))
                    found.append(2 * g(x0 + side * h / 2) - g(x0 + side * h))
    except _NO_VALUE:
        return None
    if not all(mpmath.isfinite(v) for v in found):
        return None
    size = max(abs(v) for v in found)
    if any(abs(v - found[0]) > tol * size for v in found[1:]):
        return None
    return +found[-1]


#: the decades :func:`_power_law` steps through: h = 10^(−dps − k)·max(1, |x0|), for each k
POWER_LAW_STEPS = (1, 2, 3, 4, 5)
#: the least exponent |p| of a power law g ~ c·h^p that :func:`_power_law` tells from a
#: constant (in digits per decade of h), and how far the exponents of successive decades may differ
POWER_LAW_LEAST, POWER_LAW_SPREAD = 0.25, 0.1


def _power_law(g, x0, sides):
    """The limit of g at x0 where g tends there as a power law and neither g(x0) nor
    Richardson's extrapolation gives a value: |g| at five decades of a step h below the working
    precision (:data:`POWER_LAW_STEPS`, at three times the digits) falls, or grows with one
    sign, by the same exponent at each decade (within :data:`POWER_LAW_SPREAD`, at least
    :data:`POWER_LAW_LEAST`): the limit 0 or ±∞ (sin²(ax)/x, sin(ax)/x² at 0 from the right);
    else g approaches a value as c·h^p, p > 0 not an integer (√h), and Aitken's Δ² finds it
    (:func:`_aitken`).  A logarithm's growth (exponent → 0) and an oscillation (exponents that
    differ) are neither: None, and the sequences decide.  The precision ladder moves the steps
    with the digits, so a function that only seems to vanish on one rung gives another value
    on the next and the point is unstable, not decided."""
    dps = mpmath.mp.dps
    tol = mpmath.mpf(10) ** (-AGREEMENT_FRACTION * dps)
    found = []
    try:
        with mpmath.workdps(3 * dps + 10):
            for side in sides:
                vals = [_stable(g, x0 + side * mpmath.mpf(10) ** (-(dps + k)) * max(1, abs(x0)), 3 * dps + 10, tol)
                        for k in POWER_LAW_STEPS]
                if not all(mpmath.isfinite(v) and v != 0 for v in vals):
                    return None
                found.append(_power_law_side(vals, tol))
    except _NO_VALUE:
        return None
    return found[0] if found[0] is not None and all(v == found[0] for v in found) else None


def _power_law_side(vals, tol):
    """One side of :func:`_power_law`: 0, ±∞, Aitken's value, or None."""
    if all(mpmath.im(v) == 0 for v in vals):
        slopes = [float(mpmath.log10(abs(b) / abs(a))) for a, b in zip(vals, vals[1:])]
        steady = max(slopes) - min(slopes) <= POWER_LAW_SPREAD * max(abs(s) for s in slopes)
        if steady and all(s <= -POWER_LAW_LEAST for s in slopes):
            return mpmath.mpf(0)
        if steady and all(s >= POWER_LAW_LEAST for s in slopes) and len({mpmath.sign(v) for v in vals}) == 1:
            return mpmath.sign(vals[0]) * mpmath.inf
    return _aitken(vals, tol, max(abs(v) for v in vals))


#: the powers of two :func:`_far_out` steps through: 2^8, 2^16, … up to 2^(FAR_OUT_REACH·dps)
FAR_OUT_STEP, FAR_OUT_REACH = 8, 5


def _far_out(g, x0):
    """The limit of g at ±∞ where g settles far out: g at ±2^8, ±2^16, … (up to
    2^(FAR_OUT_REACH·dps)), each at enough extra precision for what cancels in it there (eˣ − 1
    at x = θ/T, and its square e²ˣ − 2eˣ + 1: 0.61 digits per power of two), until three in a
    row agree to :data:`AGREEMENT_FRACTION` of the working digits.  The sequences (x = 1, 2, …)
    never leave a physical scale such as an Einstein temperature of 10³ K, where C_V(T) → 3Nk_B
    has not begun to settle.  A limit 0 or ±∞ never agrees so relative to itself: g tends to 0
    where three in a row fall in magnitude and the last is below that fraction of the largest seen (x²e^(−ax)), to ±∞ where three in a row grow with
    one sign beyond its inverse (e^(ax)); the precision ladder moves both thresholds, so a value
    that only seems to vanish on one rung leaves the point unstable.  A value approached as a
    power, c·x^(−p) (erfc(x/(2√(at))) → 1 as t^(−1/2)), is Aitken's (:func:`_aitken`) on the
    last five.  None where g does not settle so (a slow, logarithmic approach): the sequences
    decide."""
    dps = mpmath.mp.dps
    tol = mpmath.mpf(10) ** (-AGREEMENT_FRACTION * dps)
    sign = 1 if x0 > 0 else -1
    found: list = []
    try:
        for k in range(FAR_OUT_STEP, FAR_OUT_REACH * dps, FAR_OUT_STEP):
            found.append(_stable(g, sign * mpmath.mpf(2) ** k, dps + int(0.61 * k) + 10, tol))
            if not mpmath.isfinite(found[-1]):
                return None
            last = found[-3:]
            if len(last) < 3:
                continue
            size = max(abs(v) for v in last)
            if all(abs(v - last[-1]) <= tol * size for v in last):
                return +last[-1]
            if len(found) >= 5:
                geometric = _aitken(found[-5:], tol, max(abs(v) for v in found[-5:]))
                if geometric is not None:
                    return geometric
            mags = [abs(v) for v in last]
            if mags[0] > mags[1] > mags[2] and mags[2] <= tol * max(abs(v) for v in found):
                return mpmath.mpf(0)
            if (mags[0] < mags[1] < mags[2] and mags[2] * tol >= max(1, abs(found[0]))
                    and mpmath.im(last[-1]) == 0 and len({mpmath.sign(v) for v in last}) == 1):
                return mpmath.sign(last[-1]) * mpmath.inf
    except _NO_VALUE:
        return None
    return None
