"""Small swings of the spherical pendulum: closed forms of the motion, one algorithm for
double precision (numpy) and any precision (mpmath on object arrays).

Linear drag R = 2κmv, section 4 of [Brepta1953]: ẍ = −Ω²x − 2κẋ (16), ÿ = −Ω²y − 2κẏ (17),
with x = R0, y = 0, ẋ = 0, ẏ = v0 at t = 0.  With ω² = Ω² − κ² (of either sign),

    x = R0 e^{−κt} (C + κ S),    y = v0 e^{−κt} S,
    C = cos ωt,  S = sin(ωt)/ω        (ω² > 0, the paper's (19)),
    C = 1,       S = t                (ω² = 0, the paper's (21)),
    C = cosh μt, S = sinh(μt)/μ       (ω² = −μ² < 0, overdamped; the paper leaves it out).

C and S are entire in ω², so the three regimes join continuously; forming ω² as
(Ω − κ)(Ω + κ) keeps it exact to rounding when κ is within 1e-12 of Ω (Ω² − κ² would cancel).
S is computed as t·sinc, never as a difference.  In the overdamped regime with large μt the
exponentials are combined as e^{(μ−κ)t} with μ − κ = −Ω²/(κ + μ) (no cancellation, no overflow).
κ = 0 is the ideal ellipse (13).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mpmath
import numpy as np


class ParameterError(ValueError):
    pass


@dataclass(frozen=True)
class Ops:
    """The arithmetic a closed form runs on: numpy ufuncs, or mpmath over object arrays."""

    exp: object
    sin: object
    cos: object
    sinh: object
    cosh: object
    sqrt: object
    expm1: object
    asarray: object


DOUBLE = Ops(np.exp, np.sin, np.cos, np.sinh, np.cosh, np.sqrt, np.expm1, lambda a: np.asarray(a, dtype=float))


def _mp_ops() -> Ops:
    v = lambda f: np.frompyfunc(f, 1, 1)  # noqa: E731
    return Ops(v(mpmath.exp), v(mpmath.sin), v(mpmath.cos), v(mpmath.sinh), v(mpmath.cosh), v(mpmath.sqrt),
               v(mpmath.expm1), lambda a: np.array([mpmath.mpf(x) for x in np.ravel(a)], dtype=object))


MP = _mp_ops()


def _sinc(ops: Ops, z, t):
    """sin(z)/z · t, with the limit t at z = 0."""
    return t * ops.sin(z) / z if np.all(z != 0) else np.where(z == 0, t, t * ops.sin(z) / np.where(z == 0, 1, z))


def linear(t, R0, v0, Omega, kappa, ops: Ops = DOUBLE):
    """(x, y) of the linear-drag motion at times ``t`` (any κ ≥ 0, Ω > 0).

    >>> x, y = linear([0.0, 1.0], 0.1, 0.1, math.sqrt(10), 0.4)
    >>> float(x[0]), float(y[0])
    (0.1, 0.0)
    """
    t = ops.asarray(t)
    one = t[0] * 0 + 1 if t.size else 1.0
    R0, v0, Omega, kappa = (one * R0, one * v0, one * Omega, one * kappa)
    w2 = (Omega - kappa) * (Omega + kappa)
    damp = ops.exp(-kappa * t)
    if w2 > 0:
        w = ops.sqrt(np.asarray([w2], dtype=object if ops is MP else float))[0]
        c = ops.cos(w * t)
        s = ops.sin(w * t) / w
        return R0 * damp * (c + kappa * s), v0 * damp * s
    if w2 == 0:
        return R0 * damp * (1 + kappa * t), v0 * damp * t
    mu = ops.sqrt(np.asarray([-w2], dtype=object if ops is MP else float))[0]
    # e^{−κt} cosh μt = (e^{−(κ−μ)t} + e^{−(κ+μ)t})/2, κ − μ = Ω²/(κ + μ) exactly
    slow = ops.exp(-(Omega * Omega / (kappa + mu)) * t)
    fast = ops.exp(-(kappa + mu) * t)
    small = mu * t < 1
    # where μt is small, sinh(μt)/μ = t·(1 + …): the exponential form would cancel
    with np.errstate(over="ignore", invalid="ignore"):
        ch = np.where(small, damp * ops.cosh(np.where(small, mu * t, 0 * t)), (slow + fast) / 2)
        sh = np.where(small, damp * ops.sinh(np.where(small, mu * t, 0 * t)) / mu, (slow - fast) / (2 * mu))
    return R0 * (ch + kappa * sh), v0 * sh


def parse_exact(text: str, name: str):
    """A decimal string read exactly into mpmath (no double on the way)."""
    try:
        val = mpmath.mpf(str(text).strip())
    except (ValueError, TypeError):
        raise ParameterError(f"{name} must be a number, not {text!r}") from None
    if not mpmath.isfinite(val):
        raise ParameterError(f"{name} must be finite, not {text!r}")
    return val


def check_parameters(R0, v0, Omega2, kappa=0, beta=0) -> None:
    for name, val, ok, what in (("R0", R0, R0 > 0, "a positive length"), ("v0", v0, v0 >= 0, "≥ 0"),
                                ("Ω² (g/l)", Omega2, Omega2 > 0, "positive"),
                                ("kappa", kappa, kappa >= 0, "≥ 0 (a drag coefficient)"),
                                ("beta", beta, beta >= 0, "≥ 0 (a drag coefficient)")):
        if not ok:
            raise ParameterError(f"{name} must be {what}, not {val}")


def integrate_linear(t, R0, v0, Omega, kappa, rtol=1e-12):
    """Independent cross-check: (16)–(17) integrated numerically (scipy DOP853)."""
    from scipy.integrate import solve_ivp

    t = np.asarray(t, dtype=float)
    rhs = lambda _t, u: (u[2], u[3], -Omega**2 * u[0] - 2 * kappa * u[2], -Omega**2 * u[1] - 2 * kappa * u[3])  # noqa: E731
    sol = solve_ivp(rhs, (0, float(t.max())), (R0, 0.0, 0.0, v0), method="DOP853", t_eval=t, rtol=rtol,
                    atol=rtol * max(R0, v0 / Omega) * 1e-3)
    return sol.y[0], sol.y[1]


# --- models for the command line ------------------------------------------------------------
MODELS = {
    "ellipse": "no drag, small swings: the ellipse of section 3 (13)",
    "linear": "linear drag R = 2κmv, closed form of section 4 (all three regimes)",
}


def trajectory(model: str, t, R0, v0, Omega2, kappa=0, beta=0, dps: int | None = None):
    """(x, y) arrays for a model; with ``dps`` the parameters are mpmath numbers and the
    evaluation runs at that precision (inside a local context)."""
    check_parameters(R0, v0, Omega2, kappa, beta)
    if model == "ellipse":
        kappa = 0
    elif model != "linear":
        raise ParameterError(f"unknown model {model!r}; choose from {', '.join(MODELS)}")
    if dps is None:
        return linear(t, float(R0), float(v0), math.sqrt(float(Omega2)), float(kappa))
    with mpmath.workdps(dps + 10):
        x, y = linear(t, R0, v0, mpmath.sqrt(Omega2), mpmath.mpf(kappa), ops=MP)
    return x, y
