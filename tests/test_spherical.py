"""The full spherical pendulum with drag: exact laws along the numerical solution, the
small-swing limit, and double precision against mpmath (planar swings across the kink too)."""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from quasicentral.models import motion

from quasicentral.models import spherical as S

L_, G_ = 1.0, 10.0
OMEGA = math.sqrt(G_ / L_)


def _solve(R0, v0, kappa=0.0, beta=0.0, t_end=6.0):
    f = S.rhs_factory(L_, G_, kappa, beta)
    return solve_ivp(f, (0, t_end), (R0, 0, 0, v0), method="DOP853", rtol=1e-12, atol=1e-15, dense_output=True)


def test_angular_momentum_decays_exactly_as_law_4_for_large_swings():
    R0, v0, kappa = 0.6, 1.2, 0.35
    sol = _solve(R0, v0, kappa=kappa)
    for t in np.linspace(0, 6, 13):
        L, _ = S.invariants(sol.sol(t), L_, G_)
        assert abs(L - R0 * v0 * math.exp(-2 * kappa * t)) < 1e-10 * R0 * v0


def test_energy_decreases_under_drag():
    sol = _solve(0.6, 1.2, beta=0.7)
    energies = [S.invariants(sol.sol(t), L_, G_)[1] for t in np.linspace(0, 6, 61)]
    assert all(b <= a + 1e-12 for a, b in zip(energies, energies[1:]))


@pytest.mark.parametrize("R0", [1e-3, 1e-2, 1e-1])
def test_small_swing_limit_is_the_linear_model(R0):
    """The relative error of the small-swing model shrinks like R0²."""
    t = np.linspace(0, 4 * 2 * math.pi / OMEGA, 80)
    X, _ = S.integrate(t, R0, 0.5 * R0 * OMEGA, L_, G_, kappa=0.3)
    x, _ = motion.linear(t, R0, 0.5 * R0 * OMEGA, OMEGA, 0.3)
    rel = np.max(np.abs(X - x)) / R0
    assert 0.01 * R0**2 < rel < 0.2 * R0**2


def test_planar_quadratic_drag_keeps_order_across_the_kink():
    t = np.linspace(0, 3 * 2 * math.pi / OMEGA, 9)
    X, _ = S.integrate(t, 0.3, 0.0, L_, G_, beta=0.5, rtol=1e-13)
    assert np.all(np.isfinite(X))
    Xm, _ = S.integrate_mp(list(t), 0.3, 0.0, L_, G_, beta=0.5, dps=20)
    assert max(abs(float(a) - b) for a, b in zip(Xm, X)) < 1e-12


def test_bad_parameters():
    for args in [(0.0, 1.0), (1.5, 1.0), (0.3, -1.0)]:
        with pytest.raises(S.ModelError):
            S.integrate([0, 1], *args, L_, G_)
