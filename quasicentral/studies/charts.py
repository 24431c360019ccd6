"""Speed against accuracy, and where methods fail: work–precision charts, stability maps and
the validity of the paper's approximations.  Data first, then pictures:

* ``measure_*`` functions time and check every method and return rows (dicts);
* :func:`write_csv` writes them with a header naming the machine and the library versions
  (``# key: value`` lines; no timestamps, so the only run-to-run differences are the timings);
* :func:`render` draws a PNG from a CSV *file* — it never recomputes anything — with fixed
  sizes and metadata, byte-identical for the same CSV.

Work–precision (one chart per quantity, one panel per case; cost per evaluation against the
maximum error over the case, errors computed in mpmath so that they show below 1e-16):

* ``period`` — T/T0 at 60° and 170°: ellipk, agm (double); series (66) truncated after N terms;
  quadrature (scipy at several tolerances); ODE to the lowest point (several tolerances);
  mpmath ellipk / agm / quad at several precisions; python-flint balls correctly rounded;
* ``elliptic`` — K(m), (K − E)/m and E(φ|m), the integrals the closed forms use;
* ``linear`` — the linear-drag trajectory over 10 periods: closed form in double and mpmath,
  the reference integrators at several tolerances, the project's solve_ivp cross-check;
* ``quadratic`` — the first-order quadratic-drag closed form: double, mpmath, and the
  linearized forced equations integrated at several tolerances;
* ``quadratic-full`` and ``spherical`` — (26)–(27) and the full pendulum with drag: every
  integrator the project has, at several tolerances.

Stability maps (error against the parameter that drives a method into trouble; the project's
default beside the naive route): ``period-near-pi`` (k² → 1, amplitude → π), ``k2-to-0``
((K − E)/m and the printed ζ-form as u → v0), ``kappa-to-omega`` (ω = √(Ω² − κ²) formed
naively), ``zeta-beyond-pi`` (the printed ζ-form past Ωt = π), ``beta-r0-omega-t`` (first
order in β once βR0·Ωt is not small), ``long-times`` (phase rounding, ODE error growth).

Validity (``validity``): the error of each approximation of the paper against the full
nonlinear pendulum with drag, over amplitude × drag after 1 and 10 periods, with the contours
1 %, 0.1 % and 1e-6 of R0; and the first-order error fitted as C·(βR0)^p.
"""

from __future__ import annotations

import csv
import io
import math
import platform
import time
from dataclasses import dataclass
from pathlib import Path

import mpmath
import numpy as np

from quasicentral.models import motion

from quasicentral.models import period

from quasicentral.models import quadratic

from quasicentral.models import reference

OMEGA = math.sqrt(10.0)
QUANTITIES = ("period", "elliptic", "linear", "quadratic", "quadratic-full", "spherical")
MAPS = ("period-near-pi", "k2-to-0", "kappa-to-omega", "zeta-beyond-pi", "beta-r0-omega-t", "long-times")
CHARTS = tuple(f"workprecision-{q}" for q in QUANTITIES) + tuple(f"stability-{m}" for m in MAPS) + ("validity",)


class ChartError(ValueError):
    pass


# --- the machine --------------------------------------------------------------------------------
def machine() -> dict:
    """The machine and library versions the measurements were taken with (no timestamps)."""
    import os

    import scipy

    info = {"machine": platform.machine(), "processor": _cpu_name(), "cores": str(os.cpu_count()),
            "system": platform.system(), "python": platform.python_version(), "numpy": np.__version__,
            "scipy": scipy.__version__, "mpmath": mpmath.__version__, "mpmath_backend": mpmath.libmp.BACKEND}
    try:
        import flint

        info["python-flint"] = flint.__version__
    except Exception:  # noqa: BLE001
        info["python-flint"] = "absent"
    if reference.heyoka_available():
        import heyoka

        info["heyoka"] = heyoka.__version__
    else:
        info["heyoka"] = "absent"
    return info


def _cpu_name() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


# --- timing and errors -----------------------------------------------------------------------------
@dataclass(frozen=True)
class Settings:
    """How hard to measure: ``quick`` is a coarse run for CI and tests."""

    quick: bool = False

    @property
    def budget(self) -> float:  # seconds of repeated calls per timing
        return 0.003 if self.quick else 0.05

    @property
    def periods(self) -> int:
        return 2 if self.quick else 10


def _timed(fn, settings: Settings, per: int = 1):
    """(value, seconds per evaluation): one warm-up call (which also gives the value and pays
    for lazy imports and compilation), one timed call, then — if that was shorter than the
    budget — the best of three batches sized to the budget; ``per`` evaluations per call."""
    val = fn()
    t0 = time.perf_counter()
    fn()
    first = time.perf_counter() - t0
    best = first
    if first < settings.budget:
        n = max(1, min(10000, int(settings.budget / max(first, 1e-7))))
        for _ in range(3):
            t0 = time.perf_counter()
            for _ in range(n):
                fn()
            best = min(best, (time.perf_counter() - t0) / n)
    return val, best / per


def _rel(value, ref) -> float:
    """|value − ref| / |ref| in mpmath at the reference's precision (0 when exact)."""
    v = mpmath.mpf(value) if not isinstance(value, mpmath.mpf) else value
    return float(abs(v - ref) / abs(ref))


def _traj_err(x, y, xr, yr, scale) -> float:
    """max |Δx|, |Δy| over the points, / scale; NaN when the method returned a non-finite value."""
    e = mpmath.mpf(0)
    for a, b in list(zip(x, xr)) + list(zip(y, yr)):
        a = mpmath.mpf(a)
        if not mpmath.isfinite(a):
            return float("nan")
        e = max(e, abs(a - b))
    return float(e / scale)


def _row(quantity, case, method, family, setting, seconds, error, **extra):
    r = {"quantity": quantity, "case": case, "method": method, "family": family, "setting": str(setting),
         "seconds": seconds, "error": error}
    r.update(extra)
    return r


# --- the naive routes the maps show failing ---------------------------------------------------------
def naive_period(phi0):
    """2K(m)/π with m = sin²(φ0/2) formed first: loses everything as φ0 → π."""
    from scipy.special import ellipk

    return 2 / math.pi * ellipk(np.sin(np.asarray(phi0, dtype=float) / 2) ** 2)


def naive_k_minus_e(m):
    """(K − E)/m as written: cancels completely as m → 0."""
    from scipy.special import ellipe, ellipk

    m = np.asarray(m, dtype=float)
    return (ellipk(m) - ellipe(m)) / m


def default_k_minus_e(m):
    """(K − E)/m = R_D(0, 1 − m, 1)/3 (DLMF 19.25.1), as :mod:`quasicentral.quadratic` uses it."""
    from scipy.special import elliprd

    m = np.asarray(m, dtype=float)
    return elliprd(0 * m, 1 - m, 1 + 0 * m) / 3


