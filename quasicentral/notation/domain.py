"""Declared domains: where each symbol lives, the paper's assumptions, and the definitions that
tie derived symbols to the primitive ones (Ω = √(g/l), u = R0Ω, …).

A text's symbol table gives the default range and definition of each symbol
(:class:`~quasicentral.notation.symbols.SymbolTable`); a derivation's :class:`Domain` narrows or
adds to them for its own step.

Points are sampled at random (seeded by the equation id, so a run is reproducible) as *exact*
sympy numbers; they cross to mpmath only in :mod:`quasicentral.bridge`.
"""

from __future__ import annotations

import hashlib
import random
from dataclasses import dataclass, field

import sympy as sp

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

    @staticmethod
    def of(ranges=None, definitions=None, constraints=(), defaults=True) -> "Domain":
        return Domain(
            ranges=tuple((ranges or {}).items()),
            definitions=tuple((definitions or {}).items()),
            constraints=tuple(constraints),
            defaults=defaults,
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
        return sp.srepr((self.ranges, self.definitions, self.constraints, self.defaults))


def substitute_definitions(expr: sp.Basic, defs: dict[sp.Basic, sp.Expr], rounds: int = 6) -> sp.Basic:
    """Apply the definitions until nothing changes (definitions may refer to each other)."""
    for _ in range(rounds):
        new = expr.xreplace(defs) if defs else expr
        if new == expr:
            break
        expr = new
    return expr


def seed_for(label: str) -> int:
    return int.from_bytes(hashlib.sha256(label.encode()).digest()[:8], "big")


@dataclass
class Sampler:
    """Draws exact points for a set of free symbols inside a :class:`Domain`."""

    domain: Domain
    table: SymbolTable
    symbols: list[sp.Symbol]
    seed: int
    extra_ranges: dict = field(default_factory=dict)

    def draw(self, count: int, max_tries: int = 200) -> list[dict[sp.Symbol, sp.Expr]]:
        rng = random.Random(self.seed)
        ranges = self.domain.range_map(self.table)
        ranges.update(self.extra_ranges)
        defs = self.domain.definition_map(self.table)
        wanted = set(self.symbols)
        for c in self.domain.constraints:
            wanted |= substitute_definitions(c, defs).free_symbols
        order = _sampling_order(wanted, ranges, defs)
        missing = [sym for sym in order if sym not in ranges]
        if missing:
            raise KeyError(f"no range declared for symbol {missing[0]}")
        # endpoints and constraints with the definitions applied, once
        ends = {sym: tuple(substitute_definitions(sp.sympify(e), defs) for e in ranges[sym]) for sym in order}
        constraints = [substitute_definitions(c, defs) for c in self.domain.constraints]
        points = []
        tries = 0
        while len(points) < count and tries < count * max_tries:
            tries += 1
            pt: dict[sp.Symbol, sp.Expr] = {}
            for sym in order:
                lo, hi = (e.xreplace(pt) for e in ends[sym])
                pt[sym] = lo + (hi - lo) * sp.Rational(rng.randrange(1, 2**20), 2**20)
            if all(_holds(c, pt) for c in constraints):
                points.append(pt)
        return points


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
