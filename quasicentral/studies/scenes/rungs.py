"""The rungs' answers to a scene's question: closed forms, the period, and the integrations
(the models of :mod:`quasicentral.models`; the equations are :func:`quasicentral.models.equations.rhs`)."""

from __future__ import annotations

import math

import numpy as np

from quasicentral.models import motion, period, quadratic, spherical
from quasicentral.models.equations import System, rhs
from quasicentral.studies.scenes.reading import NEEDS_DURATION, Scene

POINTS_PER_PERIOD = 32
MIN_POINTS = 257
FADED = 1e-6  # a revolution must end before the swing fades below this fraction of its start
EPS = float(np.finfo(float).eps)


def sample_times(scene: Scene) -> np.ndarray:
    """The sample of the scene: POINTS_PER_PERIOD points per small-swing period over the duration."""
    n = max(MIN_POINTS, int(math.ceil(POINTS_PER_PERIOD * scene.duration / scene.T0)) + 1)
    return np.linspace(0.0, scene.duration, n)


def rtol_for(scene: Scene) -> float:
    """The integration tolerance the numerical rungs need: a thousandth of the asked relative
    accuracy, within [1e-12, 1e-8] (model no more than the scene needs — the integrator too)."""
    return float(min(1e-8, max(1e-12, 1e-3 * scene.tolerance / scale(scene))))


def scale(scene: Scene) -> float:
    """The size of the scene's answer: the swing, R0, T0 or the angular momentum."""
    a, b = scene.semi_axes
    return {"trajectory": max(a, b), "decay-per-revolution": scene.R0, "period": scene.T0,
            "angular-momentum": max(scene.R0 * scene.v0, EPS * scene.R0 * scene.R0 * scene.Omega)}[scene.quantity]


def distance(quantity: str, a, b) -> float:
    """How far apart two answers are: the largest distance between two trajectories, the
    largest difference of two L(t), the difference of two numbers; ∞ if one has no answer."""
    if a is None or b is None:
        return math.inf
    if quantity == "trajectory":
        return float(np.max(np.hypot(a[0] - b[0], a[1] - b[1])))
    if quantity == "angular-momentum":
        return float(np.max(np.abs(a - b)))
    return abs(float(a) - float(b))


# --- the rungs' answers -------------------------------------------------------------------------------
def _small_rhs(Omega: float, beta: float):
    """(26)–(27) as a first-order system for (x, y, ẋ, ẏ): :func:`equations.rhs` of ``QUADRATIC``."""
    return rhs(System.QUADRATIC, (Omega * Omega, beta), math)


def _full_rhs(scene: Scene):
    return spherical.rhs_factory(scene.length, scene.g, scene.kappa, scene.beta)


def _atol(scene: Scene, rtol: float) -> float:
    a, b = scene.semi_axes
    return rtol * max(a, b) * min(1.0, scene.Omega) * 1e-2


def _states(f, scene: Scene, t: np.ndarray, rtol: float) -> np.ndarray:
    """(X, Y, Ẋ, Ẏ) at times t (a swing with v0 > 0: the speed never vanishes, no kink)."""
    from scipy.integrate import solve_ivp

    sol = solve_ivp(f, (0.0, float(t[-1])), (scene.R0, 0.0, 0.0, scene.v0), method="DOP853", t_eval=t, rtol=rtol,
                    atol=_atol(scene, rtol))
    if not sol.success or sol.y.shape[1] != t.size:
        raise ArithmeticError(f"integration failed: {sol.message}")
    return sol.y


def first_revolution(f, scene: Scene, rtol: float, t_max: float):
    """(t, state) at the end of the first revolution of the system ``f``: the azimuth has turned
    through 2π (Y crosses zero upwards), or for a planar swing the bob is back at a turning point
    on the release side (Ẋ crosses zero downwards, after the far turning point).  The integration
    restarts at the far turning point, so a drag with a kink where the speed vanishes is never
    stepped across.  None when no revolution completes before ``t_max``, or before the swing
    has faded below FADED of its start (overdamped: there the integration only follows noise)."""
    from scipy.integrate import solve_ivp

    atol = _atol(scene, rtol)
    a, b = scene.semi_axes
    floor, w2 = FADED * max(a, b), scene.Omega**2

    def faded(_t, s):  # the swing's size √(X² + Y² + v²/Ω²), zero only at rest
        return math.sqrt(s[0] * s[0] + s[1] * s[1] + (s[2] * s[2] + s[3] * s[3]) / w2) - floor

    faded.terminal, faded.direction = True, -1
    # leave the start, where the event functions vanish
    t0 = scene.T0 / 8
    sol = solve_ivp(f, (0.0, t0), (scene.R0, 0.0, 0.0, scene.v0), method="DOP853", rtol=rtol, atol=atol)
    state = sol.y[:, -1].copy()
    crossings = ((2, 1), (2, -1)) if scene.planar else ((1, 1),)
    for index, direction in crossings:
        def event(_t, s, i=index):
            return s[i]

        event.terminal, event.direction = True, direction
        sol = solve_ivp(f, (t0, t_max), state, method="DOP853", rtol=rtol, atol=atol, events=(event, faded))
        if sol.status == -1:
            raise ArithmeticError(f"integration failed: {sol.message}")
        if sol.status != 1 or not sol.t_events[0].size:
            return None
        t0, state = float(sol.t_events[0][0]), sol.y_events[0][0].copy()
        state[index] = 0.0
    return t0, state