def naive_linear(t, R0, v0, Omega, kappa):
    """The general solution as ``dsolve`` gives it: exponentials e^{λ±t} with the roots
    λ± = −κ ± √(κ² − Ω²) (complex when κ < Ω), the root formed naively from the rounded κ² − Ω²,
    and the constants with 1/(λ+ − λ−):

        x = R0 (λ+ e^{λ−t} − λ− e^{λ+t})/(λ+ − λ−),   y = v0 (e^{λ+t} − e^{λ−t})/(λ+ − λ−).

    Exact in exact arithmetic for κ ≠ Ω; as κ → Ω the difference of nearly equal exponentials
    loses ~|λ+ − λ−|⁻¹ ulp, and at κ = Ω it is 0/0."""
    t = np.asarray(t, dtype=float)
    root = np.sqrt(complex(kappa * kappa - Omega * Omega))
    lp, lm = -kappa + root, -kappa - root
    with np.errstate(all="ignore"):
        ep, em = np.exp(lp * t), np.exp(lm * t)
        x = R0 * (lp * em - lm * ep) / (lp - lm)
        y = v0 * (ep - em) / (lp - lm)
    return np.real(x), np.real(y)


def naive_phase_linear(t, R0, v0, Omega, kappa):
    """The printed (19) with plain double arithmetic: ω = √(Ω² − κ²) and the phase ωt rounded
    (no compensation), the form whose rounding grows with t."""
    t = np.asarray(t, dtype=float)
    w = math.sqrt(Omega * Omega - kappa * kappa)
    damp = np.exp(-kappa * t)
    return R0 * damp * (np.cos(w * t) + kappa * np.sin(w * t) / w), v0 * damp * np.sin(w * t) / w


def zeta_form(t, R0, v0, Omega, beta):
    """The paper's printed solution (28)–(30) with its constants: F(k, ζ), E(k, ζ) of
    ζ = cos Ωt, K, E complete, the 1/k² factors as printed and k² = 1 − v0²/u² formed naively.
    Right for 0 ≤ Ωt ≤ π only: beyond, ζ = cos Ωt repeats and the secular growth is lost."""
    from scipy.special import ellipe, ellipeinc, ellipk, ellipkinc

    t = np.asarray(t, dtype=float)
    R0, v0, Omega = np.float64(R0), np.float64(v0), np.float64(Omega)  # 1/0 gives inf, not an exception
    u = R0 * Omega
    m = np.float64(1 - (v0 / u) ** 2)  # a numpy scalar: 1/k² at k² = 0 gives inf, not an exception
    th = Omega * t
    z = np.cos(th)
    phi = np.arcsin(z)
    F, E = ellipkinc(phi, m), ellipeinc(phi, m)
    K, Ec = ellipk(m), ellipe(m)
    root = z * np.sqrt((1 - z * z) * (1 - m * z * z)) / 3
    jc = -(1 - m) / (3 * m) * F + (1 + m) / (3 * m) * E + root  # the braces of (28)
    jc_end = -(1 - m) / (3 * m) * K + (1 + m) / (3 * m) * Ec
    js = (1 - m) / (3 * m) * F + (2 * m - 1) / (3 * m) * E - root  # the brackets of (30)
    js_end = (1 - m) / (3 * m) * K + (2 * m - 1) / (3 * m) * Ec
    V3 = (u * u - (u * u - v0 * v0) * z * z) ** 1.5
    x = beta * R0 / (3 * Omega * (u * u - v0 * v0)) * (V3 - v0**3) * np.sin(th) + (
        beta * R0 * R0 * (jc - jc_end) + R0) * np.cos(th)
    y = v0 / Omega * (beta * R0 * (js - js_end) + 1) * np.sin(th) + beta * v0 / (
        3 * Omega**2 * (u * u - v0 * v0)) * (V3 - v0**3) * np.cos(th)
    return x, y


# --- work–precision: the period --------------------------------------------------------------------
def _exact_decimal(x: float) -> str:
    from decimal import Decimal

    return str(Decimal(x))


def measure_period(settings: Settings) -> list[dict]:
    rows = []
    for deg in (60.0, 170.0):
        phi0 = math.radians(deg)
        case = f"amplitude {deg:g}°"
        with mpmath.workdps(140):
            ref = period.period_ratio_mp(phi0=phi0, dps=130, method="agm")
            arr = np.full(1000, phi0)
            for name in ("ellipk", "agm"):
                v, s = _timed(lambda: period.period_ratio(arr, method=name), settings, per=1000)
                rows.append(_row("period", case, f"{name} (double, arrays)", "closed form, double", "", s,
                                 _rel(float(v[0]), ref)))
            terms = (1, 2, 4, 8, 16, 32) if settings.quick else (1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 128, 256)
            for n in terms:
                v, s = _timed(lambda: period.period_ratio(arr, method="series", terms=n), settings, per=1000)
                rows.append(_row("period", case, "series (66), double", "series", n, s, _rel(float(v[0]), ref)))
            for eps in ((1e-4, 1e-10, 2e-14) if settings.quick else (1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-13, 2e-14)):
                v, s = _timed(lambda: _period_quad(phi0, eps), settings)
                rows.append(_row("period", case, "quadrature (scipy quad)", "quadrature", eps, s, _rel(v, ref)))
            for rt in ((1e-4, 1e-8, 1e-12) if settings.quick else (1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-13)):
                v, s = _timed(lambda: period.ode_ratio(phi0, rt), settings)
                rows.append(_row("period", case, "ODE to the lowest point (DOP853)", "ODE", rt, s, _rel(v, ref)))
            digits = (15, 30, 60) if settings.quick else (15, 20, 30, 50, 80, 100)
            for dps in digits:
                for meth in ("ellipk", "agm"):
                    v, s = _timed(lambda: period.period_ratio_mp(phi0=phi0, dps=dps, method=meth), settings)
                    rows.append(_row("period", case, f"mpmath {meth}", "mpmath", dps, s, _rel(v, ref)))
            for dps in ((15, 30) if settings.quick else (15, 20, 30, 50)):
                v, s = _timed(lambda: period.period_ratio_mp(phi0=phi0, dps=dps, method="quad"), settings)
                rows.append(_row("period", case, "mpmath quad", "mpmath", dps, s, _rel(v, ref)))
            text = _exact_decimal(phi0)
            for dg in ((10, 30, 60) if settings.quick else (10, 15, 20, 30, 50, 80, 100)):
                for meth in ("agm", "ellipk"):
                    v, s = _timed(lambda: period.period_ratio_rounded(phi0=text, digits=dg, method=meth), settings)
                    rows.append(_row("period", case, f"flint balls {meth}, correctly rounded", "balls", dg, s,
                                     _rel(mpmath.mpf(v), ref)))
    return rows


