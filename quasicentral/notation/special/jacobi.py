"""Jacobian elliptic functions, DLMF chapter 22, with the **modulus** k (mpmath's ``ellipfun``
takes m = k²): the twelve pq(z, k) (22.2), the amplitude am (22.16.1), ℰ(x, k) (22.16.14),
Jacobi's Z(x|k) (22.16.32) and the twelve inverses arcpq(x, k) (22.15).

The twelve are meromorphic in z and in k² (no branch cut): mpmath's ``ellipfun`` gives them,
the ball route the theta quotients of DLMF 22.2.4–22.2.9 through flint's ``modular_theta``
with τ = iK′/K (any τ with λ(τ) = k² gives the same quotient, so flint's branch choices for K
and K′ on their cuts cannot change the value, only widen the ball).  ℰ and Z are the
logarithmic derivative of θ₄ (22.16.32 with Jacobi's Θ): meromorphic in x as well.
"""

from __future__ import annotations

from types import MappingProxyType

import mpmath
import sympy as sp
from flint import acb
from sympy.core.function import ArgumentIndexError

from quasicentral.notation.special.base import (
    DLMFFunction, asin_cut, atan_cut, ball_parameters, ball_precision, is_real, lost_bits, may_meet,
    may_meet_cut, mp_route, nan_ball, parameters, real,
)
from quasicentral.notation.special.legendre import (
    EllipticE, EllipticF, EllipticK, incomplete_cut, with_delta_guard,
)
from quasicentral.notation.special.theta import nome_tau_ball


# --- the theta quotients (balls) ---------------------------------------------------------

def letters_ball(z, k):
    """{letter: f} with pq = f_p/f_q: f_s = θ₃θ₁(ζ)/θ₂, f_c = θ₄θ₂(ζ)/θ₂, f_d = θ₄θ₃(ζ)/θ₃,
    f_n = θ₄(ζ) (the nulls at 0), ζ = πz/(2K) — DLMF 22.2.4–22.2.6; also K."""
    m, mc = ball_parameters(k)
    if m.is_exact() and m.is_zero():
        return {"s": z.sin(), "c": z.cos(), "d": acb(1), "n": acb(1)}, acb.pi() / 2
    K, tau = nome_tau_ball(m, mc)
    w = z / (2 * K)  # flint's argument: ζ/π
    t1, t2, t3, t4 = acb.modular_theta(w, tau)
    _, n2, n3, n4 = acb.modular_theta(acb(0), tau)
    return {"s": n3 * t1 / n2, "c": n4 * t2 / n2, "d": n4 * t3 / n3, "n": t4}, K


def zeta_ball(x, k):
    """Jacobi's Z(x|k) = (π/(2K)) θ₄′(ζ)/θ₄(ζ), ζ = πx/(2K) (22.16.32 with Θ(x) = θ₄(ζ)), and K."""
    m, mc = ball_parameters(k)
    if m.is_exact() and m.is_zero():
        return acb(0), acb.pi() / 2
    K, tau = nome_tau_ball(m, mc)
    w = x / (2 * K)
    value = acb.modular_theta(w, tau)[3]
    slope = acb.modular_theta(w, tau, 1)[3]  # d/dw θ₄(πw)
    return slope / (2 * K * value), K


def zeta_mp(x, k):
    """Z(x|k) through mpmath's ``jtheta`` (θ₄ and its derivative), as ``zeta_ball``."""
    m, mc = parameters(k)
    if m == 0:
        return mpmath.mpf(0)
    if m == 1:
        return mpmath.tanh(x)
    with mpmath.workprec(mpmath.mp.prec + lost_bits(mc)):
        K = mpmath.ellipk(m)
        q = mpmath.qfrom(m=m)
    zeta = mpmath.pi * x / (2 * K)
    return mpmath.pi / (2 * K) * mpmath.jtheta(4, zeta, q, 1) / mpmath.jtheta(4, zeta, q)


