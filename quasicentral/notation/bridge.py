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

from dataclasses import dataclass
from functools import lru_cache

import mpmath
import sympy as sp
from sympy.printing.pycode import MpmathPrinter
from sympy.simplify.fu import TR9


QUAD_MAX_PIECES = 64  # the most pieces mpmath's quadrature cuts a path into
QUAD_PIECES_GAIN = 100  # ... and the least gain in its error estimate for which it cuts further


def _quad(f, interval, singular: bool = False):
    """mpmath.quad with guard digits.  An integrand singular at an endpoint (1/√(1 − ζ²))
    loses about half the working digits to cancellation in 1 − ζ next to it, so there
    (``singular``, or a non-finite value at an end) the precision is doubled; elsewhere ten
    guard digits suffice."""
    dps = mpmath.mp.dps
    a, b = interval
    for end in (a, b):
        try:
            with mpmath.workdps(15):
                val = f(end)
            singular = singular or not mpmath.isfinite(val)
        except (ValueError, ZeroDivisionError, TypeError, OverflowError):
            singular = True
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
            old = flint.ctx.prec
            flint.ctx.prec = prec + QUADRATURE_GUARD_BITS
            try:
                r = getattr(flint.acb, name)(*[_mp_to_acb(v) for v in vals])
                if r.is_finite() and r.imag == 0 and r.real.rel_accuracy_bits() >= prec:
                    return +_arb_to_mpf(r.real.mid())
            finally:
                flint.ctx.prec = old
        return fallback(*args)
    return f


#: sympy name -> mpmath-callable function.  One table for the whole project.  Elliptic functions
#: take the parameter m = k².
MPMATH_NAMES = {
    "elliptic_k": _ball_first("elliptic_k", None, mpmath.ellipk),
    "elliptic_f": _ball_first(None, "elliptic_f", mpmath.ellipf),
    "elliptic_e": _ball_first("elliptic_e", "elliptic_e_inc", mpmath.ellipe),
    "elliptic_pi": mpmath.ellippi,  # real only for some n, φ, m: mpmath decides
    "quad": _quad,
}


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
    modules = modules or [MPMATH_NAMES, "mpmath"]
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


@lru_cache(maxsize=1024)
def _closed_sum(sm: sp.Sum) -> sp.Basic:
    """One infinite sum's closed form (sympy's summation takes ~0.5 s: each is done once)."""
    if any(lim[2] in (sp.oo, -sp.oo) or lim[1] in (sp.oo, -sp.oo) for lim in sm.limits):
        done = sm.doit()
        # a Piecewise closed form whose "otherwise" branch keeps the Sum is fine: the
        # branch is evaluated only outside the region of convergence
        return sm if isinstance(done, sp.Sum) else done
    return sm


def _one_variable(f: sp.Basic) -> sp.Symbol | None:
    """The variable of an applied function of one symbol, ``x(t)`` → t; else None."""
    if isinstance(f, sp.core.function.AppliedUndef) and len(f.args) == 1 and isinstance(f.args[0], sp.Symbol):
        return f.args[0]
    return None


def to_jets(expr: sp.Basic) -> sp.Basic:
    """Evaluate derivatives of expressions, then name each function jet by a symbol: ``x(t)`` →
    ``x_t0``, ``x'(t)`` → ``x_t1``, ``u''(θ)`` → ``u_theta2`` (any independent variable)."""
    if expr.has(sp.Derivative):
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


@lru_cache(maxsize=1024)
def mp_function(expr: sp.Basic, args: tuple[sp.Symbol, ...]):
    """Compile ``expr`` for mpmath (remembered: an erratum's printed and corrected forms share
    their derived side, and a mutation run compiles it for every mutant).  Each definite integral becomes a
    call of :func:`_quadrature` (flint's Gauss–Legendre where it reaches the working precision,
    else mpmath's tanh–sinh)."""
    table = dict(MPMATH_NAMES)
    placeholders = {}
    for integral in _outermost_integrals(expr):
        name = f"quadrature{len(placeholders)}"
        outer = tuple(sorted(integral.free_symbols, key=str))
        table[name] = _quadrature(integral, outer)
        placeholders[integral] = sp.Function(name)(*outer) if outer else sp.Function(name)(sp.Integer(0))
    return mp_lambdify(args, expr.xreplace(placeholders), modules=[table, "mpmath"])


