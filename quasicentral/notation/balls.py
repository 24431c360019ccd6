"""python-flint balls: expressions evaluated in complex ball arithmetic (``acb``), whose radius
bounds every rounding and truncation error — so a ball that excludes zero certifies a non-zero
difference.  Elliptic functions take the parameter m = k², as in mpmath and sympy.

Why a hand-written compiler: lambdify has no python-flint printer, and a ball integrand is
called thousands of times.  The expression is turned once into the source of one Python
function, each node one line (no per-call dispatch on node types, no call per node), each
repeated sub-expression computed once: ~2.5× faster per evaluation than nested closures.
"""

from __future__ import annotations

from types import MappingProxyType
from contextlib import contextmanager
from functools import lru_cache

import mpmath
import sympy as sp

from quasicentral.notation.integrals import PERIODS_WORTH_FOLDING, period, prepare
from quasicentral.notation.special import FUNCTIONS as SPECIAL_FUNCTIONS

GUARD_BITS = 20  # bits a ball is computed with beyond the working precision
SMOOTH_END_RADIUS = 2.0 ** -30  # the disc around an end of the path that must be free of singularities


@contextmanager
def flint_precision(bits: int):
    """python-flint's working precision for the block, restored after it (the one place that
    sets it)."""
    import flint

    old = flint.ctx.prec
    flint.ctx.prec = bits
    try:
        yield
    finally:
        flint.ctx.prec = old


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
    work = work if work is not None else Work()
    with flint_precision(prec):
        env = {sym: _acb_exact(val, work) for sym, val in point.items()}
        return ball_function(expr)(env, False, work)



def _acb_exact(val: sp.Expr, work: Work):
    import flint

    val = sp.nsimplify(val) if not val.is_number else val
    if val.is_Float:  # a binary number (a root found to many digits): its exact value
        val = sp.Rational(val)
    if val.is_Rational:
        return flint.acb(flint.arb(flint.fmpq(int(val.p), int(val.q))))
    # exact expressions of pi, sqrt, … : evaluate rigorously through the same compiler
    return ball_function(val)({}, False, work)




@lru_cache(maxsize=512)
def ball_function(e: sp.Basic):
    """``e`` as a function (env, analytic, work) -> acb; ``env`` maps symbols to balls."""
    return _compile(e)


