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
from sympy.printing.pycode import MpmathPrinter

from quasicentral.notation.balls import (GUARD_BITS, Unsupported, Work, arb_to_mpf, ball_function, ball_value,
                                         compile_path, flint_precision, mp_to_acb)
from quasicentral.notation.integrals import infinite_end, prepare
from quasicentral.notation.series import geometric_sum
from quasicentral.notation.special import FUNCTIONS as SPECIAL_FUNCTIONS
from quasicentral.notation.timelimit import TimeLimitExceeded, time_limit

QUAD_MAX_PIECES = 64  # the most pieces mpmath's quadrature cuts a path into
QUAD_PIECES_GAIN = 100  # ... and the least gain in its error estimate for which it cuts further


def _quad(f, interval, singular: bool = False, omega=None):
    """mpmath.quad with guard digits.  An integrand singular at an endpoint (1/√(1 − ζ²))
    loses about half the working digits to cancellation in 1 − ζ next to it, so there
    (``singular``, or a non-finite value at an end) the precision is doubled; elsewhere ten
    guard digits suffice.  On an unbounded path an integrand that oscillates with the angular
    frequency ``omega`` (sin ωt/t, J₀(ωt)) goes to mpmath's ``quadosc``, which sums it period
    by period and extrapolates: tanh–sinh alone returns 5.42 for ∫₀^∞ sin t/t dt = π/2."""
    dps = mpmath.mp.dps
    a, b = interval
    unbounded = not (mpmath.isfinite(a) and mpmath.isfinite(b))
    for end in (a, b):
        if not mpmath.isfinite(end):
            continue
        try:
            with mpmath.workdps(15):
                val = f(end)
            singular = singular or not mpmath.isfinite(val)
        except (ValueError, ZeroDivisionError, TypeError, OverflowError):
            singular = True
    if unbounded:  # tanh–sinh maps a half-line (or the line) itself; no cutting into pieces
        with mpmath.workdps(2 * dps if singular else dps + 10):
            if omega is not None and mpmath.im(omega) == 0 and mpmath.re(omega) > 0:
                return +mpmath.quadosc(f, [a, b], omega=mpmath.re(omega))
            return +mpmath.quad(f, [a, b])
    # tanh–sinh on one interval misses oscillations over a long path (∫ sin² z … dz over
    # twenty radians is off in the 10th digit at 30 digits): where its error estimate exceeds
    # the working precision, the path is cut into more pieces — while cutting helps.  Where
    # four times the pieces do not gain QUAD_PIECES_GAIN in the estimate, the trouble is not
    # the path's length but a singularity inside it (a branch point of a root that turns
    # negative): more pieces would only cost time, and the value stands as it is, for the
    # precision ladder to judge
    with mpmath.workdps(2 * dps if singular else dps + 10):
        tol = mpmath.mpf(10) ** -dps
        pieces, before = 1, None
        while True:
            nodes = mpmath.linspace(a, b, pieces + 1) if pieces > 1 else [a, b]
            val, err = mpmath.quad(f, nodes, error=True)
            if err <= tol * max(abs(val), tol) or pieces >= QUAD_MAX_PIECES:
                break
            if before is not None and not err * QUAD_PIECES_GAIN <= before:
                break
            pieces, before = pieces * 4, err
    return +val


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
    "quad": _quad,
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
    and nobody reads it."""
    modules = modules or [dict(MPMATH_NAMES), "mpmath"]
    # the settings lambdify gives its own printer: the names of the tables' functions kept as
    # they are, looked up in the namespace at call time
    names = {k: k for m in modules if isinstance(m, dict) for k in m}
    printer = _Printer({"fully_qualified_modules": False, "inline": True, "allow_unknown_functions": True,
                        "user_functions": names})
    return sp.lambdify(args, expr, modules=modules, printer=printer, docstring_limit=0)


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
    and derivatives sympy could not carry out (a function without a closed derivative)."""
    if isinstance(expr, sp.Integral):
        return [expr] if all(len(lim) == 3 for lim in expr.limits) else []
    if isinstance(expr, (sp.Sum, sp.Product, sp.Limit, sp.Derivative)):
        return [expr]
    out: list = []
    for a in expr.args:
        out += [i for i in _outermost_forms(a) if i not in out]
    return out


