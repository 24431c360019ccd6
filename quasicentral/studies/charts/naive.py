"""The naive routes the stability maps show failing (and the defaults beside them)."""

from __future__ import annotations

import math

import numpy as np


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
    """(K − E)/m = R_D(0, 1 − m, 1)/3 (DLMF 19.25.1), as :mod:`quasicentral.models.quadratic` uses it."""
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
