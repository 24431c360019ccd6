"""Quadratic drag: the first-order closed form (valid for all t and every k²) against a
40-digit evaluation, against the linearized forced equations integrated numerically, and the
first-order error against the full motion (26)–(27), which must shrink like β²."""

import math

import mpmath
import numpy as np
import pytest
from scipy.integrate import solve_ivp

from quasicentral.models import quadratic as Q

OMEGA = math.sqrt(10.0)
R0 = 0.1


def v0_for(k2):
    """v0 giving k² = 1 − (v0/u)² with u = R0Ω."""
    return R0 * OMEGA * math.sqrt(1 - k2)


def linearized(t, v0, beta):
    """The forced linear equations of the first-order step (ellipse velocities in the drag)."""
    def rhs(tt, s):
        xd, yd = -R0 * OMEGA * math.sin(OMEGA * tt), v0 * math.cos(OMEGA * tt)
        sp = math.hypot(xd, yd)
        return (s[2], s[3], -OMEGA**2 * s[0] - beta * xd * sp, -OMEGA**2 * s[1] - beta * yd * sp)

    sol = solve_ivp(rhs, (0, t.max()), (R0, 0, 0, v0), method="DOP853", t_eval=t, rtol=1e-13, atol=1e-17)
    return sol.y[0], sol.y[1]


K2 = [-2.0, -0.5, -1e-13, 0.0, 1e-13, 0.3, 0.9, 0.999, 1.0]


@pytest.mark.parametrize("k2", K2)
def test_against_linearized_integration_over_ten_half_periods(k2):
    t = np.linspace(0, 10 * math.pi / OMEGA, 157)
    v0 = v0_for(k2)
    x, y = Q.first_order(t, R0, v0, OMEGA, 0.7)
    xl, yl = linearized(t, v0, 0.7)
    scale = max(R0, v0 / OMEGA)
    assert np.max(np.abs(x - xl)) < 1e-12 * scale and np.max(np.abs(y - yl)) < 1e-12 * scale


@pytest.mark.parametrize("k2", [-2.0, -1e-13, 0.0, 1e-13, 0.5, 0.999])
def test_double_against_40_digits_at_multiples_of_pi(k2):
    theta = np.concatenate([np.arange(0, 11) * math.pi, np.linspace(0, 10 * math.pi, 41)])
    t = theta / OMEGA
    v0 = v0_for(k2)
    x, y = Q.first_order(t, R0, v0, OMEGA, 0.7)
    with mpmath.workdps(40):
        xm, ym = Q.first_order([mpmath.mpf(float(a)) for a in t], mpmath.mpf(R0), mpmath.mpf(v0),
                               mpmath.mpf(OMEGA), mpmath.mpf(0.7), ops=Q.MP)
    scale = max(R0, v0 / OMEGA)
    ex = max(abs(float(a) - b) for a, b in zip(xm, x)) / scale
    ey = max(abs(float(a) - b) for a, b in zip(ym, y)) / scale
    assert ex < 1e-13 and ey < 1e-13


def test_conical_limit_matches_31_32():
    """k → 0 (u = v0): (31)–(32) with their constants."""
    t = np.linspace(0, 8 * math.pi / OMEGA, 50)
    v0, beta = R0 * OMEGA, 0.4
    x, y = Q.first_order(t, R0, v0, OMEGA, beta)
    th = OMEGA * t
    x31 = R0 * np.cos(th) + beta * R0**2 * (np.sin(2 * th) / 4 - th / 2) * np.cos(th) + beta * R0**2 / 2 * np.sin(th) ** 3
    y32 = (v0 / OMEGA * np.sin(th) - beta * v0**2 / OMEGA**2 * (th / 2 + np.sin(2 * th) / 4) * np.sin(th)
           + beta * v0**2 / (2 * OMEGA**2) * np.sin(th) ** 2 * np.cos(th))
    assert np.max(np.abs(x - x31)) < 1e-15 and np.max(np.abs(y - y32)) < 1e-15
    # (33): after one revolution x = R0(1 − πβR0)
    xr, _ = Q.first_order([2 * math.pi / OMEGA], R0, v0, OMEGA, beta)
    assert abs(xr[0] - R0 * (1 - math.pi * beta * R0)) < 1e-16


def test_first_order_error_shrinks_like_beta_squared():
    """Fit the exponent of max |first order − full| over 0 ≤ Ωt ≤ 4π against β."""
    t = np.linspace(0, 4 * math.pi / OMEGA, 200)
    betas = np.array([0.02, 0.04, 0.08, 0.16, 0.32])
    errs = []
    for b in betas:
        x1, y1 = Q.first_order(t, R0, 0.2, OMEGA, b)
        xf, yf = Q.integrate_full(t, R0, 0.2, OMEGA, b, rtol=1e-13)
        errs.append(max(np.max(np.abs(x1 - xf)), np.max(np.abs(y1 - yf))))
    slope, _ = np.polyfit(np.log(betas), np.log(errs), 1)
    assert 1.9 < slope < 2.1


def test_full_motion_obeys_angular_momentum_law_5():
    """x ẏ − y ẋ = R0 v0 e^{−βs} along the numerical solution of (26)–(27)."""
    beta, v0 = 0.8, 0.2
    w2 = OMEGA**2

    def rhs(_t, s):
        sp = math.hypot(s[2], s[3])
        return (s[2], s[3], -w2 * s[0] - beta * s[2] * sp, -w2 * s[1] - beta * s[3] * sp, sp)

    sol = solve_ivp(rhs, (0, 6), (R0, 0, 0, v0, 0), method="DOP853", rtol=1e-12, atol=1e-15, dense_output=True)
    for tt in np.linspace(0, 6, 13):
        x, y, vx, vy, s = sol.sol(tt)
        assert abs(x * vy - y * vx - R0 * v0 * math.exp(-beta * s)) < 1e-11 * R0 * v0


def test_full_motion_double_against_mpmath():
    t = [0.7, 2.1]
    xd, yd = Q.integrate_full(np.array(t), R0, 0.2, OMEGA, 0.5)
    with mpmath.workdps(25):
        xm, ym = Q.integrate_full_mp(t, mpmath.mpf(R0), mpmath.mpf(0.2), mpmath.mpf(OMEGA), mpmath.mpf(0.5), 20)
    assert max(abs(float(a) - b) for a, b in zip(xm, xd)) < 1e-12 * R0
    assert max(abs(float(a) - b) for a, b in zip(ym, yd)) < 1e-12 * R0