def _period_quad(phi0, eps):
    from scipy.integrate import quad

    p = math.cos(phi0 / 2) ** 2
    val = quad(lambda s: 1 / math.sqrt(math.cos(s) ** 2 + p * math.sin(s) ** 2), 0, math.pi / 2, epsabs=0,
               epsrel=eps, limit=200)[0]
    return 2 / math.pi * val


# --- work–precision: the elliptic integrals ----------------------------------------------------------
def measure_elliptic(settings: Settings) -> list[dict]:
    from scipy import special
    from scipy.integrate import quad

    import flint

    rows = []
    cases = [("K(m), m = 0.9", "K", 0.9, None), ("(K − E)/m, m = 0.01", "D", 0.01, None),
             ("E(φ|m), φ = 1.2, m = 0.7", "Einc", 0.7, 1.2)]
    for case, what, m, phi in cases:
        with mpmath.workdps(140):
            mm, pp = mpmath.mpf(m), (mpmath.mpf(phi) if phi is not None else None)
            ref = {"K": lambda: mpmath.ellipk(mm), "D": lambda: (mpmath.ellipk(mm) - mpmath.ellipe(mm)) / mm,
                   "Einc": lambda: mpmath.ellipe(pp, mm)}[what]()
            arr = np.full(1000, m)
            dbl = {"K": [("scipy ellipk", lambda: special.ellipk(arr)),
                         ("AGM π/(2 AGM(1, √(1−m)))", lambda: math.pi / 2 * period.agm_ratio(np.sqrt(1 - arr)))],
                   "D": [("R_D(0, 1−m, 1)/3 (scipy elliprd)", lambda: default_k_minus_e(arr)),
                         ("(ellipk − ellipe)/m", lambda: naive_k_minus_e(arr))],
                   "Einc": [("scipy ellipeinc", lambda: special.ellipeinc(np.full(1000, phi), arr))]}[what]
            for name, fn in dbl:
                v, s = _timed(fn, settings, per=1000)
                rows.append(_row("elliptic", case, f"{name} (double, arrays)", "closed form, double", "", s,
                                 _rel(float(v[0]), ref)))
            integrand = {"K": lambda x: 1 / math.sqrt(1 - m * math.sin(x) ** 2),
                         "D": lambda x: math.sin(x) ** 2 / math.sqrt(1 - m * math.sin(x) ** 2),
                         "Einc": lambda x: math.sqrt(1 - m * math.sin(x) ** 2)}[what]
            upper = phi if what == "Einc" else math.pi / 2
            for eps in ((1e-4, 1e-10, 2e-14) if settings.quick else (1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-13, 2e-14)):
                v, s = _timed(lambda: quad(integrand, 0, upper, epsabs=0, epsrel=eps, limit=200)[0], settings)
                rows.append(_row("elliptic", case, "quadrature (scipy quad)", "quadrature", eps, s, _rel(v, ref)))
            digits = (15, 30, 60) if settings.quick else (15, 20, 30, 50, 80, 100)
            for dps in digits:
                def mp_eval():
                    with mpmath.workdps(dps):
                        a = mpmath.mpf(m)
                        if what == "K":
                            return mpmath.ellipk(a)
                        if what == "D":
                            return mpmath.elliprd(0, 1 - a, 1) / 3
                        return mpmath.ellipe(mpmath.mpf(phi), a)

                v, s = _timed(mp_eval, settings)
                rows.append(_row("elliptic", case, "mpmath", "mpmath", dps, s, _rel(v, ref)))
            for bits in ((53, 100, 200) if settings.quick else (53, 64, 80, 100, 150, 200, 333)):
                def ball():
                    old = flint.ctx.prec
                    try:
                        flint.ctx.prec = bits
                        a = flint.acb(m)
                        if what == "K":
                            r = flint.acb.elliptic_k(a)
                        elif what == "D":
                            r = (flint.acb.elliptic_k(a) - flint.acb.elliptic_e(a)) / a
                        else:
                            r = flint.acb.elliptic_e_inc(flint.acb(phi), a)
                        return r.real.mid()
                    finally:
                        flint.ctx.prec = old

                v, s = _timed(ball, settings)
                rows.append(_row("elliptic", case, "flint acb (midpoint)", "balls", bits, s,
                                 _rel(mpmath.mpf(v.str(60, radius=False)), ref)))
    return rows


# --- work–precision: trajectories --------------------------------------------------------------------
def _ode_rows(quantity, case, model, params, t, ref_xy, scale, settings):
    """Rows for the reference integrators at several tolerances (dop853, heyoka)."""
    rows = []
    tols = (1e-4, 1e-8, 1e-12) if settings.quick else (1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11,
                                                       1e-12, 1e-13)
    for tol in tols:
        sol, s = _timed(lambda: reference.solve(model, params, t, tol=tol, method="dop853"), settings)
        rows.append(_row(quantity, case, "reference DOP853 (scipy ode)", "ODE", tol, s,
                         _traj_err(sol.x, sol.y, *ref_xy, scale)))
    if reference.heyoka_available():
        htols = ((1e-6, 1e-12, 1e-16, 1e-24) if settings.quick else
                 (1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14, 1e-15, 1e-18, 1e-20, 1e-24, 1e-28, 1e-32, 1e-40))
        for tol in htols:
            reference.solve(model, params, t[:1], tol=tol, method="heyoka")  # compile once (not timed)
            sol, s = _timed(lambda: reference.solve(model, params, t, tol=tol, method="heyoka"), settings)
            fp = "double" if tol >= 1e-15 else ("real128" if tol >= 1e-32 else "MPFR")
            rows.append(_row(quantity, case, f"reference heyoka Taylor ({fp})", "ODE, Taylor", tol, s,
                             _traj_err(sol.x, sol.y, *ref_xy, scale)))
    return rows


def _times(settings: Settings, n_per_period: int = 5):
    T = 2 * math.pi / OMEGA
    n = settings.periods * n_per_period
    return np.linspace(T / n_per_period, settings.periods * T, n)


