"""The numeric stage: a claim evaluated at many in-domain points on a precision ladder.

Every point is evaluated on the first rung; the higher rungs where the first does not agree (a
difference must prove stable) and at the first few points (a true but tiny difference, below
the first rung's tolerance, shows at every point of the domain).  Agreement at a rung means
|p − d| ≤ 10^(−0.6·dps)·scale, the scale being the largest of |p|, |d|, the claim's own scale
and the magnitudes of the terms of each side — so that a side that is exactly zero (a
condition at its root) is compared with the size of what cancels there, not with itself.  A
disagreement must be resolved on no rung and stable from rung to rung; anything else is noise
of an ill-conditioned evaluation.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from enum import Enum
from functools import lru_cache

import mpmath
import sympy as sp
from sympy.core.function import AppliedUndef

from quasicentral.engine.claims import Claim
from quasicentral.engine.options import Options
from quasicentral.engine.reasons import Code, Reason
from quasicentral.engine.verdict import Inconclusive, Method, Refuted, Verdict, Verified, Witness
from quasicentral.engine.witness import witness_at
from quasicentral.notation import bridge
from quasicentral.notation.domain import (JET_RANGE, POSITIVE_JET_RANGE, Domain, Sampler, on_condition, seed_for,
                                          substitute_definitions)
from quasicentral.notation.symbols import SymbolTable

#: the exceptions an evaluation at one point may raise: the point drops out
EVALUATION_ERRORS = (ValueError, ZeroDivisionError, TypeError, OverflowError, ArithmeticError,
                     mpmath.libmp.NoConvergence, AttributeError, NotImplementedError, RecursionError)
#: the most terms of a side whose magnitudes make its scale
SCALE_TERMS = 64


class PointClass(Enum):
    AGREE = "agree"
    VANISHES = "vanishes"  # agrees: the difference falls with the working precision (an exact zero)
    DISAGREE = "disagree"
    UNSTABLE = "unstable"


@dataclass(frozen=True)
class Rung:
    """One point on one rung: both values, their difference and the magnitudes it is judged by."""

    printed: object
    derived: object
    diff: object
    magnitude: object  # max(|p|, |d|, |scale|)
    terms: object = None  # the terms' magnitude, computed only where the values do not agree
    # the difference kept falling on a rung beyond the ladder too (checked only where it fell on it)
    falls: bool = False


def _jet_ranges(syms) -> dict:
    return {s: POSITIVE_JET_RANGE if s.is_positive else JET_RANGE for s in syms if bridge.is_jet(s)}


def prepared(e: sp.Basic | None, defs: dict) -> sp.Basic | None:
    """A claim's side ready for numbers: definitions applied, infinite sums closed, the
    motion's functions as jets."""
    if e is None:
        return None
    return bridge.to_jets(bridge.close_infinite_sums(substitute_definitions(e, defs)))


def terms_of(e: sp.Basic) -> list:
    """The terms whose magnitudes bound the rounding of ``e``: a sum's terms, a product's
    distributed over its first sum ((a − b)·c → a·c, −b·c), up to :data:`SCALE_TERMS`."""
    out, todo = [], [e]
    while todo and len(out) + len(todo) <= SCALE_TERMS:
        t = todo.pop(0)
        if isinstance(t, sp.Add):
            todo[:0] = list(t.args)
        elif isinstance(t, sp.Mul) and any(isinstance(f, sp.Add) for f in t.args):
            first = next(f for f in t.args if isinstance(f, sp.Add))
            rest = sp.Mul(*[f for f in t.args if f is not first])
            todo[:0] = [rest * a for a in first.args]
        else:
            out.append(t)
    return out + todo


@lru_cache(maxsize=1024)
def _magnitude_of_terms(e: sp.Basic) -> sp.Basic:
    return sp.Add(*[sp.Abs(t) for t in terms_of(e)])


@lru_cache(maxsize=64)
def tolerance(exponent: float, dps: int):
    """10^(−exponent·dps), a threshold: in double precision (once per rung, not per comparison)."""
    with mpmath.workprec(53):
        return mpmath.mpf(10) ** (-exponent * dps)


def agrees(diff, ref, dps: int, opts: Options) -> bool:
    """An infinite difference (one side infinite) agrees with nothing, whatever the reference."""
    return diff <= tolerance(opts.agreement_exponent, dps) * ref and not mpmath.isinf(diff)


