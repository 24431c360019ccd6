"""mpmath at any precision: expressions compiled once (lambdify through one printer and one
table of function names), definite integrals by quadrature (python-flint's Gauss–Legendre
first, mpmath's tanh–sinh where its ball does not hold every working bit), and the rung
functions of a precision ladder (balls first, mpmath where a ball does not suffice).
Precision is whatever local ``mpmath.workdps`` the caller opens — nothing here sets it.
"""

from __future__ import annotations

from functools import lru_cache
from types import MappingProxyType

import mpmath
import sympy as sp
from sympy.codegen.cfunctions import expm1, log1p
from sympy.printing.pycode import MpmathPrinter

from quasicentral.notation.balls import (GUARD_BITS, Unsupported, Work, arb_to_mpf, ball_function, ball_value,
                                         compile_path, flint_precision, mp_to_acb)
from quasicentral.notation.integrals import infinite_end, prepare
from quasicentral.notation.limits import agreeing, limit_value
from quasicentral.notation.roots import Root, root_in
from quasicentral.notation.quadrature import breaks, frequency, inside, quad
from quasicentral.notation.series import geometric_sum
from quasicentral.notation.special import FUNCTIONS as SPECIAL_FUNCTIONS
from quasicentral.notation.timelimit import TimeLimitExceeded, time_limit


def _ball_first(complete: str | None, incomplete: str | None, fallback):
    """An elliptic function with mpmath's signature (parameter m = k², as in mpmath, flint and
    sympy): python-flint's ``acb`` method ``complete`` (one argument, m) or ``incomplete`` (φ, m)
    — C, 20–50 times faster than mpmath's Carlson forms at 30–60 digits — where every argument
    is real with m < 1, so that the value is real off every branch cut, and its ball holds every
    bit of the working precision; else mpmath's own ``fallback``."""
    def f(*args):
        name = complete if len(args) == 1 else incomplete if len(args) == 2 else None
        vals = [mpmath.mpmathify(a) for a in args]
        if name and all(isinstance(v, mpmath.mpf) and mpmath.isfinite(v) for v in vals) and vals[-1] < 1:
            import flint

            prec = mpmath.mp.prec
            with flint_precision(prec + GUARD_BITS):
                r = getattr(flint.acb, name)(*[mp_to_acb(v) for v in vals])
                if r.is_finite() and r.imag == 0 and r.real.rel_accuracy_bits() >= prec:
                    return +arb_to_mpf(r.real.mid())
        return fallback(*args)
    return f


#: sympy name -> mpmath-callable function.  One table for the whole project.  Elliptic functions
#: take the parameter m = k².
MPMATH_NAMES = MappingProxyType({
    "elliptic_k": _ball_first("elliptic_k", None, mpmath.ellipk),
    "elliptic_f": _ball_first(None, "elliptic_f", mpmath.ellipf),
    "elliptic_e": _ball_first("elliptic_e", "elliptic_e_inc", mpmath.ellipe),
    "elliptic_pi": mpmath.ellippi,  # real only for some n, φ, m: mpmath decides
    "quad": quad,
    # DLMF chapters 19, 20 and 22: each class evaluates itself (modulus k, guard bits inside)
    **{name: cls.mp for name, cls in SPECIAL_FUNCTIONS.items()},
})


class _Printer(MpmathPrinter):
    """sympy's mpmath printer, with the terms of a sum and the factors of a product in the
    order of the expression's arguments (sympy's own order, the same in every process) instead
    of sorted anew for display — a third of lambdify's time went into that sort; the value is
    the same sum, rounded at the last working bit — and sinc as mpmath's ``sinc`` (1 at 0)
    instead of sin(x)/x, which fails there."""

    _default_settings = {**MpmathPrinter._default_settings, "order": "none"}

    def _print_sinc(self, e):
        return f"sinc({self._print(e.args[0])})"


