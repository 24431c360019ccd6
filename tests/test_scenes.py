"""Scenes: each shipped example's choice (the chosen model meets the tolerance against the
richest model, the next cheaper one does not), the physics behind each rung's answer checked
by an independent route, and the scene file's contract (the key and its line, exit 2)."""

import json
import math
import re
from pathlib import Path

import mpmath
import numpy as np
import pytest

from quasicentral.studies import scenes
from quasicentral.cli import main

SCENES = Path(__file__).resolve().parent.parent / "scenes"

# file → (model, terms): what each example must choose
EXPECTED = {
    "fig7-linear-drag": ("linear", None),
    "fig8-aperiodic-limit": ("linear", None),
    "fig7-angular-momentum": ("linear", None),
    "air-one-minute": ("quadratic-first-order", None),
    "conical-decay": ("quadratic-first-order", None),
    "water-heavily-damped": ("quadratic", None),
    "glycerol-overdamped": ("linear", None),
    "classroom-period": ("ellipse", None),
    "large-amplitude-period": ("period-series", 13),
    "long-run-precession": ("spherical", None),
}

BASE = """\
[pendulum]
length = 1.0          # m
g = 9.81
[start]
displacement = 0.1
speed = 0.1
[medium]
drag = "quadratic"
coefficient = 0.5
[question]
quantity = "trajectory"
duration = 4.0
tolerance = 1e-4
"""


@pytest.fixture(scope="module")
def decisions():
    return {p.stem: scenes.decide(scenes.load(p)) for p in sorted(SCENES.glob("*.toml"))}


def test_every_example_has_its_expected_choice():
    assert sorted(p.stem for p in SCENES.glob("*.toml")) == sorted(EXPECTED)


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_example_choice(decisions, name):
    d = decisions[name]
    model, terms = EXPECTED[name]
    assert d.meets and (d.chosen.model, d.chosen.terms) == (model, terms)
    tol, q = d.scene.tolerance, d.scene.quantity
    rich = d.richest
    # the chosen model meets the tolerance against the richest model ...
    if d.chosen is rich:
        assert rich.estimated_error <= tol
    else:
        assert scenes.distance(q, d.chosen.value, rich.value) + rich.estimated_error <= tol
    # ... and the next cheaper model does not
    i = d.ratings.index(d.chosen)
    if i > 0:
        assert scenes.distance(q, d.ratings[i - 1].value, rich.value) > tol
    # every rung's a-priori order estimate is confirmed by the measured difference
    assert all(r.confirmed for r in d.ratings), [r.label for r in d.ratings if not r.confirmed]
    # the estimates are upper bounds of the measured distance to the richest
    for r in d.ratings[:-1]:
        assert scenes.distance(q, r.value, rich.value) <= r.estimated_error


# --- the physics of the rungs, by independent routes -------------------------------------------------
TRAJECTORY_CHOICES = [n for n in sorted(EXPECTED) if EXPECTED[n][0] in ("linear", "quadratic-first-order", "quadratic")
                      and scenes.load(SCENES / f"{n}.toml").quantity == "trajectory"]


@pytest.mark.parametrize("name", TRAJECTORY_CHOICES)
def test_trajectory_choice_against_the_reference_integrator(decisions, name):
    """The chosen model's error as measured by the reference module's own full pendulum
    (``accuracy.approximation_error``, an independent integration)."""
    from quasicentral.models import accuracy

    d = decisions[name]
    s = d.scene
    params = {"R0": s.R0, "v0": s.v0, "l": s.length, "g": s.g, **({"kappa": s.kappa} if s.kappa else {}),
              **({"beta": s.beta} if s.beta else {})}
    err = float(np.max(accuracy.approximation_error(d.chosen.model, params, d.times))) * s.R0
    assert err <= s.tolerance
    assert abs(err - scenes.distance("trajectory", d.chosen.value, d.richest.value)) <= d.richest.estimated_error