def measure_linear(settings: Settings) -> list[dict]:
    R0 = v0 = 0.1
    kappa = 0.4
    t = _times(settings)
    case = f"κ = 0.4 1/s, Ω = √10 1/s, R0 = v0 = 0.1, {settings.periods} periods, {t.size} points"
    scale = max(R0, v0 / OMEGA)
    mt = [mpmath.mpf(float(a)) for a in t]
    with mpmath.workdps(90):
        xr, yr = motion.linear(mt, mpmath.mpf(R0), mpmath.mpf(v0), mpmath.mpf(OMEGA), mpmath.mpf(kappa), ops=motion.MP)
        rows = []
        v, s = _timed(lambda: motion.linear(t, R0, v0, OMEGA, kappa), settings)
        rows.append(_row("linear", case, "closed form (double)", "closed form, double", "", s,
                         _traj_err(v[0], v[1], xr, yr, scale)))
        v, s = _timed(lambda: naive_phase_linear(t, R0, v0, OMEGA, kappa), settings)
        rows.append(_row("linear", case, "closed form as printed (naive double)", "closed form, double", "", s,
                         _traj_err(v[0], v[1], xr, yr, scale)))
        for dps in ((15, 30, 50) if settings.quick else (15, 20, 30, 40, 50, 70)):
            def mp_eval():
                with mpmath.workdps(dps):
                    return motion.linear(mt, mpmath.mpf(R0), mpmath.mpf(v0), mpmath.mpf(OMEGA), mpmath.mpf(kappa),
                                         ops=motion.MP)

            v, s = _timed(mp_eval, settings)
            rows.append(_row("linear", case, "closed form (mpmath)", "mpmath", dps, s, _traj_err(v[0], v[1], xr, yr, scale)))
        for rt in ((1e-4, 1e-8, 1e-12) if settings.quick else (1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-12, 1e-13)):
            v, s = _timed(lambda: motion.integrate_linear(t, R0, v0, OMEGA, kappa, rtol=rt), settings)
            rows.append(_row("linear", case, "motion.integrate_linear (solve_ivp DOP853)", "ODE", rt, s,
                             _traj_err(v[0], v[1], xr, yr, scale)))
        # Ω² exactly the square of the double Ω the closed forms take (OMEGA**2 would round)
        rows += _ode_rows("linear", case, "linear", {"R0": R0, "v0": v0, "omega2": mpmath.mpf(OMEGA) ** 2,
                                                     "kappa": kappa}, t, (xr, yr), scale, settings)
    return rows


def _linearized(t, R0, v0, Omega, beta, rtol):
    """The forced linear equations of the first-order step, integrated (DOP853)."""
    from scipy.integrate import solve_ivp

    def rhs(tt, s):
        xd, yd = -R0 * Omega * math.sin(Omega * tt), v0 * math.cos(Omega * tt)
        sp = math.hypot(xd, yd)
        return (s[2], s[3], -Omega**2 * s[0] - beta * xd * sp, -Omega**2 * s[1] - beta * yd * sp)

    sol = solve_ivp(rhs, (0, float(t.max())), (R0, 0, 0, v0), method="DOP853", t_eval=t, rtol=rtol,
                    atol=rtol * R0 * 1e-2)
    return sol.y[0], sol.y[1]


def measure_quadratic(settings: Settings) -> list[dict]:
    R0, v0, beta = 0.1, 0.2, 0.5
    t = _times(settings)
    case = f"first order, β = 0.5 1/m, R0 = 0.1, v0 = 0.2, {settings.periods} periods, {t.size} points"
    scale = max(R0, v0 / OMEGA)
    mt = [mpmath.mpf(float(a)) for a in t]
    rows = []
    with mpmath.workdps(70):
        xr, yr = quadratic.first_order(mt, mpmath.mpf(R0), mpmath.mpf(v0), mpmath.mpf(OMEGA), mpmath.mpf(beta),
                                       ops=quadratic.MP)
        v, s = _timed(lambda: quadratic.first_order(t, R0, v0, OMEGA, beta), settings)
        rows.append(_row("quadratic", case, "closed form (double)", "closed form, double", "", s,
                         _traj_err(v[0], v[1], xr, yr, scale)))
        for dps in ((15, 30) if settings.quick else (15, 20, 30, 40, 50)):
            def mp_eval():
                with mpmath.workdps(dps):
                    return quadratic.first_order(mt, mpmath.mpf(R0), mpmath.mpf(v0), mpmath.mpf(OMEGA),
                                                 mpmath.mpf(beta), ops=quadratic.MP)

            v, s = _timed(mp_eval, settings)
            rows.append(_row("quadratic", case, "closed form (mpmath)", "mpmath", dps, s, _traj_err(v[0], v[1], xr, yr, scale)))
        for rt in ((1e-4, 1e-8, 1e-12) if settings.quick else (1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-12, 1e-13)):
            v, s = _timed(lambda: _linearized(t, R0, v0, OMEGA, beta, rt), settings)
            rows.append(_row("quadratic", case, "linearized equations integrated (DOP853)", "ODE", rt, s,
                             _traj_err(v[0], v[1], xr, yr, scale)))
    return rows


def _hp_reference(model, params, t, settings):
    """The highest-precision reference this machine can afford: heyoka MPFR at 1e-50, else
    mpmath's Taylor integrator at 1e-22 (seconds)."""
    tol = (1e-32 if settings.quick else 1e-50) if reference.heyoka_available() else 1e-22
    return reference.solve(model, params, t, tol=tol), tol


def measure_full(settings: Settings, quantity: str) -> list[dict]:
    rows = []
    if quantity == "quadratic-full":
        cases = [("quadratic", {"R0": 0.1, "v0": 0.2, "omega2": OMEGA**2, "beta": 0.5}, "v0 = 0.2 (elliptic)"),
                 ("quadratic", {"R0": 0.1, "v0": 0.0, "omega2": OMEGA**2, "beta": 0.5}, "v0 = 0 (planar, kinks)")]
    else:
        cases = [("spherical", {"R0": 0.5, "v0": 0.8, "l": 1.0, "g": 10.0, "beta": 0.5}, "β = 0.5, R0 = 0.5 l"),
                 ("spherical", {"R0": 0.5, "v0": 0.0, "l": 1.0, "g": 10.0, "beta": 0.5}, "β = 0.5, planar"),
                 ("spherical", {"R0": 0.5, "v0": 0.8, "l": 1.0, "g": 10.0, "kappa": 0.2}, "κ = 0.2, R0 = 0.5 l")]
    t = _times(settings)
    for model, params, label in cases:
        case = f"{label}, {settings.periods} periods"
        ref, _ = _hp_reference(model, params, t, settings)
        scale = reference._scale(ref.problem)
        with mpmath.workdps(70):
            xy = (list(ref.x), list(ref.y))
            rows += _ode_rows(quantity, case, model, params, t, xy, scale, settings)
            if model == "quadratic":
                for rt in ((1e-4, 1e-8, 1e-12) if settings.quick else (1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-12, 1e-13)):
                    v, s = _timed(lambda: quadratic.integrate_full(t, params["R0"], params["v0"], OMEGA, params["beta"],
                                                                   rtol=rt), settings)
                    rows.append(_row(quantity, case, "quadratic.integrate_full (solve_ivp DOP853)", "ODE", rt, s,
                                     _traj_err(v[0], v[1], *xy, scale)))
            else:
                for rt in ((1e-4, 1e-8, 1e-12) if settings.quick else (1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-12, 1e-13)):
                    kw = {"beta": params.get("beta", 0.0), "kappa": params.get("kappa", 0.0)}
                    from quasicentral.models import spherical

                    v, s = _timed(lambda: spherical.integrate(t, params["R0"], params["v0"], 1.0, 10.0, rtol=rt, **kw),
                                  settings)
                    rows.append(_row(quantity, case, "spherical.integrate (solve_ivp DOP853)", "ODE", rt, s,
                                     _traj_err(v[0], v[1], *xy, scale)))
    return rows


