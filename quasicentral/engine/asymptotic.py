"""Relations that hold in a passage: an O-term (``f = g + O(h)`` as x → x₀) and a limit that
is infinite (``lim f = ∞``) — decided along a sequence approaching the point, on a precision
ladder.

An O-term: each ``Landau(h_i, x, x₀)`` of the relation becomes a number ε_i; the residual
R = lhs − rhs at ε = 0 must be bounded by a constant times G = Σ |∂(lhs − rhs)/∂ε_i|·|h_i| (for
a term added, |h_i|; for f·(1 + O(h)), |f·h|).  At a few in-domain points of the other
symbols, x runs through x₀ + 2^−4, 2^−8, … 2^−24 (or 2^4 … 2^24 towards ∞; from the side a
one-sided range allows) and the ratio |R|/G is computed at two precisions, which must agree.
Where it is bounded — it does not grow by more than :data:`GROWTH_ALLOWED` over the last
three steps — the relation holds there; where it grows at a steady power of 1/(x − x₀) over
every one of them, it does not (refuted, numerically: no ball bounds a limit).  Anything in
between decides nothing.

A limit equal to ±∞: |f| grows past every bound along the sequence (by at least
:data:`BLOW_UP` over it) with the real part of the printed sign.
"""

from __future__ import annotations

import mpmath
import sympy as sp

from quasicentral.engine.options import Options
from quasicentral.engine.reasons import Code, Reason
from quasicentral.engine.verdict import Inconclusive, Method, Refuted, Verdict, Verified, Witness
from quasicentral.notation import bridge
from quasicentral.notation.domain import Domain, Sampler, seed_for, substitute_definitions
from quasicentral.notation.symbols import Landau, SymbolTable

#: the steps 2^−e of the passage (e over these), towards x₀ or, as 2^e, towards ∞
STEP_EXPONENTS = (4, 8, 12, 16, 20, 24)
#: the fewest steps of the passage, from its start, on which both precisions must agree
MIN_STEPS = 4
#: the precisions of the two evaluations that must agree (digits)
PASSAGE_DPS = (50, 90)
#: the most the ratio |R|/G may grow over the last three steps and still count as bounded
GROWTH_ALLOWED = 4.0
#: the least growth rate (a power of 1/|x − x₀|) at every step that refutes
GROWTH_REFUTES = 0.25
#: how many points of the other symbols the passage is taken at
PASSAGE_POINTS = 4
#: the least growth of |f| over the sequence that shows a limit to be infinite
BLOW_UP = 1e4


def passage_relation(printed: list) -> bool:
    """Whether the relations hold in a passage (an O-term, or a limit equal to ±∞)."""
    return any(rel.has(Landau) or _infinite_limit(rel) for rel in printed if isinstance(rel, sp.Basic))


def _infinite_limit(rel) -> bool:
    return isinstance(rel, sp.Eq) and isinstance(rel.lhs, sp.Limit) and rel.rhs in (sp.oo, -sp.oo)


def check(printed: list, domain: Domain, label: str, opts: Options, table: SymbolTable) -> Verdict:
    """The verdict on relations with O-terms or infinite limits (see the module)."""
    verdicts = []
    defs = domain.definition_map(table)
    for i, rel in enumerate(printed):
        if not isinstance(rel, sp.Eq):
            return Inconclusive(Method.NONE, Reason(Code.ASYMPTOTIC_WITHOUT_LIMIT))
        rel = substitute_definitions(rel, defs)
        if _infinite_limit(rel):
            verdicts.append(_infinite(rel, domain, f"{label}#{i}", table))
        elif rel.has(Landau):
            verdicts.append(_order(rel, domain, f"{label}#{i}", table))
        else:
            return Inconclusive(Method.NONE, Reason(Code.ASYMPTOTIC_WITHOUT_LIMIT))
    refuted = [v for v in verdicts if isinstance(v, Refuted)]
    if refuted:
        return refuted[0]
    undecided = [v for v in verdicts if not isinstance(v, Verified)]
    return undecided[0] if undecided else verdicts[0]


