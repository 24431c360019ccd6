"""The reference integrators: validated against the closed form where it is exact (linear
drag), against the exact laws (4), (5) and the energy balance, against themselves at two
precisions, across the kink of a planar swing; and the error of the paper's approximations."""

import math

import mpmath
import numpy as np
import pytest
from hypothesis import HealthCheck, example, given, settings, strategies as st

from quasicentral.models import motion

from quasicentral.models import period

from quasicentral.models import quadratic

from quasicentral.models import reference as R
from quasicentral.models import accuracy as A

OMEGA = math.sqrt(10.0)
T = 2 * math.pi / OMEGA
TEN = np.linspace(T / 3, 10 * T, 12)  # 10 periods
needs_heyoka = pytest.mark.skipif(not R.heyoka_available(), reason="heyoka (quasicentral[fast]) not installed")


def lin(kappa, v0=0.1):
    return {"R0": 0.1, "v0": v0, "omega2": OMEGA**2, "kappa": kappa}


# --- against the closed form ---------------------------------------------------------------------
@pytest.mark.parametrize("ratio", [0.0, 0.13, 1.0, 2.0])  # undamped, underdamped, aperiodic, overdamped
def test_dop853_against_the_closed_form_over_ten_periods(ratio):
    sol = R.solve("linear", lin(ratio * OMEGA), TEN, tol=1e-12, method="dop853")
    assert sol.method == "dop853" and sol.x.dtype == float
    assert A.closed_form_error(sol) < 1e-12


@needs_heyoka
@pytest.mark.parametrize("tol", [1e-20, 1e-30])
def test_heyoka_against_the_closed_form_at_high_precision(tol):
    sol = R.solve("linear", lin(0.4), TEN, tol=tol)
    assert sol.method == "heyoka" and sol.x.dtype == object
    assert A.closed_form_error(sol) < tol


def test_without_heyoka_auto_falls_back_to_mpmath(monkeypatch):
    monkeypatch.setattr(R, "heyoka_available", lambda: False)
    sol = R.solve("quadratic", {"R0": 0.1, "v0": 0.2, "omega2": OMEGA**2, "beta": 0.5}, [0.2], tol=1e-18)
    assert sol.method == "mpmath"
    with pytest.raises(R.ModelError):
        R.solve("linear", lin(0.4), [0.2], tol=1e-18, method="heyoka")


def test_mpmath_fallback_against_the_closed_form():
    sol = R.solve("linear", lin(0.4), [0.3, 0.9], tol=1e-18, method="mpmath")
    assert A.closed_form_error(sol) < 1e-18


# --- the exact laws --------------------------------------------------------------------------------
CASES = [("linear", lin(0.4)),
         ("quadratic", {"R0": 0.1, "v0": 0.2, "omega2": OMEGA**2, "beta": 0.5}),
         ("quadratic", {"R0": 0.1, "v0": 0.0, "omega2": OMEGA**2, "beta": 0.5}),
         ("spherical", {"R0": 0.5, "v0": 0.8, "l": 1.0, "g": 10.0, "beta": 0.5}),
         ("spherical", {"R0": 0.5, "v0": 0.0, "l": 1.0, "g": 10.0, "beta": 0.5}),
         ("spherical", {"R0": 0.5, "v0": 0.8, "l": 1.0, "g": 10.0, "kappa": 0.2})]
IDS = ["linear", "quadratic", "quadratic-planar", "spherical-beta", "spherical-planar", "spherical-kappa"]


@pytest.mark.parametrize("model,params", CASES, ids=IDS)
def test_laws_4_5_and_energy_balance_double(model, params):
    sol = R.solve(model, params, TEN, tol=1e-12, extras=True)
    inv = R.invariants(sol)
    assert np.max(np.abs(inv["momentum"])) < 1e-12
    assert np.max(np.abs(inv["energy"])) < 1e-12


@needs_heyoka
@pytest.mark.parametrize("model,params", CASES, ids=IDS)
def test_laws_and_two_precisions_agree_at_1e_20(model, params):
    sol = R.solve(model, params, TEN, tol=1e-20, extras=True)
    inv = R.invariants(sol)
    assert max(abs(a) for a in inv["momentum"]) < 1e-20
    assert max(abs(a) for a in inv["energy"]) < 1e-20
    finer = R.solve(model, params, TEN, tol=1e-30)
    assert R.difference(sol, finer) < 1e-20
    coarse = R.solve(model, params, TEN, tol=1e-12)
    assert R.difference(coarse, finer) < 1e-12


def test_self_check_two_precisions_in_double():
    assert R.self_check("spherical", CASES[3][1], TEN, 1e-9, method="dop853") < 1e-9


