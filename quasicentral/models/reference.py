"""Reference solutions to trust: high-precision integrators for every model, each validated,
and the error of the paper's approximations measured against the full pendulum.

Models (the state is the horizontal position and velocity; ``s`` is the arc length, ``D`` the
energy per mass lost to drag, both optional "extras"):

* ``"linear"`` — small swings under linear drag, [Brepta1953] (16)–(17):
  ẍ = −Ω²x − 2κẋ, ÿ = −Ω²y − 2κẏ;
* ``"quadratic"`` — small swings under quadratic drag, (26)–(27):
  ẍ = −Ω²x − βẋv, ÿ = −Ω²y − βẏv, v = √(ẋ² + ẏ²);
* ``"spherical"`` — the full nonlinear spherical pendulum (6)–(7) with either drag law, in the
  horizontal coordinates of :mod:`quasicentral.models.spherical` (no singularity at the lowest point):
  Ẍ = −γẊ − X(v² + gZ)/l², Ÿ = −γẎ − Y(v² + gZ)/l², Z = √(l² − X² − Y²), γ = 2κ or βv.

Initial conditions are the paper's: x = R0, y = 0, ẋ = 0, ẏ = v0.

The speed enters the quadratic drag through v = √(ẋ² + ẏ²).  Where v0 > 0 the angular momentum
xẏ − yẋ = R0 v0 e^{−βs} never vanishes, so neither does v, and the right-hand side is analytic.
A planar swing (v0 = 0) stops at each turning point: there v|ẋ| has a kink and a Taylor method
returns NaN (the derivative of √(ẋ²) at 0).  The planar system is therefore integrated as
ẍ = −Ω²x − σβẋ², σ = sign ẋ fixed on each stretch, with an event at σẋ = 0 that flips σ and
restarts: every stretch is analytic and the method keeps its order.

Back ends, one algorithm each, all with the same systems:

* ``"dop853"`` — scipy's Fortran DOP853 (``scipy.integrate.ode``); relative tolerances down to
  ~1e-13, the ~1e-12 reference in milliseconds;
* ``"heyoka"`` — heyoka.py's Taylor integrator (the optional extra ``quasicentral[fast]``): in
  double precision for tol ≥ 1e-15, in quadruple precision (real128) down to 1e-32, in MPFR
  (``heyoka.real``) at any precision beyond; compiled once per system and reused;
* ``"mpmath"`` — ``mpmath.odefun`` (Taylor series, any precision; seconds per run): the
  fallback where heyoka does not install.

``solve(..., method="auto")`` picks dop853 for tol ≥ 1e-13, else heyoka when importable, else
mpmath.  Results at tol < 1e-14 are mpmath numbers (object arrays), read in a local context.

>>> sol = solve("linear", {"R0": 0.1, "v0": 0.1, "omega2": 10.0, "kappa": 0.4}, [0.0, 1.0])
>>> float(sol.x[0]), float(sol.y[0])
(0.1, 0.0)
"""

from __future__ import annotations

import functools
import math
import warnings
from dataclasses import dataclass, field

import mpmath
import numpy as np

from quasicentral.models import registry
from quasicentral.models.equations import System, rhs
from quasicentral.models.parameters import ParameterError, Swing
from quasicentral.notation import numbers

MODELS = tuple(m.value for m in registry.REFERENCE)
METHODS = ("auto", "dop853", "heyoka", "mpmath")
DOUBLE_TOL = 1e-14  # below this the results are mpmath numbers


ModelError = ParameterError  # bad model, parameters or method


# --- parameters -------------------------------------------------------------------------------
@dataclass(frozen=True)
class Problem:
    """One initial-value problem.  Numbers are mpmath mpf read exactly (a float at its binary
    value, a string as the decimal it spells); ``length`` and ``g`` only matter for the
    spherical model (Ω² = g/l)."""

    model: str
    R0: object
    v0: object
    omega2: object
    kappa: object = 0
    beta: object = 0
    length: object = None
    g: object = None

    @property
    def planar(self) -> bool:
        """A swing along a line with quadratic drag: the speed passes through zero."""
        return self.v0 == 0 and self.beta != 0

    @property
    def kind(self) -> System:
        base = self.model if self.model != "spherical" else ("spherical-quadratic" if self.beta else "spherical-linear")
        return System(base + ("-planar" if self.planar and self.model != "linear" else ""))

    def pars(self) -> tuple:
        """The runtime parameters of the compiled system, in the order of :func:`_rhs`."""
        if self.model == "linear":
            return (self.omega2, 2 * self.kappa)
        if self.model == "quadratic":
            return (self.omega2, self.beta)
        drag = self.beta if self.beta else 2 * self.kappa
        return (self.length, self.g, drag)


