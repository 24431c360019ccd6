"""Evaluating the exact period: every method against pinned high-precision literals, the
correctly rounded route against an independent mpmath value, the complement input near π."""

import json
import math
from decimal import Decimal, localcontext

import mpmath
import numpy as np
import pytest

from quasicentral.models import period as P
from quasicentral.cli import main

# T/T0 at 10°, 90°, 179°: 20 digits, pinned (two methods agreed at 60 digits)
PINNED = {10: "1.0019071881432166070", 90: "1.1803405990160962260", 179: "3.9010651603890857349"}
TOL = {"agm": 7e-16, "ellipk": 4.5e-16, "quad": 1e-13, "ode": 1e-11}


@pytest.mark.parametrize("method", sorted(TOL))
@pytest.mark.parametrize("deg", [5, 10, 45, 90, 135, 170, 179, 179.9])
def test_double_methods(method, deg):
    """Against the exact value *for the double input* (near π the input itself is
    ill-conditioned, so the reference takes the double's exact binary value)."""
    phi = math.radians(deg)
    ref = float(P.period_ratio_mp(phi0=phi, dps=30))
    val = float(P.period_ratio(phi, method=method))
    assert abs(val - ref) <= TOL[method] * ref


@pytest.mark.parametrize("deg", sorted(PINNED))
def test_pinned_literals(deg):
    val = P.period_ratio_mp(amplitude_deg=str(deg), dps=25)
    assert mpmath.nstr(val, 20, strip_zeros=False) == PINNED[deg]


@pytest.mark.parametrize("method", ["agm", "ellipk", "quad", "series"])
def test_any_precision_methods(method):
    terms = 400 if method == "series" else 4
    val = P.period_ratio_mp(amplitude_deg="90", dps=25, method=method, terms=terms)
    with mpmath.workdps(30):
        assert abs(val - mpmath.mpf(PINNED[90])) < mpmath.mpf(10) ** -19


def test_ode_at_any_precision():
    val = P.period_ratio_mp(amplitude_deg="10", dps=20, method="ode")
    assert abs(float(val) - float(PINNED[10])) < 1e-15


@pytest.mark.parametrize("method", ["agm", "ellipk"])
@pytest.mark.parametrize("digits", [30, 100])
@pytest.mark.parametrize("deg", ["10", "90", "179", "179.99"])
def test_correctly_rounded(digits, deg, method):
    """The ball route's result is the exact value rounded half-even, checked against mpmath's
    K at twice the digits."""
    got = P.period_ratio_rounded(amplitude_deg=deg, digits=digits, method=method)
    with mpmath.workdps(2 * digits + 20):
        ref = 2 / mpmath.pi * mpmath.ellipk(mpmath.sin(mpmath.mpf(deg) * mpmath.pi / 360) ** 2)
        text = mpmath.nstr(ref, 2 * digits + 10)
    with localcontext() as ctx:
        ctx.prec = digits
        assert got == str(+Decimal(text))


@pytest.mark.parametrize("method", ["ellipk", "agm"])
def test_complement_keeps_accuracy_down_to_1e_300(method):
    for d in (1e-3, 1e-7, 1e-9, 1e-20, 1e-150, 1e-300):
        dbl = float(P.period_ratio(delta=d, method=method))
        ref = P.period_ratio_mp(delta=d, dps=30)
        assert abs(dbl - float(ref)) <= (2 if method == "ellipk" else 3) * np.spacing(float(ref))


def test_series_tail_bound_is_rigorous_and_terms_needed():
    for deg in (10, 60, 120, 170):
        m = math.sin(math.radians(deg) / 2) ** 2
        exact = float(P.period_ratio(math.radians(deg)))
        for n in (1, 2, 4, 10):
            approx, tail = P.series_ratio(np.array([m]), n)
            assert 0 <= exact - approx[0] <= tail[0] * (1 + 1e-12) + 1e-15
    assert P.terms_needed(math.radians(10), 1e-15) < P.terms_needed(math.radians(90), 1e-15)
    a = P.first_amplitude_exceeding(4, 1e-3)
    m = math.sin(a / 2) ** 2
    approx = P.series_ratio(np.array([m]), 4)[0][0]
    exact = float(P.period_ratio(a))
    assert abs((exact - approx) / exact - 1e-3) < 1e-9


