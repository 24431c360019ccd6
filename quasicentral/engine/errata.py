"""Errata and cleared suspects: the toolkit's findings, kept as records and tested both ways.

A text's ``errata/*.toml`` files hold, for each erratum, the corrected transcription (which
must verify) and its kind; the printed form must be refuted.  Every erratum names its *root
cause(s)* (``[[cause]]`` tables: ``id``, ``title``, ``title_cs``, ``kind``, ``note``,
``note_cs``; ids unique across a text): one fault that reaches many displays (a range of
validity) is one cause, and a display with two faults names both (``cause = ["a", "b"]``).

Numbers never appear in a note as literals: a note quotes its witness through placeholders
(``{witness}``, ``{witness.printed}``, ``{witness.corrected}``, ``{witness.parameters.NAME}``,
``{witness.relative_difference}``), filled by :func:`render_note` from the witness of the
current run, so a note cannot drift from the point it describes.  A *cleared* record names a
suspicion that the checker settled in the text's favour (on the ``branch`` the text states,
where it names one): the printed form must verify — or, where the entry is an erratum for
another reason, its correction (which keeps the suspected detail as printed) must verify.  If
an expectation fails, verification reports the entry as unexpected.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import sympy as sp

from quasicentral.engine.catalog import CatalogError, Entry, parse_transcription, read_toml, where
from quasicentral.notation.symbols import SymbolError, SymbolTable

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
    branch: str = ""  # the branch or range the text states, on which the suspect holds


@dataclass(frozen=True)
class Records:
    """A text's errata, cleared suspects and root causes (each keyed by id, in file order)."""

    errata: dict[str, Erratum]
    cleared: dict[str, Cleared]
    causes: dict[str, Cause]

    def displays_of(self, cause_id: str) -> list[str]:
        """The erratum ids a cause affects, in the text's order."""
        return [e.id for e in self.errata.values() if cause_id in e.causes]


def load(paths: list[Path], catalog: dict[str, Entry], table: SymbolTable, text_id: str) -> Records:
    """The records of one text (its ``errata/*.toml`` files, in order); every erratum names
    at least one of the text's causes."""
    errata: dict[str, Erratum] = {}
    cleared: dict[str, Cleared] = {}
    causes: dict[str, Cause] = {}
    for p in paths:
        _load_file(p, errata, cleared, causes, catalog, table, text_id)
    for rec in errata.values():
        for c in rec.causes:
            if c not in causes:
                raise CatalogError(f"{rec.file}: {rec.id}: unknown cause {c!r} (declare it in a [[cause]] table)")
    order = {eid: i for i, eid in enumerate(catalog)}
    errata = dict(sorted(errata.items(), key=lambda kv: order[kv[0]]))
    return Records(errata, cleared, causes)


_CAUSE_KEYS = ("id", "title", "title_cs", "kind", "note", "note_cs")


def _load_file(p: Path, errata: dict, cleared: dict, causes: dict, catalog: dict[str, Entry], table: SymbolTable,
               text_id: str) -> None:
    data = read_toml(p)
    for raw in data.get("cause", []):
        here = where(p, f'"{raw["id"]}"') if isinstance(raw.get("id"), str) else str(p)
        missing = [k for k in _CAUSE_KEYS if k not in raw]
        if missing:
            raise CatalogError(f"{here}: cause {raw.get('id', '?')} lacks {', '.join(missing)}")
        if raw["kind"] not in KINDS:
            raise CatalogError(f"{here}: cause {raw['id']}: unknown kind {raw['kind']!r} (one of: {', '.join(KINDS)})")
        if raw["id"] in causes:
            raise CatalogError(f"{here}: duplicate cause {raw['id']!r}")
        causes[raw["id"]] = Cause(raw["id"], text_id, raw["title"].strip(), raw["title_cs"].strip(), raw["kind"],
                                  raw["note"].strip(), raw["note_cs"].strip())
    for raw in data.get("erratum", []):
        here = where(p, f'"{raw["id"]}"') if isinstance(raw.get("id"), str) else str(p)
        missing = [k for k in ("id", "kind", "cause", "corrected", "corrected_latex", "note") if k not in raw]
        if missing:
            raise CatalogError(f"{here}: erratum {raw.get('id', '?')} lacks {', '.join(missing)}")
        if raw["id"] not in catalog:
            raise CatalogError(f"{here}: erratum for unknown id {raw['id']!r}")
        if raw["kind"] not in KINDS:
            raise CatalogError(f"{here}: {raw['id']}: unknown kind {raw['kind']!r} (one of: {', '.join(KINDS)})")
        if raw["id"] in errata or raw["id"] in cleared:
            raise CatalogError(f"{here}: duplicate erratum {raw['id']!r}")
        cause = raw["cause"]
        if not (isinstance(cause, list) and cause and all(isinstance(c, str) for c in cause)):
            raise CatalogError(f"{here}: {raw['id']}: 'cause' is a non-empty list of cause ids")
        try:
            table.check_names(raw["corrected"])
        except SymbolError as exc:
            raise CatalogError(f"{here}: {raw['id']}: corrected: {exc}") from None
        _check_placeholders(raw["note"], f"{here}: {raw['id']}")
        errata[raw["id"]] = Erratum(raw["id"], raw["kind"], raw["corrected"].strip(), raw["corrected_latex"].strip(),
                                    raw["note"].strip(), tuple(cause), p.name, table)
    for raw in data.get("cleared", []):
        here = where(p, f'"{raw["id"]}"') if isinstance(raw.get("id"), str) else str(p)
        if raw.get("id") not in catalog:
            raise CatalogError(f"{here}: cleared suspect for unknown id {raw.get('id')!r}")
        if raw["id"] in cleared:
            raise CatalogError(f"{here}: {raw['id']!r} cleared twice")
        if "suspicion" not in raw or "note" not in raw:
            raise CatalogError(f"{here}: cleared {raw['id']} needs 'suspicion' and 'note'")
        cleared[raw["id"]] = Cleared(raw["id"], raw["suspicion"].strip(), raw["note"].strip(),
                                     raw.get("branch", "").strip())


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