def am_derivative_k(x, k):
    """∂am(x, k)/∂k = (k² sn cn − dn (ℰ(x, k) − k′² x))/(k k′²) (from ∂F/∂k, 19.4 area)."""
    sn, cn, dn = JacobiSN(x, k), JacobiCN(x, k), JacobiDN(x, k)
    kc2 = 1 - k ** 2
    return (k ** 2 * sn * cn - dn * (JacobiEpsilon(x, k) - kc2 * x)) / (k * kc2)


def letter(l, z, k):
    return {"s": JacobiSN, "c": JacobiCN, "d": JacobiDN}[l](z, k) if l != "n" else sp.S.One


def letter_dk(l, z, k):
    """∂/∂k of sn, cn, dn, 1 through ∂am/∂k (sn = sin am, cn = cos am, dn² = 1 − k² sn²)."""
    a = am_derivative_k(z, k)
    sn, cn, dn = JacobiSN(z, k), JacobiCN(z, k), JacobiDN(z, k)
    return {"s": cn * a, "c": -sn * a, "d": -(k * sn ** 2 + k ** 2 * sn * cn * a) / dn, "n": sp.S.Zero}[l]


#: d pq/dz, DLMF Table 22.13.1, as (coefficient in k, the two factors)
DERIVATIVES = MappingProxyType({
    "sn": (1, "cn", "dn"), "cn": (-1, "sn", "dn"), "dn": ("-k2", "sn", "cn"),
    "cd": ("-kc2", "sd", "nd"), "sd": (1, "cd", "nd"), "nd": ("k2", "sd", "cd"),
    "dc": ("kc2", "sc", "nc"), "nc": (1, "sc", "dc"), "sc": (1, "dc", "nc"),
    "ns": (-1, "ds", "cs"), "ds": (-1, "cs", "ns"), "cs": (-1, "ns", "ds"),
})

#: pq(0, k) where it is finite (22.5.1 area)
AT_ZERO = MappingProxyType({"sn": 0, "cn": 1, "dn": 1, "sc": 0, "sd": 0, "cd": 1, "dc": 1, "nc": 1, "nd": 1})

#: an independent cross-check per function for its doctest (mpmath at 30 digits)
CHECKS = MappingProxyType({
    "sn": ("sn(K, k) = 1 (22.5.1) and sn² + cn² = 1 (22.6.1)",
           "print(mpmath.almosteq(JacobiSN.mp(mpmath.ellipk(k**2), k), 1, 1e-27),\n"
           "    ...       mpmath.almosteq(JacobiSN.mp(z, k)**2 + JacobiCN.mp(z, k)**2, 1, 1e-28))",
           "True True"),
    "cn": ("cn(K, k) = 0 (22.5.1) and the theta quotient 22.2.5",
           "q = mpmath.qfrom(m=k**2); zeta = mpmath.pi*z/(2*mpmath.ellipk(k**2))\n"
           "    ...     t = lambda j, u: mpmath.jtheta(j, u, q)\n"
           "    ...     print(mpmath.almosteq(JacobiCN.mp(z, k), t(4, 0)*t(2, zeta)/(t(2, 0)*t(4, zeta)), 1e-28))",
           "True"),
    "dn": ("dn² + k² sn² = 1 (22.6.1)",
           "print(mpmath.almosteq(JacobiDN.mp(z, k)**2 + k**2*JacobiSN.mp(z, k)**2, 1, 1e-28))",
           "True"),
})


def glaisher_check(name):
    p, q = name
    num = "1" if p == "n" else "Jacobi%sN.mp(z, k)" % p.upper()
    den = "1" if q == "n" else "Jacobi%sN.mp(z, k)" % q.upper()
    return ("Glaisher's quotient 22.2.10, %s = %s/%s" % (name, p + "n" if p != "n" else "1", q + "n" if q != "n" else "1"),
            "print(mpmath.almosteq(Jacobi%s.mp(z, k), (%s)/(%s), 1e-28))" % (name.upper(), num, den),
            "True")