def _exact(value, name):
    try:
        return numbers.to_mpf(value, name)
    except numbers.NumberError as exc:
        raise ModelError(str(exc), name) from None


def problem(model: str, params: dict) -> Problem:
    """A :class:`Problem` from a mapping with keys ``R0``, ``v0``, ``kappa`` *or* ``beta``, and
    either ``omega2`` (Ω² = g/l, small-swing models) or ``l`` and ``g`` (any model; the
    spherical model needs ``l``: with ``omega2`` and ``l``, g = Ω²l).  Call inside a
    ``mpmath.workdps`` of the precision wanted when strings carry many digits.  The
    parameters are checked by :class:`~quasicentral.models.parameters.Swing`."""
    model = registry.lookup(model, registry.REFERENCE, ModelError).value
    unknown = set(params) - {"R0", "v0", "omega2", "l", "g", "kappa", "beta"}
    if unknown:
        raise ModelError(f"unknown parameter(s) {', '.join(sorted(unknown))}")
    get = lambda k, d=None: _exact(params[k], k) if params.get(k) is not None else d  # noqa: E731
    R0, v0 = get("R0"), get("v0", mpmath.mpf(0))
    if R0 is None:
        raise ModelError("R0 is required", "R0")
    kappa, beta = get("kappa", mpmath.mpf(0)), get("beta", mpmath.mpf(0))
    length, g, omega2 = get("l"), get("g"), get("omega2")
    if omega2 is None:
        if length is None or g is None:
            raise ModelError("give omega2, or l and g", "omega2")
        if length <= 0 or g <= 0:
            raise ModelError("l and g must be positive", "l" if length <= 0 else "g")
        omega2 = g / length
    elif g is None and length is not None:
        g = omega2 * length
    elif g is not None and length is None and omega2 > 0:
        length = g / omega2
    if model == "linear" and beta:
        raise ModelError("the linear model takes kappa, not beta", "beta")
    if model == "quadratic" and kappa:
        raise ModelError("the quadratic model takes beta, not kappa", "kappa")
    if model == "spherical" and length is None:
        raise ModelError("the spherical model needs the length l (and g or omega2)", "l")
    Swing(R0, v0, omega2, kappa, beta, length, g)  # raises ParameterError (= ModelError)
    return Problem(model, R0, v0, omega2, kappa, beta, length, g)


# --- the systems ---------------------------------------------------------------------------
def _dim(kind, extras: bool) -> int:
    return System(kind).dimension(extras)


def _initial(p: Problem, extras: bool) -> list:
    z = mpmath.mpf(0)
    st = [p.R0, z] if p.planar else [p.R0, z, z, p.v0]
    return st + ([z, z] if extras else [])


# --- the solution ----------------------------------------------------------------------------
@dataclass
class Solution:
    """The state at the requested times: float arrays, or object arrays of mpmath numbers when
    the tolerance is below 1e-14.  ``s`` (arc length) and ``D`` (energy per mass dissipated)
    are None unless ``extras`` was asked for."""

    problem: Problem
    t: np.ndarray
    x: np.ndarray
    y: np.ndarray
    u: np.ndarray
    w: np.ndarray
    s: np.ndarray | None = None
    D: np.ndarray | None = None
    method: str = ""
    tol: float = 0.0
    info: dict = field(default_factory=dict)


def _assemble(p, times, rows, extras, method, tol, info, as_float):
    conv = (lambda a: float(a)) if as_float else (lambda a: a)  # noqa: E731
    dtype = float if as_float else object
    cols = list(zip(*rows)) if rows else [[] for _ in range(_dim(p.kind, extras))]
    arr = [np.array([conv(a) for a in c], dtype=dtype) for c in cols]
    zero = np.zeros(len(rows), dtype=dtype) if as_float else np.array([mpmath.mpf(0)] * len(rows), dtype=object)
    if p.planar:
        x, u = arr[0], arr[1]
        y, w = zero, zero.copy()
        rest = arr[2:]
    else:
        x, y, u, w = arr[:4]
        rest = arr[4:]
    s, D = (rest[0], rest[1]) if extras else (None, None)
    return Solution(p, times, x, y, u, w, s, D, method, tol, info)


