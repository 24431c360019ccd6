"""Declared domains: where each symbol lives, the paper's assumptions, and the definitions that
tie derived symbols to the primitive ones (Ω = √(g/l), u = R0Ω, …).

A text's symbol table gives the default range and definition of each symbol
(:class:`~quasicentral.notation.symbols.SymbolTable`); a derivation's :class:`Domain` narrows or
adds to them for its own step.

Points are sampled at random (seeded by the equation id, so a run is reproducible) as *exact*
sympy numbers; they cross to mpmath only in :mod:`quasicentral.bridge`.
"""

from __future__ import annotations

from types import MappingProxyType
import hashlib
import random
from dataclasses import dataclass, field
from fractions import Fraction
from functools import lru_cache

import mpmath
import sympy as sp

from quasicentral.notation.bridge import mp_lambdify, mp_value
from quasicentral.notation.symbols import SymbolTable

Interval = tuple[sp.Expr, sp.Expr]

JET_RANGE: Interval = (-2, 2)
POSITIVE_JET_RANGE: Interval = (sp.Rational(1, 10), 2)


@dataclass(frozen=True)
class Domain:
    """Ranges for symbols, definitions of dependent symbols, and constraints (sympy booleans).

    ``ranges`` override the text's declared ranges; ``defaults=False`` drops the text's
    definitions (Ω = √(g/l), …) so that the step keeps those symbols free.
    """

    ranges: tuple[tuple[sp.Basic, Interval], ...] = ()
    definitions: tuple[tuple[sp.Basic, sp.Expr], ...] = ()
    constraints: tuple[sp.Basic, ...] = ()
    defaults: bool = True  # apply the text's definitions
    real: tuple[sp.Basic, ...] = ()  # symbols drawn on the real line here (their range's real segment)

    @staticmethod
    def of(ranges=None, definitions=None, constraints=(), defaults=True, real=()) -> "Domain":
        return Domain(
            ranges=tuple((ranges or {}).items()),
            definitions=tuple((definitions or {}).items()),
            constraints=tuple(constraints),
            defaults=defaults,
            real=tuple(real),
        )

    def definition_map(self, table: SymbolTable) -> dict[sp.Basic, sp.Expr]:
        out = dict(table.definitions) if self.defaults else {}
        out.update(dict(self.definitions))
        return out

    def range_map(self, table: SymbolTable) -> dict[sp.Basic, Interval]:
        out = dict(table.ranges)
        out.update(dict(self.ranges))
        return out

    def key(self) -> str:
        return sp.srepr((self.ranges, self.definitions, self.constraints, self.defaults, self.real))


def substitute_definitions(expr: sp.Basic, defs: dict[sp.Basic, sp.Expr], rounds: int = 6) -> sp.Basic:
    """Apply the definitions until nothing changes (definitions may refer to each other).  A
    derivative in a defined symbol (d/dξ θ₄(ξ, q), ξ = x/θ₃²(0, q)) is taken in that symbol
    and then at its definition: its variable is bound, and is not replaced."""
    if defs and expr.has(sp.Derivative):
        expr = _bind_derivatives(expr, set(defs))
    if defs and expr.has(sp.Limit, sp.Sum, sp.Product, sp.Integral):
        expr = _bind_variables(expr, set(defs))
    for _ in range(rounds):
        new = expr.xreplace(defs) if defs else expr
        if new == expr:
            break
        expr = new
    return expr


def _bind_derivatives(expr: sp.Basic, names: set) -> sp.Basic:
    """Each derivative in a symbol of ``names`` as Subs(derivative in a dummy, dummy, symbol)."""
    def bind(d):
        bound = {v: sp.Dummy(str(v)) for v in d.variables if v in names}
        return sp.Subs(d.xreplace(bound), tuple(bound.values()), tuple(bound))

    return expr.replace(lambda a: isinstance(a, sp.Derivative) and any(v in names for v in a.variables), bind)


