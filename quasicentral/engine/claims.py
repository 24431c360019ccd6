"""Claims: the printed relations paired with a derivation's result, as pairs of expressions
that should be equal on the declared domain.

How a derivation's result meets the printed form is its :class:`~quasicentral.engine.registry.Mode`:
solved for the same unknowns and compared (``solve``), checked on the derived model
(``substitute``), compared as bare expressions (``expression``), or a quantity that must
vanish under the printed condition (``condition``).  :class:`CannotCompare` says, as a
:class:`~quasicentral.engine.reasons.Reason`, why the two cannot be paired.
"""

from __future__ import annotations

from types import MappingProxyType
from dataclasses import dataclass

import sympy as sp
from sympy.core.function import AppliedUndef

from quasicentral.engine.reasons import Code, Reason
from quasicentral.engine.registry import Mode, as_list
from quasicentral.notation.symbols import Approx


@dataclass(frozen=True)
class Claim:
    """Two expressions that should be equal on the domain — or, ``at_most``, a printed side
    that should not exceed the other (an inequality, checked one-sidedly on real values)."""

    printed: sp.Expr
    derived: sp.Expr
    quantity: Reason  # what the two values are (a Q_… reason)
    scale: sp.Expr | None = None  # magnitude the difference is measured against
    at_most: bool = False  # printed ≤ derived is claimed, not printed = derived
    #: an implicit condition (unknown, f): the claim holds where f = 0, the unknown solved for
    implicit: tuple = ()


#: the inequalities, each as (is "left ≤ right" rather than "left ≥ right")
INEQUALITIES = MappingProxyType({sp.StrictLessThan: True, sp.LessThan: True, sp.StrictGreaterThan: False, sp.GreaterThan: False})


class CannotCompare(Exception):
    """The printed relations cannot be paired with the derivation's result (``reason``)."""

    def __init__(self, reason: Reason):
        super().__init__(reason.code.value)
        self.reason = reason


class HoldsAsPrinted(Exception):
    """Every printed relation is one sympy decides true as it stands (from the symbols'
    assumptions: 0 ≤ erf x for x > 0): a proof, nothing left to compare."""


def put_model(e: sp.Basic, model: dict) -> sp.Basic:
    """``e`` on a derived model: ``{x: …}`` substituted, and a function given whole,
    ``{u.func: Lambda((x, t), …)}``, put in at each of its applications (u(0, t), f(v) inside
    ∫ … dv) — by ``replace``: sympy's ``subs`` of a function class fails inside an integral
    (TypeError: 'property' object is not iterable)."""
    whole = {k: v for k, v in model.items() if isinstance(k, sp.FunctionClass)}
    rest = {k: v for k, v in model.items() if k not in whole}
    for head, body in whole.items():
        e = e.replace(head, body) if isinstance(body, sp.Lambda) else e.subs(head, body)
    return e.subs(rest) if rest else e


def doit_derivatives(e):
    """Derivatives carried out, and a derivative at a point (``Subs``) too — its terms then
    show, so that a value that is exactly 0 is judged against them."""
    if e.has(sp.Derivative):
        e = e.replace(lambda a: isinstance(a, sp.Derivative), lambda a: a.doit())
    if e.has(sp.Subs):
        e = e.replace(lambda a: isinstance(a, sp.Subs), lambda a: a.doit())
    return e


def solutions_for(rel: sp.Basic, unknown: sp.Basic) -> list[sp.Expr]:
    """The values of ``unknown`` that ``rel`` states: one where it enters linearly, else
    sympy's solutions on the symbols' assumptions (v² = 2gh: ±√(2gh), or √(2gh) alone for a
    positive v); none where it states none (not an equation, the unknown absent, or sympy
    finds no solution)."""
    if not isinstance(rel, sp.Eq):
        return []
    if rel.lhs == unknown:
        return [rel.rhs]
    if rel.rhs == unknown:
        return [rel.lhs]
    dummy = sp.Dummy("u", **unknown.assumptions0) if isinstance(unknown, sp.Symbol) else sp.Dummy("u")
    expr = (rel.lhs - rel.rhs).xreplace({unknown: dummy})
    if dummy not in expr.free_symbols:
        return []
    coeff = sp.diff(expr, dummy)
    if dummy in coeff.free_symbols:
        try:
            sols = sp.solve(expr, dummy)
        except NotImplementedError:  # an equation sympy cannot solve states no value it can name
            return []
        return [v for v in sols if isinstance(v, sp.Expr) and dummy not in v.free_symbols]
    return [sp.cancel(-expr.xreplace({dummy: 0}) / coeff) if coeff.is_polynomial() else -expr.xreplace({dummy: 0}) / coeff]