_UNARY = MappingProxyType({  # sympy function -> the acb expression of its argument ``{a}`` (``an``: analytic)
    sp.sin: "{a}.sin()", sp.cos: "{a}.cos()", sp.tan: "{a}.tan()", sp.exp: "{a}.exp()",
    sp.atan: "{a}.atan()", sp.log: "{a}.log(analytic=an)", sp.asin: "{a}.asin()",
    sp.acos: "{a}.acos()", sp.sinh: "{a}.sinh()", sp.cosh: "{a}.cosh()", sp.acot: "(1 / {a}).atan()",
    # |z| is analytic nowhere: an integrand with one gets no ball (mpmath integrates it)
    sp.Abs: "(acb('nan') if an else acb(abs({a})))",
    sp.elliptic_k: "acb.elliptic_k({a})", sp.sinc: "{a}.sinc()",
    # entire or meromorphic: the same function inside an integrand
    sp.tanh: "{a}.tanh()", sp.coth: "{a}.coth()", sp.cot: "{a}.cot()", sp.sec: "{a}.sec()", sp.csc: "{a}.csc()",
    sp.gamma: "{a}.gamma()", sp.erf: "{a}.erf()", sp.erfc: "{a}.erfc()", sp.erfi: "{a}.erfi()",
    sp.zeta: "{a}.zeta()", sp.Si: "{a}.si()", sp.Shi: "{a}.shi()",
    # cut along a ray (principal branches, as sympy and mpmath take them): no analytic form,
    # so an integrand holding one gets no ball (mpmath integrates it), as |z| above
    sp.asinh: "(acb('nan') if an else {a}.asinh())", sp.acosh: "(acb('nan') if an else {a}.acosh())",
    sp.atanh: "(acb('nan') if an else {a}.atanh())", sp.loggamma: "(acb('nan') if an else {a}.lgamma())",
    sp.Ei: "(acb('nan') if an else {a}.ei())", sp.Ci: "(acb('nan') if an else {a}.ci())",
    sp.Chi: "(acb('nan') if an else {a}.chi())", sp.li: "(acb('nan') if an else {a}.li())",
    sp.LambertW: "(acb('nan') if an else {a}.lambertw())",
})
_BINARY = MappingProxyType({sp.elliptic_f: "acb.elliptic_f({a}, {b})", sp.elliptic_e: "acb.elliptic_e_inc({a}, {b})"})
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

    def real_only(self, e: sp.Basic) -> str:
        """A function of real arguments with jumps or kinks (sign, floor, ceiling, Heaviside;
        Min, Max) by flint's real-variable functions: nan for an argument that is not
        certainly real (they take the real part alone), and inside an integrand, as |z|
        (mpmath integrates it, cut at its jumps).  Heaviside at 0 is ½, as sympy's."""
        if isinstance(e, sp.Heaviside) and len(e.args) == 2 and e.args[1] != sp.S.Half:
            raise Unsupported("no ball evaluation for Heaviside with a value at 0 other than 1/2")
        args = [self.emit(a) for a in e.args]
        real = " and ".join(f"{a}.imag == 0" for a in args)
        if e.func in _STEPS:
            call = f"{args[0]}.{_STEPS[e.func]}()"
        else:
            call = args[0]
            for a in args[1:]:
                call = self.line(f"({call}.{_ORDERED[e.func]}({a}) if not an else acb('nan'))")
        return f"({call} if not an and ({real}) else acb('nan'))"

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
        if e.is_Float:  # exactly the binary number it is
            r = sp.Rational(e)
            return f"acb(arb({self.constant(flint.fmpq(int(r.p), int(r.q)))}))"
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
        if e.func in _UNARY and len(e.args) == 1:
            return _UNARY[e.func].format(a=self.emit(e.args[0]))
        if e.func in _BINARY and len(e.args) == 2:
            return _BINARY[e.func].format(a=self.emit(e.args[0]), b=self.emit(e.args[1]))
        if isinstance(e, sp.elliptic_e):
            return f"acb.elliptic_e({self.emit(e.args[0])})"
        if e.func in _STEPS or e.func in _ORDERED:
            return self.real_only(e)
        if e.func in _INDEXED:
            analytic_too = e.func in (sp.besselj, sp.besseli) and e.args[0].is_integer  # J_n, I_n: entire
            call = _INDEXED[e.func].format(z=self.emit(e.args[1]), s=self.emit(e.args[0]))
            return call if analytic_too else f"(acb('nan') if an else {call})"
        if isinstance(e, sp.hyper):
            ap = ", ".join(self.emit(a) for a in e.ap)
            bq = ", ".join(self.emit(b) for b in e.bq)
            return f"(acb('nan') if an else {self.emit(e.argument)}.hypgeom([{ap}], [{bq}]))"
        special = SPECIAL_FUNCTIONS.get(type(e).__name__)
        if special is type(e) and special.ball is not None and not any(isinstance(a, sp.Tuple) for a in e.args):
            args = ", ".join(self.emit(a) for a in e.args)  # each class's own rigorous route
            return f"{self.constant(special.ball)}({args}, analytic=an)"
        if isinstance(e, sp.factorial) and e.args[0].is_Integer:
            return f"acb({self.constant(int(sp.factorial(e.args[0])))})"
        if isinstance(e, sp.Integral) and len(e.limits) == 1 and len(e.limits[0]) == 3:
            return f"{self.constant(_compile_integral(e))}(env, an, work)"
        if isinstance(e, (sp.Sum, sp.Product)) and len(e.limits) == 1 and not e.limits[0][1:] \
                .has(sp.oo, -sp.oo, sp.zoo):
            return f"{self.constant(_compile_series(e))}(env, an, work)"
        raise Unsupported(f"no ball evaluation for {e.func.__name__}")


