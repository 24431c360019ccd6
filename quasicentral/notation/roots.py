"""A quantity defined only implicitly: "x₁ is the root of J₁(x) = 0 in [3, 4.5]" — a text's
symbol declared with ``solves`` (FORMAT.md) becomes :class:`Root`, an unevaluated sympy
expression whose value mpmath finds by bracketing (:func:`root_in`) at whatever precision the
caller opens, and whose derivative in any parameter is the implicit function theorem's.

Written here rather than taken from sympy: its ``CRootOf`` holds the roots of polynomials only,
and ``nsolve`` gives a number, not an expression that keeps its parameters (tan x = a·x, a root
that moves with a).  The bracket is the declared range; the root must be the only sign change
of f there (:data:`SIGN_SAMPLES` samples), so that the value is the one the text means, never
a neighbour.
"""

from __future__ import annotations

import mpmath
import sympy as sp

from quasicentral.notation.limits import agreeing

#: equally spaced points at which f's sign is read across the bracket: more than one change is
#: more than one root, and the text's quantity is not defined by the bracket
SIGN_SAMPLES = 64


class Root(sp.Expr):
    """The root x of ``function`` = 0 with ``low`` ≤ x ≤ ``high`` (``variable`` bound, a Dummy);
    its free symbols are the parameters of ``function`` and of the bracket."""

    is_real = True

    def __new__(cls, function, variable, low, high):
        return sp.Expr.__new__(cls, sp.sympify(function), variable, sp.sympify(low), sp.sympify(high))

    function = property(lambda self: self.args[0])
    variable = property(lambda self: self.args[1])
    low = property(lambda self: self.args[2])
    high = property(lambda self: self.args[3])

    @property
    def free_symbols(self):
        return (self.function.free_symbols - {self.variable}) | self.low.free_symbols | self.high.free_symbols

    @property
    def is_number(self):
        return not self.free_symbols

    def _eval_derivative(self, s):
        """dx/ds = −(∂f/∂s)/(∂f/∂x) at the root (the implicit function theorem)."""
        at = {self.variable: self}
        return -sp.diff(self.function, s).xreplace(at) / sp.diff(self.function, self.variable).xreplace(at)

    def _sympystr(self, printer):
        return (f"Root({printer.doprint(self.function)}, {printer.doprint(self.variable)}, "
                f"{printer.doprint(self.low)}, {printer.doprint(self.high)})")

    def _latex(self, printer):
        x = printer.doprint(self.variable)
        return (rf"\left.{x}\right|_{{{printer.doprint(self.function)} = 0,\ "
                rf"{printer.doprint(self.low)} \le {x} \le {printer.doprint(self.high)}}}")


def root_in(g, a, b):
    """The one root of the real function ``g`` in [a, b] at the working precision, found by
    bracketing (mpmath's Anderson–Björck) and confirmed at ten more digits; ValueError where g
    does not change sign exactly once on :data:`SIGN_SAMPLES` points of [a, b] (no root, or
    several: the bracket does not define the quantity)."""
    if not (mpmath.isfinite(a) and mpmath.isfinite(b)) or not a < b:
        raise ValueError(f"the bracket [{mpmath.nstr(a, 6)}, {mpmath.nstr(b, 6)}] of a root is not an interval")
    xs = [a + (b - a) * k / SIGN_SAMPLES for k in range(SIGN_SAMPLES + 1)]
    signs = [mpmath.sign(mpmath.re(g(x))) for x in xs]
    if 0 in signs:  # a sample is the root itself
        hit = xs[signs.index(0)]
        return +hit
    changes = [k for k in range(SIGN_SAMPLES) if signs[k] != signs[k + 1]]
    if len(changes) != 1:
        raise ValueError(f"{'no' if not changes else len(changes)} sign changes in "
                         f"[{mpmath.nstr(a, 6)}, {mpmath.nstr(b, 6)}]: the bracket holds "
                         f"{'no root' if not changes else 'several roots'}")
    lo, hi = xs[changes[0]], xs[changes[0] + 1]
    first = mpmath.findroot(g, (lo, hi), solver="anderson")
    with mpmath.workdps(mpmath.mp.dps + 10):
        second = mpmath.findroot(g, (lo, hi), solver="anderson")
    if not lo <= first <= hi:
        raise ValueError("the root left its bracket")
    return agreeing(+first, +second)
