"""Mutation testing of the checker: seed the typos a typesetter makes into entries that verify,
and count how many the checker catches.

Operators, each at one place of the relation: sign flip of a term, changed exponent (×2,
÷2, +1), a factor 2, k ↔ k² (one occurrence of a symbol s → s²; a function's argument m = k²
written as k), dropped parentheses (a(b + c) → ab + c), two arguments of a function swapped,
the branch of a root (√(ab) ↔ √a·√b, which differ off the positive reals); and over the whole
relation: two symbols swapped, an independent
variable slipped for another declared quantity of the same dimension (t for a period T).  A
mutant that sympy shows equal to the original is *equivalent* and not counted.  A mutant the
fast checker does not refute may still be equivalent *on the declared domain*
(ω = √(Ω² − κ²) ⇔ κ = √(Ω² − ω²) for κ, ω ≥ 0): it is set aside as such only when sympy proves
its compared values equal with the domain's signs as assumptions, or when the full checker
(:data:`STRONG`: more points, a higher ladder) verifies it; both kinds are reported
(``equivalent_on_domain``).  Recall = detected / mutants (target 100 %); false alarms =
verified entries that the same fast checker refutes unmutated (target 0).

Exit codes of ``quasicentral mutate``: 0 when the recall is 100 % and there is no false alarm;
1 otherwise (an undetected mutant or a false alarm, listed); 2 bad usage.
"""

from __future__ import annotations

import os
from dataclasses import dataclass

import sympy as sp

from enum import Enum

from quasicentral.engine import catalog
from quasicentral.engine.checker import Options, check
from quasicentral.engine.verdict import Refuted, Verified
from quasicentral.engine.registry import Mode
from quasicentral.notation.symbols import Approx, Landau, SymbolTable
from quasicentral.progress import OptionalCallback, notify

#: the check each mutant gets: 10 points, no sympy, no balls.  A mutant whose dimensions do not
#: match is refuted on them alone (nearly half are: the full checker refutes them too, whatever
#: the numbers say); one whose first three points all disagree for good is refuted there
FAST = Options(points=10, symbolic=False, certify=False, early_stop_after=3, numbers_after_dimensions=False)
#: the check that decides numeric equivalence on the domain: 3× the points, a 40/80-digit ladder
STRONG = Options(dps=40, points=30, symbolic=False, certify=False)


@dataclass(frozen=True)
class Mutant:
    entry: str
    operator: str
    site: str
    relations: tuple


def _walk(e, path=()):
    """(path, node) in preorder; a path is the chain of argument indices.  Differentiation
    variables, integration variables and the arguments of the motion's functions are not sites."""
    yield path, e
    if isinstance(e, sp.core.function.AppliedUndef) or not e.args:
        return
    if isinstance(e, sp.Derivative):
        yield from _walk(e.expr, path + (0,))
        return
    if isinstance(e, (Approx, Landau)):  # the printed value, its places, an O-term's passage are not sites
        yield from _walk(e.args[0], path + (0,))
        return
    if isinstance(e, sp.Limit):  # nor a limit's variable and side: its body and its point are
        yield from _walk(e.args[0], path + (0,))
        yield from _walk(e.args[2], path + (2,))
        return
    if isinstance(e, (sp.Integral, sp.Sum, sp.Product)):
        yield from _walk(e.function, path + (0,))
        for i, lim in enumerate(e.limits, start=1):
            for j in range(1, len(lim)):
                yield from _walk(lim[j], path + (i, j))
        return
    for i, a in enumerate(e.args):
        if isinstance(a, sp.Basic):
            yield from _walk(a, path + (i,))


def _remake(e, args):
    """``e``'s kind of node over ``args``; a relation unevaluated, as the transcription reads it
    (an evaluated Eq of an integral asks sympy's own quadrature for its truth: minutes for a
    Heaviside integrand)."""
    return e.func(*args, evaluate=False) if isinstance(e, sp.Rel) else e.func(*args)


def _replace_at(e, path, new):
    """``e`` with the node at ``path`` replaced by ``new`` (one site only, unlike xreplace)."""
    if not path:
        return new
    args = list(e.args)
    args[path[0]] = _replace_at(args[path[0]], path[1:], new)
    return _remake(e, args)


