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

import mpmath
import numpy as np


class ModelError(ValueError):
    pass


def _check(R0, v0, length, g, kappa, beta):
    if not (length > 0 and g > 0):
        raise ModelError("the length and g must be positive")
    if not 0 < R0 < length:
        raise ModelError("R0 must be in (0, l): the bob starts below the pivot's horizontal")
    if v0 < 0 or kappa < 0 or beta < 0:
        raise ModelError("v0, kappa and beta must be ≥ 0")
    if kappa and beta:
        raise ModelError("give one drag law: kappa (linear) or beta (quadratic)")


def rhs_factory(length, g, kappa=0.0, beta=0.0, lib=math):
    """The right-hand side f(t, s) for s = (X, Y, Ẋ, Ẏ) in a given arithmetic (math or mpmath)."""
    l2 = length * length

    def f(_t, s):
        X, Y, U, W = s
        Z = lib.sqrt(l2 - X * X - Y * Y)
        Zd = -(X * U + Y * W) / Z
        v2 = U * U + W * W + Zd * Zd
        gamma = 2 * kappa if not beta else beta * lib.sqrt(v2)
        c = (v2 + g * Z) / l2
        return [U, W, -gamma * U - X * c, -gamma * W - Y * c]

    return f


def integrate(t, R0, v0, length, g, kappa=0.0, beta=0.0, rtol=1e-12):
    """(X, Y) at times ``t`` (scipy DOP853).  A planar swing (v0 = 0) under quadratic drag has
    a kink where the speed passes through zero (the turning points): the integration is
    restarted there, so the method keeps its order and never steps across the kink."""
    from scipy.integrate import solve_ivp

    _check(R0, v0, length, g, kappa, beta)
    t = np.asarray(t, dtype=float)
    f = rhs_factory(length, g, kappa, beta)
    state = np.array([R0, 0.0, 0.0, v0])
    atol = rtol * R0 * 1e-2
    if not (beta and v0 == 0):
        sol = solve_ivp(f, (0.0, float(t.max())), state, method="DOP853", t_eval=t, rtol=rtol, atol=atol)
        if not sol.success:
            raise ModelError(f"the integration failed: {sol.message}")
        return sol.y[0], sol.y[1]

    def turning(_t, s):  # planar: the speed vanishes where Ẋ does
        return s[2]

    turning.terminal = True
    X = np.full_like(t, np.nan)
    Y = np.zeros_like(t)
    t0, end = 0.0, float(t.max())
    sig = -1.0 if R0 > 0 else 1.0  # from rest the bob first moves towards the vertical
    while True:
        # the segment starts at rest (Ẋ = 0): only the crossing back through 0 ends it
        turning.direction = -sig
        sol = solve_ivp(f, (t0, end), state, method="DOP853", rtol=rtol, atol=atol, events=turning,
                        dense_output=True)
        if not sol.success:
            raise ModelError(f"the integration failed: {sol.message}")
        seg_end = sol.t[-1]
        mask = (t >= t0) & (t <= seg_end)
        if mask.any():
            X[mask] = sol.sol(t[mask])[0]
        if sol.status != 1 or seg_end >= end:
            break
        state = sol.y_events[0][0].copy()
        state[2] = 0.0  # exactly at rest
        t0, sig = seg_end, -sig
    return X, Y


def integrate_mp(t, R0, v0, length, g, kappa=0, beta=0, dps: int = 30):
    """(X, Y) at times ``t`` with mpmath's Taylor-series integrator at ``dps`` digits."""
    from quasicentral.models.quadratic import planar_segments

    with mpmath.workdps(dps + 10):
        args = [mpmath.mpf(a) for a in (R0, v0, length, g, kappa, beta)]
        _check(*args)
        R0, v0, length, g, kappa, beta = args
        if beta and v0 == 0:
            # planar: v = |Ẋ| l/Z, analytic as σẊ l/Z between turning points
            def rhs(sig):
                def f1(_t, s):
                    X, U = s
                    Z = mpmath.sqrt(length**2 - X * X)
                    v2 = U * U * length**2 / (Z * Z)
                    return [U, -beta * sig * U * length / Z * U - X * (v2 + g * Z) / length**2]
                return f1

            xs = planar_segments(rhs, R0, t, 2 * mpmath.pi * mpmath.sqrt(length / g))
            return np.array(xs, dtype=object), np.array([mpmath.mpf(0)] * len(xs), dtype=object)
        f = rhs_factory(length, g, kappa, beta, lib=mpmath)
        sol = mpmath.odefun(f, 0, [args[0], mpmath.mpf(0), mpmath.mpf(0), args[1]])
        out = [sol(mpmath.mpf(tt)) for tt in t]
        return np.array([s[0] for s in out], dtype=object), np.array([s[1] for s in out], dtype=object)


def invariants(state, length, g):
    """(L, E): the vertical angular momentum XẎ − YẊ and the energy per mass ½v² − gZ."""
    X, Y, U, W = state
    Z = math.sqrt(length**2 - X * X - Y * Y)
    Zd = -(X * U + Y * W) / Z
    return X * W - Y * U, 0.5 * (U * U + W * W + Zd * Zd) - g * Z