def _bind_variables(expr: sp.Basic, names: set) -> sp.Basic:
    """Each limit, sum, product or integral whose variable is a defined symbol (lim_{β→0} sin β/β
    with β = (πa/λ) sin θ) over a dummy of that name instead: its variable is bound, and is not
    replaced by the definition."""
    def bound(a) -> dict:
        found = [a.args[1]] if isinstance(a, sp.Limit) else [lim[0] for lim in a.limits]
        return {v: sp.Dummy(str(v)) for v in found if v in names}

    return expr.replace(lambda a: isinstance(a, (sp.Limit, sp.Sum, sp.Product, sp.Integral)) and bool(bound(a)),
                        lambda a: a.xreplace(bound(a)))


def seed_for(label: str) -> int:
    return int.from_bytes(hashlib.sha256(label.encode()).digest()[:8], "big")


class NoRange(KeyError):
    """A symbol to be sampled that has no range (``symbol``)."""

    def __init__(self, symbol):
        super().__init__(symbol)
        self.symbol = symbol


@dataclass
class Sampler:
    """Draws exact points for a set of free symbols inside a :class:`Domain`."""

    domain: Domain
    table: SymbolTable
    symbols: list[sp.Symbol]
    seed: int
    extra_ranges: dict = field(default_factory=dict)

    def draw(self, count: int, max_tries: int = 200) -> list[dict[sp.Symbol, sp.Expr]]:
        """``count`` points (fewer if the constraints reject too many tries); the same arguments
        give the same points, which are remembered (a mutation run draws them for every mutant)."""
        ranges = self.domain.range_map(self.table)
        ranges.update(self.extra_ranges)
        key = (tuple(sorted(ranges.items(), key=lambda kv: sp.default_sort_key(kv[0]))),
               tuple(sorted(self.domain.definition_map(self.table).items(), key=lambda kv: sp.default_sort_key(kv[0]))),
               self.domain.constraints, self.domain.real, tuple(self.symbols), self.seed, count, max_tries)
        return [dict(pt) for pt in _draw(*key)]


@lru_cache(maxsize=2_000)
def _draw(ranges: tuple, definitions: tuple, constraints: tuple, real: tuple, symbols: tuple, seed: int,
          count: int, max_tries: int) -> tuple:
    """The points (remembered: a function of its arguments alone)."""
    rng = random.Random(seed)
    ranges, defs = dict(ranges), dict(definitions)
    wanted = set(symbols)
    for c in constraints:
        wanted |= substitute_definitions(c, defs).free_symbols
    order = _sampling_order(wanted, ranges, defs)
    missing = [sym for sym in order if sym not in ranges]
    if missing:
        raise NoRange(missing[0])
    # endpoints and constraints with the definitions applied, once
    applied = [substitute_definitions(c, defs) for c in constraints]
    spans = {}
    for sym in order:
        lo, hi = (substitute_definitions(sp.sympify(e), defs) for e in ranges[sym])
        lo, hi, on_line = narrowed(sym, lo, hi, applied)
        spans[sym] = _Span(lo, hi, real=sym in real or on_line, integer=bool(getattr(sym, "is_integer", False)))
    checks = [_Constraint(c) for c in applied]
    points = []
    tries = 0
    while len(points) < count and tries < count * max_tries:
        tries += 1
        pt: dict[sp.Symbol, sp.Expr] = {}
        for sym in order:
            pt[sym] = spans[sym].at(pt, rng)
        if all(c.holds(pt) for c in checks):
            points.append(pt)
    return tuple(points)


_BOUNDS = MappingProxyType({sp.StrictGreaterThan: "lower", sp.GreaterThan: "lower", sp.StrictLessThan: "upper", sp.LessThan: "upper"})


