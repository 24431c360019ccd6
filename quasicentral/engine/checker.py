"""The checker: printed against derived — numerically on a precision ladder at many in-domain
points, symbolically (a proof decides the method), and with ball arithmetic where it decides a
refutation.

A *claim* is a pair of expressions that should be equal on the declared domain.  The order:

1. dimensions of every printed relation (an inconsistent one is refuted outright);
2. numeric: many random in-domain points (seeded by the id), each evaluated at the digits of
   every rung of the ladder; agreement must hold on every rung, a disagreement must be stable
   from rung to rung;
3. symbolic, unless the numbers already refute (then no simplification can return 0):
   p − d proved 0 within a CPU-time bound, cheapest means first (expansion and cancellation;
   the exponential form of sines and cosines; ``simplify``, unless p − d is seen non-zero at a
   point its symbols' assumptions allow; radicals combined as if positive);
   for an integral with a variable upper limit X, the fundamental theorem: d/dX (p − d) = 0
   and (p − d) = 0 at the lower limit.
   A proof makes the verdict "verified, symbolic"; a proof the numbers contradict is not
   trusted (inconclusive);
4. certified: the worst disagreement re-evaluated in python-flint balls; a ball for p − d that
   excludes 0 proves the printed form wrong at that point.
"""

from __future__ import annotations

import math
from fractions import Fraction
from dataclasses import dataclass, replace
from functools import lru_cache
from random import Random

import mpmath
import sympy as sp

from quasicentral.notation import bridge
from quasicentral.notation.dimensions import check_relation
from quasicentral.notation.domain import JET_RANGE, POSITIVE_JET_RANGE, Domain, Sampler, seed_for, substitute_definitions
from quasicentral.engine.registry import Derivation, Mode, as_list
from quasicentral.notation.symbols import SymbolTable
from quasicentral.notation.timelimit import TimeLimitExceeded, time_limit
from quasicentral.engine.verdict import Inconclusive, Method, Refuted, Verdict, Verified, Witness, combine


@dataclass(frozen=True)
class Options:
    """The checker's settings; every threshold it uses is named here."""

    dps: int = 30  # first rung of the ladder; the second is 2 × dps
    points: int = 20  # in-domain points per claim
    integral_points: int = 12  # per claim with an integral (a quadrature costs ~100× a closed form)
    confirm_points: int = 4  # points evaluated on every rung even where the first rung agrees
    symbolic_seconds: float = 3.0
    symbolic: bool = True
    certify: bool = True
    # integrand evaluations one witness ball may spend (~30 µs each at 200 bits): past this
    # its ball integral gives up and the value stays uncertified.  Counted, not timed, so that
    # a report's certified digits are the same on every machine
    certify_evaluations: int = 10_000
    agreement_exponent: float = 0.6  # agreement: |p − d| ≤ 10^(−0.6·dps)·scale on each rung
    stable_within: float = 1e-3  # a difference is real when it changes by less than this between rungs
    scale_floor: float = 1e-6  # the scale is at least this fraction of the median magnitude
    early_stop_after: int = 6  # points evaluated before a refutation may stop the run early ...
    early_stop_disagreements: int = 3  # ... once this many of them disagree for good
    remembered_values: int = 50_000  # derived values kept for an erratum's second comparison
    # False: a dimensionally inconsistent relation is refuted on its dimensions alone, without
    # the numbers (and so without a witness) — it is refuted whatever they say
    numbers_after_dimensions: bool = True

    MIN_DPS = 15  # below, the agreement tolerance 10^(−0.6·dps) would be too loose to mean anything

    def __post_init__(self):
        if self.dps < self.MIN_DPS:
            raise ValueError(f"the precision ladder starts at {self.MIN_DPS} digits or more, not {self.dps}")

    @property
    def ladder(self) -> tuple[int, ...]:
        return (self.dps, 2 * self.dps)


@dataclass(frozen=True)
class Claim:
    printed: sp.Expr
    derived: sp.Expr
    quantity: str
    scale: sp.Expr | None = None  # magnitude the difference is measured against


# --- building claims ----------------------------------------------------------------------
def _doit_derivatives(e):
    return e.replace(lambda a: isinstance(a, sp.Derivative), lambda a: a.doit()) if e.has(sp.Derivative) else e


def _solve_for(rel: sp.Basic, unknown: sp.Basic) -> sp.Expr | None:
    if not isinstance(rel, sp.Eq):
        return None
    if rel.lhs == unknown:
        return rel.rhs
    if rel.rhs == unknown:
        return rel.lhs
    dummy = sp.Dummy("u")
    expr = (rel.lhs - rel.rhs).xreplace({unknown: dummy})
    if dummy not in expr.free_symbols:
        return None
    coeff = sp.diff(expr, dummy)
    if dummy in coeff.free_symbols:
        sols = sp.solve(expr, dummy)
        return sols[0] if len(sols) == 1 else None
    return sp.cancel(-expr.xreplace({dummy: 0}) / coeff) if coeff.is_polynomial() else -expr.xreplace({dummy: 0}) / coeff


class CannotCompare(Exception):
    """The printed relations cannot be paired with the derivation's result (the reason)."""


def decided(rel: sp.Basic) -> sp.Basic:
    """A printed equation whose two sides are the same expression (True), or two numbers (sympy
    decides), as sympy's ``Eq`` would give it; any other relation as it is (a transcription
    keeps its equations undecided: :func:`quasicentral.notation.symbols.printed_eq`)."""
    if isinstance(rel, sp.Eq):
        if rel.lhs == rel.rhs:
            return sp.true
        if rel.lhs.is_number and rel.rhs.is_number:
            return sp.Eq(rel.lhs, rel.rhs)
    return rel


