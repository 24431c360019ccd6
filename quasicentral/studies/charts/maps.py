"""Stability maps (error against the parameter that drives a method into trouble) and the
validity of the paper's approximations against the full pendulum."""

from __future__ import annotations

import math

import mpmath
import numpy as np

from quasicentral.models import accuracy, motion, period, quadratic, reference
from quasicentral.models.parameters import G_STANDARD
from quasicentral.studies.charts.common import OMEGA, rel as _rel, traj_err as _traj_err
from quasicentral.studies.charts.naive import (
    default_k_minus_e, naive_k_minus_e, naive_linear, naive_period, naive_phase_linear, zeta_form,
)
from quasicentral.studies.charts.timing import Settings


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
    """Max over [0, N periods] of :func:`accuracy.approximation_error`, over amplitude R0/l ×
    drag (κ/Ω or βR0), N = 1 and 10; v0 = R0Ω/2 (an ellipse), l = 1 m, g = 9.81 m/s²."""
    rows = []
    length, g = 1.0, G_STANDARD
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
                err = accuracy.approximation_error(model, params, t, against=against)
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
