"""The linear-drag closed form: all three regimes, κ at and within 1e-12 of Ω, against a
40-digit evaluation of the same formula and against numerical integration of (16)–(17)."""

import json
import math

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from quasicentral.models import motion
from quasicentral.cli import main

OMEGA = math.sqrt(10.0)


def reference(t, R0, v0, Omega, kappa):
    """The same formulas at 40 digits, at the exact binary values of the double inputs."""
    with mpmath.workdps(40):
        x, y = motion.linear([mpmath.mpf(float(a)) for a in t], mpmath.mpf(R0), mpmath.mpf(v0),
                             mpmath.mpf(Omega), mpmath.mpf(kappa), ops=motion.MP)
        return np.array([float(a) for a in x]), np.array([float(a) for a in y])


KAPPAS = [0.0, 0.4, OMEGA * (1 - 1e-12), OMEGA, OMEGA * (1 + 1e-12), 1.5 * OMEGA, 10 * OMEGA, 1e4]


@pytest.mark.parametrize("kappa", KAPPAS)
def test_double_against_40_digits(kappa):
    t = np.linspace(0, 10, 301)
    x, y = motion.linear(t, 0.1, 0.1, OMEGA, kappa)
    xr, yr = reference(t, 0.1, 0.1, OMEGA, kappa)
    assert np.all(np.isfinite(x)) and np.all(np.isfinite(y))
    assert np.max(np.abs(x - xr)) <= 8 * np.spacing(0.1)
    assert np.max(np.abs(y - yr)) <= 8 * np.spacing(0.1 / OMEGA)


@pytest.mark.parametrize("kappa", KAPPAS[:-1])
def test_against_numerical_integration(kappa):
    t = np.linspace(0, 6, 61)
    x, y = motion.linear(t, 0.1, 0.1, OMEGA, kappa)
    xi, yi = motion.integrate_linear(t, 0.1, 0.1, OMEGA, kappa)
    assert np.max(np.abs(x - xi)) < 1e-11 and np.max(np.abs(y - yi)) < 1e-11


@pytest.mark.parametrize("kappa", [0.3, OMEGA, 3 * OMEGA])
def test_blocked_evaluation_equals_pointwise(kappa):
    """Long arrays go through in blocks of motion.CHUNK: every point, block edges included,
    equals its evaluation alone."""
    t = np.linspace(0, 30, 2 * motion.CHUNK + 7)
    x, y = motion.linear(t, 0.1, 0.1, OMEGA, kappa)
    idx = [0, motion.CHUNK - 1, motion.CHUNK, 2 * motion.CHUNK, t.size - 1]
    xs, ys = motion.linear(t[idx], 0.1, 0.1, OMEGA, kappa)
    assert np.array_equal(x[idx], xs) and np.array_equal(y[idx], ys)


def test_regimes_join_continuously_at_critical_damping():
    t = np.linspace(0, 3, 31)
    xc, yc = motion.linear(t, 0.1, 0.1, OMEGA, OMEGA)
    for eps in (1e-12, 1e-9, 1e-7):
        for sign in (-1, 1):
            x, y = motion.linear(t, 0.1, 0.1, OMEGA, OMEGA * (1 + sign * eps))
            assert np.max(np.abs(x - xc)) < 10 * eps and np.max(np.abs(y - yc)) < 10 * eps


def test_initial_conditions_and_angular_momentum_law():
    """x(0) = R0, y(0) = 0, and x·ẏ − y·ẋ = R0 v0 e^{−2κt} (law (4)), with derivatives by
    mpmath's numerical differentiation of the 40-digit closed form."""
    R0, v0, kappa = mpmath.mpf("0.1"), mpmath.mpf("0.25"), mpmath.mpf("0.7")
    with mpmath.workdps(40):
        def xy(tt):
            x, y = motion.linear([tt], R0, v0, mpmath.sqrt(10), kappa, ops=motion.MP)
            return x[0], y[0]
        for tt in (mpmath.mpf(0), mpmath.mpf("0.3"), mpmath.mpf("2.9"), mpmath.mpf("7.5")):
            x, y = xy(tt)
            dx = mpmath.diff(lambda s: xy(s)[0], tt) if tt else mpmath.mpf(0)
            dy = mpmath.diff(lambda s: xy(s)[1], tt) if tt else v0
            assert abs(x * dy - y * dx - R0 * v0 * mpmath.exp(-2 * kappa * tt)) < mpmath.mpf(10) ** -25


@settings(max_examples=60, deadline=None)
@given(kappa_ratio=st.floats(0, 20), omega=st.floats(0.1, 30), t=st.floats(0, 50))
def test_property_double_matches_reference(kappa_ratio, omega, t):
    kappa = kappa_ratio * omega
    x, y = motion.linear(np.array([t]), 0.2, 0.3, omega, kappa)
    xr, yr = reference([t], 0.2, 0.3, omega, kappa)
    assert abs(x[0] - xr[0]) <= 1e-13 * 0.2 and abs(y[0] - yr[0]) <= 1e-13 * 0.3 / omega + 1e-300


def test_cli_trajectory_contract(capsys):
    assert main(["trajectory", "--model", "linear", "--R0", "0.1", "--v0", "0.1", "--omega2", "10",
                 "--kappa", "0.4", "--t0", "0", "--t1", "2", "--n", "5", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert set(doc) >= {"model", "parameters", "t", "x", "y"} and len(doc["x"]) == 5
    assert doc["x"][0] == 0.1 and doc["y"][0] == 0.0
    assert main(["trajectory", "--model", "linear", "--R0", "0.1", "--v0", "0.1", "--l", "1", "--g", "10",
                 "--kappa", "0.1", "--t", "1", "--dps", "40", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert isinstance(doc["x"][0], str) and len(doc["x"][0].lstrip("-0.")) >= 39
    with mpmath.workdps(60):
        x, _ = motion.linear([mpmath.mpf(1)], mpmath.mpf("0.1"), mpmath.mpf("0.1"), mpmath.sqrt(10),
                             mpmath.mpf("0.1"), ops=motion.MP)
        assert abs(mpmath.mpf(doc["x"][0]) - x[0]) < mpmath.mpf(10) ** -40


@pytest.mark.parametrize("args", [
    ["--R0", "-1"], ["--R0", "0"], ["--kappa", "-0.1"], ["--omega2", "0"], ["--R0", "nan"], ["--t", ","],
    ["--model", "nosuch"], ["--t", "-1"], ["--beta", "0.1"],
])
def test_cli_trajectory_bad_input(args, capsys):
    base = {"--model": "linear", "--R0": "0.1", "--v0": "0.1", "--omega2": "10", "--kappa": "0", "--t": "0,1"}
    opts = dict(base)
    opts.update(dict(zip(args[::2], args[1::2])))
    argv = ["trajectory"] + [a for kv in opts.items() for a in kv]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("quasicentral: error:")