def claims_for(printed: list[sp.Basic], derivation: Derivation, result) -> list[Claim]:
    """Pair the printed relations with the derivation's result; :class:`CannotCompare` says
    why they cannot be."""
    mode = derivation.mode
    printed = [decided(rel) for rel in printed]
    if mode is Mode.CONDITION:
        if not all(isinstance(r, sp.Eq) for r in printed):
            raise CannotCompare("a condition is an equation")
        cond = {r.lhs: r.rhs for r in printed}
        q = _doit_derivatives(result)
        return [Claim(q.subs(cond), sp.Integer(0), f"{sp.sstr(q)} under the condition", sp.Abs(q))]
    if mode is Mode.SUBSTITUTE:
        model = dict(result or {})
        out = []
        for rel in printed:
            if isinstance(rel, sp.Eq):
                lhs = _doit_derivatives(_doit_derivatives(rel.lhs).subs(model))
                rhs = _doit_derivatives(_doit_derivatives(rel.rhs).subs(model))
                out.append(Claim(lhs - rhs, sp.Integer(0), "lhs - rhs on the derived solution",
                                 sp.Abs(lhs) + sp.Abs(rhs)))
            elif isinstance(rel, sp.Basic) and rel in (sp.true, sp.false):
                raise CannotCompare(f"printed relation evaluates to {rel}")
            else:
                out.append(Claim(_doit_derivatives(rel.subs(model)), sp.Integer(0), "expression on the derived solution"))
        return out
    derived = [_doit_derivatives(d) if isinstance(d, sp.Basic) else d for d in as_list(result)]
    printed = [_doit_derivatives(p) for p in printed]
    unknowns = derivation.unknowns
    if len(derived) == 1 and len(printed) > 1:
        # one derived relation, printed in several rows (a chain of equal forms): each row is
        # compared with it
        derived = derived * len(printed)
        unknowns = unknowns * len(printed) if unknowns is not None and len(unknowns) == 1 else unknowns
    if len(derived) != len(printed):
        raise CannotCompare(f"printed has {len(printed)} relation(s), derivation gives {len(derived)}")
    if mode is Mode.EXPRESSION:
        return [Claim(p, d, "value") for p, d in zip(printed, derived)]
    out = []
    unknowns = unknowns or tuple(d.lhs for d in derived)
    for p, d, unk in zip(printed, derived, unknowns):
        unk = _doit_derivatives(unk)
        if p in (sp.true, sp.false):
            raise CannotCompare(f"printed relation evaluates to {p}")
        pv, dv = _solve_for(p, unk), _solve_for(d, unk)
        if dv is None:
            raise CannotCompare(f"cannot solve the derived relation for {sp.sstr(unk)}")
        if pv is not None:
            out.append(Claim(pv, dv, sp.sstr(unk)))
        elif isinstance(p, sp.Eq):
            # not solvable for the unknown (absent, or several branches): the printed relation
            # must still hold wherever the derived one does
            lhs, rhs = p.lhs.xreplace({unk: dv}), p.rhs.xreplace({unk: dv})
            out.append(Claim(lhs - rhs, sp.Integer(0), f"printed lhs - rhs where {sp.sstr(unk)} is derived",
                             sp.Abs(lhs) + sp.Abs(rhs)))
        else:
            raise CannotCompare(f"the printed entry is not an equation for {sp.sstr(unk)}")
    return out


# --- the stages -----------------------------------------------------------------------------
def symbolic_zero(diff: sp.Expr, seconds: float, force: bool = True) -> bool:
    """True when sympy proves ``diff`` identically zero within ``seconds``.  With ``force``, a
    last attempt combines radicals as if their radicands were positive (see
    :func:`_forced_zero`): a proof on the physical domain, which the numeric stage then checks
    at every point.  The answer is remembered for the same expression (a display the text
    repeats, an erratum's claims that share their difference): each is sought once."""
    key = (diff, seconds, force)
    if key not in _PROOFS:
        if len(_PROOFS) > PROOFS_REMEMBERED:
            _PROOFS.clear()
        _PROOFS[key] = _symbolic_zero(diff, seconds, force)
    return _PROOFS[key]


_PROOFS: dict = {}
PROOFS_REMEMBERED = 10_000  # answers of symbolic_zero kept in one process


def _symbolic_zero(diff: sp.Expr, seconds: float, force: bool) -> bool:
    try:
        with time_limit(seconds):
            if diff == 0:
                return True
            if diff.has(sp.Integral):  # simplify cannot see through an integral: differentiate it
                return _ftc_zero(diff, force)
            return _zero(diff, force)
    except TimeLimitExceeded:
        return False
    except Exception:  # noqa: BLE001 - a CAS failure proves nothing
        return False


_TRIGONOMETRIC = (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc)


def _zero(e: sp.Expr, force: bool) -> bool:
    """The proof, cheapest means first.  Expansion and cancellation prove nine in ten of the
    catalog's identities at a fifth of simplify's cost.  Of the rest, those in sines and cosines
    fall to their exponential form (sin x = (e^(ix) − e^(−ix))/2i, every step an identity for
    all complex values) expanded and cancelled, at a tenth of simplify's cost, which spends half
    its time in trigsimp; simplify (trigonometric, radicals) takes what is left — unless a few
    numbers show that it cannot succeed (:func:`_seen_nonzero`)."""
    expanded = sp.expand(e)
    if expanded == 0 or _rational_zero(expanded):
        return True
    if e.has(*_TRIGONOMETRIC):
        exponential = sp.expand(sp.powsimp(sp.expand(e.rewrite(sp.exp))))
        if exponential == 0 or _rational_zero(exponential):
            return True
    if not _seen_nonzero(e) and sp.simplify(e, doit=False) == 0:
        return True
    return force and _forced_zero(e)