_STEPS = MappingProxyType({sp.sign: "real_sgn", sp.floor: "real_floor", sp.ceiling: "real_ceil",
                          sp.Heaviside: "real_heaviside"})
_ORDERED = MappingProxyType({sp.Min: "real_min", sp.Max: "real_max"})
#: functions of an order (or index) and an argument, ``{s}`` and ``{z}``: in an integrand only
#: where entire (a branch cut or a logarithmic end flint's call cannot flag)
_INDEXED = MappingProxyType({sp.besselj: "{z}.bessel_j({s})", sp.bessely: "{z}.bessel_y({s})",
                             sp.besseli: "{z}.bessel_i({s})", sp.besselk: "{z}.bessel_k({s})",
                             sp.polylog: "{z}.polylog({s})", sp.expint: "{z}.expint({s})"})


def _compile(e: sp.Basic):
    """``e`` as a function (env, analytic, work) -> acb (see :class:`_Source`)."""
    import flint

    source = _Source(_Source.pairs(e))
    out = source.emit(e)
    text = "\n".join(["def ball(env, an, work):", *source.lines, f"    return {out}", ""])
    namespace = {"acb": flint.acb, "arb": flint.arb, **source.constants}
    exec(compile(text, "<quasicentral ball function>", "exec"), namespace)  # noqa: S102 - our own source
    return namespace["ball"]


#: terms a finite sum or product in balls adds one by one; beyond, it has no ball (mpmath's
#: series summation takes it)
BALL_TERMS = 10_000


def _compile_series(e: sp.Sum | sp.Product):
    """A finite sum or product whose bounds are exact integers at the point, term by term (nan
    where they are not integers or hold more than BALL_TERMS terms: no ball then)."""
    import flint

    var, lo, hi = e.limits[0]
    lower, upper, term = _compile(lo), _compile(hi), _compile(e.function)
    product = isinstance(e, sp.Product)

    def total(env, an, work):
        a, b = (end(env, an, work) for end in (lower, upper))
        if not (a.imag == 0 and b.imag == 0):
            return flint.acb("nan")
        a, b = a.real.unique_fmpz(), b.real.unique_fmpz()
        if a is None or b is None or int(b) - int(a) >= BALL_TERMS:
            return flint.acb("nan")
        out = flint.acb(1 if product else 0)
        for k in range(int(a), int(b) + 1):
            value = term({**env, var: flint.acb(k)}, an, work)
            out = out * value if product else out + value
        return out
    return total


def _compile_integral(e: sp.Integral):
    prep = prepare(e)
    params = [(d, _compile(expr)) for d, expr in prep.params]
    parts = [compile_path(piece) for piece in prep.pieces]

    def total(env, an, work):
        inner = {**env, **{d: g(env, an, work) for d, g in params}}
        out = parts[0](inner, an, work)
        for part in parts[1:]:
            out = out + part(inner, an, work)
        return out
    return total



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


def compile_path(e: sp.Integral):
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



def mp_to_acb(v):
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


def arb_to_mpf(x):
    man, exp = x.man_exp()
    return mpmath.mpf((int(man), int(exp)))



def ball_value(ball, outer, vals, work: Work):
    """The value of a compiled ball function (:func:`ball_function`, :func:`compile_path`)
    at the values ``vals`` of ``outer`` (mpmath numbers, taken as exact), computed at the
    working precision plus guard bits: its midpoint where the ball holds every working bit,
    else None (the fast path failed: mpmath decides)."""
    prec = mpmath.mp.prec
    with flint_precision(prec + GUARD_BITS):
        env = {}
        for sym, v in zip(outer, vals):
            b = mp_to_acb(v)
            if b is None:
                return None
            env[sym] = b
        try:
            r = ball(env, False, work)
        except (Unsupported, ArithmeticError, ValueError, TypeError, AttributeError):
            return None
        if not r.is_finite() or r.rel_accuracy_bits() < prec:
            return None
        re, im = arb_to_mpf(r.real.mid()), arb_to_mpf(r.imag.mid())
        return +re if r.imag.contains(0) else +mpmath.mpc(re, im)