def test_bad_inputs_raise_domain_errors():
    for bad in (0.0, math.pi, -1.0, float("nan"), 4.0):
        with pytest.raises(P.DomainError):
            P.period_ratio(bad)
    with pytest.raises(P.DomainError):
        P.period_ratio(1.0, delta=1.0)


def test_cli_period_json(capsys):
    assert main(["period", "--amplitude-deg", "90", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["method"] == "ellipk" and abs(doc["T_over_T0"] - float(PINNED[90])) < 1e-15
    assert main(["period", "--amplitude-deg", "60", "--method", "series", "--terms", "4", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["error_estimate"] > 0 and doc["terms"] == 4
    assert main(["period", "--complement-rad", "1e-300", "--dps", "30", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["T_over_T0"].startswith("441.085172928572554084051195236")


@pytest.mark.parametrize("args", [["--amplitude-deg", "180"], ["--amplitude-deg", "0"], ["--amplitude-rad", "nan"],
                                  ["--amplitude-deg", "10", "--l", "-1"], [], ["--complement-rad", "-1"]])
def test_cli_period_bad_input(args, capsys):
    assert main(["period", *args]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("quasicentral: error:")


def test_table_two_methods_agree():
    rows = P.table(digits=20)
    assert rows[0]["amplitude_deg"] == "5" and rows[-1]["amplitude_deg"] == "179.99"
    assert all(r["agree"] for r in rows)
    pinned = {r["amplitude_deg"]: r["T_over_T0"] for r in rows}
    assert pinned["90"] == PINNED[90] and pinned["179"] == PINNED[179]


# --- issue 16: each reproduction, replayed --------------------------------------------------------------
TRUTH_DELTA_1 = 1.3969137910128526  # T/T0 at δ = 1 rad (mpmath, 30 digits: 1.39691379101285258…)
TRUTH_DELTA_TINY = 441.0851729285726  # T/T0 at δ = 1e-300


def _period_json(capsys, *args):
    assert main(["period", *args, "--json"]) == 0
    out = capsys.readouterr()
    return json.loads(out.out), out.err


@pytest.mark.parametrize("args,truth,rel", [
    (["--complement-rad", "1", "--method", "ode"], TRUTH_DELTA_1, 1e-11),
    (["--complement-rad", "1e-300", "--method", "ode"], TRUTH_DELTA_TINY, 1e-11),
    (["--complement-rad", "1e-300", "--method", "quad"], TRUTH_DELTA_TINY, 1e-13),
    (["--complement-rad", "1e-300", "--method", "agm"], TRUTH_DELTA_TINY, 1e-15),
    (["--amplitude-deg", "1e-12", "--method", "ode"], 1.0, 1e-13),
    (["--amplitude-deg", "1e-12", "--method", "quad"], 1.0, 1e-15),
])
def test_cli_period_methods_at_the_edges(capsys, args, truth, rel):
    doc, err = _period_json(capsys, *args)
    assert abs(doc["T_over_T0"] - truth) <= rel * truth and err == ""
    with mpmath.workdps(30):
        assert abs(P.period_ratio_mp(delta="1", dps=25) - mpmath.mpf(TRUTH_DELTA_1)) < 1e-15


def test_cli_period_quad_at_any_precision_near_pi(capsys):
    doc, _ = _period_json(capsys, "--complement-rad", "1e-300", "--method", "quad", "--dps", "40")
    assert doc["T_over_T0"].startswith("441.08517292857255408405119523626")


def test_cli_amplitude_near_180_is_read_exactly(capsys):
    """δ = 180° − A is formed from the decimal string: T agrees with 50 digits at the exact A."""
    doc, _ = _period_json(capsys, "--amplitude-deg", "179.9999999999")
    with mpmath.workdps(50):
        delta = (180 - mpmath.mpf("179.9999999999")) * mpmath.pi / 180  # exact: 1e-10 degrees
        truth = 4 * mpmath.sqrt(1 / mpmath.mpf("9.81")) * mpmath.ellipk(1 - mpmath.sin(delta / 2) ** 2)
    assert abs(doc["T"] - float(truth)) <= 4e-16 * float(truth)
    assert str(truth).startswith("37.232009630")


def test_cli_series_says_how_many_digits_hold_or_refuses(capsys):
    doc, err = _period_json(capsys, "--amplitude-deg", "60", "--method", "series", "--terms", "4")
    assert doc["digits"] == 3 and "3 significant digits" in doc["warning"]
    assert err.startswith("quasicentral: warning:") and err.count("\n") == 1
    doc, err = _period_json(capsys, "--amplitude-deg", "10", "--method", "series", "--terms", "40")
    assert "warning" not in doc and err == ""
    assert main(["period", "--amplitude-deg", "179.999", "--method", "series"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--terms" in err and "no digit" in err


@pytest.mark.parametrize("args,named", [
    (["--amplitude-deg", "10", "--terms", "5"], "--terms"),
    (["--amplitude-deg", "10", "--method", "agm", "--terms", "5"], "--terms"),
    (["--table", "--amplitude-deg", "10"], "--amplitude-deg"),
    (["--table", "--dps", "30"], "--dps"),
    (["--table", "--method", "agm"], "--method"),
    (["--table", "--l", "2"], "--l"),
    (["--complement-rad", "nan"], "--complement-rad"),
    (["--complement-rad", "inf"], "--complement-rad"),
    (["--amplitude-rad", "4"], "--amplitude-rad"),
    (["--amplitude-deg", "1_0"], "--amplitude-deg"),
    (["--amplitude-deg", "١٠"], "--amplitude-deg"),
    (["--amplitude-deg", "1" * 2000], "--amplitude-deg"),
    (["--amplitude-deg", "10", "--g", "1e999"], "--g"),
    (["--amplitude-deg", "10", "--dps", "100000"], "--dps"),
    (["--amplitude-deg", "10", "--method", "series", "--terms", "10000001"], "--terms"),
    (["--amplitude-deg", "60", "--method", "ode", "--dps", "41"], "--dps"),
    (["--complement-rad", "1e-300", "--method", "ode", "--dps", "20"], "--method ode"),
])
def test_cli_period_refusals_name_the_option(capsys, args, named):
    assert main(["period", *args]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("quasicentral: error:") and named in err, err


def _series_mp(m, n):
    """Σ_{k<n} c_k m^k with c_k = (C(2k, k)/4^k)² exact (an independent route to the coefficients)."""
    from fractions import Fraction

    total = mpmath.mpf(0)
    for k in range(n):
        c = Fraction(math.comb(2 * k, k), 4**k) ** 2
        total += mpmath.mpf(c.numerator) / c.denominator * m**k
    return total


@pytest.mark.parametrize("m,n", [(0.1, 1), (0.1, 2), (0.1, 5), (0.1, 10), (0.5, 3), (0.5, 12), (0.5, 25),
                                 (0.9, 4), (0.9, 25), (0.99, 60)])
def test_double_series_term_by_term_against_mpmath(m, n):
    """The double-precision (66) after n terms equals the exact n-term sum to (2n + 4) ulp, and
    the sum of n + 1 terms is farther than that: one term more or less fails the test."""
    got = float(P.series_ratio(np.array([m]), n)[0][0])
    with mpmath.workdps(40):
        exact, one_more = _series_mp(mpmath.mpf(m), n), _series_mp(mpmath.mpf(m), n + 1)
        tol = (2 * n + 4) * np.spacing(float(exact))
        assert abs(got - exact) <= tol
        assert abs(got - one_more) > tol
        if n > 1:
            assert abs(got - _series_mp(mpmath.mpf(m), n - 1)) > tol
    mp_sum = P.period_ratio_mp(phi0=2 * math.asin(math.sqrt(m)), dps=30, method="series", terms=n)
    assert abs(float(mp_sum) - got) <= tol + 1e-15 * got  # the mpmath context runs the same Horner loop