def _outermost_integrals(expr: sp.Basic) -> list[sp.Integral]:
    if isinstance(expr, sp.Integral):
        return [expr] if len(expr.limits) == 1 and len(expr.limits[0]) == 3 else []
    out: list = []
    for a in expr.args:
        out += [i for i in _outermost_integrals(a) if i not in out]
    return out


# integrand evaluations flint may spend before mpmath takes over: at least QUADRATURE_EVALUATIONS,
# and QUADRATURE_EVALUATIONS_PER_BIT per bit of working precision — Gauss–Legendre needs about
# 35 per bit on a long oscillating path (4 200 evaluations at 120 bits, 21 300 at 600 for four
# periods of √(a sin² + b cos²)·sin²), where mpmath's tanh–sinh then takes 20–30 times as long
QUADRATURE_EVALUATIONS = 20_000
QUADRATURE_EVALUATIONS_PER_BIT = 50
QUADRATURE_GUARD_BITS = 20
SMOOTH_END_RADIUS = 2.0 ** -30  # the disc around an end of the path that must be free of singularities


def _singular(value: sp.Basic) -> bool:
    return value.has(sp.zoo, sp.oo, -sp.oo, sp.nan)


@dataclass(frozen=True)
class Prepared:
    """A definite integral made ready for quadrature (:func:`prepare`): ``pieces`` are
    integrals in the ``params`` only, each parameter standing for an expression in the outer
    symbols, computed once per value instead of at every node; ``singular`` says which pieces
    keep a singular end (mpmath integrates those at doubled precision)."""

    params: tuple[tuple[sp.Dummy, sp.Expr], ...]
    pieces: tuple[sp.Integral, ...]
    singular: tuple[bool, ...]


@lru_cache(maxsize=512)
def prepare(integral: sp.Integral) -> Prepared:
    """``integral`` with its ends smoothed, then its parameters lifted out (:func:`_lift`).

    At an end e where the integrand is unbounded like |x − e|^(−1/2) (1/√(1 − ζ²) at ζ = 1),
    x = e ± (b − a)·u² (u from 0 to 1) makes it analytic: every radicand is factored, its
    factor u² leaves the root as u (u > 0, so √(u²·W) = u·√W on the principal branch: the
    value is unchanged) and cancels the Jacobian's u.  The distance to the end is then u²,
    computed without cancellation, so both flint's Gauss–Legendre and tanh–sinh keep every
    working digit there.  A radicand in sines and cosines, cos(φ₀ − c·u²) − cos φ₀, shows its
    factor u² once written as products of sines (:func:`_small_sines`).  A path singular at
    both ends is cut at its midpoint.  Where the substitution does not leave an integrand sympy
    sees bounded (a log, a higher order) the path stays as it is, marked singular."""
    x, a, b = integral.limits[0]
    f = integral.function
    ends = [_singular(f.xreplace({x: e})) for e in (a, b)]
    pieces = [(integral, any(ends))]
    if any(ends):
        u = sp.Dummy("u", positive=True)
        spans = [(a, (a + b) / 2, True), ((a + b) / 2, b, False)] if all(ends) else [(a, b, ends[0])]
        smoothed = []
        for lo, hi, at_lower in spans:
            # ∫_lo^hi f dx = ∫_0^1 f(x(u))·2(hi − lo)·u du, x = lo + (hi − lo)u² or hi − (hi − lo)u²
            xs = lo + (hi - lo) * u**2 if at_lower else hi - (hi - lo) * u**2
            substituted = f.xreplace({x: xs}) * 2 * (hi - lo) * u
            bounded = False
            rewrites = [lambda r: r]
            if substituted.has(sp.sin, sp.cos):  # the product form is tried only where it can differ
                rewrites.append(lambda r: _small_sines(TR9(r), u))
            for radicand in rewrites:
                try:
                    g = substituted.replace(
                        lambda e: isinstance(e, sp.Pow) and not e.exp.is_Integer and e.base.has(u),
                        lambda e: sp.factor(radicand(e.base)) ** e.exp)
                    bounded = not _singular(g.xreplace({u: 0}))
                except (sp.PolynomialError, ValueError, TypeError, NotImplementedError):
                    bounded = False  # sympy cannot factor it: the path stays as it is
                if bounded:
                    break
            smoothed.append((sp.Integral(g, (u, 0, 1)), False))
            if not bounded:
                break
        else:
            pieces = smoothed
    table: dict[sp.Expr, sp.Dummy] = {}
    lifted = []
    for piece, _ in pieces:
        var, lo, hi = piece.limits[0]
        try:
            if piece.function.has(sp.Integral, sp.Sum, sp.Derivative, sp.Piecewise):
                raise TypeError("bound variables or conditions inside")
            body = _lift(piece.function, var, table)
        except (TypeError, ValueError, AttributeError):
            # kept whole (bound variables inside, or a node that cannot be rebuilt from its
            # arguments): only its outer symbols become parameters
            body = piece.function.xreplace({sym: _param(sym, table) for sym in piece.function.free_symbols - {var}})
        lo, hi = (end if end.is_number else _param(end, table) for end in (lo, hi))
        lifted.append(sp.Integral(body, (var, lo, hi)))
    return Prepared(tuple((d, e) for e, d in table.items()), tuple(lifted), tuple(s for _, s in pieces))


