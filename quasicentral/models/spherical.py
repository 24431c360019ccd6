"""The full (not small-swing) spherical pendulum with drag: the reference the paper's
approximations are measured against.

Coordinates without the singularity of (6)–(7) at the lowest point: the horizontal
displacement (X, Y) of the bob, with Z = √(l² − X² − Y²) its depth below the pivot.  The bob
moves on the sphere |r| = l under gravity, the string's tension along −r, and a drag
−γ(v)·ṙ with γ = 2κ (R = 2κmv) or γ = βv (R = mβv²).  The drag is tangent to the sphere, so the
tension follows from the constraint alone (r·r̈ = −|ṙ|²), and

    Ẍ = −γẊ − X (v² + gZ)/l²,    Ÿ = −γẎ − Y (v² + gZ)/l²,    v² = Ẋ² + Ẏ² + Ż²,
    Ż = −(XẊ + YẎ)/Z.

Small swings (Z ≈ l, v² ≪ gl) give back (16)–(17) and (26)–(27).  Exact laws along the
solution, used to validate any integration: the vertical angular momentum L = XẎ − YẊ obeys
L̇ = −γL (so L = L0 e^{−2κt} for linear drag, the law (4) without approximation, and
L = L0 e^{−βs} for quadratic drag, (5)); the energy ½v² − gZ decreases at the rate γv².

Initial conditions as in the paper: X = R0, Y = 0, Ẋ = 0, Ẏ = v0 (horizontal velocity).
"""

from __future__ import annotations

import math

import numpy as np

from quasicentral.models import reference
from quasicentral.models.equations import System, rhs
from quasicentral.models.parameters import ParameterError, Swing

ModelError = ParameterError


def rhs_factory(length, g, kappa=0.0, beta=0.0, lib=math):
    """The right-hand side f(t, s) for s = (X, Y, Ẋ, Ẏ) in a given arithmetic (math or mpmath):
    :func:`quasicentral.models.equations.rhs` of the spherical system with this drag."""
    if beta:
        return rhs(System.SPHERICAL_QUADRATIC, (length, g, beta), lib)
    return rhs(System.SPHERICAL_LINEAR, (length, g, 2 * kappa), lib)


def _params(R0, v0, length, g, kappa, beta) -> dict:
    return {"R0": R0, "v0": v0, "l": length, "g": g, "kappa": kappa, "beta": beta}


def integrate(t, R0, v0, length, g, kappa=0.0, beta=0.0, rtol=1e-12):
    """(X, Y) at times ``t`` as float arrays (scipy DOP853 with dense output at ``rtol``).  A
    planar swing (v0 = 0) under quadratic drag has a kink where the speed passes through zero:
    it is integrated by :func:`reference.solve`, which restarts at each turning point (at the
    tolerance 10·rtol: its own rtol is a tenth of the tolerance)."""
    from scipy.integrate import solve_ivp

    Swing(R0, v0, g / length, kappa, beta, length, g)
    t = np.asarray(t, dtype=float)
    if beta and v0 == 0:
        tol = 10 * rtol
        sol = reference.solve("spherical", _params(R0, v0, length, g, kappa, beta), t, tol=tol,
                              method="dop853" if tol >= 1e-14 else "auto")
        return np.asarray(sol.x, dtype=float), np.asarray(sol.y, dtype=float)
    sol = solve_ivp(rhs_factory(length, g, kappa, beta), (0.0, float(t.max())), np.array([R0, 0.0, 0.0, v0]),
                    method="DOP853", t_eval=t, rtol=rtol, atol=rtol * R0 * 1e-2)
    if not sol.success:
        raise ModelError(f"the integration failed: {sol.message}")
    return sol.y[0], sol.y[1]


def integrate_mp(t, R0, v0, length, g, kappa=0, beta=0, dps: int = 30):
    """(X, Y) at times ``t`` with mpmath's Taylor-series integrator at ``dps`` digits (object
    arrays of mpmath numbers; a planar swing restarted at its turning points)."""
    sol = reference.solve("spherical", _params(R0, v0, length, g, kappa, beta), list(t), tol=10.0**-dps,
                          method="mpmath")
    return sol.x, sol.y


def invariants(state, length, g):
    """(L, E): the vertical angular momentum XẎ − YẊ and the energy per mass ½v² − gZ."""
    X, Y, U, W = state
    Z = math.sqrt(length**2 - X * X - Y * Y)
    Zd = -(X * U + Y * W) / Z
    return X * W - Y * U, 0.5 * (U * U + W * W + Zd * Zd) - g * Z
