"""Errata and cleared suspects: the toolkit's findings, kept as records and tested both ways.

``data/errata/*.toml`` (one file per section) hold, for each erratum, the corrected transcription (which must verify)
and its kind; the printed form must be refuted.  A *cleared* record names a suspicion that
the checker settled in the paper's favour: the printed form must verify — or, where the
entry is an erratum for another reason, its correction (which keeps the suspected detail as
printed) must verify.  If an expectation fails, verification reports the entry as unexpected.
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass
from functools import cached_property, lru_cache
from importlib import resources
from pathlib import Path

import sympy as sp

from quasicentral.engine.catalog import CatalogError, load as load_catalog, parse_transcription

KINDS = ("sign", "exponent", "wrong variable", "missing factor", "limits of integration",
         "range of validity", "OCR glyph", "derivative order", "parenthesis", "coefficient")


@dataclass(frozen=True)
class Erratum:
    id: str
    kind: str
    corrected_text: str
    corrected_latex: str
    note: str

    @cached_property
    def corrected(self) -> sp.Basic:
        return parse_transcription(self.corrected_text, f"errata.toml: {self.id}")

    def relations(self) -> list[sp.Basic]:
        c = self.corrected
        return list(c) if isinstance(c, (sp.Tuple, list, tuple)) else [c]


@dataclass(frozen=True)
class Cleared:
    id: str
    suspicion: str
    note: str


def _root() -> Path:
    return Path(str(resources.files("quasicentral") / "data" / "errata"))


@lru_cache(maxsize=None)
def load(root: str | None = None) -> tuple[dict[str, Erratum], dict[str, Cleared]]:
    errata: dict[str, Erratum] = {}
    cleared: dict[str, Cleared] = {}
    for p in sorted((Path(root) if root else _root()).glob("*.toml")):
        _load_file(p, errata, cleared)
    return errata, cleared


def _load_file(p: Path, errata: dict, cleared: dict) -> None:
    try:
        data = tomllib.loads(p.read_text(encoding="utf-8"))
    except (OSError, tomllib.TOMLDecodeError) as exc:
        raise CatalogError(f"{p.name}: {exc}") from None
    catalog = load_catalog()
    for raw in data.get("erratum", []):
        missing = [k for k in ("id", "kind", "corrected", "corrected_latex", "note") if k not in raw]
        if missing:
            raise CatalogError(f"{p.name}: erratum {raw.get('id', '?')} lacks {', '.join(missing)}")
        if raw["id"] not in catalog:
            raise CatalogError(f"{p.name}: erratum for unknown id {raw['id']!r}")
        if raw["kind"] not in KINDS:
            raise CatalogError(f"{p.name}: {raw['id']}: unknown kind {raw['kind']!r}")
        if raw["id"] in errata or raw["id"] in cleared:
            raise CatalogError(f"{p.name}: duplicate erratum {raw['id']!r}")
        errata[raw["id"]] = Erratum(raw["id"], raw["kind"], raw["corrected"].strip(),
                                    raw["corrected_latex"].strip(), raw["note"].strip())
    for raw in data.get("cleared", []):
        if raw.get("id") not in catalog:
            raise CatalogError(f"{p.name}: cleared suspect for unknown id {raw.get('id')!r}")
        if raw["id"] in cleared:
            raise CatalogError(f"{p.name}: {raw['id']!r} cleared twice")
        if "suspicion" not in raw or "note" not in raw:
            raise CatalogError(f"{p.name}: cleared {raw['id']} needs 'suspicion' and 'note'")
        cleared[raw["id"]] = Cleared(raw["id"], raw["suspicion"].strip(), raw["note"].strip())
