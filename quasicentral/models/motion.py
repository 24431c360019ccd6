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

from quasicentral.models import registry
from quasicentral.models.equations import System, rhs
from quasicentral.models.parameters import ParameterError, Swing

__all__ = ["ParameterError", "Swing", "linear", "integrate_linear", "trajectory", "first_order_warning", "MODELS"]


@dataclass(frozen=True)
class Ops:
    """The arithmetic a closed form runs on: numpy ufuncs, or mpmath over object arrays.

    ``two_prod(a, b)`` returns (p, e) with p + e = a·b exactly in double precision (Dekker's
    splitting) — the phase ωt and the decay κt grow with t, and their rounding would otherwise
    cost ~10 ulp after a few periods; in mpmath the guard digits make e = 0.
    """

    exp: object
    sin: object
    cos: object
    sinh: object
    cosh: object
    sqrt: object
    asarray: object
    two_prod: object


_SPLIT = 134217729.0  # 2^27 + 1


def _split(a):
    c = _SPLIT * a
    hi = c - (c - a)
    return hi, a - hi


def _two_prod_double(a, b):
    p = a * b
    ah, al = _split(a)
    bh, bl = _split(b)
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


DOUBLE = Ops(np.exp, np.sin, np.cos, np.sinh, np.cosh, np.sqrt, lambda a: np.asarray(a, dtype=float),
             _two_prod_double)


def _mp_ops() -> Ops:
    v = lambda f: np.frompyfunc(f, 1, 1)  # noqa: E731
    return Ops(v(mpmath.exp), v(mpmath.sin), v(mpmath.cos), v(mpmath.sinh), v(mpmath.cosh), mpmath.sqrt,
               lambda a: np.array([mpmath.mpf(x) for x in np.ravel(a)], dtype=object), lambda a, b: (a * b, 0 * b))


MP = _mp_ops()


def _two_sum(a, b):
    """(s, e) with s + e = a + b exactly (Knuth); e is 0 in mpmath up to its guard digits."""
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def _dd_sqrt(ops: Ops, hi, lo):
    """√(hi + lo) as a double-double (r, rl)."""
    r = ops.sqrt(hi)
    p, e = ops.two_prod(r, r)
    return r, ((hi - p) - e + lo) / (2 * r)


CHUNK = 16384  # points per block in double precision: the ~40 temporaries stay in the L2 cache


def linear(t, R0, v0, Omega, kappa, ops: Ops = DOUBLE, *, omega2=None):
    """(x, y) of the linear-drag motion at times ``t`` (any κ ≥ 0, Ω > 0).

    ``omega2``, when given, is Ω² = g/l exactly (the double the user gave): ω² = Ω² − κ² is then
    formed as a double-double from it, and the rounding of Ω = √(Ω²) never enters the phase.
    A drag beyond κ = 1e150 (where κ² and the splitting of κ overflow) takes the overdamped
    form in plain arithmetic: the fast mode has died within 1e-148 s.

    Long arrays are evaluated in blocks of ``CHUNK`` points (measured on 10⁶ points: 37 ns per
    point instead of 63 ns, the memory traffic of the compensated arithmetic being the cost).

    >>> x, y = linear([0.0, 1.0], 0.1, 0.1, math.sqrt(10), 0.4)
    >>> float(x[0]), float(y[0])
    (0.1, 0.0)
    """
    t = ops.asarray(t)
    if ops is DOUBLE:
        with np.errstate(over="ignore", under="ignore", invalid="ignore", divide="ignore"):
            if kappa > HUGE_DRAG:
                return _strongly_overdamped(t, R0, v0, Omega * Omega if omega2 is None else omega2, kappa)
            if t.ndim == 1 and t.size > CHUNK:
                x, y = np.empty_like(t), np.empty_like(t)
                for i in range(0, t.size, CHUNK):
                    x[i:i + CHUNK], y[i:i + CHUNK] = _linear(t[i:i + CHUNK], R0, v0, Omega, kappa, ops, omega2)
                return x, y
            return _linear(t, R0, v0, Omega, kappa, ops, omega2)
    return _linear(t, R0, v0, Omega, kappa, ops, omega2)


