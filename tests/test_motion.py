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


# --- issue 16: each reproduction, replayed --------------------------------------------------------------
def _run(args, capsys):
    code = main(["trajectory", *args])
    out = capsys.readouterr()
    return code, out.out, out.err


def test_cli_linear_without_drag_compensates_the_phase(capsys):
    """κ = 0 at Ω² ≈ 36, t = 7.5: within 3 ulp of the amplitude scale, as every κ > 0 (Ω² is
    taken exactly; the rounding of Ω = √(Ω²) never enters the phase)."""
    rng = np.random.default_rng(16)
    for om2 in rng.uniform(35.0, 37.0, 25):
        for kappa in ("0", "0.4"):
            code, out, _ = _run(["--model", "linear", "--R0", "0.1", "--v0", "0.1", "--omega2", repr(float(om2)),
                                 "--kappa", kappa, "--t", "7.5", "--json"], capsys)
            doc = json.loads(out)
            with mpmath.workdps(40):
                x, y = motion.linear([mpmath.mpf(7.5)], mpmath.mpf(0.1), mpmath.mpf(0.1),
                                     mpmath.sqrt(mpmath.mpf(float(om2))), mpmath.mpf(kappa), ops=motion.MP)
            assert abs(doc["x"][0] - float(x[0])) <= 3 * np.spacing(0.1)
            assert abs(doc["y"][0] - float(y[0])) <= 3 * np.spacing(0.1 / 6)


def test_cli_enormous_drag_is_finite_and_quiet(capsys):
    code, out, err = _run(["--model", "linear", "--R0", "0.1", "--v0", "0.1", "--omega2", "10", "--kappa", "1e300",
                           "--t", "0,1,2", "--json"], capsys)
    doc = json.loads(out)
    assert code == 0 and err == ""
    assert doc["x"] == [0.1, 0.1, 0.1] and doc["y"][0] == 0.0 and 0 < doc["y"][2] <= 0.1 / 2e300
    x, y = motion.linear(np.array([1.0]), 0.1, 0.1, math.sqrt(10), 1e149)
    assert x[0] == 0.1 and abs(y[0] - 0.1 / 2e149) <= 1e-15 * 0.1 / 2e149


def test_cli_first_order_out_of_range_warns(capsys):
    args = ["--model", "quadratic-first-order", "--beta", "20", "--R0", "0.1", "--v0", "0", "--l", "1", "--g", "9.81",
            "--t", "5", "--json"]
    code, out, err = _run(args, capsys)
    assert code == 0 and "out of its range" in json.loads(out)["warning"]
    assert err.startswith("quasicentral: warning:") and err.count("\n") == 1
    code, out, err = _run(args[:3] + ["0.01"] + args[4:], capsys)  # β = 0.01: βR0·Ωt small
    assert code == 0 and "warning" not in json.loads(out) and err == ""
    code, out, err = _run(args[:3] + ["1e300"] + args[4:], capsys)  # far out: warned, never an internal error
    assert code == 0 and "out of its range" in json.loads(out)["warning"]
    code, out, err = _run(["--model", "quadratic", "--beta", "1e300"] + args[4:], capsys)  # stiff: one line
    assert code == 2 and err.count("\n") == 1 and "internal" not in err


@pytest.mark.parametrize("args,named", [
    (["--model", "linear", "--R0", "5", "--v0", "0", "--l", "1", "--g", "9.81", "--kappa", "0"], "--R0"),
    (["--model", "linear", "--R0", "0.1", "--v0", "0", "--omega2", "10"], "--kappa"),
    (["--model", "quadratic", "--R0", "0.1", "--v0", "0", "--omega2", "10"], "--beta"),
    (["--model", "ellipse", "--R0", "0.1", "--v0", "0", "--omega2", "10", "--kappa", "0.3"], "--kappa"),
    (["--model", "linear", "--R0", "1_0", "--v0", "0", "--omega2", "10", "--kappa", "0"], "--R0"),
    (["--model", "linear", "--R0", "0.1", "--v0", "0", "--omega2", "10", "--kappa", "nan"], "--kappa"),
    (["--model", "linear", "--R0", "0.1", "--v0", "0", "--omega2", "1e999", "--kappa", "0"], "--omega2"),
    (["--model", "linear", "--R0", "0.1", "--v0", "0", "--omega2", "10", "--kappa", "0", "--dps", "30",
      "--t0", "0", "--t1", "1", "--n", "100000"], "--n"),
    (["--model", "linear", "--R0", "0.1", "--v0", "0", "--omega2", "10", "--kappa", "0", "--t0", "0", "--t1", "1",
      "--n", "100000000"], "--n"),
    (["--model", "linear", "--R0", "0.1", "--v0", "5", "--l", "1", "--g", "9.81", "--kappa", "0"], "--v0"),
])
def test_cli_trajectory_refusals_name_the_option(args, named, capsys):
    code, out, err = _run(args + ([] if "--t0" in args else ["--t", "1"]), capsys)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and err.startswith("quasicentral: error:") and named in err, err


def test_models_import_only_downward():
    """The model layer imports nothing above it (engine, studies, documents, cli)."""
    import ast
    from pathlib import Path

    import quasicentral.models as pkg

    for path in Path(pkg.__file__).parent.glob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else \
                [node.module or ""] if isinstance(node, ast.ImportFrom) else []
            for name in names:
                assert not name.startswith(("quasicentral.engine", "quasicentral.studies", "quasicentral.documents",
                                            "quasicentral.cli")), f"{path.name} imports {name}"
