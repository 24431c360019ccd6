"""Errata and cleared suspects: the toolkit's findings, kept as records and tested both ways.

A text's ``errata/*.toml`` files hold, for each erratum, the corrected transcription (which
must verify) and its kind; the printed form must be refuted.  Every erratum names its *root
cause(s)* (``[[cause]]`` tables: ``id``, ``title``, ``kind``, ``note``, and their wording in
other languages, ``title_<lang>``, ``note_<lang>``; ids unique across a text): one fault that
reaches many displays (a range of validity) is one cause, and a display with two faults names
both (``cause = ["a", "b"]``).

Numbers never appear in a note as literals: a note quotes its witness through placeholders
(``{witness}``, ``{witness.printed}``, ``{witness.corrected}``, ``{witness.parameters.NAME}``,
``{witness.relative_difference}``), filled from the witness of the current run, so a note
cannot drift from the point it describes.  A *cleared* record names a suspicion that the
checker settled in the text's favour (on the ``branch`` the text states, where it names one):
the printed form must verify — or, where the entry is an erratum for another reason, its
correction (which keeps the suspected detail as printed) must verify.  If an expectation
fails, verification reports the entry as unexpected.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from enum import Enum
from functools import cached_property
from pathlib import Path
from types import MappingProxyType

import sympy as sp

from quasicentral.engine.catalog import (CatalogError, Entry, locate, parse_transcription, read_toml,
                                         transcription_line, where)
from quasicentral.notation.symbols import SymbolError, SymbolTable


class Kind(str, Enum):
    """The kinds of errata."""

    SIGN = "sign"
    EXPONENT = "exponent"
    WRONG_VARIABLE = "wrong variable"
    MISSING_FACTOR = "missing factor"
    LIMITS = "limits of integration"
    RANGE = "range of validity"
    OCR = "OCR glyph"
    DERIVATIVE_ORDER = "derivative order"
    PARENTHESIS = "parenthesis"
    COEFFICIENT = "coefficient"
    ROUNDING = "rounding"  # a printed decimal that the exact value does not round to


KINDS = tuple(k.value for k in Kind)


def _language_keys(raw: dict, base: str) -> dict[str, str]:
    """``base`` and ``base_<lang>`` of a table: the wording per language ('' for the text's own)."""
    out = {}
    for key, value in raw.items():
        if key == base:
            out[""] = value
        elif key.startswith(base + "_") and re.fullmatch(r"[a-z]{2}", key[len(base) + 1:]):
            out[key[len(base) + 1:]] = value
    return out


@dataclass(frozen=True)
class Cause:
    """One root cause: a fault of the text that may reach several displays.  ``titles`` and
    ``notes`` hold the wording per language ('' is the wording written without a language
    suffix, in English by convention of the format)."""

    id: str
    source: str
    kind: Kind
    order: int = 0  # its place among the text's causes, as the records declare them
    titles: MappingProxyType = field(default_factory=lambda: MappingProxyType({}))
    notes: MappingProxyType = field(default_factory=lambda: MappingProxyType({}))

    @property
    def title(self) -> str:
        return self.titles.get("", "")

    @property
    def note(self) -> str:
        return self.notes.get("", "")

    @property
    def title_cs(self) -> str:
        return self.titles.get("cs", "")

    @property
    def note_cs(self) -> str:
        return self.notes.get("cs", "")

    def title_in(self, lang: str) -> str:
        """The title in ``lang`` ('' where the records have none in it)."""
        return self.titles.get(lang, "") or (self.titles.get("", "") if lang == "en" else "")

    def note_in(self, lang: str) -> str:
        return self.notes.get(lang, "") or (self.notes.get("", "") if lang == "en" else "")


@dataclass(frozen=True)
class Erratum:
    id: str
    kind: Kind
    corrected_text: str
    corrected_latex: str
    notes: MappingProxyType
    causes: tuple[str, ...] = ()
    file: str = ""
    symbols: SymbolTable | None = field(default=None, compare=False, repr=False)

    @property
    def note(self) -> str:
        return self.notes.get("", "")

    def note_in(self, lang: str) -> str:
        return self.notes.get(lang, "") or (self.notes.get("", "") if lang == "en" else "")

    path: str = ""  # the errata file's full path, for messages

    @cached_property
    def corrected(self) -> sp.Basic:
        first = self.corrected_text.strip().splitlines()[0] if self.corrected_text.strip() else None
        here = where(Path(self.path), first) if self.path and first else self.file
        return parse_transcription(self.corrected_text, self.symbols, f"{here}: {self.id}: corrected")

    def relations(self) -> list[sp.Basic]:
        return relations_of(self.corrected)


@dataclass(frozen=True)
class Cleared:
    id: str
    suspicion: str
    notes: MappingProxyType
    branch: str = ""  # the branch or range the text states, on which the suspect holds
    suspicions: MappingProxyType = field(default_factory=lambda: MappingProxyType({}))

    @property
    def note(self) -> str:
        return self.notes.get("", "")

    def note_in(self, lang: str) -> str:
        return self.notes.get(lang, "") or (self.notes.get("", "") if lang == "en" else "")

    def suspicion_in(self, lang: str) -> str:
        return self.suspicions.get(lang, "") or (self.suspicion if lang == "en" else "")


def relations_of(obj) -> list[sp.Basic]:
    """A transcription's relations: a system (Tuple, list) as its members, one relation alone."""
    return list(obj) if isinstance(obj, (sp.Tuple, list, tuple)) else [obj]


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


def _tables(data: dict, key: str, p: Path) -> list[dict]:
    value = data.get(key, [])
    if not isinstance(value, list) or not all(isinstance(v, dict) for v in value):
        raise CatalogError(f"{locate(p, key)}: write each {key} as a [[{key}]] table (double brackets)")
    return value


#: the keys each table of an errata file may set (and their wording in another language: KEY_<lang>)
_ALLOWED = MappingProxyType({"cause": {"id", "title", "kind", "note"},
            "erratum": {"id", "kind", "cause", "corrected", "corrected_latex", "note"},
            "cleared": {"id", "suspicion", "note", "branch"}})


def _check_keys(raw: dict, table: str, p: Path, i: int, what: str) -> None:
    """Unknown keys are refused, and the wording keys are strings (naming the key's line)."""
    for key, value in raw.items():
        base = key.rsplit("_", 1)[0] if re.fullmatch(r".+_[a-z]{2}", key) else key
        if key not in _ALLOWED[table] and not (base in ("title", "note", "suspicion") and base in _ALLOWED[table]):
            raise CatalogError(f"{locate(p, table, i, key)}: {what}: unknown key {key!r} "
                               f"(a [[{table}]] holds {', '.join(sorted(_ALLOWED[table]))})")
        if key != "cause" and not isinstance(value, str):
            raise CatalogError(f"{locate(p, table, i, key)}: {what}: {key} is a string")


_CAUSE_KEYS = ("id", "title", "kind", "note")
_ERRATUM_KEYS = ("id", "kind", "cause", "corrected", "corrected_latex", "note")


def _kind(raw: dict, here: str, what: str) -> Kind:
    try:
        return Kind(raw["kind"])
    except ValueError:
        raise CatalogError(f"{here}: {what}: unknown kind {raw['kind']!r} (one of: {', '.join(KINDS)})") from None


def _load_file(p: Path, errata: dict, cleared: dict, causes: dict, catalog: dict[str, Entry], table: SymbolTable,
               text_id: str) -> None:
    data = read_toml(p)
    unknown = set(data) - {"cause", "erratum", "cleared"}
    if unknown:
        raise CatalogError(f"{locate(p, sorted(unknown)[0])}: unknown key(s) {', '.join(sorted(unknown))} "
                           "(an errata file holds [[cause]], [[erratum]] and [[cleared]] tables)")
    for i, raw in enumerate(_tables(data, "cause", p)):
        here = locate(p, "cause", i)
        missing = [k for k in _CAUSE_KEYS if k not in raw]
        if missing:
            raise CatalogError(f"{here}: cause {raw.get('id', '?')} lacks {', '.join(missing)}")
        _check_keys(raw, "cause", p, i, f"cause {raw.get('id')}")
        kind = _kind(raw, here, f"cause {raw['id']}")
        if raw["id"] in causes:
            raise CatalogError(f"{here}: duplicate cause {raw['id']!r}")
        causes[raw["id"]] = Cause(raw["id"], text_id, kind, len(causes),
                                  MappingProxyType({k: v.strip() for k, v in _language_keys(raw, "title").items()}),
                                  MappingProxyType({k: v.strip() for k, v in _language_keys(raw, "note").items()}))
    for i, raw in enumerate(_tables(data, "erratum", p)):
        _erratum(raw, p, i, errata, cleared, catalog, table)
    for i, raw in enumerate(_tables(data, "cleared", p)):
        _cleared(raw, p, i, cleared, catalog, table)


def _erratum(raw: dict, p: Path, i: int, errata: dict, cleared: dict, catalog: dict, table: SymbolTable) -> None:
    here = locate(p, "erratum", i)
    missing = [k for k in _ERRATUM_KEYS if k not in raw]
    if missing:
        raise CatalogError(f"{here}: erratum {raw.get('id', '?')} lacks {', '.join(missing)}")
    _check_keys(raw, "erratum", p, i, f"erratum {raw.get('id')}")
    if raw["id"] not in catalog:
        raise CatalogError(f"{here}: erratum for unknown id {raw['id']!r}")
    kind = _kind(raw, here, raw["id"])
    if raw["id"] in errata:
        raise CatalogError(f"{here}: duplicate erratum {raw['id']!r}")
    cause = raw["cause"]
    if not (isinstance(cause, list) and cause and all(isinstance(c, str) for c in cause)):
        raise CatalogError(f"{here}: {raw['id']}: 'cause' is a non-empty list of cause ids")
    try:
        table.check_names(raw["corrected"])
    except SymbolError as exc:
        raise CatalogError(f"{transcription_line(p, i, exc, 'erratum', 'corrected')}: {raw['id']}: corrected: {exc}") from None
    notes = {k: v.strip() for k, v in _language_keys(raw, "note").items()}
    for key, note in notes.items():
        check_placeholders(note, f"{locate(p, 'erratum', i, 'note' + ('_' + key if key else ''))}: {raw['id']}", table)
    errata[raw["id"]] = Erratum(raw["id"], kind, raw["corrected"].strip(), raw["corrected_latex"].strip(),
                                MappingProxyType(notes), tuple(cause), p.name, table, str(p))


def _cleared(raw: dict, p: Path, i: int, cleared: dict, catalog: dict, table: SymbolTable) -> None:
    here = locate(p, "cleared", i)
    if raw.get("id") not in catalog:
        raise CatalogError(f"{here}: cleared suspect for unknown id {raw.get('id')!r}")
    if raw["id"] in cleared:
        raise CatalogError(f"{here}: {raw['id']!r} cleared twice")
    if "suspicion" not in raw or "note" not in raw:
        raise CatalogError(f"{here}: cleared {raw['id']} needs 'suspicion' and 'note'")
    _check_keys(raw, "cleared", p, i, f"cleared {raw['id']}")
    notes = {k: v.strip() for k, v in _language_keys(raw, "note").items()}
    for key, note in notes.items():
        check_placeholders(note, f"{locate(p, 'cleared', i, 'note' + ('_' + key if key else ''))}: {raw['id']}", table)
    suspicions = {k: v.strip() for k, v in _language_keys(raw, "suspicion").items()}
    cleared[raw["id"]] = Cleared(raw["id"], raw["suspicion"].strip(), MappingProxyType(notes),
                                 raw.get("branch", "").strip(), MappingProxyType(suspicions))


# --- notes quote their witness --------------------------------------------------------------
_PLACEHOLDER = re.compile(r"\{witness(?:\.(printed|corrected|relative_difference|quantity|parameters\.[A-Za-z_0-9]+))?\}")


def check_placeholders(note: str, where: str, table: SymbolTable | None = None) -> None:
    """Refuse a placeholder the witness cannot fill (a misspelt field, a parameter that is not
    a declared symbol)."""
    for m in re.finditer(r"\{[^{}]*\}", note):
        if not m.group(0).startswith("{witness"):
            continue
        got = _PLACEHOLDER.fullmatch(m.group(0))
        if not got:
            raise CatalogError(f"{where}: unknown placeholder {m.group(0)}")
        field_ = got.group(1) or ""
        if field_.startswith("parameters.") and table is not None and field_.split(".", 1)[1] not in table:
            raise CatalogError(f"{where}: placeholder {m.group(0)}: {field_.split('.', 1)[1]} is not a declared symbol")
