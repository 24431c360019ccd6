"""The checker: printed against derived — numerically on a precision ladder at many in-domain
points, symbolically (a proof decides the method), and with ball arithmetic where it decides a
refutation.

A *claim* (:mod:`quasicentral.engine.claims`) is a pair of expressions that should be equal on
the declared domain.  The order:

1. dimensions of every printed relation (:mod:`quasicentral.engine.dimensions`);
2. numeric (:mod:`quasicentral.engine.ladder`): many random in-domain points (seeded by the
   id), each evaluated at the digits of every rung of the ladder; agreement must hold on every
   rung, a disagreement must be stable from rung to rung;
3. symbolic (:mod:`quasicentral.engine.proofs`), unless the numbers already refute (then no
   simplification can return 0): p − d proved 0 within a CPU-time bound.  A proof makes the
   verdict "verified, symbolic"; a proof the numbers contradict is not trusted (inconclusive);
4. certified (:mod:`quasicentral.engine.witness`): the worst disagreement re-evaluated in
   python-flint balls; a ball for p − d that excludes 0 proves the printed form wrong there.

Dimensions and numbers: a relation that is dimensionally inconsistent is refuted (with the
numbers' witness where they refute too); where the numbers verify it at every point, the
dimension check is the suspect, and the entry is inconclusive with both facts.  Any failure of
one stage (an exception of sympy, mpmath or the text's own code) makes the entry inconclusive
with the stage and the reason; it never ends the run.
"""

from __future__ import annotations

from dataclasses import replace

import sympy as sp
from sympy.core.cache import clear_cache

from quasicentral.engine import asymptotic, rounding
from quasicentral.engine.claims import (CannotCompare, Claim, HoldsAsPrinted, claims_for, decided, put_model,  # noqa: F401
                                        doit_derivatives)
from quasicentral.engine.dimensions import check_relation
from quasicentral.engine.ladder import numeric
from quasicentral.engine.options import Options
from quasicentral.engine.proofs import prove_zero
from quasicentral.engine.reasons import Code, Reason
from quasicentral.engine.registry import Derivation, Mode
from quasicentral.engine.verdict import Inconclusive, Method, Refuted, Verdict, Verified, combine
from quasicentral.notation.domain import substitute_definitions
from quasicentral.notation.symbols import Approx, SymbolTable
from quasicentral.notation.timelimit import TimeLimitExceeded, time_limit

__all__ = ["Claim", "Options", "check", "claims_for", "numeric"]


def _error(exc: BaseException) -> str:
    return f"{type(exc).__name__}: {exc}"[:300]


def check(printed: list[sp.Basic], dims: dict, derivation: Derivation, label: str, opts: Options,
          table: SymbolTable, result=None, failed: str | None = None) -> Verdict:
    """The verdict on ``printed`` against ``derivation``'s ``result`` (see the module
    docstring); ``failed`` is the error of a derivation that could not be computed."""
    # a text that declares no dimension at all (mathematics: a formula collection) has none to check;
    # a formula with printed decimals (θ ≈ 1.22 λ/D) has the dimensions of its equation
    findings = tuple(c for c in (check_relation(rel.equation() if isinstance(rel, Approx) else rel, dims)
                                 for rel in printed if not rounding.relation_is_rounding(rel))
                     if c.inconsistent or c.undetermined) if dims else ()
    inconsistent = tuple(c for c in findings if c.inconsistent)
    if inconsistent and not opts.numbers_after_dimensions:
        return Refuted(Method.DIMENSIONAL, Reason.of(Code.DIMENSIONAL, numbers=None), dimensions=findings)

    def unsettled(reason: Reason) -> Verdict:
        # a relation whose two sides differ in dimension is wrong whatever the comparison
        if inconsistent:
            return Refuted(Method.DIMENSIONAL, Reason.of(Code.DIMENSIONAL, numbers=reason), dimensions=findings)
        return Inconclusive(Method.NONE, reason, dimensions=findings)

    roundings = [rel for rel in printed if rounding.relation_is_rounding(rel)]
    if roundings:
        # a printed rounding is decided by the exact value alone; the rest of a chain as usual
        rest = [rel for rel in printed if not rounding.relation_is_rounding(rel)]
        defs = derivation.domain.definition_map(table)
        verdicts = [_rounding_verdict(rel, defs, opts) for rel in roundings]
        if rest:
            verdicts.append(check(rest, dims, derivation, label, opts, table, result, failed))
        return replace(combine(verdicts), dimensions=findings)
    if failed is not None:
        return unsettled(Reason.of(Code.DERIVATION_FAILED, error=failed))
    printed = [_defined_inside_derivatives(rel, derivation.domain.definition_map(table)) for rel in printed]
    if derivation.mode is not Mode.IDENTITY and asymptotic.passage_relation(printed):
        if derivation.mode is not Mode.SUBSTITUTE or not isinstance(result, dict):
            return unsettled(Reason.of(Code.NO_NUMERIC_FORM, function="O"))
        # an expansion of the derived model: the printed relation with the model put in
        model = dict(result)
        printed = [doit_derivatives(put_model(doit_derivatives(rel), model)) for rel in printed]
    if asymptotic.passage_relation(printed):
        try:
            return replace(asymptotic.check(printed, derivation.domain, label, opts, table), dimensions=findings)
        except Exception as exc:  # noqa: BLE001 - a failure of the passage is this entry's
            return unsettled(Reason.of(Code.STAGE_FAILED, stage="evaluation", error=_error(exc)))
    try:
        with time_limit(opts.symbolic_seconds) as limit:
            claims = claims_for(printed, derivation, result)
    except CannotCompare as exc:
        return unsettled(exc.reason)
    except HoldsAsPrinted:
        return Verified(Method.SYMBOLIC, Reason(Code.DECIDED_TRUE), dimensions=findings)
    except TimeLimitExceeded as exc:
        if limit is None or not limit.owns(exc):
            raise
        return unsettled(Reason.of(Code.SOLVE_TIMEOUT, seconds=opts.symbolic_seconds))
    except Exception as exc:  # noqa: BLE001 - a relation sympy cannot solve is inconclusive
        return unsettled(Reason.of(Code.SETUP_FAILED, error=_error(exc)))
    defs = derivation.domain.definition_map(table)
    verdicts = [_claim_verdict(claim, derivation, f"{label}#{i}", opts, table, defs) for i, claim in enumerate(claims)]
    out = combine(verdicts)
    if inconsistent and isinstance(out, Verified):
        # the numbers verify at every point of the ladder and the dimension check says no: the
        # check is the suspect (a false erratum is as bad as a false "verified")
        return Inconclusive(Method.NONE, Reason.of(Code.DIMENSIONS_DISAGREE, numbers=out.reason,
                                                   finding=inconsistent[0].problem),
                            out.points, out.digits, dimensions=findings)
    if inconsistent and not isinstance(out, Refuted):
        return Refuted(Method.DIMENSIONAL, Reason.of(Code.DIMENSIONAL, numbers=out.name), out.points, out.digits,
                       dimensions=findings)
    return replace(out, dimensions=findings)


