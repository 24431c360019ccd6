"""Legendre's elliptic integrals F, E, D, Π and K, E, D, Π complete, DLMF §19.2(ii), with the
**modulus** k (the functions built on them — K′, E′, the AGM, Jacobi's Zeta, Heuman's Lambda — are
in :mod:`quasicentral.notation.special.legendre_derived`).

mpmath routes: ``ellipk``, ``ellipe``, ``ellipf``, ``ellippi`` at the parameter m = k² (exact
for a real k, with guard bits for the cancellation in 1 − k² sin²φ), and Carlson's
``elliprf``/``elliprd``/``elliprj``/``elliprg`` where a Legendre form would cancel (19.25.1,
19.25.5–19.25.14).  Ball routes: flint's ``elliptic_k/e/f/e_inc/pi/pi_inc`` and Carlson's
``elliptic_r*``.  Cauchy principal values (Π with 1 < α², real arguments, DLMF 19.2.7) are the
real part of the libraries' one-sided limits.
"""

from __future__ import annotations

import mpmath
import sympy as sp
from flint import acb, arb
from sympy.core.function import ArgumentIndexError

from quasicentral.notation.special.base import (
    DLMFFunction, rd, rj, ball_parameters, ball_route, exact_real, is_real, lost_bits, may_meet,
    may_meet_cut, mp_route, nan_ball, negative_real, parameters, pv_union, real,
)


# --- shared numerics ---------------------------------------------------------------------

def reduce_amplitude(phi):
    """(j, ψ) with φ = jπ + ψ, j = nint(Re φ/π): the reduction of the quasi-periodic
    incomplete integrals (DLMF §19.2(ii): F(φ + jπ) = F(φ) + 2jK)."""
    j = int(mpmath.nint(mpmath.re(phi) / mpmath.pi))
    return j, phi - j * mpmath.pi


def delta_squared(phi, mc):
    """Δ² = 1 − k² sin²φ written as cos²φ + k′² sin²φ (no cancellation as k → 1, φ → π/2)."""
    s, c = mpmath.sin(phi), mpmath.cos(phi)
    return c * c + mc * s * s


def with_delta_guard(phi, mc, body):
    """Run *body* with extra bits for the digits mpmath's own 1 − m sin²φ loses."""
    with mpmath.workprec(40):
        extra = lost_bits(delta_squared(phi, mc))
    with mpmath.workprec(mpmath.mp.prec + extra):
        return body()


def d_complete_mp(mc):
    """D(k) = R_D(0, k′², 1)/3 (DLMF 19.25.1)."""
    return rd(0, mc, 1) / 3


def d_incomplete_mp(phi, mc):
    """D(φ, k) = sin³φ R_D(cos²φ, Δ², 1)/3 on |Re φ| ≤ π/2 (19.25.13 by homogeneity), and
    D(φ + jπ) = D(φ) + 2jD(k) elsewhere."""
    j, psi = reduce_amplitude(phi)
    s, c = mpmath.sin(psi), mpmath.cos(psi)
    value = s ** 3 * rd(c * c, c * c + mc * s * s, 1) / 3
    return value + 2 * j * d_complete_mp(mc) if j else value


def incomplete_cut(phi, m, *more):
    """A ball argument of an incomplete integral may touch a cut: Δ² = 1 − m sin²φ on
    (−∞, 0], a further factor in *more* there (1 − α² sin²φ for Π), or, where the amplitude
    reaches |Re φ| ≥ π/2 (the quasi-periodic continuation adds 2jK(m)), m on [1, ∞)."""
    s = phi.sin()
    if may_meet_cut(1 - m * s * s) or any(may_meet_cut(f) for f in more):
        return True
    half = arb.pi() / 2
    if not (phi.real.abs_upper() < half):
        return may_meet(m, 1, None)
    return False


def d_incomplete_ball(phi, m, mc):
    """D(φ, k) as a ball: the R_D form where the reduction index is certain, (F − E)/k²
    from flint's rigorous F and E where the ball straddles Re φ = (j + ½)π."""
    pi = arb.pi()
    t = phi.real / pi
    j = int(mpmath.nint(float(t.mid())))
    psi = phi - j * acb(pi)
    if psi.real.abs_upper() < pi / 2:
        s, c = psi.sin(), psi.cos()
        value = s ** 3 * acb.elliptic_rd(c * c, c * c + mc * s * s, acb(1)) / 3
        if j:
            value += 2 * j * acb.elliptic_rd(acb(0), mc, acb(1)) / 3
        return value
    return (acb.elliptic_f(phi, m) - acb.elliptic_e_inc(phi, m)) / m


