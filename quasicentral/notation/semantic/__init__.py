"""A reader of DLMF's semantic LaTeX: ``\\incellintFk@{\\phi}{k}`` → ``EllipticF(phi, k)``.

The DLMF writes every formula twice: as presentation LaTeX (what the page shows) and as
*semantic* LaTeX, where each function is a macro that names it (``\\incellintFk`` is
Legendre's F(φ, k), ``\\Jacobiellsnk`` is sn(z, k), ``\\CarlsonsymellintRF`` is R_F).  This
reader turns the semantic form into a transcription in sympy syntax, in the names of
:mod:`quasicentral.notation` (modulus k throughout; see :mod:`.macros`), and lists the
symbols and functions it used.  It only produces strings: it imports nothing outside the
standard library.

>>> r = read(r"\\incellintFk@{\\phi}{k}=\\int_{0}^{\\phi}\\frac{\\diff{\\theta}}{\\sqrt{1-k^{2}\\sin^{2}@@{\\theta}}}")
>>> print(r.transcription)
Eq(EllipticF(phi, k), Integral(1/sqrt(1 - k**2*sin(theta)**2), (theta, 0, phi)))
>>> sorted(r.symbols)
['k', 'phi', 'theta']

A chain is a list, each member compared with the first; correlated signs give two readings:

>>> print(read(r"\\incellintFk@{m\\pi\\pm\\phi}{k}=2m\\compellintKk@{k}\\pm\\incellintFk@{\\phi}{k}").transcription)
[Eq(EllipticF(m*pi + phi, k), 2*m*EllipticK(k) + EllipticF(phi, k)), Eq(EllipticF(m*pi - phi, k), 2*m*EllipticK(k) - EllipticF(phi, k))]

A prime on the modulus is the complementary modulus, ``k′ = √(1 − k²)``:

>>> print(read(r"\\ccompellintKk@{k}=\\compellintKk@{k^{\\prime}}").transcription)
Eq(EllipticKp(k), EllipticK(sqrt(1 - k**2)))

What it cannot read is an error naming the macro or token:

>>> read(r"\\Hankel@{z}")
Traceback (most recent call last):
...
quasicentral.notation.semantic.options.SemanticLatexError: the macro \\Hankel is not known to the reader (at offset 0: '\\\\Hankel@{z}')
"""

from __future__ import annotations

from dataclasses import dataclass

from . import nodes as N
from .lexer import LexError, tokenize
from .options import Options, SemanticLatexError
from .parser import Parser

__all__ = ["Options", "Reading", "SemanticLatexError", "parse", "read", "Limit"]


@dataclass(frozen=True)
class Limit:
    """The passage a relation ``a \\to b`` or ``a \\sim b`` holds in: var → point (side)."""

    var: str
    point: str
    side: str = ""  # "+", "-" or "" (both sides)


@dataclass(frozen=True)
class Parsed:
    """The trees of a formula (signs unresolved) and what the reading noted."""

    trees: tuple[N.Node, ...]
    notes: tuple[str, ...]


@dataclass(frozen=True)
class Reading:
    """A formula read: its relations in sympy syntax (a chain or a ± gives several), the
    names of its symbols and functions, and the notes on what the reading had to decide."""

    relations: tuple[str, ...]
    symbols: frozenset[str]
    functions: frozenset[str]
    notes: tuple[str, ...] = ()

    @property
    def transcription(self) -> str:
        """One relation as it is; several as a list ``[r1, r2, …]``."""
        if len(self.relations) == 1:
            return self.relations[0]
        return "[" + ", ".join(self.relations) + "]"


def parse(latex: str, options: Options | None = None) -> Parsed:
    """The trees of ``latex`` (one per relation of a chain, per formula of a ``\\quad`` list)."""
    options = options or Options()
    try:
        tokens = tokenize(latex)
    except LexError as exc:
        raise SemanticLatexError(str(exc)) from None
    p = Parser(tokens, options, latex)
    trees = p.formulas()
    return Parsed(tuple(trees), tuple(dict.fromkeys(p.notes)))


def read(latex: str, options: Options | None = None, limit: Limit | None = None,
         sign: int | None = None) -> Reading:
    """Read one formula of semantic LaTeX.

    ``limit`` states the passage of a relation ``a \\to b`` (read as
    ``Eq(Limit(a, var, point, side), b)``) or ``a \\sim b`` (``Eq(Limit(a/b, …), 1)``); a
    formula holding one without it is an error.  ``sign`` +1 (−1) reads only the upper
    (lower) signs of ``\\pm`` and ``\\mp``; by default both readings are returned.
    """
    parsed = parse(latex, options)
    relations: list[str] = []
    symbols: set[str] = set()
    functions: set[str] = set()
    for tree in parsed.trees:
        tree = _limit(tree, limit)
        choices = ((1, -1) if sign is None else (sign,)) if N.has_signs(tree) else (1,)
        for choice in choices:
            resolved = N.resolve(tree, choice)
            text = N.to_sympy(resolved)
            if text not in relations:
                relations.append(text)
            for node in N.walk(resolved):
                if isinstance(node, N.Sym):
                    symbols.add(node.name)
                elif isinstance(node, N.Call):
                    functions.add(node.func)
    return Reading(tuple(relations), frozenset(symbols), frozenset(functions), parsed.notes)


def _limit(tree: N.Node, limit: Limit | None) -> N.Node:
    if not isinstance(tree, N.Rel) or tree.op not in ("to", "sim", "in"):
        return tree
    if tree.op == "in" or limit is None:
        what = {"to": "a relation \\to", "sim": "an asymptotic relation \\sim", "in": "a membership \\in"}
        raise SemanticLatexError(f"{what[tree.op]} needs the passage it holds in (give limit=Limit(...))",
                                 token="\\" + tree.op)
    at = N.Const("oo") if limit.point == "oo" else N.Num(limit.point) if limit.point.isdigit() else N.Sym(limit.point)
    args = (N.Sym(limit.var), at) + ((N.Str(limit.side),) if limit.side else ())
    if tree.op == "to":
        return N.Rel("Eq", N.Call("Limit", (tree.lhs,) + args), tree.rhs)
    return N.Rel("Eq", N.Call("Limit", (N.div(tree.lhs, tree.rhs),) + args), N.ONE)
