"""The exact period of the simple pendulum, T = T0 · 2K(k²)/π with k = sin(φ0/2),
T0 = 2π√(l/g) — equations (60), (61), (66) of the pendulum text.

Convention: ``K(m)`` takes the *parameter* m = k² (scipy, mpmath, python-flint); the text
writes K(sin φ0/2) with the modulus.  Near φ0 → π, m → 1 and K has a logarithmic singularity;
forming m = sin²(φ0/2) and then 1 − m loses everything, so every route here uses the
complement p = 1 − m = cos²(φ0/2) = sin²(δ/2) with δ = π − φ0, or its square root
c = cos(φ0/2) = sin(δ/2) directly:

    T/T0 = 2K(1 − p)/π = 1/AGM(1, c)        (DLMF 19.8.5)

Each method is written once over an arithmetic context (:data:`DOUBLE`: numpy arrays;
:data:`MP`: mpmath at the working precision; :data:`BALL`: python-flint balls), the way mpmath
writes a function once for its contexts; the context supplies the primitives (sin, the AGM,
K from the complement, a quadrature, an ODE solver).  Methods (:class:`Method`):

* ``ellipk`` — the default: ``scipy.special.ellipkm1(p)`` with the complement p given exactly
  (and the asymptote ln(4/c) where p would underflow); ``mpmath.ellipk`` / ``acb.elliptic_k``;
* ``agm`` — the arithmetic-geometric mean 1/AGM(1, c) (no cancellation either; one ulp more);
* ``series`` — (66) truncated after N terms, with a rigorous bound of the tail;
* ``quad`` — quadrature of (60) after the substitution tan(π/2 − ψ) = c·sinh w, which turns it
  into K = ∫₀^∞ dw/√(1 + c² sinh²w): no peak of width c at ψ = π/2, so it holds down to δ = 1e-300;
* ``ode`` — integration of φ̈ = −(g/l) sin φ from rest at the amplitude to the lowest point;
  above 90° the deviation from the top ψ = π − φ is integrated (ψ̈ = sin ψ from ψ = δ to π),
  so that δ is never rounded away.

Inputs are the amplitude φ0 in (0, π) (radians, or ``amplitude_deg`` in degrees) *or* its
complement δ = π − φ0 (which keeps full accuracy for amplitudes within 1e-300 of π, where φ0
itself cannot be stored).  A decimal string is read exactly: 180° − A is formed in decimal,
and the half-angle sines are computed at the string's precision before any rounding to double.

>>> round(float(period_ratio(math.radians(90))), 15)
1.180340599016096
"""

from __future__ import annotations

import math
from decimal import ROUND_HALF_EVEN, Decimal, localcontext
from functools import cached_property

import mpmath
import numpy as np

from quasicentral.models.arithmetic import BALL, DOUBLE, LN4, MP, DomainError  # noqa: F401 - LN4 re-exported
# the routes' names live with the models' (a light module the command line reads for its choices)
from quasicentral.models.registry import PERIOD_METHODS as METHODS, SERIES_MAX_TERMS, PeriodMethod as Method  # noqa: F401
from quasicentral.notation import numbers

TWO_OVER_PI = 2 / math.pi


def method_of(name) -> Method:
    try:
        return Method(name)
    except ValueError:
        raise DomainError(f"unknown method {name!r}; choose from {', '.join(METHODS)}") from None


# --- the input: sin(φ0/2) and cos(φ0/2), once for every context --------------------------------
def _is_text(x) -> bool:
    return isinstance(x, (str, Decimal))


def _inside(ctx, x, upper) -> bool:
    """0 < x < upper everywhere (True for balls: their domain is checked in mpmath first)."""
    if ctx is DOUBLE:
        return bool(x.min(initial=math.inf) > 0 and x.max(initial=-math.inf) < upper) if x.size else True
    return ctx is BALL or 0 < x < upper


