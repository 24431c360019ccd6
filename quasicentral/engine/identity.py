"""Identity texts: entries checked as the relations they print, on their stated constraints,
with no derivation module at all (a formula collection: DLMF's chapters, a table of integrals).

An entry of such a text (``check = "identity"`` in its ``text.toml``) is self-contained: left
= right, a chain a = b = c (a list of equations), an inequality, a special value, a series, an
integral representation, a derivative, an O-term.  Its ``constraints`` narrow where it is
sampled — except an equation whose left side is a bare symbol that its right side does not
hold (``Eq(c, csc(phi)**2)``): that *defines* the symbol, which is then computed, not drawn.
Its ``real`` symbols are drawn on the real line, and so is every symbol of an inequality (an
order is a statement about real numbers).  The definitions of the entries it ``rests_on``
hold for it too.  A derivation of the text's own may still settle an entry (then it is used
instead).
"""

from __future__ import annotations

import sympy as sp
from sympy.core.function import AppliedUndef

from quasicentral.engine.catalog import Entry
from quasicentral.engine.claims import INEQUALITIES
from quasicentral.engine.registry import Derivation, Mode
from quasicentral.notation.domain import Domain
from quasicentral.notation.timelimit import TimeLimitExceeded, time_limit


def identity_derivation(entry: Entry, rests_on: tuple[Entry, ...] = ()) -> Derivation:
    """The entry's relations checked as they stand (``mode="identity"``), on the domain its
    constraints make (:func:`entry_domain`)."""
    domain = entry_domain(entry, rests_on)
    defined = set(dict(domain.definitions))
    # in identity mode, the "unknowns" are the symbols the entry itself introduces (notation)
    return Derivation(entry.id, None, Mode.IDENTITY, domain, (), tuple(s for s in entry.defines if s not in defined),
                      "The relation as printed, checked on its stated constraints.", "")


#: CPU seconds sympy may spend solving one constraint for the symbol it defines
SOLVE_SECONDS = 1.0


def definitions_in(constraints) -> tuple[dict, list]:
    """The constraints split into definitions ``{symbol: value}`` (in order; a later one may use
    an earlier) and the conditions that remain.  An equation that one symbol enters on one
    side only (``cos φ = (√3 + 1 − x)/(√3 − 1 + x)``, ``k² = 1/2``) defines it by its principal
    solution (:func:`principal_solution`); an equation sympy cannot solve stays a condition."""
    defs: dict = {}
    rest: list = []
    for c in constraints:
        solved = _defines(c, defs)
        if solved is None:
            rest.append(c)
        else:
            defs[solved[0]] = solved[1]
    return defs, rest


def _defines(c, defs) -> tuple | None:
    if not isinstance(c, sp.Eq) or c.has(sp.floor):
        return None
    for side, other in ((c.lhs, c.rhs), (c.rhs, c.lhs)):
        # a declared function given along its variables (x(t) = sin ωt, u(x, t) = …): defined
        # there, derivatives in its variables included
        if isinstance(side, AppliedUndef) and side not in defs and not other.has(side.func) \
                and all(isinstance(a, sp.Symbol) for a in side.args) and len(set(side.args)) == len(side.args):
            return side, other
    for side, other in ((c.lhs, c.rhs), (c.rhs, c.lhs)):
        free = side.free_symbols
        if len(free) != 1:
            continue
        (s,) = free
        if s in defs or s in other.free_symbols or not isinstance(s, sp.Symbol):
            continue
        if side == s:
            return s, other
        value = principal_solution(sp.Eq(side, other), s)
        if value is not None:
            return s, value
    return None


def principal_solution(eq: sp.Eq, s: sp.Symbol):
    """The solution of ``eq`` for ``s`` on the principal branches (no multiple of π added, no
    sign changed: acos(a) of cos s = a, √a of s² = a, asin √a of sin² s = a), or None where
    sympy finds none within :data:`SOLVE_SECONDS`."""
    try:
        with time_limit(SOLVE_SECONDS) as limit:
            solutions = sp.solve(eq, s)
    except TimeLimitExceeded as exc:
        if limit is None or not limit.owns(exc):
            raise
        return None
    except Exception:  # noqa: BLE001 - an equation sympy cannot solve stays a condition
        return None
    solutions = [v for v in solutions if isinstance(v, sp.Expr) and not v.has(s)]
    if not solutions:
        return None

    def rank(v):
        shifted = isinstance(v, sp.Add) and any(t.has(sp.pi) and not t.has(sp.Function) for t in v.args)
        return (shifted, v.could_extract_minus_sign(), sp.count_ops(v), sp.default_sort_key(v))
    return min(solutions, key=rank)


def entry_domain(entry: Entry, rests_on: tuple[Entry, ...] = ()) -> Domain:
    """The sampling domain an entry's constraints, its real symbols, its relations' kind and
    the definitions of what it rests on make."""
    defs: dict = {}
    for other in rests_on:
        defs.update(definitions_in(other.constraints)[0])
        for rel in other.relations():
            if isinstance(rel, sp.Eq) and isinstance(rel.lhs, sp.Symbol) and rel.lhs not in rel.rhs.free_symbols:
                defs.setdefault(rel.lhs, rel.rhs)
    own, conditions = definitions_in(entry.constraints)
    defs.update(own)
    real = set(entry.real)
    relations = entry.relations()
    if any(type(rel) in INEQUALITIES for rel in relations):
        for rel in relations:
            real |= {s for s in rel.free_symbols if isinstance(s, sp.Symbol)}
        for value in defs.values():
            real |= value.free_symbols
    return Domain.of(definitions=defs, constraints=conditions, real=sorted(real, key=str))
