"""Witnesses: the point where two sides differ, with both values to guaranteed digits.

Every digit a witness shows is guaranteed: rounded from a python-flint ball whose precision is
raised until both ends round alike (``good()``'s way), or — where a side has no ball form —
the digits on which a recomputation at twice the precision agrees (then not certified).  The
ball of the difference decides whether the refutation is certified.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import mpmath
import sympy as sp

from quasicentral.engine.options import Options
from quasicentral.engine.verdict import Witness
from quasicentral.notation import bridge


def witness_at(quantity, p, d, pt, top, low, dps, opts: Options, rel, at_most: bool = False) -> Witness:
    """The witness at ``pt``: both values with only guaranteed digits (see :func:`witness_values`);
    ``top`` and ``low`` are the (printed, derived) values on the ladder's top and first rungs;
    ``at_most``: an inequality's two sides (certified where the lesser's ball lies above the
    greater's)."""
    vals = witness_values(p, d, pt, top, low, dps, opts, at_most=at_most)
    return Witness(
        parameters={str(s): sp.sstr(v) for s, v in sorted(pt.items(), key=lambda kv: str(kv[0]))},
        printed=vals.printed, corrected=vals.corrected, digits=min(vals.printed_digits, vals.corrected_digits),
        certified=vals.certified, quantity=quantity, relative_difference=f"{rel:.3e}",
        printed_certified=vals.printed_certified, corrected_certified=vals.corrected_certified,
        working_digits=dps,
    )


WITNESS_DIGITS = 20  # significant digits a witness value shows at most
IMAGINARY_NEGLIGIBLE = 10.0 ** -(WITNESS_DIGITS + 5)  # an imaginary bound this far below the real part
BALL_PREC_LIMIT = 4096  # bits: the last precision tried for a witness ball
WITNESS_BUDGET = 4  # integrand evaluations of a witness's balls, in units of Options.certify_evaluations


@dataclass(frozen=True)
class WitnessValues:
    printed: str
    corrected: str
    printed_digits: int
    corrected_digits: int
    printed_certified: bool
    corrected_certified: bool
    certified: bool  # the ball of printed − corrected excludes 0


def witness_values(p, d, pt, top, low, dps, opts, want: int = WITNESS_DIGITS, at_most: bool = False) -> WitnessValues:
    """Both witness values, every digit shown guaranteed.

    With balls (python-flint, as ``good()`` does): start at the ladder's precision and double
    until both balls round to ``want`` significant digits at both ends and the ball of the
    difference decides, or :data:`BALL_PREC_LIMIT` is reached; a value is then printed with the
    digits its ball guarantees (correctly rounded).  Where a side has no ball form (an integrand
    unbounded at an end of the path, a function without a ball evaluation), its value is
    recomputed at twice the top rung's precision and only the digits on which the two agree are
    shown (``*_certified`` False).  Without ``opts.certify`` (the fast mutation checker) the two
    rungs of the ladder play that part.
    """
    balls: list = [None, None]
    certified = False
    if opts.certify:
        prec = max(64, int(dps * 3.33) + 8)
        # the whole ladder of balls shares one budget: a ball integral's cost grows fast with
        # the precision, and running out only turns its integrand into NaN
        work = bridge.Work(WITNESS_BUDGET * opts.certify_evaluations)
        stalled = [False, False]
        while True:
            for i, expr in enumerate((p, d)):
                if balls[i] is not None and _ball_digits(balls[i], want) >= want:
                    continue
                if balls[i] is False or stalled[i] or (work.spent and balls[i] is not None):
                    continue
                try:
                    b = bridge.arb_eval(expr, pt, prec=prec, work=work.share(opts.certify_evaluations))
                except (bridge.Unsupported, ValueError, ZeroDivisionError, TypeError, AttributeError):
                    b = None
                # a ball that is not finite (out of work, or unbounded) will not become finite
                # at a higher precision: keep the last good one, or give up on balls for this side.
                # Nor will one that gained no digit from the doubled precision (its integral is
                # limited by the evaluations, not the precision): keep it and stop there
                if b is not None and b.is_finite():
                    old = balls[i]
                    if old is not None and _ball_digits(b, want) <= _ball_digits(old, want):
                        stalled[i] = True
                        b = b if _ball_digits(b, want) == _ball_digits(old, want) else old
                    balls[i] = b
                elif balls[i] is None:
                    balls[i] = False
            if all(b is not None and b is not False for b in balls):  # identity: acb(0) == False
                certified = _exceeds(balls[0], balls[1]) if at_most else not (balls[0] - balls[1]).contains(0)
            done = all(b is False or stalled[i] or (b is not None and _ball_digits(b, want) >= want)
                       for i, b in enumerate(balls))
            settled = done and (certified or any(b is False for b in balls))
            if settled or prec >= BALL_PREC_LIMIT or work.spent:
                break
            prec *= 2
    out = []
    for i in range(2):
        b = balls[i]
        n = _ball_digits(b, want) if b is not None and b is not False else 0
        if n >= 1:
            out.append((_ball_str(b, n), n, True))
            continue
        # no ball: agreement with a recomputation at twice the precision
        if opts.certify:
            try:
                again = bridge.mp_eval((p, d)[i], pt, 2 * dps)
            except (ValueError, ZeroDivisionError, TypeError, OverflowError, mpmath.libmp.NoConvergence):
                again = None
            ref, other = again, top[i]
        else:
            ref, other = top[i], low[i]
        s, n = _agreed(ref, other, want) if ref is not None else ("", 0)
        out.append((s, n, False))
    (ps, pn, pc), (cs, cn, cc) = out
    return WitnessValues(ps, cs, pn, cn, pc, cc, certified)