# --- the kink of a planar swing ------------------------------------------------------------------
def test_planar_swing_is_split_at_every_turning_point_and_keeps_its_order():
    params = {"R0": 0.1, "v0": 0.0, "omega2": OMEGA**2, "beta": 0.5}
    errs = []
    best = R.solve("quadratic", params, TEN, tol=1e-30 if R.heyoka_available() else 1e-13)
    for tol in (1e-6, 1e-8, 1e-10, 1e-12):
        sol = R.solve("quadratic", params, TEN, tol=tol, method="dop853")
        assert np.all(np.isfinite(sol.x)) and sol.info["turning_points"] == 19
        errs.append(R.difference(sol, best))
    # the error follows the tolerance decade by decade (no order lost at the kinks)
    assert all(e < 3 * tol for e, tol in zip(errs, (1e-6, 1e-8, 1e-10, 1e-12)))
    assert all(b < a / 20 for a, b in zip(errs, errs[1:]))


@needs_heyoka
def test_taylor_integrator_across_the_kink_returns_no_nan():
    sol = R.solve("spherical", CASES[4][1], TEN, tol=1e-30)
    assert all(mpmath.isfinite(a) for a in sol.x) and sol.info["turning_points"] == 19


def test_mpmath_fallback_splits_a_planar_swing():
    params = {"R0": 0.1, "v0": 0.0, "omega2": OMEGA**2, "beta": 0.5}
    t = [0.3 * T, 0.7 * T]  # one turning point in between
    a = R.solve("quadratic", params, t, tol=1e-16, method="mpmath")
    b = R.solve("quadratic", params, t, tol=1e-13, method="dop853")
    assert a.info["turning_points"] == 1
    assert R.difference(a, b) < 1e-13


def test_small_swing_quadratic_agrees_with_quadratic_module():
    t = np.linspace(0, 4 * T, 9)
    sol = R.solve("quadratic", {"R0": 0.1, "v0": 0.2, "omega2": OMEGA**2, "beta": 0.5}, t, tol=1e-12)
    x, y = quadratic.integrate_full(t, 0.1, 0.2, OMEGA, 0.5, rtol=1e-13)
    assert np.max(np.abs(sol.x - x)) < 1e-12 and np.max(np.abs(sol.y - y)) < 1e-12


# --- input ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("model,params,tol,method", [
    ("nosuch", lin(0.1), 1e-12, "auto"),
    ("linear", {"R0": -1, "v0": 0, "omega2": 10}, 1e-12, "auto"),
    ("linear", {"R0": 0.1, "v0": 0, "omega2": 10, "beta": 0.1}, 1e-12, "auto"),
    ("linear", {"R0": 0.1, "v0": 0, "omega2": 10, "kappa": 0.1, "beta": 0.1}, 1e-12, "auto"),
    ("linear", {"R0": 0.1, "v0": 0, "omega2": "nan"}, 1e-12, "auto"),
    ("linear", {"R0": 0.1, "v0": 0, "omega2": 10, "bogus": 1}, 1e-12, "auto"),
    ("spherical", {"R0": 0.1, "v0": 0, "omega2": 10}, 1e-12, "auto"),
    ("spherical", {"R0": 1.5, "v0": 0, "l": 1, "g": 10}, 1e-12, "auto"),
    ("spherical", {"R0": 0.5, "v0": 9, "l": 1, "g": 10}, 1e-12, "auto"),
    ("linear", lin(0.1), 0.0, "auto"),
    ("linear", lin(0.1), 1e-20, "dop853"),
    ("linear", lin(0.1), 1e-12, "rk4"),
])
def test_bad_input_is_a_model_error(model, params, tol, method):
    with pytest.raises(R.ModelError):
        R.solve(model, params, [0.0, 1.0], tol=tol, method=method)


def test_negative_times_refused_and_unsorted_times_kept_in_order():
    with pytest.raises(R.ModelError):
        R.solve("linear", lin(0.1), [-1.0])
    t = [2.0, 0.5, 1.0]
    a = R.solve("linear", lin(0.1), t)
    b = R.solve("linear", lin(0.1), sorted(t))
    assert list(a.x) == [b.x[2], b.x[0], b.x[1]]


# --- validity of the approximations ----------------------------------------------------------------
def test_small_swing_error_shrinks_like_amplitude_squared():
    t = np.linspace(0, 2 * 2 * math.pi / math.sqrt(9.81), 50)
    errs = [np.max(A.approximation_error("linear", {"R0": a, "v0": 0.5 * a * math.sqrt(9.81), "l": 1.0, "g": 9.81,
                                                     "kappa": 0.05}, t)) for a in (0.01, 0.02, 0.04)]
    slope = np.polyfit(np.log([0.01, 0.02, 0.04]), np.log(errs), 1)[0]
    assert 1.9 < slope < 2.1


def test_first_order_error_is_second_order_in_beta():
    t = np.linspace(0, 2 * math.pi / math.sqrt(9.81), 40)
    bs = np.array([0.01, 0.02, 0.04])  # βR0
    errs = [np.max(A.approximation_error("quadratic-first-order", {"R0": 0.1, "v0": 0.15, "l": 1.0, "g": 9.81,
                                                                   "beta": b / 0.1}, t, against="small-swing"))
            for b in bs]
    slope = np.polyfit(np.log(bs), np.log(errs), 1)[0]
    assert 1.9 < slope < 2.1