def narrowed(sym, lo, hi, constraints) -> tuple:
    """``sym``'s range [lo, hi] narrowed by the constraints that bound it alone — ``x > 0``,
    ``k ≤ 1``, ``Im z = 0``, ``Re z > 0`` — and whether they put it on the real line (an order
    holds between real numbers only).  Only a sampling aid: every constraint is still tested
    at every point, and a range the constraints leave empty is left as it was (the tests then
    reject its points, and the check says so)."""
    lo, hi = sp.sympify(lo), sp.sympify(hi)
    if not (lo.is_number and hi.is_number) or any(e.has(sp.oo, -sp.oo, sp.zoo) for e in (lo, hi)):
        return lo, hi, False
    re_lo, re_hi, real = sp.re(lo), sp.re(hi), False
    for c in constraints:
        if isinstance(c, sp.Eq) and sp.im(sym) in (c.lhs, c.rhs) and 0 in (c.lhs, c.rhs):
            real = True
            continue
        if type(c) not in _BOUNDS:
            continue
        side = _BOUNDS[type(c)]
        for this, other, flip in ((c.lhs, c.rhs, False), (c.rhs, c.lhs, True)):
            if not (other.is_number and other.is_real) or other.has(sp.oo, -sp.oo):
                continue
            bound = "upper" if (side == "lower") == flip else "lower"
            if this == sym:
                real = True
            elif this != sp.re(sym):
                continue
            re_lo, re_hi = (sp.Max(re_lo, other), re_hi) if bound == "lower" else (re_lo, sp.Min(re_hi, other))
    if not (re_lo < re_hi) is sp.true:
        return lo, hi, False
    return (re_lo + sp.I * sp.im(lo), re_hi + sp.I * sp.im(hi), real) if not real else (re_lo, re_hi, True)


#: significant digits of a point drawn inside a range whose ends are irrational in earlier points
DRAWN_DIGITS = 25
#: the share of a complex box's draws made on its real segment
REAL_SHARE = 1 / 3


