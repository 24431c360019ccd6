"""The ladder of models for a scene: which rungs model it, what each neglects (a priori), and
the decision (a posteriori: each rung against the next richer one)."""

from __future__ import annotations

import math
import time
import warnings
from dataclasses import dataclass

import numpy as np

from quasicentral.models import period
from quasicentral.models.registry import Model
from quasicentral.studies.scenes.reading import NEEDS_DURATION, Scene, SceneError
from quasicentral.studies.scenes.rungs import EPS, FADED, answer, distance, rtol_for, sample_times, scale

SERIES_MAX_TERMS = 200
#: the rungs and what each is (the one registry of model names)
RUNGS = {m.value: m.description for m in Model}


# --- the ladder ------------------------------------------------------------------------------------
def ladder(scene: Scene) -> list[str]:
    """The rungs that model this scene, cheapest first."""
    if scene.quantity == "period" and scene.planar and scene.drag == "none":
        return ["ellipse", "period-series", "period-exact"]
    middle = {"none": [], "linear": ["linear"], "quadratic": ["quadratic-first-order", "quadratic"]}[scene.drag]
    return ["ellipse", *middle, "spherical"]


@dataclass(frozen=True)
class Rating:
    """One rung's answer for the scene and its error estimates (in the answer's unit)."""

    model: str
    value: object  # float, or an array: (2, n) positions, (n,) angular momenta; None: no answer
    a_priori: float
    neglects: str
    estimated_error: float  # a posteriori: difference + the richer rung's own estimate
    checked_against: str
    difference: float  # |answer − the richer rung's answer| on the sample (or the two tolerances')
    confirmed: bool  # the difference is within ten times the a-priori estimate (plus the richer's error)
    seconds: float
    terms: int | None = None  # for period-series

    @property
    def label(self) -> str:
        return f"{self.model} ({self.terms} terms)" if self.terms else self.model


@dataclass(frozen=True)
class Decision:
    scene: Scene
    ratings: tuple  # Rating, cheapest first (for the series: the failing N − 1, the chosen N)
    chosen: Rating
    meets: bool
    times: np.ndarray | None  # the sample of the scene (trajectory, angular momentum)
    seconds: float

    @property
    def rejected(self) -> list[Rating]:
        return self.ratings[: self.ratings.index(self.chosen)] if self.meets else list(self.ratings[:-1])

    @property
    def richest(self) -> Rating:
        return self.ratings[-1]


# --- a priori: the orders of what a rung neglects ---------------------------------------------------
@dataclass(frozen=True)
class Effect:
    """A neglected effect: what it is (words, with its order) and its size for the scene."""

    what: str
    size: float


#: the effects each rung neglects (the ellipse's depend on the scene: see :func:`_neglected`)
NEGLECTS = {
    "linear": ("finite-swing",),
    "quadratic-first-order": ("drag-second-order", "finite-swing"),
    "quadratic": ("finite-swing", "integration"),
    "spherical": ("integration",),
    "period-series": ("series",),
    "period-exact": ("rounding",),
}


@dataclass(frozen=True)
class _Sizes:
    """The scene's scales the a-priori orders are built from."""

    A: float  # the larger semi-axis
    eps2: float  # (A/l)²
    T: float  # the duration (or T0)
    L0: float  # R0·v0
    w: float  # √(Ω² − κ²), 0 when overdamped
    x: float  # the fraction of the amplitude lost to quadratic drag over T
    t_eff: float  # the time over which the finite-swing phase drift accumulates
    drift: float  # phase drift + apsidal precession per radian of Ωt
    rounding: float

    @classmethod
    def of(cls, scene: Scene) -> "_Sizes":
        a, b = scene.semi_axes
        A, Om, k = max(a, b), scene.Omega, scene.kappa
        T = scene.duration or scene.T0
        x = scene.beta * A * Om * T / 2
        t_eff = (T if k == 0 else -math.expm1(-2 * k * T) / (2 * k)) / (1 + x)
        return cls(A, (A / scene.length) ** 2, T, scene.R0 * scene.v0, math.sqrt(max(0.0, (Om - k) * (Om + k))), x,
                   t_eff, ((a * a + b * b) / 16 + 3 * a * b / 8) / scene.length**2, 4 * EPS * scale(scene))


