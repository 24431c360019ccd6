"""Bulirsch's elliptic integrals, DLMF §19.2(iii), with the complementary modulus k_c = k′.

Evaluated (mpmath and balls) through their Carlson forms (DLMF §19.25(i)), written in x rather
than in r = 1/x² so that they are odd and analytic through x = 0:

* cel(k_c, p, a, b) = a R_F(0, k_c², 1) + ((b − pa)/3) R_J(0, k_c², 1, p),
* el1(x, k_c) = x R_F(1, 1 + k_c²x², 1 + x²),
* el2(x, k_c, a, b) = a x R_F(1, 1 + k_c²x², 1 + x²) + ((b − a)/3) x³ R_D(1, 1 + k_c²x², 1 + x²),
* el3(x, k_c, p) = x R_F(…) + ((1 − p)/3) x³ R_J(1, 1 + k_c²x², 1 + x², 1 + px²).

For complex x these are the analytic continuations of DLMF's real-x integrals (principal
Carlson branches).  Where p < 0 (cel) or 1 + px² < 0 (el3), with real arguments, the integrals
are Cauchy principal values (§19.2(iii)), the real part of the one-sided limits.
"""

from __future__ import annotations

import mpmath
import sympy as sp
from flint import acb
from sympy.core.function import ArgumentIndexError

from quasicentral.notation.special.base import (
    DLMFFunction, rd, rj, ball_route, exact_real, is_real, may_meet_cut, mp_route, nan_ball, negative_real,
    pv_union, real,
)
from quasicentral.notation.special.carlson import CarlsonRD, CarlsonRF, CarlsonRJ
from quasicentral.notation.special.legendre import pi_complete_mp


def carlson_args(x, kc):
    x2 = x * x
    return 1, 1 + kc * kc * x2, 1 + x2


class BulirschCel(DLMFFunction):
    r"""Bulirsch's complete integral, DLMF 19.2.11:

    cel(k_c, p, a, b) = ∫₀^{π/2} (a cos²θ + b sin²θ) dθ / ((cos²θ + p sin²θ) √(cos²θ + k_c² sin²θ)),

    k_c = k′ the complementary modulus, p ≠ 0 (principal value for p < 0).  Special cases
    (§19.2(iii)): cel(k_c, 1, 1, 1) = K(k), cel(k_c, 1, 1, k_c²) = E(k), cel(k_c, p, 1, 1) = Π(1 − p, k).
    Derivatives: of the Carlson form.

    >>> import mpmath
    >>> from quasicentral.notation.special.legendre import EllipticK, EllipticE
    >>> with mpmath.workdps(30):
    ...     kc = mpmath.mpf(3)/5; k = mpmath.sqrt(1 - kc**2)
    ...     print(mpmath.almosteq(BulirschCel.mp(kc, 1, 1, 1), EllipticK.mp(k), 1e-28),
    ...           mpmath.almosteq(BulirschCel.mp(kc, 1, 1, kc**2), EllipticE.mp(k), 1e-28))
    True True
    """

    nargs = 4
    latex_name = r"\operatorname{cel}"

    @classmethod
    def definition(cls, kc, p, a, b):
        return a * CarlsonRF(0, kc ** 2, 1) + (b - p * a) / 3 * CarlsonRJ(0, kc ** 2, 1, p)

    def fdiff(self, argindex=1):
        if argindex not in (1, 2, 3, 4):
            raise ArgumentIndexError(self, argindex)
        return self.diff_definition(argindex)

    @mp_route()
    def mp(cls, kc, p, a, b):
        kc2 = kc * kc
        if is_real(kc, p) and real(p) < 0:
            # the principal value through Π's (19.6.5): R_J(0, k_c², 1, p) = 3(Π(1 − p, k) − K)/(1 − p)
            m = 1 - kc2
            n = 1 - p
            K = mpmath.ellipk(m)
            r_j = -3 * pi_complete_mp(m / n, m, kc2) / n
        else:
            r_j = rj(0, kc2, 1, p)
        return a * mpmath.elliprf(0, kc2, 1) + (b - p * a) / 3 * r_j

    @ball_route
    def ball(kc, p, a, b, analytic=False):
        kc2 = kc * kc
        if analytic and (may_meet_cut(kc2) or may_meet_cut(p)):
            return nan_ball()
        zero, one = acb(0), acb(1)
        rj = acb.elliptic_rj(zero, kc2, one, p)
        rj = pv_union(rj, exact_real(kc) and exact_real(p), p.imag.contains(0) and not (p.real > 0))
        return a * acb.elliptic_rf(zero, kc2, one) + (b - p * a) / 3 * rj


class BulirschEl1(DLMFFunction):
    r"""Bulirsch's el1, DLMF §19.2(iii): el1(x, k_c) = ∫₀^{arctan x} dθ / √(cos²θ + k_c² sin²θ)
    = F(arctan x, k), k_c = k′.

    d el1/dx = 1/(√(1 + x²) √(1 + k_c²x²)); ∂/∂k_c of the Carlson form.

    >>> import mpmath
    >>> from quasicentral.notation.special.legendre import EllipticF
    >>> with mpmath.workdps(30):
    ...     x, kc = mpmath.mpf(2), mpmath.mpf(1)/2
    ...     print(mpmath.almosteq(BulirschEl1.mp(x, kc), EllipticF.mp(mpmath.atan(x), mpmath.sqrt(1 - kc**2)), 1e-28))
    True
    """

    nargs = 2
    latex_name = r"\operatorname{el1}"

    @classmethod
    def definition(cls, x, kc):
        return x * CarlsonRF(*carlson_args(x, kc))

    def fdiff(self, argindex=1):
        x, kc = self.args
        if argindex == 1:
            return 1 / (sp.sqrt(1 + x ** 2) * sp.sqrt(1 + kc ** 2 * x ** 2))
        if argindex == 2:
            return self.diff_definition(argindex)
        raise ArgumentIndexError(self, argindex)

    @mp_route()
    def mp(cls, x, kc):
        return x * mpmath.elliprf(*carlson_args(x, kc))

    @ball_route
    def ball(x, kc, analytic=False):
        one, y, z = carlson_args(x, kc)
        if analytic and (may_meet_cut(y) or may_meet_cut(z)):
            return nan_ball()
        return x * acb.elliptic_rf(acb(one), y, z)


