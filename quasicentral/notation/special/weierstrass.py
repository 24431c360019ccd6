r"""Weierstrass's elliptic functions ℘, ζ and σ of DLMF chapter 23, on the lattice 𝕃 with the
half-periods ω₁ and ω₃ (DLMF 23.2: 𝕃 = {2mω₁ + 2nω₃}), written ``(z, omega_1, omega_3)``.

They depend only on the lattice, so τ = ω₃/ω₁ is taken in the upper half-plane (τ → −τ spans the
same lattice); ω₃/ω₁ real is no lattice, and the value is an error (mpmath) or a non-finite ball.

* mpmath, through the theta function θ₁ of the nome q = e^{iπτ} and v = πz/(2ω₁) (DLMF 23.6.9,
  23.6.13, and ℘ = −ζ′ of 23.2.8): η₁ = −π²θ₁‴(0)/(12ω₁θ₁′(0)),
  ζ(z) = η₁z/ω₁ + (π/(2ω₁))·θ₁′(v)/θ₁(v), ℘(z) = −η₁/ω₁ − (π/(2ω₁))²·(log θ₁)″(v),
  σ(z) = (2ω₁/π)·exp(η₁z²/(2ω₁))·θ₁(v)/θ₁′(0); mpmath's ``jtheta`` with its derivatives.
* flint: ``acb.elliptic_p``, ``elliptic_zeta``, ``elliptic_sigma`` on the lattice (1, τ), scaled
  by homogeneity (DLMF 23.10.17-18): ℘(z | 2ω₁, 2ω₃) = (2ω₁)⁻²·℘(z/(2ω₁) | 1, τ), ζ of degree −1,
  σ of degree +1.
"""

from __future__ import annotations

import mpmath
from flint import acb
from sympy.core.function import ArgumentIndexError

from quasicentral.notation.special.base import DLMFFunction, ball_precision, mp_route, nan_ball


def _tau(omega_1, omega_3):
    """τ = ω₃/ω₁ in the upper half-plane (mpmath), or ValueError where the lattice degenerates."""
    tau = mpmath.mpmathify(omega_3) / omega_1
    if mpmath.im(tau) == 0:
        raise ValueError("ω₃/ω₁ is real: no lattice")
    return tau if mpmath.im(tau) > 0 else -tau


def _theta_parts(z, omega_1, omega_3):
    """(v, q, θ₁(v), θ₁′(v), θ₁″(v), θ₁′(0), θ₁‴(0)) at the caller's precision."""
    tau = _tau(omega_1, omega_3)
    q = mpmath.exp(1j * mpmath.pi * tau)
    v = mpmath.pi * z / (2 * omega_1)
    return (v, q, mpmath.jtheta(1, v, q), mpmath.jtheta(1, v, q, 1), mpmath.jtheta(1, v, q, 2),
            mpmath.jtheta(1, 0, q, 1), mpmath.jtheta(1, 0, q, 3))


def _eta_1(omega_1, d1_0, d3_0):
    return -mpmath.pi ** 2 * d3_0 / (12 * omega_1 * d1_0)


def _ball_lattice(z, omega_1, omega_3):
    """(z/(2ω₁), τ, 2ω₁) as balls, τ in the upper half-plane; None where that is not certain."""
    z, w1, w3 = acb(z), acb(omega_1), acb(omega_3)
    tau = w3 / w1
    if tau.imag > 0:
        pass
    elif tau.imag < 0:
        tau = -tau
    else:
        return None
    return z / (2 * w1), tau, 2 * w1


class WeierstrassBase(DLMFFunction):
    nargs = 3
    #: the name of flint's function and the degree of homogeneity in the lattice's scale
    flint_name = None
    degree = 0

    def _latex_args(self, printer):
        z, w1, w3 = (printer._print(a) for a in self.args)
        return r"%s; %s, %s" % (z, w1, w3)

    @classmethod
    def ball_value(cls, z, omega_1, omega_3):
        lattice = _ball_lattice(z, omega_1, omega_3)
        if lattice is None:
            return nan_ball()
        u, tau, scale = lattice
        return getattr(u, cls.flint_name)(tau) * scale ** cls.degree


