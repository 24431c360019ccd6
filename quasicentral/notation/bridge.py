"""The one bridge from exact sympy to numbers: mpmath at any precision, python-flint balls.

* :func:`to_jets` replaces the motion's functions and their time derivatives by plain symbols
  (``x(t) -> x_t0``, ``x'(t) -> x_t1`` …): an identity among derivatives holds for all
  motions exactly when it holds for all values of these jets.
* :func:`mp_function` compiles an expression once with ``lambdify(modules=[table, "mpmath"])``;
  precision is whatever local ``mpmath.workdps`` the caller opens — nothing here sets it.
* :func:`arb_eval` evaluates an expression in complex ball arithmetic (python-flint ``acb``):
  the result's radius bounds all rounding and truncation errors, so a ball that excludes zero
  certifies a non-zero difference.  Elliptic functions take the parameter m = k² in both.
"""

from __future__ import annotations

from functools import lru_cache

import mpmath
import sympy as sp

from quasicentral.notation.timelimit import Deadline


#: sympy name -> mpmath function.  One table for the whole project.
def _quad(f, *intervals):
    """mpmath.quad with guard digits.  An integrand singular at an endpoint (1/√(1 − ζ²))
    loses about half the working digits to cancellation in 1 − ζ next to it, so there the
    precision is doubled; elsewhere ten guard digits suffice."""
    dps = mpmath.mp.dps
    (a, b), = intervals
    singular = False
    for end in (a, b):
        try:
            with mpmath.workdps(15):
                val = f(end)
            singular = singular or not mpmath.isfinite(val)
        except (ValueError, ZeroDivisionError, TypeError, OverflowError):
            singular = True
    with mpmath.workdps(2 * dps if singular else dps + 10):
        val = mpmath.quad(f, [a, b])
    return +val


MPMATH_NAMES = {
    "elliptic_k": mpmath.ellipk,
    "elliptic_f": mpmath.ellipf,
    "elliptic_e": mpmath.ellipe,
    "elliptic_pi": mpmath.ellippi,
    "quad": _quad,
}


def close_infinite_sums(expr: sp.Basic) -> sp.Basic:
    """Replace each infinite ``Sum`` by the closed form sympy finds for it (lambdify cannot
    evaluate an infinite sum, and ``mpmath.nsum`` loses accuracy near the radius of
    convergence); a sum sympy cannot close stays, and its evaluation then fails honestly."""
    def close(sm):
        if any(lim[2] in (sp.oo, -sp.oo) or lim[1] in (sp.oo, -sp.oo) for lim in sm.limits):
            done = sm.doit()
            # a Piecewise closed form whose "otherwise" branch keeps the Sum is fine: the
            # branch is evaluated only outside the region of convergence
            return sm if isinstance(done, sp.Sum) else done
        return sm

    return expr.replace(lambda e: isinstance(e, sp.Sum), close)


def _one_variable(f: sp.Basic) -> sp.Symbol | None:
    """The variable of an applied function of one symbol, ``x(t)`` → t; else None."""
    if isinstance(f, sp.core.function.AppliedUndef) and len(f.args) == 1 and isinstance(f.args[0], sp.Symbol):
        return f.args[0]
    return None


def to_jets(expr: sp.Basic) -> sp.Basic:
    """Evaluate derivatives of expressions, then name each function jet by a symbol: ``x(t)`` →
    ``x_t0``, ``x'(t)`` → ``x_t1``, ``u''(θ)`` → ``u_theta2`` (any independent variable)."""
    expr = expr.replace(lambda e: isinstance(e, sp.Derivative), lambda e: e.doit())
    repl = {}
    for d in expr.atoms(sp.Derivative):
        var = _one_variable(d.expr)
        if var is not None and {v for v, _ in d.variable_count} == {var}:
            repl[d] = jet_symbol(d.expr, d.derivative_count)
    expr = expr.xreplace(repl)
    repl = {f: jet_symbol(f, 0) for f in expr.atoms(sp.core.function.AppliedUndef) if _one_variable(f) is not None}
    return expr.xreplace(repl)


_JETS: dict[sp.Symbol, tuple[sp.Basic, int]] = {}


@lru_cache(maxsize=None)
def jet_symbol(f: sp.Basic, order: int) -> sp.Symbol:
    """The symbol standing for the ``order``-th derivative of ``f`` (positive where f's value is
    declared nonnegative; derivatives are real)."""
    name = f"{f.func.__name__}_{f.args[0].name}{order}"
    sym = sp.Symbol(name, positive=True) if order == 0 and f.is_nonnegative else sp.Symbol(name, real=True)
    _JETS[sym] = (f, order)
    return sym


def is_jet(sym: sp.Basic) -> bool:
    return sym in _JETS


def jet_of(sym: sp.Symbol) -> tuple[sp.Basic, int]:
    """The function and derivative order a jet symbol stands for."""
    return _JETS[sym]


def mp_function(expr: sp.Basic, args: tuple[sp.Symbol, ...]):
    """Compile ``expr`` for mpmath (cached by the caller)."""
    return sp.lambdify(args, expr, modules=[MPMATH_NAMES, "mpmath"])


def mp_value(value: sp.Expr, dps: int):
    """An exact sympy number as an mpmath number at ``dps`` digits (plus guard digits)."""
    num = sp.N(value, dps + 10)
    if num.is_real:
        return mpmath.mpf(sp.Float(num, dps + 10)._mpf_)
    re, im = num.as_real_imag()
    return mpmath.mpc(sp.Float(re, dps + 10)._mpf_, sp.Float(im, dps + 10)._mpf_)