def _bound(rel) -> set:
    """The variables a sum, a product, an integral or a limit binds (no printed slip makes x² of one)."""
    return ({lim[0] for e in rel.atoms(sp.Integral, sp.Sum, sp.Product) for lim in e.limits}
            | {e.args[1] for e in rel.atoms(sp.Limit)})


def _replace_variable(e, var, new):
    """var -> new, except as a differentiation variable or the argument of a function."""
    if e == var:
        return new
    if isinstance(e, (sp.core.function.AppliedUndef, sp.Symbol, sp.Number)) or not e.args:
        return e
    if isinstance(e, sp.Derivative):
        return sp.Derivative(_replace_variable(e.expr, var, new), *e.variable_count)
    if isinstance(e, sp.Integral):
        return e
    return _remake(e, [_replace_variable(a, var, new) for a in e.args])


def mutations(rel: sp.Basic, table: SymbolTable):
    """(operator, site, mutated relation) for every site of every operator, deterministic.
    Each mutation changes one place of the relation, as a typesetter's slip does."""
    variables = table.variables
    for path, node in list(_walk(rel)):
        at = lambda new, path=path: _replace_at(rel, path, new)  # noqa: E731
        if isinstance(node, sp.Add):
            for term in node.args:
                yield "sign flip", sp.sstr(term), at(node - 2 * term)
                yield "factor 2", sp.sstr(term), at(node + term)
        if isinstance(node, sp.Pow) and node.exp.is_Number and node.exp not in (-1,):
            for name, ex in (("exponent x2", node.exp * 2), ("exponent /2", node.exp / 2), ("exponent +1", node.exp + 1)):
                yield name, sp.sstr(node), at(sp.Pow(node.base, ex))
        if isinstance(node, sp.Mul):
            adds = [a for a in node.args if isinstance(a, sp.Add)]
            if adds:
                inner = adds[0]
                rest = sp.Mul(*[a for a in node.args if a is not inner])
                yield "dropped parentheses", sp.sstr(node), at(rest * inner.args[0] + sp.Add(*inner.args[1:]))
        if isinstance(node, sp.Symbol) and node not in variables and node not in _bound(rel):
            yield "k <-> k^2", sp.sstr(node), at(node**2)
        if _applied(node) and len(node.args) >= 2 and node.args[0] != node.args[1]:
            swapped = (node.args[1], node.args[0]) + tuple(node.args[2:])
            yield "swapped arguments", sp.sstr(node), at(node.func(*swapped))
        if _applied(node) and any(isinstance(a, sp.Pow) and a.exp == 2 for a in node.args):
            # a parameter m = k² written where the modulus k belongs (or the converse, above)
            i = next(i for i, a in enumerate(node.args) if isinstance(a, sp.Pow) and a.exp == 2)
            args = list(node.args)
            args[i] = args[i].base
            yield "parameter for modulus", sp.sstr(node), at(node.func(*args))
        if isinstance(node, sp.Pow) and node.exp in (sp.S.Half, -sp.S.Half) and isinstance(node.base, sp.Mul):
            # √(ab) for √a·√b: the same on the positive reals, another branch in the complex plane
            factors = node.base.args
            yield "branch of the root", sp.sstr(node), at(sp.Mul(*[sp.Pow(f, node.exp) for f in factors],
                                                               evaluate=False))
        if isinstance(node, sp.Mul):
            roots = [f for f in node.args if isinstance(f, sp.Pow) and f.exp == sp.S.Half]
            if len(roots) >= 2:
                rest = [f for f in node.args if f not in roots[:2]]
                yield "branch of the root", sp.sstr(node), at(sp.Mul(*rest, sp.sqrt(roots[0].base * roots[1].base)))
    free = sorted((a for a in rel.free_symbols if a not in variables and isinstance(a, sp.Symbol) and a not in _bound(rel)),
                  key=str)
    for a, b in zip(free, free[1:]):
        yield "swapped variables", f"{a} <-> {b}", _remake(rel, [x.xreplace({a: b, b: a}) for x in rel.args])
    dims = table.dims
    for var in sorted(variables & rel.free_symbols, key=str):
        alike = [o for o, d in dims.items() if isinstance(o, sp.Symbol) and o != var and d == dims.get(var)
                 and o not in table.definitions]
        for other in sorted(alike, key=str)[:1]:
            yield "variable slip", f"{var} -> {other}", _replace_variable(rel, var, other)