def _trajectory_effects(s: Scene, z: _Sizes, rtol, terms) -> dict:
    A, Om, k, beta, T = z.A, s.Omega, s.kappa, s.beta, z.T
    return {
        "drag-linear": Effect("the drag, O(κT)", min(A * (-math.expm1(-k * T) + k * k * T / (2 * Om)), 2 * A)),
        "drag-quadratic": Effect("the drag, O(βA·ΩT)", min(A * z.x, 2 * A)),
        "drag-second-order": Effect("second order in β, O((βA)²(1 + ΩT)²)",
                                    min(A * (beta * A) ** 2 * (1 + (Om * T / 2) ** 2), 2 * A)),
        "finite-swing": Effect("finite swings, O(ε²) + O(ε²ΩT)", min(A * (z.eps2 / 8 + Om * z.t_eff * z.drift), 2 * A)),
        "integration": Effect("the integration, O(rtol·ΩT)", A * rtol * (10 + Om * T)),
    }


def _period_effects(s: Scene, z: _Sizes, rtol, terms) -> dict:
    from quasicentral.models import period

    T0, Om, A = s.T0, s.Omega, z.A
    m = math.sin(s.phi0 / 2) ** 2

    def tail(n):
        return T0 * float(period.series_coefficients(n + 1)[-1]) * m**n / (1 - m)

    return {
        "drag-linear": Effect("the drag, O(κ²/Ω²)", T0 * (Om / z.w - 1) if z.w > 0 else math.inf),
        "drag-quadratic": Effect("the drag, O((βA)²) (no first-order change)", T0 * (s.beta * A) ** 2),
        "drag-second-order": Effect("second order in β, O((βA)²)", T0 * (s.beta * A) ** 2),
        "finite-swing": Effect("finite swings, O(ε²)", T0 * z.drift),
        "integration": Effect("the integration, O(rtol)", T0 * rtol * 10),
        "series-1": Effect("the terms of (66) after the first, O(k²)", tail(1)),
        "series": Effect(f"the tail of (66) after {terms} terms", tail(terms or 1)),
        "rounding": Effect("rounding only", z.rounding),
    }


def _decay_effects(s: Scene, z: _Sizes, rtol, terms) -> dict:
    R0, k, beta, l = s.R0, s.kappa, s.beta, s.length
    a, b = s.semi_axes
    d_lin = -R0 * math.expm1(-2 * math.pi * k / z.w) if z.w > 0 else R0
    d_quad = min(R0, math.pi * beta * R0 * R0)
    precession = R0 * abs(a * a - b * b) * a * a * (9 * math.pi**2 / 32) / l**4 if not s.planar else 0.0
    return {
        "drag-linear": Effect("the drag, O(κ/Ω)", d_lin),
        "drag-quadratic": Effect("the drag, O(βR0)", d_quad),
        "drag-second-order": Effect("second order in β, O((βR0)²)", min(R0, R0 * (math.pi * beta * R0) ** 2)),
        "finite-swing": Effect("finite swings, O(ε²) and the precession, O(ε⁴)",
                               (d_lin if k else d_quad) * z.eps2 + precession),
        "integration": Effect("the integration, O(rtol)", R0 * rtol * 10),
    }


