"""Jacobi's theta functions with the nome, DLMF §20.2(i), and the nome of a modulus (22.2.1).

DLMF's θ_j(z, q) does **not** scale z by π; python-flint's ``acb.modular_theta(z, τ)`` does
(θ_j^{flint}(z, τ) = θ_j(πz, q), q = e^{iπτ}), so the ball route passes z/π and
τ = −i log(q)/π; q^{1/4} in θ₁, θ₂ is the principal power (τ from the principal log), which
puts their cut on q ∈ (−1, 0].  θ₃ and θ₄ are analytic in |q| < 1, and there τ is taken from
log(−q) where Re q < 0 so that the ball never straddles the log's cut.
"""

from __future__ import annotations

import mpmath
import sympy as sp
from flint import acb
from sympy.core.function import ArgumentIndexError

from quasicentral.notation.special.base import (
    DLMFFunction, ball_parameters, ball_precision, ball_route, may_meet, may_meet_cut, mp_route,
    nan_ball, parameters,
)


def tau_from_nome(q, principal: bool):
    """τ with e^{iπτ} = q: −i log(q)/π (principal), or 1 − i log(−q)/π, which differs by 2
    (θ₃, θ₄ are unchanged by τ → τ + 2) and has its cut on the positive axis instead."""
    minus_i_over_pi = acb(0, -1) / acb.pi()
    if principal or not (q.real.mid() < 0):
        return q.log() * minus_i_over_pi
    return 1 + (-q).log() * minus_i_over_pi


def thetas_ball(z, tau):
    """(θ₁, θ₂, θ₃, θ₄) at DLMF's argument z (flint's argument z/π)."""
    return acb.modular_theta(z / acb.pi(), tau)


class JacobiThetaBase(DLMFFunction):
    """θ_j(z, q), the index j set by the subclass."""

    nargs = 2
    index = None

    @property
    def latex_name(self):
        return r"\theta_{%d}" % self.index

    def fdiff(self, argindex=1):
        # DLMF gives series (20.4) and the heat equation (20.13.1), no closed derivative
        raise ArgumentIndexError(self, argindex)

    @mp_route()
    def mp(cls, z, q):
        return mpmath.jtheta(cls.index, z, q)

    @classmethod
    def ball_value(cls, z, q, analytic=False):
        z, q = acb(z), acb(q)
        principal = cls.index in (1, 2)
        if analytic and principal and may_meet_cut(q):
            return nan_ball()
        if not (q.abs_upper() < 1):
            return nan_ball()
        return thetas_ball(z, tau_from_nome(q, principal))[cls.index - 1]


def theta_class(j, doc):
    """The class of θ_j, with its own ``ball`` staticmethod."""

    def ball(z, q, analytic=False):
        with ball_precision():
            value = cls.ball_value(acb(z), acb(q), analytic=analytic)
        return +value

    cls = type("JacobiTheta%d" % j, (JacobiThetaBase,), {
        "index": j, "__doc__": doc, "__module__": __name__, "ball": staticmethod(ball)})
    return cls


JacobiTheta1 = theta_class(1, r"""θ₁(z, q) = 2 Σ_{n≥0} (−1)^n q^{(n+½)²} sin((2n + 1)z), DLMF 20.2.1.

    The nome q (|q| < 1), z not scaled by π; q^{1/4} principal.  mpmath ``jtheta(1, z, q)``;
    flint ``modular_theta(z/π, τ)``, τ = −i log(q)/π.  No closed derivative (DLMF gives series).

    >>> import mpmath
    >>> with mpmath.workdps(30):   # the series 20.2.1 summed directly
    ...     z, q = mpmath.mpf(1)/3, mpmath.mpf(1)/5
    ...     s = 2*mpmath.nsum(lambda n: (-1)**n*q**((n + 0.5)**2)*mpmath.sin((2*n + 1)*z), [0, mpmath.inf])
    ...     print(mpmath.almosteq(JacobiTheta1.mp(z, q), s, 1e-28))
    True
    """)

JacobiTheta2 = theta_class(2, r"""θ₂(z, q) = 2 Σ_{n≥0} q^{(n+½)²} cos((2n + 1)z), DLMF 20.2.2.

    Nome q, z not scaled by π; q^{1/4} principal.  θ₂(z, q) = θ₁(z + π/2, q) (20.2.11).

    >>> import mpmath
    >>> with mpmath.workdps(30):
    ...     z, q = mpmath.mpf(1)/3, mpmath.mpf(1)/5
    ...     print(mpmath.almosteq(JacobiTheta2.mp(z, q), JacobiTheta1.mp(z + mpmath.pi/2, q), 1e-28))
    True
    """)