#: points at which :func:`_seen_nonzero` evaluates an expression, and the digits it uses
NONZERO_POINTS = 3
NONZERO_DPS = 30
#: |e| above this fraction of the sum of its terms' magnitudes is not a rounding error at
#: NONZERO_DPS digits (a true identity leaves about 10^-29 of it)
NONZERO_MARGIN = sp.Float("1e-15")
#: the reach of a sampled value: |x| < NONZERO_REACH (wide, so that a sign or a branch that an
#: identity depends on shows: sin(φ0/2) changes sign at φ0 = 2π)
NONZERO_REACH = 16
#: facts a sampled value is not made to obey: an expression whose symbols carry one is not sampled
_UNSAMPLED_FACTS = ("even", "odd", "prime", "composite", "zero", "imaginary", "noninteger", "irrational",
                    "transcendental", "polar", "infinite")
#: what would let sympy see into a function defined outside sympy
_SEEING_HOOKS = ("eval", "_eval_")


def _seen_nonzero(e: sp.Expr) -> bool:
    """True when ``e`` is clearly not 0 at one of a few points that sympy's assumptions allow:
    then no sound simplification returns 0, and simplify (the costliest means, most of the
    time of a proof that fails) is not tried.  Each free symbol takes a value from the set its
    assumptions name (positive, real, integer, …; complex where none is said); so does each
    application of a function sympy cannot see into (an undefined x(t), its derivatives, a
    function class without evaluation rules of its own, such as one computed by ``_imp_``):
    for simplify it is a bare value.  Seeded by the expression, the points are the same in
    every run.  Where anything is in doubt (an integral or a sum, a value that cannot be
    computed, a function met at two different arguments) the answer is False: simplify
    decides as before.  A proof this test prevents is one that sympy could only have given
    in error."""
    if not _samplable(e):
        return False
    opaque: dict = {}
    for f in sorted(e.atoms(sp.Derivative, sp.Function), key=sp.default_sort_key):
        if isinstance(f, sp.Derivative) or _opaque(f):
            opaque[f] = sp.Dummy(**{fact: True for fact in ("integer", "positive", "nonnegative", "negative",
                                                            "nonpositive", "real")
                                    if getattr(f, "is_" + fact)})
    heads = [f.func if not isinstance(f, sp.Derivative) else (f.expr.func, f.variable_count) for f in opaque]
    if len(heads) != len(set(heads)):
        return False  # f(a) and f(b): simplify might show a = b, independent values would not
    if any(getattr(f, "is_" + fact) for f in opaque for fact in _UNSAMPLED_FACTS):
        return False
    # derivatives first (they contain the function), then the functions
    sampled = e.xreplace({f: d for f, d in opaque.items() if isinstance(f, sp.Derivative)})
    sampled = sampled.xreplace({f: d for f, d in opaque.items() if not isinstance(f, sp.Derivative)})
    symbols = sorted(sampled.free_symbols, key=sp.default_sort_key)
    if any(getattr(s, "is_" + fact) for s in symbols for fact in _UNSAMPLED_FACTS):
        return False
    terms = sampled.args if isinstance(sampled, sp.Add) else (sampled,)
    rng = Random(seed_for(sp.srepr(e)))
    for _ in range(NONZERO_POINTS):
        point = {s: _assumed_value(s, rng) for s in symbols}
        try:
            values = [t.evalf(NONZERO_DPS, subs=point) for t in terms]
        except (TypeError, ValueError, ZeroDivisionError, ArithmeticError):
            continue
        if not all(v.is_number and v.is_finite for v in values):
            continue
        total = sp.Add(*values)
        if total.is_finite and abs(total) > NONZERO_MARGIN * sum(abs(v) for v in values):
            return True
    return False


def _samplable(e: sp.Expr) -> bool:
    """No integral, sum, product or limit; each derivative one of an undefined function's."""
    return (not e.has(sp.Integral, sp.Sum, sp.Product, sp.Limit)
            and all(isinstance(d.expr, sp.core.function.AppliedUndef) for d in e.atoms(sp.Derivative)))


def _opaque(f: sp.Basic) -> bool:
    """An application sympy's simplification sees only as a value: an undefined function, or a
    class defined outside sympy with no evaluation rule or rewrite of its own (``eval``,
    ``_eval_*``)."""
    if isinstance(f, sp.core.function.AppliedUndef):
        return True
    own = [c for c in type(f).__mro__ if not (c.__module__ or "").startswith("sympy") and c is not object]
    return bool(own) and not any(name.startswith(_SEEING_HOOKS) for c in own for name in vars(c))


def _assumed_value(s: sp.Symbol, rng: Random) -> sp.Expr:
    """A value in the set ``s``'s assumptions name: an integer 1…9 (or −9…9 without 0), a
    rational in (0, NONZERO_REACH) or (−NONZERO_REACH, NONZERO_REACH), or a complex one."""
    def rational() -> sp.Rational:
        return sp.Rational(rng.randrange(1, NONZERO_REACH * 2**16), 2**16)

    if s.is_integer:
        if s.is_positive or s.is_nonnegative:
            return sp.Integer(rng.randint(1, 9))
        if s.is_negative or s.is_nonpositive:
            return sp.Integer(-rng.randint(1, 9))
        return sp.Integer(rng.choice([-1, 1]) * rng.randint(1, 9))
    if s.is_positive or s.is_nonnegative:
        return rational()
    if s.is_negative or s.is_nonpositive:
        return -rational()
    if s.is_real:
        return rng.choice([-1, 1]) * rational()
    return rng.choice([-1, 1]) * rational() + sp.I * rng.choice([-1, 1]) * rational()