class _Span:
    """A symbol's range [lo, hi] (definitions applied), its ends possibly depending on symbols
    drawn before it.

    Where the ends are rational functions of those symbols, a point is lo + (hi − lo)·r exactly.
    Where they are not (t up to 4K(sin²(φ0/2))/√(g/l)), the exact value would be a sympy
    expression that every later evaluation has to take apart again: the point is instead the
    rational of ``DRAWN_DIGITS`` significant digits nearest to lo + (hi − lo)·r, the ends
    computed at 40 and at 80 digits.  r is at least 2^-20 from 0 and 1, so the point stays
    strictly inside while the two computations of the ends agree to 10^-12 of the width (an end
    that cancels, 1 − cos x at tiny x, does not) and the width exceeds 10^-17 of the value;
    otherwise, or where an end cannot be computed in mpmath, the point is exact.  The earlier
    points may themselves be irrational (φ0 = 1/100 + (π − 1/50)·r): their values are exact
    numbers, computed at each precision.

    An infinite end maps r to lo + r/(1 − r) (or hi − r/(1 − r); both infinite: (r − ½)/(r(1 − r))),
    exact rationals over the whole half-line.  Ends with imaginary parts make a box in the
    complex plane (the corners lo and hi): a point draws its real and its imaginary part — one
    draw in :data:`REAL_SHARE` on the box's real segment, so that a formula that holds on the
    real line only is told apart from one that holds in the plane, and a constraint that pins
    a value to the real line (Im k² = 0) is met; a symbol the domain holds ``real`` is always
    drawn on the real segment.  An integer symbol (``assumptions = ["integer"]``) is drawn
    among the integers of its range."""

    def __init__(self, lo: sp.Expr, hi: sp.Expr, real: bool = False, integer: bool = False):
        self.ends = (lo, hi)
        self.integer = None
        if integer and lo.is_number and hi.is_number and sp.im(lo) == 0 and sp.im(hi) == 0 \
                and not any(e in (sp.oo, -sp.oo) for e in (lo, hi)):
            self.integer = (int(sp.ceiling(lo)), int(sp.floor(hi)))
        free = lo.free_symbols | hi.free_symbols
        self.infinite = tuple(e in (sp.oo, -sp.oo) for e in (lo, hi))
        self.box = None
        if not free and not any(self.infinite) and (sp.im(lo) != 0 or sp.im(hi) != 0):
            re_lo, re_hi, im_lo, im_hi = (_fraction(v) for v in (sp.re(lo), sp.re(hi), sp.im(lo), sp.im(hi)))
            self.box = (re_lo, re_hi - re_lo, Fraction(0) if real else im_lo, Fraction(0) if real else im_hi - im_lo)
        self.fixed = (lo, hi - lo) if not free and not any(self.infinite) else None  # (lo, width), every point's
        # rational fixed ends: a point in Python's fractions, one sympy number made (sympy's own
        # arithmetic took half the time of drawing points)
        self.exact = (Fraction(int(lo.p), int(lo.q)), Fraction(int((hi - lo).p), int((hi - lo).q))) \
            if not free and lo.is_Rational and hi.is_Rational else None
        self.args = tuple(sorted(free, key=str))
        rational = all(e.is_rational_function(*free) and not e.atoms(sp.NumberSymbol) and not e.has(sp.I)
                       and all(n.is_Rational for n in e.atoms(sp.Number)) for e in self.ends)
        self.compiled = None
        if free and not rational:
            try:
                self.compiled = mp_lambdify(self.args, [lo, hi])
            except Exception:  # noqa: BLE001 - an end lambdify cannot print: drawn exactly
                self.compiled = None

    def _ends(self, pt: dict, dps: int):
        with mpmath.workdps(dps):
            lo, hi = (mpmath.mpmathify(v) for v in self.compiled(*[_mp(pt[a]) for a in self.args]))
        ok = isinstance(lo, mpmath.mpf) and isinstance(hi, mpmath.mpf) and mpmath.isfinite(hi - lo) and hi > lo
        return (lo, hi) if ok else None

    def at(self, pt: dict, rng: random.Random) -> sp.Expr:
        if self.integer is not None and self.integer[0] <= self.integer[1]:
            return sp.Integer(rng.randint(*self.integer))
        r = Fraction(rng.randrange(1, 2**20), 2**20)
        if self.box is not None:
            re_lo, re_w, im_lo, im_w = self.box
            on_real_line = im_w and im_lo <= 0 <= im_lo + im_w and rng.random() < REAL_SHARE
            im = Fraction(0) if on_real_line else im_lo + im_w * Fraction(rng.randrange(1, 2**20), 2**20) \
                if im_w else im_lo
            re = re_lo + re_w * r
            return sp.Rational(re.numerator, re.denominator) + sp.I * sp.Rational(im.numerator, im.denominator)
        if any(self.infinite):
            return self._unbounded(pt, r)
        if self.compiled is not None and all(pt[a].is_number for a in self.args):
            got = self._drawn_in_mpmath(pt, r)
            if got is not None:
                return got
        if self.exact is not None:
            lo, width = self.exact
            v = lo + width * r
            return sp.Rational(v.numerator, v.denominator)
        r = sp.Rational(r.numerator, r.denominator)
        if self.fixed is not None:
            lo, width = self.fixed
            return lo + width * r
        lo, hi = (e.xreplace(pt) for e in self.ends)
        return lo + (hi - lo) * r

    def _unbounded(self, pt: dict, r: Fraction) -> sp.Expr:
        lo, hi = self.ends
        if all(self.infinite):
            v = (r - Fraction(1, 2)) / (r * (1 - r))
            return sp.Rational(v.numerator, v.denominator)
        t = r / (1 - r)
        tail = sp.Rational(t.numerator, t.denominator)
        return lo.xreplace(pt) + tail if self.infinite[1] else hi.xreplace(pt) - tail

    def _drawn_in_mpmath(self, pt: dict, r: Fraction) -> sp.Expr | None:
        try:
            coarse, fine = self._ends(pt, 40), self._ends(pt, 80)
            if coarse is None or fine is None:
                return None
            with mpmath.workdps(80):
                (lo, hi), width = fine, fine[1] - fine[0]
                v = lo + width * r.numerator / r.denominator
                if (abs(coarse[0] - lo) + abs(coarse[1] - hi) <= width * mpmath.mpf(10) ** -12
                        and width > abs(v) * mpmath.mpf(10) ** (8 - DRAWN_DIGITS)):
                    f = Fraction(mpmath.nstr(v, DRAWN_DIGITS, min_fixed=-mpmath.inf, max_fixed=mpmath.inf))
                    return sp.Rational(f.numerator, f.denominator)
        except Exception:  # noqa: BLE001 - an end mpmath cannot compute (an undefined function): exact
            pass
        return None