def _defined_inside_derivatives(rel, defs: dict):
    """``rel`` with the defined symbols inside each derivative (and derivative at a point) put
    in: x with the definition A e^(−γt) cos ω_d t is a symbol to sympy, and dx/dt would be 0
    (a correct ẍ + 2γẋ + ω0²x = 0 refuted, dE/dt = … vacuously "verified")."""
    if not defs or not isinstance(rel, sp.Basic) or not rel.has(sp.Derivative, sp.Subs):
        return rel
    names = set(defs)
    return rel.replace(lambda a: isinstance(a, (sp.Derivative, sp.Subs)) and bool(a.free_symbols & names),
                       lambda a: substitute_definitions(a, defs))


def _rounding_verdict(rel, defs: dict, opts: Options) -> Verdict:
    try:
        return rounding.check(rel, defs, opts)
    except Exception as exc:  # noqa: BLE001 - a failure of the numbers is this entry's, not the run's
        return Inconclusive(Method.NONE, Reason.of(Code.STAGE_FAILED, stage="evaluation", error=_error(exc)))


def _claim_verdict(claim: Claim, derivation: Derivation, label: str, opts: Options, table: SymbolTable,
                   defs: dict) -> Verdict:
    """Every claim is checked at every point; the symbolic stage (bounded in CPU time) then
    tries to prove what the numbers found equal — where they found a difference no
    simplification can return 0, and the bound is not spent.  A proof the numbers contradict
    is not trusted (a CAS slip, or a rewrite that holds on part of the domain)."""
    try:
        v = numeric(claim, derivation.domain, label, opts, table)
    except Exception as exc:  # noqa: BLE001 - a failure of the numbers is this entry's, not the run's
        return Inconclusive(Method.NONE, Reason.of(Code.STAGE_FAILED, stage="evaluation", error=_error(exc)))
    if not opts.symbolic or isinstance(v, Refuted):
        return v
    if claim.at_most:
        return v  # an inequality: the numbers decide
    seconds = opts.identity_symbolic_seconds if derivation.mode is Mode.IDENTITY else opts.symbolic_seconds
    if derivation.mode is Mode.IDENTITY:
        # the short bound of an identity's proof is spent from a cold sympy cache: what the
        # entries a worker checked before left in it would decide a proof near the bound, and
        # the method would differ between --jobs 1 and --jobs 2
        clear_cache()
    try:
        proved = prove_zero(substitute_definitions(claim.printed - claim.derived, defs), seconds)
    except Exception:  # noqa: BLE001 - a failed proof proves nothing
        proved = False
    if not proved:
        return v
    if isinstance(v, Verified):
        return Verified(Method.SYMBOLIC, Reason.of(Code.PROVED, numbers=v.reason), v.points, v.digits)
    return Inconclusive(Method.NONE, Reason.of(Code.PROOF_CONTRADICTED, verdict=v.name, numbers=v.reason),
                        v.points, v.digits)