def pv_condition(n, m, *reals):
    """Π's Cauchy principal value applies (DLMF 19.2.7): α² > 1 and k² < 1 real (balls: may)."""
    return (n.imag.contains(0) and not (n.real < 1) and m.imag.contains(0) and not (m.real > 1)
            and all(r.imag.contains(0) for r in reals))


def pv_real(value, n, m, *reals):
    """The principal value from mpmath's one-sided limit: its real part, where every argument
    is real, α² > 1 and k² < 1."""
    if is_real(n, m, *reals) and real(n) > 1 and real(m) < 1:
        return real(value)
    return value


def pi_complete_mp(n, m, mc):
    """Π(n, k) = K + (n/3) R_J(0, k′², 1, 1 − n) (19.25.2); for real n > 1, k² < 1 the principal
    value K − Π(k²/n, k) (19.6.5).  (mpmath's ``ellippi(n, m)`` takes 35 s at 57 digits for
    n = 0.25 + 0.125i, m = (1.25 + 0.5i)².)"""
    with mpmath.workprec(mpmath.mp.prec + lost_bits(mc)):
        K = mpmath.ellipk(m)
    if is_real(n, m) and real(n) > 1 and real(m) < 1:
        return K - pi_complete_mp(real(m) / real(n), m, mc)
    if n == 0:
        return K
    return K + n / 3 * rj(0, mc, 1, 1 - n)


def pi_incomplete_mp(phi, n, m, mc):
    """Π(φ, n, k) = s R_F(c², Δ², 1) + (n/3) s³ R_J(c², Δ², 1, 1 − n s²) on |Re φ| ≤ π/2 (19.25.14),
    Π(φ + jπ) = Π(φ) + 2jΠ(n, k); the real part of R_J where it is a principal value."""
    j, psi = reduce_amplitude(phi)
    s, c = mpmath.sin(psi), mpmath.cos(psi)
    c2, d2, w = c * c, c * c + mc * s * s, 1 - n * s * s
    value = s * mpmath.elliprf(c2, d2, 1)
    if n != 0:
        value += n / 3 * s ** 3 * rj(c2, d2, 1, w)
    return value + 2 * j * pi_complete_mp(n, m, mc) if j else value


class EllipticK(DLMFFunction):
    r"""Complete elliptic integral of the first kind, DLMF 19.2.8,

    K(k) = ∫₀^{π/2} dθ / √(1 − k² sin²θ),   with the **modulus** k (sympy's ``elliptic_k``,
    mpmath's ``ellipk`` and flint's ``elliptic_k`` take m = k²).

    Principal branch: cut k² ∈ [1, ∞); on the cut the value is mpmath's and flint's (the limit
    from Im k² < 0).  K(0) = π/2 (19.6.1); dK/dk = (E − k′²K)/(k k′²) (19.4.1).

    >>> import mpmath, sympy as sp
    >>> sp.N(EllipticK(sp.Rational(1, 2)), 25)
    1.685750354812596042871204
    >>> with mpmath.workdps(30):   # the integral 19.2.8 by quadrature
    ...     q = mpmath.quad(lambda t: 1/mpmath.sqrt(1 - mpmath.sin(t)**2/4), [0, mpmath.pi/2])
    ...     print(mpmath.almosteq(EllipticK.mp(mpmath.mpf(1)/2), q, 1e-28))
    True
    >>> EllipticK(0), EllipticK(sp.Symbol("k")).diff(sp.Symbol("k")).has(EllipticE)
    (pi/2, True)
    """

    nargs = 1
    latex_name = "K"

    @classmethod
    def eval(cls, k):
        if k.is_zero:
            return sp.pi / 2

    def fdiff(self, argindex=1):
        if argindex != 1:
            raise ArgumentIndexError(self, argindex)
        k = self.args[0]
        kc2 = 1 - k ** 2
        return (EllipticE(k) - kc2 * EllipticK(k)) / (k * kc2)

    @mp_route()
    def mp(cls, k):
        m, mc = parameters(k)
        with mpmath.workprec(mpmath.mp.prec + lost_bits(mc)):
            return mpmath.ellipk(m)

    @ball_route
    def ball(k, analytic=False):
        m, _ = ball_parameters(k)
        if analytic and may_meet(m, 1, None):
            return nan_ball()
        return m.elliptic_k()


