"""Arithmetic contexts for the period's algorithms, in the manner of mpmath's ``mp``/``fp``/``iv``:
each method of :mod:`quasicentral.models.period` is written once and runs on

* :data:`DOUBLE` — numpy arrays of doubles (any shape), scipy for K, quadrature and the ODE;
* :data:`MP` — mpmath numbers at the working precision (set by the caller's ``workdps``);
* :data:`BALL` — python-flint balls at ``flint.ctx.prec`` bits (the AGM and K only).

A context supplies ``read`` (text or numbers into the context, finite), ``require`` (a domain
check), sin/cos/sqrt/atan2/pi, ``agm1(c)`` = AGM(1, c), ``kc(c)`` = K(m) with m = 1 − c² given
by its complement (the parameter m, not the modulus k), ``kernel`` and ``integrate`` (the
quadrature), ``first_passage`` (the ODE), ``coefficients`` (of the series (66)).
"""

from __future__ import annotations

import math

import mpmath
import numpy as np

from quasicentral.notation import numbers

LN4 = math.log(4.0)


class DomainError(ValueError):
    """An input outside the physical domain."""


class _Double:
    """numpy arrays of doubles (any shape); scipy for K, quadrature and the ODE."""

    name = "double"

    @staticmethod
    def read(x, what):
        a = np.asarray(x, dtype=float)
        if not np.all(np.isfinite(a)):
            raise DomainError(f"{what} must be finite")
        return a

    @staticmethod
    def require(cond, message):
        if not np.all(cond):
            raise DomainError(message)

    sin, cos, sqrt, atan2 = staticmethod(np.sin), staticmethod(np.cos), staticmethod(np.sqrt), staticmethod(np.arctan2)

    @staticmethod
    def pi():
        return math.pi

    @staticmethod
    def agm1(c):
        """AGM(1, c), vectorized; converges quadratically (≤ 12 steps for c ≥ 1e-300)."""
        a = np.ones_like(c)
        b = np.array(c, dtype=float)
        for _ in range(40):
            if np.all(np.abs(a - b) <= 1e-15 * a):
                break
            a, b = 0.5 * (a + b), np.sqrt(a * b)
        return 0.5 * (a + b)

    @staticmethod
    def kc(c):
        """K(1 − c²) from the complement: ``scipy.special.ellipkm1(p)``, p = c² given exactly
        (1.3 ulp); for c < 1e-8 the asymptote K = ln(4/c) + O(c² ln c), exact to rounding there
        and free of the underflow of c² (δ down to 1e-300)."""
        from scipy.special import ellipkm1

        c = np.asarray(c, dtype=float)
        tiny = c < 1e-8
        if not tiny.any():
            return ellipkm1(c * c)
        with np.errstate(divide="ignore"):
            return np.where(tiny, LN4 - np.log(np.where(tiny, c, 1.0)), ellipkm1(np.where(tiny, 1.0, c * c)))

    @staticmethod
    def elementwise(f, *arrays):
        return np.vectorize(f, otypes=[float])(*arrays)

    @staticmethod
    def kernel(c, w):
        """1/√(1 + (c sinh w)²) without overflow (c as small as 1e-300, any w ≥ 0): beyond
        w = 20, c sinh w = e^{w + ln(c/2)} to rounding, and 1/√(1 + x²) = 1/x beyond x = e²⁰."""
        if w > 20:
            lx = w + math.log(c) - math.log(2)
            if lx > 20:
                return math.exp(-lx)
            x = math.exp(lx)
        else:
            x = c * math.sinh(w)
        return 1 / math.sqrt(1 + x * x)

    @staticmethod
    def integrate(f, points):
        from scipy.integrate import quad

        return sum(quad(f, a, b, epsabs=0, epsrel=2e-14, limit=200)[0] for a, b in zip(points, points[1:]))

    @staticmethod
    def first_passage(sign, x0, target, guess, rtol=1e-13):
        """The first time at which x(t) of ẍ = sign·sin x, x(0) = x0, ẋ(0) = 0, reaches ``target``
        (DOP853 with an event; tolerances relative to x0)."""
        from scipy.integrate import solve_ivp

        def reach(t, y):
            return y[0] - target

        reach.terminal, reach.direction = True, (1.0 if target > x0 else -1.0)
        atol = rtol * min(1.0, x0) * 1e-2
        sol = solve_ivp(lambda t, y: (y[1], sign * math.sin(y[0])), (0, 2 * guess + 4), (x0, 0.0), method="DOP853",
                        rtol=rtol, atol=atol, events=reach)
        if not sol.t_events[0].size:
            raise ArithmeticError("the integration did not reach the lowest point")
        return sol.t_events[0][0]

    @staticmethod
    def coefficients(n_terms):
        n = np.arange(1, n_terms, dtype=float)
        return np.concatenate(([1.0], np.cumprod(((2 * n - 1) / (2 * n)) ** 2)))


class _Mp(_Double):
    """mpmath numbers at the working precision (scalars)."""

    name = "mpmath"

    @staticmethod
    def read(x, what):
        try:
            return numbers.to_mpf(x, what)
        except numbers.NumberError as exc:
            raise DomainError(str(exc)) from None

    @staticmethod
    def require(cond, message):
        if not cond:
            raise DomainError(message)

    sin, cos, sqrt, atan2 = (staticmethod(mpmath.sin), staticmethod(mpmath.cos), staticmethod(mpmath.sqrt),
                             staticmethod(mpmath.atan2))

    @staticmethod
    def pi():
        return +mpmath.pi

    @staticmethod
    def agm1(c):
        return mpmath.agm(1, c)

    @staticmethod
    def kc(c):
        p = c * c  # m = 1 − p needs the digits of p too: raise the precision by p's decimal exponent
        with mpmath.workdps(mpmath.mp.dps + max(0, -int(mpmath.floor(mpmath.log10(p))))):
            return mpmath.ellipk(1 - p)

    @staticmethod
    def elementwise(f, *args):
        return f(*args)

    @staticmethod
    def kernel(c, w):
        return 1 / mpmath.sqrt(1 + (c * mpmath.sinh(w)) ** 2)

    @staticmethod
    def integrate(f, points):
        return mpmath.quad(f, points)

    @staticmethod
    def first_passage(sign, x0, target, guess, rtol=None):
        f = mpmath.odefun(lambda t, y: [y[1], sign * mpmath.sin(y[0])], 0, [x0, mpmath.mpf(0)])
        return mpmath.findroot(lambda t: f(t)[0] - target, guess)

    @staticmethod
    def coefficients(n_terms):
        out, cn = [], mpmath.mpf(1)
        for n in range(n_terms):
            if n:
                cn *= (mpmath.mpf(2 * n - 1) / (2 * n)) ** 2
            out.append(cn)
        return out


class _Ball:
    """python-flint balls at ``flint.ctx.prec`` bits (AGM and K only: the routes with rigorous
    enclosures); the domain is checked in mpmath before."""

    name = "ball"

    @staticmethod
    def read(x, what):
        import flint

        return flint.arb(x) if isinstance(x, float) else flint.arb(str(x))

    @staticmethod
    def require(cond, message):
        pass

    @staticmethod
    def sin(x):
        return x.sin()

    @staticmethod
    def cos(x):
        return x.cos()

    @staticmethod
    def pi():
        import flint

        return flint.arb.pi()

    @staticmethod
    def agm1(c):
        import flint

        return flint.arb(1).agm(c)

    @staticmethod
    def kc(c):
        import flint

        return flint.acb.elliptic_k(flint.acb(1 - c * c)).real


DOUBLE, MP, BALL = _Double(), _Mp(), _Ball()