# --- stability maps ----------------------------------------------------------------------------------
def _map_row(name, x, method, role, error, **extra):
    r = {"map": name, "x": x, "method": method, "role": role, "error": error}
    r.update(extra)
    return r


def map_period_near_pi(settings: Settings) -> list[dict]:
    """T/T0 as φ0 → π (k² → 1): x = δ = π − φ0."""
    rows = []
    deltas = np.geomspace(1e-15, 1.0, 8 if settings.quick else 31)
    for d in deltas:
        d = float(d)
        with mpmath.workdps(60):
            ref = period.period_ratio_mp(delta=d, dps=50)
            phi0 = math.pi - d  # the amplitude as a double: already off by up to 2e-16 rad
            rows += [
                _map_row("period-near-pi", d, "default: ellipkm1(cos²(φ0/2)), δ given", "default",
                         _rel(float(period.period_ratio(delta=d)), ref)),
                _map_row("period-near-pi", d, "default, φ0 = π − δ given as a double", "default (ill-conditioned input)",
                         _rel(float(period.period_ratio(phi0)), ref) if phi0 < math.pi else float("nan")),
                _map_row("period-near-pi", d, "AGM 1/AGM(1, sin(δ/2))", "alternative",
                         _rel(float(period.period_ratio(delta=d, method="agm")), ref)),
                _map_row("period-near-pi", d, "naive: ellipk(sin²(φ0/2))", "naive",
                         _rel(float(naive_period(phi0)), ref) if phi0 < math.pi else float("nan")),
                _map_row("period-near-pi", d, "series (66), 50 terms", "naive",
                         _rel(float(period.period_ratio(delta=d, method="series", terms=50)), ref)),
            ]
    return rows


def map_k2_to_0(settings: Settings) -> list[dict]:
    """k² → 0 (u → v0): (K − E)/m and the quadratic first-order solution over 0 ≤ Ωt ≤ π."""
    rows = []
    ms = np.geomspace(1e-18, 0.5, 7 if settings.quick else 30)
    R0, beta = 0.1, 0.5
    u = R0 * OMEGA
    th = np.linspace(0.05, math.pi - 0.05, 7)
    t = th / OMEGA
    for m in ms:
        m = float(m)
        with mpmath.workdps(60):
            mm = mpmath.mpf(m)
            refd = (mpmath.ellipk(mm) - mpmath.ellipe(mm)) / mm
            rows.append(_map_row("k2-to-0", m, "(K − E)/m default: R_D(0, 1−m, 1)/3", "default",
                                 _rel(float(default_k_minus_e(m)), refd)))
            rows.append(_map_row("k2-to-0", m, "(K − E)/m naive: (ellipk − ellipe)/m", "naive",
                                 _rel(float(naive_k_minus_e(m)), refd)))
        v0 = u * math.sqrt(1 - m)
        mt = [mpmath.mpf(float(a)) for a in t]
        with mpmath.workdps(40):
            xr, yr = quadratic.first_order(mt, mpmath.mpf(R0), mpmath.mpf(v0), mpmath.mpf(OMEGA), mpmath.mpf(beta),
                                           ops=quadratic.MP)
            sc = max(R0, v0 / OMEGA)
            x, y = quadratic.first_order(t, R0, v0, OMEGA, beta)
            rows.append(_map_row("k2-to-0", m, "quadratic first order, default closed form", "default",
                                 _traj_err(x, y, xr, yr, sc)))
            with np.errstate(all="ignore"):
                x, y = zeta_form(t, R0, v0, OMEGA, beta)
            rows.append(_map_row("k2-to-0", m, "quadratic first order, printed ζ-form (1/k²)", "naive",
                                 _traj_err(x, y, xr, yr, sc) if np.all(np.isfinite(x)) else float("nan")))
    return rows


def map_kappa_to_omega(settings: Settings) -> list[dict]:
    """κ → Ω: x = |κ/Ω − 1| on both sides (under- and overdamped), 3 periods."""
    rows = []
    R0 = v0 = 0.1
    t = np.linspace(0.1, 3 * 2 * math.pi / OMEGA, 12)
    mt = [mpmath.mpf(float(a)) for a in t]
    for side in (-1, 1):
        for e in np.geomspace(1e-16, 1e-1, 8 if settings.quick else 31):
            kappa = OMEGA * (1 + side * float(e))
            with mpmath.workdps(50):
                xr, yr = motion.linear(mt, mpmath.mpf(R0), mpmath.mpf(v0), mpmath.mpf(OMEGA), mpmath.mpf(kappa),
                                       ops=motion.MP)
                sc = max(R0, v0 / OMEGA)
                lab = "κ < Ω" if side < 0 else "κ > Ω"
                x, y = motion.linear(t, R0, v0, OMEGA, kappa)
                rows.append(_map_row("kappa-to-omega", float(e), f"default closed form ({lab})", "default",
                                     _traj_err(x, y, xr, yr, sc)))
                x, y = naive_linear(t, R0, v0, OMEGA, kappa)
                rows.append(_map_row("kappa-to-omega", float(e), f"naive: e^(λ±t), λ± = −κ ± √(κ² − Ω²) ({lab})", "naive",
                                     _traj_err(x, y, xr, yr, sc)))
    return rows


def map_zeta_beyond_pi(settings: Settings) -> list[dict]:
    """The first-order solution against Ωt: the printed ζ-form holds only up to Ωt = π."""
    rows = []
    R0, v0, beta = 0.1, 0.2, 0.5
    th = np.linspace(0.1, 10 * math.pi, 30 if settings.quick else 120)
    t = th / OMEGA
    mt = [mpmath.mpf(float(a)) for a in t]
    with mpmath.workdps(40):
        xr, yr = quadratic.first_order(mt, mpmath.mpf(R0), mpmath.mpf(v0), mpmath.mpf(OMEGA), mpmath.mpf(beta),
                                       ops=quadratic.MP)
    x, y = quadratic.first_order(t, R0, v0, OMEGA, beta)
    xz, yz = zeta_form(t, R0, v0, OMEGA, beta)
    sc = max(R0, v0 / OMEGA)
    with mpmath.workdps(40):
        for i, a in enumerate(th):
            rows.append(_map_row("zeta-beyond-pi", float(a), "default closed form (quasi-periodic reduction)",
                                 "default", _traj_err([x[i]], [y[i]], [xr[i]], [yr[i]], sc)))
            rows.append(_map_row("zeta-beyond-pi", float(a), "printed ζ-form, ζ = cos Ωt", "naive",
                                 _traj_err([xz[i]], [yz[i]], [xr[i]], [yr[i]], sc)))
    return rows