def test_conical_decay_is_33(decisions):
    """(33): R1 = R0(1 − πβR0) in first order for R0Ω = v0."""
    d = decisions["conical-decay"]
    s = d.scene
    assert d.chosen.value == pytest.approx(math.pi * s.beta * s.R0**2, rel=1e-12)


def test_large_amplitude_period_against_mpmath(decisions):
    d = decisions["large-amplitude-period"]
    with mpmath.workdps(30):
        exact = 2 * mpmath.pi * mpmath.sqrt(mpmath.mpf(1) / mpmath.mpf(9.81)) * 2 * mpmath.ellipk(
            mpmath.sin(mpmath.pi / 6) ** 2) / mpmath.pi
    assert abs(d.richest.value - float(exact)) < 1e-14
    assert abs(d.chosen.value - float(exact)) <= d.scene.tolerance
    # 60° of a 1 m pendulum: T/T0 = 2K(1/4)/π = 1.0731820071493643
    assert d.richest.value / d.scene.T0 == pytest.approx(1.0731820071493643, rel=2e-16)


def test_long_run_apsides_advance_as_airy(decisions):
    """The full pendulum's ellipse turns by 3ab/(8l²) per radian of Ωt (Airy): after five
    minutes the apsis lies ~64° from the x axis, which the small-swing ellipse never leaves."""
    d = decisions["long-run-precession"]
    s = d.scene
    a, b = s.semi_axes
    t = d.times
    x, y = d.richest.value
    last = t > t[-1] - s.T0 / 2  # half a revolution holds one apocentre
    k = np.argmax(np.hypot(x[last], y[last]))
    angle = math.atan2(y[last][k], x[last][k]) % math.pi
    predicted = (3 * a * b / (8 * s.length**2) * s.Omega * t[-1]) % math.pi
    assert abs(angle - predicted) < 0.1 * predicted


def test_first_revolution_of_the_linear_small_swing_is_2pi_over_omega():
    """The event machinery on (16)–(17): the revolution ends at 2π/ω, R1 = R0 e^{−2πκ/ω}."""
    text = BASE.replace('drag = "quadratic"', 'drag = "linear"').replace("coefficient = 0.5", "coefficient = 0.7")
    for speed in ("0.1", "0.0"):
        s = scenes.parse(text.replace("speed = 0.1", f"speed = {speed}").replace("duration = 4.0\n", "")
                         .replace('"trajectory"', '"period"'))
        k, Om = s.kappa, s.Omega

        def f(_t, u):
            return (u[2], u[3], -Om**2 * u[0] - 2 * k * u[2], -Om**2 * u[1] - 2 * k * u[3])

        t_rev, state = scenes.first_revolution(f, s, 1e-12, 100.0)
        w = math.sqrt(Om**2 - k**2)
        assert t_rev == pytest.approx(2 * math.pi / w, rel=1e-10)
        assert state[0] == pytest.approx(s.R0 * math.exp(-2 * math.pi * k / w), rel=1e-9)
        assert scenes.answer(s, "linear") == pytest.approx(2 * math.pi / w, rel=1e-15)


def test_period_with_quadratic_drag_is_t0_to_first_order():
    """The revolution's duration changes only at second order in β."""
    text = BASE.replace("duration = 4.0\n", "").replace('"trajectory"', '"period"')
    dts = []
    for beta in (0.05, 0.1):
        s = scenes.parse(text.replace("coefficient = 0.5", f"coefficient = {beta}"))
        dts.append(scenes.answer(s, "quadratic") - s.T0)
    assert abs(dts[1] / dts[0] - 4) < 0.2


