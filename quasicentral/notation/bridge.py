"""The one bridge from exact sympy to numbers: mpmath at any precision, python-flint balls.

The bridge is four modules, one job each; this one gathers their public names:

* :mod:`~quasicentral.notation.jets` — :func:`to_jets` replaces the motion's functions and their
  derivatives by plain symbols (``x(t) -> x_t0``, ``x'(t) -> x_t1`` …): an identity among
  derivatives holds for all motions exactly when it holds for all values of these jets;
* :mod:`~quasicentral.notation.mpeval` — :func:`mp_function` compiles an expression once for
  mpmath; precision is whatever local ``mpmath.workdps`` the caller opens (nothing here sets
  it); :func:`rung_function` computes in balls first;
* :mod:`~quasicentral.notation.integrals` — definite integrals made ready for numbers;
* :mod:`~quasicentral.notation.balls` — :func:`arb_eval` evaluates an expression in complex
  ball arithmetic (python-flint ``acb``): the result's radius bounds all rounding and
  truncation errors, so a ball that excludes zero certifies a non-zero difference.

Elliptic functions take the parameter m = k² in both.
"""

from quasicentral.notation.balls import Unsupported, Work, arb_eval, ball_function, flint_precision  # noqa: F401
from quasicentral.notation.integrals import Prepared, period, prepare  # noqa: F401
from quasicentral.notation.jets import Jet, is_jet, jet_of, jet_symbol, to_jets  # noqa: F401
from quasicentral.notation.mpeval import (MPMATH_NAMES, close_infinite_sums, mp_eval, mp_function,  # noqa: F401
                                          mp_lambdify, mp_value, rung_function)