# --- sums, products, limits and derivatives by numbers ---------------------------------------
#: terms a finite sum or product adds one by one; beyond, it is summed as a series
DIRECT_TERMS = 100_000
#: a series' or a limit's value stands where two ways of computing it agree to this fraction of
#: the working digits (else the point drops out: the precision ladder is not fooled by an
#: extrapolation that is stably wrong, as Richardson's is for a limit in √h)
AGREEMENT_FRACTION = 0.8


def _agreeing(a, b):
    """``a`` where it and ``b`` agree to AGREEMENT_FRACTION of the working digits, else ValueError."""
    tol = mpmath.mpf(10) ** (-AGREEMENT_FRACTION * mpmath.mp.dps)
    if not (mpmath.isfinite(a) and mpmath.isfinite(b)) or abs(a - b) > tol * max(abs(a), abs(b), tol):
        raise ValueError("no value the numbers agree on (a series or a limit that converges too slowly here)")
    return a


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
        return _agreeing(first, second)
    return value


def _limit(form, outer):
    body, var, point, side = form.args
    x = sp.Dummy("x")
    f = mp_function(body.xreplace({var: x}), (x,) + outer)
    at = mp_lambdify(outer, point)
    sides = {"+": (1,), "-": (-1,), "+-": (1, -1)}[str(side)]

    def value(*vals):
        vals = vals[:len(outer)]
        x0 = at(*vals)
        g = lambda t: f(t, *vals)  # noqa: E731
        direct = _continuous_value(g, x0, sides)
        if direct is None:
            direct = _small_steps(g, x0, sides)
        if direct is not None:
            return direct
        out = []
        for direction in sides:
            # Richardson's extrapolation (mpmath's default) and the exponential sequence
            # (exp=True) must agree: each alone can be stably wrong
            out.append(_agreeing(mpmath.limit(g, x0, direction=direction),
                                 mpmath.limit(g, x0, direction=direction, exp=True)))
        return _agreeing(out[0], out[-1])
    return value