def solve_for(rel: sp.Basic, unknown: sp.Basic) -> sp.Expr | None:
    """The value of ``unknown`` that ``rel`` states (None where it states none, or several)."""
    sols = solutions_for(rel, unknown)
    return sols[0] if len(sols) == 1 else None


def decided(rel: sp.Basic) -> sp.Basic:
    """A printed equation whose two sides are the same expression, or two numbers sympy finds
    equal (True); any other relation as it is (a transcription
    keeps its equations undecided: :func:`quasicentral.notation.symbols.printed_eq`)."""
    if isinstance(rel, sp.Eq):
        if rel.lhs == rel.rhs:
            return sp.true
        if rel.lhs.is_number and rel.rhs.is_number and sp.Eq(rel.lhs, rel.rhs) is sp.true:
            return sp.true
        # two numbers sympy finds unequal are left to the numbers: a refutation has a witness
    return rel


def _truth(rel) -> None:
    if rel in (sp.true, sp.false):
        raise CannotCompare(Reason.of(Code.EVALUATES_TO, value=str(rel)))


def claims_for(printed: list[sp.Basic], derivation, result) -> list[Claim]:
    """Pair the printed relations with the derivation's result; :class:`CannotCompare` says
    why they cannot be."""
    mode = derivation.mode
    if mode is Mode.IDENTITY:
        return identity_claims(printed, derivation.unknowns or ())
    printed = [decided(rel) for rel in printed]
    if mode is Mode.CONDITION:
        return _condition_claims(printed, result, derivation.unknowns)
    if mode is Mode.SUBSTITUTE:
        return _model_claims(printed, dict(result or {}))
    derived = [doit_derivatives(d) if isinstance(d, sp.Basic) else d for d in as_list(result)]
    printed = [doit_derivatives(p) for p in printed]
    unknowns = derivation.unknowns
    if len(derived) == 1 and len(printed) > 1:
        # one derived relation, printed in several rows (a chain of equal forms): each row is
        # compared with it
        derived = derived * len(printed)
        unknowns = unknowns * len(printed) if unknowns is not None and len(unknowns) == 1 else unknowns
    if len(derived) != len(printed):
        raise CannotCompare(Reason.of(Code.RELATION_COUNT, printed=len(printed), derived=len(derived)))
    if mode is Mode.EXPRESSION:
        return [Claim(p, d, Reason(Code.Q_VALUE)) for p, d in zip(printed, derived)]
    return _solved_claims(printed, derived, unknowns or tuple(d.lhs for d in derived))


def window_claim(rel: Approx, put) -> Claim:
    """A formula with printed decimals (θ ≈ 1.22 λ/D): |x − value| at most what the decimals'
    rounding allows (:meth:`~quasicentral.notation.symbols.Approx.window`), ``put`` applied
    to both (the derived model, derivatives carried out)."""
    distance, allowed = rel.window()
    return Claim(put(distance), put(allowed), Reason(Code.Q_ROUNDING_WINDOW), at_most=True)


def _name(s: sp.Basic) -> str:
    """A symbol's name; a declared function's (θ for θ(t))."""
    return s.func.__name__ if isinstance(s, AppliedUndef) else str(s)