def mp_eval(expr: sp.Basic, point: dict[sp.Symbol, sp.Expr], dps: int):
    """Value of ``expr`` at an exact ``point`` with ``dps`` significant digits (local context)."""
    args = tuple(sorted(expr.free_symbols, key=str))
    fn = mp_function(expr, args)
    with mpmath.workdps(dps):
        vals = [mp_value(point[a], dps) for a in args]
        return +fn(*vals)


# --- python-flint balls ---------------------------------------------------------------------
class Unsupported(Exception):
    """The expression has a node the ball evaluator does not handle."""


def arb_eval(expr: sp.Basic, point: dict[sp.Symbol, sp.Expr], prec: int = 256, seconds: float | None = None):
    """Evaluate in ``flint.acb`` at ``prec`` bits; returns an acb ball.  Raises
    :class:`Unsupported` for nodes it cannot bound rigorously.  ``seconds`` bounds the time
    of CPU time spent in ball integrals: past it their integrands return NaN balls, so the
    result is simply not finite (flint's integrator cannot be interrupted by an exception).
    CPU time, not wall time, so that the outcome does not depend on the machine's load."""
    import flint

    old = flint.ctx.prec
    flint.ctx.prec = prec
    deadline = Deadline.after(seconds)
    try:
        env = {sym: _acb_exact(val, deadline) for sym, val in point.items()}
        return _arb(expr, env, False, deadline)
    finally:
        flint.ctx.prec = old


def _acb_exact(val: sp.Expr, deadline: Deadline):
    import flint

    val = sp.nsimplify(val) if not val.is_number else val
    if val.is_Rational:
        return flint.acb(flint.arb(flint.fmpq(int(val.p), int(val.q))))
    # exact expressions of pi, sqrt, … : evaluate rigorously through the same walker
    return _arb(val, {}, False, deadline)


def _arb(e: sp.Basic, env: dict, analytic: bool, deadline: Deadline):  # noqa: C901 - one dispatch table
    import flint

    acb = flint.acb
    if e in env:
        return env[e]
    if e.is_Rational:
        return acb(flint.arb(flint.fmpq(int(e.p), int(e.q))))
    if e is sp.pi:
        return acb(flint.arb.pi())
    if e is sp.E:
        return acb(1).exp()
    if e is sp.I:
        return acb(0, 1)
    if isinstance(e, sp.Add):
        out = acb(0)
        for a in e.args:
            out += _arb(a, env, analytic, deadline)
        return out
    if isinstance(e, sp.Mul):
        out = acb(1)
        for a in e.args:
            out *= _arb(a, env, analytic, deadline)
        return out
    if isinstance(e, sp.Pow):
        base = _arb(e.base, env, analytic, deadline)
        ex = e.exp
        if ex.is_Integer:
            return base ** int(ex)
        if ex == sp.Rational(1, 2):
            return base.sqrt(analytic=analytic)
        if ex == -sp.Rational(1, 2):
            return 1 / base.sqrt(analytic=analytic)
        if ex.is_Rational:
            return base.sqrt(analytic=analytic) ** int(2 * ex) if (2 * ex).is_Integer else (
                (base.log(analytic=analytic) * _arb(ex, env, analytic, deadline)).exp())
        return (base.log(analytic=analytic) * _arb(ex, env, analytic, deadline)).exp()
    unary = {
        sp.sin: lambda a: a.sin(), sp.cos: lambda a: a.cos(), sp.tan: lambda a: a.tan(),
        sp.exp: lambda a: a.exp(), sp.atan: lambda a: a.atan(),
        sp.log: lambda a: a.log(analytic=analytic), sp.asin: lambda a: a.asin(),
        sp.acos: lambda a: a.acos(), sp.sinh: lambda a: a.sinh(), sp.cosh: lambda a: a.cosh(),
        sp.acot: lambda a: (1 / a).atan(),
    }
    if e.func in unary:
        return unary[e.func](_arb(e.args[0], env, analytic, deadline))
    if isinstance(e, sp.Abs):
        a = _arb(e.args[0], env, analytic, deadline)
        return acb(a.abs())
    if isinstance(e, sp.elliptic_k):
        return acb.elliptic_k(_arb(e.args[0], env, analytic, deadline))
    if isinstance(e, sp.elliptic_f):
        return acb.elliptic_f(_arb(e.args[0], env, analytic, deadline), _arb(e.args[1], env, analytic, deadline))
    if isinstance(e, sp.elliptic_e):
        if len(e.args) == 1:
            return acb.elliptic_e(_arb(e.args[0], env, analytic, deadline))
        return acb.elliptic_e_inc(_arb(e.args[0], env, analytic, deadline), _arb(e.args[1], env, analytic, deadline))
    if isinstance(e, sp.factorial) and e.args[0].is_Integer:
        return acb(int(sp.factorial(e.args[0])))
    if isinstance(e, sp.Integral) and len(e.limits) == 1 and len(e.limits[0]) == 3:
        var, lo, hi = e.limits[0]
        a, b = _arb(lo, env, analytic, deadline), _arb(hi, env, analytic, deadline)
        body = e.function
        for end in (a, b):
            # flint's integrator needs the integrand analytic on the whole path: at an integrable
            # endpoint singularity (1/√(1 − ζ²) at ζ = 1) it only returns a non-finite ball, after
            # seconds of subdivision — say so at once instead
            try:
                finite = _arb(body, {**env, var: end}, False, deadline).is_finite()
            except ZeroDivisionError:
                finite = False
            if not finite:
                raise Unsupported("the integrand is unbounded at an end of the path")

        def f(zz, an):
            if deadline.expired():
                return acb("nan")
            return _arb(body, {**env, var: zz}, an, deadline)

        return acb.integral(f, a, b)
    raise Unsupported(f"no ball evaluation for {e.func.__name__}")
