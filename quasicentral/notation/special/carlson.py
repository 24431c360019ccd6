r"""Carlson's symmetric elliptic integrals, DLMF §19.16, and the hypergeometric R-function
R_{−a}(b; z) of 19.16.9 that contains them all.

Principal branches (19.16(i)): every argument in C \ (−∞, 0], at most one of them zero.  Cauchy
principal values on the real axis (19.2.20 for R_C with y < 0, 19.16.2 and 19.20.14 for R_J
with p < 0 and x, y, z ≥ 0) — mpmath's ``elliprc`` already gives the former, the latter is the
real part of mpmath's and flint's one-sided limits.  Derivatives: 19.18.1–19.18.2 and the
general rule of §19.18(i), ∂R_{−a}(b; z)/∂z_j = −(a b_j/c) R_{−a−1}(b + e_j; z), c = Σ b_j.
"""

from __future__ import annotations

import mpmath
import sympy as sp
from flint import acb
from sympy.core.function import ArgumentIndexError

from quasicentral.notation.special.base import (
    DLMFFunction, rd, rj, ball_route, exact_real, is_real, may_meet_cut, mp_route, nan_ball, negative_real, pv_union,
    real,
)


def any_cut(*args) -> bool:
    return any(may_meet_cut(a) for a in args)


def r_derivative(a, b, z, j):
    """∂R_{−a}(b; z)/∂z_j = −(a b_j / c) R_{−a−1}(b + e_j; z) (DLMF §19.18(i))."""
    b = list(b)
    c = sp.Add(*b)
    factor = -a * b[j] / c
    b[j] = b[j] + 1
    return factor * CarlsonR(a + 1, sp.Tuple(*b), sp.Tuple(*z))


class CarlsonRF(DLMFFunction):
    r"""R_F(x, y, z) = ½ ∫₀^∞ dt / √((t + x)(t + y)(t + z)), DLMF 19.16.1.

    Symmetric, homogeneous of degree −½; R_F(x, x, x) = x^{−1/2}.  ∂R_F/∂z = −R_D(x, y, z)/6
    (19.18.1) and its permutations.  mpmath ``elliprf``, flint ``elliptic_rf``.

    >>> import mpmath
    >>> with mpmath.workdps(30):   # Carlson (1995): R_F(0, 1, 2) = ϖ/2, half the lemniscate constant
    ...     print(mpmath.nstr(CarlsonRF.mp(0, 1, 2), 25))
    ...     f = lambda s: mpmath.exp(s)/mpmath.sqrt((mpmath.exp(s) + 1)*(mpmath.exp(s) + 2)*(mpmath.exp(s) + 3))
    ...     print(mpmath.almosteq(CarlsonRF.mp(1, 2, 3), mpmath.quad(f, [-mpmath.inf, 0, mpmath.inf])/2, 1e-27))
    1.31102877714605990523242
    True
    """

    nargs = 3
    latex_name = "R_{F}"

    def fdiff(self, argindex=1):
        x, y, z = self.args
        if argindex == 1:
            return -CarlsonRD(y, z, x) / 6
        if argindex == 2:
            return -CarlsonRD(z, x, y) / 6
        if argindex == 3:
            return -CarlsonRD(x, y, z) / 6
        raise ArgumentIndexError(self, argindex)

    @mp_route()
    def mp(cls, x, y, z):
        return mpmath.elliprf(x, y, z)

    @ball_route
    def ball(x, y, z, analytic=False):
        if analytic and any_cut(x, y, z):
            return nan_ball()
        return acb.elliptic_rf(x, y, z)


