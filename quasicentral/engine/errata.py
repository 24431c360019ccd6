"""Errata and cleared suspects: the toolkit's findings, kept as records and tested both ways.

A text's ``errata/*.toml`` files hold, for each erratum, the corrected transcription (which must verify)
and its kind; the printed form must be refuted.  A *cleared* record names a suspicion that
the checker settled in the paper's favour: the printed form must verify — or, where the
entry is an erratum for another reason, its correction (which keeps the suspected detail as
printed) must verify.  If an expectation fails, verification reports the entry as unexpected.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import sympy as sp

from quasicentral.engine.catalog import CatalogError, Entry, parse_transcription, read_toml, where
from quasicentral.notation.symbols import SymbolError, SymbolTable

KINDS = ("sign", "exponent", "wrong variable", "missing factor", "limits of integration",
         "range of validity", "OCR glyph", "derivative order", "parenthesis", "coefficient")


@dataclass(frozen=True)
class Erratum:
    id: str
    kind: str
    corrected_text: str
    corrected_latex: str
    note: str
    file: str = ""
    symbols: SymbolTable | None = field(default=None, compare=False, repr=False)

    @cached_property
    def corrected(self) -> sp.Basic:
        return parse_transcription(self.corrected_text, self.symbols, f"{self.file}: {self.id}")

    def relations(self) -> list[sp.Basic]:
        c = self.corrected
        return list(c) if isinstance(c, (sp.Tuple, list, tuple)) else [c]


@dataclass(frozen=True)
class Cleared:
    id: str
    suspicion: str
    note: str


def load(paths: list[Path], catalog: dict[str, Entry], table: SymbolTable) -> tuple[dict[str, Erratum], dict[str, Cleared]]:
    """The errata and cleared suspects of one text (its ``errata/*.toml`` files, in order)."""
    errata: dict[str, Erratum] = {}
    cleared: dict[str, Cleared] = {}
    for p in paths:
        _load_file(p, errata, cleared, catalog, table)
    return errata, cleared


def _load_file(p: Path, errata: dict, cleared: dict, catalog: dict[str, Entry], table: SymbolTable) -> None:
    data = read_toml(p)
    for raw in data.get("erratum", []):
        here = where(p, f'"{raw["id"]}"') if isinstance(raw.get("id"), str) else str(p)
        missing = [k for k in ("id", "kind", "corrected", "corrected_latex", "note") if k not in raw]
        if missing:
            raise CatalogError(f"{here}: erratum {raw.get('id', '?')} lacks {', '.join(missing)}")
        if raw["id"] not in catalog:
            raise CatalogError(f"{here}: erratum for unknown id {raw['id']!r}")
        if raw["kind"] not in KINDS:
            raise CatalogError(f"{here}: {raw['id']}: unknown kind {raw['kind']!r} (one of: {', '.join(KINDS)})")
        if raw["id"] in errata or raw["id"] in cleared:
            raise CatalogError(f"{here}: duplicate erratum {raw['id']!r}")
        try:
            table.check_names(raw["corrected"])
        except SymbolError as exc:
            raise CatalogError(f"{here}: {raw['id']}: corrected: {exc}") from None
        errata[raw["id"]] = Erratum(raw["id"], raw["kind"], raw["corrected"].strip(),
                                    raw["corrected_latex"].strip(), raw["note"].strip(), p.name, table)
    for raw in data.get("cleared", []):
        here = where(p, f'"{raw["id"]}"') if isinstance(raw.get("id"), str) else str(p)
        if raw.get("id") not in catalog:
            raise CatalogError(f"{here}: cleared suspect for unknown id {raw.get('id')!r}")
        if raw["id"] in cleared:
            raise CatalogError(f"{here}: {raw['id']!r} cleared twice")
        if "suspicion" not in raw or "note" not in raw:
            raise CatalogError(f"{here}: cleared {raw['id']} needs 'suspicion' and 'note'")
        cleared[raw["id"]] = Cleared(raw["id"], raw["suspicion"].strip(), raw["note"].strip())