def solve(model: str, params: dict, t, *, tol: float = 1e-12, method: str = "auto", extras: bool = False) -> Solution:
    """The state of ``model`` at times ``t`` (≥ 0, any order), accurate to about ``tol``
    relative to the motion's scale over ~10 periods.

    ``params`` as :func:`problem`; ``method`` one of :data:`METHODS`.  ``extras`` adds the arc
    length s and the dissipated energy D (for the laws (4), (5) and the energy balance).
    """
    if method not in METHODS:
        raise ModelError(f"unknown method {method!r}; choose from {', '.join(METHODS)}")
    if not (isinstance(tol, (int, float)) and 0 < tol < 1):
        raise ModelError(f"tol must be in (0, 1), not {tol!r}")
    dps = max(20, int(-math.log10(tol)) + 15)
    with mpmath.workdps(dps):
        p = problem(model, params)
        times = np.array([_exact(a, "t") for a in np.ravel(np.asarray(t, dtype=object))], dtype=object)
        if any(a < 0 for a in times):
            raise ModelError("times must be ≥ 0 (the motion starts at t = 0)")
        if method == "auto":
            method = "dop853" if tol >= 1e-13 else ("heyoka" if heyoka_available() else "mpmath")
        if method == "dop853":
            if tol < 1e-14:
                raise ModelError("dop853 works in double precision: tol must be ≥ 1e-14")
            rows, info = _solve_dop853(p, [float(a) for a in times], tol, extras)
        elif method == "heyoka":
            if not heyoka_available():
                raise ModelError("heyoka is not installed (pip install 'quasicentral[fast]')")
            rows, info = _solve_heyoka(p, times, tol, extras)
        else:
            rows, info = _solve_mpmath(p, times, tol, extras)
        return _assemble(p, times if tol < DOUBLE_TOL else np.array([float(a) for a in times]), rows, extras, method,
                         tol, info, as_float=tol >= DOUBLE_TOL)


# --- back end: scipy DOP853 (Fortran) -----------------------------------------------------------
def scale(p: Problem) -> float:
    """max(R0, v0/Ω) as a float: the size of the motion errors are measured against."""
    om = math.sqrt(float(p.omega2))
    return max(float(p.R0), float(p.v0) / om)


def _solve_dop853(p: Problem, times: list[float], tol: float, extras: bool, branchwise: bool | None = None):
    from scipy.integrate import ode

    order = sorted(range(len(times)), key=lambda i: times[i])
    pars = tuple(float(a) for a in p.pars())
    planar, kind = p.planar, p.kind
    om = math.sqrt(float(p.omega2))
    # planar: the main integration runs on the physical law σ = sign ẋ (never the analytic
    # continuation of a stretch beyond its turning point, which can blow up within a long step);
    # the step that crosses a turning point is discarded and redone up to the zero of ẋ on the
    # stretch's own analytic branch (σ fixed), so no accepted step straddles the kink.
    # (at tight tolerances the steps are short and the stretch's own branch is used throughout:
    # the step across a turning point is then smooth and accepted at once, fewer evaluations)
    if branchwise is None:
        branchwise = planar and tol <= 1e-6
    cur = {"sig": -1.0, "f": rhs(kind, pars + ((-1.0 if branchwise else None,) if planar else ()), math, extras)}
    rtol = 0.1 * tol  # the global error of DOP853 grows to ~3–10× its local tolerance over 10 periods
    atol = rtol * scale(p) * 1e-2

    def fun(tt, y):
        return cur["f"](tt, y.tolist())

    r = ode(fun).set_integrator("dop853", rtol=rtol, atol=atol, nsteps=10**7)
    prev = {}

    def solout(tt, y):  # stop where σẋ turns negative (a turning point passed inside the step)
        if cur["sig"] * y[1] < 0:
            return -1
        prev["t"], prev["y"] = tt, y.copy()
        return 0

    if planar:
        r.set_solout(solout)
        finder = ode(lambda tt, y: cur["branch"](tt, y.tolist())).set_integrator("dop853", rtol=rtol, atol=atol,
                                                                                  nsteps=10**6)
    r.set_initial_value([float(a) for a in _initial(p, extras)], 0.0)
    out = [None] * len(times)
    turns = 0
    for i in order:
        target = times[i]
        while True:
            if target - r.t <= 1e-10 / om:  # too short for DOP853: one Euler step, error ≤ 1e-20
                out[i] = list(np.asarray(r.y) + (target - r.t) * np.asarray(cur["f"](r.t, list(r.y))))
                break
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # failures are checked below (successful())
                y = r.integrate(target)
            crossed = planar and cur["sig"] * y[1] < 0  # the last step passed a turning point
            if not crossed:
                if not r.successful():
                    if branchwise:  # a branch continued too far past a turning point: the safe law
                        return _solve_dop853(p, times, tol, extras, branchwise=False)
                    raise ArithmeticError(f"dop853 failed (code {r.get_return_code()})")
                out[i] = list(y)
                break
            # a turning point in (last accepted step, r.t): Newton on ẋ(t) with the same stretch
            cur["branch"] = branch = rhs(kind, pars + (cur["sig"],), math, extras)
            tz, yz = _turning_point(finder, branch, prev["t"], prev["y"], r.t, y, 0.01 * tol / om)
            yz[1] = 0.0  # exactly at rest
            cur["sig"] = -cur["sig"]
            if branchwise:
                cur["f"] = rhs(kind, pars + (cur["sig"],), math, extras)
            turns += 1
            prev.clear()
            r.set_initial_value(yz, tz)
    return out, {"turning_points": turns}