HUGE_DRAG = 1e150  # κ [1/s] beyond which κ² or Dekker's splitting of κ would overflow


def _strongly_overdamped(t, R0, v0, omega2, kappa):
    """x = R0[e_s(1 + κ/μ) + e_f(1 − κ/μ)]/2, y = v0(e_s − e_f)/(2μ), rates Ω²/(κ + μ) and κ + μ."""
    r = math.sqrt(omega2) / kappa
    mu = kappa * math.sqrt((1 - r) * (1 + r))
    slow = np.exp(-(omega2 / (kappa + mu)) * t)
    fast = np.exp(-(kappa + mu) * t)
    k_mu = 1 / math.sqrt((1 - r) * (1 + r))
    x = R0 * (slow * (1 + k_mu) + fast * (1 - k_mu)) / 2
    return x, v0 * (slow - fast) / (2 * mu)


def _omega_squared(ops: Ops, Omega, kappa, omega2):
    """ω² = Ω² − κ² as a double-double (hi, lo)."""
    if omega2 is None:  # (Ω − κ)(Ω + κ): exact differences, one exact product
        d1, d1e = _two_sum(Omega, -kappa)
        d2, d2e = _two_sum(Omega, kappa)
        w2, w2e = ops.two_prod(d1, d2)
        return w2, w2e + d1 * d2e + d1e * d2
    k2, k2e = ops.two_prod(kappa, kappa)
    hi, lo = _two_sum(omega2, -k2)
    return _two_sum(hi, lo - k2e)


def _linear(t, R0, v0, Omega, kappa, ops: Ops, omega2=None):
    w2, w2e = _omega_squared(ops, Omega, kappa, omega2)
    om2 = Omega * Omega if omega2 is None else omega2
    q, qe = ops.two_prod(kappa, t)
    damp = ops.exp(-q) * (1 - qe)  # e^{−κt}, its exponent's rounding error qe corrected
    if w2 + w2e > 0:
        w, wl = _dd_sqrt(ops, w2, w2e)
        ph, phe = ops.two_prod(w, t)
        phe = phe + wl * t
        sn, cs = ops.sin(ph), ops.cos(ph)
        if ops is DOUBLE and np.max(np.abs(ph), initial=0.0) > 1e7:
            # the correction is no longer tiny: rotate by it exactly
            ce, se = np.cos(phe), np.sin(phe)
            c = cs * ce - sn * se
            s = (sn * ce + cs * se) / w * (1 - wl / w)
        else:
            c = cs - phe * sn  # |phe| ≤ ulp(ωt): its square is below the rounding
            s = (sn + phe * cs) / w * (1 - wl / w)
        return R0 * damp * (c + kappa * s), v0 * damp * s
    if w2 + w2e == 0:
        return R0 * damp * (1 + kappa * t), v0 * damp * t
    mu, mul = _dd_sqrt(ops, -w2, -w2e)
    mt, mte = ops.two_prod(mu, t)
    mte = mte + mul * t
    small = mt < 1
    # e^{−κt} cosh μt = (e^{−(κ−μ)t} + e^{−(κ+μ)t})/2 with κ − μ = Ω²/(κ + μ) (no cancellation);
    # where μt is small the sinh form is used instead (the difference of exponentials cancels)
    slow = ops.exp(-(om2 / (kappa + mu)) * t)
    fast = ops.exp(-(kappa + mu) * t)
    with np.errstate(over="ignore", invalid="ignore"):
        m_small = np.where(small, mt, 0 * t)
        e_small = np.where(small, mte, 0 * t)
        chs, shs = ops.cosh(m_small), ops.sinh(m_small)
        ch = np.where(small, damp * (chs + e_small * shs), (slow + fast) / 2)
        sh = np.where(small, damp * (shs + e_small * chs) / mu * (1 - mul / mu), (slow - fast) / (2 * mu))
    return R0 * (ch + kappa * sh), v0 * sh