def _small_sines(e: sp.Expr, u: sp.Symbol) -> sp.Expr:
    """A radicand that vanishes at u = 0 without u² as a factor, cos(φ₀ − c·u²) − cos φ₀: after
    sympy's sum-to-product rules (``TR9``: −2·sin(φ₀ − c·u²/2)·sin(−c·u²/2)), each sine of an
    argument w that vanishes at u = 0 is written w·sinc(w) (sinc 1 at 0).  Identities for all
    complex values; the radicand's factor u² then shows, and its small factor is computed
    without the cancellation of cos(φ₀ − c·u²) − cos φ₀."""
    return e.replace(lambda s: isinstance(s, sp.sin) and s.args[0].has(u) and s.args[0].xreplace({u: 0}) == 0,
                     lambda s: s.args[0] * sp.sinc(s.args[0]))


def _param(e: sp.Expr, table: dict) -> sp.Dummy:
    if e not in table:
        table[e] = sp.Dummy(f"p{len(table)}")
    return table[e]


def _lift(e: sp.Expr, x: sp.Symbol, table: dict) -> sp.Expr:
    """``e`` with each largest sub-expression free of ``x`` (other than a number) replaced by a
    parameter: cos(√(g/l)·t)·(1 − k²x²) → p0·(1 − p1·x²).  The tree is only rebuilt, so its
    value is unchanged; an integrand is then a small expression in x and the parameters."""
    if not e.has(x):
        return e if e.is_number else _param(e, table)
    if e.is_Atom:
        return e
    if isinstance(e, sp.Add):
        e = sp.collect(e, x)  # a polynomial in x keeps one coefficient per power
    if isinstance(e, (sp.Add, sp.Mul)):
        free, bound = e.as_independent(x, as_Add=isinstance(e, sp.Add))
        rest = bound.args if bound.func is e.func else (bound,)
        return e.func(_lift(free, x, table), *[_lift(r, x, table) for r in rest])
    return e.func(*[_lift(arg, x, table) for arg in e.args])


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


def _piece_quadrature(integral: sp.Integral, params: tuple[sp.Dummy, ...], singular: bool):
    """One piece's value at the values of its parameters.  First python-flint's ball
    integration at the working precision plus guard bits: for an integrand analytic along the
    path it converges in a few hundred evaluations, and its ball says whether every working bit
    is right.  Where it does not (no ball form, an endpoint singularity, too much subdivision)
    mpmath's quadrature (:func:`_quad`) computes the value."""
    try:
        ball = _compile_path(integral)
    except Unsupported:
        ball = None
    var, lo, hi = integral.limits[0]
    compiled: list = []  # mpmath's integrand and limits, compiled when first needed

    def mpmath_form():
        if not compiled:
            x = sp.Dummy("x")  # the variable may also be a limit: ∫_0^t f(t) dt
            compiled.extend((mp_lambdify((x,) + params, integral.function.xreplace({var: x})),
                             mp_lambdify(params, lo), mp_lambdify(params, hi)))
        return compiled

    if ball is None:
        mpmath_form()  # the only way: compiled now, as every other part of the expression

    def compute(vals):
        if ball is not None:
            got = _ball_quadrature(ball, params, vals)
            if got is not None:
                return got
        body, lower, upper = mpmath_form()
        return _quad(lambda z: body(z, *vals), [lower(*vals), upper(*vals)], singular=singular)

    def value(*vals):
        # remembered: a printed integral that is also the derived one (or an erratum's printed
        # and corrected forms) meets the same piece at the same point and precision — about a
        # quarter of a verification's quadratures.  The piece's parameters are its own dummies
        # (prepare), so equal keys are the same integral at the same values
        key = (integral, singular, vals, mpmath.mp.prec)
        if key not in _QUADRATURES:
            if len(_QUADRATURES) >= QUADRATURES_REMEMBERED:
                _QUADRATURES.clear()
            _QUADRATURES[key] = compute(vals)
        return _QUADRATURES[key]
    return value