def identity_claims(printed: list, defines: tuple = ()) -> list[Claim]:
    """The printed relations as they stand: each equation's two sides (a chain is a list of
    equations), each inequality as its lesser side at most its greater.  Derivatives sympy can
    carry out are carried out; the rest is left to the numbers.  A relation that holds a symbol
    the entry introduces (``defines``) is its definition: notation, nothing to check."""
    out, decided_true = [], False
    # a chain a < b < c is read as And(a < b, b < c): each of its relations
    printed = [r for rel in printed for r in (rel.args if isinstance(rel, sp.And) else (rel,))]
    for rel in printed:
        if rel is sp.true:  # sympy decided it from the symbols' assumptions: it holds as printed
            decided_true = True
            continue
        # a symbol it introduces, or a function it introduces (the θ(t) an equation of motion is
        # about: declared in text.toml, or written Function('theta')(t))
        introduced = sorted(({_name(s) for s in defines if s in rel.free_symbols}
                             | ({_name(s) for s in defines} & {f.func.__name__ for f in rel.atoms(AppliedUndef)}))
                            if isinstance(rel, sp.Basic) else ())
        if introduced:
            raise CannotCompare(Reason.of(Code.DEFINES, symbols=tuple(introduced)))
        if isinstance(rel, Approx) and rel.is_formula:
            out.append(window_claim(rel, doit_derivatives))
        elif isinstance(rel, sp.Eq) and _antiderivative(rel) is not None:
            out.append(_antiderivative(rel))
        elif isinstance(rel, sp.Eq):
            out.append(Claim(doit_derivatives(rel.lhs), doit_derivatives(rel.rhs), Reason(Code.Q_SIDES)))
        elif type(rel) in INEQUALITIES:
            low, high = (rel.lhs, rel.rhs) if INEQUALITIES[type(rel)] else (rel.rhs, rel.lhs)
            out.append(Claim(doit_derivatives(low), doit_derivatives(high), Reason(Code.Q_LESSER_GREATER),
                             at_most=True))
        elif rel in (sp.true, sp.false):
            _truth(rel)
        elif isinstance(rel, sp.Ne):
            raise CannotCompare(Reason(Code.NOT_EQUAL_ONLY))
        else:
            raise CannotCompare(Reason(Code.NOTATION_ONLY))
    if not out and decided_true:
        raise HoldsAsPrinted()
    if not out:
        raise CannotCompare(Reason(Code.NOTHING_TO_CHECK))
    return out


def _indefinite(e) -> bool:
    return isinstance(e, sp.Integral) and len(e.limits) == 1 and len(e.limits[0]) == 1


def _antiderivative(rel: sp.Eq) -> Claim | None:
    """``∫ f dx = F`` (an indefinite integral, determined up to a constant): F′ = f is what it
    states, and what is checked (DLMF §22.14, tables of integrals)."""
    for side, other in ((rel.lhs, rel.rhs), (rel.rhs, rel.lhs)):
        if _indefinite(side) and not (_indefinite(other) or other.has(sp.Integral)):
            (x,) = side.limits[0]
            return Claim(doit_derivatives(sp.Derivative(other, x)), side.function,
                         Reason.of(Code.Q_ANTIDERIVATIVE, variable=str(x)))
    return None


def _condition_claims(printed: list, result, unknowns=None) -> list[Claim]:
    """The derived quantity must vanish under the printed condition: substituted where the
    condition names what the quantity holds (``Eq(A, 0)``, ``Eq(ω², k/m)``), else *implicit* —
    "x solves f(x) = 0" — and then checked only at points where it holds: the unknown (the
    derivation's ``unknowns``, or the one symbol the condition and the quantity share) is
    solved for at every point (:func:`quasicentral.notation.domain.on_condition`), so that no
    point, and no witness, violates the premise."""
    if not all(isinstance(r, sp.Eq) for r in printed):
        raise CannotCompare(Reason(Code.CONDITION_NOT_EQUATION))
    q = doit_derivatives(result)
    quantity = Reason.of(Code.Q_UNDER_CONDITION, quantity=sp.sstr(q))
    # a substitution holds the premise only where it eliminates what the condition names: a
    # symbol on either side (A = 0, R₀Ω = v₀), or the unknown solved for (½mv_p² = k_BT: v_p), or
    # a pattern that leaves none of its symbols (ω² = k/m with ω only squared in q); put in as a
    # pattern that leaves v_p and m free, points drawn for them would break the premise (a
    # certified false refutation)
    cond, named = {}, set()
    for r in printed:
        key, value = _eliminated_by(r, unknowns)
        cond[key] = value
        named |= key.free_symbols - value.free_symbols
    substituted = q.subs(cond)
    if substituted != q and not (substituted.free_symbols & named):
        return [Claim(substituted, sp.Integer(0), quantity, sp.Abs(q))]
    if len(printed) != 1:
        raise CannotCompare(Reason.of(Code.CONDITIONS_NOT_ELIMINATING, symbols=tuple(sorted(map(str, named)))))
    f = doit_derivatives(printed[0].lhs - printed[0].rhs)
    # any symbol of the condition will do: solved for it, the points satisfy the premise; the
    # derivation's unknown, else one the quantity shares, samples where the text means
    candidates = [u for u in (unknowns or ()) if u in f.free_symbols] or \
        sorted(f.free_symbols & q.free_symbols, key=str) or sorted(f.free_symbols, key=str)
    if not candidates:
        raise CannotCompare(Reason.of(Code.CONDITION_UNKNOWN, symbols=()))
    return [Claim(q, sp.Integer(0), quantity, None, implicit=(candidates[0], f))]