def _turning_point(finder, f, t_a, y_a, t_b, y_b, dt_tol):
    """The zero of ẋ between two step points: a secant start, then Newton steps (ẍ from the
    right-hand side), each integrated afresh from the last accepted point.  A time error δ
    costs ~|ẍ|δ in the restart velocity, so δ ≤ ``dt_tol`` is enough."""
    u_a, u_b = y_a[1], y_b[1]
    span = t_b - t_a
    h = span * u_a / (u_a - u_b)

    def state_at(h):
        """The branch's state at t_a + h, or None where its continuation has blown up."""
        if h <= 1e-9 * span:  # too short for a step of its own: one Taylor term is exact enough
            return np.array(y_a) + h * np.array(f(t_a, list(y_a)))
        finder.set_initial_value(y_a, t_a)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # "step size becomes too small": handled below
            y = finder.integrate(t_a + h)
        return y if finder.successful() and np.all(np.isfinite(y)) else None

    yz = None
    for _ in range(60):
        yz = state_at(h)
        if yz is None:  # overshot into the branch's blow-up beyond the turning point
            h *= 0.5
            continue
        dh = -yz[1] / f(t_a + h, yz.tolist())[1]
        if abs(dh) <= dt_tol:
            break
        h = min(max(h + dh, 0.0), span)
    if yz is None:
        raise ArithmeticError("no turning point found")
    return t_a + h, np.array(yz)


# --- back end: heyoka ---------------------------------------------------------------------------
@functools.lru_cache(maxsize=1)
def heyoka_available() -> bool:
    """True when heyoka.py imports (the optional extra ``quasicentral[fast]``)."""
    try:
        import heyoka  # noqa: F401
    except Exception:  # noqa: BLE001 - any import failure means: use the fallback
        return False
    return True


def _heyoka_fp(tol: float):
    """(fp_type, precision in bits, converter from mpmath) for a tolerance."""
    import heyoka as hy

    if tol >= 1e-15:
        return float, 0, lambda a: float(a)
    if tol >= 1e-32:
        return hy.real128, 0, lambda a: hy.real128(mpmath.nstr(a, 40, min_fixed=1, max_fixed=0))
    prec = int(-math.log2(tol)) + 24
    return hy.real, prec, lambda a: hy.real(mpmath.nstr(a, int(prec * 0.302) + 6, min_fixed=1, max_fixed=0), prec)