def test_approximation_error_shape_and_start():
    e = A.approximation_error("quadratic", {"R0": 0.2, "v0": 0.3, "l": 1.0, "g": 9.81, "beta": 0.3},
                              np.array([[0.0, 1.0], [2.0, 3.0]]))
    assert e.shape == (2, 2) and e[0, 0] == 0.0 and np.all(e[1] > 0)


@pytest.mark.parametrize("model,params", [
    ("nosuch", {"R0": 0.1, "l": 1, "g": 10}),
    ("ellipse", {"R0": 0.1, "l": 1, "g": 10, "kappa": 0.1}),
    ("linear", {"R0": 0.1, "l": 1, "g": 10, "beta": 0.1}),
    ("quadratic", {"R0": 0.1, "l": 1, "g": 10}),
])
def test_approximation_error_bad_input(model, params):
    with pytest.raises(R.ModelError):
        A.approximation_error(model, params, [1.0])


# --- property-based: the evaluators against the references -----------------------------------------
@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(kappa_ratio=st.floats(0.0, 3.0), v0=st.floats(0.0, 0.5), t=st.floats(0.0, 10 * T))
def test_linear_closed_form_against_the_reference_integrator(kappa_ratio, v0, t):
    kappa = kappa_ratio * OMEGA
    x, y = motion.linear([t], 0.1, v0, OMEGA, kappa)
    sol = R.solve("linear", lin(kappa, v0), [t], tol=1e-12, method="dop853")
    scale = max(0.1, v0 / OMEGA)
    assert abs(x[0] - sol.x[0]) < 1e-11 * scale and abs(y[0] - sol.y[0]) < 1e-11 * scale


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(v0_ratio=st.floats(0.0, 1.5), beta=st.floats(0.0, 2.0), theta=st.floats(0.0, 12 * math.pi))
@example(v0_ratio=1e-20, beta=1.0, theta=4.0)  # m = 1 − 10⁻⁴⁰: 1 − m must not be formed by subtraction
@example(v0_ratio=8.162074779734221e-159, beta=0.0, theta=0.0)  # 1 − m subnormal in double precision
def test_quadratic_first_order_against_40_digits_of_itself(v0_ratio, beta, theta):
    """The closed form at any k² and Ωt against 40 digits of itself (the reference for the
    first-order solution, cross-checked by integration in tests/test_quadratic.py)."""
    R0 = 0.1
    v0 = v0_ratio * R0 * OMEGA
    t = theta / OMEGA
    x, y = quadratic.first_order([t], R0, v0, OMEGA, beta)
    with mpmath.workdps(40):
        xm, ym = quadratic.first_order([mpmath.mpf(t)], mpmath.mpf(R0), mpmath.mpf(v0), mpmath.mpf(OMEGA),
                                       mpmath.mpf(beta), ops=quadratic.MP)
    scale = max(R0, v0 / OMEGA) * (1 + beta * R0 * (1 + theta))
    assert abs(float(xm[0]) - x[0]) < 1e-13 * scale and abs(float(ym[0]) - y[0]) < 1e-13 * scale


@settings(max_examples=30, deadline=None)
@given(delta=st.floats(1e-300, math.pi - 1e-9))
def test_period_default_against_40_digits_over_the_whole_domain(delta):
    val = float(period.period_ratio(delta=delta))
    ref = period.period_ratio_mp(delta=delta, dps=40)
    assert abs(val - float(ref)) <= 4e-16 * float(ref)


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(R0=st.floats(0.05, 0.8), v0_ratio=st.floats(0.0, 1.0), drag=st.floats(0.0, 1.0), quad=st.booleans())
def test_spherical_reference_obeys_its_laws_everywhere(R0, v0_ratio, drag, quad):
    v0 = v0_ratio * math.sqrt(10.0 * math.sqrt(1 - R0 * R0))  # below the height limit
    params = {"R0": R0, "v0": v0, "l": 1.0, "g": 10.0, ("beta" if quad else "kappa"): drag}
    sol = R.solve("spherical", params, np.linspace(0.2, 4 * T, 5), tol=1e-10, extras=True)
    inv = R.invariants(sol)
    assert np.max(np.abs(inv["momentum"])) < 1e-9 and np.max(np.abs(inv["energy"])) < 1e-9


@pytest.mark.slow
@pytest.mark.parametrize("model,params", CASES, ids=IDS)
def test_mpmath_fallback_over_a_period(model, params):
    t = [0.4 * T, 1.1 * T]
    a = R.solve(model, params, t, tol=1e-16, method="mpmath")
    b = R.solve(model, params, t, tol=1e-13, method="dop853")
    assert R.difference(a, b) < 1e-12