def _applied(node) -> bool:
    """An application of a named function (sympy's or the notation's), not an operator, nor a
    printed rounding or an O-term (their arguments are not interchangeable)."""
    return isinstance(node, sp.Function) and not isinstance(node, (sp.core.function.AppliedUndef, Approx, Landau))


def _valid(gen):
    """Mutations that sympy accepts (an operator may build an invalid tree: skip it)."""
    while True:
        try:
            yield next(gen)
        except StopIteration:
            return
        except (ValueError, TypeError):
            continue


def mutants_of(entry: catalog.Entry, per_entry: int | None = None, roundings: bool = False) -> list[Mutant]:
    rels = entry.relations(roundings=roundings)
    out, seen = [], set()
    for i, rel in enumerate(rels):
        for op, site, new in _valid(mutations(rel, entry.symbols)):
            if new == rel or new in (sp.true, sp.false) or not isinstance(new, sp.Basic):
                continue
            if isinstance(new, sp.Rel) and new.lhs == new.rhs:
                continue  # the two sides made the same: nothing a checker could refute
            key = (i, sp.srepr(new))
            if key in seen:
                continue
            seen.add(key)
            out.append(Mutant(entry.id, op, site, tuple(rels[:i] + [new] + rels[i + 1:])))
    if per_entry is not None and len(out) > per_entry:
        # spread the sample over the operators
        by_op: dict[str, list[Mutant]] = {}
        for m in out:
            by_op.setdefault(m.operator, []).append(m)
        sample: list[Mutant] = []
        while len(sample) < per_entry:
            for ops in by_op.values():
                if ops and len(sample) < per_entry:
                    sample.append(ops.pop(0))
        out = sample
    return out


class Equivalence(str, Enum):
    """How a mutant that the fast checker does not refute was shown equivalent on the domain."""

    PROOF = "proof"  # sympy proves it equal with the domain's signs as assumptions
    NUMERIC = "numeric"  # the full checker verifies it at every point


def _equivalent(mutant: list, original: list, der, result) -> bool:
    """The mutant says the same as the original: sympy proves every compared value equal."""
    from quasicentral.engine.claims import claims_for
    from quasicentral.engine.proofs import prove_zero
    from quasicentral.notation.timelimit import TimeLimitExceeded, time_limit

    def residual(rel):
        return rel.lhs - rel.rhs if isinstance(rel, sp.Eq) else None

    pairs = [(residual(a), residual(b)) for a, b in zip(mutant, original)]
    if len(mutant) == len(original) and all(
            a is not None and b is not None and (sp.expand(a - b) == 0 or sp.expand(a + b) == 0) for a, b in pairs):
        return True  # the same equations, sides exchanged (a = b for b = a)
    try:  # a mutant sympy cannot solve is not shown equivalent: the checker then judges it
        with time_limit(FAST.symbolic_seconds) as limit:
            cm, co = claims_for(mutant, der, result), claims_for(original, der, result)
    except TimeLimitExceeded as exc:
        if limit is None or not limit.owns(exc):
            raise
        return False
    except Exception:  # noqa: BLE001 - CannotCompare included
        return False
    if len(cm) != len(co):
        return False
    # no forced radical rewriting here: an "equivalent" mutant must be equal everywhere, or the
    # recall would be flattered by mutants dropped on a rewrite that holds only in part
    return all(prove_zero(a.printed - b.printed, 1.0, force=False) for a, b in zip(cm, co))


def _domain_assumptions(der, syms, table: SymbolTable) -> dict:
    """Each symbol whose declared range is non-negative, replaced by a non-negative (or
    positive) symbol of the same name: the domain's signs as sympy assumptions."""
    ranges = der.domain.range_map(table)
    repl = {}
    for s in syms:
        if not isinstance(s, sp.Symbol) or s not in ranges:
            continue
        lo = sp.sympify(ranges[s][0])
        if lo.is_number and lo.is_nonnegative:
            repl[s] = sp.Symbol(s.name, positive=True) if lo.is_positive else sp.Symbol(s.name, nonnegative=True)
    return repl