def _revolution_limit(scene: Scene) -> float:
    w2 = (scene.Omega - scene.kappa) * (scene.Omega + scene.kappa)
    base = 50 * scene.T0
    return max(base, 3 * 2 * math.pi / math.sqrt(w2)) if w2 > 0 else base


def answer(scene: Scene, model: str, rtol: float = 1e-12, times: np.ndarray | None = None, terms: int | None = None):
    """The answer of one rung to the scene's question (None: the rung has no answer, e.g. no
    revolution completes)."""
    q, Om, R0, v0 = scene.quantity, scene.Omega, scene.R0, scene.v0
    k, beta, T0 = scene.kappa, scene.beta, scene.T0
    if q in NEEDS_DURATION and times is None:
        times = sample_times(scene)
    w2 = (Om - k) * (Om + k)
    if model in ("period-series", "period-exact"):
        if model == "period-exact":
            return T0 * float(period.period_ratio(scene.phi0))
        m = math.sin(scene.phi0 / 2) ** 2
        return T0 * float(period.series_ratio(np.array([m]), terms)[0][0])
    if model == "ellipse":
        return {"trajectory": lambda: np.array(motion.linear(times, R0, v0, Om, 0.0)),
                "period": lambda: T0,
                "decay-per-revolution": lambda: 0.0,
                "angular-momentum": lambda: np.full(times.shape, R0 * v0)}[q]()
    if model == "linear":
        if q == "trajectory":
            return np.array(motion.linear(times, R0, v0, Om, k))
        if q == "angular-momentum":  # law (4), exact in this model
            return R0 * v0 * np.exp(-2 * k * times)
        if w2 <= 0:
            return None  # aperiodic: no revolution
        w = math.sqrt(w2)
        return 2 * math.pi / w if q == "period" else -R0 * math.expm1(-2 * math.pi * k / w)
    if model == "quadratic-first-order":
        if q == "trajectory":
            return np.array(quadratic.first_order(times, R0, v0, Om, beta))
        if q == "period":  # the first-order revolution ends at Ωt = 2π exactly (G(2π) = 0)
            return T0
        if q == "decay-per-revolution":
            x, _ = quadratic.first_order(np.array([T0]), R0, v0, Om, beta)
            return R0 - float(x[0])
        return R0 * v0 * np.exp(-beta * ellipse_path(scene, times))  # (5) along the ideal ellipse
    if model in ("quadratic", "spherical"):
        f = _small_rhs(Om, beta) if model == "quadratic" else _full_rhs(scene)
        if q == "trajectory":
            if model == "quadratic":
                return np.array(quadratic.integrate_full(times, R0, v0, Om, beta, rtol=rtol))
            return np.array(spherical.integrate(times, R0, v0, scene.length, scene.g, k, beta, rtol=rtol))
        if q == "angular-momentum":
            if scene.planar:
                return np.zeros(times.shape)
            X, Y, U, W = _states(f, scene, times, rtol)
            return X * W - Y * U
        rev = first_revolution(f, scene, rtol, _revolution_limit(scene))
        if rev is None:
            return None
        t_rev, state = rev
        return t_rev if q == "period" else R0 - float(state[0])
    raise ValueError(f"unknown model {model!r}")


def ellipse_path(scene: Scene, t) -> np.ndarray:
    """The path length s0(t) along the ideal ellipse (24)–(25):
    s0 = (u/Ω)∫₀^{Ωt} √(1 − m cos²φ) dφ = R0 [E(Ωt − π/2 | m) + E(m)], u = R0Ω, m = (u² − v0²)/u²."""
    from scipy.special import ellipe, ellipeinc

    u = scene.R0 * scene.Omega
    m = (u - scene.v0) * (u + scene.v0) / (u * u)
    return scene.R0 * (ellipeinc(scene.Omega * np.asarray(t, dtype=float) - math.pi / 2, m) + ellipe(m))