def integrate_linear(t, R0, v0, Omega, kappa, rtol=1e-12):
    """Independent cross-check: (16)–(17) integrated numerically (scipy DOP853)."""
    from scipy.integrate import solve_ivp

    t = np.asarray(t, dtype=float)
    f = rhs(System.LINEAR, (Omega**2, 2 * kappa))
    sol = solve_ivp(f, (0, float(t.max())), (R0, 0.0, 0.0, v0), method="DOP853", t_eval=t, rtol=rtol,
                    atol=rtol * max(R0, v0 / Omega) * 1e-3)
    if not sol.success:
        raise ParameterError(f"the integration failed: {sol.message}")
    return sol.y[0], sol.y[1]


# --- models for the command line ------------------------------------------------------------
MODELS = {m.value: m.description for m in registry.TRAJECTORY}

#: how far in time each model is evaluated: the closed forms while the double-double phase
#: resolves ωt (and Dekker's splitting cannot overflow), the integrations within seconds
MAX_PERIODS = {"ellipse": 1e150, "linear": 1e150, "quadratic-first-order": 1e12, "quadratic": 1e5}

#: the first-order quadratic-drag solution is reported as out of its range when the neglected
#: second order, (βA)²(1 + (Ωt/2)²) of the amplitude A, exceeds this
FIRST_ORDER_LIMIT = 1e-3


def first_order_warning(swing: Swing, t_end: float) -> str | None:
    """A sentence when the first order in β does not hold up to ``t_end``, else None: the
    neglected second order is O((βA)²(1 + (Ωt/2)²)) of the amplitude A = max(R0, v0/Ω)
    (the a-priori estimate of the scenes)."""
    beta, A, Om = float(swing.beta), float(swing.scale), math.sqrt(float(swing.omega2))
    x, phase = beta * A, Om * t_end / 2
    second = x * x * (1 + phase * phase)  # products overflow to inf (a power would raise)
    if not second > FIRST_ORDER_LIMIT:
        return None
    return (f"quadratic-first-order is out of its range here: the neglected second order in β is about "
            f"{min(second, 1e300):.2g} of the amplitude by t = {t_end:g} s (βA = {beta * A:.2g}); "
            "use --model quadratic")


def trajectory(model: str, t, R0, v0, Omega2, kappa=0, beta=0, dps: int | None = None, *, length=None, g=None):
    """(x, y) arrays for a model; with ``dps`` the parameters are mpmath numbers and the
    evaluation runs at that precision (inside a local context).  The parameters are checked by
    :class:`Swing` (with ``length`` and ``g`` when known: R0 below the length)."""
    from quasicentral.models import quadratic

    model = registry.lookup(model, registry.TRAJECTORY, ParameterError).value
    Swing(R0, v0, Omega2, kappa, beta, length, g)
    periods = max((float(x) for x in t), default=0.0) * math.sqrt(float(Omega2)) / (2 * math.pi)
    if periods > MAX_PERIODS[model]:
        raise ParameterError(f"model {model} covers at most {MAX_PERIODS[model]:.0e} periods 2π/Ω; "
                             f"the last time asked is {periods:.3g} periods", "t")
    if model == "ellipse":
        kappa = 0
    if dps is None:
        args = (float(R0), float(v0), math.sqrt(float(Omega2)))
        if model == "quadratic-first-order":
            with np.errstate(all="ignore"):
                return quadratic.first_order(t, *args, float(beta))
        if model == "quadratic":
            return quadratic.integrate_full(t, *args, float(beta))
        return linear(t, *args, float(kappa), omega2=float(Omega2))
    with mpmath.workdps(dps + 10):
        Omega = mpmath.sqrt(Omega2)
        if model == "quadratic-first-order":
            return quadratic.first_order(t, R0, v0, Omega, mpmath.mpf(beta), ops=quadratic.MP)
        if model == "quadratic":
            return quadratic.integrate_full_mp(t, R0, v0, Omega, mpmath.mpf(beta), dps)
        return linear(t, R0, v0, Omega, mpmath.mpf(kappa), ops=MP, omega2=Omega2)