class _Evaluator:
    """The claim's sides compiled once; values at a point on a rung (derived values remembered
    per expression, exact point and digits: an erratum's printed and corrected forms share them)."""

    def __init__(self, p, d, scale, args, at_most: bool = False):
        self.p, self.d, self.args, self.at_most = p, d, args, at_most
        self.fp = bridge.rung_function(p, args)
        self.fs = bridge.rung_function(scale, args) if scale is not None else None
        self.d_args = tuple(sorted(d.free_symbols, key=str))
        self._terms = None
        self._one_term = len(terms_of(p)) == 1 and len(terms_of(d)) == 1  # each side a single term

    def rung(self, pt: dict, dps: int) -> Rung:
        with mpmath.workdps(dps):
            vals = [bridge.mp_value(pt[a], dps) for a in self.args]
            pv = +self.fp(*vals)
            dv = derived_value(self.d, self.d_args, tuple(pt[a] for a in self.d_args), dps)
            mag = max(abs(pv), abs(dv))
            if self.fs is not None:
                mag = max(mag, abs(+self.fs(*vals)))
            finite = [v for v in (pv, dv) if mpmath.isfinite(v)]
            if not self.at_most and len(finite) == 1 and (mpmath.isinf(pv) or mpmath.isinf(dv)):
                # one side infinite (a limit that grows without bound), the other finite: a
                # difference no precision closes, judged by the finite side's magnitude
                return Rung(pv, dv, mpmath.inf, abs(finite[0]))
            diff = abs(pv - dv) if not self.at_most else _excess(pv, dv, mag, dps)
            if not (mpmath.isfinite(diff) and mpmath.isfinite(mag)):
                raise ValueError("not finite")
        return Rung(pv, dv, diff, mag)

    def with_terms(self, r: Rung, pt: dict, dps: int) -> Rung:
        """``r`` with the magnitude of each side's terms (where |p|, |d| alone do not agree).
        Where each side is one term, that is |p| + |d|, known already: the sides are not
        evaluated again (an R_{−a} by quadrature costs a second a point)."""
        if self._one_term:
            with mpmath.workdps(dps):
                return Rung(r.printed, r.derived, r.diff, r.magnitude, abs(r.printed) + abs(r.derived))
        if self._terms is None:
            self._terms = bridge.rung_function(_magnitude_of_terms(self.p) + _magnitude_of_terms(self.d), self.args)
        with mpmath.workdps(dps):
            try:
                t = +self._terms(*[bridge.mp_value(pt[a], dps) for a in self.args])
                t = abs(t) if mpmath.isfinite(t) else None
            except EVALUATION_ERRORS:
                t = None
        return Rung(r.printed, r.derived, r.diff, r.magnitude, t)


def _excess(low, high, magnitude, dps: int):
    """How far the side printed lesser exceeds the greater (0 where the inequality holds); a
    point where either side is not real is not in an inequality's domain (ValueError)."""
    negligible = tolerance(1.0, dps) * (magnitude or 1)
    if abs(mpmath.im(low)) > negligible or abs(mpmath.im(high)) > negligible:
        raise ValueError("a side of the inequality is not real here")
    return max(mpmath.re(low) - mpmath.re(high), mpmath.mpf(0))


@lru_cache(maxsize=50_000)
def derived_value(d: sp.Basic, d_args: tuple, values: tuple, dps: int):
    """The derived side's value at an exact point (hashed structurally), at ``dps`` digits."""
    f = bridge.rung_function(d, d_args)
    with mpmath.workdps(dps):
        return +f(*[bridge.mp_value(v, dps) for v in values])


def reference(r: Rung, floor) -> object:
    """What a rung's difference is judged against: the values', the claim's and the terms'
    magnitudes, floored."""
    ref = max(r.magnitude, floor)
    if r.terms is not None:
        ref = max(ref, r.terms)
    return ref or mpmath.mpf(1)


