"""Functions built on Legendre's integrals, with the **modulus** k: the complementary integrals
K′, E′ (DLMF 19.2.9, continued into the left half-plane), the AGM (§19.8), Jacobi's Zeta and
Heuman's Lambda (§19.2(iv)).

mpmath routes through ``ellipk``/``ellipe`` at the parameter m = k² and Carlson's ``elliprf``/
``elliprd``/``elliprj`` where a Legendre form would cancel; ball routes through flint's
``elliptic_k``/``elliptic_e``/``agm`` and Carlson's ``elliptic_r*``.
"""

from __future__ import annotations

import mpmath
import sympy as sp
from flint import acb
from sympy.core.function import ArgumentIndexError

from quasicentral.notation.special.base import (
    DLMFFunction, ball_parameters, ball_route, is_real, lost_bits, may_meet, may_meet_cut,
    mp_route, nan_ball, parameters, real, rj,
)
from quasicentral.notation.special.legendre import (
    EllipticE, EllipticF, EllipticK, d_incomplete_ball, d_incomplete_mp, incomplete_cut,
    with_delta_guard,
)

class EllipticKp(DLMFFunction):
    r"""K′(k) = K(k′), k′ = √(1 − k²) (DLMF 19.2.9 with 19.2.8), **modulus** k.

    In the right half-plane K′(k) = K(k′) = R_F(0, k², 1) (19.25.1 with k ↔ k′), exact in k² near
    k = 0 where K(√(1 − k²)) would cancel; in the left half-plane DLMF 19.2.9 continues it as
    K(k′) ∓ 2iK(k) for π/2 < ±ph k < π (:func:`continuation_side`), so that K′ is analytic across
    the imaginary axis and not even in k there.  Cut:
    k² ∈ (−∞, 0] (k imaginary), where the value is K(k′) at the real k′ > 1, i.e. mpmath's
    ``ellipk(1 − k²)`` on its own cut.  dK′/dk = −(E′ − k²K′)/(k k′²) (19.4.1 with k ↔ k′).

    >>> import mpmath
    >>> with mpmath.workdps(30):   # against K(k′), and Legendre's relation 19.7.1
    ...     k = mpmath.mpf(1)/3
    ...     print(mpmath.almosteq(EllipticKp.mp(k), EllipticK.mp(mpmath.sqrt(1 - k**2)), 1e-28))
    ...     K, E, Kp, Ep = EllipticK.mp(k), EllipticE.mp(k), EllipticKp.mp(k), EllipticEp.mp(k)
    ...     print(mpmath.almosteq(E*Kp + Ep*K - K*Kp, mpmath.pi/2, 1e-28))
    True
    True
    """

    nargs = 1
    latex_name = "K'"

    def _latex(self, printer, exp=None):
        power = "^{%s}" % exp if exp is not None else ""
        return r"{K'}%s\left(%s\right)" % (power, self._latex_args(printer))

    def fdiff(self, argindex=1):
        if argindex != 1:
            raise ArgumentIndexError(self, argindex)
        k = self.args[0]
        return -(EllipticEp(k) - k ** 2 * EllipticKp(k)) / (k * (1 - k ** 2))

    @mp_route()
    def mp(cls, k):
        m, mc = parameters(k)
        if is_real(m) and real(m) < 0:
            return mpmath.ellipk(mc)
        side = continuation_side(k)
        base = mpmath.elliprf(0, m, 1)
        # only where the side adds 2iK(k): K(k) is infinite at k = ±1, where K′ = K(0) = π/2
        return base + side * 2j * EllipticK.mp(k) if side else base

    @ball_route
    def ball(k, analytic=False):
        m, mc = ball_parameters(k)
        if analytic and may_meet_cut(m):
            return nan_ball()
        if m.imag.contains(0) and not (m.real > 0):
            return mc.elliptic_k()
        side = ball_continuation_side(k)
        if side is None:
            return nan_ball()
        base = acb.elliptic_rf(acb(0), m, acb(1))
        return base + side * 2 * acb(0, 1) * m.elliptic_k() if side else base