def test_ellipse_path_is_the_arc_length():
    from scipy.integrate import quad

    for speed in ("0.05", "0.3132", "1.0"):
        s = scenes.parse(BASE.replace("speed = 0.1", f"speed = {speed}"))
        a, b = s.semi_axes
        t = np.array([0.3, 1.7, 5.2])
        got = scenes.ellipse_path(s, t)
        for tt, g in zip(t, got):
            want = quad(lambda u: s.Omega * math.hypot(a * math.sin(s.Omega * u), b * math.cos(s.Omega * u)), 0, tt,
                        limit=200, epsabs=1e-14)[0]
            assert g == pytest.approx(want, rel=1e-11)


def test_angular_momentum_first_order_is_law_5_along_the_ellipse():
    """(5) with the ellipse's path differs from the numerical small swing at O(β²)."""
    errs = []
    for beta in (0.02, 0.04):
        s = scenes.parse(BASE.replace("coefficient = 0.5", f"coefficient = {beta}")
                         .replace('"trajectory"', '"angular-momentum"'))
        t = np.linspace(0, 4.0, 41)
        errs.append(np.max(np.abs(scenes.answer(s, "quadratic-first-order", times=t)
                                  - scenes.answer(s, "quadratic", times=t))))
    assert 3.5 < errs[1] / errs[0] < 4.5


def test_planar_angular_momentum_is_zero_and_the_ellipse_answers():
    s = scenes.parse(BASE.replace("speed = 0.1", "speed = 0").replace('"trajectory"', '"angular-momentum"'))
    d = scenes.decide(s)
    assert d.chosen.model == "ellipse" and not np.any(d.chosen.value)


def test_a_priori_orders_shrink_with_the_swing():
    small = scenes.parse(BASE.replace("displacement = 0.1", "displacement = 0.01")
                         .replace("speed = 0.1", "speed = 0.01"))
    large = scenes.parse(BASE)
    for model in ("ellipse", "quadratic-first-order", "quadratic"):
        assert scenes.a_priori(small, model)[0] < scenes.a_priori(large, model)[0] / 50


def test_no_model_meets_an_impossible_tolerance(capsys, tmp_path):
    p = tmp_path / "tight.toml"
    p.write_text(BASE.replace("tolerance = 1e-4", "tolerance = 1e-16"))
    code = main(["scene", str(p), "--json"])
    doc = json.loads(capsys.readouterr().out)
    assert code == 1 and doc["meets_tolerance"] is False and doc["model"] == "spherical"
    assert [r["model"] for r in doc["rejected"]] == ["ellipse", "quadratic-first-order", "quadratic"]