class EllipticE(DLMFFunction):
    r"""Elliptic integrals of the second kind, DLMF 19.2.5 and 19.2.8,

    E(φ, k) = ∫₀^φ √(1 − k² sin²θ) dθ,   E(k) = E(π/2, k),   **modulus** k.

    One argument: the complete integral; two: the incomplete one (DLMF's order E(φ, k)).
    Real φ beyond ±π/2: E(φ + jπ, k) = E(φ, k) + 2jE(k); complex φ: mpmath's and flint's
    reduction by Re φ.  E(0) = π/2, E(1) = 1 (19.6.1); dE/dk = (E − K)/k (19.4.1);
    ∂E(φ,k)/∂φ = Δ, ∂E(φ,k)/∂k = (E(φ,k) − F(φ,k))/k (19.4.2).

    >>> import mpmath, sympy as sp
    >>> sp.N(EllipticE(sp.Rational(1, 3), sp.Rational(1, 2)), 20)
    0.33181789856101344474
    >>> with mpmath.workdps(30):   # 19.2.5 by quadrature; E(1) = 1
    ...     f = lambda t: mpmath.sqrt(1 - mpmath.sin(t)**2/4)
    ...     print(mpmath.almosteq(EllipticE.mp(mpmath.mpf(1)/3, mpmath.mpf(1)/2),
    ...                           mpmath.quad(f, [0, mpmath.mpf(1)/3]), 1e-28))
    True
    >>> EllipticE(1), EllipticE(0)
    (1, pi/2)
    """

    nargs = (1, 2)
    latex_name = "E"

    @classmethod
    def eval(cls, *args):
        if len(args) == 1:
            k = args[0]
            if k.is_zero:
                return sp.pi / 2
            if k == 1:
                return sp.S.One
        else:
            phi, k = args
            if phi.is_zero:
                return sp.S.Zero
            if k.is_zero:
                return phi

    def fdiff(self, argindex=1):
        if len(self.args) == 1:
            if argindex != 1:
                raise ArgumentIndexError(self, argindex)
            k = self.args[0]
            return (EllipticE(k) - EllipticK(k)) / k
        phi, k = self.args
        if argindex == 1:
            return sp.sqrt(1 - k ** 2 * sp.sin(phi) ** 2)
        if argindex == 2:
            return (EllipticE(phi, k) - EllipticF(phi, k)) / k
        raise ArgumentIndexError(self, argindex)

    @mp_route()
    def mp(cls, *args):
        if len(args) == 1:
            m, mc = parameters(args[0])
            with mpmath.workprec(mpmath.mp.prec + lost_bits(mc)):
                return mpmath.ellipe(m)
        phi, k = args
        m, mc = parameters(k)
        return with_delta_guard(phi, mc, lambda: mpmath.ellipe(phi, m))

    @ball_route
    def ball(*args, analytic=False):
        if len(args) == 1:
            m, _ = ball_parameters(args[0])
            if analytic and may_meet(m, 1, None):
                return nan_ball()
            return m.elliptic_e()
        phi, k = args
        m, _ = ball_parameters(k)
        if analytic and incomplete_cut(phi, m):
            return nan_ball()
        return acb.elliptic_e_inc(phi, m)


class EllipticF(DLMFFunction):
    r"""Incomplete elliptic integral of the first kind, DLMF 19.2.4,

    F(φ, k) = ∫₀^φ dθ / √(1 − k² sin²θ),   **modulus** k (mpmath's ``ellipf(φ, m)``).

    F(φ + jπ, k) = F(φ, k) + 2jK(k) continues it beyond |Re φ| ≤ π/2 (mpmath's and flint's
    reduction by Re φ).  F(0, k) = 0, F(φ, 0) = φ (19.6.9); ∂F/∂φ = 1/Δ,
    ∂F/∂k = (E(φ,k) − k′²F(φ,k))/(k k′²) − k sinφ cosφ/(k′² Δ) (19.4 area), Δ = √(1 − k² sin²φ).

    >>> import mpmath, sympy as sp
    >>> with mpmath.workdps(30):   # F(π/2, k) = K(k); and Carlson's form 19.25.5
    ...     k = mpmath.mpf(3)/5
    ...     print(mpmath.almosteq(EllipticF.mp(mpmath.pi/2, k), EllipticK.mp(k), 1e-28))
    ...     s, c = mpmath.sin(1), mpmath.cos(1)
    ...     print(mpmath.almosteq(EllipticF.mp(1, k), s*mpmath.elliprf(c**2, 1 - k**2*s**2, 1), 1e-28))
    True
    True
    >>> sp.N(EllipticF(1, sp.Rational(3, 5)), 20)
    1.0562731098220990391
    """

    nargs = 2
    latex_name = "F"

    @classmethod
    def eval(cls, phi, k):
        if phi.is_zero:
            return sp.S.Zero
        if k.is_zero:
            return phi

    def fdiff(self, argindex=1):
        phi, k = self.args
        delta = sp.sqrt(1 - k ** 2 * sp.sin(phi) ** 2)
        if argindex == 1:
            return 1 / delta
        if argindex == 2:
            kc2 = 1 - k ** 2
            return ((EllipticE(phi, k) - kc2 * EllipticF(phi, k)) / (k * kc2)
                    - k * sp.sin(phi) * sp.cos(phi) / (kc2 * delta))
        raise ArgumentIndexError(self, argindex)

    @mp_route()
    def mp(cls, phi, k):
        m, mc = parameters(k)
        return with_delta_guard(phi, mc, lambda: mpmath.ellipf(phi, m))

    @ball_route
    def ball(phi, k, analytic=False):
        m, _ = ball_parameters(k)
        if analytic and incomplete_cut(phi, m):
            return nan_ball()
        return acb.elliptic_f(phi, m)