def _ball_of(cls):
    def ball(z, omega_1, omega_3, analytic=False):
        # meromorphic in z, analytic in the half-periods away from a degenerate lattice: no cut
        with ball_precision():
            value = cls.ball_value(z, omega_1, omega_3)
        return +value
    return staticmethod(ball)


class WeierstrassP(WeierstrassBase):
    r"""℘(z; ω₁, ω₃), DLMF 23.2.4: 1/z² + Σ′ (1/(z − w)² − 1/w²) over the lattice points w ≠ 0.

    >>> import mpmath
    >>> with mpmath.workdps(30):   # the Laurent expansion 1/z² + g₂z²/20 + …: ℘ − 1/z² → 0
    ...     print(abs(WeierstrassP.mp(mpmath.mpf("1e-8"), 1, 1j) - mpmath.mpf("1e16")) < 1e-10)
    True
    """

    latex_name = r"\wp"
    flint_name = "elliptic_p"
    degree = -2

    def fdiff(self, argindex=1):
        raise ArgumentIndexError(self, argindex)  # ℘′ has no closed form in ℘ alone (23.3.10)

    @mp_route()
    def mp(cls, z, omega_1, omega_3):
        v, q, t, d1, d2, d1_0, d3_0 = _theta_parts(z, omega_1, omega_3)
        eta = _eta_1(omega_1, d1_0, d3_0)
        return -eta / omega_1 - (mpmath.pi / (2 * omega_1)) ** 2 * (d2 / t - (d1 / t) ** 2)


class WeierstrassZeta(WeierstrassBase):
    r"""ζ(z; ω₁, ω₃), DLMF 23.2.5: ζ′ = −℘, ζ(z) − 1/z → 0 as z → 0.

    >>> import mpmath
    >>> with mpmath.workdps(30):   # quasi-periodicity 23.2.14: ζ(z + 2ω₁) = ζ(z) + 2η₁, η₁ = ζ(ω₁)
    ...     z, w1, w3 = mpmath.mpf("0.3"), mpmath.mpf(1), mpmath.mpc(0.2, 1.1)
    ...     lhs = WeierstrassZeta.mp(z + 2*w1, w1, w3) - WeierstrassZeta.mp(z, w1, w3)
    ...     print(mpmath.almosteq(lhs, 2*WeierstrassZeta.mp(w1, w1, w3), 1e-25))
    True
    """

    latex_name = r"\zeta"
    flint_name = "elliptic_zeta"
    degree = -1

    def fdiff(self, argindex=1):
        if argindex == 1:
            return -WeierstrassP(*self.args)
        raise ArgumentIndexError(self, argindex)

    @mp_route()
    def mp(cls, z, omega_1, omega_3):
        v, q, t, d1, d2, d1_0, d3_0 = _theta_parts(z, omega_1, omega_3)
        eta = _eta_1(omega_1, d1_0, d3_0)
        return eta * z / omega_1 + mpmath.pi / (2 * omega_1) * d1 / t


class WeierstrassSigma(WeierstrassBase):
    r"""σ(z; ω₁, ω₃), DLMF 23.2.6: an entire function with σ′/σ = ζ, σ(z)/z → 1 as z → 0.

    >>> import mpmath
    >>> with mpmath.workdps(30):
    ...     print(mpmath.almosteq(WeierstrassSigma.mp(mpmath.mpf("1e-10"), 1, 1j), mpmath.mpf("1e-10"), 1e-25))
    True
    """

    latex_name = r"\sigma"
    flint_name = "elliptic_sigma"
    degree = 1

    def fdiff(self, argindex=1):
        if argindex == 1:
            return WeierstrassZeta(*self.args) * self
        raise ArgumentIndexError(self, argindex)

    @mp_route()
    def mp(cls, z, omega_1, omega_3):
        v, q, t, d1, d2, d1_0, d3_0 = _theta_parts(z, omega_1, omega_3)
        eta = _eta_1(omega_1, d1_0, d3_0)
        return 2 * omega_1 / mpmath.pi * mpmath.exp(eta * z ** 2 / (2 * omega_1)) * t / d1_0


for _cls in (WeierstrassP, WeierstrassZeta, WeierstrassSigma):
    _cls.ball = _ball_of(_cls)

__all__ = ["WeierstrassP", "WeierstrassSigma", "WeierstrassZeta"]
