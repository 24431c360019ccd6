"""The catalog of a text: every equation as it was printed, read from ``<text>/catalog/*.toml``.

Each entry keeps the printed LaTeX verbatim and a sympy transcription of exactly what is
printed, typos included (see ``derivations/FORMAT.md``), read in the text's symbol table.  The
transcriptions are parsed lazily, their names checked at load; a malformed file raises
:class:`CatalogError` naming the file and line or the entry.
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import sympy as sp

from quasicentral.notation.symbols import SymbolError, SymbolTable, parse_dim


class CatalogError(ValueError):
    """A text's file that cannot be read as specified (the message names the file and line or
    the entry)."""


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
    symbols: SymbolTable | None = field(default=None, compare=False, repr=False)

    @property
    def text(self) -> str:
        """The id of the text the entry belongs to."""
        return self.source

    @cached_property
    def printed(self) -> sp.Basic:
        """The transcription, parsed: an ``Eq``, a bare expression, or a ``Tuple`` of them."""
        return parse_transcription(self.printed_text, self.symbols, f"{self.file}: {self.id}")

    @cached_property
    def dims(self) -> dict[sp.Basic, sp.Expr]:
        out = dict(self.symbols.dims)
        for name, text in self.dims_text:
            out[symbol_named(self.symbols, name)] = parse_dim(text)
        return out

    def relations(self) -> list[sp.Basic]:
        p = self.printed
        return list(p) if isinstance(p, (sp.Tuple, list, tuple)) else [p]


def symbol_named(table: SymbolTable, name: str) -> sp.Basic:
    """The declared object of ``name``; an undeclared name stands for a symbol of that name
    (a per-entry dimension of, e.g., an integration variable the table does not list)."""
    return table.namespace.get(name) if name in table else sp.Symbol(name)


def parse_transcription(text: str, table: SymbolTable, where: str) -> sp.Basic:
    try:
        out = table.parse(text)
    except Exception as exc:  # noqa: BLE001 - any parse failure is a malformed catalog
        raise CatalogError(f"{where}: cannot read transcription {text!r}: {exc}") from None
    if isinstance(out, list):
        out = sp.Tuple(*out)
    return out


def line_of(path: Path, needle: str) -> int | None:
    """The first line of ``path`` holding ``needle`` (for messages naming file and line)."""
    try:
        for i, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            if needle in line:
                return i
    except OSError:
        return None
    return None


def where(path: Path, needle: str | None = None) -> str:
    line = line_of(path, needle) if needle else None
    return f"{path}:{line}" if line else str(path)


def read_toml(path: Path) -> dict:
    """A text's TOML file; a syntax error names the file and line."""
    try:
        return tomllib.loads(path.read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as exc:
        import re

        m = re.search(r"\(at line (\d+), column (\d+)\)", str(exc))
        msg = re.sub(r"\s*\(at line \d+, column \d+\)", "", str(exc))
        raise CatalogError(f"{path}:{m.group(1)}: {msg}" if m else f"{path}: {msg}") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise CatalogError(f"{path}: cannot read: {getattr(exc, 'strerror', None) or exc}") from None


_REQUIRED = ("id", "name", "latex", "printed")
_KNOWN = set(_REQUIRED) | {"number", "dims", "note"}


def load_file(path: Path, text_id: str, table: SymbolTable, order0: int = 0) -> list[Entry]:
    """The entries of one catalog file of text ``text_id``; names are checked at once."""
    data = read_toml(path)
    if "section" not in data:
        raise CatalogError(f"{path}: missing top-level key 'section'")
    if data.get("source", text_id) != text_id:
        raise CatalogError(f"{where(path, 'source')}: source {data['source']!r} is not this text's id {text_id!r}")
    equations = data.get("equation", [])
    if not isinstance(equations, list):
        raise CatalogError(f"{where(path, 'equation')}: write each entry as [[equation]]")
    entries = []
    for i, raw in enumerate(equations):
        missing = [k for k in _REQUIRED if k not in raw]
        here = where(path, f'"{raw["id"]}"') if isinstance(raw.get("id"), str) else str(path)
        if missing:
            raise CatalogError(f"{here}: equation #{i + 1} lacks {', '.join(missing)}")
        if not all(isinstance(raw[k], str) for k in _REQUIRED):
            raise CatalogError(f"{here}: id, name, latex and printed are strings")
        unknown = set(raw) - _KNOWN
        if unknown:
            raise CatalogError(f"{here}: {raw['id']}: unknown key(s) {', '.join(sorted(unknown))}")
        if not raw["id"].startswith(text_id + ":"):
            raise CatalogError(f"{here}: id {raw['id']!r} does not start with {text_id}:")
        dims = raw.get("dims", {})
        if not isinstance(dims, dict):
            raise CatalogError(f"{here}: {raw['id']}: dims is a table such as {{ A = \"L^2/T\" }}")
        try:
            for text in dims.values():
                parse_dim(str(text))
            table.check_names(raw["printed"])
        except SymbolError as exc:
            raise CatalogError(f"{where(path, raw['printed'].strip().splitlines()[0]) if raw['printed'].strip() else here}: "
                               f"{raw['id']}: {exc}") from None
        entries.append(Entry(
            id=raw["id"], source=text_id, section=str(data["section"]), name=raw["name"],
            latex=raw["latex"].strip(), printed_text=raw["printed"].strip(),
            number=str(raw["number"]) if "number" in raw else None,
            dims_text=tuple(sorted((str(a), str(b)) for a, b in dims.items())),
            note=raw.get("note", "").strip(), file=path.name, order=order0 + i, symbols=table,
        ))
    return entries