def test_overdamped_has_no_period(tmp_path, capsys):
    p = tmp_path / "od.toml"
    p.write_text(BASE.replace('"quadratic"', '"linear"').replace("coefficient = 0.5", "coefficient = 5.0")
                 .replace("duration = 4.0\n", "").replace('"trajectory"', '"period"'))
    assert main(["scene", str(p)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "question.quantity" in err and ":11:" in err


# --- the command line -------------------------------------------------------------------------------
def test_json_contract_and_determinism(capsys, tmp_path):
    path = str(SCENES / "fig7-linear-drag.toml")
    docs = []
    for _ in range(2):
        assert main(["scene", path, "--json"]) == 0
        docs.append(json.loads(capsys.readouterr().out))
    doc = docs[0]
    for key in ("model", "rejected", "estimated_error", "answer", "seconds"):
        assert key in doc
    assert doc["model"] == "linear" and doc["estimated_error"] <= doc["tolerance"]
    assert [set(r) >= {"model", "estimated_error"} for r in doc["rejected"]] == [True]
    assert set(doc["answer"]) == {"t", "x", "y"} and len(doc["answer"]["t"]) == len(doc["answer"]["x"])

    def strip(d):
        if isinstance(d, dict):
            return {k: strip(v) for k, v in d.items() if k != "seconds"}
        return [strip(v) for v in d] if isinstance(d, list) else d

    assert strip(docs[0]) == strip(docs[1])


def test_text_report_and_plot(capsys, tmp_path):
    out = tmp_path / "p.png"
    assert main(["scene", str(SCENES / "large-amplitude-period.toml"), "--plot", str(out)]) == 0
    text = capsys.readouterr().out
    assert "period-series (13 terms)" in text and "rejected" in text and "ellipse" in text
    first = out.read_bytes()
    assert first[:8] == b"\x89PNG\r\n\x1a\n"
    assert main(["scene", str(SCENES / "large-amplitude-period.toml"), "--plot", str(out)]) == 0
    assert out.read_bytes() == first


def test_scalar_answers_in_json(capsys):
    assert main(["scene", str(SCENES / "conical-decay.toml"), "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert set(doc["answer"]) == {"value"} and doc["unit"] == "m"


# --- the scene file: every problem names the key and its line -----------------------------------------
BAD = [
    ("length = 1.0          # m", "length = -1", "pendulum.length", 2, "positive"),
    ("length = 1.0          # m", 'length = "1 s"', "pendulum.length", 2, "time"),
    ("length = 1.0          # m", "length = true", "pendulum.length", 2, "boolean"),
    ("length = 1.0          # m", "lenght = 1.0", "pendulum.lenght", 2, "unknown key"),
    ("g = 9.81", "g = 0", "pendulum.g", 3, "positive"),
    ("displacement = 0.1", "displacement = 1.5", "start.displacement", 5, "between"),
    ("displacement = 0.1", "amplitude_deg = 95", "start.amplitude_deg", 5, "90"),
    ("displacement = 0.1", "displacement = 0.1\namplitude_deg = 5", "start.amplitude_deg", 6, "exactly one"),
    ("speed = 0.1", "speed = -0.1", "start.speed", 6, "≥ 0"),
    ("speed = 0.1", "speed = 10", "start.speed", 6, "too large"),
    ("speed = 0.1", "", "start.speed", 4, "missing"),
    ('drag = "quadratic"', 'drag = "cubic"', "medium.drag", 8, "cubic"),
    ('drag = "quadratic"', "drag = 2", "medium.drag", 8, "string"),
    ("coefficient = 0.5", 'coefficient = "0.5 1/s"', "medium.coefficient", 9, "rate"),
    ("coefficient = 0.5", 'coefficient = "0.5 blorp"', "medium.coefficient", 9, "unknown unit"),
    ("coefficient = 0.5", 'coefficient = "0.5 furlong"', "medium.coefficient", 9, "length"),
    ("coefficient = 0.5", "coefficient = 0", "medium.coefficient", 9, "positive"),
    ("coefficient = 0.5", "", "medium.coefficient", 7, "missing"),
    ('drag = "quadratic"', 'drag = "none"', "medium.coefficient", 9, "no meaning"),
    ('quantity = "trajectory"', 'quantity = "speed"', "question.quantity", 11, "choose from"),
    ('quantity = "trajectory"', 'quantity = "period"', "question.duration", 12, "no meaning"),
    ("duration = 4.0", "", "question.duration", 10, "missing"),
    ("duration = 4.0", "duration = -1", "question.duration", 12, "positive"),
    ("duration = 4.0", "duration = nan", "question.duration", 12, "finite"),
    ("duration = 4.0", "duration = 1e7", "question.duration", 12, "periods"),
    ("tolerance = 1e-4", 'tolerance = "1e-4 s"', "question.tolerance", 13, "time"),
    ("tolerance = 1e-4", "tolerance = 0", "question.tolerance", 13, "positive"),
    ("[question]", "[questions]", "questions", 10, "unknown table"),
    ("duration = 4.0", "duration = ", None, 12, "not valid TOML"),
    ("length = 1.0          # m", 'length = "1_ m"', "pendulum.length", 2, "unit"),
    ("length = 1.0          # m", "length = " + "9" * 401, "pendulum.length", 2, "too large"),
    ("length = 1.0          # m", "length = 1e-300", "pendulum.length", 2, "between"),
    ("length = 1.0          # m", 'length = "1 degC"', "pendulum.length", 2, "temperature"),
    ("g = 9.81", 'g = "9.81 m/s"', "pendulum.g", 3, "speed"),
    ("g = 9.81", "g = 1e300", "pendulum.g", 3, "between"),
    ("displacement = 0.1", 'displacement = "0.1 s"', "start.displacement", 5, "time"),
    ("displacement = 0.1", "amplitude_deg = 89.9999999", "start.amplitude_deg", 5, "horizontal"),
    ("displacement = 0.1", 'amplitude_deg = "30 m"', "start.amplitude_deg", 5, "angle"),
    ("displacement = 0.1", 'amplitude_deg = "1.6 rad"', "start.amplitude_deg", 5, "90"),
    ("speed = 0.1", 'speed = "0.1 m"', "start.speed", 6, "length"),
    ("speed = 0.1", "speed = [1, 2]", "start.speed", 6, "array"),
    ("coefficient = 0.5", "coefficient = 1e300", "medium.coefficient", 9, "too large"),
    ('quantity = "trajectory"', "quantity = 3", "question.quantity", 11, "string"),
    ("duration = 4.0", 'duration = "4 m"', "question.duration", 12, "length"),
    ("duration = 4.0", 'duration = "4 furlong/s"', "question.duration", 12, "speed"),
    ("tolerance = 1e-4", 'tolerance = "1e-4 parsec/fortnight"', "question.tolerance", 13, "speed"),
    ("tolerance = 1e-4", 'tolerance = "1e-4"', "question.tolerance", 13, None),
    ("[pendulum]", '[scene]\ntitle = "a\\u001b[31m"\n[pendulum]', "scene.title", 2, "control characters"),
    ("[pendulum]", "[scene]\ntitle = 3\n[pendulum]", "scene.title", 2, "string"),
    ("[pendulum]", "[scene]\nnotes = [1]\n[pendulum]", "scene.notes", 2, "string"),
    ("[pendulum]", "[scene]\nauthor = 'x'\n[pendulum]", "scene.author", 2, "unknown key"),
    ("[pendulum]", "pendulum = 1\n[start2]", "pendulum", 1, "must be a table"),
]


@pytest.mark.parametrize("old,new,key,line,words", BAD, ids=[f"{b[2]}-{i}" for i, b in enumerate(BAD)])
def test_bad_scene_names_key_and_line(old, new, key, line, words):
    assert old in BASE
    if words is None:  # a string without a unit is accepted in SI
        assert scenes.parse(BASE.replace(old, new)).tolerance == 1e-4
        return
    with pytest.raises(scenes.SceneError) as exc:
        scenes.parse(BASE.replace(old, new), source="s.toml")
    e = exc.value
    assert (e.key, e.line) == (key, line), str(e)
    assert words in str(e) and str(e).startswith(f"s.toml:{line}: ")


def test_bad_scene_on_the_command_line_is_one_line_exit_2(tmp_path):
    import subprocess
    import sys

    p = tmp_path / "bad.toml"
    p.write_text(BASE.replace("coefficient = 0.5", "coefficient = -3"))
    proc = subprocess.run([sys.executable, "-m", "quasicentral.cli", "scene", str(p)], capture_output=True, text=True)
    assert proc.returncode == 2 and proc.stdout == ""
    assert proc.stderr.count("\n") == 1 and "Traceback" not in proc.stderr
    assert re.match(r"quasicentral: error: .*bad\.toml:9: medium\.coefficient: must be positive", proc.stderr)


def test_missing_file_and_missing_table(tmp_path, capsys):
    assert main(["scene", str(tmp_path / "nope.toml")]) == 2
    assert "cannot read" in capsys.readouterr().err
    with pytest.raises(scenes.SceneError, match="no \\[medium\\] table"):
        scenes.parse(BASE.replace('[medium]\ndrag = "quadratic"\ncoefficient = 0.5\n', ""))


def test_units_and_amplitude():
    text = BASE
    for old, new in [("length = 1.0          # m", 'length = "150 cm"'), ("g = 9.81", 'g = "9.81 m/s^2"'),
                     ("displacement = 0.1", "amplitude_deg = 30"), ("speed = 0.1", 'speed = "1.8 km/h"'),
                     ("coefficient = 0.5", 'coefficient = "0.5 1/m"'), ("duration = 4.0", 'duration = "0.5 min"'),
                     ("tolerance = 1e-4", 'tolerance = "2 mm"')]:
        text = text.replace(old, new)
    s = scenes.parse(text)
    assert s.length == 1.5 and s.g == 9.81 and s.v0 == pytest.approx(0.5) and s.beta == 0.5
    assert s.duration == 30.0 and s.tolerance == 0.002
    assert s.R0 == pytest.approx(1.5 * 0.5) and s.phi0 == pytest.approx(math.pi / 6)


def test_key_lines_with_quotes_dotted_keys_and_multiline_strings():
    text = ('[scene]\nnotes = """two\nlength = 5\n"""\n[pendulum]\n"length" = 1.0\n'
            '[start]\ndisplacement = 0.1\nspeed = 0.1\n[medium]\ndrag = "none"\n'
            "[question]\nquantity = \"trajectory\"\nduration = 1.0\ntolerance = 'x'\n")
    lines = scenes.key_lines(text)
    assert lines["pendulum.length"] == 6 and "scene.length" not in lines
    with pytest.raises(scenes.SceneError) as exc:
        scenes.parse(text)
    assert (exc.value.key, exc.value.line) == ("question.tolerance", 15)
    dotted = scenes.key_lines('pendulum.length = 1\n[start]\n  speed . "x" = 2\n')
    assert dotted == {"pendulum.length": 1, "start": 2, "start.speed.x": 3}


# --- a sweep (slow): random scenes, the decision's own promises --------------------------------------
@pytest.mark.slow
def test_random_scenes_keep_their_promises():
    rng = np.random.default_rng(1953)
    for _ in range(120):
        drag = rng.choice(["none", "linear", "quadratic"])
        quantity = rng.choice(list(scenes.QUANTITIES))
        R0 = float(rng.uniform(0.01, 0.3))
        v0 = 0.0 if rng.random() < 0.25 else float(rng.uniform(0, 1.2) * R0 * 3.13)
        text = (f"[pendulum]\nlength = 1.0\n[start]\ndisplacement = {R0!r}\nspeed = {v0!r}\n"
                f"[medium]\ndrag = \"{drag}\"\n"
                + (f"coefficient = {float(rng.uniform(0.01, 1.0))!r}\n" if drag != "none" else "")
                + f"[question]\nquantity = \"{quantity}\"\n"
                + (f"duration = {float(rng.uniform(1, 30))!r}\n" if quantity in scenes.NEEDS_DURATION else "")
                + f"tolerance = {float(10 ** rng.uniform(-7, -2))!r}\n")
        try:
            d = scenes.decide(scenes.parse(text))
        except scenes.SceneError as exc:
            assert exc.key == "question.quantity"  # overdamped: no revolution
            continue
        q, rich = d.scene.quantity, d.richest
        for r in d.ratings[:-1]:
            assert scenes.distance(q, r.value, rich.value) <= r.estimated_error
        if d.meets and d.chosen is not rich:
            assert scenes.distance(q, d.chosen.value, rich.value) <= d.scene.tolerance


# --- issue 16: each reproduction, replayed --------------------------------------------------------------
@pytest.mark.parametrize("name", ["classroom-period", "fig7-angular-momentum", "large-amplitude-period"])
def test_shipped_scenes_give_json(name, capsys):
    assert main(["scene", str(SCENES / f"{name}.toml"), "--json"]) in (0, 1)
    doc = json.loads(capsys.readouterr().out)
    assert doc["model"] == EXPECTED[name][0] and isinstance(doc["meets_tolerance"], bool)
    assert all(isinstance(r["confirmed"], bool) for r in doc["ladder"])


def test_any_unit_of_the_right_dimension():
    s = scenes.parse(BASE.replace("duration = 4.0", 'duration = "4000000 us"')
                     .replace("tolerance = 1e-4", 'tolerance = "0.1 mm"').replace("speed = 0.1", 'speed = "10 cm/s"'))
    assert s.duration == pytest.approx(4.0, rel=1e-15) and s.tolerance == pytest.approx(1e-4) and s.v0 == 0.1
    assert scenes.parse(BASE.replace("displacement = 0.1", 'amplitude_deg = "0.5 rad"')).phi0 == pytest.approx(0.5)


@pytest.mark.parametrize("tail,words", [
    ("x = " + "[" * 100000 + "]" * 100000 + "\n", "nested"),
    ("x = " + "{a = " * 3000 + "1" + "}" * 3000 + "\n", "nested"),
    ("\0\1\2", "TOML"),
])
def test_hostile_toml_is_one_error(tail, words):
    with pytest.raises(scenes.SceneError, match=words):
        scenes.parse(BASE + tail)


@pytest.mark.parametrize("make", [
    lambda p: "/dev/zero",
    lambda p: (p.write_bytes(b"\xff\xfe" * 10) and str(p)),
    lambda p: (p.write_text("x = 1\n" * 300000) and str(p)),
    lambda p: (p.write_text(BASE.replace('drag = "quadratic"', 'drag = "linear"').replace("coefficient = 0.5",
                                                                                         "coefficient = 1e300"))
               and str(p)),
    lambda p: (p.write_text(BASE.replace("length = 1.0          # m", "length = 1e-300")
                            .replace("displacement = 0.1", "amplitude_deg = 10")) and str(p)),
])
def test_hostile_scene_files_on_the_command_line(make, tmp_path):
    import subprocess
    import sys

    path = make(tmp_path / "s.toml")
    proc = subprocess.run([sys.executable, "-m", "quasicentral.cli", "scene", path], capture_output=True, text=True,
                          timeout=120)
    assert proc.returncode == 2 and proc.stdout == "", proc.stderr
    assert proc.stderr.count("\n") == 1 and proc.stderr.startswith("quasicentral: error:")
    assert "Traceback" not in proc.stderr and "Warning" not in proc.stderr


def test_title_is_plain_text_in_the_plot_and_escaped_on_the_terminal(tmp_path, capsys):
    p = tmp_path / "t.toml"
    p.write_text('[scene]\ntitle = "$\\\\foo{$ and ∑"\n' + BASE.replace("duration = 4.0", "duration = 1.0")
                 .replace("tolerance = 1e-4", "tolerance = 1e-2"))
    assert main(["scene", str(p), "--plot", str(tmp_path / "t.png")]) == 0
    assert (tmp_path / "t.png").read_bytes()[:4] == b"\x89PNG"
    assert "$\\foo{$" in capsys.readouterr().out
    err = scenes.SceneError("bad", "scene.title", 1, "a\x1b[31m.toml")
    assert "\x1b" not in str(err) and "\\x1b" in str(err)


def test_plot_is_never_written_through_a_symbolic_link(tmp_path, capsys):
    """--plot writes a temporary file and renames it into place: a link at the path is refused
    (one line naming the option, exit 2) and its target is left as it was."""
    target = tmp_path / "target.txt"
    target.write_text("keep")
    link = tmp_path / "p.png"
    link.symlink_to(target)
    assert main(["scene", str(SCENES / "large-amplitude-period.toml"), "--plot", str(link)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--plot" in err and "symbolic link" in err
    assert target.read_text() == "keep" and link.is_symlink()
    assert [p.name for p in tmp_path.iterdir() if p.name.endswith(".tmp")] == []