def _fraction(v: sp.Expr) -> Fraction:
    v = sp.nsimplify(v) if not v.is_Rational else v
    if not v.is_Rational:
        v = sp.Rational(str(sp.N(v, 30)))
    return Fraction(int(v.p), int(v.q))


#: a constraint whose two sides differ by less than this (relative, at 30 digits) is decided exactly
CONSTRAINT_MARGIN = 1e-20
#: a relation lhs ∘ rhs decided from the sign of lhs − rhs (far from zero: see CONSTRAINT_MARGIN)
_SIGN_TEST = MappingProxyType({sp.StrictLessThan: lambda d: d < 0, sp.LessThan: lambda d: d <= 0, sp.StrictGreaterThan: lambda d: d > 0,
              sp.GreaterThan: lambda d: d >= 0, sp.Eq: lambda d: d == 0, sp.Ne: lambda d: d != 0})


class _Constraint:
    """A constraint (definitions applied) decided at a point: lhs − rhs at 30 digits in mpmath
    (compiled once), exactly by sympy only where the two sides are too close to tell."""

    def __init__(self, constraint: sp.Basic):
        self.constraint = constraint
        self.compiled = None
        if isinstance(constraint, sp.core.relational.Relational):
            self.args = tuple(sorted(constraint.free_symbols, key=str))
            diff = constraint.lhs - constraint.rhs
            self.compiled = mp_lambdify(self.args, [diff, abs(constraint.lhs) + abs(constraint.rhs)])

    def holds(self, pt: dict) -> bool:
        if self.compiled is not None and all(a in pt for a in self.args):
            try:
                with mpmath.workdps(30):
                    diff, size = self.compiled(*[_mp(pt[a]) for a in self.args])
                    test = _SIGN_TEST.get(type(self.constraint))
                    if test is not None and isinstance(diff, mpmath.mpf) and abs(diff) > CONSTRAINT_MARGIN * size:
                        return test(diff)
            except (TypeError, ValueError, ZeroDivisionError, OverflowError):
                pass
        return _holds(self.constraint, pt)


def _mp(value: sp.Expr):
    """An exact sympy number as mpmath at the precision in force (the one bridge's)."""
    return mp_value(value, mpmath.mp.dps)


def _holds(constraint: sp.Basic, pt: dict) -> bool:
    """A constraint (definitions already applied) at an exact point."""
    c = constraint.xreplace(pt)
    try:
        if c in (sp.true, True):
            return True
        if c in (sp.false, False):
            return False
        lhs = sp.N(c.lhs - c.rhs, 30)
        return bool(type(c)(lhs, 0))
    except (TypeError, AttributeError):
        return False


def _sampling_order(symbols, ranges, defs) -> list[sp.Symbol]:
    """Symbols whose ranges refer to other symbols are drawn after those (adding them)."""
    needed: list[sp.Symbol] = []

    def visit(sym, stack=()):
        if sym in needed:
            return
        if sym in stack:
            raise ValueError(f"circular range for {sym}")
        lo, hi = ranges.get(sym, (0, 0))
        deps = set()
        for end in (lo, hi):
            deps |= substitute_definitions(sp.sympify(end), defs).free_symbols
        for d in sorted(deps, key=str):
            visit(d, stack + (sym,))
        needed.append(sym)

    for sym in sorted(symbols, key=str):
        visit(sym)
    return needed