@functools.lru_cache(maxsize=64)
def _heyoka_integrator(kind: str, extras: bool, tol: float):
    """A compiled Taylor integrator for ``kind`` (parameters at run time), cached per process."""
    import heyoka as hy

    fp, prec, conv = _heyoka_fp(tol)
    n = _dim(kind, extras)
    names = ["x", "y", "u", "w"] if not System(kind).planar else ["x", "u"]
    names += ["s", "D"] if extras else []
    vs = hy.make_vars(*names)
    npar = System(kind).n_parameters
    pars = [hy.par[i] for i in range(npar)]
    rhs = rhs(kind, pars, hy, extras)(None, vs)
    sysl = list(zip(vs, rhs))
    kw = {"fp_type": fp, "tol": conv(mpmath.mpf(tol) / 10)}
    if prec:
        kw.update(prec=prec, compact_mode=True)
    events = []
    if System(kind).planar:  # σẋ falls through zero at a turning point
        events = [hy.t_event(pars[-1] * vs[1], direction=hy.event_direction.negative, fp_type=fp)]
    zero = conv(mpmath.mpf(0))
    ta = hy.taylor_adaptive(sysl, [zero] * n, pars=[zero] * npar, t_events=events, **kw)
    return ta, conv


def _solve_heyoka(p: Problem, times, tol: float, extras: bool):
    import heyoka as hy

    ta, conv = _heyoka_integrator(p.kind, extras, float(tol))
    order = sorted(range(len(times)), key=lambda i: times[i])
    pars = list(p.pars()) + ([mpmath.mpf(-1)] if p.planar else [])
    ta.time = conv(mpmath.mpf(0))
    ta.state[:] = np.array([conv(a) for a in _initial(p, extras)], dtype=ta.state.dtype)
    ta.pars[:] = np.array([conv(a) for a in pars], dtype=ta.pars.dtype)
    if p.planar:
        ta.reset_cooldowns()
    to_mp = (lambda a: mpmath.mpf(float(a))) if ta.state.dtype == float else (lambda a: mpmath.mpf(str(a)))  # noqa: E731
    out = [None] * len(times)
    turns = 0
    if not p.planar:
        # the grid must start at the current time: prepend t = 0 and drop its row
        grid = np.array([conv(mpmath.mpf(0))] + [conv(times[i]) for i in order], dtype=ta.state.dtype)
        res = ta.propagate_grid(grid)
        if res[0] != hy.taylor_outcome.time_limit:
            raise ArithmeticError(f"heyoka stopped: {res[0]}")
        for j, i in enumerate(order):
            out[i] = [to_mp(a) for a in res[-1][j + 1]]
        return out, {"steps": None}
    for i in order:
        target = conv(times[i])
        while True:
            res = ta.propagate_until(target)
            if res[0] == hy.taylor_outcome.time_limit:
                out[i] = [to_mp(a) for a in ta.state]
                break
            if res[0] != hy.taylor_outcome(-1):
                raise ArithmeticError(f"heyoka stopped: {res[0]}")
            ta.state[1] = conv(mpmath.mpf(0))  # exactly at rest
            ta.pars[-1] = -ta.pars[-1]
            turns += 1
    return out, {"turning_points": turns}


# --- back end: mpmath odefun -------------------------------------------------------------------
def _solve_mpmath(p: Problem, times, tol: float, extras: bool):
    dps = int(-math.log10(tol)) + 8
    with mpmath.workdps(dps):
        order = sorted(range(len(times)), key=lambda i: times[i])
        pars = tuple(mpmath.mpf(a) for a in p.pars())
        y0 = [mpmath.mpf(a) for a in _initial(p, extras)]
        out = [None] * len(times)
        if not p.planar:
            sol = mpmath.odefun(rhs(p.kind, pars, mpmath, extras), 0, y0)
            for i in order:
                out[i] = list(sol(times[i]))
            return out, {}
        sig, t0, turns = -1, mpmath.mpf(0), 0
        h = 2 * mpmath.pi / mpmath.sqrt(p.omega2) / 16
        k = 0
        while k < len(order):
            sol = mpmath.odefun(rhs(p.kind, pars + (mpmath.mpf(sig),), mpmath, extras), t0, y0)
            a = t0
            while True:  # bracket the next zero of σẋ, then a root
                b = a + h
                if sig * sol(b)[1] <= 0:
                    break
                a = b
            tz = mpmath.findroot(lambda tt: sol(tt)[1], (a, b), solver="anderson")
            while k < len(order) and times[order[k]] <= tz:
                out[order[k]] = list(sol(times[order[k]]))
                k += 1
            if k == len(order):
                break
            y0 = list(sol(tz))
            y0[1] = mpmath.mpf(0)
            t0, sig, turns = tz, -sig, turns + 1
        return out, {"turning_points": turns}


