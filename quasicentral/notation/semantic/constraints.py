"""DLMF's constraints (``\\constraint{…}``) read as relations, in the names of a reading.

>>> c = read_constraint(r"0\\leq k\\leq 1")
>>> c.relations, sorted(c.real)
(('Le(0, k)', 'Le(k, 1)'), ['k'])
>>> read_constraint(r"z\\in\\Complexes\\setminus(-\\infty,0]").relations
('Or(Ne(im(z), 0), Gt(re(z), 0))',)
>>> read_constraint(r"m=0,1,\\dots").relations
('Eq(m, floor(m))', 'Ge(m, 0)')
>>> read_constraint(r"j=1,2,3").relations
('Or(Eq(j, 1), Eq(j, 2), Eq(j, 3))',)
>>> read_constraint(r"x,y,z>0").relations
('Gt(x, 0)', 'Gt(y, 0)', 'Gt(z, 0)')
>>> read_constraint(r"\\alpha^{2}\\to 1-").limits
(Limit(var='alpha', point='1', side='-'),)

An interval of ±∞ says only that its member is real: ``-\\infty<k^{2}<1`` is
``Lt(k**2, 1)`` with ``Eq(im(k**2), 0)``.  An equation whose left side is a bare symbol
(``r=\\frac{1}{16}k^{2}``) is kept as ``Eq(r, k**2/16)``: it defines that symbol for the
formula.
"""

from __future__ import annotations

from dataclasses import dataclass

from . import Limit, nodes as N
from .lexer import Kind, tokenize
from .macros import RELATIONS
from .options import Options, SemanticLatexError
from .parser import Parser

_SETS = frozenset({r"\Reals", r"\Complexes", r"\Integers", r"\NatNumber"})


@dataclass(frozen=True)
class ConstraintReading:
    relations: tuple[str, ...]          # sympy relations that must hold
    real: frozenset[str] = frozenset()  # symbols the constraint makes real
    limits: tuple[Limit, ...] = ()      # passages (x → 0+) the formula holds in


def read_constraint(latex: str, options: Options | None = None) -> ConstraintReading:
    """Read one ``\\constraint`` of DLMF (a relation, a chain, a membership, an integer range,
    a passage to a limit)."""
    options = options or Options()
    toks = tokenize(latex)
    p = Parser(toks, options, latex)
    cuts = _relation_positions(toks)
    if not cuts:
        raise SemanticLatexError("a constraint without a relation", token=latex[:20])
    ops = [RELATIONS[toks[i].text] for i in cuts]
    bounds = [0] + [i + 1 for i in cuts]
    ends = cuts + [len(toks) - 1]
    spans = list(zip(bounds, ends))
    subjects = p.sub(*spans[0], p.comma_list)
    if ops[0] == "to":
        return _passage(p, subjects, spans[1])
    if ops[0] == "in":
        return _membership(p, subjects, toks, spans[1])
    if ops == ["Eq"] and _has_dots(toks, spans[1]):
        return _integers(p, subjects, spans[1])
    members = [subjects] + [p.sub(a, b, p.comma_list) for a, b in spans[1:]]
    if ops == ["Eq"] and len(members[1]) > 1:  # j=1,2,3: one of a few values
        rels = [f"Or({', '.join(f'Eq({_text(s)}, {_text(v)})' for v in members[1])})" for s in subjects]
        return ConstraintReading(tuple(rels), frozenset(s.name for s in subjects if isinstance(s, N.Sym)))
    rels: list[str] = []
    real: set[str] = set()
    for subject in subjects:
        chain = [[subject]] + members[1:]
        for j, op in enumerate(ops):
            for lhs in chain[j]:
                for rhs in chain[j + 1]:
                    rel = N.Rel(op, lhs, rhs)
                    if not N.has_signs(rel):
                        _relation(op, lhs, rhs, rels, real)
                        continue
                    # p_± = …: both hold; p = x ± …: one of the two does
                    both = [N.resolve(rel, c) for c in (1, -1)]
                    if any(isinstance(n, N.PMSym) for n in N.walk(rel)):
                        for r in both:
                            _relation(r.op, r.lhs, r.rhs, rels, real)
                    else:
                        rels.append(f"Or({', '.join(_text(r) for r in both)})")
    return ConstraintReading(tuple(dict.fromkeys(rels)), frozenset(real))


def _relation_positions(toks) -> list[int]:
    depth, out = 0, []
    for i, t in enumerate(toks):
        if t.kind is Kind.OPEN or t.is_("(", "["):
            depth += 1
        elif t.kind is Kind.CLOSE or t.is_(")", "]"):
            depth -= 1
        elif depth == 0 and t.kind in (Kind.CHAR, Kind.COMMAND) and t.text in RELATIONS:
            out.append(i)
    return out


def _has_dots(toks, span) -> bool:
    return any(t.is_(r"\dots", r"\ldots", r"\cdots") for t in toks[span[0]:span[1]])


def _text(node: N.Node) -> str:
    return N.to_sympy(node)


