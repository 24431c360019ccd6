"""What every special function of this package shares: the sympy ``Function`` base class, the
one way to evaluate through mpmath (guard bits in a local context, never the global
precision), the python-flint precision guard, and the tests a ball must pass before a function
with a branch cut may be integrated by ``acb.integral`` (``analytic=True``).

Conventions, once: the CamelCase functions take DLMF's **modulus** k; mpmath, python-flint and
sympy's own ``elliptic_k`` … take the **parameter** m = k², so every route converts inside.
Branches are DLMF's principal ones (§4.2, §19.2, §19.16, §22.15).
"""

from __future__ import annotations

import contextlib
import functools

import flint
import mpmath
import sympy as sp
from flint import acb, arb
from sympy.core.function import ArgumentIndexError

#: guard bits every mpmath route adds to the caller's working precision
GUARD_BITS = 24
#: guard bits every ball route adds to flint.ctx.prec
BALL_GUARD_BITS = 16


#: the extra bits of the precision ladder: a value stands when two successive rungs agree
LADDER_BITS = (GUARD_BITS, 2 * GUARD_BITS + 8, 5 * GUARD_BITS)


def stable_value(compute, prec: int, ladder: bool = True):
    """``compute()`` at the caller's precision *prec* plus guard bits, climbing the ladder
    LADDER_BITS until two successive values agree to 2^−(prec+4) relative.  mpmath's own routines
    do not always deliver their working precision: ``elliprj`` at 40 digits loses 13 of them at
    R_J(0, 1 − k², 1, 1 − n) with k = 1.25 + 0.5i, n = 0.25 + 0.125i, and is right at 30 and 60."""
    previous = None
    for extra in (LADDER_BITS if ladder else LADDER_BITS[:1]):
        with mpmath.workprec(prec + extra):
            value = compute()
            if previous is not None:
                if not (mpmath.isfinite(value) and mpmath.isfinite(previous)):
                    return value
                if abs(value - previous) <= abs(value) * mpmath.ldexp(1, -prec - 4):
                    return value
        previous = value
    return value


def mp_route(extra: int = GUARD_BITS, ladder=True):
    """Decorate ``mp(cls, *args)``: the body runs at the caller's precision plus guard bits
    (``mpmath.workprec``, restored on exit) on a precision ladder (``stable_value``; *ladder*
    False, or a predicate of the arguments that says where to climb it), the value
    is rounded back to the caller's precision, and a complex value whose imaginary part vanishes
    exactly becomes real."""

    def decorate(body):
        @functools.wraps(body)
        def wrapper(cls, *args):
            prec = mpmath.mp.prec
            args = [a if isinstance(a, tuple) else mpmath.mpmathify(a) for a in args]
            climb = ladder(*args) if callable(ladder) else ladder
            value = stable_value(lambda: body(cls, *args), prec, climb)
            value = +value  # rounded to the caller's precision
            if isinstance(value, mpmath.mpc) and value.imag == 0:
                value = value.real
            return value

        return classmethod(wrapper)

    return decorate


def negative_real(value) -> bool:
    """*value* is a real number < 0 (an mpc with zero imaginary part counts)."""
    return is_real(value) and real(value) < 0


def is_real(*values) -> bool:
    """Every value is a real mpmath number (an mpc with a zero imaginary part counts)."""
    return all(not isinstance(v, mpmath.mpc) or v.imag == 0 for v in values)


def real(value):
    """The real part of *value* as an mpf (for a function known to be real there)."""
    return value.real if isinstance(value, mpmath.mpc) else value


@contextlib.contextmanager
def ball_precision(extra: int = BALL_GUARD_BITS):
    """Raise ``flint.ctx.prec`` by *extra* bits for the body and restore it, however the body
    ends (the caller owns the precision)."""
    prec = flint.ctx.prec
    flint.ctx.prec = prec + extra
    try:
        yield prec
    finally:
        flint.ctx.prec = prec


