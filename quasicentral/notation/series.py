"""A series summed term by term while its terms fall off geometrically, with a bound of its tail
(:func:`geometric_sum`): the direct way for the power series of a formula collection, before
the extrapolations of :mod:`quasicentral.notation.mpeval` take over.  At the caller's precision,
with guard bits."""

from __future__ import annotations

import mpmath

#: the most terms a series is summed term by term before extrapolation takes over
SERIES_TERMS = 400
#: the largest ratio of successive terms at which the tail is bounded geometrically
SERIES_RATIO = 0.95
#: the last terms whose ratios bound the tail
SERIES_WINDOW = 8


def geometric_sum(f, a, b):
    """Σ f(n) over a half-line (or the whole line, as two), term by term while the terms fall
    off at least geometrically: the sum stops where the tail bound |t|·r/(1 − r), r the largest
    ratio of the last :data:`SERIES_WINDOW` terms, is below the working precision.  None where
    the terms do not fall off so within :data:`SERIES_TERMS` (a series that converges slowly,
    or not: extrapolation, two ways, decides).  A power series inside its disc of convergence —
    most series of a formula collection — takes a few dozen terms this way, where Richardson's
    and Shanks's extrapolations take hundreds of evaluations and a quadratic cost."""
    if not mpmath.isfinite(a) and not mpmath.isfinite(b):
        right, left = geometric_sum(f, 0, mpmath.inf), geometric_sum(f, -mpmath.inf, -1)
        return None if right is None or left is None else right + left
    start, step = (a, 1) if mpmath.isfinite(a) else (b, -1)
    eps = mpmath.mpf(2) ** (-mpmath.mp.prec - 4)
    with mpmath.workprec(mpmath.mp.prec + 20):
        total, last, ratios = mpmath.mpf(0), None, []
        for i in range(SERIES_TERMS):
            t = f(start + step * i)
            total += t
            size = abs(t)
            if last is not None and last > 0:
                ratios = (ratios + [size / last])[-SERIES_WINDOW:]
            if size > 0:
                last = size
            if len(ratios) == SERIES_WINDOW:
                r = max(ratios)
                if r < SERIES_RATIO and size * r / (1 - r) <= eps * abs(total):
                    return +total
            if not mpmath.isfinite(total):
                return None
    return None