class CarlsonRD(DLMFFunction):
    r"""R_D(x, y, z) = R_J(x, y, z, z) = (3/2) ∫₀^∞ dt / ((t + z) √((t + x)(t + y)(t + z))),
    DLMF 19.16.5; symmetric in x and y only.

    Derivatives by the general rule: ∂R_D/∂x = −(3/10) R_{−5/2}(3/2, 1/2, 3/2; x, y, z), …
    mpmath ``elliprd``, flint ``elliptic_rd``.

    >>> import mpmath
    >>> with mpmath.workdps(30):   # Carlson (1995): R_D(0, 2, 1)/3 = 0.5990701173677961037…; R_D(x, y, z) = R_J(x, y, z, z)
    ...     print(mpmath.nstr(CarlsonRD.mp(0, 2, 1)/3, 20))
    ...     print(mpmath.almosteq(CarlsonRD.mp(2, 3, 4), mpmath.elliprj(2, 3, 4, 4), 1e-28))
    0.59907011736779610372
    True
    """

    nargs = 3
    latex_name = "R_{D}"

    def fdiff(self, argindex=1):
        if argindex not in (1, 2, 3):
            raise ArgumentIndexError(self, argindex)
        half = sp.Rational(1, 2)
        return r_derivative(sp.Rational(3, 2), (half, half, 3 * half), self.args, argindex - 1)

    @mp_route()
    def mp(cls, x, y, z):
        return rd(x, y, z)

    @ball_route
    def ball(x, y, z, analytic=False):
        if analytic and any_cut(x, y, z):
            return nan_ball()
        return acb.elliptic_rd(x, y, z)


class CarlsonRJ(DLMFFunction):
    r"""R_J(x, y, z, p) = (3/2) ∫₀^∞ dt / ((t + p) √((t + x)(t + y)(t + z))), DLMF 19.16.2.

    For real x, y, z ≥ 0 and p < 0 it is a **Cauchy principal value** (19.16.2, 19.20.14): the
    real part of mpmath's ``elliprj`` and flint's ``elliptic_rj``, which return a one-sided
    limit there.  Derivatives by the general rule (§19.18(i)).

    >>> import mpmath
    >>> with mpmath.workdps(30):   # Carlson (1995): R_J(0, 1, 2, 3), and the principal value R_J(2, 3, 4, −1/2)
    ...     print(mpmath.nstr(CarlsonRJ.mp(0, 1, 2, 3), 13), mpmath.nstr(CarlsonRJ.mp(2, 3, 4, -0.5), 13))
    0.7768862377858 0.2472381970305
    """

    nargs = 4
    latex_name = "R_{J}"

    def fdiff(self, argindex=1):
        if argindex not in (1, 2, 3, 4):
            raise ArgumentIndexError(self, argindex)
        half = sp.Rational(1, 2)
        return r_derivative(3 * half, (half, half, half, sp.S.One), self.args, argindex - 1)

    # mpmath's principal value for p < 0 is slow (seconds at 30 digits for Boost's arguments):
    # one rung only there
    @mp_route(ladder=lambda x, y, z, p: not negative_real(p))
    def mp(cls, x, y, z, p):
        return rj(x, y, z, p)

    @ball_route
    def ball(x, y, z, p, analytic=False):
        if analytic and any_cut(x, y, z, p):
            return nan_ball()
        value = acb.elliptic_rj(x, y, z, p)
        pv = p.imag.contains(0) and not (p.real > 0)
        return pv_union(value, all(exact_real(a) for a in (x, y, z, p)), pv)


class CarlsonRC(DLMFFunction):
    r"""R_C(x, y) = R_F(x, y, y) = ½ ∫₀^∞ dt / ((t + y) √(t + x)), DLMF 19.2.17.

    For y < 0 it is the **Cauchy principal value** R_C(x, y) = (x/(x − y))^{1/2} R_C(x − y, −y)
    (19.2.20), as mpmath's ``elliprc`` computes it; flint's ``elliptic_rc`` returns a one-sided
    limit there, so the ball route uses 19.2.20.  ∂/∂x = −R_D(y, y, x)/6, ∂/∂y = −R_D(x, y, y)/3
    (19.18.1 through R_F(x, y, y)).

    >>> import mpmath
    >>> with mpmath.workdps(30):   # Carlson (1995): R_C(9/4, 2) = ln 2, R_C(1/4, −2) = (ln 2)/3
    ...     print(mpmath.almosteq(CarlsonRC.mp(2.25, 2), mpmath.log(2), 1e-28),
    ...           mpmath.almosteq(CarlsonRC.mp(0.25, -2), mpmath.log(2)/3, 1e-28))
    True True
    """

    nargs = 2
    latex_name = "R_{C}"

    def fdiff(self, argindex=1):
        x, y = self.args
        if argindex == 1:
            return -CarlsonRD(y, y, x) / 6
        if argindex == 2:
            return -CarlsonRD(x, y, y) / 3
        raise ArgumentIndexError(self, argindex)

    @mp_route()
    def mp(cls, x, y):
        return mpmath.elliprc(x, y)

    @ball_route
    def ball(x, y, analytic=False):
        if analytic and any_cut(x, y):
            return nan_ball()
        if y.imag.contains(0) and not (y.real > 0):
            pv = (x / (x - y)).sqrt() * acb.elliptic_rc(x - y, -y)
            if exact_real(y):
                return pv
            value = acb.elliptic_rc(x, y)
            return value.union(pv) if value.is_finite() and pv.is_finite() else acb("nan")
        return acb.elliptic_rc(x, y)