def map_beta_r0_omega_t(settings: Settings) -> list[dict]:
    """Quadratic drag once βR0·Ωt is not small: first order in β against the exact
    small-swing motion (26)–(27); the default (26)–(27) integrated stays accurate."""
    rows = []
    R0, v0 = 0.1, 0.2
    periods = 4 if settings.quick else 20
    th = np.linspace(0.5, periods * 2 * math.pi, 40 if settings.quick else 200)
    t = th / OMEGA
    for beta in ((0.1, 1.0) if settings.quick else (0.03, 0.1, 0.3, 1.0, 3.0)):
        params = {"R0": R0, "v0": v0, "omega2": OMEGA**2, "beta": beta}
        ref = reference.solve("quadratic", params, t, tol=1e-14 if reference.heyoka_available() else 1e-13,
                              method="heyoka" if reference.heyoka_available() else "dop853")
        x1, y1 = quadratic.first_order(t, R0, v0, OMEGA, beta)
        xd, yd = motion.trajectory("quadratic", t, R0, v0, OMEGA**2, beta=beta)
        xr, yr = np.asarray(ref.x, dtype=float), np.asarray(ref.y, dtype=float)
        e1 = np.hypot(x1 - xr, y1 - yr) / R0
        ed = np.hypot(xd - xr, yd - yr) / R0
        for i, a in enumerate(th):
            xv = beta * R0 * a
            rows.append(_map_row("beta-r0-omega-t", float(xv), f"first order in β (βR0 = {beta * R0:g})", "naive",
                                 float(e1[i]), beta=beta))
            rows.append(_map_row("beta-r0-omega-t", float(xv), f"default: (26)–(27) integrated (βR0 = {beta * R0:g})",
                                 "default", float(ed[i]), beta=beta))
    return rows


def map_long_times(settings: Settings) -> list[dict]:
    """The linear-drag motion over many periods (κ small so that it is still moving): the
    closed form with compensated phase, the naive closed form, and DOP853."""
    rows = []
    R0 = v0 = 0.1
    kappa = 1e-4
    T = 2 * math.pi / OMEGA
    nper = np.geomspace(1, 1e3 if settings.quick else 1e4, 7 if settings.quick else 13)
    t = nper * T
    mt = [mpmath.mpf(float(a)) for a in t]
    with mpmath.workdps(50):
        xr, yr = motion.linear(mt, mpmath.mpf(R0), mpmath.mpf(v0), mpmath.mpf(OMEGA), mpmath.mpf(kappa), ops=motion.MP)
    x, y = motion.linear(t, R0, v0, OMEGA, kappa)
    xn, yn = naive_phase_linear(t, R0, v0, OMEGA, kappa)
    ode_limit = 30 if settings.quick else 1000
    tode = t[nper <= ode_limit]
    sol = reference.solve("linear", {"R0": R0, "v0": v0, "omega2": OMEGA**2, "kappa": kappa}, tode, tol=1e-12,
                          method="dop853")
    sc = max(R0, v0 / OMEGA)
    with mpmath.workdps(50):
        for i, n in enumerate(nper):
            rows.append(_map_row("long-times", float(n), "default closed form (compensated phase)", "default",
                                 _traj_err([x[i]], [y[i]], [xr[i]], [yr[i]], sc)))
            rows.append(_map_row("long-times", float(n), "naive closed form (phase ωt rounded)", "naive",
                                 _traj_err([xn[i]], [yn[i]], [xr[i]], [yr[i]], sc)))
            if i < tode.size:
                rows.append(_map_row("long-times", float(n), "DOP853, rtol 1e-12", "ODE",
                                     _traj_err([sol.x[i]], [sol.y[i]], [xr[i]], [yr[i]], sc)))
    return rows


# --- validity of the paper's approximations ----------------------------------------------------------
VALIDITY_MODELS = (("linear", "spherical", "kappa"), ("quadratic", "spherical", "beta"),
                   ("quadratic-first-order", "spherical", "beta"), ("quadratic-first-order", "small-swing", "beta"))


def measure_validity(settings: Settings) -> list[dict]:
    """Max over [0, N periods] of :func:`reference.approximation_error`, over amplitude R0/l ×
    drag (κ/Ω or βR0), N = 1 and 10; v0 = R0Ω/2 (an ellipse), l = 1 m, g = 9.81 m/s²."""
    rows = []
    length, g = 1.0, 9.81
    om = math.sqrt(g / length)
    T = 2 * math.pi / om
    amps = np.geomspace(1e-3, 0.5, 4 if settings.quick else 10)
    drags = np.geomspace(1e-3, 1.0, 4 if settings.quick else 10)
    tmax = 10
    t = np.linspace(0, tmax * T, tmax * 24 + 1)
    for model, against, law in VALIDITY_MODELS:
        for a in amps:
            R0 = float(a) * length
            if against == "small-swing" and a != amps[0]:
                continue  # the drag approximation alone does not depend on the amplitude (scaled)
            for d in drags:
                drag = float(d) * om if law == "kappa" else float(d) / R0
                params = {"R0": R0, "v0": 0.5 * R0 * om, "l": length, "g": g, law: drag}
                err = reference.approximation_error(model, params, t, against=against)
                for n in (1, tmax):
                    rows.append({"model": model, "against": against, "drag_law": law, "amplitude": float(a),
                                 "drag": float(d), "periods": n, "error": float(np.max(err[t <= n * T + 1e-9]))})
    return rows


def beta_fit(rows: list[dict], periods: int = 1) -> tuple[float, float]:
    """(C, p) of the first-order error against (26)–(27), err/R0 ≈ C·(βR0)^p over the first
    ``periods`` periods, fitted where βR0·Ωt ≤ 0.5 (the asymptotic regime of the β expansion)
    from validity rows (computation on the data only)."""
    sel = [r for r in rows if r["model"] == "quadratic-first-order" and r["against"] == "small-swing"
           and int(r["periods"]) == periods and float(r["drag"]) * 2 * math.pi * periods <= 0.5
           and float(r["error"]) > 0]
    if len(sel) < 2:
        return float("nan"), float("nan")
    x = np.log([float(r["drag"]) for r in sel])
    y = np.log([float(r["error"]) for r in sel])
    p, c = np.polyfit(x, y, 1)
    return float(math.exp(c)), float(p)


def validity_limits(rows: list[dict], levels=(1e-2, 1e-3, 1e-6)) -> list[dict]:
    """From validity rows: for each approximation, horizon and error level, the largest
    amplitude R0/l (at the smallest drag) and the largest drag (at the smallest amplitude) on
    the measured grid whose error stays within the level (0 when none does)."""
    out = []
    keys = list(dict.fromkeys((r["model"], r["against"], int(r["periods"])) for r in rows))
    for model, against, n in keys:
        sub = [r for r in rows if r["model"] == model and r["against"] == against and int(r["periods"]) == n]
        amin = min(float(r["amplitude"]) for r in sub)
        dmin = min(float(r["drag"]) for r in sub)
        for level in levels:
            amp = [float(r["amplitude"]) for r in sub if float(r["drag"]) == dmin and float(r["error"]) <= level]
            drg = [float(r["drag"]) for r in sub if float(r["amplitude"]) == amin and float(r["error"]) <= level]
            out.append({"model": model, "against": against, "periods": n, "level": level,
                        "max_amplitude": max(amp, default=0.0), "at_drag": dmin,
                        "max_drag": max(drg, default=0.0), "at_amplitude": amin})
    return out