def jacobi_doc(name):
    check, code, result = CHECKS.get(name) or glaisher_check(name)
    c, f, g = DERIVATIVES[name]
    coefficient = {1: "", -1: "−", "k2": "k² ", "-k2": "−k² ", "kc2": "k′² ", "-kc2": "−k′² "}[c]
    return r"""Jacobi's elliptic function %(n)s(z, k), DLMF 22.2 (22.2.4–22.2.10), **modulus** k.

    Meromorphic in z and in k²; mpmath ``ellipfun('%(n)s', z, m=k²)``; balls: theta quotients
    through flint's ``modular_theta`` (z/(2K), τ = iK′/K).  d%(n)s/dz = %(c)s%(f)s·%(g)s
    (Table 22.13.1); ∂/∂k through ∂am/∂k (not in DLMF: from ∂F/∂k, 19.4).

    >>> import mpmath
    >>> with mpmath.workdps(30):   # %(check)s
    ...     z, k = mpmath.mpf(7)/10, mpmath.mpf(4)/5
    ...     %(code)s
    %(result)s
    """ % {"n": name, "c": coefficient, "f": f, "g": g, "check": check, "code": code, "result": result}


class JacobiBase(DLMFFunction):
    """pq(z, k); the letters set by the subclass."""

    nargs = 2
    name = None

    @property
    def latex_name(self):
        return r"\operatorname{%s}" % self.name

    @classmethod
    def eval(cls, z, k):
        if z.is_zero and cls.name in AT_ZERO:
            return sp.Integer(AT_ZERO[cls.name])

    def fdiff(self, argindex=1):
        z, k = self.args
        if argindex == 1:
            c, f, g = DERIVATIVES[self.name]
            coefficient = {1: 1, -1: -1, "k2": k ** 2, "-k2": -k ** 2, "kc2": 1 - k ** 2, "-kc2": k ** 2 - 1}[c]
            return coefficient * JACOBI[f](z, k) * JACOBI[g](z, k)
        if argindex == 2:
            p, q = self.name
            num, den = letter(p, z, k), letter(q, z, k)
            return (letter_dk(p, z, k) * den - num * letter_dk(q, z, k)) / den ** 2
        raise ArgumentIndexError(self, argindex)

    @mp_route()
    def mp(cls, z, k):
        m, _ = parameters(k)
        value = mpmath.ellipfun(cls.name, z, m=m)
        return real(value) if is_real(z, k) else value

    @classmethod
    def ball_value(cls, z, k):
        letters, _ = letters_ball(z, k)
        p, q = cls.name
        return letters[p] / letters[q]


def jacobi_class(name):
    def ball(z, k, analytic=False):
        # meromorphic: a pole inside the ball gives a non-finite quotient by itself
        with ball_precision():
            value = cls.ball_value(acb(z), acb(k))
        return +value

    cls = type("Jacobi%s" % name.upper(), (JacobiBase,), {
        "name": name, "__doc__": jacobi_doc(name), "__module__": __name__, "ball": staticmethod(ball)})
    return cls


JacobiSN, JacobiCN, JacobiDN = jacobi_class("sn"), jacobi_class("cn"), jacobi_class("dn")
JacobiNS, JacobiNC, JacobiND = jacobi_class("ns"), jacobi_class("nc"), jacobi_class("nd")
JacobiSC, JacobiSD, JacobiCS = jacobi_class("sc"), jacobi_class("sd"), jacobi_class("cs")
JacobiCD, JacobiDS, JacobiDC = jacobi_class("cd"), jacobi_class("ds"), jacobi_class("dc")

JACOBI = MappingProxyType({c.name: c for c in (JacobiSN, JacobiCN, JacobiDN, JacobiNS, JacobiNC, JacobiND,
                                               JacobiSC, JacobiSD, JacobiCS, JacobiCD, JacobiDS, JacobiDC)})