class BulirschEl2(DLMFFunction):
    r"""Bulirsch's el2, DLMF §19.2(iii):

    el2(x, k_c, a, b) = ∫₀^{arctan x} (a + b tan²θ) dθ / √((1 + tan²θ)(1 + k_c² tan²θ))
                      = a F(φ, k) + (b − a) D(φ, k),   φ = arctan x, k_c = k′.

    el2(x, k_c, 1, k_c²) = E(arctan x, k).  d el2/dx = (a + bx²)/((1 + x²)^{3/2} √(1 + k_c²x²));
    the other derivatives of the Carlson form.

    >>> import mpmath
    >>> from quasicentral.notation.special.legendre import EllipticE
    >>> with mpmath.workdps(30):
    ...     x, kc = mpmath.mpf(2), mpmath.mpf(1)/2
    ...     print(mpmath.almosteq(BulirschEl2.mp(x, kc, 1, kc**2), EllipticE.mp(mpmath.atan(x), mpmath.sqrt(1 - kc**2)), 1e-28))
    True
    """

    nargs = 4
    latex_name = r"\operatorname{el2}"

    @classmethod
    def definition(cls, x, kc, a, b):
        args = carlson_args(x, kc)
        return a * x * CarlsonRF(*args) + (b - a) / 3 * x ** 3 * CarlsonRD(*args)

    def fdiff(self, argindex=1):
        x, kc, a, b = self.args
        if argindex == 1:
            return (a + b * x ** 2) / ((1 + x ** 2) * sp.sqrt(1 + x ** 2) * sp.sqrt(1 + kc ** 2 * x ** 2))
        if argindex in (2, 3, 4):
            return self.diff_definition(argindex)
        raise ArgumentIndexError(self, argindex)

    @mp_route()
    def mp(cls, x, kc, a, b):
        args = carlson_args(x, kc)
        return a * x * mpmath.elliprf(*args) + (b - a) / 3 * x ** 3 * rd(*args)

    @ball_route
    def ball(x, kc, a, b, analytic=False):
        one, y, z = carlson_args(x, kc)
        if analytic and (may_meet_cut(y) or may_meet_cut(z)):
            return nan_ball()
        one = acb(one)
        return a * x * acb.elliptic_rf(one, y, z) + (b - a) / 3 * x ** 3 * acb.elliptic_rd(one, y, z)


class BulirschEl3(DLMFFunction):
    r"""Bulirsch's el3, DLMF §19.2(iii):

    el3(x, k_c, p) = ∫₀^{arctan x} dθ / ((cos²θ + p sin²θ) √(cos²θ + k_c² sin²θ)) = Π(arctan x, 1 − p, k),

    k_c = k′; a Cauchy principal value where 1 + px² < 0 (real arguments).
    d el3/dx = √(1 + x²)/((1 + px²) √(1 + k_c²x²)); the other derivatives of the Carlson form.

    >>> import mpmath
    >>> from quasicentral.notation.special.legendre import EllipticPi
    >>> with mpmath.workdps(30):
    ...     x, kc, p = mpmath.mpf(2), mpmath.mpf(1)/2, mpmath.mpf(3)/10
    ...     k = mpmath.sqrt(1 - kc**2)
    ...     print(mpmath.almosteq(BulirschEl3.mp(x, kc, p), EllipticPi.mp(mpmath.atan(x), 1 - p, k), 1e-28))
    True
    """

    nargs = 3
    latex_name = r"\operatorname{el3}"

    @classmethod
    def definition(cls, x, kc, p):
        args = carlson_args(x, kc)
        return x * CarlsonRF(*args) + (1 - p) / 3 * x ** 3 * CarlsonRJ(*args, 1 + p * x ** 2)

    def fdiff(self, argindex=1):
        x, kc, p = self.args
        if argindex == 1:
            return sp.sqrt(1 + x ** 2) / ((1 + p * x ** 2) * sp.sqrt(1 + kc ** 2 * x ** 2))
        if argindex in (2, 3):
            return self.diff_definition(argindex)
        raise ArgumentIndexError(self, argindex)

    @mp_route(ladder=lambda x, kc, p: not negative_real(1 + p * x * x))
    def mp(cls, x, kc, p):
        args = carlson_args(x, kc)
        w = 1 + p * x * x
        return x * mpmath.elliprf(*args) + (1 - p) / 3 * x ** 3 * rj(*args, w)

    @ball_route
    def ball(x, kc, p, analytic=False):
        one, y, z = carlson_args(x, kc)
        w = 1 + p * x * x
        if analytic and (may_meet_cut(y) or may_meet_cut(z) or may_meet_cut(w)):
            return nan_ball()
        one = acb(one)
        rj = acb.elliptic_rj(one, y, z, w)
        rj = pv_union(rj, exact_real(x) and exact_real(kc) and exact_real(p), w.imag.contains(0) and not (w.real > 0))
        return x * acb.elliptic_rf(one, y, z) + (1 - p) / 3 * x ** 3 * rj