_QUADRATURES: dict = {}
QUADRATURES_REMEMBERED = 20_000  # values of _piece_quadrature kept in one process


def _ball_quadrature(ball, outer, vals):
    """flint's value of a compiled integral, or None where it does not hold every bit of the
    working precision."""
    budget = max(QUADRATURE_EVALUATIONS, QUADRATURE_EVALUATIONS_PER_BIT * (mpmath.mp.prec + QUADRATURE_GUARD_BITS))
    return _ball_value(ball, outer, vals, Work(budget, smooth_ends=True))


def _ball_value(ball, outer, vals, work: Work):
    """The value of a compiled ball function (:func:`_ball_function`, :func:`_compile_path`)
    at the values ``vals`` of ``outer`` (mpmath numbers, taken as exact), computed at the
    working precision plus guard bits: its midpoint where the ball holds every working bit,
    else None (the fast path failed: mpmath decides)."""
    import flint

    prec = mpmath.mp.prec
    old = flint.ctx.prec
    flint.ctx.prec = prec + QUADRATURE_GUARD_BITS
    try:
        env = {}
        for sym, v in zip(outer, vals):
            b = _mp_to_acb(v)
            if b is None:
                return None
            env[sym] = b
        try:
            r = ball(env, False, work)
        except (Unsupported, ArithmeticError, ValueError, TypeError, AttributeError):
            return None
        if not r.is_finite() or r.rel_accuracy_bits() < prec:
            return None
        re, im = _arb_to_mpf(r.real.mid()), _arb_to_mpf(r.imag.mid())
        return +re if r.imag.contains(0) else +mpmath.mpc(re, im)
    finally:
        flint.ctx.prec = old


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
        ball = _ball_function(expr)
    except Unsupported:
        return mp_function(expr, args)

    def value(*vals):
        got = _ball_value(ball, args, vals, Work())
        return got if got is not None else mp_function(expr, args)(*vals)
    return value


def _mp_to_acb(v):
    """An mpmath number as an exact acb (None for inf/nan)."""
    import flint

    v = mpmath.mpmathify(v)
    parts = (v.real, v.imag) if isinstance(v, mpmath.mpc) else (v,)
    out = []
    for x in parts:
        if not mpmath.isfinite(x):
            return None
        sign, man, exp, _ = x._mpf_
        out.append(flint.arb((-int(man) if sign else int(man), int(exp))))
    return flint.acb(*out)


def _arb_to_mpf(x):
    man, exp = x.man_exp()
    return mpmath.mpf((int(man), int(exp)))


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
class Unsupported(Exception):
    """The expression has a node the ball evaluator does not handle."""


class Work:
    """A budget of ball-integrand evaluations, shared by every integral of one or more
    :func:`arb_eval` calls (``None``: unbounded).

    Counted work, not time, so that the same input gives the same balls — and the same
    certified digits in a report — on every machine (flint's integrator is deterministic).
    flint's integrator cannot be interrupted by an exception: once the budget is spent, the
    integrands return NaN balls and the result is simply not finite."""

    def __init__(self, evaluations: int | None = None, parent: "Work | None" = None, smooth_ends: bool = False):
        self.left = evaluations
        self.parent = parent
        # refuse at once an integrand that is not analytic at an end of the path (a branch
        # point such as √(1 − ζ²) at ζ = 1): flint converges there only after heavy
        # subdivision, where tanh–sinh quadrature is at its best
        self.smooth_ends = smooth_ends

    def share(self, evaluations: int) -> "Work":
        """A budget of at most ``evaluations`` that also spends this one."""
        return Work(evaluations, self, self.smooth_ends)

    def spend(self) -> bool:
        """Count one evaluation here and in every parent; False (counting nothing) once this
        budget or a parent's is spent.  (Called for every integrand evaluation: two walks up the
        chain, nothing allocated.)"""
        node = self
        while node is not None:
            if node.left is not None and node.left <= 0:
                return False
            node = node.parent
        node = self
        while node is not None:
            if node.left is not None:
                node.left -= 1
            node = node.parent
        return True

    def remaining(self) -> int | None:
        """Evaluations left here and in every parent (``None``: unbounded)."""
        own = self.left
        up = self.parent.remaining() if self.parent is not None else None
        if own is None or up is None:
            return own if up is None else up
        return max(min(own, up), 0)

    @property
    def spent(self) -> bool:
        return (self.left is not None and self.left <= 0) or (self.parent is not None and self.parent.spent)