class JacobiAM(DLMFFunction):
    r"""The amplitude am(x, k), DLMF 22.16.1: am(x, k) = Arcsin(sn(x, k)), continuous in real x
    (principal value for −K ≤ x ≤ K), the inverse of F(φ, k) in φ (22.16.11); **modulus** k.

    Computed as am = ζ − i Log(e^{−iζ}(cn + i sn)), ζ = πx/(2K): exact for real x and
    0 ≤ k ≤ 1 (|am − ζ| < π/2 there, 22.16.9), and for complex x, k the continuation from the
    real axis as long as |Re(am − ζ)| < π (the principal Log's cut otherwise).  am(x, 1) = gd x.
    d am/dx = dn(x, k) (22.16.2 area); ∂am/∂k from ∂F/∂k.

    >>> import mpmath
    >>> with mpmath.workdps(30):   # F(am(x, k), k) = x, for x beyond 2K too
    ...     x, k = mpmath.mpf(9), mpmath.mpf(4)/5
    ...     print(mpmath.almosteq(mpmath.ellipf(JacobiAM.mp(x, k), k**2), x, 1e-27))
    True
    """

    nargs = 2
    latex_name = r"\operatorname{am}"

    @classmethod
    def eval(cls, x, k):
        if x.is_zero:
            return sp.S.Zero
        if k.is_zero:
            return x

    def fdiff(self, argindex=1):
        x, k = self.args
        if argindex == 1:
            return JacobiDN(x, k)
        if argindex == 2:
            return am_derivative_k(x, k)
        raise ArgumentIndexError(self, argindex)

    @mp_route()
    def mp(cls, x, k):
        m, mc = parameters(k)
        with mpmath.workprec(mpmath.mp.prec + lost_bits(mc)):
            K = mpmath.ellipk(m)
        zeta = mpmath.pi * x / (2 * K) if mpmath.isfinite(K) else mpmath.mpf(0)
        sn, cn = mpmath.ellipfun("sn", x, m=m), mpmath.ellipfun("cn", x, m=m)
        value = zeta - 1j * mpmath.log(mpmath.exp(-1j * zeta) * (cn + 1j * sn))
        return real(value) if is_real(x, k) and real(m) <= 1 else value

    @staticmethod
    def ball(x, k, analytic=False):
        x, k = acb(x), acb(k)
        with ball_precision():
            m, _ = ball_parameters(k)
            if analytic and may_meet(m, 1, None):
                value = nan_ball()
            else:
                letters, K = letters_ball(x, k)
                sn, cn = letters["s"] / letters["n"], letters["c"] / letters["n"]
                zeta = acb.pi() * x / (2 * K)
                i = acb(0, 1)
                value = zeta - i * ((-i * zeta).exp() * (cn + i * sn)).log(analytic=analytic)
        return +value


class JacobiEpsilon(DLMFFunction):
    r"""ℰ(x, k) = ∫₀^x dn²(t, k) dt, DLMF 22.16.14, = E(am(x, k), k) (22.16.15 area), **modulus** k.

    Computed as Z(x|k) + (E(k)/K(k)) x (22.16.32) with Z the logarithmic derivative of θ₄:
    meromorphic in x (simple poles at the poles of dn).  dℰ/dx = dn²; ∂ℰ/∂k = dn ∂am/∂k + (ℰ − x)/k.

    >>> import mpmath
    >>> with mpmath.workdps(30):   # the integral 22.16.14 by quadrature, and E(am x, k)
    ...     x, k = mpmath.mpf(3), mpmath.mpf(4)/5
    ...     q = mpmath.quad(lambda t: mpmath.ellipfun('dn', t, m=k**2)**2, [0, 1.5, 3])
    ...     print(mpmath.almosteq(JacobiEpsilon.mp(x, k), q, 1e-27),
    ...           mpmath.almosteq(JacobiEpsilon.mp(x, k), mpmath.ellipe(JacobiAM.mp(x, k), k**2), 1e-27))
    True True
    """

    nargs = 2
    latex_name = r"\mathcal{E}"

    @classmethod
    def eval(cls, x, k):
        if x.is_zero:
            return sp.S.Zero

    def fdiff(self, argindex=1):
        x, k = self.args
        if argindex == 1:
            return JacobiDN(x, k) ** 2
        if argindex == 2:
            return JacobiDN(x, k) * am_derivative_k(x, k) + (JacobiEpsilon(x, k) - x) / k
        raise ArgumentIndexError(self, argindex)

    @mp_route()
    def mp(cls, x, k):
        m, mc = parameters(k)
        if m == 1:
            return mpmath.tanh(x)
        with mpmath.workprec(mpmath.mp.prec + lost_bits(mc)):
            ratio = mpmath.ellipe(m) / mpmath.ellipk(m)
        return zeta_mp(x, k) + ratio * x

    @staticmethod
    def ball(x, k, analytic=False):
        x, k = acb(x), acb(k)
        with ball_precision():
            z, K = zeta_ball(x, k)
            m, _ = ball_parameters(k)
            value = z + m.elliptic_e() / K * x
        return +value