def mp_lambdify(args, expr, modules=None):
    """``sympy.lambdify`` for mpmath (the table above, then mpmath) through :class:`_Printer`,
    without the docstring: printing the expression into it costs a fifth of lambdify's time,
    and nobody reads it; eˣ − 1 and ln(1 + x) as expm1 and log1p."""
    modules = modules or [dict(MPMATH_NAMES), "mpmath"]
    # the settings lambdify gives its own printer: the names of the tables' functions kept as
    # they are, looked up in the namespace at call time
    names = {k: k for m in modules if isinstance(m, dict) for k in m}
    printer = _Printer({"fully_qualified_modules": False, "inline": True, "allow_unknown_functions": True,
                        "user_functions": names})
    if isinstance(expr, sp.Basic) and expr.has(sp.exp, sp.log):
        expr = _without_cancellation(expr)
    return sp.lambdify(args, expr, modules=modules, printer=printer, docstring_limit=0)


def _without_cancellation(expr: sp.Basic) -> sp.Basic:
    """eˣ − 1 and ln(1 + x) as expm1 and log1p: for a small x they cancel every working digit
    (hν/kT at ν → 0 in Planck's law divided by zero at 60 digits).  By hand, on the sums that
    hold exactly such a pair: sympy's codegen ``optimize`` (expm1_opt) factors the whole
    expression first, which never ended on a divergence test's integrand."""
    def is_pair(e) -> bool:
        return isinstance(e, sp.Add) and any(a == -1 for a in e.args) and any(isinstance(a, sp.exp) for a in e.args)

    def pair(e):
        first = next(a for a in e.args if isinstance(a, sp.exp))
        rest = list(e.args)
        rest.remove(first)
        rest.remove(sp.Integer(-1))
        return sp.Add(expm1(first.args[0]), *rest, evaluate=False)

    def is_log1p(e) -> bool:
        return isinstance(e, sp.log) and isinstance(e.args[0], sp.Add) and any(a == 1 for a in e.args[0].args)

    def log_1p(e):
        rest = list(e.args[0].args)
        rest.remove(sp.Integer(1))
        return log1p(sp.Add(*rest))
    return expr.replace(is_pair, pair).replace(is_log1p, log_1p)


def close_infinite_sums(expr: sp.Basic) -> sp.Basic:
    """Replace each infinite ``Sum`` by the closed form sympy finds for it (lambdify cannot
    evaluate an infinite sum, and ``mpmath.nsum`` loses accuracy near the radius of
    convergence); a sum sympy cannot close stays, and its evaluation then fails honestly."""
    # replace() walks and rebuilds the whole tree: only where there is a sum to close
    return expr.replace(lambda e: isinstance(e, sp.Sum), _closed_sum) if expr.has(sp.Sum) else expr


#: CPU seconds sympy may spend closing one infinite sum; past them it is summed numerically
SUMMATION_SECONDS = 2.0


@lru_cache(maxsize=1024)
def _closed_sum(sm: sp.Sum) -> sp.Basic:
    """One infinite sum's closed form (sympy's summation takes ~0.5 s: each is done once); a sum
    sympy does not close within :data:`SUMMATION_SECONDS` is summed numerically
    (:func:`_series`)."""
    if any(lim[2] in (sp.oo, -sp.oo) or lim[1] in (sp.oo, -sp.oo) for lim in sm.limits):
        try:
            with time_limit(SUMMATION_SECONDS) as limit:
                done = sm.doit()
        except TimeLimitExceeded as exc:
            if limit is None or not limit.owns(exc):
                raise
            return sm
        except Exception:  # noqa: BLE001 - sympy's summation failing leaves the sum to the numbers
            return sm
        # a Piecewise closed form whose "otherwise" branch keeps the Sum is fine: the
        # branch is evaluated only outside the region of convergence
        return sm if isinstance(done, sp.Sum) or done.has(sp.nan, sp.zoo) else done
    return sm


