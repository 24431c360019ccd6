"""Identity texts: entries checked as the relations they print, on their stated constraints,
with no derivation module at all (a formula collection: DLMF's chapters, a table of integrals).

An entry of such a text (``check = "identity"`` in its ``text.toml``) is self-contained: left
= right, a chain a = b = c (a list of equations), an inequality, a special value, a series, an
integral representation, a derivative.  Its ``constraints`` narrow where it is sampled; its
``real`` symbols are drawn on the real line.  A derivation of the text's own may still settle
an entry (then it is used instead).
"""

from __future__ import annotations

from quasicentral.engine.catalog import Entry
from quasicentral.engine.registry import Derivation, Mode
from quasicentral.notation.domain import Domain


def identity_derivation(entry: Entry) -> Derivation:
    """The entry's relation checked as it stands: the empty model of ``mode="substitute"``, on
    the entry's constraints."""
    return Derivation(entry.id, None, Mode.SUBSTITUTE, entry_domain(entry), (), None,
                      "The relation as printed, checked on its stated constraints.", "")


def entry_domain(entry: Entry) -> Domain:
    """The sampling domain an entry's constraints and real symbols make."""
    return Domain.of(constraints=entry.constraints, real=entry.real)