def arb_eval(expr: sp.Basic, point: dict[sp.Symbol, sp.Expr], prec: int = 256, work: Work | None = None):
    """Evaluate in ``flint.acb`` at ``prec`` bits; returns an acb ball.  Raises
    :class:`Unsupported` for nodes it cannot bound rigorously.  ``work`` bounds the number of
    integrand evaluations of its ball integrals (see :class:`Work`)."""
    import flint

    old = flint.ctx.prec
    flint.ctx.prec = prec
    work = work if work is not None else Work()
    try:
        env = {sym: _acb_exact(val, work) for sym, val in point.items()}
        return _ball_function(expr)(env, False, work)
    finally:
        flint.ctx.prec = old


def _acb_exact(val: sp.Expr, work: Work):
    import flint

    val = sp.nsimplify(val) if not val.is_number else val
    if val.is_Rational:
        return flint.acb(flint.arb(flint.fmpq(int(val.p), int(val.q))))
    # exact expressions of pi, sqrt, … : evaluate rigorously through the same compiler
    return _ball_function(val)({}, False, work)


# Why a hand-written compiler: lambdify has no python-flint printer, and a ball integrand is
# called thousands of times.  The expression is turned once into the source of one Python
# function, each node one line (no per-call dispatch on node types, no call per node), each
# repeated sub-expression computed once: ~2.5× faster per evaluation than nested closures.
# Constants are built at call time: a ball's radius depends on the precision in force then.
@lru_cache(maxsize=512)
def _ball_function(e: sp.Basic):
    """``e`` as a function (env, analytic, work) -> acb; ``env`` maps symbols to balls."""
    return _compile(e)


_UNARY = {  # sympy function -> the acb expression of its argument ``{a}`` (``an``: analytic)
    sp.sin: "{a}.sin()", sp.cos: "{a}.cos()", sp.tan: "{a}.tan()", sp.exp: "{a}.exp()",
    sp.atan: "{a}.atan()", sp.log: "{a}.log(analytic=an)", sp.asin: "{a}.asin()",
    sp.acos: "{a}.acos()", sp.sinh: "{a}.sinh()", sp.cosh: "{a}.cosh()", sp.acot: "(1 / {a}).atan()",
    # |z| is analytic nowhere: an integrand with one gets no ball (mpmath integrates it)
    sp.Abs: "(acb('nan') if an else acb(abs({a})))",
    sp.elliptic_k: "acb.elliptic_k({a})", sp.sinc: "{a}.sinc()",
}
_BINARY = {sp.elliptic_f: "acb.elliptic_f({a}, {b})", sp.elliptic_e: "acb.elliptic_e_inc({a}, {b})"}
_EXACT_INTEGER = 2**53  # integers below are exact balls at any working precision (≥ 53 bits) either way