# --- validation --------------------------------------------------------------------------------
def invariants(sol: Solution) -> dict:
    """The laws every solution must obey, as residuals relative to their scale (arrays):

    * ``"momentum"`` — L = xẏ − yẋ against L0 e^{−2κt} (law (4), linear drag) or L0 e^{−βs}
      (law (5), quadratic drag); exact for the small-swing models and for the full pendulum;
    * ``"energy"`` — E(t) + D(t) − E(0), the energy balance with the dissipated energy D.

    Needs ``extras=True``.  The arithmetic is the solution's (mpmath numbers where it has them).
    """
    if sol.s is None:
        raise ModelError("invariants need a solution computed with extras=True")
    p = sol.problem
    hp = sol.x.dtype == object
    lib = mpmath if hp else math
    F = (lambda a: a) if hp else float  # noqa: E731
    dps = max(20, int(-math.log10(sol.tol)) + 10) if hp else 15
    with mpmath.workdps(dps):
        R0, v0, om2 = F(p.R0), F(p.v0), F(p.omega2)
        L0 = R0 * v0
        mom, en = [], []
        if p.model == "spherical":
            ln, g = F(p.length), F(p.g)
            e0 = v0 * v0 / 2 - g * lib.sqrt(ln * ln - R0 * R0)
            escale = g * ln
        else:
            e0 = (v0 * v0 + om2 * R0 * R0) / 2
            escale = om2 * R0 * R0 + v0 * v0
        for i in range(len(sol.t)):
            x, y, u, w, s, D, t = sol.x[i], sol.y[i], sol.u[i], sol.w[i], sol.s[i], sol.D[i], F(sol.t[i])
            L = x * w - y * u
            law = L0 * (lib.exp(-2 * F(p.kappa) * t) if not p.beta else lib.exp(-F(p.beta) * s))
            mom.append((L - law) / max(L0, R0 * R0 * lib.sqrt(om2)))
            if p.model == "spherical":
                Z = lib.sqrt(ln * ln - x * x - y * y)
                zd = -(x * u + y * w) / Z
                E = (u * u + w * w + zd * zd) / 2 - g * Z
            else:
                E = (u * u + w * w + om2 * (x * x + y * y)) / 2
            en.append((E + D - e0) / escale)
        return {"momentum": np.array(mom, dtype=object if hp else float),
                "energy": np.array(en, dtype=object if hp else float)}


def closed_form_error(sol: Solution) -> float:
    """max |(x, y) − closed form| / scale for the linear model (the closed form of
    :func:`quasicentral.models.motion.linear`, exact in all three regimes), at the solution's precision."""
    from quasicentral.models import motion

    p = sol.problem
    if p.model != "linear":
        raise ModelError("the closed form is exact for the linear model only")
    hp = sol.x.dtype == object
    if not hp:
        x, y = motion.linear(np.asarray(sol.t, dtype=float), float(p.R0), float(p.v0), math.sqrt(float(p.omega2)),
                             float(p.kappa))
        return float(max(np.max(np.abs(x - sol.x)), np.max(np.abs(y - sol.y))) / scale(p))
    with mpmath.workdps(int(-math.log10(sol.tol)) + 15):
        x, y = motion.linear(list(sol.t), p.R0, p.v0, mpmath.sqrt(p.omega2), p.kappa, ops=motion.MP)
        err = max(max(abs(a - b) for a, b in zip(x, sol.x)), max(abs(a - b) for a, b in zip(y, sol.y)))
        return float(err / max(p.R0, p.v0 / mpmath.sqrt(p.omega2)))


def difference(a: Solution, b: Solution) -> float:
    """max |(x, y)_a − (x, y)_b| / scale: two solutions of one problem (e.g. two precisions)."""
    with mpmath.workdps(60):
        d = max(max(abs(mpmath.mpf(p) - mpmath.mpf(q)) for p, q in zip(a.x, b.x)),
                max(abs(mpmath.mpf(p) - mpmath.mpf(q)) for p, q in zip(a.y, b.y)))
        return float(d) / scale(a.problem)


def self_check(model: str, params: dict, t, tol: float, *, method: str = "auto") -> float:
    """The reference against itself at two precisions (tol and tol/1000): their difference
    relative to the scale; it must be ≲ tol."""
    a = solve(model, params, t, tol=tol, method=method)
    b = solve(model, params, t, tol=tol / 1000, method="auto" if tol / 1000 < 1e-13 else method)
    return difference(a, b)