def _passage(var, point, table: SymbolTable, domain: Domain):
    """The sequence of values of ``var`` approaching ``point`` (from inside its range where the
    range ends there)."""
    lo, hi = domain.range_map(table).get(var, (None, None))
    if point in (sp.oo, -sp.oo):
        sign = 1 if point is sp.oo else -1
        return [sign * sp.Integer(2) ** e for e in STEP_EXPONENTS]
    side = 1
    if hi is not None and sp.sympify(hi) == point:
        side = -1
    return [point + side * sp.Rational(1, 2 ** e) for e in STEP_EXPONENTS]


def _points(symbols, domain, label, table):
    if not symbols:
        return [{}]
    return Sampler(domain, table, sorted(symbols, key=str), seed_for(label)).draw(PASSAGE_POINTS)


def _values(expr, var, seq, pt):
    """|expr| along the sequence at ``pt``, at each precision of PASSAGE_DPS (None where a value
    cannot be computed)."""
    out = []
    for dps in PASSAGE_DPS:
        row = []
        for x in seq:
            try:
                v = bridge.mp_eval(expr, {**pt, var: x}, dps) if expr.free_symbols else \
                    bridge.mp_eval(expr, {}, dps)
            except (ValueError, ZeroDivisionError, TypeError, OverflowError, ArithmeticError,
                    mpmath.libmp.NoConvergence, NotImplementedError):
                return None
            row.append(v)
        out.append(row)
    return out