class HalfAngle:
    """s = sin(φ0/2) and c = cos(φ0/2) = sin(δ/2) of one input (amplitude in rad or deg, or the
    complement δ = π − φ0), each computed without cancellation in the context ``ctx``.  In
    double precision a decimal string is evaluated in mpmath at its own number of digits plus
    30 and rounded once: 180° − A is never formed from a rounded A."""

    def __init__(self, ctx, phi0=None, delta=None, amplitude_deg=None):
        given = [(k, v) for k, v in (("phi0", phi0), ("delta", delta), ("deg", amplitude_deg)) if v is not None]
        if len(given) != 1:
            raise DomainError("give exactly one of the amplitude (rad or deg) and its complement")
        self.ctx, (self.kind, raw) = ctx, given[0]
        pi = ctx.pi()
        if ctx is DOUBLE and _is_text(raw):
            with mpmath.workdps(30 + numbers.digits(str(raw)) + max(0, -numbers.decimal(str(raw), "x").adjusted())):
                exact = HalfAngle(MP, **{{"deg": "amplitude_deg"}.get(self.kind, self.kind): raw})
                self.half, self.rest = None, None
                self.__dict__["s"], self.__dict__["c"] = np.float64(exact.s), np.float64(exact.c)
            return
        if self.kind == "delta":
            d = ctx.read(raw, "the complement π − φ0")
            ctx.require(_inside(ctx, d, pi), "the complement π − φ0 must be in (0, π)")
            self.half, self.rest = None, d / 2  # s = cos(δ/2), c = sin(δ/2): no π − δ
        elif self.kind == "phi0":
            a = ctx.read(raw, "the amplitude")
            ctx.require(_inside(ctx, a, pi), "the amplitude must be in (0, π) rad")
            self.half, self.rest = a / 2, None
        else:
            if _is_text(raw):
                a_dec = numbers.decimal(raw, "the amplitude")
                a, r = ctx.read(str(a_dec), "the amplitude"), ctx.read(str(180 - a_dec), "the amplitude")
            else:
                a = ctx.read(raw, "the amplitude")
                r = 180 - a
            ctx.require(_inside(ctx, a, 180),
                        "the amplitude must be in (0, π) rad, i.e. (0°, 180°)")
            self.half, self.rest = a * pi / 360, r * pi / 360

    @cached_property
    def s(self):
        return self.ctx.cos(self.rest) if self.kind == "delta" else self.ctx.sin(self.half)

    @cached_property
    def c(self):
        return self.ctx.sin(self.rest) if self.rest is not None else self.ctx.cos(self.half)


# --- the methods, each written once --------------------------------------------------------------
def _agm(ctx, h: HalfAngle, _terms):
    """T/T0 = 1/AGM(1, c) (DLMF 19.8.5)."""
    return 1 / ctx.agm1(h.c)


def _ellipk(ctx, h: HalfAngle, _terms):
    """T/T0 = 2K(1 − c²)/π, K from the complement c² (never from m)."""
    return 2 * ctx.kc(h.c) / ctx.pi()


def _series(ctx, h: HalfAngle, terms):
    """(66) with m = s², its tail bounded with 1 − m = c²."""
    return series_ratio(h.s * h.s, terms, p=h.c * h.c, ctx=ctx)[0]


def _quad(ctx, h: HalfAngle, _terms):
    """(60) with tan(π/2 − ψ) = c sinh w: K = ∫₀^∞ dw/√(1 + c² sinh²w), split where c sinh w = 1."""
    def one(c):
        w1 = math.asinh(1 / float(c)) if ctx is DOUBLE else mpmath.asinh(1 / c)
        return 2 / ctx.pi() * ctx.integrate(lambda w: ctx.kernel(c, w),
                                            [0, w1, w1 + 1, math.inf if ctx is DOUBLE else mpmath.inf])

    return ctx.elementwise(one, h.c)


def _quarter(ctx, s, c, rtol=1e-13):
    """T/T0 as 4 × the time from rest at φ0 to the lowest point, in units of 1/Ω: φ̈ = −sin φ
    from φ0 to 0 up to 90°, beyond ψ̈ = sin ψ (ψ = π − φ) from δ to π (δ never rounded away)."""
    guess = ctx.pi() / 2 / ctx.agm1(c)  # the quarter period: a start for the solver
    if c >= s:
        t = ctx.first_passage(-1, 2 * ctx.atan2(s, c), 0 * s, guess, rtol)
    else:
        t = ctx.first_passage(1, 2 * ctx.atan2(c, s), ctx.pi(), guess, rtol)
    return 2 * t / ctx.pi()


def _ode(ctx, h: HalfAngle, _terms):
    return ctx.elementwise(lambda s, c: _quarter(ctx, s, c), h.s, h.c)


