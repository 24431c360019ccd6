"""The exact period of the simple pendulum, T = T0 · 2K(k²)/π with k = sin(φ0/2),
T0 = 2π√(l/g) — equations (60), (61), (66) of the pendulum text.

Convention: ``K(m)`` takes the *parameter* m = k² (scipy, mpmath, python-flint); the text
writes K(sin φ0/2) with the modulus.  Near φ0 → π, m → 1 and K has a logarithmic singularity;
forming m = sin²(φ0/2) and then 1 − m loses everything, so every route here uses the
complement p = 1 − m = cos²(φ0/2) = sin²(δ/2) with δ = π − φ0, or its square root
c = cos(φ0/2) = sin(δ/2) directly:

    T/T0 = 2K(1 − p)/π = 1/AGM(1, c)        (DLMF 19.8.5)

Methods (the same names in double precision and at any precision):

* ``ellipk`` — the default: ``scipy.special.ellipkm1(p)`` with the complement p given exactly
  (and the asymptote ln(4/c) where p would underflow); ``mpmath.ellipk`` / ``acb.elliptic_k``;
* ``agm`` — the arithmetic-geometric mean 1/AGM(1, c) (no cancellation either; one ulp more);
* ``series`` — (66) truncated after N terms, with a rigorous bound of the tail;
* ``quad`` — quadrature of (60) written with the complement, 1/√(cos²ψ + p sin²ψ);
* ``ode`` — integration of φ̈ = −(g/l) sin φ from the amplitude to the lowest point.

Inputs are the amplitude φ0 in (0, π) *or* its complement δ = π − φ0 (which keeps full
accuracy for amplitudes within 1e-300 of π, where φ0 itself cannot be stored).

>>> round(float(period_ratio(math.radians(90))), 15)
1.180340599016096
"""

from __future__ import annotations

import math
from decimal import ROUND_HALF_EVEN, Decimal, localcontext

import mpmath
import numpy as np

METHODS = ("agm", "series", "ellipk", "quad", "ode")


class DomainError(ValueError):
    """An input outside the physical domain."""


# --- double precision, vectorized -------------------------------------------------------------
def _complement_sine(phi0=None, delta=None) -> np.ndarray:
    """c = cos(φ0/2) = sin(δ/2), computed from whichever input was given."""
    if (phi0 is None) == (delta is None):
        raise DomainError("give the amplitude or its complement, not both")
    if delta is not None:
        d = np.asarray(delta, dtype=float)
        if not np.all(np.isfinite(d)) or np.any(d <= 0) or np.any(d >= math.pi):
            raise DomainError("the complement π − φ0 must be in (0, π)")
        return np.sin(d / 2)
    a = np.asarray(phi0, dtype=float)
    if not np.all(np.isfinite(a)) or np.any(a <= 0) or np.any(a >= math.pi):
        raise DomainError("the amplitude must be in (0, π) rad")
    return np.cos(a / 2)


def agm_ratio(c: np.ndarray) -> np.ndarray:
    """1/AGM(1, c), vectorized; converges quadratically (≤ 12 steps for c ≥ 1e-300)."""
    a = np.ones_like(c)
    b = np.array(c, dtype=float)
    for _ in range(40):
        if np.all(np.abs(a - b) <= 1e-15 * a):
            break
        a, b = 0.5 * (a + b), np.sqrt(a * b)
    return 1.0 / (0.5 * (a + b))


def ellipk_ratio(c: np.ndarray) -> np.ndarray:
    """2K(1 − c²)/π from the complement: ``scipy.special.ellipkm1(p)``, p = c² given exactly
    (1.3 ulp); for c < 1e-8 the asymptote K = ln(4/c) + O(c² ln c), exact to rounding there
    and free of the underflow of c² (δ down to 1e-300)."""
    from scipy.special import ellipkm1

    c = np.asarray(c, dtype=float)
    tiny = c < 1e-8
    if not tiny.any():
        return TWO_OVER_PI * ellipkm1(c * c)
    with np.errstate(divide="ignore"):
        k = np.where(tiny, LN4 - np.log(np.where(tiny, c, 1.0)), ellipkm1(np.where(tiny, 1.0, c * c)))
    return TWO_OVER_PI * k