def ball_route(body):
    """Decorate a ``ball(*args, analytic=False)`` staticmethod body: arguments become acb, the
    body runs with guard bits, and the result is rounded to the caller's ``flint.ctx.prec``."""

    @functools.wraps(body)
    def wrapper(*args, analytic=False):
        args = [a if isinstance(a, tuple) else acb(a) for a in args]
        with ball_precision():
            value = body(*args, analytic=analytic)
        return +value

    return staticmethod(wrapper)


def nan_ball():
    """The non-finite ball: "no enclosure here" (a cut touched, a pole inside)."""
    return acb("nan")


def exact_real(z) -> bool:
    """The ball *z* lies on the real axis exactly (its imaginary part is the exact zero)."""
    return z.imag.is_exact() and z.imag.is_zero()


def may_meet(z, lo=None, hi=None) -> bool:
    """The ball *z* may meet the real segment [lo, hi] (None: unbounded on that side)."""
    if not z.is_finite():
        return True
    if not z.imag.contains(0):
        return False
    re = z.real
    if hi is not None and re > arb(hi):
        return False
    if lo is not None and re < arb(lo):
        return False
    return True


def may_meet_cut(z) -> bool:
    """The ball may meet (−∞, 0], the cut of the principal √ and log (DLMF §4.2(i))."""
    return may_meet(z, None, 0)


def asin_cut(w) -> bool:
    """The ball may meet the cuts (−∞, −1] ∪ [1, ∞) of arcsin and arccos (DLMF §4.23(ii))."""
    return may_meet(w, None, -1) or may_meet(w, 1, None)


def atan_cut(w) -> bool:
    """The ball may meet the cuts ±i[1, ∞) of arctan (DLMF §4.23(ii))."""
    return asin_cut(w * acb(0, -1))


def pv_union(value, args_real: bool, condition: bool):
    """A Cauchy principal value (DLMF 19.2.7, 19.16.2) from flint's one-sided limit *value*.

    Where every argument is an exact real number on the cut, flint returns the limit from one
    side; by Schwarz reflection the principal value is its real part.  Where the ball only may
    touch the cut, the union with the real part keeps the enclosure."""
    if not condition:
        return value
    if args_real:
        return acb(value.real)
    return value.union(acb(value.real)) if value.is_finite() else value


def sympify_args(args):
    return [sp.Tuple(*a) if isinstance(a, (tuple, list)) else a for a in args]


def to_mpmath(arg, prec):
    """A sympy number (or a Tuple of them) as mpmath number(s) at *prec* bits; ValueError when
    it is not a number."""
    if isinstance(arg, sp.Tuple):
        return tuple(to_mpmath(a, prec) for a in arg)
    value = arg.evalf(prec_to_dps(prec) + 5)
    if not value.is_number or value.has(sp.zoo, sp.oo, -sp.oo, sp.nan):
        raise ValueError(arg)
    return value._to_mpmath(prec)


def prec_to_dps(prec):
    return mpmath.libmp.prec_to_dps(prec)


class DLMFFunction(sp.Function):
    """Base class: evaluation through ``cls.mp`` (mpmath), balls through ``cls.ball`` (flint),
    LaTeX in DLMF's notation from ``latex_name`` (the arguments printed after it in
    parentheses, separated by commas)."""

    #: the LaTeX of the function's name, DLMF's notation
    latex_name = None
    #: the rigorous ball route, or None where there is none
    ball = None

    @classmethod
    def mp(cls, *args):  # pragma: no cover - every subclass overrides
        raise NotImplementedError

    def _eval_evalf(self, prec):
        try:
            args = [to_mpmath(a, prec + 10) for a in self.args]
        except (ValueError, TypeError, AttributeError):
            return None
        try:
            with mpmath.workprec(prec):
                value = self.mp(*args)
        except (ValueError, ZeroDivisionError, NotImplementedError):
            return None
        if not mpmath.isfinite(value):
            return None
        return sp.Expr._from_mpmath(value, prec)

    def _latex_args(self, printer):
        return ", ".join(printer._print(a) for a in self.args)

    def _latex(self, printer, exp=None):
        text = r"%s\left(%s\right)" % (self.latex_name, self._latex_args(printer))
        if exp is not None:
            text = r"%s^{%s}\left(%s\right)" % (self.latex_name, exp, self._latex_args(printer))
        return text

    @classmethod
    def definition(cls, *args):
        """The function written in other functions of this package, where that is how its
        derivatives are best obtained; None otherwise."""
        return None

    def diff_definition(self, argindex):
        """∂/∂(argument *argindex*) of ``definition``, differentiated at dummy arguments and
        evaluated at the actual ones (so a repeated argument is not differentiated twice)."""
        dummies = [sp.Dummy("a%d" % i) for i in range(len(self.args))]
        definition = self.definition(*dummies)
        if definition is None:
            raise ArgumentIndexError(self, argindex)
        return definition.diff(dummies[argindex - 1]).subs(dict(zip(dummies, self.args)))