class EllipticEp(DLMFFunction):
    r"""E′(k) = E(k′), k′ = √(1 − k²) (DLMF 19.2.9 with 19.2.8), **modulus** k.

    E′(k) = 2R_G(0, k², 1) (19.25.1 with k ↔ k′); cut k² ∈ (−∞, 0] as for K′ (there: mpmath's
    ``ellipe(1 − k²)``).  dE′/dk = k(K′ − E′)/k′² (19.4.1 with k ↔ k′).

    >>> import mpmath
    >>> with mpmath.workdps(30):   # E′(k) = E(k′); E′(0) = E(1) = 1
    ...     k = mpmath.mpf(1)/3
    ...     print(mpmath.almosteq(EllipticEp.mp(k), EllipticE.mp(mpmath.sqrt(1 - k**2)), 1e-28))
    ...     print(EllipticEp.mp(0))
    True
    1.0
    """

    nargs = 1
    latex_name = "E'"

    def _latex(self, printer, exp=None):
        power = "^{%s}" % exp if exp is not None else ""
        return r"{E'}%s\left(%s\right)" % (power, self._latex_args(printer))

    def fdiff(self, argindex=1):
        if argindex != 1:
            raise ArgumentIndexError(self, argindex)
        k = self.args[0]
        return k * (EllipticKp(k) - EllipticEp(k)) / (1 - k ** 2)

    @mp_route()
    def mp(cls, k):
        m, mc = parameters(k)
        if is_real(m) and real(m) < 0:
            return mpmath.ellipe(mc)
        side = continuation_side(k)
        base = 2 * mpmath.elliprg(0, m, 1)
        return base + side * 2j * (EllipticK.mp(k) - EllipticE.mp(k)) if side else base

    @ball_route
    def ball(k, analytic=False):
        m, mc = ball_parameters(k)
        if analytic and may_meet_cut(m):
            return nan_ball()
        if m.imag.contains(0) and not (m.real > 0):
            return mc.elliptic_e()
        side = ball_continuation_side(k)
        if side is None:
            return nan_ball()
        base = 2 * acb.elliptic_rg(acb(0), m, acb(1))
        return base + side * 2 * acb(0, 1) * (m.elliptic_k() - m.elliptic_e()) if side else base


def continuation_side(k) -> int:
    """DLMF 19.2.9: K′(k) = K(k′) for |ph k| ≤ π/2, and K(k′) ∓ 2iK(k) for π/2 < ±ph k < π
    (E′ likewise with K − E): 0 in the right half-plane (and on the real line), −1 above the
    left half-plane's real axis, +1 below it — the factor of 2iK(k) added."""
    if not isinstance(k, mpmath.mpc) or k.imag == 0 or not (k.real < 0):
        return 0
    return -1 if k.imag > 0 else 1


def ball_continuation_side(k):
    """:func:`continuation_side` of a ball; None where the ball straddles a boundary of the cases."""
    if k.real > 0 or (k.imag.is_exact() and k.imag == 0):
        return 0
    if k.real < 0 and k.imag > 0:
        return -1
    if k.real < 0 and k.imag < 0:
        return 1
    return None


class AGM(DLMFFunction):
    r"""Arithmetic–geometric mean M(a, b), DLMF 19.8.1: a₀ = a, b₀ = b, a_{n+1} = (a_n + b_n)/2,
    b_{n+1} = √(a_n b_n), M = lim a_n.

    DLMF defines it for a, b > 0.  Elsewhere this is the analytic continuation
    M(a, b) = a M(1, b/a), cut b/a ∈ (−∞, 0] — the "optimal" choice of square roots (flint's
    ``agm``), equal to π(a + b)/(4K((a − b)/(a + b))) (19.8.5 with Landen's 19.8.12).
    **mpmath's ``agm`` takes the principal root at every step, a different function off the
    positive reals** (M(1 + 2i, −3 + 0.5i): mpmath 0.97 − 0.06i, this one −1.10 + 1.75i), so it
    is used only for positive ratios.  Derivatives: of the K form above (DLMF gives none).

    >>> import mpmath
    >>> with mpmath.workdps(30):   # 19.8.5: K(k) = π/(2M(1, k′)); the lemniscate constant ϖ = π/M(1, √2)
    ...     k = mpmath.mpf(1)/2
    ...     print(mpmath.almosteq(AGM.mp(1, mpmath.sqrt(1 - k**2)), mpmath.pi/(2*EllipticK.mp(k)), 1e-28))
    ...     print(mpmath.nstr(mpmath.pi/AGM.mp(1, mpmath.sqrt(2)), 25))
    True
    2.62205755429211981046484
    """

    nargs = 2
    latex_name = "M"

    @classmethod
    def eval(cls, a, b):
        if a == b:
            return a

    @classmethod
    def definition(cls, a, b):
        return sp.pi * (a + b) / (4 * EllipticK((a - b) / (a + b)))

    def fdiff(self, argindex=1):
        if argindex not in (1, 2):
            raise ArgumentIndexError(self, argindex)
        return self.diff_definition(argindex)

    @mp_route()
    def mp(cls, a, b):
        if a == 0 or b == 0:
            return mpmath.mpf(0)
        z = b / a
        if is_real(z) and real(z) > 0:
            return a * mpmath.agm(1, real(z))
        if z == -1:
            return mpmath.mpf(0)
        return a * mpmath.pi * (1 + z) / (4 * mpmath.ellipk(((1 - z) / (1 + z)) ** 2))

    @ball_route
    def ball(a, b, analytic=False):
        if analytic and (a.contains(0) or may_meet_cut(b / a)):
            return nan_ball()
        return a.agm(b)