def _continuous_value(g, x0, sides):
    """g(x0) where g is continuous there: finite at x0 and, a step h = 10^(−dps/3)·max(1, |x0|)
    away on each side of the limit, within 10^(−dps/4) (relative) of it — three evaluations
    instead of an extrapolation's hundreds (DLMF 22.5.1's limit at K + iK′: 37 s → 4 s for the entry).
    None where g is not evaluable at x0 (0/0, a pole) or jumps there: the sequences decide."""
    if not mpmath.isfinite(x0):
        return None
    dps = mpmath.mp.dps
    try:
        v0 = g(x0)
        if not mpmath.isfinite(v0):
            return None
        h = mpmath.mpf(10) ** (-dps // 3) * max(1, abs(x0))
        near = [g(x0 + side * h) for side in sides]
    except (ValueError, ZeroDivisionError, TypeError, OverflowError, ArithmeticError, mpmath.libmp.NoConvergence):
        return None
    tol = mpmath.mpf(10) ** (-dps // 4) * max(1, abs(v0))
    return v0 if all(mpmath.isfinite(v) and abs(v - v0) <= tol for v in near) else None


#: the step exponents of :func:`_small_steps`: h = 10^(−dps/2 − k)·max(1, |x0|), for each k
SMALL_STEPS = (1, 2)


def _small_steps(g, x0, sides):
    """The limit of g at x0 where g cannot be evaluated at x0 (0/0: sin(ω_d t)/ω_d at ω_d = 0)
    but is smooth on each side: Richardson's step-halving 2g(x0 + h/2) − g(x0 + h), whose error
    is O(h²), from two tiny steps h (:data:`SMALL_STEPS`) at twice the working precision; the
    sides and the steps must agree to :data:`AGREEMENT_FRACTION` of the working digits, else
    None and the sequences decide.  The sequences (x0 + 1/n) start a unit away, where a function
    such as e^(−γt)·cosh(…) is 10^30 times its limit and their extrapolation loses every digit."""
    if not mpmath.isfinite(x0):
        return None
    dps = mpmath.mp.dps
    tol = mpmath.mpf(10) ** (-AGREEMENT_FRACTION * dps)
    try:
        with mpmath.workdps(2 * dps + 10):
            found = []
            for side in sides:
                for k in SMALL_STEPS:
                    h = mpmath.mpf(10) ** (-(dps // 2 + k)) * max(1, abs(x0))
                    found.append(2 * g(x0 + side * h / 2) - g(x0 + side * h))
    except (ValueError, ZeroDivisionError, TypeError, OverflowError, ArithmeticError, mpmath.libmp.NoConvergence):
        return None
    if not all(mpmath.isfinite(v) for v in found):
        return None
    size = max(abs(v) for v in found)
    if any(abs(v - found[0]) > tol * size for v in found[1:]):
        return None
    return +found[-1]


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


def _nested_integral(form: sp.Integral, outer: tuple[sp.Symbol, ...]):
    """An integral over several variables (∫∫ f dt du, inner limits perhaps depending on the
    outer variable) as the integral over its outermost variable of the inner integral's value,
    each by quadrature at the working precision."""
    var, lo, hi = form.limits[-1]
    x = sp.Dummy("x")
    body = mp_function(_inner(form, var, x), (x,) + outer)
    bounds = mp_lambdify(outer, [lo, hi])

    def value(*vals):
        vals = vals[:len(outer)]
        a, b = bounds(*vals)
        return _quad(lambda z: body(z, *vals), [a, b])
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


#: functions with a jump or a kink where their argument crosses zero
_KINKED = (sp.Abs, sp.sign, sp.Heaviside)


def _breaks(f: sp.Expr, var: sp.Symbol) -> list:
    """Where ``f`` has a jump or a kink along its path: the zeros in ``var`` of the arguments of
    |·|, sign and Heaviside that sympy can solve (polynomials of degree ≤ 2 in the variable)."""
    out = []
    for g in f.atoms(*_KINKED):
        arg = g.args[0]
        if var in arg.free_symbols and arg.is_polynomial(var) and sp.degree(arg, var) <= 2:
            out += sp.solve(arg, var)
    return list(dict.fromkeys(out))


#: functions that oscillate in their last argument, with a period 2π/ω for an argument ωt + c
#: (the Bessel functions J, Y asymptotically)
_OSCILLATING = (sp.sin, sp.cos, sp.besselj, sp.bessely)


def _frequency(f: sp.Expr, var: sp.Symbol) -> sp.Expr | None:
    """The angular frequency ω with which ``f`` oscillates in ``var`` where every oscillating
    factor has an argument ωt + c with one and the same |ω| (None where there is none, or
    several: tanh–sinh then, and the precision ladder judges)."""
    found = set()
    for g in f.atoms(*_OSCILLATING):
        arg = g.args[-1]
        if var not in arg.free_symbols:
            continue
        if not arg.is_polynomial(var) or sp.degree(arg, var) != 1:
            return None
        found.add(sp.Abs(sp.diff(arg, var)))
    return found.pop() if len(found) == 1 else None


def _inside(c, a, b) -> bool:
    """Is the break ``c`` real and strictly between the ends (finite, in either order)?"""
    if not (mpmath.isfinite(c) and mpmath.isfinite(a) and mpmath.isfinite(b)):
        return False
    if abs(mpmath.im(c)) > 0 or mpmath.im(a) != 0 or mpmath.im(b) != 0:
        return False
    lo, hi = sorted((mpmath.re(a), mpmath.re(b)))
    return lo < mpmath.re(c) < hi


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
            omega = _frequency(integral.function, var) if infinite_end(integral) else None
            compiled.extend((mp_lambdify((x,) + params, integral.function.xreplace({var: x})),
                             mp_lambdify(params, lo), mp_lambdify(params, hi),
                             [mp_lambdify(params, r) for r in _breaks(integral.function, var)],
                             mp_lambdify(params, omega) if omega is not None else None))
        return compiled

    if ball is None:
        mpmath_form()  # the only way: compiled now, as every other part of the expression

    def compute(vals):
        if ball is not None:
            got = _ball_quadrature(ball, params, vals)
            if got is not None:
                return got
        body, lower, upper, breaks, frequency = mpmath_form()
        a, b = lower(*vals), upper(*vals)
        inner = sorted({mpmath.re(c) for c in (r(*vals) for r in breaks) if _inside(c, a, b)})
        if inner:  # a jump or a kink of the integrand: each smooth stretch on its own
            ends = [a, *inner, b] if a < b else [a, *reversed(inner), b]
            return mpmath.fsum(_quad(lambda z: body(z, *vals), [u, w], singular=singular) for u, w in zip(ends, ends[1:]))
        omega = frequency(*vals) if frequency is not None else None
        return _quad(lambda z: body(z, *vals), [a, b], singular=singular, omega=omega)

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