LN4 = math.log(4.0)
TWO_OVER_PI = 2 / math.pi

SERIES_MAX_TERMS = 10**7


def series_coefficients(n_terms: int) -> np.ndarray:
    """c_n = ((2n−1)!!/(2n)!!)², n = 0 … N−1, the coefficients of (66) in powers of k²."""
    n = np.arange(1, n_terms, dtype=float)
    return np.concatenate(([1.0], np.cumprod(((2 * n - 1) / (2 * n)) ** 2)))


def series_ratio(m: np.ndarray, n_terms: int) -> tuple[np.ndarray, np.ndarray]:
    """(66) truncated after ``n_terms`` terms, and a bound of the neglected tail:
    Σ_{n≥N} c_n mⁿ ≤ c_N m^N/(1 − m), since c_n decreases."""
    if not 1 <= n_terms <= SERIES_MAX_TERMS:
        raise DomainError(f"the number of terms must be between 1 and {SERIES_MAX_TERMS}")
    coef = series_coefficients(n_terms + 1)
    m = np.asarray(m, dtype=float)
    total = np.zeros_like(m)
    for cn in coef[-2::-1]:  # Horner
        total = total * m + cn
    with np.errstate(divide="ignore"):
        tail = coef[-1] * m**n_terms / (1 - m)
    return total, tail


def period_ratio(phi0=None, *, delta=None, method: str = "ellipk", terms: int = 4):
    """T/T0 in double precision for scalars or arrays of amplitudes (radians)."""
    c = _complement_sine(phi0, delta)
    if method == "agm":
        return agm_ratio(c)
    p = c * c
    if method == "ellipk":
        return ellipk_ratio(c)
    if method == "series":
        m = 1 - p if delta is not None else np.sin(np.asarray(phi0, dtype=float) / 2) ** 2
        return series_ratio(m, terms)[0]
    if method == "quad":
        from scipy.integrate import quad

        f = np.vectorize(lambda pp: quad(lambda s: 1 / math.sqrt(math.cos(s) ** 2 + pp * math.sin(s) ** 2),
                                         0, math.pi / 2, epsabs=0, epsrel=2e-14, limit=200)[0])
        return 2 / math.pi * f(p)
    if method == "ode":
        return np.vectorize(ode_ratio)(np.arccos(np.clip(1 - 2 * p, -1, 1)) if phi0 is None else phi0)
    raise DomainError(f"unknown method {method!r}; choose from {', '.join(METHODS)}")


def ode_ratio(phi0: float, rtol: float = 1e-13) -> float:
    """T/T0 by integrating φ'' = −sin φ (time in units of 1/Ω) from rest at φ0 to the lowest
    point (DOP853 with an event), times 4."""
    from scipy.integrate import solve_ivp

    def lowest(t, y):
        return y[0]

    lowest.terminal, lowest.direction = True, -1
    span = 4 * (math.log(8 / max(math.cos(phi0 / 2), 1e-300)) + 2)
    sol = solve_ivp(lambda t, y: (y[1], -math.sin(y[0])), (0, span), (phi0, 0.0), method="DOP853",
                    rtol=rtol, atol=rtol * 1e-2, events=lowest)
    return 4 * sol.t_events[0][0] / (2 * math.pi)