@lru_cache(maxsize=1024)
def mp_function(expr: sp.Basic, args: tuple[sp.Symbol, ...]):
    """Compile ``expr`` for mpmath (remembered: an erratum's printed and corrected forms share
    their derived side, and a mutation run compiles it for every mutant).  Each definite integral becomes a
    call of :func:`_quadrature` (flint's Gauss–Legendre where it reaches the working precision,
    else mpmath's tanh–sinh)."""
    table = dict(MPMATH_NAMES)
    placeholders = {}
    for form in _outermost_forms(expr):
        name = f"form{len(placeholders)}"
        outer = tuple(sorted(form.free_symbols, key=str))
        if isinstance(form, sp.Integral):
            table[name] = _quadrature(form, outer) if len(form.limits) == 1 else _nested_integral(form, outer)
        else:
            table[name] = _numeric_form(form, outer)
        placeholders[form] = sp.Function(name)(*outer) if outer else sp.Function(name)(sp.Integer(0))
    return mp_lambdify(args, expr.xreplace(placeholders), modules=[table, "mpmath"])


def _outermost_forms(expr: sp.Basic) -> list[sp.Basic]:
    """The outermost parts of ``expr`` that lambdify cannot print as a call: definite integrals
    (of one variable each: nested ones are integrals of integrals), sums and products, limits,
    derivatives sympy could not carry out (a function without a closed derivative) and roots
    defined implicitly (:class:`~quasicentral.notation.roots.Root`)."""
    if isinstance(expr, sp.Integral):
        return [expr] if all(len(lim) == 3 for lim in expr.limits) else []
    if isinstance(expr, (sp.Sum, sp.Product, sp.Limit, sp.Derivative, Root)):
        return [expr]
    out: list = []
    for a in expr.args:
        out += [i for i in _outermost_forms(a) if i not in out]
    return out