def _momentum_effects(s: Scene, z: _Sizes, rtol, terms) -> dict:
    a, b = s.semi_axes
    path = s.Omega * math.sqrt((a * a + b * b) / 2) * z.T  # rms speed of the ellipse × T
    L0, k, beta = z.L0, s.kappa, s.beta
    return {
        "drag-linear": Effect("the drag, O(κT) (law (4))", -L0 * math.expm1(-2 * k * z.T)),
        "drag-quadratic": Effect("the drag, O(βs) (law (5))", -L0 * math.expm1(-beta * path)),
        "drag-second-order": Effect("the path's change by the drag, O(βs·βA·ΩT)", L0 * min(1.0, beta * path * z.x)),
        "finite-swing": Effect("the path's change by finite swings, O(βs·ε²) (laws (4), (5) are exact)",
                               L0 * min(1.0, beta * path * z.eps2)),
        "integration": Effect("the integration, O(rtol·ΩT)", L0 * rtol * (10 + s.Omega * z.T)),
        "rounding": Effect("nothing: the law is exact (rounding only)", z.rounding),
    }


_EFFECTS = {"trajectory": _trajectory_effects, "period": _period_effects, "decay-per-revolution": _decay_effects,
            "angular-momentum": _momentum_effects}


def _neglected(scene: Scene, model: str) -> tuple[str, ...]:
    """The names of the effects a rung neglects on this scene."""
    if model in NEGLECTS:
        if model == "linear" and scene.quantity == "angular-momentum":
            return ("rounding",)
        return NEGLECTS[model]
    if model != "ellipse":
        raise ValueError(f"unknown model {model!r}")
    if scene.quantity == "period" and scene.planar and scene.drag == "none":
        return ("series-1",)
    if scene.quantity == "angular-momentum" and scene.drag != "quadratic":
        return ("drag-linear",) if scene.drag == "linear" else ("rounding",)
    return {"none": (), "linear": ("drag-linear",), "quadratic": ("drag-quadratic",)}[scene.drag] + ("finite-swing",)


def a_priori(scene: Scene, model: str, rtol: float = 1e-12, terms: int | None = None) -> tuple[float, str]:
    """(estimate, what is neglected) for a rung on this scene, from the orders of the neglected
    terms (O(1) constants; see the package's docstring)."""
    keys = _neglected(scene, model)
    effects = _EFFECTS[scene.quantity](scene, _Sizes.of(scene), rtol, terms)
    value = sum(effects[k].size for k in keys)
    return max(value, 4 * EPS * scale(scene)), "; ".join(effects[k].what for k in keys)


# --- the decision ------------------------------------------------------------------------------------
def decide(scene: Scene) -> Decision:
    """Rate every rung of the scene's ladder and choose the cheapest within the tolerance.
    Warnings of numpy and scipy stay inside; a failed integration is a :class:`SceneError`."""
    import scipy.integrate  # noqa: F401 - imported before the clocks start: each rung's seconds are its own
    import scipy.special  # noqa: F401

    start = time.perf_counter()
    times = sample_times(scene) if scene.quantity in NEEDS_DURATION else None
    names = ladder(scene)
    try:
        with np.errstate(all="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore")
            if names[-1] == "period-exact":
                ratings = _decide_planar_period(scene)
            else:
                ratings = _decide_ladder(scene, names, rtol_for(scene), times)
    except (ArithmeticError, ValueError) as exc:
        if isinstance(exc, SceneError):
            raise
        raise scene.error(f"cannot be answered for this scene: {exc}", "question.quantity") from None
    ratings = tuple(ratings)
    chosen = next((r for r in ratings if r.estimated_error <= scene.tolerance), None)
    meets = chosen is not None
    return Decision(scene, ratings, chosen if meets else ratings[-1], meets, times, time.perf_counter() - start)