_ROUTES = {Method.AGM: _agm, Method.ELLIPK: _ellipk, Method.SERIES: _series, Method.QUAD: _quad, Method.ODE: _ode}


# --- double precision, vectorized -----------------------------------------------------------------
def agm_ratio(c) -> np.ndarray:
    """1/AGM(1, c) in double precision (c = cos(φ0/2))."""
    return 1.0 / DOUBLE.agm1(np.asarray(c, dtype=float))


def ellipk_ratio(c) -> np.ndarray:
    """2K(1 − c²)/π in double precision from the complement c = cos(φ0/2) (see ``_Double.kc``)."""
    return TWO_OVER_PI * DOUBLE.kc(c)


def series_coefficients(n_terms: int, ctx=DOUBLE):
    """c_n = ((2n−1)!!/(2n)!!)², n = 0 … N−1, the coefficients of (66) in powers of m = k²."""
    return ctx.coefficients(n_terms)


def series_ratio(m, n_terms: int, *, p=None, ctx=DOUBLE):
    """(66) truncated after ``n_terms`` terms (Horner), and a bound of the neglected tail:
    Σ_{n≥N} c_n mⁿ ≤ c_N m^N/(1 − m), since c_n decreases; ``p`` = 1 − m when known exactly."""
    if not 1 <= n_terms <= SERIES_MAX_TERMS:
        raise DomainError(f"the number of terms must be between 1 and {SERIES_MAX_TERMS}")
    coef = series_coefficients(n_terms + 1, ctx)
    if ctx is DOUBLE:
        m = np.asarray(m, dtype=float)
    p = 1 - m if p is None else p
    total = 0 * m
    for cn in coef[-2::-1]:
        total = total * m + cn
    with np.errstate(divide="ignore", over="ignore"):
        tail = coef[-1] * m**n_terms / p
    return total, tail


def period_ratio(phi0=None, *, delta=None, amplitude_deg=None, method: str = "ellipk", terms: int = 4):
    """T/T0 in double precision for scalars or arrays of amplitudes (radians or degrees) or
    complements; decimal strings are read exactly (see :class:`HalfAngle`)."""
    route = _ROUTES[method_of(method)]
    return route(DOUBLE, HalfAngle(DOUBLE, phi0, delta, amplitude_deg), terms)


def ode_ratio(phi0: float, rtol: float = 1e-13) -> float:
    """T/T0 by integrating the pendulum equation in double precision (the ``ode`` method)."""
    h = HalfAngle(DOUBLE, phi0)
    return float(_quarter(DOUBLE, float(h.s), float(h.c), rtol))


def series_error(phi0=None, *, delta=None, amplitude_deg=None, terms: int = 4):
    """(T/T0 by the series, the bound of its tail) in double precision."""
    h = HalfAngle(DOUBLE, phi0, delta, amplitude_deg)
    return series_ratio(h.s * h.s, terms, p=h.c * h.c)


# --- any precision ----------------------------------------------------------------------------
def _input_digits(*texts) -> int:
    return max((numbers.digits(str(t)) for t in texts if _is_text(t)), default=0)


def period_ratio_mp(phi0=None, *, delta=None, amplitude_deg=None, dps: int = 30, method: str = "ellipk",
                    terms: int = 4):
    """T/T0 at ``dps`` digits (an mpmath number, computed with guard digits in a local context).
    Inputs are decimal strings read exactly (never rounded through a double) or floats taken
    at their binary values."""
    route = _ROUTES[method_of(method)]
    with mpmath.workdps(dps + 20 + _input_digits(phi0, delta, amplitude_deg)):
        r = route(MP, HalfAngle(MP, phi0, delta, amplitude_deg), terms)
    with mpmath.workdps(dps):
        return +r