class JacobiZ(DLMFFunction):
    r"""Jacobi's zeta function Z(x|k) = ℰ(x, k) − (E(k)/K(k)) x, DLMF 22.16.32, **modulus** k;
    the argument is x = F(φ, k), so Z(F(φ, k)|k) = Z(φ, k) of §19.2(iv) (``JacobiZeta``).

    Z(x|k) = (π/(2K)) θ₄′(ζ, q)/θ₄(ζ, q), ζ = πx/(2K) (Θ(x) = θ₄(ζ)): mpmath ``jtheta(4, ζ, q, 1)``,
    flint ``modular_theta(…, r=1)``.  Cut in k² ∈ [1, ∞) (from E/K).  Derivatives: of the definition.

    >>> import mpmath
    >>> from quasicentral.notation.special.legendre_derived import JacobiZeta
    >>> with mpmath.workdps(30):
    ...     phi, k = mpmath.mpf(7)/10, mpmath.mpf(4)/5
    ...     print(mpmath.almosteq(JacobiZ.mp(mpmath.ellipf(phi, k**2), k), JacobiZeta.mp(phi, k), 1e-28))
    True
    """

    nargs = 2
    latex_name = r"\mathrm{Z}"

    def _latex(self, printer, exp=None):
        x, k = (printer._print(a) for a in self.args)
        power = "^{%s}" % exp if exp is not None else ""
        return r"\mathrm{Z}%s\left(%s\middle|%s\right)" % (power, x, k)

    @classmethod
    def eval(cls, x, k):
        if x.is_zero or k.is_zero:
            return sp.S.Zero

    @classmethod
    def definition(cls, x, k):
        return JacobiEpsilon(x, k) - EllipticE(k) / EllipticK(k) * x

    def fdiff(self, argindex=1):
        if argindex not in (1, 2):
            raise ArgumentIndexError(self, argindex)
        return self.diff_definition(argindex)

    @mp_route()
    def mp(cls, x, k):
        return zeta_mp(x, k)

    @staticmethod
    def ball(x, k, analytic=False):
        x, k = acb(x), acb(k)
        with ball_precision():
            m, _ = ball_parameters(k)
            value = nan_ball() if analytic and may_meet(m, 1, None) else zeta_ball(x, k)[0]
        return +value


# --- the inverse functions, DLMF 22.15 ------------------------------------------------------