class JacobiZeta(DLMFFunction):
    r"""Jacobi's Zeta function, DLMF §19.2(iv):

    Z(φ, k) = E(φ, k) − (E(k)/K(k)) F(φ, k),   **modulus** k, period π in φ.

    Evaluated without cancellation as Z = (k²/(3K)) sinφ cosφ Δ R_J(0, k′², 1, Δ²)
    (§19.25(i); Δ = √(1 − k² sin²φ) principal), which is analytic across Re φ = π/2.
    For Jacobi's Z(x|k) with the argument x = F(φ, k) see ``JacobiZ`` (22.16.32).
    Derivatives: of the definition.

    >>> import mpmath
    >>> with mpmath.workdps(30):   # against the definition
    ...     phi, k = mpmath.mpf(7)/10, mpmath.mpf(4)/5
    ...     d = EllipticE.mp(phi, k) - EllipticE.mp(k)/EllipticK.mp(k)*EllipticF.mp(phi, k)
    ...     print(mpmath.almosteq(JacobiZeta.mp(phi, k), d, 1e-28))
    True
    """

    nargs = 2
    latex_name = r"\mathrm{Z}"

    @classmethod
    def eval(cls, phi, k):
        if phi.is_zero or k.is_zero:
            return sp.S.Zero

    @classmethod
    def definition(cls, phi, k):
        return EllipticE(phi, k) - EllipticE(k) / EllipticK(k) * EllipticF(phi, k)

    def fdiff(self, argindex=1):
        if argindex not in (1, 2):
            raise ArgumentIndexError(self, argindex)
        return self.diff_definition(argindex)

    @mp_route()
    def mp(cls, phi, k):
        m, mc = parameters(k)
        s, c = mpmath.sin(phi), mpmath.cos(phi)
        d2 = c * c + mc * s * s
        with mpmath.workprec(mpmath.mp.prec + lost_bits(mc)):
            K = mpmath.ellipk(m)
        return m / (3 * K) * s * c * mpmath.sqrt(d2) * rj(0, mc, 1, d2)

    @ball_route
    def ball(phi, k, analytic=False):
        m, mc = ball_parameters(k)
        s, c = phi.sin(), phi.cos()
        d2 = c * c + mc * s * s
        if analytic and (may_meet_cut(d2) or may_meet(m, 1, None)):
            return nan_ball()
        return m / (3 * m.elliptic_k()) * s * c * d2.sqrt() * acb.elliptic_rj(acb(0), mc, acb(1), d2)


class HeumanLambda(DLMFFunction):
    r"""Heuman's Lambda function, DLMF §19.2(iv):

    Λ₀(φ, k) = (2/π) (E(k) F(φ, k′) + K(k) E(φ, k′) − K(k) F(φ, k′)),   **modulus** k,
    k′ = √(1 − k²) (only k′² enters).

    Evaluated as (2/π)(E(k)F(φ, k′) − K(k) k′² D(φ, k′)), since E − F = −k′²D (19.2.6), without
    the cancellation of E(φ, k′) − F(φ, k′).  Λ₀(π/2, k) = 1 by Legendre's relation;
    Λ₀(φ + π, k) = Λ₀(φ, k) + 2.  Derivatives: of the definition.

    >>> import mpmath
    >>> with mpmath.workdps(30):   # Λ₀(π/2, k) = 1 (Legendre's relation); the definition at φ = 0.6
    ...     k, phi = mpmath.mpf(3)/5, mpmath.mpf(3)/5
    ...     print(mpmath.almosteq(HeumanLambda.mp(mpmath.pi/2, k), 1, 1e-28))
    ...     kp = mpmath.sqrt(1 - k**2)
    ...     d = 2/mpmath.pi*(EllipticE.mp(k)*EllipticF.mp(phi, kp) + EllipticK.mp(k)*(EllipticE.mp(phi, kp) - EllipticF.mp(phi, kp)))
    ...     print(mpmath.almosteq(HeumanLambda.mp(phi, k), d, 1e-28))
    True
    True
    """

    nargs = 2
    latex_name = r"\Lambda_{0}"

    @classmethod
    def eval(cls, phi, k):
        if phi.is_zero:
            return sp.S.Zero

    @classmethod
    def definition(cls, phi, k):
        kp = sp.sqrt(1 - k ** 2)
        return 2 / sp.pi * (EllipticE(k) * EllipticF(phi, kp) + EllipticK(k) * EllipticE(phi, kp)
                            - EllipticK(k) * EllipticF(phi, kp))

    def fdiff(self, argindex=1):
        if argindex not in (1, 2):
            raise ArgumentIndexError(self, argindex)
        return self.diff_definition(argindex)

    @mp_route()
    def mp(cls, phi, k):
        m, mc = parameters(k)
        with mpmath.workprec(mpmath.mp.prec + lost_bits(mc)):
            K, E = mpmath.ellipk(m), mpmath.ellipe(m)
        F = with_delta_guard(phi, m, lambda: mpmath.ellipf(phi, mc))
        return 2 / mpmath.pi * (E * F - K * mc * d_incomplete_mp(phi, m))

    @ball_route
    def ball(phi, k, analytic=False):
        m, mc = ball_parameters(k)
        if analytic and (may_meet(m, 1, None) or incomplete_cut(phi, mc)):
            return nan_ball()
        F = acb.elliptic_f(phi, mc)
        D = d_incomplete_ball(phi, mc, m)
        return 2 / acb.pi() * (m.elliptic_e() * F - m.elliptic_k() * mc * D)