def parameters(k):
    """(m, m′) = (k², 1 − k²) from the modulus, exact for a real mpf k (``exact=True``
    products) and as (1 − k)(1 + k) otherwise: 1 − k² never cancels near k = ±1."""
    if isinstance(k, mpmath.mpf):
        m = mpmath.fmul(k, k, exact=True)
        mc = mpmath.fmul(mpmath.fsub(1, k, exact=True), mpmath.fadd(1, k, exact=True), exact=True)
        return m, mc
    return k * k, (1 - k) * (1 + k)


def ball_parameters(k):
    """(m, m′) = (k², (1 − k)(1 + k)) as balls."""
    return k * k, (1 - k) * (1 + k)


def lost_bits(value) -> int:
    """Bits lost to cancellation when *value* (small) is formed as 1 − (something near 1)."""
    if value == 0:
        return 0
    return max(0, -mpmath.mag(value))


def to_arb(x):
    """An mpf as an exact arb."""
    if not mpmath.isfinite(x):
        raise ValueError("not finite: %s" % x)
    sign, man, exp, _ = x._mpf_
    return arb(-int(man) if sign else int(man)) * arb(2) ** int(exp) if man else arb(0)


def to_acb(x):
    x = mpmath.mpmathify(x)
    if isinstance(x, mpmath.mpc):
        return acb(to_arb(x.real), to_arb(x.imag))
    return acb(to_arb(x))


def from_arb(x):
    man, exp = x.mid().man_exp()
    return mpmath.mpf((int(man), int(exp)))


def flint_value(fn, *args):
    """*fn* (a flint function of acb balls) at mpmath arguments, as an mpmath number correct
    to the caller's precision: the ball's precision rises until its radius is below 2^−(prec+4)
    of its value.  Used where mpmath's own routine is unreliable (``elliprj``, ``elliprd``:
    R_J(0, 0.390625, 1, −0.5) loses 10 of 30 digits, complex arguments up to 13 of 40, and some
    precisions take minutes)."""
    prec = mpmath.mp.prec
    before = flint.ctx.prec
    try:
        for extra in (32, 96, 320):
            flint.ctx.prec = prec + extra
            value = fn(*[to_acb(a) for a in args])  # exact: the precision is set first
            if value.is_finite() and value.rad() <= value.mid().abs_upper() * arb(2) ** (-prec - 4):
                break
    finally:
        flint.ctx.prec = before
    if not value.is_finite():
        raise ValueError("no finite value")
    re, im = from_arb(value.real), from_arb(value.imag)
    return mpmath.mpc(re, im) if im != 0 else re


def rj(x, y, z, p):
    """R_J through flint (``flint_value``); for real x, y, z ≥ 0 and p < 0 the Cauchy principal
    value, the real part of flint's one-sided limit (DLMF 19.16.2)."""
    value = flint_value(acb.elliptic_rj, x, y, z, p)
    if is_real(x, y, z, p) and real(p) < 0 and min(real(x), real(y), real(z)) >= 0:
        return real(value)
    return value


def rd(x, y, z):
    """R_D through flint (``flint_value``)."""
    return flint_value(acb.elliptic_rd, x, y, z)
