"""Work–precision measurements: every method of each quantity, its cost and its error."""

from __future__ import annotations

import math

import mpmath
import numpy as np

from quasicentral.models import motion, period, quadratic, reference, spherical
from quasicentral.studies.charts.common import OMEGA, rel as _rel, row as _row, traj_err as _traj_err
from quasicentral.studies.charts.naive import default_k_minus_e, naive_k_minus_e, naive_phase_linear
from quasicentral.studies.charts.timing import Settings, timed as _timed


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
        scale = reference.scale(ref.problem)
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
                    v, s = _timed(lambda: spherical.integrate(t, params["R0"], params["v0"], 1.0, 10.0, rtol=rt, **kw),
                                  settings)
                    rows.append(_row(quantity, case, "spherical.integrate (solve_ivp DOP853)", "ODE", rt, s,
                                     _traj_err(v[0], v[1], *xy, scale)))
    return rows