# --- CSV -------------------------------------------------------------------------------------------
def _fmt(v) -> str:
    if isinstance(v, float):
        return repr(v)
    return str(v)


def write_csv(path: Path, rows: list[dict], header: dict) -> None:
    """Rows with a ``# key: value`` header (machine, versions, what was measured)."""
    buf = io.StringIO()
    for k, v in header.items():
        buf.write(f"# {k}: {v}\n")
    cols = list(rows[0].keys()) if rows else []
    for r in rows:
        for k in r:
            if k not in cols:
                cols.append(k)
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(cols)
    for r in rows:
        w.writerow([_fmt(r.get(c, "")) for c in cols])
    path.write_text(buf.getvalue(), encoding="utf-8")


def read_csv(path: Path) -> tuple[dict, list[dict]]:
    """(header, rows) of a CSV written by :func:`write_csv`; numbers stay strings."""
    header, body = {}, []
    for line in Path(path).read_text(encoding="utf-8").splitlines():
        if line.startswith("# "):
            k, _, v = line[2:].partition(": ")
            header[k] = v
        else:
            body.append(line)
    rows = list(csv.DictReader(io.StringIO("\n".join(body) + "\n")))
    return header, rows


# --- rendering (from the CSV only) -------------------------------------------------------------------
_STYLE = {"closed form, double": ("o", "-"), "mpmath": ("s", "-"), "balls": ("D", "-"), "series": ("v", "-"),
          "quadrature": ("^", "-"), "ODE": ("x", "--"), "ODE, Taylor": ("+", "--")}
FLOOR = 1e-125  # errors below are drawn at the floor (the references carry 130–140 digits)
NONFINITE = 1e2  # where a stability map draws the points at which a method returned inf or NaN


