"""The catalog: every equation as it was printed, read from ``data/catalog/<source>/*.toml``.

Each entry keeps the printed LaTeX verbatim and a sympy transcription of exactly what is
printed, typos included (see ``data/catalog/FORMAT.md``).  The transcriptions are parsed
lazily; a malformed file raises :class:`CatalogError` with the file and the entry.
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass, field
from functools import cached_property, lru_cache
from importlib import resources
from pathlib import Path

import sympy as sp

from quasicentral.notation import symbols as S

SOURCES = {
    "brepta1953": 'R. Brepta (1953), "Pohyb bodu v odporujícím prostředí — quasicentrální pohyb"',
    "pendulum": "Přesné řešení matematického kyvadla (exact period of the simple pendulum), eqs. (49)–(66)",
}


class CatalogError(ValueError):
    """A catalog or errata file that cannot be read as specified."""


@dataclass(frozen=True)
class Entry:
    id: str
    source: str
    section: str
    name: str
    latex: str
    printed_text: str
    number: str | None = None
    dims_text: tuple[tuple[str, str], ...] = ()
    note: str = ""
    file: str = ""
    order: int = 0

    @cached_property
    def printed(self) -> sp.Basic:
        """The transcription, parsed: an ``Eq``, a bare expression, or a ``Tuple`` of them."""
        return parse_transcription(self.printed_text, f"{self.file}: {self.id}")

    @cached_property
    def dims(self) -> dict[sp.Basic, sp.Expr]:
        out = dict(S.DIMS)
        for name, text in self.dims_text:
            out[symbol_named(name)] = S.parse_dim(text)
        return out

    def relations(self) -> list[sp.Basic]:
        p = self.printed
        return list(p) if isinstance(p, (sp.Tuple, list, tuple)) else [p]


def symbol_named(name: str) -> sp.Basic:
    obj = S.NAMESPACE.get(name)
    if obj is None:
        obj = sp.Symbol(name)
    return obj


def parse_transcription(text: str, where: str) -> sp.Basic:
    try:
        out = S.parse(text)
    except Exception as exc:  # noqa: BLE001 - any parse failure is a malformed catalog
        raise CatalogError(f"{where}: cannot read transcription {text!r}: {exc}") from None
    if isinstance(out, list):
        out = sp.Tuple(*out)
    return out


_REQUIRED = ("id", "name", "latex", "printed")
_KNOWN = set(_REQUIRED) | {"number", "dims", "note"}


def _catalog_root() -> Path:
    return Path(str(resources.files("quasicentral") / "data" / "catalog"))


def load_file(path: Path, order0: int = 0) -> list[Entry]:
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, tomllib.TOMLDecodeError) as exc:
        raise CatalogError(f"{path.name}: {exc}") from None
    for key in ("source", "section"):
        if key not in data:
            raise CatalogError(f"{path.name}: missing top-level key '{key}'")
    if data["source"] not in SOURCES:
        raise CatalogError(f"{path.name}: unknown source {data['source']!r}")
    entries = []
    for i, raw in enumerate(data.get("equation", [])):
        missing = [k for k in _REQUIRED if k not in raw]
        if missing:
            raise CatalogError(f"{path.name}: equation #{i + 1} lacks {', '.join(missing)}")
        unknown = set(raw) - _KNOWN
        if unknown:
            raise CatalogError(f"{path.name}: {raw['id']}: unknown key(s) {', '.join(sorted(unknown))}")
        if not raw["id"].startswith(data["source"] + ":"):
            raise CatalogError(f"{path.name}: id {raw['id']!r} does not start with {data['source']}:")
        entries.append(Entry(
            id=raw["id"], source=data["source"], section=str(data["section"]), name=raw["name"],
            latex=raw["latex"].strip(), printed_text=raw["printed"].strip(),
            number=str(raw["number"]) if "number" in raw else None,
            dims_text=tuple(sorted((str(a), str(b)) for a, b in raw.get("dims", {}).items())),
            note=raw.get("note", "").strip(), file=path.name, order=order0 + i,
        ))
    return entries


@lru_cache(maxsize=None)
def load(root: str | None = None) -> dict[str, Entry]:
    """All entries of all sources, in the texts' order; duplicate ids are refused."""
    base = Path(root) if root else _catalog_root()
    out: dict[str, Entry] = {}
    for source in SOURCES:
        for path in sorted((base / source).glob("*.toml")):
            for e in load_file(path, order0=len(out)):
                if e.id in out:
                    raise CatalogError(f"{path.name}: duplicate id {e.id!r}")
                out[e.id] = e
    return out


def entries(source: str | None = None) -> list[Entry]:
    return [e for e in load().values() if source is None or e.source == source]


def get(eid: str) -> Entry:
    cat = load()
    if eid not in cat:
        raise KeyError(f"unknown equation id {eid!r}")
    return cat[eid]