def classify(rows, opts: Options) -> list[tuple[PointClass, float]]:
    """Each point as (class, relative difference).  All in mpmath: values far beyond the
    double range (factorials, 2^(n²)) must not overflow to inf.

    Agreement: |p − d| ≤ 10^(−0.6·dps)·reference on every rung evaluated.  A true difference:
    resolved on no rung, and stable (within ``opts.stable_within``) from the first rung to the
    last.  A difference that shrinks with the working precision (by 10^(−0.8·Δdps) or more from
    the first rung to the last, and again as much on one rung beyond) is the rounding of an
    exact zero and agrees: a function at its zero, whose argument is itself rounded (cn(K, k) =
    0), has no magnitude to be judged against, but its value falls with every digit added.  The relative difference
    reported is |p − d| / max(|p|, |d|), floored at ``opts.scale_floor`` of the median
    magnitude."""
    ladder = opts.ladder
    mags = sorted(abs(r[-1].magnitude) for _, r in rows)
    floor = mags[len(mags) // 2] * mpmath.mpf(opts.scale_floor) if mags else mpmath.mpf(0)
    out = []
    for _, row in rows:
        ok = [agrees(r.diff, reference(r, floor), dps, opts) for dps, r in zip(ladder, row)]
        lo, hi = row[0].diff, row[-1].diff
        rel = math.inf if mpmath.isinf(hi) else float(min(hi / (max(row[-1].magnitude, floor) or mpmath.mpf(1)),
                                                          mpmath.mpf(1e300)))
        if all(ok):
            out.append((PointClass.AGREE, rel))
        elif all(mpmath.isinf(r.diff) for r in row):
            out.append((PointClass.DISAGREE, rel))  # one side infinite on every rung
        elif len(row) > 1 and row[-1].falls:
            out.append((PointClass.VANISHES, rel))
        elif len(row) > 1 and not any(ok) and abs(lo - hi) <= mpmath.mpf(opts.stable_within) * hi:
            out.append((PointClass.DISAGREE, rel))
        else:
            out.append((PointClass.UNSTABLE, rel))
    return out


def _falls(lo, hi, gained_digits: int, opts: Options) -> bool:
    """A difference ``lo`` falling to ``hi``, ``gained_digits`` later, as rounding noise does."""
    return lo > 0 and hi <= lo * tolerance(opts.vanishing_exponent, gained_digits)


def _confirm_fall(ev: _Evaluator, pt: dict, row: list, opts: Options) -> Rung:
    """The top rung, marked ``falls`` where the difference that fell over the ladder falls again
    as far on one more rung as far beyond: a true difference of 10^(−29), whose 30-digit value
    was noise of 10^(−5), has fallen to itself at 60 digits and stays there at 90."""
    top = row[-1]
    gained = opts.ladder[-1] - opts.ladder[0]
    if len(row) < 2 or not _falls(row[0].diff, top.diff, gained, opts):
        return top
    if top.diff == 0:  # exactly zero on the top rung: no true difference comes out so
        return replace(top, falls=True)
    beyond = ev.rung(pt, opts.ladder[-1] + gained)
    return replace(top, falls=_falls(top.diff, beyond.diff, gained, opts))


def _refuted_already(rows, opts) -> bool:
    """Enough points that already disagree for good."""
    if len(rows) < opts.early_stop_after:
        return False
    # a point can disagree only if its first rung does not agree even against its own magnitude
    # (the scale floor only raises the reference): most runs stop here, without classifying
    # every row again at every point
    candidates = sum(len(r) > 1 and not (r[0].magnitude and agrees(r[0].diff, reference(r[0], 0), opts.ladder[0], opts))
                     for _, r in rows)
    return (candidates >= opts.early_stop_disagreements
            and sum(k is PointClass.DISAGREE for k, _ in classify(rows, opts)) >= opts.early_stop_disagreements)


def _parameters(pt: dict) -> dict[str, str]:
    return {str(k): sp.sstr(v) for k, v in sorted(pt.items(), key=lambda kv: str(kv[0]))}


def _divergence(p: sp.Basic, pts: list, claim: Claim, opts: Options, before_numbers: bool) -> Verdict | None:
    """A printed integral that diverges (integrand ~ |x − e|^(−q), q ≥ 1, or decaying no faster
    than 1/x at an infinite end), a printed series whose terms grow, or a printed two-sided
    limit whose sides differ, is refuted with that reason: its quadratures, partial sums or
    sequences only return noise, or nothing.  Where the numbers have failed, one of the first
    four points showing it is enough; ``before_numbers``, the integrals alone are tested (a
    series' test sums in sympy) and every one of the four points must show it."""
    from quasicentral.engine.divergence import (
        integral_divergence, limit_nonexistent, series_divergence, undefined_term,
    )

    if not (p.has(sp.Integral) or (not before_numbers and p.has(sp.Sum, sp.Product, sp.Limit))):
        return None
    for pt in (pts[:4] if not before_numbers else ()):
        # a printed form without a value: a two-sided limit whose sides differ, a term at a pole
        why = limit_nonexistent(p, pt) if p.has(sp.Limit) else None
        why = why or (undefined_term(p, pt) if p.has(sp.Sum, sp.Product) else None)
        if why is not None:
            shown = f"{why['left']} (−), {why['right']} (+)" if why.code is Code.NO_LIMIT else "undefined"
            w = Witness(parameters=_parameters(pt), printed=shown, corrected="", digits=0, certified=False,
                        quantity=claim.quantity, relative_difference="inf", working_digits=opts.ladder[-1])
            return Refuted(Method.NUMERIC, why, len(pts), opts.ladder, witness=w)
    seen = ((pt, integral_divergence(p, pt) or (None if before_numbers else series_divergence(p, pt)))
            for pt in pts[:4])
    if before_numbers:
        seen = list(seen)
        if not seen or not all(why for _, why in seen):
            return None
    pt, why = next(((pt, why) for pt, why in seen if why), (None, None))
    if why is None:
        return None
    w = Witness(parameters=_parameters(pt), printed="divergent", corrected="", digits=0, certified=False,
                quantity=claim.quantity, relative_difference="inf", working_digits=opts.ladder[-1])
    return Refuted(Method.NUMERIC, Reason.of(Code.DIVERGES, why=why), len(pts), opts.ladder, witness=w)


def numeric(claim: Claim, domain: Domain, label: str, opts: Options, table: SymbolTable) -> Verdict:
    """The claim at in-domain points on the ladder: verified, refuted with a witness, or
    inconclusive with the reason."""
    defs = domain.definition_map(table)
    # a function the text declares is a quantity along its motion (any values: a jet), and so is
    # one both sides hold (an identity for every function, or a derivation's unknown A′(t)); an
    # ad-hoc Function('u') on the printed side alone is something the text defines elsewhere:
    # it has no numbers here
    declared = {s.obj.func for s in table.specs if s.variables} if table is not None else set()
    declared |= {f.func for f in claim.derived.atoms(AppliedUndef)}
    undeclared = sorted({f.func.__name__ for f in claim.printed.atoms(AppliedUndef) if f.func not in declared})
    if undeclared:
        return Inconclusive(Method.NONE, Reason.of(Code.NO_NUMERIC_FORM, function=undeclared[0]))
    p, d, scale = prepared(claim.printed, defs), prepared(claim.derived, defs), prepared(claim.scale, defs)
    unknown = sorted({f.func.__name__ for e in (p, d) for f in e.atoms(AppliedUndef)})
    if unknown:  # a function the text names but does not define (a sequence a(n)): no numbers
        return Inconclusive(Method.NONE, Reason.of(Code.NO_NUMERIC_FORM, function=unknown[0]))
    syms = set(p.free_symbols) | set(d.free_symbols) | (scale.free_symbols if scale is not None else set())
    condition = prepared(claim.implicit[1], defs) if claim.implicit else None
    if condition is not None:
        syms |= condition.free_symbols | {claim.implicit[0]}
    try:
        integral = p.has(sp.Integral) or d.has(sp.Integral)
        count = min(opts.points, opts.integral_points) if integral else opts.points
        pts = Sampler(domain, table, sorted(syms, key=str), seed_for(label), _jet_ranges(syms)).draw(count)
        if condition is not None:
            # only where the condition holds: the unknown solved for, each distinct point once
            # (a condition in the unknown alone holds at its roots, perhaps at one point)
            unknown = claim.implicit[0]
            solved = on_condition(pts, unknown, condition, domain.range_map(table))
            pts = list({tuple(sorted(pt.items(), key=lambda kv: str(kv[0]))): pt for pt in solved}.values())
            if not pts:
                return Inconclusive(Method.NONE, Reason.of(Code.CONDITION_UNSOLVED, unknown=str(unknown), count=0))
    except KeyError as exc:
        return Inconclusive(Method.NONE, Reason.of(Code.NO_RANGE, symbol=str(exc.args[0])))
    if condition is None and len(pts) < max(3, count // 2):
        return Inconclusive(Method.NONE, Reason(Code.TOO_FEW_POINTS))
    args = tuple(sorted(syms, key=str))
    ev = _Evaluator(p, d, scale, args, claim.at_most)
    # an endpoint where the printed integrand is not integrable is seen in a few evaluations,
    # where its quadratures would cost seconds and return noise
    early_divergence = _divergence(p, pts, claim, opts, before_numbers=True)
    if early_divergence is not None:
        return early_divergence
    rows, early, first_error = _evaluate(ev, pts, opts)
    if not early and len(rows) < (max(3, (4 * len(pts) + 4) // 5) if condition is None else max(1, len(pts) // 2)):
        # a point where a side cannot be evaluated is not evidence of agreement: at most a
        # fifth of them may drop out
        return _divergence(p, pts, claim, opts, False) or Inconclusive(
            Method.NONE, Reason.of(Code.TOO_FEW_EVALUATED, n=len(rows), of=len(pts), error=first_error))
    return _judge(rows, pts, claim, p, d, opts)


def _evaluate(ev: _Evaluator, pts: list, opts: Options):
    """The rows of the ladder (per point, its rungs), whether a refutation stopped the run
    early, and the first evaluation error met ('' for none)."""
    rows, first_error = [], ""
    for i_pt, pt in enumerate(pts):
        if i_pt >= opts.early_stop_after and _refuted_already(rows, opts):
            return rows, True, first_error  # a refutation stands; further points would only cost time
        try:
            row = [ev.rung(pt, opts.ladder[0])]
            if i_pt < opts.confirm_points or not agrees(row[0].diff, row[0].magnitude, opts.ladder[0], opts):
                row += [ev.rung(pt, dps) for dps in opts.ladder[1:]]
            if not all(agrees(r.diff, r.magnitude, dps, opts) for dps, r in zip(opts.ladder, row)):
                row = [ev.with_terms(r, pt, dps) for dps, r in zip(opts.ladder, row)]
                row[-1] = _confirm_fall(ev, pt, row, opts)
        except EVALUATION_ERRORS as exc:
            first_error = first_error or f"{type(exc).__name__}: {exc}"[:160]
            continue
        rows.append((pt, row))
    return rows, False, first_error


#: functions with a jump or a kink where their argument crosses a value: an integrand holding one
#: defeats a quadrature's error estimate
NONSMOOTH = (sp.Abs, sp.sign, sp.Heaviside, sp.floor, sp.ceiling, sp.frac, sp.Piecewise, sp.Min, sp.Max, sp.Mod)


#: the relative difference beyond which a rough integral's difference is no quadrature error
NONSMOOTH_TRUSTED = 1e-2


def _nonsmooth_integrand(e: sp.Basic) -> str:
    """The name of a non-smooth function inside an integrand of ``e`` ('' for none)."""
    for integral in e.atoms(sp.Integral):
        for f in integral.function.atoms(*NONSMOOTH):
            return type(f).__name__
    return ""


def _judge(rows, pts, claim: Claim, p, d, opts: Options) -> Verdict:
    disagree, unstable, zeros = [], 0, 0
    for (kind, rel), (pt, row) in zip(classify(rows, opts), rows):
        zeros += kind is PointClass.VANISHES
        if kind is PointClass.DISAGREE:
            disagree.append((rel, pt, row))
        elif kind is PointClass.UNSTABLE:
            unstable += 1
    n, ladder = len(rows), opts.ladder
    if disagree:
        rel, pt, row = max(disagree, key=lambda r: r[0])
        witness = witness_at(claim.quantity, p, d, pt, (row[-1].printed, row[-1].derived),
                             (row[0].printed, row[0].derived), ladder[-1], opts, rel, claim.at_most)
        method = Method.CERTIFIED if witness.certified else Method.NUMERIC
        rough = _nonsmooth_integrand(p) or _nonsmooth_integrand(d)
        if rough and not witness.certified and rel < NONSMOOTH_TRUSTED:
            # a quadrature across a jump or a kink is good to a few digits only: its difference
            # is no refutation unless balls certify it
            return Inconclusive(Method.NUMERIC, Reason.of(Code.NONSMOOTH_QUADRATURE, function=rough, count=len(disagree),
                                                          points=n), n, ladder)
        reason = Reason.of(Code.FAILS_AT, count=len(disagree), points=n) if claim.at_most else \
            Reason.of(Code.DISAGREES, count=len(disagree), points=n, relative=rel)
        return Refuted(method, reason, n, ladder, witness=witness)
    if unstable:
        return _divergence(p, pts, claim, opts, False) or Inconclusive(
            Method.NUMERIC, Reason.of(Code.UNSTABLE, n=unstable, of=n), n, ladder)
    vacuous = all(r[-1].magnitude == 0 for _, r in rows)
    confirmed = sum(len(r) == len(ladder) for _, r in rows)
    if claim.at_most:
        return Verified(Method.NUMERIC, Reason.of(Code.HOLDS, n=n, of=len(pts), top=ladder[-1]), n, ladder)
    return Verified(Method.NUMERIC, Reason.of(Code.AGREES, n=n, of=len(pts),
                                              digits=math.floor(opts.agreement_exponent * ladder[0]),
                                              confirmed=confirmed, top=ladder[-1], vacuous=vacuous,
                                              zeros=zeros), n, ladder)