class _Source:
    """The lines of one generated ball function.  A sub-expression met again is read from its
    variable — except one holding an integral: each occurrence spends its own share of the
    :class:`Work` budget, as it always has, so that the certified digits do not change.  The
    sine and the cosine of one argument (``paired``) come from one ``sin_cos``: the same balls,
    at about half the cost of the two (an integrand in sin Ωt and cos Ωt, at every evaluation)."""

    def __init__(self, paired: frozenset = frozenset()):
        self.lines: list[str] = []
        self.names: dict[object, str] = {}
        self.constants: dict[str, object] = {}
        self.paired = paired

    @staticmethod
    def pairs(e: sp.Basic) -> frozenset:
        """The arguments (free of integrals) of both a sine and a cosine in ``e``."""
        both = {s.args[0] for s in e.atoms(sp.sin)} & {c.args[0] for c in e.atoms(sp.cos)}
        return frozenset(a for a in both if not a.has(sp.Integral))

    def sin_cos(self, arg: sp.Basic) -> str:
        key = ("sin_cos", arg)
        if key not in self.names:
            self.names[key] = self.line(f"{self.emit(arg)}.sin_cos()")
        return self.names[key]

    def constant(self, obj) -> str:
        name = f"c{len(self.constants)}"
        self.constants[name] = obj
        return name

    def line(self, code: str) -> str:
        var = f"t{len(self.lines)}"
        self.lines.append(f"    {var} = {code}")
        return var

    def emit(self, e: sp.Basic) -> str:
        if e in self.names:
            return self.names[e]
        var = self.line(self.code(e))
        if not e.has(sp.Integral):
            self.names[e] = var
        return var

    def code(self, e: sp.Basic) -> str:  # noqa: C901 - one dispatch table
        import flint

        if isinstance(e, sp.Symbol):
            return f"env[{self.constant(e)}]"
        if e.is_Rational:
            p, q = int(e.p), int(e.q)
            if q == 1 and abs(p) < _EXACT_INTEGER:
                return f"acb({p})"
            return f"acb(arb({self.constant(flint.fmpq(p, q))}))"  # exact; not as text (4300-digit limit)
        if e is sp.pi:
            return "acb(arb.pi())"
        if e is sp.E:
            return "acb(1).exp()"
        if e is sp.I:
            return "acb(0, 1)"
        if isinstance(e, (sp.Add, sp.Mul)):
            op = " + " if isinstance(e, sp.Add) else " * "
            parts = [self.emit(a) for a in e.args]
            out = parts[0]
            for part in parts[1:-1]:  # folded left to right, as written
                out = self.line(out + op + part)
            return out + op + parts[-1]
        if isinstance(e, sp.Pow):
            base, ex = self.emit(e.base), e.exp
            if ex.is_Integer:
                return f"{base} ** {int(ex)}"
            if ex == sp.Rational(1, 2):
                return f"{base}.sqrt(analytic=an)"
            if ex == -sp.Rational(1, 2):
                return f"1 / {base}.sqrt(analytic=an)"
            if ex.is_Rational and (2 * ex).is_Integer:
                return f"{base}.sqrt(analytic=an) ** {int(2 * ex)}"
            power = self.emit(ex)
            return f"({base}.log(analytic=an) * {power}).exp()"
        if isinstance(e, (sp.sin, sp.cos)) and e.args[0] in self.paired:
            return f"{self.sin_cos(e.args[0])}[{0 if isinstance(e, sp.sin) else 1}]"
        if e.func in _UNARY:
            return _UNARY[e.func].format(a=self.emit(e.args[0]))
        if e.func in _BINARY and len(e.args) == 2:
            return _BINARY[e.func].format(a=self.emit(e.args[0]), b=self.emit(e.args[1]))
        if isinstance(e, sp.elliptic_e):
            return f"acb.elliptic_e({self.emit(e.args[0])})"
        if isinstance(e, sp.factorial) and e.args[0].is_Integer:
            return f"acb({self.constant(int(sp.factorial(e.args[0])))})"
        if isinstance(e, sp.Integral) and len(e.limits) == 1 and len(e.limits[0]) == 3:
            return f"{self.constant(_compile_integral(e))}(env, an, work)"
        raise Unsupported(f"no ball evaluation for {e.func.__name__}")


def _compile(e: sp.Basic):
    """``e`` as a function (env, analytic, work) -> acb (see :class:`_Source`)."""
    import flint

    source = _Source(_Source.pairs(e))
    out = source.emit(e)
    text = "\n".join(["def ball(env, an, work):", *source.lines, f"    return {out}", ""])
    namespace = {"acb": flint.acb, "arb": flint.arb, **source.constants}
    exec(compile(text, "<quasicentral ball function>", "exec"), namespace)  # noqa: S102 - our own source
    return namespace["ball"]


def _compile_integral(e: sp.Integral):
    prep = prepare(e)
    params = [(d, _compile(expr)) for d, expr in prep.params]
    parts = [_compile_path(piece) for piece in prep.pieces]

    def total(env, an, work):
        inner = {**env, **{d: g(env, an, work) for d, g in params}}
        out = parts[0](inner, an, work)
        for part in parts[1:]:
            out = out + part(inner, an, work)
        return out
    return total


