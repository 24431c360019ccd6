"""Errata and cleared suspects: the toolkit's findings, kept as records and tested both ways.

``data/errata/*.toml`` (one file per section) hold, for each erratum, the corrected transcription (which must verify)
and its kind; the printed form must be refuted.  Every erratum names its *root cause(s)*
(``[[cause]]`` tables: ``id``, ``title``, ``title_cs``, ``kind``, ``note``, ``note_cs``; ids
unique across a text): one fault that reaches many displays (section 5's ζ = cos Ωt range) is
one cause, and a display with two faults names both (``cause = ["a", "b"]``).

Numbers never appear in a note as literals: a note quotes its witness through placeholders
(``{witness}``, ``{witness.printed}``, ``{witness.corrected}``, ``{witness.parameters.NAME}``,
``{witness.relative_difference}``), filled by :func:`render_note` from the witness of the
current run, so a note cannot drift from the point it describes.  A *cleared* record names a suspicion that
the checker settled in the paper's favour: the printed form must verify — or, where the
entry is an erratum for another reason, its correction (which keeps the suspected detail as
printed) must verify.  If an expectation fails, verification reports the entry as unexpected.
"""

from __future__ import annotations

import re
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
class Cause:
    """One root cause: a fault of the text that may reach several displays."""

    id: str
    source: str
    title: str
    title_cs: str
    kind: str
    note: str
    note_cs: str


@dataclass(frozen=True)
class Erratum:
    id: str
    kind: str
    corrected_text: str
    corrected_latex: str
    note: str
    causes: tuple[str, ...] = ()

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
    branch: str = ""  # the branch or range the text states, on which the suspect holds


def _root() -> Path:
    return Path(str(resources.files("quasicentral") / "data" / "errata"))


@lru_cache(maxsize=None)
def load(root: str | None = None) -> tuple[dict[str, Erratum], dict[str, Cleared]]:
    errata: dict[str, Erratum] = {}
    cleared: dict[str, Cleared] = {}
    causes: dict[str, Cause] = {}
    for p in sorted((Path(root) if root else _root()).glob("*.toml")):
        _load_file(p, errata, cleared, causes)
    catalog = load_catalog()
    for rec in errata.values():
        source = catalog[rec.id].source
        for c in rec.causes:
            if c not in causes or causes[c].source != source:
                raise CatalogError(f"{rec.id}: unknown cause {c!r} (a cause of the same text)")
    return errata, cleared


@lru_cache(maxsize=None)
def load_causes(root: str | None = None) -> dict[str, Cause]:
    """Every root cause, keyed by id, in file order (ids are unique across a text)."""
    causes: dict[str, Cause] = {}
    for p in sorted((Path(root) if root else _root()).glob("*.toml")):
        _load_file(p, {}, {}, causes, causes_only=True)
    return causes


def displays_of(cause_id: str, root: str | None = None) -> list[str]:
    """The erratum ids a cause affects, in catalog order."""
    errs, _ = load(root)
    order = {eid: i for i, eid in enumerate(load_catalog())}
    return sorted((e.id for e in errs.values() if cause_id in e.causes), key=lambda i: order.get(i, 0))


_CAUSE_KEYS = ("id", "title", "title_cs", "kind", "note", "note_cs")