# --- correctly rounded, with balls -------------------------------------------------------------
def period_ratio_rounded(*, delta=None, phi0=None, amplitude_deg=None, digits: int = 30,
                         method: str = "ellipk") -> str:
    """T/T0 correctly rounded to ``digits`` significant digits (round-half-even), proved with
    python-flint balls (``arb.agm`` or ``acb.elliptic_k``): the precision rises until both ends
    of the ball round alike (python-flint's ``good()`` strategy)."""
    import flint

    method = method_of(method)
    if method not in (Method.AGM, Method.ELLIPK):
        raise DomainError("correctly rounded values come from agm or ellipk only")
    with mpmath.workdps(30 + _input_digits(phi0, delta, amplitude_deg)):  # the domain, before any ball
        HalfAngle(MP, phi0, delta, amplitude_deg)
    old = flint.ctx.prec
    try:
        prec = int(3.33 * digits) + 32
        for _ in range(16):
            flint.ctx.prec = prec
            ball = _ROUTES[method](BALL, HalfAngle(BALL, phi0, delta, amplitude_deg), 0)
            if ball.is_finite():  # near π the ball of 1 − c² may still contain 1
                lo, hi = _round_decimal(ball.lower(), digits), _round_decimal(ball.upper(), digits)
                if lo == hi:
                    return lo
            prec *= 2
        raise ArithmeticError("no convergence of the ball to a correctly rounded value")
    finally:
        flint.ctx.prec = old


def _round_decimal(x, digits: int) -> str:
    """An exact binary number (arb with zero radius) rounded to ``digits`` significant digits."""
    man, exp = x.mid().man_exp()
    with localcontext() as ctx:
        ctx.prec = max(100, abs(int(exp)) + man.bit_length() + 10)
        d = Decimal(int(man)) * (Decimal(2) ** int(exp))
        if d == 0:
            return "0"
        ctx.prec = digits
        ctx.rounding = ROUND_HALF_EVEN
        return str(+d)


# --- the series: how many terms ----------------------------------------------------------------
def terms_needed(phi0: float, tol: float) -> int:
    """Smallest N for which (66) truncated after N terms is within ``tol`` (relative) of T/T0.
    The neglected tail Σ_{n≥N} c_n mⁿ is summed from its small end (no cancellation)."""
    m = math.sin(phi0 / 2) ** 2
    exact = float(ellipk_ratio(np.array([math.cos(phi0 / 2)]))[0])
    target = tol * exact
    # terms until they and their geometric remainder are far below the target
    n_max = 64
    while True:
        terms = series_coefficients(n_max) * m ** np.arange(n_max)
        if terms[-1] / (1 - m) < 1e-3 * target or n_max >= SERIES_MAX_TERMS:
            break
        n_max *= 4
    tails = np.cumsum(terms[::-1])[::-1] + terms[-1] * m / (1 - m)  # tails[N] = Σ_{n≥N}
    ok = np.nonzero(tails <= target)[0]
    if not ok.size:
        raise DomainError(f"more than {SERIES_MAX_TERMS} terms needed")
    return int(ok[0])


def first_amplitude_exceeding(n_terms: int, tol: float) -> float:
    """The smallest amplitude (rad) at which the N-term truncation's relative error exceeds ``tol``."""
    from scipy.optimize import brentq

    def err(a):
        exact = float(ellipk_ratio(np.array([math.cos(a / 2)]))[0])
        approx = float(series_ratio(np.array([math.sin(a / 2) ** 2]), n_terms)[0][0])
        return (exact - approx) / exact - tol

    lo, hi = 1e-6, math.pi - 1e-9
    if err(hi) < 0:
        return math.pi
    return brentq(err, lo, hi, xtol=1e-14)


# --- the table of T/T0 ---------------------------------------------------------------------------
TABLE_AMPLITUDES_DEG = ("5", "10", "15", "20", "30", "45", "60", "75", "90", "105", "120", "135", "150",
                        "160", "170", "175", "179", "179.9", "179.99")


def table(digits: int = 20) -> list[dict]:
    """T/T0 at ``digits`` digits for amplitudes 5° … 179.99°, by two independent routes: the
    AGM (correctly rounded with balls) and mpmath quadrature of (60); they must agree."""
    rows = []
    for a in TABLE_AMPLITUDES_DEG:
        agm = period_ratio_rounded(amplitude_deg=a, digits=digits, method="agm")
        q = period_ratio_mp(amplitude_deg=a, dps=digits + 10, method="quad")
        with mpmath.workdps(digits + 10):
            agree = abs(q - mpmath.mpf(agm)) <= mpmath.mpf(10) ** (-(digits - 1)) * abs(q)
        rows.append({"amplitude_deg": a, "T_over_T0": agm, "quad": mpmath.nstr(q, digits), "agree": bool(agree)})
    return rows