#: arcpq(x, k) = c·K(k) + s·F(φ(x), k): (c, s, φ as a function of (x, k) in sympy terms,
#: DLMF's real interval and range of the principal value, 22.15.4–22.15.11 and 22.15.12–22.15.23)
INVERSES = MappingProxyType({
    "sn": (0, 1, lambda x, k: sp.asin(x), "−1 ≤ x ≤ 1, −K ≤ arcsn ≤ K"),
    "cn": (0, 1, lambda x, k: sp.acos(x), "−1 ≤ x ≤ 1, 0 ≤ arccn ≤ 2K"),
    "dn": (0, 1, lambda x, k: sp.asin(sp.sqrt(1 - x ** 2) / k), "k′ ≤ x ≤ 1, 0 ≤ arcdn ≤ K"),
    "cd": (1, -1, lambda x, k: sp.asin(x), "−1 ≤ x ≤ 1, 0 ≤ arccd ≤ 2K"),
    "sd": (0, 1, lambda x, k: sp.asin(x / sp.sqrt(1 + k ** 2 * x ** 2)), "−1/k′ ≤ x ≤ 1/k′, −K ≤ arcsd ≤ K"),
    "nd": (0, 1, lambda x, k: sp.asin(sp.sqrt(1 - 1 / x ** 2) / k), "1 ≤ x ≤ 1/k′, 0 ≤ arcnd ≤ K"),
    "dc": (1, -1, lambda x, k: sp.asin(1 / x), "1 ≤ |x|, 0 ≤ arcdc ≤ 2K"),
    "nc": (0, 1, lambda x, k: sp.acos(1 / x), "1 ≤ |x|, 0 ≤ arcnc ≤ 2K"),
    "sc": (0, 1, lambda x, k: sp.atan(x), "x real, −K < arcsc < K"),
    "ns": (0, 1, lambda x, k: sp.asin(1 / x), "1 ≤ |x|, −K ≤ arcns ≤ K"),
    "ds": (0, 1, lambda x, k: sp.asin(1 / (x * sp.sqrt(1 + k ** 2 / x ** 2))), "k′ ≤ |x|, −K ≤ arcds ≤ K"),
    "cs": (0, 1, lambda x, k: sp.pi / 2 - sp.atan(x), "x real, 0 < arccs < 2K"),
})


def amplitude_mp(name, x, k):
    m, _ = parameters(k)
    f = {"sn": lambda: mpmath.asin(x), "cn": lambda: mpmath.acos(x),
         "dn": lambda: mpmath.asin(mpmath.sqrt(1 - x * x) / k), "cd": lambda: mpmath.asin(x),
         "sd": lambda: mpmath.asin(x / mpmath.sqrt(1 + m * x * x)),
         "nd": lambda: mpmath.asin(mpmath.sqrt(1 - 1 / (x * x)) / k), "dc": lambda: mpmath.asin(1 / x),
         "nc": lambda: mpmath.acos(1 / x), "sc": lambda: mpmath.atan(x), "ns": lambda: mpmath.asin(1 / x),
         "ds": lambda: mpmath.asin(1 / (x * mpmath.sqrt(1 + m / (x * x)))),
         "cs": lambda: mpmath.pi / 2 - mpmath.atan(x)}
    return f[name]()


def amplitude_ball(name, x, k, analytic):
    """φ(x) as a ball, or None where an analytic ball may touch a cut of the inverse
    trigonometric function or of a square root on the way."""
    m = k * k
    one = acb(1)
    if name in ("sn", "cd"):
        w, trig = x, "asin"
    elif name == "cn":
        w, trig = x, "acos"
    elif name in ("dn", "nd"):
        u = one - (x * x if name == "dn" else one / (x * x))
        if analytic and may_meet_cut(u):
            return None
        w, trig = u.sqrt() / k, "asin"
    elif name == "sd":
        u = one + m * x * x
        if analytic and may_meet_cut(u):
            return None
        w, trig = x / u.sqrt(), "asin"
    elif name in ("dc", "ns"):
        w, trig = one / x, "asin"
    elif name == "nc":
        w, trig = one / x, "acos"
    elif name == "ds":
        u = one + m / (x * x)
        if analytic and may_meet_cut(u):
            return None
        w, trig = one / (x * u.sqrt()), "asin"
    else:  # sc, cs
        w, trig = x, "atan"
    if analytic and (atan_cut(w) if trig == "atan" else asin_cut(w)):
        return None
    phi = getattr(w, trig)()
    return acb.pi() / 2 - phi if name == "cs" else phi