# --- sums, products, limits and derivatives by numbers ---------------------------------------
#: terms a finite sum or product adds one by one; beyond, it is summed as a series
DIRECT_TERMS = 100_000
def _integer(v) -> int:
    """A bound of a sum that must be an integer."""
    n = mpmath.nint(v)
    if abs(v - n) > mpmath.mpf(10) ** (-mpmath.mp.dps // 2):
        raise ValueError(f"a bound of a sum or product is not an integer: {v}")
    return int(n)


def _numeric_form(form: sp.Basic, outer: tuple[sp.Symbol, ...]):
    """An mpmath-callable value of a sum, product, limit or derivative at the values of
    ``outer`` (its free symbols), its body compiled once (:func:`mp_function`, so that what
    it holds — an integral, another sum — is handled the same way)."""
    if isinstance(form, (sp.Sum, sp.Product)):
        return _series(form, outer)
    if isinstance(form, sp.Limit):
        return _limit(form, outer)
    if isinstance(form, Root):
        return _root(form, outer)
    return _derivative(form, outer)


def _inner(form: sp.Basic, var: sp.Symbol, dummy: sp.Dummy) -> sp.Basic:
    """The body of a sum, product or integral over its outermost limit, ``var`` renamed: the
    form over its other limits (sympy writes Σ_n Σ_j f as one Sum of two limits, and would
    flatten a rebuilt nest again), compiled on its own by :func:`mp_function`."""
    body = type(form)(form.function, *form.limits[:-1]) if len(form.limits) > 1 else form.function
    return body.xreplace({var: dummy})


def _series(form, outer):
    var, lo, hi = form.limits[-1]
    n = sp.Dummy("n")
    term = mp_function(_inner(form, var, n), (n,) + outer)
    bounds = mp_lambdify(outer, [lo, hi])
    product = isinstance(form, sp.Product)

    def value(*vals):
        vals = vals[:len(outer)]
        a, b = bounds(*vals)
        f = lambda k: term(mpmath.mpf(k), *vals)  # noqa: E731 - an mpf index: 1/j is no float division
        infinite = not (mpmath.isfinite(a) and mpmath.isfinite(b))
        if not infinite and abs(_integer(b) - _integer(a)) <= DIRECT_TERMS:
            ks = range(_integer(a), _integer(b) + 1)
            return mpmath.fprod(f(k) for k in ks) if product else mpmath.fsum(f(k) for k in ks)
        interval = [a if not mpmath.isfinite(a) else _integer(a), b if not mpmath.isfinite(b) else _integer(b)]
        if not product:
            direct = geometric_sum(f, *interval)
            if direct is not None:
                return direct
        total = mpmath.nprod if product else mpmath.nsum
        first = total(f, interval)
        with mpmath.workdps(mpmath.mp.dps + 10):
            second = total(f, interval)
        return agreeing(first, second)
    return value


def _root(form, outer):
    x = sp.Dummy("x")
    f = mp_function(form.function.xreplace({form.variable: x}), (x,) + outer)
    bracket = mp_lambdify(outer, [form.low, form.high])

    def value(*vals):
        vals = vals[:len(outer)]
        a, b = bracket(*vals)
        return root_in(lambda t: f(t, *vals), a, b)
    return value


def _limit(form, outer):
    body, var, point, side = form.args
    x = sp.Dummy("x")
    f = mp_function(body.xreplace({var: x}), (x,) + outer)
    at = mp_lambdify(outer, point)
    sides = {"+": (1,), "-": (-1,), "+-": (1, -1)}[str(side)]

    def value(*vals):
        vals = vals[:len(outer)]
        return limit_value(lambda t: f(t, *vals), at(*vals), sides)
    return value


def _derivative(form, outer):
    counts = [(v, int(c)) for v, c in form.variable_count]
    dummies = tuple(sp.Dummy(f"d{i}") for i in range(len(counts)))
    body = mp_function(form.expr.xreplace({v: d for (v, _), d in zip(counts, dummies)}), dummies + outer)
    where = [outer.index(v) for v, _ in counts]
    orders = tuple(c for _, c in counts)

    def value(*vals):
        vals = vals[:len(outer)]
        at = tuple(vals[i] for i in where)
        return mpmath.diff(lambda *ds: body(*ds, *vals), at if len(at) > 1 else at[0],
                           orders if len(orders) > 1 else orders[0])
    return value


#: CPU seconds sympy may spend on the inner integral of a nested one in closed form
INNER_CLOSED_SECONDS = 3.0


def _closed_inner(inner: sp.Integral) -> sp.Expr | None:
    """The inner integral of a nested one in closed form, where sympy finds one free of
    integrals and of case distinctions within :data:`INNER_CLOSED_SECONDS` (None else).  Only a
    candidate: :func:`_nested_integral` uses it where it agrees with the inner quadrature."""
    try:
        with time_limit(INNER_CLOSED_SECONDS) as limit:
            done = inner.doit(conds="none")
    except TimeLimitExceeded as exc:
        if limit is None or not limit.owns(exc):
            raise
        return None
    except Exception:  # noqa: BLE001 - sympy's integrator failing is only no closed form
        return None
    if done.has(sp.Integral, sp.Piecewise, sp.nan, sp.zoo, sp.oo, -sp.oo):
        return None
    return done


def _nested_integral(form: sp.Integral, outer: tuple[sp.Symbol, ...]):
    """An integral over several variables (∫∫ f dt du, inner limits perhaps depending on the
    outer variable) as the integral over its outermost variable of the inner integral's value,
    by quadrature at the working precision — an oscillating integrand on an unbounded outer path
    through quadosc, as a single integral's.  Where sympy gives the inner integral in closed form
    (:func:`_closed_inner`) and that form agrees with the inner quadrature to
    :data:`~quasicentral.notation.limits.AGREEMENT_FRACTION` of the working digits at a point of the path, the outer quadrature
    integrates the closed form: ∫₀^∞∫₀^∞ e^{−γ(t+s)} cos ω(t − s) ds dt is a quadosc of a
    quadosc (minutes at 30 digits) by quadrature alone, one quadosc with the inner closed form
    (milliseconds); a closed form that disagrees (a sympy integral valid on other parameters
    only) is never used."""
    var, lo, hi = form.limits[-1]
    x = sp.Dummy("x")
    inner = _inner(form, var, x)
    body = mp_function(inner, (x,) + outer)
    bounds = mp_lambdify(outer, [lo, hi])
    unbounded = any(end in (sp.oo, -sp.oo) for end in (lo, hi))
    omega = frequency(form.function, var) if unbounded else None
    rate = mp_lambdify(outer, omega) if omega is not None else None
    closed = _closed_inner(inner) if isinstance(inner, sp.Integral) else None
    fast = mp_function(closed, (x,) + outer) if closed is not None else None
    trusted: dict = {}  # point -> whether the closed form agreed there

    def integrand(a, b, vals):
        # checked at each point (at the first precision it is met at: the points of a ladder are
        # binary numbers, the same at every rung): a form sympy found for some parameters only
        # (its conditions dropped) may agree at one point and not at the next
        if fast is None:
            return body
        key = vals
        if key not in trusted:
            # at three places along the outer path: a form valid on part of it only (its
            # conditions dropped depend on the outer variable) disagrees at one of them
            if mpmath.isfinite(a) and mpmath.isfinite(b):
                zs = [a + (b - a) * mpmath.mpf(f) for f in ("0.25", "0.5", "0.75")]
            else:
                start, sign = (a, 1) if mpmath.isfinite(a) else (b, -1) if mpmath.isfinite(b) else (mpmath.mpf(0), 1)
                zs = [start + sign * mpmath.mpf(d) for d in ("0.5", "2", "8")]
            try:
                trusted[key] = all(agreeing(fast(z, *vals), body(z, *vals)) is not None for z in zs)
            except (ValueError, ZeroDivisionError, TypeError, OverflowError):
                trusted[key] = False
        return fast if trusted[key] else body

    def value(*vals):
        vals = vals[:len(outer)]
        a, b = bounds(*vals)
        f = integrand(a, b, vals)
        w = rate(*vals) if rate is not None else None
        return quad(lambda z: f(z, *vals), [a, b], omega=w)
    return value


# integrand evaluations flint may spend before mpmath takes over: at least QUADRATURE_EVALUATIONS,
# and QUADRATURE_EVALUATIONS_PER_BIT per bit of working precision — Gauss–Legendre needs about
# 35 per bit on a long oscillating path (4 200 evaluations at 120 bits, 21 300 at 600 for four
# periods of √(a sin² + b cos²)·sin²), where mpmath's tanh–sinh then takes 20–30 times as long
QUADRATURE_EVALUATIONS = 20_000
QUADRATURE_EVALUATIONS_PER_BIT = 50
def _quadrature(integral: sp.Integral, outer: tuple[sp.Symbol, ...]):
    """An mpmath-callable value of ``integral`` at the values of ``outer`` (its free symbols),
    at the precision in force: its parameters computed once, then the sum over its pieces
    (:func:`prepare`)."""
    prep = prepare(integral)
    names = tuple(d for d, _ in prep.params)
    param_values = mp_lambdify(outer, [e for _, e in prep.params])
    pieces = [_piece_quadrature(piece, names, singular) for piece, singular in zip(prep.pieces, prep.singular)]

    def value(*vals):
        # at the precision of a singular path's quadrature: its integrand may cancel a parameter
        # (cos φ − cos φ₀ next to φ₀)
        with mpmath.workdps(2 * mpmath.mp.dps + 10):
            pv = param_values(*vals[:len(outer)])
        return mpmath.fsum(piece(*pv) for piece in pieces) if len(pieces) > 1 else pieces[0](*pv)
    return value


@lru_cache(maxsize=2048)
def _piece_quadrature(integral: sp.Integral, params: tuple[sp.Dummy, ...], singular: bool):
    """One piece's value at the values of its parameters (one function per piece, so that its
    values are remembered across every expression it occurs in).  First python-flint's ball
    integration at the working precision plus guard bits: for an integrand analytic along the
    path it converges in a few hundred evaluations, and its ball says whether every working bit
    is right.  Where it does not (no ball form, an endpoint singularity, an infinite end, too
    much subdivision) mpmath's quadrature (:func:`_quad`) computes the value."""
    try:
        ball = compile_path(integral) if not infinite_end(integral) else None
    except Unsupported:
        ball = None
    remembered: dict = {}
    var, lo, hi = integral.limits[0]
    compiled: list = []  # mpmath's integrand and limits, compiled when first needed

    def mpmath_form():
        if not compiled:
            x = sp.Dummy("x")  # the variable may also be a limit: ∫_0^t f(t) dt
            omega = frequency(integral.function, var) if infinite_end(integral) else None
            compiled.extend((mp_lambdify((x,) + params, integral.function.xreplace({var: x})),
                             mp_lambdify(params, lo), mp_lambdify(params, hi),
                             [mp_lambdify(params, r) for r in breaks(integral.function, var)],
                             mp_lambdify(params, omega) if omega is not None else None))
        return compiled

    if ball is None:
        mpmath_form()  # the only way: compiled now, as every other part of the expression

    def compute(vals):
        if ball is not None:
            got = _ball_quadrature(ball, params, vals)
            if got is not None:
                return got
        body, lower, upper, jumps, rate = mpmath_form()
        a, b = lower(*vals), upper(*vals)
        inner = sorted({mpmath.re(c) for c in (r(*vals) for r in jumps) if inside(c, a, b)})
        if inner:  # a jump or a kink of the integrand: each smooth stretch on its own
            ends = [a, *inner, b] if a < b else [a, *reversed(inner), b]
            return mpmath.fsum(quad(lambda z: body(z, *vals), [u, w], singular=singular) for u, w in zip(ends, ends[1:]))
        omega = rate(*vals) if rate is not None else None
        return quad(lambda z: body(z, *vals), [a, b], singular=singular, omega=omega)

    def value(*vals):
        # remembered: a printed integral that is also the derived one (or an erratum's printed
        # and corrected forms) meets the same piece at the same point and precision — about a
        # quarter of a verification's quadratures.  The piece's parameters are its own dummies
        # (prepare), so equal keys are the same integral at the same values
        key = (vals, mpmath.mp.prec)
        if key not in remembered:
            if len(remembered) >= QUADRATURES_REMEMBERED:
                remembered.clear()
            remembered[key] = compute(vals)
        return remembered[key]
    value.computed = remembered  # for tests: what this piece has computed
    return value


QUADRATURES_REMEMBERED = 20_000  # values of one piece kept in one process


def _ball_quadrature(ball, outer, vals):
    """flint's value of a compiled integral, or None where it does not hold every bit of the
    working precision."""
    budget = max(QUADRATURE_EVALUATIONS, QUADRATURE_EVALUATIONS_PER_BIT * (mpmath.mp.prec + GUARD_BITS))
    return ball_value(ball, outer, vals, Work(budget, smooth_ends=True))


@lru_cache(maxsize=1024)
def rung_function(expr: sp.Basic, args: tuple[sp.Symbol, ...]):
    """``expr`` compiled for the rungs of a precision ladder: a function of mpmath values, like
    :func:`mp_function`'s, that computes in python-flint balls first — 2 to 100 times faster
    than mpmath (measured: the more so, the longer the expression), and every bit of the value
    it returns is guaranteed — and in mpmath (compiled only when first needed) wherever the ball does not hold every working bit or has no ball form (floor, a
    function known by its numbers only).  An expression with an integral keeps
    :func:`mp_function`, whose quadratures are ball-first piece by piece and remembered."""
    if expr.has(sp.Integral):
        return mp_function(expr, args)
    try:
        ball = ball_function(expr)
    except Unsupported:
        return mp_function(expr, args)

    def value(*vals):
        got = ball_value(ball, args, vals, Work())
        return got if got is not None else mp_function(expr, args)(*vals)
    return value


def mp_value(value: sp.Expr, dps: int):
    """An exact sympy number as an mpmath number at ``dps`` digits (plus guard digits)."""
    if value.is_Rational:  # most points: rounded as sp.N would, without its evaluation machinery
        from mpmath.libmp import dps_to_prec, from_rational

        return mpmath.mpf(from_rational(int(value.p), int(value.q), dps_to_prec(dps + 10), "n"))
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
