"""Reference solutions to trust: high-precision integrators for every model, each validated,
(the error of the paper's approximations against them: :mod:`quasicentral.models.accuracy`).

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

import math
from dataclasses import dataclass, field

import mpmath
import numpy as np

from quasicentral.models import registry
from quasicentral.models.equations import System
from quasicentral.models.integrators import heyoka_available, scale, solve_dop853, solve_heyoka, solve_mpmath
from quasicentral.models.parameters import ParameterError, Swing
from quasicentral.notation import numbers

MODELS = tuple(m.value for m in registry.REFERENCE)
METHODS = ("auto", "dop853", "heyoka", "mpmath")
DOUBLE_TOL = 1e-14  # below this the results are mpmath numbers


ModelError = ParameterError  # bad model, parameters or method


# --- parameters -------------------------------------------------------------------------------
@dataclass(frozen=True)
class Problem(Swing):
    """One initial-value problem: a :class:`Swing` (checked there) and the model.  Numbers are
    mpmath mpf read exactly (a float at its binary value, a string as the decimal it spells);
    ``length`` and ``g`` only matter for the spherical model (Ω² = g/l)."""

    model: str = "linear"

    @property
    def planar(self) -> bool:
        """A swing along a line with quadratic drag: the speed passes through zero."""
        return self.v0 == 0 and self.beta != 0

    @property
    def kind(self) -> System:
        base = self.model if self.model != "spherical" else ("spherical-quadratic" if self.beta else "spherical-linear")
        return System(base + ("-planar" if self.planar and self.model != "linear" else ""))

    def pars(self) -> tuple:
        """The runtime parameters of the compiled system, in the order of :func:`equations.rhs`."""
        if self.model == "linear":
            return (self.omega2, 2 * self.kappa)
        if self.model == "quadratic":
            return (self.omega2, self.beta)
        drag = self.beta if self.beta else 2 * self.kappa
        return (self.length, self.g, drag)


def exact_parameter(value, name):
    """A parameter read exactly (mpmath), or :class:`ModelError` naming it."""
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
    get = lambda k, d=None: exact_parameter(params[k], k) if params.get(k) is not None else d  # noqa: E731
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
    return Problem(R0, v0, omega2, kappa, beta, length, g, model=model)  # checked by Swing


# --- the systems ---------------------------------------------------------------------------
def _dim(kind, extras: bool) -> int:
    return System(kind).dimension(extras)


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
        times = np.array([exact_parameter(a, "t") for a in np.ravel(np.asarray(t, dtype=object))], dtype=object)
        if any(a < 0 for a in times):
            raise ModelError("times must be ≥ 0 (the motion starts at t = 0)")
        if method == "auto":
            method = "dop853" if tol >= 1e-13 else ("heyoka" if heyoka_available() else "mpmath")
        if method == "dop853":
            if tol < 1e-14:
                raise ModelError("dop853 works in double precision: tol must be ≥ 1e-14")
            rows, info = solve_dop853(p, [float(a) for a in times], tol, extras)
        elif method == "heyoka":
            if not heyoka_available():
                raise ModelError("heyoka is not installed (pip install 'quasicentral[fast]')")
            rows, info = solve_heyoka(p, times, tol, extras)
        else:
            rows, info = solve_mpmath(p, times, tol, extras)
        return _assemble(p, times if tol < DOUBLE_TOL else np.array([float(a) for a in times]), rows, extras, method,
                         tol, info, as_float=tol >= DOUBLE_TOL)


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