JacobiTheta3 = theta_class(3, r"""θ₃(z, q) = 1 + 2 Σ_{n≥1} q^{n²} cos(2nz), DLMF 20.2.3.

    Nome q, z not scaled by π; analytic in |q| < 1.  Jacobi's identity θ₃⁴ = θ₂⁴ + θ₄⁴ at z = 0
    (20.7.3).

    >>> import mpmath
    >>> with mpmath.workdps(30):
    ...     q = mpmath.mpf(1)/5
    ...     t2, t3, t4 = (f.mp(0, q) for f in (JacobiTheta2, JacobiTheta3, JacobiTheta4))
    ...     print(mpmath.almosteq(t3**4, t2**4 + t4**4, 1e-28))
    True
    """)

JacobiTheta4 = theta_class(4, r"""θ₄(z, q) = 1 + 2 Σ_{n≥1} (−1)^n q^{n²} cos(2nz), DLMF 20.2.4.

    Nome q, z not scaled by π; analytic in |q| < 1.  θ₄(z, q) = θ₃(z + π/2, q) (20.2.11).

    >>> import mpmath
    >>> with mpmath.workdps(30):
    ...     z, q = mpmath.mpf(1)/3, mpmath.mpc(1, 1)/5
    ...     print(mpmath.almosteq(JacobiTheta4.mp(z, q), JacobiTheta3.mp(z + mpmath.pi/2, q), 1e-28))
    True
    """)


class EllipticNome(DLMFFunction):
    r"""The nome q(k) = exp(−π K′(k)/K(k)), DLMF 22.2.1, **modulus** k (mpmath's ``qfrom``
    takes m = k² or k=…).

    Analytic for k² ∉ (−∞, 0] ∪ [1, ∞); q(0) = 0.  dq/dk = π² q/(2k k′² K²) (Legendre's
    relation 19.7.1 in d(K′/K)/dk).  Balls: exp(−πK′/K) with K′ = R_F(0, k², 1).

    >>> import mpmath
    >>> with mpmath.workdps(30):   # k² = θ₂⁴(0, q)/θ₃⁴(0, q) (20.9.1 with 22.2.2)
    ...     k = mpmath.mpf(3)/5; q = EllipticNome.mp(k)
    ...     print(mpmath.almosteq((mpmath.jtheta(2, 0, q)/mpmath.jtheta(3, 0, q))**4, k**2, 1e-28))
    True
    """

    nargs = 1
    latex_name = "q"

    @classmethod
    def eval(cls, k):
        if k.is_zero:
            return sp.S.Zero

    def fdiff(self, argindex=1):
        if argindex != 1:
            raise ArgumentIndexError(self, argindex)
        from quasicentral.notation.special.legendre import EllipticK
        k = self.args[0]
        return sp.pi ** 2 * EllipticNome(k) / (2 * k * (1 - k ** 2) * EllipticK(k) ** 2)

    @mp_route()
    def mp(cls, k):
        m, mc = parameters(k)
        if m == 0:
            return mpmath.mpf(0)
        with mpmath.workprec(mpmath.mp.prec + max(0, -mpmath.mag(mc))):
            return mpmath.qfrom(m=m)

    @ball_route
    def ball(k, analytic=False):
        m, mc = ball_parameters(k)
        if analytic and (may_meet_cut(m) or may_meet(m, 1, None)):
            return nan_ball()
        return (-acb.pi() * kprime_ball(m, mc) / m.elliptic_k()).exp()


def kprime_ball(m, mc):
    """K′ = R_F(0, k², 1) (K(k′) where k² may be negative real)."""
    if m.imag.contains(0) and not (m.real > 0):
        return mc.elliptic_k()
    return acb.elliptic_rf(acb(0), m, acb(1))


def nome_tau_ball(m, mc):
    """(K, τ = iK′/K) for the theta quotients of chapter 22 (22.2.1–22.2.3)."""
    K = m.elliptic_k()
    return K, acb(0, 1) * kprime_ball(m, mc) / K


__all__ = ["JacobiTheta1", "JacobiTheta2", "JacobiTheta3", "JacobiTheta4", "EllipticNome",
           "nome_tau_ball", "kprime_ball", "tau_from_nome", "thetas_ball"]