class EllipticD(DLMFFunction):
    r"""DLMF 19.2.6: D(φ, k) = ∫₀^φ sin²θ dθ/√(1 − k² sin²θ) = (F(φ,k) − E(φ,k))/k²,
    D(k) = D(π/2, k) = (K − E)/k², **modulus** k.

    Evaluated without the cancellation of (F − E)/k²: D(k) = R_D(0, k′², 1)/3 (19.25.1),
    D(φ, k) = sin³φ R_D(cos²φ, Δ², 1)/3 on |Re φ| ≤ π/2 (19.25.13) and D(φ + jπ) = D(φ) + 2jD.
    dD/dk = E/(k k′²) − 2D/k (from 19.4.1); ∂D(φ,k)/∂φ = sin²φ/Δ.

    >>> import mpmath
    >>> with mpmath.workdps(30):   # against (K − E)/k² and the integral
    ...     k = mpmath.mpf(1)/2
    ...     print(mpmath.almosteq(EllipticD.mp(k), (EllipticK.mp(k) - EllipticE.mp(k))/k**2, 1e-27))
    ...     q = mpmath.quad(lambda t: mpmath.sin(t)**2/mpmath.sqrt(1 - (k*mpmath.sin(t))**2), [0, 4])
    ...     print(mpmath.almosteq(EllipticD.mp(4, k), q, 1e-27))
    True
    True
    """

    nargs = (1, 2)
    latex_name = "D"

    @classmethod
    def eval(cls, *args):
        if len(args) == 2 and args[0].is_zero:
            return sp.S.Zero

    @classmethod
    def definition(cls, *args):
        if len(args) == 1:
            k, = args
            return (EllipticK(k) - EllipticE(k)) / k ** 2
        phi, k = args
        return (EllipticF(phi, k) - EllipticE(phi, k)) / k ** 2

    def fdiff(self, argindex=1):
        if len(self.args) == 1:
            if argindex != 1:
                raise ArgumentIndexError(self, argindex)
            k = self.args[0]
            return EllipticE(k) / (k * (1 - k ** 2)) - 2 * EllipticD(k) / k
        phi, k = self.args
        if argindex == 1:
            return sp.sin(phi) ** 2 / sp.sqrt(1 - k ** 2 * sp.sin(phi) ** 2)
        return self.diff_definition(argindex)

    @mp_route()
    def mp(cls, *args):
        _, mc = parameters(args[-1])
        if len(args) == 1:
            return d_complete_mp(mc)
        return d_incomplete_mp(args[0], mc)

    @ball_route
    def ball(*args, analytic=False):
        m, mc = ball_parameters(args[-1])
        if len(args) == 1:
            if analytic and may_meet(m, 1, None):
                return nan_ball()
            return acb.elliptic_rd(acb(0), mc, acb(1)) / 3
        phi = args[0]
        if analytic and incomplete_cut(phi, m):
            return nan_ball()
        return d_incomplete_ball(phi, m, mc)


