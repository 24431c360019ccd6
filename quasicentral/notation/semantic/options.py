"""How a reading is steered, and the error it raises."""

from __future__ import annotations

from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Mapping


class SemanticLatexError(ValueError):
    """A formula the reader cannot read; ``token`` is the macro or token it stopped at."""

    def __init__(self, message: str, token: str = ""):
        super().__init__(message)
        self.token = token


def _frozen(mapping) -> Mapping:
    return MappingProxyType(dict(mapping or {}))


@dataclass(frozen=True)
class Options:
    """What a formula's context says and its LaTeX does not.

    ``letters``: generic letters bound to values — ``{"p": "s", "q": "c"}`` reads
    ``\\genJacobiellk{p}{q}`` as sc, ``{"j": "1"}`` reads ``x_{j}`` as ``x_1``.
    ``defined``: notations the text defines, ``{"Delta": (("x",), r"\\sqrt{1-k^{2}\\sin^{2}@@{x}}")}``:
    ``\\Delta(\\theta)`` is read as that body with x bound to θ.
    ``applied``: letters that are functions where a parenthesis follows (``d(m)``, ``s(t)``),
    written ``Function("d")(m)``; a letter before a parenthesis holding a comma always is.
    ``complementary``: the letters whose prime is the complementary modulus √(1 − x²).
    ``imaginary_i``: a plain ``i`` is the imaginary unit (DLMF also writes ``\\iunit``).
    ``order``: the variable and the point of every O-term, ``("k", "1")``; without it an
    O-term of one symbol is read at that symbol → 0.
    ``modulus``: the modulus a presentation ``\\operatorname{sn}z`` of a table suppresses.
    ``operators``: symbols that are differential operators, ``{"D_k": "k"}`` (DLMF's D_k = ∂/∂k).
    ``dimension``: the length n of DLMF's vectors: ``\\mathbf{z}`` is (z_1, …, z_n) and
    ``\\boldsymbol{{1}}`` is (1, …, 1); the letter n is bound to it too.
    ``sequences``: letters whose subscript is an index of a sequence (``c_{n}``, ``Q_{n+1}``),
    written ``Function("c")(n)``.
    """

    letters: Mapping[str, str] = field(default_factory=dict)
    defined: Mapping[str, tuple[tuple[str, ...], str]] = field(default_factory=dict)
    applied: frozenset[str] = frozenset()
    complementary: frozenset[str] = frozenset({"k", "kappa"})
    imaginary_i: bool = True
    order: tuple[str, str] | None = None
    modulus: str = "k"
    operators: Mapping[str, str] = field(default_factory=dict)
    dimension: int | None = None
    sequences: frozenset[str] = frozenset()

    def __post_init__(self):
        if self.dimension is not None and "n" not in self.letters:
            object.__setattr__(self, "letters", {**self.letters, "n": str(self.dimension)})
        object.__setattr__(self, "operators", _frozen(self.operators))
        object.__setattr__(self, "sequences", frozenset(self.sequences))
        object.__setattr__(self, "letters", _frozen(self.letters))
        object.__setattr__(self, "defined", _frozen(self.defined))
        object.__setattr__(self, "applied", frozenset(self.applied))
        object.__setattr__(self, "complementary", frozenset(self.complementary))

    def __hash__(self):
        return hash((tuple(sorted(self.letters.items())), tuple(sorted(self.defined.items())),
                     self.applied, self.complementary, self.imaginary_i, self.order, self.modulus,
                     tuple(sorted(self.operators.items())), self.dimension, self.sequences))
