"""Helpers of the measurements: errors in mpmath, rows of the tables."""

from __future__ import annotations

import mpmath

from quasicentral.models.parameters import FIGURE_OMEGA as OMEGA  # noqa: F401 - the figures' Ω = √10


def rel(value, ref) -> float:
    """|value − ref| / |ref| in mpmath at the reference's precision (0 when exact)."""
    v = mpmath.mpf(value) if not isinstance(value, mpmath.mpf) else value
    return float(abs(v - ref) / abs(ref))


def traj_err(x, y, xr, yr, scale) -> float:
    """max |Δx|, |Δy| over the points, / scale; NaN when the method returned a non-finite value."""
    e = mpmath.mpf(0)
    for a, b in list(zip(x, xr)) + list(zip(y, yr)):
        a = mpmath.mpf(a)
        if not mpmath.isfinite(a):
            return float("nan")
        e = max(e, abs(a - b))
    return float(e / scale)


def row(quantity, case, method, family, setting, seconds, error, **extra):
    r = {"quantity": quantity, "case": case, "method": method, "family": family, "setting": str(setting),
         "seconds": seconds, "error": error}
    r.update(extra)
    return r