def _decide_ladder(scene: Scene, names: list[str], rtol: float, times) -> list[Rating]:
    """Each rung's answer, its difference to the next richer rung, and its error estimate."""
    values, seconds = [], []
    for name in names:
        t0 = time.perf_counter()
        values.append(answer(scene, name, rtol=rtol, times=times))
        seconds.append(time.perf_counter() - t0)
    if values[-1] is None:
        raise scene.error(f"has no answer for this scene: the bob does not complete a revolution before its "
                          f"swing fades below {FADED:g} of its start (overdamped: κ ≥ Ω)", "question.quantity")
    # the richest rung: its own integration at two tolerances
    loose_rtol = min(1e-6, 100 * rtol)
    t0 = time.perf_counter()
    loose = answer(scene, names[-1], rtol=loose_rtol, times=times)
    seconds[-1] += time.perf_counter() - t0
    n = len(names)
    diffs = [distance(scene.quantity, values[i], values[i + 1]) for i in range(n - 1)]
    diffs.append(max(distance(scene.quantity, values[-1], loose), 4 * EPS * scale(scene)))
    errors = [0.0] * n
    errors[-1] = diffs[-1]
    for i in range(n - 2, -1, -1):
        # two triangle bounds, both measured: via the next richer rung, and via the richest
        errors[i] = min(diffs[i] + errors[i + 1], distance(scene.quantity, values[i], values[-1]) + errors[-1])
    ratings = []
    for i, name in enumerate(names):
        # the richest rung's estimate measures the run at 100·rtol: its a priori is that run's
        pri, neglects = a_priori(scene, name, rtol=rtol if i < n - 1 else loose_rtol)
        against = names[i + 1] if i < n - 1 else f"itself at rtol {loose_rtol:.0e} (answer at rtol {rtol:.0e})"
        richer = errors[i + 1] if i < n - 1 else 0.0
        ratings.append(Rating(name, values[i], float(pri), neglects, float(errors[i]), against, float(diffs[i]),
                              bool(diffs[i] <= 10 * pri + richer), seconds[i]))
    return ratings


def _decide_planar_period(scene: Scene) -> list[Rating]:
    """Planar swing, no drag: T0, the series (66) with the fewest terms that meets the tolerance
    (and the one term fewer, rejected), and the exact period, itself checked against mpmath."""
    import mpmath

    t0 = time.perf_counter()
    exact = answer(scene, "period-exact")
    with mpmath.workdps(40):
        t_mp = 2 * mpmath.pi * mpmath.sqrt(mpmath.mpf(scene.length) / mpmath.mpf(scene.g)) * \
            period.period_ratio_mp(phi0=scene.phi0, dps=30)
        err_exact = float(abs(mpmath.mpf(exact) - t_mp)) + 2 * EPS * exact
    sec_exact = time.perf_counter() - t0
    pri, neg = a_priori(scene, "period-exact")
    exact_rating = Rating("period-exact", exact, pri, neg, err_exact, "mpmath, 30 digits", err_exact,
                          bool(err_exact <= 10 * pri), sec_exact)

    def rate(model, value, seconds, terms=None):
        pri, neg = a_priori(scene, model, terms=terms)
        diff = abs(value - exact)
        return Rating(model, value, pri, neg, diff + err_exact, "period-exact", diff, bool(diff <= 10 * pri + err_exact),
                      seconds, terms)

    t0 = time.perf_counter()
    ellipse_rating = rate("ellipse", scene.T0, time.perf_counter() - t0)
    ratings = [ellipse_rating]
    if ellipse_rating.estimated_error > scene.tolerance:
        # the fewest terms of (66) within the tolerance; the series converges like mⁿ/n with
        # m = sin²(φ0/2) < ½ (amplitudes below 90°): it reaches rounding before 60 terms
        m = math.sin(scene.phi0 / 2) ** 2
        series = []
        for n in range(2, SERIES_MAX_TERMS + 1):
            t0 = time.perf_counter()
            series.append(rate("period-series", answer(scene, "period-series", terms=n), time.perf_counter() - t0,
                               terms=n))
            if series[-1].estimated_error <= scene.tolerance or m**n < 1e-3 * EPS:
                break
        # the rejected one term fewer (if it is not the ellipse) and the last one tried
        ratings += series[-2:]
    ratings.append(exact_rating)
    return ratings