class CarlsonRG(DLMFFunction):
    r"""R_G(x, y, z) = (1/(4π)) ∫₀^{2π} ∫₀^π (x sin²θ cos²φ + y sin²θ sin²φ + z cos²θ)^{1/2}
    sin θ dθ dφ, DLMF 19.16.3; symmetric, homogeneous of degree ½.

    ∂R_G/∂z = R_F(x, y, z)/4 − z R_D(x, y, z)/12 (19.18.2) and permutations.
    mpmath ``elliprg``, flint ``elliptic_rg``.

    >>> import mpmath
    >>> with mpmath.workdps(30):   # Carlson (1995): R_G(0, 16, 16) = π; E(k) = 2R_G(0, k′², 1) (19.25.1)
    ...     print(mpmath.almosteq(CarlsonRG.mp(0, 16, 16), mpmath.pi, 1e-28),
    ...           mpmath.almosteq(2*CarlsonRG.mp(0, 0.75, 1), mpmath.ellipe(0.25), 1e-28))
    True True
    """

    nargs = 3
    latex_name = "R_{G}"

    def fdiff(self, argindex=1):
        x, y, z = self.args
        if argindex == 1:
            return CarlsonRF(x, y, z) / 4 - x * CarlsonRD(y, z, x) / 12
        if argindex == 2:
            return CarlsonRF(x, y, z) / 4 - y * CarlsonRD(z, x, y) / 12
        if argindex == 3:
            return CarlsonRF(x, y, z) / 4 - z * CarlsonRD(x, y, z) / 12
        raise ArgumentIndexError(self, argindex)

    @mp_route()
    def mp(cls, x, y, z):
        return mpmath.elliprg(x, y, z)

    @ball_route
    def ball(x, y, z, analytic=False):
        if analytic and any_cut(x, y, z):
            return nan_ball()
        return acb.elliptic_rg(x, y, z)