def period(body: sp.Expr, var: sp.Symbol) -> sp.Expr | None:
    """A period P of ``body`` in ``var``, body(var + P) ≡ body(var) for every complex var, where
    var enters only through sines, cosines and tangents of c·var + d with one rate c for all:
    π/c if the shift by it leaves ``body`` unchanged (sympy's own rules, sin(x + π) = −sin x,
    then expansion), else 2π/c if that does; None otherwise (also where a period exists but
    is not found this way)."""
    trig = [f for f in body.atoms(sp.sin, sp.cos, sp.tan) if f.has(var)]
    if not trig or body.xreplace({f: sp.Dummy() for f in trig}).has(var):
        return None
    rates = set()
    for f in trig:
        arg = sp.expand(f.args[0])
        c = arg.coeff(var)
        if c == 0 or c.has(var) or (arg - c * var).has(var):
            return None
        rates.add(c)
    if len(rates) != 1:
        return None
    (c,) = rates
    for candidate in (sp.pi / c, 2 * sp.pi / c):
        shifted = body.xreplace({f: f.func(sp.expand(f.args[0].xreplace({var: var + candidate}))) for f in trig})
        if sp.expand(shifted - body) == 0:
            return candidate
    return None


#: a path of at least this many periods is integrated over one period and what is left over
PERIODS_WORTH_FOLDING = 2


def _whole_periods(length, span) -> int:
    """The whole periods in a path of ``length`` (balls), towards 0 and signed; 0 unless both
    are real and the period positive.  Any integer would do (periodicity): the midpoints
    choose one."""
    if not (length.imag == 0 and span.imag == 0 and span.real > 0):
        return 0
    whole = (abs(length.real.mid()) / span.real.mid()).floor().unique_fmpz()  # the floor of a ratio of
    if whole is None:  # two exact numbers, rounded at the working precision: an integer ball
        return 0
    return int(whole) if length.real.mid() >= 0 else -int(whole)


def _compile_path(e: sp.Integral):
    import flint

    var, lo, hi = e.limits[0]
    lower, upper, body = _compile(lo), _compile(hi), _compile(e.function)
    # a periodic integrand over many periods (sin² Ωt √(a + b cos² Ωt) over four turns) is
    # integrated over one period and the rest: ∫_a^b = m·∫_a^{a+sP} + ∫_{a+nP}^b, n = s·m
    # whole periods — the same integral by periodicity, at a fraction of the evaluations
    one_period = period(e.function, var)
    span = _compile(one_period) if one_period is not None else None

    def integral(env, an, work):
        a, b = lower(env, an, work), upper(env, an, work)
        inner = dict(env)
        for end in (a, b):
            # flint's integrator needs the integrand analytic on the whole path: at an integrable
            # endpoint singularity (1/√(1 − ζ²) at ζ = 1) it only returns a non-finite ball, after
            # much subdivision — say so at once instead
            inner[var] = end
            try:
                finite = body(inner, False, work).is_finite()
            except ZeroDivisionError:
                finite = False
            if not finite:
                raise Unsupported("the integrand is unbounded at an end of the path")
            if work.smooth_ends:
                inner[var] = end + flint.acb(flint.arb(0, SMOOTH_END_RADIUS), flint.arb(0, SMOOTH_END_RADIUS))
                if not body(inner, True, work).is_finite():
                    raise Unsupported("the integrand is not analytic at an end of the path")

        def f(z, analytic):
            if not work.spend():
                return flint.acb("nan")
            inner[var] = z
            return body(inner, analytic, work)

        def over(x, y):
            # flint stops by itself at eval_limit: without it, an integrand that has turned NaN
            # would still be subdivided up to flint's default limit (millions of calls)
            limit = work.remaining()
            if limit is None:
                return flint.acb.integral(f, x, y)
            if limit <= 0:  # spent (and flint would read an eval_limit of 0 as its default)
                return flint.acb("nan")
            return flint.acb.integral(f, x, y, eval_limit=limit)

        if span is not None:
            step = span(env, an, work)
            n = _whole_periods(b - a, step)
            if abs(n) >= PERIODS_WORTH_FOLDING:
                step = step if n > 0 else -step  # along the path
                return abs(n) * over(a, a + step) + over(a + abs(n) * step, b)
        return over(a, b)
    return integral