#: points of an unknown's range where an implicit condition is evaluated in search of a sign change
IMPLICIT_GRID = 64
#: digits a root of an implicit condition is found to (and kept with)
IMPLICIT_DPS = 90


def on_condition(points: list[dict], unknown: sp.Symbol, condition: sp.Expr, ranges: dict) -> list[dict]:
    """The points with ``unknown`` replaced by a root of ``condition`` = 0 in its range, the
    other symbols as drawn — the root nearest the drawn value, so that the points cover every
    root; a point where the condition has none in the range drops out.  Roots are bracketed by
    the sign changes of the real condition on a grid of :data:`IMPLICIT_GRID` points and refined
    by mpmath's ``findroot`` (Anderson–Björck) to :data:`IMPLICIT_DPS` digits; where the grid
    shows none (a double root, a complex condition), the secant method from the drawn value,
    accepted only inside the range and where the condition vanishes to those digits."""
    others = tuple(sorted(condition.free_symbols - {unknown}, key=str))
    f = mp_lambdify((unknown, *others), condition)
    lo_e, hi_e = (sp.sympify(e) for e in ranges[unknown])
    out = []
    for pt in points:
        with mpmath.workdps(IMPLICIT_DPS):
            try:
                root = _root(f, pt, unknown, others, lo_e, hi_e)
            except (ValueError, ZeroDivisionError, TypeError, OverflowError, ArithmeticError,
                    mpmath.libmp.NoConvergence):
                root = None
            if root is not None:
                out.append({**pt, unknown: sp.Float(mpmath.nstr(root, IMPLICIT_DPS - 10), IMPLICIT_DPS - 10)})
    return out


def _root(f, pt: dict, unknown, others: tuple, lo_e, hi_e):
    vals = [_mp(pt[s]) for s in others]
    lo, hi = (_mp(e.xreplace(pt)) for e in (lo_e, hi_e))
    lo, hi = mpmath.re(lo), mpmath.re(hi)
    if not (mpmath.isfinite(lo) and mpmath.isfinite(hi)) or not lo < hi:
        return None
    g = lambda u: f(u, *vals)  # noqa: E731
    tiny = mpmath.mpf(10) ** (-IMPLICIT_DPS // 2)
    grid = [lo + (hi - lo) * i / (IMPLICIT_GRID - 1) for i in range(IMPLICIT_GRID)]
    values = []
    for u in grid:
        try:
            v = g(u)
        except (ValueError, ZeroDivisionError, TypeError, OverflowError, ArithmeticError):
            v = None
        values.append(mpmath.re(v) if v is not None and mpmath.isfinite(v) and abs(mpmath.im(v)) <= tiny * (1 + abs(v))
                      else None)
    size = max([abs(v) for v in values if v is not None] or [mpmath.mpf(1)])
    roots = []
    for (a, va), (b, vb) in zip(zip(grid, values), zip(grid[1:], values[1:])):
        if va is None or vb is None:
            continue
        if va == 0:
            roots.append(a)
        elif va * vb < 0:
            r = mpmath.findroot(g, (a, b), solver="anderson")
            if a <= mpmath.re(r) <= b:
                roots.append(mpmath.re(r))
    if values[-1] == 0:
        roots.append(grid[-1])
    drawn = _mp(pt[unknown]) if unknown in pt else (lo + hi) / 2
    if not roots:
        r = mpmath.findroot(g, mpmath.re(drawn), solver="secant")
        if mpmath.im(r) == 0 and lo <= r <= hi and abs(g(r)) <= tiny * size:
            roots.append(mpmath.re(r))
    return min(roots, key=lambda r: abs(r - mpmath.re(drawn))) if roots else None