def _rational_zero(e: sp.Expr) -> bool:
    """``e`` is 0 as a rational function of its generators: the numerator of its form over a
    common denominator expands to 0 (``together`` is an identity).  Where the answer is yes,
    ``cancel`` would say 0 too, but it first computes the numerator's gcd with the denominator,
    which a zero test does not need (a seventh of the symbolic stage's time)."""
    return sp.expand(sp.fraction(sp.together(e))[0]) == 0


def _forced_zero(e: sp.Expr) -> bool:
    """√a·√b = √(ab) as if every radicand were positive — true inside the physical domains
    (|ζ| ≤ 1, k² < 1, …) though not for all complex values; the numeric cross-check that
    follows every proof guards against a domain where it fails.  Where forcing changes nothing,
    simplify has already failed on this very expression (:func:`_zero`): not tried again."""
    forced = sp.powsimp(sp.powdenest(e, force=True), force=True)
    return forced != e and (forced == 0 or not _seen_nonzero(forced) and sp.simplify(forced, doit=False) == 0)


def _ftc_zero(diff: sp.Expr, force: bool = True) -> bool:
    """Integrals with a variable upper limit X: d/dX diff ≡ 0 and diff(lower limit) = 0."""
    for integral in diff.atoms(sp.Integral):
        for lim in integral.limits:
            if len(lim) == 3 and isinstance(lim[2], sp.Symbol):
                X, lower = lim[2], lim[1]
                dd = sp.diff(diff, X)
                if dd == 0 or _zero(dd, force):
                    # integrals over [a, a] vanish and those over [b, a] are −∫_a^b before sympy
                    # tries to integrate them (for an elliptic integrand it would search for an
                    # antiderivative until the bound): equal integrals then cancel as terms
                    at_lower = diff.subs(X, lower).replace(lambda e: isinstance(e, sp.Integral), _oriented)
                    if at_lower == 0:
                        return True
                    at_lower = at_lower.doit()
                    if at_lower == 0 or _zero(at_lower, False):
                        return True
    return False


def _oriented(integral: sp.Integral) -> sp.Expr:
    """A one-variable definite integral with numeric limits in increasing order (0 over an empty
    path); any other integral as it is."""
    if len(integral.limits) == 1 and len(integral.limits[0]) == 3:
        var, lo, hi = integral.limits[0]
        if lo == hi:
            return sp.S.Zero
        if lo.is_comparable and hi.is_comparable and (lo > hi) is sp.true:
            return -sp.Integral(integral.function, (var, hi, lo))
    return integral


def _jet_ranges(syms) -> dict:
    out = {}
    for s in syms:
        if bridge.is_jet(s):
            out[s] = POSITIVE_JET_RANGE if s.is_positive else JET_RANGE
    return out


_DERIVED_VALUES: dict = {}