def equivalent_on_domain(mutant: list, der, result, label: str, table: SymbolTable, dims=None) -> Equivalence | None:
    """:data:`Equivalence.PROOF` when sympy proves every compared value of the mutant equal to
    the derived one with the domain's signs as assumptions (κ ≥ 0 ⇒ √(κ²) = κ);
    :data:`Equivalence.NUMERIC` when the full checker (:data:`STRONG`) verifies it at every
    point — or, for a relation judged along a passage (an O-term, a limit printed ∞), verifies
    it there: a(1 + e²)/(1 + e cos φ) = a(1 − e cos φ) + O(e²) holds with the e² term's sign
    flipped, and I₁(a²x)/x⁴ still grows without bound; else None."""
    from quasicentral.engine.asymptotic import passage_relation
    from quasicentral.engine.claims import claims_for
    from quasicentral.engine.ladder import numeric
    from quasicentral.engine.proofs import prove_zero
    from quasicentral.notation.domain import substitute_definitions
    from quasicentral.notation.timelimit import TimeLimitExceeded, time_limit

    if passage_relation(mutant) or any(isinstance(r, sp.Eq) and r.has(sp.Limit) and r.has(sp.oo, -sp.oo)
                                       for r in mutant):
        # an O-term or an infinite limit is judged along its passage, never as two values
        try:
            verdict = check(mutant, dims or {}, der, label, STRONG, table, result)
        except Exception:  # noqa: BLE001 - a mutant the checker cannot judge is not shown equivalent
            return None
        return Equivalence.NUMERIC if isinstance(verdict, Verified) else None
    try:
        with time_limit(FAST.symbolic_seconds) as limit:
            cm = claims_for(mutant, der, result)
    except TimeLimitExceeded as exc:
        if limit is None or not limit.owns(exc):
            raise
        return None
    except Exception:  # noqa: BLE001 - CannotCompare included
        return None
    defs = der.domain.definition_map(table)
    residuals = [substitute_definitions(c.printed - c.derived, defs) for c in cm]
    syms = set().union(*(r.free_symbols for r in residuals)) if residuals else set()
    repl = _domain_assumptions(der, syms, table)
    if repl and all(prove_zero(r.xreplace(repl), 2.0, force=False) for r in residuals):
        return Equivalence.PROOF
    try:
        if all(isinstance(numeric(c, der.domain, f"{label}#{i}", STRONG, table), Verified) for i, c in enumerate(cm)):
            return Equivalence.NUMERIC
    except Exception:  # noqa: BLE001 - a mutant the numbers cannot judge is not shown equivalent
        return None
    return None


def _run_entry(ws, eid: str, per_entry: int | None):
    from quasicentral.engine.run import derivation_of, quiet_stdout

    entry = ws.entry(eid)
    der = derivation_of(ws, entry)
    with quiet_stdout():
        try:
            result, failed = (ws.result(eid) if der.func is not None else {}), None
        except (Exception, SystemExit) as exc:  # noqa: BLE001 - the entry's derivation failed: no mutants to judge
            result, failed = None, f"{type(exc).__name__}: {exc}"
        # the relations as verify reads them (in an identity text a printed decimal is a rounding)
        roundings = der.mode is Mode.IDENTITY
        printed = entry.relations(roundings=roundings)
        base = check(printed, entry.dims, der, eid, FAST, entry.symbols, result, failed)
        rows, on_domain = [], []
        if failed is not None:
            return eid, True, rows, on_domain
        for mu in mutants_of(entry, per_entry, roundings):
            v = check(list(mu.relations), entry.dims, der, eid, FAST, entry.symbols, result)
            # an equivalent mutant has the original's values, so it cannot be refuted where the
            # original is not (a refuted original is a false alarm, counted apart): sympy is asked
            # whether a mutant is equivalent only when the numbers did not refute it
            if not isinstance(v, Refuted) and _equivalent(list(mu.relations), printed, der, result):
                continue
            if isinstance(v, Verified):
                how = equivalent_on_domain(list(mu.relations), der, result, f"{eid}:{mu.operator}:{mu.site}",
                                           entry.symbols, entry.dims)
                if how is not None:
                    on_domain.append({"entry": eid, "operator": mu.operator, "site": mu.site, "how": how.value})
                    continue
            rows.append({"entry": eid, "operator": mu.operator, "site": mu.site, "detected": isinstance(v, Refuted),
                         "verdict": v.name, "method": v.method.value, "detail": v.detail[:200]})
    return eid, isinstance(base, Refuted), rows, on_domain