class EllipticPi(DLMFFunction):
    r"""Elliptic integrals of the third kind, DLMF 19.2.7 and 19.2.8,

    Π(φ, α², k) = ∫₀^φ dθ / (√(1 − k² sin²θ) (1 − α² sin²θ)),   Π(α², k) = Π(π/2, α², k),

    DLMF's argument order (the characteristic is n = α² itself, not α), **modulus** k; mpmath's
    ``ellippi(n, φ, m)`` orders them differently.  For real arguments with 1 < α², k² < 1 the
    integral is a **Cauchy principal value** (DLMF 19.2.7), the real part of the one-sided
    limits; elsewhere the principal branch.  mpmath route: Carlson's forms 19.25.2 and 19.25.14
    with ``elliprf``/``elliprj`` (mpmath's ``ellippi`` can take tens of seconds at complex
    arguments); balls: flint's ``elliptic_pi``/``elliptic_pi_inc``.
    Derivatives: 19.4.4 (∂/∂k) and sympy's ∂/∂n, converted from m to k.

    >>> import mpmath
    >>> with mpmath.workdps(30):   # Π(0, k) = K(k); the principal value 19.6.5: Π(α²) = K − Π(k²/α²)
    ...     k = mpmath.mpf(1)/2
    ...     print(mpmath.almosteq(EllipticPi.mp(0, k), EllipticK.mp(k), 1e-28))
    ...     print(mpmath.almosteq(EllipticPi.mp(2, k), EllipticK.mp(k) - EllipticPi.mp(k**2/2, k), 1e-27))
    True
    True
    """

    nargs = (2, 3)
    latex_name = r"\Pi"

    @classmethod
    def eval(cls, *args):
        if len(args) == 3 and args[0].is_zero:
            return sp.S.Zero

    def fdiff(self, argindex=1):
        if len(self.args) == 2:
            n, k = self.args
            m = k ** 2
            if argindex == 1:
                return ((EllipticE(k) + (m - n) * EllipticK(k) / n + (n ** 2 - m) * EllipticPi(n, k) / n)
                        / (2 * (m - n) * (n - 1)))
            if argindex == 2:
                return k * (EllipticE(k) / (m - 1) + EllipticPi(n, k)) / (n - m)
            raise ArgumentIndexError(self, argindex)
        phi, n, k = self.args
        m = k ** 2
        s2 = sp.sin(phi) ** 2
        delta = sp.sqrt(1 - m * s2)
        sin2 = sp.sin(2 * phi)
        if argindex == 1:
            return 1 / (delta * (1 - n * s2))
        if argindex == 2:
            return ((EllipticE(phi, k) + (m - n) * EllipticF(phi, k) / n + (n ** 2 - m) * EllipticPi(phi, n, k) / n
                     - n * delta * sin2 / (2 * (1 - n * s2))) / (2 * (m - n) * (n - 1)))
        if argindex == 3:
            return k * (EllipticE(phi, k) / (m - 1) + EllipticPi(phi, n, k)
                        - m * sin2 / (2 * (m - 1) * delta)) / (n - m)
        raise ArgumentIndexError(self, argindex)

    @mp_route(ladder=lambda *args: not (len(args) == 3 and is_real(*args)
                                        and negative_real(1 - args[1] * mpmath.sin(args[0]) ** 2)))
    def mp(cls, *args):
        if len(args) == 2:
            n, k = args
            m, mc = parameters(k)
            return pi_complete_mp(n, m, mc)
        phi, n, k = args
        m, mc = parameters(k)
        return pi_incomplete_mp(phi, n, m, mc)

    @ball_route
    def ball(*args, analytic=False):
        if len(args) == 2:
            n, k = args
            m, _ = ball_parameters(k)
            if analytic and (may_meet(m, 1, None) or may_meet(n, 1, None)):
                return nan_ball()
            if exact_real(n) and exact_real(m) and n.real > 1 and m.real < 1:
                # the principal value by 19.6.5, Π(α², k) = K − Π(k²/α², k): flint's one-sided
                # limit on the cut is ~10⁻¹⁶ wide whatever the precision
                return m.elliptic_k() - acb.elliptic_pi(m / n, m)
            value = acb.elliptic_pi(n, m)
            return pv_union(value, False, pv_condition(n, m))
        phi, n, k = args
        m, _ = ball_parameters(k)
        if analytic and (incomplete_cut(phi, m, 1 - n * phi.sin() ** 2)
                         or (not (phi.real.abs_upper() < arb.pi() / 2) and may_meet(n, 1, None))):
            return nan_ball()
        value = acb.elliptic_pi_inc(n, phi, m)
        return pv_union(value, exact_real(n) and exact_real(m) and exact_real(phi), pv_condition(n, m, phi))