class JacobiInverseBase(DLMFFunction):
    """arcpq(x, k); the letters set by the subclass."""

    nargs = 2
    name = None

    @property
    def latex_name(self):
        return r"\operatorname{arc%s}" % self.name

    @classmethod
    def definition(cls, x, k):
        c, s, phi, _ = INVERSES[cls.name]
        return c * EllipticK(k) + s * EllipticF(phi(x, k), k)

    def fdiff(self, argindex=1):
        if argindex not in (1, 2):
            raise ArgumentIndexError(self, argindex)
        return self.diff_definition(argindex)

    @mp_route()
    def mp(cls, x, k):
        c, s, _, _ = INVERSES[cls.name]
        m, mc = parameters(k)
        phi = amplitude_mp(cls.name, x, k)
        value = s * with_delta_guard(phi, mc, lambda: mpmath.ellipf(phi, m))
        if c:
            with mpmath.workprec(mpmath.mp.prec + lost_bits(mc)):
                value += c * mpmath.ellipk(m)
        return value

    @classmethod
    def ball_value(cls, x, k, analytic):
        c, s, _, _ = INVERSES[cls.name]
        m = k * k
        phi = amplitude_ball(cls.name, x, k, analytic)
        if phi is None or (analytic and incomplete_cut(phi, m)) or (analytic and c and may_meet(m, 1, None)):
            return nan_ball()
        value = s * acb.elliptic_f(phi, m)
        return value + c * m.elliptic_k() if c else value


def inverse_doc(name):
    c, s, phi, interval = INVERSES[name]
    formula = {"sn": "F(arcsin x, k)", "cn": "F(arccos x, k)", "dn": "F(arcsin(√(1 − x²)/k), k)",
               "cd": "K − F(arcsin x, k)", "sd": "F(arcsin(x/√(1 + k²x²)), k)",
               "nd": "arcdn(1/x, k)", "dc": "K − F(arcsin(1/x), k)", "nc": "F(arccos(1/x), k)",
               "sc": "F(arctan x, k)", "ns": "F(arcsin(1/x), k)", "ds": "arcsd(1/x, k)",
               "cs": "F(π/2 − arctan x, k)"}[name]
    x = {"dn": "mpmath.mpf(9)/10", "nd": "mpmath.mpf(11)/10", "dc": "mpmath.mpf(-3)", "nc": "mpmath.mpf(-3)",
         "ns": "mpmath.mpf(3)", "ds": "mpmath.mpf(2)", "cs": "mpmath.mpf(-2)", "sc": "mpmath.mpf(2)",
         "sd": "mpmath.mpf(3)/2"}.get(name, "mpmath.mpf(-1)/3")
    return r"""The inverse of %(n)s(·, k), DLMF 22.15: arc%(n)s(x, k) = %(f)s, **modulus** k.

    DLMF's principal value on the real line: %(i)s (22.15(i)); for complex x the principal
    branches of the inverse trigonometric functions (§4.23(ii)) and of F (cut where
    1 − k² sin²φ ≤ 0).  Derivatives: of the definition (d/dx is DLMF's integrand, 22.15(ii)).

    >>> import mpmath
    >>> with mpmath.workdps(30):   # %(n)s(arc%(n)s(x, k), k) = x
    ...     x, k = %(x)s, mpmath.mpf(3)/5
    ...     print(mpmath.almosteq(Jacobi%(N)s.mp(JacobiArc%(N)s.mp(x, k), k), x, 1e-27))
    True
    """ % {"n": name, "N": name.upper(), "f": formula, "i": interval, "x": x}


def inverse_class(name):
    def ball(x, k, analytic=False):
        with ball_precision():
            value = cls.ball_value(acb(x), acb(k), analytic)
        return +value

    cls = type("JacobiArc%s" % name.upper(), (JacobiInverseBase,), {
        "name": name, "__doc__": inverse_doc(name), "__module__": __name__, "ball": staticmethod(ball)})
    return cls


JacobiArcSN, JacobiArcCN, JacobiArcDN = inverse_class("sn"), inverse_class("cn"), inverse_class("dn")
JacobiArcNS, JacobiArcNC, JacobiArcND = inverse_class("ns"), inverse_class("nc"), inverse_class("nd")
JacobiArcSC, JacobiArcSD, JacobiArcCS = inverse_class("sc"), inverse_class("sd"), inverse_class("cs")
JacobiArcCD, JacobiArcDS, JacobiArcDC = inverse_class("cd"), inverse_class("ds"), inverse_class("dc")