def _order(rel: sp.Eq, domain: Domain, label: str, table: SymbolTable) -> Verdict:
    terms = sorted(rel.atoms(Landau), key=sp.default_sort_key)
    passages = {(t.args[1], t.args[2]) for t in terms}
    if len(passages) != 1:
        return Inconclusive(Method.NONE, Reason(Code.ASYMPTOTIC_WITHOUT_LIMIT))
    (var, point), = passages
    eps = [sp.Dummy(f"e{i}") for i in range(len(terms))]
    diff = (rel.lhs - rel.rhs).xreplace(dict(zip(terms, eps)))
    residual = diff.xreplace({e: 0 for e in eps})
    bound = sp.Add(*[sp.Abs(sp.diff(diff, e).xreplace({x: 0 for x in eps}) * t.args[0]) for e, t in zip(eps, terms)])
    ratio = sp.Abs(residual) / bound
    seq = _passage(var, point, table, domain)
    others = (ratio.free_symbols | set().union(*[c.free_symbols for c in domain.constraints])) - {var}
    pts = _points(others - set(domain.definition_map(table)), domain, label, table)
    held, steps = 0, len(seq)
    for pt in pts:
        rows = _values(ratio, var, seq, pt)
        if rows is None or not all(mpmath.isfinite(v) for row in rows for v in row):
            continue
        low, high = rows
        # the passage as far as the two precisions agree: nearer x₀ the remainder R is what is
        # left of a cancellation (sn z minus its Maclaurin polynomial, z⁹ ≈ 10^(−65) at 2^(−24))
        # and runs out of the working digits; fewer than MIN_STEPS steps decide nothing
        agree = next((j for j, (a, b) in enumerate(zip(low, high))
                      if abs(a - b) > mpmath.mpf(10) ** -8 * max(abs(b), 1)), len(high))
        if agree < MIN_STEPS:
            continue  # the two precisions disagree: not a value to judge by
        r = [abs(v) for v in high[:agree]]
        step = seq[:agree]
        growth = [_rate(r[j], r[j + 1], step[j], step[j + 1], point) for j in range(len(r) - 1)]
        if all(g is not None and g > GROWTH_REFUTES for g in growth[-3:]) and r[-1] > GROWTH_ALLOWED * r[-4]:
            params = {str(k): sp.sstr(v) for k, v in sorted({**pt, var: step[-1]}.items(), key=lambda kv: str(kv[0]))}
            w = Witness(parameters=params, printed=mpmath.nstr(r[-1], 4), corrected=mpmath.nstr(r[-4], 4), digits=4,
                        certified=False, quantity=Reason.of(Code.Q_ORDER_RATIO, variable=str(var), point=sp.sstr(point)),
                        working_digits=PASSAGE_DPS[-1])
            return Refuted(Method.NUMERIC, Reason.of(Code.ORDER_GROWS, variable=str(var), point=sp.sstr(point),
                                                     rate=round(float(min(growth[-3:])), 2)),
                           held + 1, PASSAGE_DPS, witness=w)
        if r[-1] <= GROWTH_ALLOWED * max(r[-4:-1]) + mpmath.mpf(10) ** -30:
            held, steps = held + 1, min(steps, agree)
    if held >= max(1, (len(pts) + 1) // 2):
        return Verified(Method.NUMERIC, Reason.of(Code.ORDER_HOLDS, n=held, variable=str(var), point=sp.sstr(point),
                                                  steps=steps), held, PASSAGE_DPS)
    return Inconclusive(Method.NONE, Reason.of(Code.LIMIT_UNDECIDED, variable=str(var), point=sp.sstr(point)))


def _rate(r0, r1, x0, x1, point):
    """The power of 1/|x − x₀| (or of x, towards ∞) at which the ratio grows from r0 to r1."""
    if r0 <= 0 or r1 <= 0:
        return None
    if point in (sp.oo, -sp.oo):
        d0, d1 = (abs(bridge.mp_value(1 / x, 30)) for x in (x0, x1))
    else:
        d0, d1 = (abs(bridge.mp_value(sp.sympify(x - point), 30)) for x in (x0, x1))
    return float(mpmath.log(r1 / r0) / mpmath.log(d0 / d1))


def _infinite(rel: sp.Eq, domain: Domain, label: str, table: SymbolTable) -> Verdict:
    body, var, point, side = rel.lhs.args
    seq = _passage(var, point, table, domain)
    if str(side) == "-" and point not in (sp.oo, -sp.oo):
        seq = [2 * point - x for x in seq]
    sign = 1 if rel.rhs is sp.oo else -1
    pts = _points((body.free_symbols | set().union(*[c.free_symbols for c in domain.constraints])) - {var}
                  - set(domain.definition_map(table)), domain, label, table)
    held = 0
    for pt in pts:
        rows = _values(body, var, seq, pt)
        if rows is None:
            continue
        v = rows[-1]
        if not all(mpmath.isfinite(x) for x in v):
            continue
        grows = all(abs(v[j + 1]) > abs(v[j]) for j in range(len(v) - 1)) and abs(v[-1]) > BLOW_UP * abs(v[0])
        if grows and mpmath.re(v[-1]) * sign > 0:
            held += 1
        elif abs(v[-1]) < 2 * abs(v[0]):
            params = {str(k): sp.sstr(x) for k, x in sorted({**pt, var: seq[-1]}.items(), key=lambda kv: str(kv[0]))}
            w = Witness(parameters=params, printed=mpmath.nstr(v[-1], 4), corrected=sp.sstr(rel.rhs), digits=4,
                        certified=False, quantity=Reason(Code.Q_SIDES), working_digits=PASSAGE_DPS[-1])
            return Refuted(Method.NUMERIC, Reason.of(Code.STAYS_BOUNDED, variable=str(var), point=sp.sstr(point)),
                           held + 1, PASSAGE_DPS, witness=w)
    if held >= max(1, (len(pts) + 1) // 2):
        return Verified(Method.NUMERIC, Reason.of(Code.BLOWS_UP, n=held, variable=str(var), point=sp.sstr(point)),
                        held, PASSAGE_DPS)
    return Inconclusive(Method.NONE, Reason.of(Code.LIMIT_UNDECIDED, variable=str(var), point=sp.sstr(point)))