def _exceeds(low, high) -> bool:
    """The ball of the side printed lesser lies wholly above the greater's: both real, and their
    difference positive."""
    a, b = _real_part(low), _real_part(high)
    return a is not None and b is not None and (a - b) > 0


def _real_part(b):
    """The real ball of an acb whose imaginary part is 0 or negligible, else None.  A ball
    integral of a real integrand along a real path comes back with an imaginary part of
    [± tiny] (a bound, not a value): below 10^−(WITNESS_DIGITS + 5) of the real part it
    cannot move any digit shown."""
    im, re = b.imag, b.real
    if im.is_exact() and im == 0:
        return re
    if im.contains(0) and not re.contains(0) and im.rad() <= abs(re).lower() * IMAGINARY_NEGLIGIBLE:
        return re
    return None


def _ball_digits(b, want: int) -> int:
    """How many significant digits (≤ want) both ends of the ball ``b`` round to alike — of
    each of its parts, where it is complex."""
    if b is None or b is False:
        return 0
    r = _real_part(b)
    if r is None:
        return min(_arb_digits(b.real, want), _arb_digits(b.imag, want))
    return _arb_digits(r, want)


def _arb_digits(r, want: int) -> int:
    if r.is_exact() and r == 0:
        return want
    mid, rad = exact_fraction(r.mid()), exact_fraction(r.rad())  # exact (lower()/upper() would round)
    lo, hi = mid - rad, mid + rad
    if lo == 0 or hi == 0 or (lo > 0) != (hi > 0):
        return 0
    for n in range(want, 0, -1):
        if round_significant(lo, n) == round_significant(hi, n):
            return n
    return 0


def _ball_str(b, n: int) -> str:
    r = _real_part(b)
    if r is None:
        return complex_string(_arb_str(b.real, n), _arb_str(b.imag, n))
    return _arb_str(r, n)


def _arb_str(r, n: int) -> str:
    if r.is_exact() and r == 0:
        return "0"
    return round_significant(exact_fraction(r.mid()), n)


def complex_string(re: str, im: str) -> str:
    """A complex value from its two parts' decimal strings: ``1.25 - 0.5i`` (``0.5i`` where the
    real part is 0)."""
    if im in ("0", ""):
        return re
    sign, mag = ("-", im[1:]) if im.startswith("-") else ("+", im)
    return f"{mag}i" if re == "0" and sign == "+" else f"-{mag}i" if re == "0" else f"{re} {sign} {mag}i"


def exact_fraction(x) -> Fraction:
    """An exact arb (a ball's end), mpf or Python number as a fraction."""
    if isinstance(x, (int, float)):
        return Fraction(x)
    if not hasattr(x, "man_exp"):
        x = mpmath.mpf(x)
    if isinstance(x, mpmath.mpf):
        sgn, man, exp, _ = x._mpf_
        if not man:
            return Fraction(0)
        man = -man if sgn else man
    else:
        man, exp = x.man_exp()
    man, exp = int(man), int(exp)
    return Fraction(man * 2**exp) if exp >= 0 else Fraction(man, 2**-exp)


def round_significant(x: Fraction, n: int) -> str:
    """``x`` correctly rounded (half to even) to ``n`` significant decimal digits, exactly."""
    if x == 0:
        return "0"
    sign = "-" if x < 0 else ""
    a = abs(x)
    e10 = len(str(a.numerator)) - len(str(a.denominator))  # within one of floor(log10 a)
    while a >= Fraction(10) ** (e10 + 1):
        e10 += 1
    while a < Fraction(10) ** e10:
        e10 -= 1
    q = round(a * Fraction(10) ** (n - 1 - e10))  # Fraction.__round__: half to even, exact
    if q >= 10**n:
        q //= 10
        e10 += 1
    digits = str(q)
    if -5 <= e10 < n:
        if e10 >= 0:
            whole, frac = digits[:e10 + 1], digits[e10 + 1:]
            return sign + whole + ("." + frac if frac else "")
        return sign + "0." + "0" * (-e10 - 1) + digits
    return sign + digits[0] + ("." + digits[1:] if n > 1 else "") + f"e{e10:+d}"


def _agreed(a, b, want: int) -> tuple[str, int]:
    """The digits (≤ want) on which two evaluations of one value agree, from the more precise
    (part by part, where it is complex)."""
    ra, rb = _as_real(a), _as_real(b)
    if ra is None or rb is None:
        if a is None or b is None:
            return "", 0
        a, b = mpmath.mpc(a), mpmath.mpc(b)
        (_, nr), (_, ni) = _agreed(a.real, b.real, want), _agreed(a.imag, b.imag, want)
        n = min(nr, ni)
        if n == 0:
            return "", 0
        return complex_string(_agreed_to(a.real, n), _agreed_to(a.imag, n)), n
    a, b = ra, rb
    if a == 0 and b == 0:
        return "0", want
    if mpmath.isinf(a) or mpmath.isinf(b):  # a limit that grows without bound, on both evaluations
        return ("inf" if a > 0 else "-inf", want) if a == b else ("", 0)
    fa, fb = exact_fraction(a), exact_fraction(b)
    for n in range(want, 0, -1):
        sa = round_significant(fa, n)
        if sa == round_significant(fb, n):
            return sa, n
    return "", 0


def _agreed_to(v, n: int) -> str:
    return "0" if v == 0 else round_significant(exact_fraction(v), n)


def _as_real(v):
    if isinstance(v, mpmath.mpc):
        if abs(v.imag) <= abs(v) * mpmath.mpf(10) ** (-40):
            return v.real
        return None
    return v