# --- validity of the paper's approximations ----------------------------------------------------
APPROXIMATIONS = {m.value: m.description for m in registry.APPROXIMATIONS}


def approximation_error(model: str, params: dict, t, *, tol: float = 1e-11, against: str = "spherical") -> np.ndarray:
    """The error of one of the paper's approximate models against the full nonlinear spherical
    pendulum with the same drag, at each time of ``t``.

    Signature (stable; the scene selector builds on it)::

        approximation_error(model, params, t, *, tol=1e-11, against="spherical") -> ndarray

    * ``model`` — ``"ellipse"``, ``"linear"``, ``"quadratic"`` or ``"quadratic-first-order"``
      (:data:`quasicentral.models.registry.APPROXIMATIONS`);
    * ``params`` — a mapping with ``R0`` [m], ``v0`` [m/s], ``l`` [m] and ``g`` [m/s²] (or
      ``omega2`` = g/l with ``l``), and the drag: ``kappa`` [1/s] (R = 2κmv) or ``beta`` [1/m]
      (R = mβv²); floats or decimal strings;
    * ``t`` — times ≥ 0 [s] (scalar or array);
    * ``against`` — ``"spherical"`` (the full pendulum: every approximation at once) or
      ``"small-swing"`` (the exact small-swing motion with the same drag: only the drag
      approximation, e.g. first order in β);
    * returns float array, shape of ``t``: |(x, y)_model − (X, Y)_reference| / R0, the
      distance between the two bobs' horizontal positions relative to the initial
      displacement (1e-2 means 1 % of R0).

    The reference is integrated to ``tol`` (DOP853), far below any error of interest here.

    >>> e = approximation_error("linear", {"R0": 0.01, "v0": 0.0, "l": 1.0, "g": 9.81, "kappa": 0.1}, [0.0, 2.0])
    >>> float(e[0]), bool(1e-6 < e[1] < 1e-4)
    (0.0, True)
    """
    from quasicentral.models import motion
    from quasicentral.models import quadratic

    model = registry.lookup(model, registry.APPROXIMATIONS, ModelError).value
    if against not in ("spherical", "small-swing"):
        raise ModelError("against must be 'spherical' or 'small-swing'")
    shape = np.shape(t)
    tt = np.ravel(np.asarray(t, dtype=float))
    params = dict(params)
    beta_given = params.get("beta") not in (None, 0, 0.0, "0")
    kappa_given = params.get("kappa") not in (None, 0, 0.0, "0")
    if model == "ellipse" and (beta_given or kappa_given):
        raise ModelError("the ellipse has no drag: leave out kappa and beta")
    if model == "linear" and beta_given:
        raise ModelError("the linear model takes kappa, not beta")
    if model.startswith("quadratic") and kappa_given:
        raise ModelError(f"model {model} takes beta, not kappa")
    if model.startswith("quadratic") and not beta_given:
        raise ModelError(f"model {model} needs beta (quadratic drag, 1/m)")
    if against == "spherical":
        ref = solve("spherical", params, tt, tol=tol)
    else:
        small = {k: v for k, v in params.items() if k not in ("l", "g")}
        if "omega2" not in small:
            small["omega2"] = float(_exact(params["g"], "g") / _exact(params["l"], "l"))
        ref = solve("quadratic" if model.startswith("quadratic") else "linear", small, tt, tol=tol)
    p = ref.problem
    R0, v0, om, kap, bet = float(p.R0), float(p.v0), math.sqrt(float(p.omega2)), float(p.kappa), float(p.beta)
    if model in ("ellipse", "linear"):
        x, y = motion.linear(tt, R0, v0, om, kap if model == "linear" else 0.0)
    elif model == "quadratic-first-order":
        x, y = quadratic.first_order(tt, R0, v0, om, bet)
    else:
        x, y = _small_swing_quadratic(tt, R0, v0, om, bet, tol)
    err = np.hypot(np.asarray(x, dtype=float) - ref.x, np.asarray(y, dtype=float) - ref.y) / R0
    return err.reshape(shape)


def _small_swing_quadratic(tt, R0, v0, om, beta, tol):
    sol = solve("quadratic", {"R0": R0, "v0": v0, "omega2": om * om, "beta": beta}, tt, tol=tol)
    return sol.x, sol.y
