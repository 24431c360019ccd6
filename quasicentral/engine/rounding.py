"""Printed roundings: ``x ≈ 4.965114`` holds when the exact value of x rounds to the printed
decimal at the places printed (|x − 4.965114| < ½·10⁻⁶), never "agrees to many digits".

A rounding is written ``Approx(x, 4.965114)`` in a transcription, or ``approx = "4.965114"``
beside a bare expression, and in an identity text an equation one of whose sides is a decimal
literal (``Eq(CarlsonRF(1, 2, 4), 0.6850858166)``, :meth:`~quasicentral.engine.catalog.Entry.relations`).

The exact value is enclosed in a python-flint ball whose precision is doubled until the ball
lies inside or outside the half-unit interval around the printed decimal (certified either
way); where a part of x has no ball form, mpmath computes it at two precisions that must agree
well beyond the printed places (not a proof: the verdict is then ``numeric``).  A value on the
half of the last place (to the precision tried) is a tie: either rounding is right.
"""

from __future__ import annotations

from fractions import Fraction

import mpmath
import sympy as sp

from quasicentral.engine.ladder import prepared
from quasicentral.engine.options import Options
from quasicentral.engine.reasons import Code, Reason
from quasicentral.engine.verdict import Inconclusive, Method, Refuted, Verdict, Verified, Witness
from quasicentral.engine.witness import exact_fraction
from quasicentral.notation import bridge
from quasicentral.notation.symbols import Approx

#: the ball precisions tried (bits), doubling; then mpmath at two precisions
BALL_BITS = (128, 256, 512, 1024, 2048)
#: evaluations a ball integral may spend per precision
BALL_WORK = 200_000
#: digits beyond the printed places the exact value is shown with
SHOWN_BEYOND = 4


def relation_is_rounding(rel) -> bool:
    """A printed rounding of one number (a formula with printed decimals is compared as a
    relation: :meth:`~quasicentral.notation.symbols.Approx.window`)."""
    return isinstance(rel, Approx) and not rel.is_formula


def _decimal(x: Fraction, places: int) -> str:
    """``x`` correctly rounded to ``places`` decimal places (half away from zero), as text."""
    scaled = abs(x) * 10 ** places
    q = int(scaled + Fraction(1, 2))
    sign = "-" if x < 0 and q else ""
    if places <= 0:
        return sign + str(q * 10 ** -places)
    digits = str(q).rjust(places + 1, "0")
    return f"{sign}{digits[:-places]}.{digits[-places:]}"


def _enclosure(expr: sp.Expr, places: int):
    """(lower, upper, certified) bounds of the real value of the closed ``expr`` — from balls at
    doubling precision while they are wider than the digits shown beyond the last place, else mpmath at
    two precisions; None where it is not real, the error where it cannot be computed."""
    unit = Fraction(1, 10 ** places) if places >= 0 else Fraction(10 ** -places)
    for bits in BALL_BITS:
        try:
            b = bridge.arb_eval(expr, {}, prec=bits, work=bridge.Work(BALL_WORK))
        except (bridge.Unsupported, ValueError, ZeroDivisionError, TypeError, AttributeError, ArithmeticError):
            break
        if not b.is_finite():
            break
        if not b.imag.contains(0):
            return None
        mid, rad = exact_fraction(b.real.mid()), exact_fraction(b.real.rad())  # exact ends
        lo, hi = mid - rad, mid + rad
        if hi - lo < unit / 10 ** (SHOWN_BEYOND + 1) or bits == BALL_BITS[-1]:
            return lo, hi, True
    dps = max(30, places + 20)
    try:
        values = [bridge.mp_eval(expr, {}, d) for d in (dps, 2 * dps)]
    except (ValueError, ZeroDivisionError, TypeError, OverflowError, ArithmeticError, mpmath.libmp.NoConvergence,
            bridge.Unsupported) as exc:
        return str(exc)[:200] or type(exc).__name__
    with mpmath.workdps(2 * dps):
        a, b = values
        if not (mpmath.isfinite(a) and mpmath.isfinite(b)) or abs(mpmath.im(b)) > abs(b) * mpmath.mpf(10) ** -dps:
            return None
        a, b = mpmath.re(a), mpmath.re(b)
        # the two precisions agree to within their difference (and the lower one's last digits)
        width = exact_fraction(abs(a - b) + abs(b) * mpmath.mpf(10) ** (2 - dps))
        mid = exact_fraction(b)
    return mid - width, mid + width, False


def check(rel: Approx, defs: dict, opts: Options) -> Verdict:
    """The verdict on one printed rounding (see the module docstring)."""
    expr = prepared(rel.args[0], defs)
    printed = Fraction(int(rel.args[1].p), int(rel.args[1].q))
    places = int(rel.args[2])
    shown = _decimal(printed, places)
    free = sorted((str(s) for s in expr.free_symbols), key=str)
    if free:
        return Inconclusive(Method.NONE, Reason.of(Code.ROUNDING_FREE, symbols=tuple(free)))
    bounds = _enclosure(expr, places)
    if isinstance(bounds, str):
        return Inconclusive(Method.NONE, Reason.of(Code.ROUNDING_NO_VALUE, printed=shown, error=bounds))
    if bounds is None:
        return Inconclusive(Method.NONE, Reason.of(Code.ROUNDING_UNDECIDED, printed=shown, places=places))
    lo, hi, certified = bounds
    half = Fraction(1, 2 * 10 ** places) if places >= 0 else Fraction(10 ** -places, 2)
    method = Method.CERTIFIED if certified else Method.NUMERIC
    mid = (lo + hi) / 2
    # the exact value in the digits both ends of its enclosure round to alike (every one guaranteed)
    shown_places = places + SHOWN_BEYOND
    while shown_places > places and _decimal(lo, shown_places) != _decimal(hi, shown_places):
        shown_places -= 1
    exact = _decimal(mid, shown_places)
    if printed - half < lo and hi < printed + half:
        return Verified(method, Reason.of(Code.ROUNDS_TO, value=exact, printed=shown, places=places), 1)
    if hi < printed - half or lo > printed + half:
        rel_diff = abs(mid - printed) / abs(mid) if mid else Fraction(1)
        significant = len(exact.lstrip("-").replace(".", "").lstrip("0"))
        w = Witness(parameters={}, printed=shown, corrected=exact, digits=significant, certified=certified,
                    quantity=Reason(Code.Q_ROUNDING), relative_difference=f"{float(rel_diff):.3g}",
                    printed_certified=True, corrected_certified=certified, working_digits=0)
        return Refuted(method, Reason.of(Code.ROUNDS_OTHERWISE, printed=shown, exact=exact, places=places), 1,
                       witness=w)
    if hi - lo < half / 1000:
        return Inconclusive(Method.NONE, Reason.of(Code.ROUNDING_TIE, printed=shown, places=places))
    return Inconclusive(Method.NONE, Reason.of(Code.ROUNDING_UNDECIDED, printed=shown, places=places))