def _eliminated_by(rel: sp.Eq, unknowns) -> tuple[sp.Basic, sp.Expr]:
    """What a printed condition puts in: a symbol (or function) alone on either side and absent
    from the other; else an unknown it states one value of; else its left side as a pattern."""
    for side, other in ((rel.lhs, rel.rhs), (rel.rhs, rel.lhs)):
        if isinstance(side, (sp.Symbol, AppliedUndef)) and not other.has(side):
            return side, other
    for u in unknowns or ():
        if rel.has(u):
            value = solve_for(rel, u)
            if value is not None:
                return u, value
    return rel.lhs, rel.rhs


def _model_claims(printed: list, model: dict) -> list[Claim]:
    out = []
    for rel in printed:
        if isinstance(rel, Approx) and rel.is_formula:
            out.append(window_claim(rel, lambda e: doit_derivatives(put_model(doit_derivatives(e), model))))
        elif isinstance(rel, sp.Eq):
            lhs = doit_derivatives(put_model(doit_derivatives(rel.lhs), model))
            rhs = doit_derivatives(put_model(doit_derivatives(rel.rhs), model))
            out.append(Claim(lhs - rhs, sp.Integer(0), Reason(Code.Q_RESIDUAL), sp.Abs(lhs) + sp.Abs(rhs)))
        elif isinstance(rel, sp.Basic) and rel in (sp.true, sp.false):
            _truth(rel)
        else:
            out.append(Claim(doit_derivatives(put_model(rel, model)), sp.Integer(0), Reason(Code.Q_EXPRESSION)))
    return out


def _solved_claims(printed: list, derived: list, unknowns) -> list[Claim]:
    out = []
    for p, d, unk in zip(printed, derived, unknowns):
        unk = doit_derivatives(unk)
        _truth(p)
        if isinstance(p, Approx) and p.is_formula:
            dvs = solutions_for(d, unk)
            if len(dvs) != 1:
                raise CannotCompare(Reason.of(Code.CANNOT_SOLVE, unknown=sp.sstr(unk)))
            out.append(window_claim(p, lambda e, dv=dvs[0]: doit_derivatives(e.xreplace({unk: dv}))))
            continue
        pv, dvs = solve_for(p, unk), solutions_for(d, unk)
        if not isinstance(p, sp.Eq) and pv is None:
            raise CannotCompare(Reason.of(Code.NOT_EQUATION_FOR, unknown=sp.sstr(unk)))
        if len(dvs) == 1 and pv is not None:
            out.append(Claim(pv, dvs[0], Reason.of(Code.Q_UNKNOWN, unknown=sp.sstr(unk))))
        elif pv is not None:
            # the derived relation of several branches (v² = 2gh) of which the printed value
            # is one (v = √(2gh)), or of none sympy can name (a transcendental one): it must
            # hold at the value printed
            out.append(_residual(d, unk, pv, Code.Q_DERIVED_RESIDUAL))
        elif dvs:
            # the printed relation not solvable for the unknown (absent, or several branches):
            # it must hold on every branch the derived one states
            out += [_residual(p, unk, dv, Code.Q_PRINTED_RESIDUAL) for dv in dvs]
        else:
            raise CannotCompare(Reason.of(Code.CANNOT_SOLVE, unknown=sp.sstr(unk)))
    return out


def _residual(rel: sp.Eq, unknown: sp.Basic, value: sp.Expr, code: Code) -> Claim:
    """lhs − rhs of ``rel`` at ``unknown`` = ``value``, which must vanish (judged against the
    size of its two sides)."""
    lhs, rhs = rel.lhs.xreplace({unknown: value}), rel.rhs.xreplace({unknown: value})
    return Claim(lhs - rhs, sp.Integer(0), Reason.of(code, unknown=sp.sstr(unknown)), sp.Abs(lhs) + sp.Abs(rhs))