# --- any precision ----------------------------------------------------------------------------
def period_ratio_mp(phi0: str | None = None, *, delta: str | None = None, amplitude_deg: str | None = None,
                    dps: int = 30, method: str = "ellipk", terms: int = 4):
    """T/T0 at ``dps`` digits (an mpmath number, computed with guard digits in a local context).
    Inputs are decimal strings read exactly (never rounded through a double)."""
    with mpmath.workdps(dps + 20):
        c = _complement_sine_mp(phi0, delta, amplitude_deg)
        p = c * c
        if method == "agm":
            r = 1 / mpmath.agm(1, c)
        elif method == "ellipk":
            # m = 1 − p needs the digits of p too: raise the precision by p's decimal exponent
            with mpmath.workdps(dps + 20 + max(0, -int(mpmath.floor(mpmath.log10(p))))):
                r = 2 / mpmath.pi * mpmath.ellipk(1 - p)
        elif method == "series":
            m = 1 - p
            if not 1 <= terms <= 10**6:
                raise DomainError("the number of terms must be between 1 and 1000000")
            total, cn = mpmath.mpf(0), mpmath.mpf(1)
            for n in range(terms):
                if n:
                    cn *= (mpmath.mpf(2 * n - 1) / (2 * n)) ** 2
                total += cn * m**n
            r = total
        elif method == "quad":
            r = 2 / mpmath.pi * mpmath.quad(lambda s: 1 / mpmath.sqrt(mpmath.cos(s) ** 2 + p * mpmath.sin(s) ** 2),
                                            [0, mpmath.pi / 2])
        elif method == "ode":
            phi = 2 * mpmath.acos(c)
            f = mpmath.odefun(lambda t, y: [y[1], -mpmath.sin(y[0])], 0, [phi, 0])
            guess = mpmath.pi / 2 * (1 / mpmath.agm(1, c))  # a start for the root only
            tq = mpmath.findroot(lambda t: f(t)[0], guess)
            r = 4 * tq / (2 * mpmath.pi)
        else:
            raise DomainError(f"unknown method {method!r}; choose from {', '.join(METHODS)}")
    with mpmath.workdps(dps):
        return +r


def _complement_sine_mp(phi0, delta, amplitude_deg):
    given = [x is not None for x in (phi0, delta, amplitude_deg)]
    if sum(given) != 1:
        raise DomainError("give exactly one of the amplitude (rad or deg) and its complement")
    if delta is not None:
        d = _exact(delta, "the complement")
        if not 0 < d < mpmath.pi:
            raise DomainError("the complement π − φ0 must be in (0, π)")
        return mpmath.sin(d / 2)
    a = _exact(phi0, "the amplitude") if phi0 is not None else _exact(amplitude_deg, "the amplitude") * mpmath.pi / 180
    if not 0 < a < mpmath.pi:
        raise DomainError("the amplitude must be in (0, π) rad, i.e. (0°, 180°)")
    return mpmath.cos(a / 2)


def _exact(text, what: str):
    """A decimal string read exactly, or a float taken at its exact binary value."""
    try:
        val = mpmath.mpf(text) if isinstance(text, float) else mpmath.mpf(str(text).strip())
    except (ValueError, TypeError):
        raise DomainError(f"{what} must be a number, not {text!r}") from None
    if not mpmath.isfinite(val):
        raise DomainError(f"{what} must be finite, not {text!r}")
    return val


# --- correctly rounded, with balls -------------------------------------------------------------
def period_ratio_rounded(*, delta: str | None = None, phi0: str | None = None, amplitude_deg: str | None = None,
                         digits: int = 30, method: str = "ellipk") -> str:
    """T/T0 correctly rounded to ``digits`` significant digits (round-half-even), proved with
    python-flint balls (``arb.agm`` or ``acb.elliptic_k``): the precision rises until both ends
    of the ball round alike."""
    import flint

    with mpmath.workdps(30):  # the same domain checks as every other route, before any ball
        _complement_sine_mp(phi0, delta, amplitude_deg)
    old = flint.ctx.prec
    try:
        prec = int(3.33 * digits) + 32
        for _ in range(16):
            flint.ctx.prec = prec
            c = _complement_sine_arb(phi0, delta, amplitude_deg)
            if method == "agm":
                ball = 1 / flint.arb(1).agm(c)
            else:
                ball = (2 * flint.acb.elliptic_k(flint.acb(1 - c * c)) / flint.arb.pi()).real
            if ball.is_finite():  # near π the ball of 1 − c² may still contain 1
                lo, hi = _round_decimal(ball.lower(), digits), _round_decimal(ball.upper(), digits)
                if lo == hi:
                    return lo
            prec *= 2
        raise ArithmeticError("no convergence of the ball to a correctly rounded value")
    finally:
        flint.ctx.prec = old


def _complement_sine_arb(phi0, delta, amplitude_deg):
    import flint

    if delta is not None:
        return (flint.arb(str(delta)) / 2).sin()
    a = flint.arb(str(phi0)) if phi0 is not None else flint.arb(str(amplitude_deg)) * flint.arb.pi() / 180
    return (a / 2).cos()


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