def render(csv_path: Path, png_path: Path) -> None:
    """Draw the PNG for one CSV (the kind is read from its header)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    header, rows = read_csv(csv_path)
    kind = header.get("chart", "")
    with matplotlib.rc_context({"font.size": 8, "svg.hashsalt": "quasicentral", "path.simplify": False}):
        if kind.startswith("workprecision"):
            fig = _render_workprecision(plt, header, rows)
        elif kind.startswith("stability"):
            fig = _render_stability(plt, header, rows)
        elif kind == "validity":
            fig = _render_validity(plt, header, rows)
        else:
            raise ChartError(f"{csv_path}: unknown chart kind {kind!r}")
        foot = f"measured on {header.get('processor', '?')} ({header.get('cores', '?')} cores), " \
               f"Python {header.get('python', '?')}, numpy {header.get('numpy', '?')}, scipy {header.get('scipy', '?')}, " \
               f"mpmath {header.get('mpmath', '?')}, python-flint {header.get('python-flint', '?')}, " \
               f"heyoka {header.get('heyoka', '?')}"
        fig.text(0.005, 0.003, foot, fontsize=5.5, color="0.35")
        fig.savefig(png_path, format="png", metadata={"Software": None})
        plt.close(fig)


def _render_workprecision(plt, header, rows):
    cases = list(dict.fromkeys(r["case"] for r in rows))
    fig, axes = plt.subplots(1, len(cases), figsize=(5.2 * len(cases), 5.6), dpi=110, squeeze=False)
    for ax, case in zip(axes[0], cases):
        sub = [r for r in rows if r["case"] == case]
        methods = list(dict.fromkeys(r["method"] for r in sub))
        for j, meth in enumerate(methods):
            pts = [r for r in sub if r["method"] == meth]
            fam = pts[0]["family"]
            mk, ls = _STYLE.get(fam, ("o", "-"))
            err = [max(float(r["error"]), FLOOR) for r in pts]
            sec = [float(r["seconds"]) for r in pts]
            ax.plot(err, sec, marker=mk, ls=ls if len(pts) > 1 else "none", lw=0.8, ms=3.5,
                    color=plt.cm.tab10(j % 10), label=meth)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.invert_xaxis()
        ax.set_xlabel("max relative error (→ more accurate)")
        ax.set_ylabel("seconds per evaluation")
        ax.set_title(case, fontsize=7.5)
        ax.grid(True, which="major", lw=0.3)
        ax.legend(fontsize=5.5, loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=2, frameon=False)
    fig.suptitle(header.get("title", ""), fontsize=9)
    fig.tight_layout(rect=(0, 0.02, 1, 0.97))
    return fig


def _render_stability(plt, header, rows):
    fig, ax = plt.subplots(figsize=(6.4, 4.6), dpi=110)
    methods = list(dict.fromkeys(r["method"] for r in rows))
    for j, meth in enumerate(methods):
        pts = [r for r in rows if r["method"] == meth]
        role = pts[0]["role"]
        xs = [float(r["x"]) for r in pts]
        es = [max(float(r["error"]), 1e-18) if r["error"] else float("nan") for r in pts]
        ls = "-" if role.startswith("default") else ("--" if role == "naive" else ":")
        color = plt.cm.tab10(j % 10)
        ax.plot(xs, [e if math.isfinite(e) else float("nan") for e in es], ls=ls, marker="o", ms=2.5,
                lw=1.2 if role == "default" else 0.9, color=color, label=f"{meth} [{role}]")
        bad = [x for x, e in zip(xs, es) if not math.isfinite(e)]
        if bad:  # inf or NaN returned: drawn as crosses on the top edge
            ax.plot(bad, [NONFINITE] * len(bad), ls="none", marker="x", ms=4, color=color)
    if any(not math.isfinite(float(r["error"])) for r in rows if r["error"]):
        ax.axhline(NONFINITE, color="0.5", lw=0.5, ls=":")
        ax.text(0.01, 0.995, "× : inf or NaN returned", transform=ax.transAxes, fontsize=6, va="top")
    ax.set_yscale("log")
    if header.get("xscale", "log") == "log":
        ax.set_xscale("log")
    if header.get("invert_x") == "yes":
        ax.invert_xaxis()
    ax.set_xlabel(header.get("xlabel", "x"))
    ax.set_ylabel(header.get("ylabel", "error"))
    for level in (1e-2, 1e-3, 1e-6, 1e-12):
        ax.axhline(level, color="0.8", lw=0.5, zorder=0)
    ax.set_title(header.get("title", ""), fontsize=8)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=5.5)
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    return fig


def _render_validity(plt, header, rows):
    panels = list(dict.fromkeys((r["model"], r["against"]) for r in rows if r["against"] == "spherical"))
    periods = sorted({int(r["periods"]) for r in rows})
    fig, axes = plt.subplots(len(periods), len(panels) + 1, figsize=(4.0 * (len(panels) + 1), 3.5 * len(periods)),
                             dpi=100, squeeze=False)
    levels = [-6, -3, -2]
    for i, n in enumerate(periods):
        for j, (model, against) in enumerate(panels):
            ax = axes[i][j]
            sub = [r for r in rows if r["model"] == model and r["against"] == against and int(r["periods"]) == n]
            amps = sorted({float(r["amplitude"]) for r in sub})
            drags = sorted({float(r["drag"]) for r in sub})
            grid = np.full((len(drags), len(amps)), np.nan)
            for r in sub:
                grid[drags.index(float(r["drag"])), amps.index(float(r["amplitude"]))] = math.log10(
                    max(float(r["error"]), 1e-16))
            A, D = np.meshgrid(amps, drags)
            cf = ax.contourf(A, D, grid, levels=np.arange(-10, 1, 1), cmap="viridis", extend="both")
            cs = ax.contour(A, D, grid, levels=levels, colors=["w", "orange", "red"], linewidths=1.0)
            ax.clabel(cs, fmt={-6: "1e-6", -3: "0.1 %", -2: "1 %"}, fontsize=6)
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("amplitude R0 / l")
            ax.set_ylabel("drag κ/Ω" if sub and sub[0]["drag_law"] == "kappa" else "drag βR0")
            ax.set_title(f"{model} vs full pendulum, {n} period{'s' if n > 1 else ''}", fontsize=7)
            fig.colorbar(cf, ax=ax, label="log10 error / R0")
        ax = axes[i][-1]
        sub = [r for r in rows if r["against"] == "small-swing" and int(r["periods"]) == n]
        xs = [float(r["drag"]) for r in sub]
        ys = [max(float(r["error"]), 1e-18) for r in sub]
        ax.loglog(xs, ys, "o-", ms=3, label="first order vs (26)–(27)")
        c, p = beta_fit(rows, n)
        if math.isfinite(c):
            xf = np.geomspace(min(xs), max(xs), 50)
            ax.loglog(xf, c * xf**p, "k--", lw=0.8, label=f"fit {c:.3g}·(βR0)^{p:.2f}")
        for level in (1e-2, 1e-3, 1e-6):
            ax.axhline(level, color="0.7", lw=0.5)
        ax.set_xlabel("βR0")
        ax.set_ylabel("max error / R0")
        ax.set_title(f"first order in β alone, {n} period{'s' if n > 1 else ''}", fontsize=7)
        ax.legend(fontsize=6)
        ax.grid(True, lw=0.3)
    fig.suptitle(header.get("title", ""), fontsize=9)
    fig.tight_layout(rect=(0, 0.02, 1, 0.97))
    return fig


# --- the whole set ---------------------------------------------------------------------------------
_WP = {"period": (measure_period, "Work–precision: the pendulum period T/T0"),
       "elliptic": (measure_elliptic, "Work–precision: the elliptic integrals of the closed forms"),
       "linear": (measure_linear, "Work–precision: the linear-drag trajectory (16)–(17)"),
       "quadratic": (measure_quadratic, "Work–precision: the first-order quadratic-drag closed form"),
       "quadratic-full": (lambda s: measure_full(s, "quadratic-full"), "Work–precision: the full small-swing motion (26)–(27)"),
       "spherical": (lambda s: measure_full(s, "spherical"), "Work–precision: the full spherical pendulum with drag")}

_MAPS = {
    "period-near-pi": (map_period_near_pi, "T/T0 as the amplitude → π (k² → 1)", "δ = π − φ0 [rad]", "relative error", "log", "yes"),
    "k2-to-0": (map_k2_to_0, "k² → 0 (u → v0): (K − E)/m and the first-order solution on 0 ≤ Ωt ≤ π", "k² = 1 − (v0/u)²",
                "relative error (trajectory: / scale)", "log", "yes"),
    "kappa-to-omega": (map_kappa_to_omega, "Linear drag as κ → Ω (aperiodic limit), 3 periods", "|κ/Ω − 1|",
                       "max error / scale", "log", "yes"),
    "zeta-beyond-pi": (map_zeta_beyond_pi, "First-order quadratic solution: the printed ζ-form beyond Ωt = π",
                       "Ωt", "error / scale (against the exact first-order solution)", "linear", "no"),
    "beta-r0-omega-t": (map_beta_r0_omega_t, "Quadratic drag once βR0·Ωt is not small (against (26)–(27) exactly)",
                        "βR0·Ωt", "error / R0", "log", "no"),
    "long-times": (map_long_times, "Linear drag (κ = 1e-4 1/s) over long times", "periods", "error / scale", "log", "no"),
}


def build(out: Path, quick: bool = False, only: list[str] | None = None, progress=None) -> list[Path]:
    """Measure, write each CSV, then render each PNG from its CSV.  Returns the paths written.
    ``progress`` (a :class:`quasicentral.progress.Progress` callback) is told of each chart."""
    from quasicentral.progress import notify

    settings = Settings(quick=quick)
    out.mkdir(parents=True, exist_ok=True)
    wanted = list(only) if only else list(CHARTS)
    for w in wanted:
        if w not in CHARTS:
            raise ChartError(f"unknown chart {w!r}; choose from {', '.join(CHARTS)}")
    base = machine()
    base["mode"] = "quick" if quick else "full"
    written = []
    notify(progress, 0, len(wanted), "", 0, "charts")
    for name in wanted:
        if name.startswith("workprecision-"):
            q = name.removeprefix("workprecision-")
            fn, title = _WP[q]
            header = dict(base, chart=name, title=title,
                          columns="seconds per evaluation (best of 3 batches); error = max relative error over the case")
        elif name.startswith("stability-"):
            m = name.removeprefix("stability-")
            fn, title, xlabel, ylabel, xscale, inv = _MAPS[m]
            header = dict(base, chart=name, title=title, xlabel=xlabel, ylabel=ylabel, xscale=xscale, invert_x=inv)
        else:
            fn = measure_validity
            header = dict(base, chart=name, title="Validity of the paper's approximations against the full pendulum "
                                                  "with drag (v0 = R0Ω/2, l = 1 m, g = 9.81 m/s²)")
        rows = fn(settings)
        csv_path, png_path = out / f"{name}.csv", out / f"{name}.png"
        write_csv(csv_path, rows, header)
        render(csv_path, png_path)
        written += [csv_path, png_path]
        notify(progress, len(written) // 2, len(wanted), name, 0, "charts")
    return written


def render_all(folder: Path) -> list[Path]:
    """Re-render every chart's PNG from the CSVs in ``folder`` (nothing is measured)."""
    written = []
    for csv_path in sorted(Path(folder).glob("*.csv")):
        png = csv_path.with_suffix(".png")
        render(csv_path, png)
        written.append(png)
    return written