class CarlsonR(DLMFFunction):
    r"""Carlson's hypergeometric R-function, DLMF 19.16.9:

    R_{−a}(b; z) = (1/B(a, a′)) ∫₀^∞ t^{a′−1} ∏_j (t + z_j)^{−b_j} dt,   a′ = Σ b_j − a,

    written ``CarlsonR(a, Tuple(b_1, …, b_n), Tuple(z_1, …, z_n))`` (note: the first argument
    is a, printed R_{−a}).  Valid for Re b_j > 0, Re a > 0, Re a′ > 0, z_j ∈ C \ (−∞, 0];
    R_F = R_{−1/2}(½, ½, ½; x, y, z), R_D = R_{−3/2}(½, ½, 3/2; …), R_J = R_{−3/2}(½, ½, ½, 1; …),
    R_C = R_{−1/2}(½, 1; x, y), R_G = R_{1/2}(½, ½, ½; …) (19.16.14–19.16.20 area).

    mpmath route: n = 1: z^{−a}; n = 2: z₂^{−a} ₂F₁(a, b₁; b₁ + b₂; 1 − z₁/z₂) (§19.16(ii), for
    z₁, z₂ on one side of the cut); otherwise the integral by tanh–sinh quadrature, with Re a ≤ 0
    first raised by the contiguous relation c R_{−a}(b; z) = Σ b_j z_j R_{−a−1}(b + e_j; z).
    Re a′ ≤ 0 is not implemented (ValueError).  No ball route (``ball = None``).
    ∂/∂z_j by the rule of §19.18(i); no derivative in a or b.

    >>> import mpmath, sympy as sp
    >>> h = sp.Rational(1, 2)
    >>> with mpmath.workdps(30):   # R_F and R_G as R-functions
    ...     print(mpmath.almosteq(CarlsonR.mp(h, (h, h, h), (1, 2, 3)), mpmath.elliprf(1, 2, 3), 1e-27))
    ...     print(mpmath.almosteq(CarlsonR.mp(-h, (h, h, h), (1, 2, 3)), mpmath.elliprg(1, 2, 3), 1e-27))
    True
    True
    >>> sp.latex(CarlsonR(h, sp.Tuple(h, h, h), sp.Tuple(*sp.symbols("x y z"))))
    'R_{- \\frac{1}{2}}\\left(\\frac{1}{2}, \\frac{1}{2}, \\frac{1}{2}; x, y, z\\right)'
    """

    nargs = 3
    ball = None

    @classmethod
    def eval(cls, a, b, z):  # noqa: D102 - validation only
        if not isinstance(b, sp.Tuple) or not isinstance(z, sp.Tuple) or len(b) != len(z) or not len(b):
            raise ValueError("CarlsonR(a, b, z): b and z are Tuples of one length")

    def _latex(self, printer, exp=None):
        a, b, z = self.args
        power = "^{%s}" % exp if exp is not None else ""
        return r"R_{%s}%s\left(%s; %s\right)" % (
            printer._print(-a), power, ", ".join(printer._print(x) for x in b),
            ", ".join(printer._print(x) for x in z))

    def fdiff(self, argindex=1):
        raise ArgumentIndexError(self, argindex)

    def _eval_derivative(self, s):
        a, b, z = self.args
        if a.has(s) or b.has(s):
            return None
        return sp.Add(*[r_derivative(a, b, z, j) * zj.diff(s) for j, zj in enumerate(z) if zj.has(s)])

    @mp_route(ladder=False)  # the quadrature checks its own error
    def mp(cls, a, b, z):
        b = [mpmath.mpmathify(x) for x in b]
        z = [mpmath.mpmathify(x) for x in z]
        if len(b) != len(z):
            raise ValueError("b and z differ in length")
        return r_function(a, b, z)


def r_function(a, b, z):
    """R_{−a}(b; z) at the working precision (see ``CarlsonR``)."""
    c = mpmath.fsum(b)
    ap = c - a
    if len(b) == 1:
        return z[0] ** (-a)
    if len(b) == 2 and not (mpmath.re(ap) > 0 and mpmath.re(a) > 0):
        return z[1] ** (-a) * mpmath.hyp2f1(a, b[0], c, 1 - z[0] / z[1])
    if not mpmath.re(ap) > 0:
        raise ValueError("R_{-a}(b; z) with Re a' <= 0 is not implemented")
    if not mpmath.re(a) > 0:
        # c R_{-a}(b; z) = sum_j b_j z_j R_{-a-1}(b + e_j; z): raises a by one, keeps a'
        total = 0
        for j in range(len(b)):
            bj = list(b)
            bj[j] += 1
            total += b[j] * z[j] * r_function(a + 1, bj, z)
        return total / c
    # t = e^s: the integrand decays exponentially at both ends (like e^{a's} and e^{-as}), which
    # tanh-sinh handles to full precision (the algebraic tail in t costs it ~10 digits)
    centre = mpmath.log(max([abs(x) for x in z] + [mpmath.mpf(1)]))

    def integrand(s):
        t = mpmath.exp(s)
        value = t ** ap
        for bj, zj in zip(b, z):
            value *= (t + zj) ** (-bj)
        return value

    with mpmath.workprec(mpmath.mp.prec + 30):
        nodes = [-mpmath.inf, centre - 3, centre, centre + 3, mpmath.inf]
        return mpmath.quad(integrand, nodes) / mpmath.beta(a, ap)