def _load_file(p: Path, errata: dict, cleared: dict, causes: dict, causes_only: bool = False) -> None:
    try:
        data = tomllib.loads(p.read_text(encoding="utf-8"))
    except (OSError, tomllib.TOMLDecodeError) as exc:
        raise CatalogError(f"{p.name}: {exc}") from None
    catalog = load_catalog()
    source = _source_of(data, catalog, p)
    for raw in data.get("cause", []):
        missing = [k for k in _CAUSE_KEYS if k not in raw]
        if missing:
            raise CatalogError(f"{p.name}: cause {raw.get('id', '?')} lacks {', '.join(missing)}")
        if raw["kind"] not in KINDS:
            raise CatalogError(f"{p.name}: cause {raw['id']}: unknown kind {raw['kind']!r}")
        if raw["id"] in causes:
            raise CatalogError(f"{p.name}: duplicate cause {raw['id']!r}")
        causes[raw["id"]] = Cause(raw["id"], source, raw["title"].strip(), raw["title_cs"].strip(), raw["kind"],
                                  raw["note"].strip(), raw["note_cs"].strip())
    if causes_only:
        return
    for raw in data.get("erratum", []):
        missing = [k for k in ("id", "kind", "cause", "corrected", "corrected_latex", "note") if k not in raw]
        if missing:
            raise CatalogError(f"{p.name}: erratum {raw.get('id', '?')} lacks {', '.join(missing)}")
        if raw["id"] not in catalog:
            raise CatalogError(f"{p.name}: erratum for unknown id {raw['id']!r}")
        if raw["kind"] not in KINDS:
            raise CatalogError(f"{p.name}: {raw['id']}: unknown kind {raw['kind']!r}")
        if raw["id"] in errata or raw["id"] in cleared:
            raise CatalogError(f"{p.name}: duplicate erratum {raw['id']!r}")
        cause = raw["cause"]
        if not (isinstance(cause, list) and cause and all(isinstance(c, str) for c in cause)):
            raise CatalogError(f"{p.name}: {raw['id']}: 'cause' is a non-empty list of cause ids")
        _check_placeholders(raw["note"], f"{p.name}: {raw['id']}")
        errata[raw["id"]] = Erratum(raw["id"], raw["kind"], raw["corrected"].strip(),
                                    raw["corrected_latex"].strip(), raw["note"].strip(), tuple(cause))
    for raw in data.get("cleared", []):
        if raw.get("id") not in catalog:
            raise CatalogError(f"{p.name}: cleared suspect for unknown id {raw.get('id')!r}")
        if raw["id"] in cleared:
            raise CatalogError(f"{p.name}: {raw['id']!r} cleared twice")
        if "suspicion" not in raw or "note" not in raw:
            raise CatalogError(f"{p.name}: cleared {raw['id']} needs 'suspicion' and 'note'")
        cleared[raw["id"]] = Cleared(raw["id"], raw["suspicion"].strip(), raw["note"].strip(),
                                     raw.get("branch", "").strip())


def _source_of(data: dict, catalog: dict, p: Path) -> str:
    ids = [r.get("id") for r in data.get("erratum", []) + data.get("cleared", [])]
    sources = {catalog[i].source for i in ids if i in catalog}
    if len(sources) > 1:
        raise CatalogError(f"{p.name}: records of several texts in one file")
    return sources.pop() if sources else p.stem.split("-")[0]


# --- notes quote their witness --------------------------------------------------------------
_PLACEHOLDER = re.compile(r"\{witness(?:\.(printed|corrected|relative_difference|quantity|parameters\.[A-Za-z_0-9]+))?\}")


def _check_placeholders(note: str, where: str) -> None:
    for m in re.finditer(r"\{[^{}]*\}", note):
        if m.group(0).startswith("{witness") and not _PLACEHOLDER.fullmatch(m.group(0)):
            raise CatalogError(f"{where}: unknown placeholder {m.group(0)}")


def witness_parameters_text(w) -> dict[str, str]:
    """The witness's exact parameters as short decimals (8 significant digits) for prose."""
    out = {}
    for k, v in w.parameters.items():
        val = sp.sympify(v)
        out[k] = v if val.is_Rational and val.q == 1 else sp.sstr(sp.N(val, 8))
    return out


def witness_sentence(w) -> str:
    """The witness as one sentence (English), from its record only."""
    if w is None:
        return "no numeric witness (the printed relation is dimensionally inconsistent)"
    at = ", ".join(f"{k} = {v}" for k, v in witness_parameters_text(w).items())
    cert = "certified" if w.certified else "not certified"
    return (f"at {at} the printed {w.quantity} is {w.printed}, the derived {w.corrected} "
            f"(relative difference {w.relative_difference}; {cert})")


def render_note(note: str, w) -> str:
    """``note`` with its ``{witness…}`` placeholders filled from the witness ``w``."""
    def fill(m: re.Match) -> str:
        field = m.group(1)
        if field is None:
            return witness_sentence(w)
        if w is None:
            return "—"
        if field.startswith("parameters."):
            return witness_parameters_text(w)[field.split(".", 1)[1]]
        return str(getattr(w, field))

    return _PLACEHOLDER.sub(fill, note)
