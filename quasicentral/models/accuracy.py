"""The error of the paper's approximate models against the reference solutions of
:mod:`quasicentral.models.reference` — the closed forms of :mod:`quasicentral.models.motion` and
:mod:`quasicentral.models.quadratic` measured against an independent integration.  Above the three
(it imports each), so that none of them imports another back.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np

from quasicentral.models import motion, quadratic, registry
from quasicentral.models.integrators import scale
from quasicentral.models.reference import ModelError, Solution, exact_parameter, solve

def closed_form_error(sol: Solution) -> float:
    """max |(x, y) − closed form| / scale for the linear model (the closed form of
    :func:`quasicentral.models.motion.linear`, exact in all three regimes), at the solution's precision."""
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
    model = registry.lookup(model, registry.APPROXIMATIONS, ModelError).value
    if against not in ("spherical", "small-swing"):
        raise ModelError("against must be 'spherical' or 'small-swing'")
    shape = np.shape(t)
    tt = np.ravel(np.asarray(t, dtype=float))
    params = dict(params)
    _check_drag(model, params)
    if against == "spherical":
        ref = solve("spherical", params, tt, tol=tol)
    else:
        small = {k: v for k, v in params.items() if k not in ("l", "g")}
        if "omega2" not in small:
            small["omega2"] = float(exact_parameter(params["g"], "g") / exact_parameter(params["l"], "l"))
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


def _check_drag(model: str, params: dict) -> None:
    """The drag law the approximation takes, and only that one."""
    beta_given = params.get("beta") not in (None, 0, 0.0, "0")
    kappa_given = params.get("kappa") not in (None, 0, 0.0, "0")
    if model == "ellipse" and (beta_given or kappa_given):
        raise ModelError("the ellipse has no drag: leave out kappa and beta", "kappa" if kappa_given else "beta")
    if model == "linear" and beta_given:
        raise ModelError("the linear model takes kappa, not beta", "beta")
    if model.startswith("quadratic") and kappa_given:
        raise ModelError(f"model {model} takes beta, not kappa", "kappa")
    if model.startswith("quadratic") and not beta_given:
        raise ModelError(f"model {model} needs beta (quadratic drag, 1/m)", "beta")


def _small_swing_quadratic(tt, R0, v0, om, beta, tol):
    sol = solve("quadratic", {"R0": R0, "v0": v0, "omega2": om * om, "beta": beta}, tt, tol=tol)
    return sol.x, sol.y
