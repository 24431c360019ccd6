"""The checker: printed against derived — numerically on a precision ladder at many in-domain
points, symbolically (a proof decides the method), and with ball arithmetic where it decides a
refutation.

A *claim* is a pair of expressions that should be equal on the declared domain.  The order:

1. dimensions of every printed relation (an inconsistent one is refuted outright);
2. numeric: many random in-domain points (seeded by the id), each evaluated at the digits of
   every rung of the ladder; agreement must hold on every rung, a disagreement must be stable
   from rung to rung;
3. symbolic, unless the numbers already refute (then no simplification can return 0):
   ``simplify(p − d) == 0`` within a CPU-time bound; for an integral with a variable upper
   limit X, the fundamental theorem: d/dX (p − d) = 0 and (p − d) = 0 at the lower limit.
   A proof makes the verdict "verified, symbolic"; a proof the numbers contradict is not
   trusted (inconclusive);
4. certified: the worst disagreement re-evaluated in python-flint balls; a ball for p − d that
   excludes 0 proves the printed form wrong at that point.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

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
    certify_seconds: float = 1.0  # ball integrals can be slow: past this the witness stays uncertified
    agreement_exponent: float = 0.6  # agreement: |p − d| ≤ 10^(−0.6·dps)·scale on each rung
    stable_within: float = 1e-3  # a difference is real when it changes by less than this between rungs
    scale_floor: float = 1e-6  # the scale is at least this fraction of the median magnitude
    early_stop_after: int = 6  # points evaluated before a refutation may stop the run early ...
    early_stop_disagreements: int = 3  # ... once this many of them disagree for good
    remembered_values: int = 50_000  # derived values kept for an erratum's second comparison

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
    return e.replace(lambda a: isinstance(a, sp.Derivative), lambda a: a.doit())


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


def claims_for(printed: list[sp.Basic], derivation: Derivation, result) -> list[Claim]:
    """Pair the printed relations with the derivation's result; :class:`CannotCompare` says
    why they cannot be."""
    mode = derivation.mode
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
    at every point."""
    try:
        with time_limit(seconds):
            if diff == 0:
                return True
            if diff.has(sp.Integral):  # simplify cannot see through an integral: differentiate it
                return _ftc_zero(diff, force)
            return sp.simplify(diff, doit=False) == 0 or (force and _forced_zero(diff))
    except TimeLimitExceeded:
        return False
    except Exception:  # noqa: BLE001 - a CAS failure proves nothing
        return False


def _forced_zero(e: sp.Expr) -> bool:
    """√a·√b = √(ab) as if every radicand were positive — true inside the physical domains
    (|ζ| ≤ 1, k² < 1, …) though not for all complex values; the numeric cross-check that
    follows every proof guards against a domain where it fails."""
    return sp.simplify(sp.powsimp(sp.powdenest(e, force=True), force=True), doit=False) == 0


def _ftc_zero(diff: sp.Expr, force: bool = True) -> bool:
    """Integrals with a variable upper limit X: d/dX diff ≡ 0 and diff(lower limit) = 0."""
    for integral in diff.atoms(sp.Integral):
        for lim in integral.limits:
            if len(lim) == 3 and isinstance(lim[2], sp.Symbol):
                X, lower = lim[2], lim[1]
                dd = sp.diff(diff, X)
                if sp.simplify(dd, doit=False) == 0 or (force and _forced_zero(dd)):
                    at_lower = diff.subs(X, lower).doit()
                    if sp.simplify(at_lower, doit=False) == 0:
                        return True
    return False


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
    fp = bridge.mp_function(p, args)
    fs = bridge.mp_function(scale, args) if scale is not None else None
    # the derived side is shared by an erratum's printed and corrected forms (same points):
    # its values are remembered, keyed by the expression, the exact point and the digits
    d_args = tuple(sorted(d.free_symbols, key=str))
    fd_own, d_key = bridge.mp_function(d, d_args), sp.srepr(d)

    def fd(pt, dps):
        key = (d_key, tuple(sp.srepr(pt[a]) for a in d_args), dps)
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
        return Inconclusive(Method.NUMERIC, f"{unstable} of {n} points unstable under the precision ladder", n, ladder)
    counted = f"{n} of {len(pts)}" if n < len(pts) else f"{n}"
    vacuous = all(r[-1][3] == 0 for _, r in rows)
    confirmed = sum(len(r) == len(ladder) for _, r in rows)
    return Verified(Method.NUMERIC, f"agrees at {counted} points to {math.floor(opts.agreement_exponent * ladder[0])}+ "
                    f"digits ({confirmed} of them also at {ladder[-1]} digits)"
                    + (" (both sides vanish at every point)" if vacuous else ""), n, ladder)


def _agrees(diff, ref, dps: int, opts: Options) -> bool:
    return diff <= mpmath.mpf(10) ** (-opts.agreement_exponent * dps) * ref


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
    return (len(rows) >= opts.early_stop_after
            and sum(k == "disagree" for k, _ in _classify(rows, opts)) >= opts.early_stop_disagreements)


def _witness(claim, p, d, pt, row, dps, opts, rel) -> Witness:
    certified = False
    if opts.certify:
        try:
            pb = bridge.arb_eval(p, pt, seconds=opts.certify_seconds)
            db = bridge.arb_eval(d, pt, seconds=opts.certify_seconds)
            certified = bool(pb.is_finite() and db.is_finite() and not (pb - db).contains(0))
        except (bridge.Unsupported, ValueError, ZeroDivisionError, TypeError, AttributeError):
            certified = False
    pv, dv = row[-1][0], row[-1][1]
    with mpmath.workdps(dps):
        return Witness(
            parameters={str(s): sp.sstr(v) for s, v in sorted(pt.items(), key=lambda kv: str(kv[0]))},
            printed=_num_str(pv), corrected=_num_str(dv), digits=dps, certified=certified,
            quantity=claim.quantity, relative_difference=f"{rel:.3e}",
        )


def _num_str(v) -> str:
    if isinstance(v, mpmath.mpc) and abs(v.imag) <= abs(v) * mpmath.mpf(10) ** (-mpmath.mp.dps + 5):
        v = v.real
    return mpmath.nstr(v, 25)


def check(printed: list[sp.Basic], dims: dict, derivation: Derivation, label: str, opts: Options,
          table: SymbolTable) -> Verdict:
    """The verdict on ``printed`` against ``derivation`` (see the module docstring)."""
    from quasicentral.engine.registry import derived

    found = [c for c in (check_relation(rel, dims) for rel in printed) if c.inconsistent or c.undetermined]
    dim_problems = [c.reason for c in found if c.inconsistent]
    dim_text = ("inconsistent: " + "; ".join(dim_problems) if dim_problems
                else "; ".join(str(c) for c in found) if found else "consistent")

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