def verified_entries(ws, selected: list) -> list[str]:
    """Entries whose printed form is expected to verify (not errata, not cleared suspects that
    are errata), with a derivation; not an entry that introduces what it states (notation: a
    mutant of a definition is another definition, nothing a checker can catch)."""
    for t in selected:
        t.validate()  # a mistake in a folder's data is named now (file and line), not in a worker
    ws.survey(selected)  # a folder's modules run in a child: never in this process
    return [e.id for t in selected for e in t.entries.values()
            if (ws.has_derivation(e.id) or t.check == "identity") and e.id not in t.errata
            and not (t.check == "identity" and e.defines)]


def run(ws, selected: list, per_entry: int | None = None, ids: list[str] | None = None,
        jobs: int | None = None, progress: OptionalCallback = None, timeout: float | None = None) -> dict:
    """Mutation testing over the verified entries of ``selected`` or over ``ids``.  ``progress``,
    if given, is called with a :class:`quasicentral.progress.Progress` at the start and after
    each entry.  An entry whose worker is lost (past ``timeout``, or ended) counts as a false
    alarm: its unmutated form could not be confirmed."""
    from quasicentral.engine.run import families
    from quasicentral.engine.workers import map_grouped

    ids = ids if ids is not None else verified_entries(ws, selected)
    jobs = jobs or min(len(ids), os.cpu_count() or 1) or 1
    notify(progress, 0, len(ids), "", 0, "entries mutated")
    by_id = {}

    def done(_eid, res) -> None:
        by_id[res[0]] = res
        notify(progress, len(by_id), len(ids), res[0], 0, "entries mutated")

    map_grouped(lambda eid: _run_entry(ws, eid, per_entry), families(ws, ids), jobs, done,
                timeout=(timeout or 120.0) * 10, on_lost=lambda eid, why: (eid, True, [], []))
    results = [by_id[i] for i in ids]
    rows = [r for _, _, rs, _ in results for r in rs]
    on_domain = [r for _, _, _, ds in results for r in ds]
    false_alarms = [eid for eid, alarmed, _, _ in results if alarmed]
    detected = sum(r["detected"] for r in rows)
    by_op: dict[str, dict[str, int]] = {}
    for r in rows:
        d = by_op.setdefault(r["operator"], {"mutants": 0, "detected": 0})
        d["mutants"] += 1
        d["detected"] += r["detected"]
    return {
        "entries": len(ids),
        "mutants": len(rows),
        "detected": detected,
        "recall": (detected / len(rows)) if rows else None,
        "false_alarms": len(false_alarms),
        "false_alarm_entries": false_alarms,
        "by_operator": dict(sorted(by_op.items())),
        "undetected": [r for r in rows if not r["detected"]],
        "equivalent_on_domain": on_domain,
    }


def passed(res: dict) -> bool:
    """Recall 100 % on at least one mutant, and no false alarm."""
    return res["mutants"] > 0 and res["recall"] == 1.0 and res["false_alarms"] == 0


def table(res: dict) -> str:
    recall = f"recall {100 * res['recall']:.1f} %" if res["recall"] is not None else "no mutant to measure a recall on"
    lines = [f"{res['mutants']} mutants of {res['entries']} verified entries: {res['detected']} detected, "
             f"{recall}; false alarms on the unmutated catalog: {res['false_alarms']}"]
    for op, d in res["by_operator"].items():
        lines.append(f"  {op:22s} {d['detected']:4d} / {d['mutants']:<4d}")
    for r in res["undetected"]:
        lines.append(f"  undetected: {r['entry']} {r['operator']} at {r['site']} ({r['verdict']})")
    for r in res.get("equivalent_on_domain", []):
        lines.append(f"  equivalent on the domain ({r['how']}), not counted: {r['entry']} {r['operator']} at {r['site']}")
    return "\n".join(lines)
