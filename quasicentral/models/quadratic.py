"""Quadratic drag R = mβv², section 5 of [Brepta1953]: the first-order solution in closed form,
correct for all times and every k², and the full motion (26)–(27) integrated numerically.

First order (velocities of the ideal ellipse put into the drag, variation of constants).
With θ = Ωt, u = R0Ω, the parameter m = k² = (u² − v0²)/u² (the paper's modulus k; m < 0
when u < v0), and the ellipse speed V = u√(1 − m cos²θ):

    x = A sin θ + B cos θ,   A = βR0² G(θ),          B = R0 − βR0² I_B(θ),
    y = C sin θ + D cos θ,   C = (v0/Ω)(1 − βR0 I_C(θ)),  D = (v0/Ω) βR0 G(θ),

    I_B = ∫₀^θ sin²φ √(1 − m cos²φ) dφ,   I_C = ∫₀^θ cos²φ √(1 − m cos²φ) dφ,
    G = (1/3)[(1 − m cos²θ)^{3/2} − (1 − m)^{3/2}]/m
      = (1/3) sin²θ (X² + XY + Y²)/(X^{3/2} + Y^{3/2}),  X = 1 − m cos²θ, Y = 1 − m

(the second form of G has no 1/m and no cancellation as m → 0).  The paper's (28)–(30)
write I_B, I_C through F(k, ζ), E(k, ζ) with ζ = cos Ωt, which holds for 0 ≤ Ωt ≤ π only.
Here, with ψ = φ − π/2 (so that 1 − m cos²φ = 1 − m sin²ψ = Δ²) and the Legendre integrals of
*amplitude* ψ, quasi-periodic in ψ (F(ψ + π) = F(ψ) + 2K, E(ψ + π) = E(ψ) + 2E):

    J_s(ψ) = ∫₀^ψ sin²ψ Δ dψ = [(1 − m)·Dₘ(ψ) + E(ψ|m) − sin ψ cos ψ Δ(ψ)]/3,
    J_c(ψ) = ∫₀^ψ cos²ψ Δ dψ = E(ψ|m) − J_s(ψ),
    Dₘ(ψ) = (F − E)(ψ|m)/m = sin³ψ R_D(cos²ψ, Δ², 1)/3   (|ψ| ≤ π/2; DLMF 19.25.1 / 19.29),

so I_B(θ) = J_c(θ − π/2) − J_c(−π/2) and I_C(θ) = J_s(θ − π/2) − J_s(−π/2).  Every term is
free of 1/m.  Near the planar limit m → 1 the natural variable is the complementary parameter
m' = 1 − m = (v0/u)², formed directly from v0/u rather than as 1 − m (which keeps only its
leading digits once m is rounded): Δ² = cos²ψ + m' sin²ψ, and the complete integrals are taken
from m' as E = 2 R_G(0, m', 1) and (K − E)/m = R_D(0, m', 1)/3 (DLMF 19.25.1), free of
cancellation.  (mpmath's ellipe(m) itself loses about half its digits as m → 1: at 40 digits,
E(1 − 10⁻⁴⁰) comes out wrong by 5·10⁻¹¹.)  At m' = 0 exactly (v0 = 0, a planar swing)
V = u|sin θ| and the integrals are elementary.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mpmath
import numpy as np

from quasicentral.models.equations import System, rhs


@dataclass(frozen=True)
class EllipticOps:
    """Arithmetic for the closed form: scipy in double precision, or mpmath elementwise."""

    sin: object
    cos: object
    sqrt: object
    elliprd: object
    elliprg: object
    ellipeinc: object
    floor: object
    asarray: object
    pi: object
    tiny: float  # the smallest normal number: a smaller 1 − m is the planar limit (scipy's R_D overflows there)


def _double() -> EllipticOps:
    from scipy import special

    return EllipticOps(np.sin, np.cos, np.sqrt, special.elliprd, special.elliprg, special.ellipeinc, np.floor,
                       lambda a: np.asarray(a, dtype=float), math.pi, float(np.finfo(float).tiny))


def _mp() -> EllipticOps:
    v = lambda f, n=1: np.frompyfunc(f, n, 1)  # noqa: E731
    return EllipticOps(v(mpmath.sin), v(mpmath.cos), v(mpmath.sqrt), v(mpmath.elliprd, 3), mpmath.elliprg,
                       v(mpmath.ellipe, 2), v(mpmath.floor),
                       lambda a: np.array([mpmath.mpf(x) for x in np.ravel(a)], dtype=object), None, 0.0)


def _js(psi, m, mc, ops: EllipticOps, pi):
    """J_s(ψ) = ∫₀^ψ sin²ψ √(1 − m sin²ψ) dψ for any real ψ (quasi-periodic reduction);
    mc = 1 − m, formed by the caller without cancellation."""
    j = ops.floor(psi / pi + 0.5)
    r = psi - j * pi  # in [−π/2, π/2)
    sn, cs = ops.sin(r), ops.cos(r)
    d2 = cs * cs + mc * sn * sn
    dm = sn**3 * ops.elliprd(cs * cs, d2, 1 + 0 * r) / 3
    dm_full = ops.elliprd(0 * mc, mc, 1 + 0 * mc) / 3  # (K − E)/m
    ecomp = 2 * ops.elliprg(0 * mc, mc, 1 + 0 * mc)  # E(m)
    dm = dm + 2 * j * dm_full
    e = ops.ellipeinc(r, m + 0 * r) + 2 * j * ecomp
    return (mc * dm + e - sn * cs * ops.sqrt(d2)) / 3, e


def _g(theta, m, mc, ops):
    c2 = ops.cos(theta) ** 2
    s2 = ops.sin(theta) ** 2
    X = s2 + mc * c2  # 1 − m cos²θ
    Y = mc + 0 * theta
    num = X * X + X * Y + Y * Y
    den = X * ops.sqrt(X) + Y * ops.sqrt(Y)
    out = s2 * num / np.where(den == 0, 1, den) / 3
    return np.where(den == 0, 0 * theta, out)


def _integrals(theta, m, mc, ops: EllipticOps, pi):
    """(I_B, I_C) at θ."""
    if mc == 0:  # v0 = 0: √(1 − cos²φ) = |sin φ|, elementary
        j = ops.floor(theta / pi)
        r = theta - j * pi
        c = ops.cos(r)
        ib = j * 4 / 3 + (2 - 3 * c + c**3) / 3
        ic = j * 2 / 3 + (1 - c**3) / 3
        return ib, ic
    js_t, e_t = _js(theta - pi / 2, m, mc, ops, pi)
    js_0, e_0 = _js(-pi / 2 + 0 * m, m, mc, ops, pi)  # a constant: one evaluation
    ic = js_t - js_0
    ib = (e_t - js_t) - (e_0 - js_0)
    return ib, ic


def first_order(t, R0, v0, Omega, beta, ops: EllipticOps | None = None):
    """(x, y) of the first-order quadratic-drag solution at times ``t`` (any v0 ≥ 0, R0 > 0).

    >>> x, y = first_order([0.0], 0.1, 0.1, math.sqrt(10), 0.5)
    >>> float(x[0]), float(y[0])
    (0.1, 0.0)
    """
    ops = ops or DOUBLE
    t = ops.asarray(t)
    pi = ops.pi if ops.pi is not None else mpmath.pi
    theta = Omega * t
    u = R0 * Omega
    m = (u - v0) * (u + v0) / (u * u)  # accurate near m = 0 (v0 ≈ u)
    mc = (v0 / u) ** 2  # 1 − m, accurate near m = 1 (v0 ≪ u)
    if mc < ops.tiny:
        # a subnormal m' in double precision: the planar integrals differ from the exact ones
        # by O(m' ln(1/m')) < 10⁻³⁰⁵
        mc = 0 * mc
    ib, ic = _integrals(theta, m, mc, ops, pi)
    g = _g(theta, m, mc, ops)
    sn, cs = ops.sin(theta), ops.cos(theta)
    x = beta * R0 * R0 * g * sn + (R0 - beta * R0 * R0 * ib) * cs
    y = v0 / Omega * ((1 - beta * R0 * ic) * sn + beta * R0 * g * cs)
    return x, y


DOUBLE = _double()
MP = _mp()


# --- the full motion (26)–(27) -----------------------------------------------------------------
def integrate_full(t, R0, v0, Omega, beta, rtol: float = 1e-12):
    """(26)–(27) integrated with scipy's DOP853 (the drag's kink where the speed passes through
    zero is crossed by the adaptive step; error ~1e-12 relative at rtol 1e-12).  The right-hand
    side is :func:`quasicentral.models.equations.rhs` of ``System.QUADRATIC``."""
    from scipy.integrate import solve_ivp

    t = np.asarray(t, dtype=float)
    f = rhs(System.QUADRATIC, (Omega * Omega, beta), math)
    scale = max(R0, v0 / Omega)
    sol = solve_ivp(f, (0.0, float(t.max()) if t.size else 0.0), (R0, 0.0, 0.0, v0), method="DOP853",
                    t_eval=t, rtol=rtol, atol=rtol * scale * 1e-2)
    if not sol.success:
        raise ValueError(f"the integration of (26)–(27) failed: {sol.message}")
    return sol.y[0], sol.y[1]


def integrate_full_mp(t, R0, v0, Omega, beta, dps: int):
    """(26)–(27) with mpmath's Taylor-series integrator at ``dps`` digits (slow: seconds), by
    :func:`quasicentral.models.reference.solve`; a planar swing (v0 = 0) is integrated stretch
    by stretch between the zeros of the speed, where |ẋ| = σẋ is analytic."""
    from quasicentral.models import reference

    with mpmath.workdps(dps + 10):
        params = {"R0": R0, "v0": v0, "omega2": mpmath.mpf(Omega) ** 2, "beta": beta}
        sol = reference.solve("quadratic", params, list(t), tol=10.0**-dps, method="mpmath")
    return sol.x, sol.y