def _relation(op: str, lhs: N.Node, rhs: N.Node, rels: list[str], real: set[str]) -> None:
    if op == "Eq" and isinstance(lhs, N.Tup) and isinstance(rhs, N.Tup) and len(lhs.items) == len(rhs.items):
        for a, b in zip(lhs.items, rhs.items):  # (ξ, η) = (x + λ, y + λ): one per member
            _relation(op, a, b, rels, real)
        return
    infinite = {N.Const("oo"), N.neg(N.Const("oo"))}
    if op in ("Lt", "Le", "Gt", "Ge"):
        for side in (lhs, rhs):
            if isinstance(side, N.Sym):
                real.add(side.name)
            elif side not in infinite and not _real_valued(side):
                rels.append(f"Eq(im({_text(side)}), 0)")
        if lhs in infinite or rhs in infinite:
            return
    rels.append(f"{op}({_text(lhs)}, {_text(rhs)})")


def _real_valued(node: N.Node) -> bool:
    """Whether a side is real by its form alone (a number, |x|, Re x, Im x, ph x)."""
    if isinstance(node, (N.Num, N.Const)) and node != N.Const("I"):
        return True
    if isinstance(node, N.Neg):
        return _real_valued(node.arg)
    if isinstance(node, N.Div):
        return _real_valued(node.num) and _real_valued(node.den)
    return isinstance(node, N.Call) and node.func in ("Abs", "re", "im", "arg", "Max", "Min")


def _passage(p, subjects, span) -> ConstraintReading:
    p.trailing_sign = None
    point = p.sub(*span, p.expr)
    side = "" if p.trailing_sign is None else ("-" if isinstance(p.trailing_sign, N.Neg) else "+")
    var = subjects[0]
    at = _text(point)
    if isinstance(var, N.Pow) and isinstance(var.base, N.Sym):
        var = var.base  # α² → 1−: α → 1− (DLMF's α² and k² are read through α, k)
    if isinstance(var, N.Div) and at == "0" and not side:
        # a ratio u/v → 0: v → ∞ with u fixed (or u → 0 with v fixed)
        if isinstance(var.den, N.Sym):
            return ConstraintReading((), frozenset(), (Limit(var.den.name, "oo", ""),))
        var, at = var.num, "0"
    if len(subjects) != 1 or not isinstance(var, N.Sym):
        raise SemanticLatexError("a passage to a limit of an expression", token=r"\to")
    return ConstraintReading((), frozenset(), (Limit(var.name, at, side),))


def _membership(p, subjects, toks, span) -> ConstraintReading:
    body = [t for t in toks[span[0]:span[1]]]
    head = body[0].text if body else ""
    if head not in _SETS:
        raise SemanticLatexError("a membership in a set the reader does not know", token=head)
    rest = body[1:]
    rels: list[str] = []
    real: set[str] = set()
    excluded = None
    if rest and rest[0].is_(r"\setminus"):
        excluded = "".join(t.text for t in rest[1:])
    for s in subjects:
        x = _text(s)
        if head == r"\Reals":
            if isinstance(s, N.Sym):
                real.add(s.name)
            else:
                rels.append(f"Eq(im({x}), 0)")
            if excluded == r"\{0\}":
                rels.append(f"Ne({x}, 0)")
            elif excluded is not None:
                raise SemanticLatexError("a set difference the reader does not know", token=excluded)
        elif head == r"\Complexes":
            if excluded == r"(-\infty,0]":
                rels.append(f"Or(Ne(im({x}), 0), Gt(re({x}), 0))")
            elif excluded == r"(-\infty,0)":
                rels.append(f"Or(Ne(im({x}), 0), Ge(re({x}), 0))")
            elif excluded is not None:
                raise SemanticLatexError("a set difference the reader does not know", token=excluded)
        else:
            rels += [f"Eq({x}, floor({x}))"] + ([f"Ge({x}, 0)"] if head == r"\NatNumber" else [])
            real.add(s.name) if isinstance(s, N.Sym) else None
    return ConstraintReading(tuple(rels), frozenset(real))


def _integers(p, subjects, span) -> ConstraintReading:
    """``m=0,1,\\dots`` (a nonnegative integer), ``j=1,2,3`` (one of a few), ``j=1,\\dots,n``."""
    items = [t for t in p.toks[span[0]:span[1]] if not t.is_(",")]
    values = [t for t in items if not t.is_(r"\dots", r"\ldots", r"\cdots")]
    first = values[0].text if values and values[0].kind is Kind.NUMBER else None
    last = None
    if items and not items[-1].is_(r"\dots", r"\ldots", r"\cdots"):
        last = p.sub(span[0] + len(p.toks[span[0]:span[1]]) - 1, span[1], p.expr)
    if first is None:
        raise SemanticLatexError("an integer range the reader does not know", token=r"\dots")
    rels: list[str] = []
    real: set[str] = set()
    for s in subjects:
        x = _text(s)
        rels += [f"Eq({x}, floor({x}))", f"Ge({x}, {first})"]
        if last is not None:
            rels.append(f"Le({x}, {_text(last)})")
        if isinstance(s, N.Sym):
            real.add(s.name)
    return ConstraintReading(tuple(rels), frozenset(real))