def numeric(claim: Claim, domain: Domain, label: str, opts: Options, table: SymbolTable) -> Verdict:
    defs = domain.definition_map(table)
    p = bridge.to_jets(bridge.close_infinite_sums(substitute_definitions(claim.printed, defs)))
    d = bridge.to_jets(bridge.close_infinite_sums(substitute_definitions(claim.derived, defs)))
    scale = (bridge.to_jets(bridge.close_infinite_sums(substitute_definitions(claim.scale, defs)))
             if claim.scale is not None else None)
    syms = set(p.free_symbols) | set(d.free_symbols) | (scale.free_symbols if scale is not None else set())
    try:
        integral = p.has(sp.Integral) or d.has(sp.Integral)
        count = min(opts.points, opts.integral_points) if integral else opts.points
        pts = Sampler(domain, table, sorted(syms, key=str), seed_for(label), _jet_ranges(syms)).draw(count)
    except KeyError as exc:
        return Inconclusive(Method.NONE, f"{exc.args[0]}")
    if len(pts) < max(3, count // 2):
        return Inconclusive(Method.NONE, "the domain's constraints leave too few points")
    args = tuple(sorted(syms, key=str))
    fp = bridge.rung_function(p, args)
    fs = bridge.rung_function(scale, args) if scale is not None else None
    # the derived side is shared by an erratum's printed and corrected forms (same points):
    # its values are remembered, keyed by the expression, the exact point and the digits
    d_args = tuple(sorted(d.free_symbols, key=str))
    fd_own = bridge.rung_function(d, d_args)

    def fd(pt, dps):
        key = (d, tuple(pt[a] for a in d_args), dps)  # the expression and exact numbers: hashed structurally
        if key not in _DERIVED_VALUES:
            if len(_DERIVED_VALUES) > opts.remembered_values:
                _DERIVED_VALUES.clear()
            _DERIVED_VALUES[key] = +fd_own(*[bridge.mp_value(pt[a], dps) for a in d_args])
        return _DERIVED_VALUES[key]

    def rung(pt, dps):
        with mpmath.workdps(dps):
            vals = [bridge.mp_value(pt[a], dps) for a in args]
            pv, dv = +fp(*vals), fd(pt, dps)
            mag = max(abs(pv), abs(dv))
            if fs is not None:
                mag = max(mag, abs(+fs(*vals)))
            diff = abs(pv - dv)
            if not (mpmath.isfinite(diff) and mpmath.isfinite(mag)):
                raise ValueError("not finite")
        return pv, dv, diff, mag

    def divergent(before_numbers: bool = False) -> Verdict | None:
        """A printed integral that diverges at an endpoint (integrand ~ |x − e|^(−q), q ≥ 1),
        or a printed series whose terms grow, is refuted with that reason: its quadratures or
        partial sums only return noise.  Where the numbers have failed, one of the first four
        points showing it is enough; ``before_numbers``, the integrals alone are tested (a
        series' test sums in sympy) and every one of the four points must show it."""
        if not (p.has(sp.Integral) or (not before_numbers and p.has(sp.Sum))):
            return None
        seen = ((pt, integral_divergence(p, pt) or ("" if before_numbers else series_divergence(p, pt)))
                for pt in pts[:4])
        if before_numbers:
            seen = list(seen)
            if not seen or not all(why for _, why in seen):
                return None
        pt, why = next(((pt, why) for pt, why in seen if why), (None, ""))
        if not why:
            return None
        w = Witness(parameters={str(k): sp.sstr(v) for k, v in sorted(pt.items(), key=lambda kv: str(kv[0]))},
                    printed="divergent", corrected="", digits=0, certified=False, quantity=claim.quantity,
                    relative_difference="inf", working_digits=opts.ladder[-1])
        return Refuted(Method.NUMERIC, f"the printed form diverges: {why}", len(pts), opts.ladder, witness=w)

    # an endpoint where the printed integrand is not integrable is seen in a few evaluations,
    # where its quadratures would cost seconds and return noise
    dv_ = divergent(before_numbers=True)
    if dv_ is not None:
        return dv_
    # The ladder, economically: every point on the first rung; the higher rungs where the first
    # does not agree (a difference must prove stable) and at the first few points (a true but
    # tiny difference, below the first rung's tolerance, shows at every point of the domain).
    rows = []  # per point: the rungs evaluated, each (pv, dv, diff, mag)
    early = False
    for i_pt, pt in enumerate(pts):
        if i_pt >= opts.early_stop_after and _refuted_already(rows, opts):
            early = True  # a refutation stands; further points would only cost time
            break
        try:
            row = [rung(pt, opts.ladder[0])]
            pv, dv, diff, mag = row[0]
            if i_pt < opts.confirm_points or not _agrees(diff, mag, opts.ladder[0], opts):
                row += [rung(pt, dps) for dps in opts.ladder[1:]]
        except (ValueError, ZeroDivisionError, TypeError, OverflowError, mpmath.libmp.NoConvergence):
            continue
        rows.append((pt, row))

    if not early and len(rows) < max(3, (4 * len(pts) + 4) // 5):
        dv_ = divergent()
        if dv_ is not None:
            return dv_
        # a point where a side cannot be evaluated is not evidence of agreement: at most a
        # fifth of them may drop out
        return Inconclusive(Method.NONE, f"only {len(rows)} of {len(pts)} points could be evaluated")
    disagree, unstable = [], 0
    for (kind, rel), (pt, row) in zip(_classify(rows, opts), rows):
        if kind == "disagree":
            disagree.append((rel, pt, row))
        elif kind == "unstable":
            unstable += 1
    n, ladder = len(rows), opts.ladder
    if disagree:
        rel, pt, row = max(disagree, key=lambda r: r[0])
        witness = _witness(claim, p, d, pt, row, ladder[-1], opts, rel)
        method = Method.CERTIFIED if witness.certified else Method.NUMERIC
        return Refuted(method, f"{len(disagree)} of {n} points disagree (largest relative difference {rel:.3g})",
                       n, ladder, witness=witness)
    if unstable:
        dv_ = divergent()
        if dv_ is not None:
            return dv_
        return Inconclusive(Method.NUMERIC, f"{unstable} of {n} points unstable under the precision ladder", n, ladder)
    counted = f"{n} of {len(pts)}" if n < len(pts) else f"{n}"
    vacuous = all(r[-1][3] == 0 for _, r in rows)
    confirmed = sum(len(r) == len(ladder) for _, r in rows)
    return Verified(Method.NUMERIC, f"agrees at {counted} points to {math.floor(opts.agreement_exponent * ladder[0])}+ "
                    f"digits ({confirmed} of them also at {ladder[-1]} digits)"
                    + (" (both sides vanish at every point)" if vacuous else ""), n, ladder)


def integral_divergence(expr: sp.Expr, pt: dict) -> str:
    """Why an integral of ``expr`` diverges at the point ``pt`` ("" if none is seen): at an
    endpoint where the integrand is unbounded, its growth order q in |f| ~ |x − e|^(−q) is
    estimated from two distances (1e-10, 1e-20) at 40 digits; q ≥ 1 − 1e-3 is not integrable."""
    for integral in expr.atoms(sp.Integral):
        if len(integral.limits) != 1 or len(integral.limits[0]) != 3:
            continue
        x, a, b = integral.limits[0]
        outer = tuple(sorted(integral.function.free_symbols - {x}, key=str))
        if any(s not in pt for s in outer):
            continue
        try:
            with mpmath.workdps(40):
                ends = [bridge.mp_value(sp.sympify(e).xreplace(pt), 40) for e in (a, b)]
                # compiled once for every point (mp_function remembers it), the point's values as arguments
                f = bridge.mp_function(integral.function, (x,) + outer)
                values = [bridge.mp_value(pt[s], 40) for s in outer]
                for e, inward in ((ends[0], 1), (ends[1], -1)):
                    if mpmath.im(e) != 0:
                        continue
                    direction = inward if ends[1] >= ends[0] else -inward
                    g1 = abs(f(e + direction * mpmath.mpf("1e-10"), *values))
                    g2 = abs(f(e + direction * mpmath.mpf("1e-20"), *values))
                    if not (mpmath.isfinite(g1) and mpmath.isfinite(g2)) or g1 == 0 or g2 <= g1:
                        continue
                    q = mpmath.log(g2 / g1) / mpmath.log(mpmath.mpf(10) ** 10)
                    if q >= 1 - 1e-3:
                        return (f"the integrand grows like |{x} − {mpmath.nstr(e, 8)}|^(−{mpmath.nstr(q, 3)}) "
                                f"at an end of the path (not integrable)")
        except (ValueError, ZeroDivisionError, TypeError, OverflowError):
            continue
    return ""


def series_divergence(expr: sp.Expr, pt: dict) -> str:
    """Why an infinite series of ``expr`` diverges at ``pt`` ("" if none is seen): the ratio
    test, |a(n+1)/a(n)| at n = 100 and 200 (30 digits), both above 1 + 1e-3 and not falling."""
    for sm in expr.atoms(sp.Sum):
        if len(sm.limits) != 1 or sm.limits[0][2] is not sp.oo:
            continue
        var = sm.limits[0][0]
        term = sm.function.xreplace(pt)
        if term.free_symbols - {var}:
            continue
        try:
            with time_limit(2.0):
                r = [abs(sp.N(term.subs(var, k + 1) / term.subs(var, k), 30)) for k in (100, 200)]
        except (TimeLimitExceeded, ValueError, TypeError, ZeroDivisionError):
            continue
        if all(x.is_number and x.is_finite for x in r) and r[0] > 1 + 1e-3 and r[1] >= r[0] * (1 - 1e-6):
            return (f"the terms of the series in {var} grow (|a(n+1)/a(n)| = {sp.N(r[0], 4)} at n = 100, "
                    f"{sp.N(r[1], 4)} at n = 200): it does not converge")
    return ""


def _agrees(diff, ref, dps: int, opts: Options) -> bool:
    return diff <= _tolerance(opts.agreement_exponent, dps) * ref


@lru_cache(maxsize=64)
def _tolerance(exponent: float, dps: int):
    """10^(−exponent·dps), a threshold: in double precision (once per rung, not per comparison)."""
    with mpmath.workprec(53):
        return mpmath.mpf(10) ** (-exponent * dps)


def _classify(rows, opts: Options) -> list[tuple[str, float]]:
    """Each point as ("agree" | "disagree" | "unstable", relative difference).  All in mpmath:
    values far beyond the double range (factorials, 2^(n²)) must not overflow to inf.

    Agreement: |p − d| ≤ 10^(−0.6·dps)·scale on every rung evaluated.  A true difference:
    resolved on no rung, and stable (within ``opts.stable_within``) from the first rung to the
    last; anything else is noise of an ill-conditioned evaluation.  The scale is max(|p|, |d|),
    floored at ``opts.scale_floor`` of the median magnitude.
    """
    ladder = opts.ladder
    mags = sorted((abs(r[-1][3]) for _, r in rows), key=lambda m: m)
    floor = mags[len(mags) // 2] * mpmath.mpf(opts.scale_floor) if mags else mpmath.mpf(0)
    out = []
    for _, row in rows:
        refs = [max(mag, floor) or mpmath.mpf(1) for (_, _, _, mag) in row]
        ok = [_agrees(diff, ref, dps, opts) for (dps, (_, _, diff, _), ref) in zip(ladder, row, refs)]
        lo, hi = row[0][2], row[-1][2]
        rel = float(min(hi / refs[-1], mpmath.mpf(1e300)))
        if all(ok):
            out.append(("agree", rel))
        elif len(row) > 1 and not any(ok) and abs(lo - hi) <= mpmath.mpf(opts.stable_within) * hi:
            out.append(("disagree", rel))
        else:
            out.append(("unstable", rel))
    return out


def _refuted_already(rows, opts) -> bool:
    """Enough points that already disagree for good."""
    if len(rows) < opts.early_stop_after:
        return False
    # a point can disagree only if its first rung does not agree even against its own magnitude
    # (the scale floor only raises the reference): most runs stop here, without classifying
    # every row again at every point
    candidates = sum(len(r) > 1 and not (r[0][3] and _agrees(r[0][2], r[0][3], opts.ladder[0], opts))
                     for _, r in rows)
    return (candidates >= opts.early_stop_disagreements
            and sum(k == "disagree" for k, _ in _classify(rows, opts)) >= opts.early_stop_disagreements)


def _witness(claim, p, d, pt, row, dps, opts, rel) -> Witness:
    """The witness at ``pt``: both values with only guaranteed digits (see :func:`witness_values`)."""
    pv, dv = row[-1][0], row[-1][1]
    lo_rung = (row[0][0], row[0][1])
    vals = witness_values(p, d, pt, (pv, dv), lo_rung, dps, opts)
    return Witness(
        parameters={str(s): sp.sstr(v) for s, v in sorted(pt.items(), key=lambda kv: str(kv[0]))},
        printed=vals.printed, corrected=vals.corrected, digits=min(vals.printed_digits, vals.corrected_digits),
        certified=vals.certified, quantity=claim.quantity, relative_difference=f"{rel:.3e}",
        printed_certified=vals.printed_certified, corrected_certified=vals.corrected_certified,
        working_digits=dps,
    )


WITNESS_DIGITS = 20  # significant digits a witness value shows at most
IMAGINARY_NEGLIGIBLE = 10.0 ** -(WITNESS_DIGITS + 5)  # an imaginary bound this far below the real part
BALL_PREC_LIMIT = 4096  # bits: the last precision tried for a witness ball
WITNESS_BUDGET = 4  # integrand evaluations of a witness's balls, in units of Options.certify_evaluations


@dataclass(frozen=True)
class WitnessValues:
    printed: str
    corrected: str
    printed_digits: int
    corrected_digits: int
    printed_certified: bool
    corrected_certified: bool
    certified: bool  # the ball of printed − corrected excludes 0


def witness_values(p, d, pt, top, low, dps, opts, want: int = WITNESS_DIGITS) -> WitnessValues:
    """Both witness values, every digit shown guaranteed.

    With balls (python-flint, as ``good()`` does): start at the ladder's precision and double
    until both balls round to ``want`` significant digits at both ends and the ball of the
    difference decides, or :data:`BALL_PREC_LIMIT` is reached; a value is then printed with the
    digits its ball guarantees (correctly rounded).  Where a side has no ball form (an integrand
    unbounded at an end of the path, a function without a ball evaluation), its value is
    recomputed at twice the top rung's precision and only the digits on which the two agree are
    shown (``*_certified`` False).  Without ``opts.certify`` (the fast mutation checker) the two
    rungs of the ladder play that part.
    """
    balls: list = [None, None]
    certified = False
    if opts.certify:
        prec = max(64, int(dps * 3.33) + 8)
        # the whole ladder of balls shares one budget: a ball integral's cost grows fast with
        # the precision, and running out only turns its integrand into NaN
        work = bridge.Work(WITNESS_BUDGET * opts.certify_evaluations)
        stalled = [False, False]
        while True:
            for i, expr in enumerate((p, d)):
                if balls[i] is not None and _ball_digits(balls[i], want) >= want:
                    continue
                if balls[i] is False or stalled[i] or (work.spent and balls[i] is not None):
                    continue
                try:
                    b = bridge.arb_eval(expr, pt, prec=prec, work=work.share(opts.certify_evaluations))
                except (bridge.Unsupported, ValueError, ZeroDivisionError, TypeError, AttributeError):
                    b = None
                # a ball that is not finite (out of work, or unbounded) will not become finite
                # at a higher precision: keep the last good one, or give up on balls for this side.
                # Nor will one that gained no digit from the doubled precision (its integral is
                # limited by the evaluations, not the precision): keep it and stop there
                if b is not None and b.is_finite():
                    old = balls[i]
                    if old is not None and _ball_digits(b, want) <= _ball_digits(old, want):
                        stalled[i] = True
                        b = b if _ball_digits(b, want) == _ball_digits(old, want) else old
                    balls[i] = b
                elif balls[i] is None:
                    balls[i] = False
            if all(b is not None and b is not False for b in balls):  # identity: acb(0) == False
                certified = not (balls[0] - balls[1]).contains(0)
            done = all(b is False or stalled[i] or (b is not None and _ball_digits(b, want) >= want)
                       for i, b in enumerate(balls))
            settled = done and (certified or any(b is False for b in balls))
            if settled or prec >= BALL_PREC_LIMIT or work.spent:
                break
            prec *= 2
    out = []
    for i in range(2):
        b = balls[i]
        n = _ball_digits(b, want) if b is not None and b is not False else 0
        if n >= 1:
            out.append((_ball_str(b, n), n, True))
            continue
        # no ball: agreement with a recomputation at twice the precision
        if opts.certify:
            try:
                again = bridge.mp_eval((p, d)[i], pt, 2 * dps)
            except (ValueError, ZeroDivisionError, TypeError, OverflowError, mpmath.libmp.NoConvergence):
                again = None
            ref, other = again, top[i]
        else:
            ref, other = top[i], low[i]
        s, n = _agreed(ref, other, want) if ref is not None else ("", 0)
        out.append((s, n, False))
    (ps, pn, pc), (cs, cn, cc) = out
    return WitnessValues(ps, cs, pn, cn, pc, cc, certified)


def _real_part(b):
    """The real ball of an acb whose imaginary part is 0 or negligible, else None.  A ball
    integral of a real integrand along a real path comes back with an imaginary part of
    [± tiny] (a bound, not a value): below 10^−(WITNESS_DIGITS + 5) of the real part it
    cannot move any digit shown."""
    im, re = b.imag, b.real
    if im.is_exact() and im == 0:
        return re
    if im.contains(0) and not re.contains(0) and im.rad() <= abs(re).lower() * IMAGINARY_NEGLIGIBLE:
        return re
    return None


def _ball_digits(b, want: int) -> int:
    """How many significant digits (≤ want) both ends of the real ball ``b`` round to alike."""
    r = _real_part(b) if b is not None and b is not False else None
    if r is None:
        return 0
    if r.is_exact() and r == 0:
        return want
    mid, rad = _exact(r.mid()), _exact(r.rad())  # exact (lower()/upper() would round)
    lo, hi = mid - rad, mid + rad
    if lo == 0 or hi == 0 or (lo > 0) != (hi > 0):
        return 0
    for n in range(want, 0, -1):
        if round_significant(lo, n) == round_significant(hi, n):
            return n
    return 0


def _ball_str(b, n: int) -> str:
    r = _real_part(b)
    if r.is_exact() and r == 0:
        return "0"
    return round_significant(_exact(r.mid()), n)


def _exact(x) -> Fraction:
    """An exact arb (a ball's end), mpf or Python number as a fraction."""
    if isinstance(x, (int, float)):
        return Fraction(x)
    if not hasattr(x, "man_exp"):
        x = mpmath.mpf(x)
    if isinstance(x, mpmath.mpf):
        sgn, man, exp, _ = x._mpf_
        if not man:
            return Fraction(0)
        man = -man if sgn else man
    else:
        man, exp = x.man_exp()
    man, exp = int(man), int(exp)
    return Fraction(man * 2**exp) if exp >= 0 else Fraction(man, 2**-exp)


def round_significant(x: Fraction, n: int) -> str:
    """``x`` correctly rounded (half to even) to ``n`` significant decimal digits, exactly."""
    if x == 0:
        return "0"
    sign = "-" if x < 0 else ""
    a = abs(x)
    e10 = len(str(a.numerator)) - len(str(a.denominator))  # within one of floor(log10 a)
    while a >= Fraction(10) ** (e10 + 1):
        e10 += 1
    while a < Fraction(10) ** e10:
        e10 -= 1
    q = round(a * Fraction(10) ** (n - 1 - e10))  # Fraction.__round__: half to even, exact
    if q >= 10**n:
        q //= 10
        e10 += 1
    digits = str(q)
    if -5 <= e10 < n:
        if e10 >= 0:
            whole, frac = digits[:e10 + 1], digits[e10 + 1:]
            return sign + whole + ("." + frac if frac else "")
        return sign + "0." + "0" * (-e10 - 1) + digits
    return sign + digits[0] + ("." + digits[1:] if n > 1 else "") + f"e{e10:+d}"


def _agreed(a, b, want: int) -> tuple[str, int]:
    """The digits (≤ want) on which two evaluations of one value agree, from the more precise."""
    a, b = _as_real(a), _as_real(b)
    if a is None or b is None:
        return "", 0
    if a == 0 and b == 0:
        return "0", want
    fa, fb = _exact(a), _exact(b)
    for n in range(want, 0, -1):
        sa = round_significant(fa, n)
        if sa == round_significant(fb, n):
            return sa, n
    return "", 0


def _as_real(v):
    if isinstance(v, mpmath.mpc):
        if abs(v.imag) <= abs(v) * mpmath.mpf(10) ** (-40):
            return v.real
        return None
    return v


def check(printed: list[sp.Basic], dims: dict, derivation: Derivation, label: str, opts: Options,
          table: SymbolTable) -> Verdict:
    """The verdict on ``printed`` against ``derivation`` (see the module docstring)."""
    from quasicentral.engine.registry import derived

    found = [c for c in (check_relation(rel, dims) for rel in printed) if c.inconsistent or c.undetermined]
    dim_problems = [c.reason for c in found if c.inconsistent]
    dim_text = ("inconsistent: " + "; ".join(dim_problems) if dim_problems
                else "; ".join(str(c) for c in found) if found else "consistent")

    if dim_problems and not opts.numbers_after_dimensions:
        return Refuted(Method.DIMENSIONAL, "dimensionally inconsistent", dimensions=dim_text)

    def unsettled(reason: str) -> Verdict:
        # a relation whose two sides differ in dimension is wrong whatever the comparison
        if dim_problems:
            return Refuted(Method.DIMENSIONAL, f"dimensionally inconsistent ({reason})", dimensions=dim_text)
        return Inconclusive(Method.NONE, reason, dimensions=dim_text)

    try:
        result = derived(derivation.id)
    except Exception as exc:  # noqa: BLE001 - a failing derivation is an inconclusive entry
        return unsettled(f"derivation failed: {type(exc).__name__}: {exc}")
    try:
        with time_limit(opts.symbolic_seconds):
            claims = claims_for(printed, derivation, result)
    except CannotCompare as exc:
        return unsettled(str(exc))
    except TimeLimitExceeded:
        return unsettled(f"cannot set up the comparison: sympy did not solve the relation within {opts.symbolic_seconds} s")
    except Exception as exc:  # noqa: BLE001 - a relation sympy cannot solve is inconclusive
        return unsettled(f"cannot set up the comparison: {type(exc).__name__}: {exc}"[:300])
    verdicts = []
    defs = derivation.domain.definition_map(table)
    for i, claim in enumerate(claims):
        # Every claim is checked at every point; the symbolic stage (bounded in CPU time) then
        # tries to prove what the numbers found equal — where they found a difference no
        # simplification can return 0, and the bound is not spent.  A proof the numbers
        # contradict is not trusted (a CAS slip, or a rewrite that holds on part of the domain).
        v = numeric(claim, derivation.domain, f"{label}#{i}", opts, table)
        if opts.symbolic and not isinstance(v, Refuted) and symbolic_zero(
                substitute_definitions(claim.printed - claim.derived, defs), opts.symbolic_seconds):
            if isinstance(v, Verified):
                v = Verified(Method.SYMBOLIC, "sympy proves the difference zero; " + v.detail, v.points, v.digits)
            else:
                v = Inconclusive(Method.NONE, f"sympy proves zero but numerics say {v.name}: {v.detail}",
                                 v.points, v.digits)
        verdicts.append(v)
    out = combine(verdicts)
    if dim_problems and not isinstance(out, Refuted):
        return Refuted(Method.DIMENSIONAL, f"dimensionally inconsistent ({out.name} numerically)",
                       out.points, out.digits, dimensions=dim_text)
    return replace(out, dimensions=dim_text)
