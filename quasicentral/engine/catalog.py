"""The catalog of a text: every equation as it was printed, read from ``<text>/catalog/*.toml``.

Each entry keeps the printed LaTeX verbatim and a sympy transcription of exactly what is
printed, typos included (see ``quasicentral/texts/FORMAT.md``), read in the text's symbol table.  The
transcriptions are parsed lazily, their names checked at load; a malformed file raises
:class:`CatalogError` naming the file and line or the entry.
"""

from __future__ import annotations

import re
import tomllib
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import sympy as sp

from quasicentral.notation.symbols import Approx, SymbolError, SymbolTable
from quasicentral.notation.transcription import decimal_literal, decimal_literals, decimal_places
from quasicentral.notation.units import UnitError, parse_dim


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
    constraints_text: tuple[str, ...] = ()  # the entry's stated constraints (transcription syntax)
    real_names: tuple[str, ...] = ()  # symbols drawn on the real line in this entry
    url: str = ""
    kind: str = ""  # identity | definition | inequality | series | asymptotic | notation ("" = not said)
    semantic: str = ""  # the semantic LaTeX the entry was read from, if any
    approx: str = ""  # a printed rounding of the entry's value ("4.965114")
    rests_on: tuple[str, ...] = ()  # ids of the entries whose definitions hold here too
    defines_names: tuple[str, ...] = ()  # symbols the entry introduces (a definition: notation)
    path: str = ""  # the catalog file's full path, for messages
    names: tuple[tuple[str, str], ...] = ()  # (language, name) from name_<lang>: the heading in that language

    def name_in(self, lang: str) -> str:
        """The entry's short name in ``lang``: its ``name_<lang>``, else in English its ``name``
        (the unsuffixed wording is English, as an erratum's), else '' (the heading is its number)."""
        return dict(self.names).get(lang) or (self.name if lang == "en" else "")

    @cached_property
    def constraints(self) -> tuple:
        """The stated constraints, parsed (sympy relations)."""
        return tuple(parse_transcription(c, self.symbols, f"{self._where(c)}: {self.id}: constraints")
                     for c in self.constraints_text)

    @cached_property
    def defines(self) -> tuple:
        """The symbols the entry introduces: said (``defines``), or an equation of a
        ``kind = "definition"`` entry with a bare symbol on its left that its right does not hold."""
        out = [symbol_named(self.symbols, n) for n in self.defines_names]
        if self.kind == "definition":
            for rel in self.relations():
                if isinstance(rel, sp.Eq) and isinstance(rel.lhs, sp.Symbol) and rel.lhs not in rel.rhs.free_symbols:
                    out.append(rel.lhs)
        return tuple(dict.fromkeys(out))

    @cached_property
    def real(self) -> tuple:
        return tuple(symbol_named(self.symbols, n) for n in self.real_names)

    @cached_property
    def printed(self) -> sp.Basic:
        """The transcription, parsed: an ``Eq``, a bare expression, or a ``Tuple`` of them."""
        return parse_transcription(self.printed_text, self.symbols, f"{self._where(self.printed_text)}: {self.id}")

    def _where(self, text: str) -> str:
        """``file:line`` of the first line of ``text`` in the entry's catalog file."""
        first = text.strip().splitlines()[0] if text.strip() else None
        return where(Path(self.path), first) if self.path and first else (self.path or self.file)

    def validate(self) -> None:
        """Read everything the entry holds (its transcription and constraints), so that a
        mistake is named now, with its file and line."""
        self.printed
        self.constraints
        self.dims

    @cached_property
    def dims(self) -> dict[sp.Basic, sp.Expr]:
        out = dict(self.symbols.dims)
        for name, text in self.dims_text:
            out[symbol_named(self.symbols, name)] = parse_dim(text)
        return out

    @cached_property
    def decimals(self) -> dict:
        """The decimal literals the transcription prints: {exact value: decimal places}."""
        return decimal_literals(self.printed_text)

    def relations(self, roundings: bool = False) -> list[sp.Basic]:
        """The printed relations; a bare expression beside ``approx`` as its printed rounding
        (:class:`~quasicentral.notation.symbols.Approx`), and with ``roundings`` (an identity
        text, where a printed number means what it shows) an equation of an expression and a
        decimal literal too."""
        p = self.printed
        rels = list(p) if isinstance(p, (sp.Tuple, list, tuple)) else [p]
        if self.approx:
            value, places = decimal_literal(self.approx), decimal_places(self.approx)
            rels = [Approx(r, value, places) if isinstance(r, sp.Expr) else r for r in rels]
        if roundings and self.decimals:
            rels = [_as_rounding(r, self.decimals) for r in rels]
        return rels


def _as_rounding(rel, decimals: dict):
    """``Eq(x, 0.685…)`` as the rounding ``Approx(x, 0.685…, places)`` where one side is a printed
    decimal literal (or its negative) and the other is not a bare number."""
    if not isinstance(rel, sp.Eq):
        return rel
    for side, other in ((rel.rhs, rel.lhs), (rel.lhs, rel.rhs)):
        if side.is_Rational and not other.is_Rational:
            places = decimals.get(side, decimals.get(-side))
            if places is not None:
                return Approx(other, side, places)
    return rel


def locate_key(entry: Entry, key: str) -> str:
    """``file:line`` of ``key`` in ``entry``'s table of its catalog file."""
    path = Path(entry.path)
    try:
        data = read_toml(path)
        i = next(i for i, raw in enumerate(data.get("equation", [])) if raw.get("id") == entry.id)
    except (CatalogError, StopIteration):
        return entry.path or entry.file
    return locate(path, "equation", i, key)


def symbol_named(table: SymbolTable, name: str) -> sp.Basic:
    """The declared object of ``name``; an undeclared name stands for a symbol of that name
    (a per-entry dimension of, e.g., an integration variable the table does not list)."""
    return table.namespace.get(name) if name in table else sp.Symbol(name)


def parse_transcription(text: str, table: SymbolTable, where: str) -> sp.Basic:
    try:
        out = table.parse(text)
    except Exception as exc:  # noqa: BLE001 - any parse failure is a malformed catalog
        shown = text if len(text) <= 120 else text[:117] + "..."
        raise CatalogError(f"{where}: cannot read transcription {shown!r}: {exc}") from None
    if isinstance(out, list):
        out = sp.Tuple(*out)
    return out


def _lines(path: Path) -> list[str]:
    try:
        return read_bytes(Path(path)).decode("utf-8", "replace").splitlines()
    except CatalogError:
        return []


def line_of(path: Path, needle: str) -> int | None:
    """The line of ``path`` where the top-level key ``needle`` is set (``needle = …``), else the
    first line holding ``needle`` (for messages naming file and line)."""
    lines = _lines(path)
    if re.fullmatch(r"[A-Za-z_][A-Za-z0-9_-]*", needle):
        for i, line in enumerate(lines, 1):
            if re.match(rf"\s*{re.escape(needle)}\s*=", line):
                return i
    for i, line in enumerate(lines, 1):
        if needle in line:
            return i
    return None


def where(path: Path, needle: str | None = None) -> str:
    line = line_of(path, needle) if needle else None
    return f"{path}:{line}" if line else str(path)


def locate(path: Path, table: str, index: int = 0, key: str | None = None) -> str:
    """``path:line`` of the ``index``-th ``[[table]]`` (or ``[table]``) of a TOML file, or of its
    ``key`` where that table sets it."""
    header = re.compile(rf"\s*\[\[?\s*{re.escape(table)}\s*\]\]?\s*(#.*)?$")
    any_header = re.compile(r"\s*\[")
    lines = _lines(path)
    seen, start = -1, None
    for i, line in enumerate(lines, 1):
        if header.match(line):
            seen += 1
            if seen == index:
                start = i
                break
    if start is None:
        return where(path, key or table)
    if key is not None:
        for i in range(start, len(lines)):
            line = lines[i]
            if any_header.match(line):
                break
            if re.match(rf"\s*{re.escape(key)}\s*=", line):
                return f"{path}:{i + 1}"
    return f"{path}:{start}"


MAX_FILE_BYTES = 4 * 2**20  # a text's TOML file is typed by hand: more is not a text


def read_bytes(path: Path, limit: int = MAX_FILE_BYTES) -> bytes:
    """A text's file, refused unless it is a regular file (not a pipe or a device, where a read
    would block or never end) of at most ``limit`` bytes."""
    import os
    import stat

    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK)
    except OSError as exc:
        raise CatalogError(f"{path}: cannot read: {exc.strerror}") from None
    with os.fdopen(fd, "rb") as fh:
        st = os.fstat(fh.fileno())
        if not stat.S_ISREG(st.st_mode):
            raise CatalogError(f"{path}: not a regular file (a pipe, a device or a folder): refused")
        if st.st_size > limit:
            raise CatalogError(f"{path}: {st.st_size} bytes; a text's file is at most {limit} bytes")
        data = fh.read(limit + 1)
    if len(data) > limit:
        raise CatalogError(f"{path}: more than {limit} bytes; a text's file is at most {limit} bytes")
    return data


def read_toml(path: Path) -> dict:
    """A text's TOML file; a syntax error names the file and line."""
    data = read_bytes(path)
    try:
        return tomllib.loads(data.decode("utf-8"))
    except tomllib.TOMLDecodeError as exc:
        m = re.search(r"\(at line (\d+), column (\d+)\)", str(exc))
        msg = re.sub(r"\s*\(at line \d+, column \d+\)", "", str(exc))
        raise CatalogError(f"{path}:{m.group(1)}: {msg}" if m else f"{path}: {msg}") from None
    except UnicodeDecodeError as exc:
        raise CatalogError(f"{path}: not UTF-8 text (byte {exc.start})") from None
    except RecursionError:
        raise CatalogError(f"{path}:{_deep_line(data.decode('utf-8', 'replace'))}: arrays or tables nested too "
                           "deeply to be a text's data") from None


def _deep_line(text: str, depth_limit: int = 64) -> int:
    """The line where brackets first nest deeper than ``depth_limit`` (quoted text skipped)."""
    depth, line, quote, comment = 0, 1, None, False
    for ch in text:
        if ch == "\n":
            line += 1
            comment = False
            continue
        if comment:
            continue
        if quote:
            quote = None if ch == quote else quote
        elif ch == "#":
            comment = True
        elif ch in "\"'":
            quote = ch
        elif ch in "[{":
            depth += 1
            if depth > depth_limit:
                return line
        elif ch in "]}":
            depth -= 1
    return 1


_REQUIRED = ("id", "name", "latex", "printed")
_KNOWN = frozenset(set(_REQUIRED) | {"number", "dims", "note", "constraints", "real", "url", "kind", "semantic", "approx",
                           "rests_on", "defines"})
#: an entry's name in another language: name_cs, name_de …
_NAME_IN = re.compile(r"name_[a-z]{2}")
KINDS = ("identity", "definition", "inequality", "series", "asymptotic", "notation")


def load_file(path: Path, text_id: str, table: SymbolTable, order0: int = 0) -> list[Entry]:
    """The entries of one catalog file of text ``text_id``; names are checked at once."""
    data = read_toml(path)
    if "section" not in data:
        raise CatalogError(f"{path}: missing top-level key 'section'")
    if not isinstance(data["section"], (str, int)) or isinstance(data["section"], bool):
        raise CatalogError(f"{where(path, 'section')}: section is a string such as \"2\"")
    if "title" in data and not isinstance(data["title"], str):
        raise CatalogError(f"{where(path, 'title')}: title is a string")
    if data.get("source", text_id) != text_id:
        raise CatalogError(f"{where(path, 'source')}: source {data['source']!r} is not this text's id {text_id!r}")
    equations = data.get("equation", [])
    if not isinstance(equations, list) or not all(isinstance(raw, dict) for raw in equations):
        raise CatalogError(f"{where(path, 'equation')}: write each entry as an [[equation]] table")
    return [_entry(raw, i, path, text_id, table, str(data["section"]), order0 + i) for i, raw in enumerate(equations)]


def _strings(raw: dict, key: str, here: str) -> tuple[str, ...]:
    value = raw.get(key, [])
    if isinstance(value, str):
        value = [value]
    if not (isinstance(value, list) and all(isinstance(v, str) for v in value)):
        raise CatalogError(f"{here}: {key} is a list of strings")
    return tuple(v.strip() for v in value)


def _entry(raw: dict, i: int, path: Path, text_id: str, table: SymbolTable, section: str, order: int) -> Entry:
    here = locate(path, "equation", i)
    missing = [k for k in _REQUIRED if k not in raw]
    if missing:
        raise CatalogError(f"{here}: equation #{i + 1} lacks {', '.join(missing)}")
    if not all(isinstance(raw[k], str) for k in _REQUIRED):
        raise CatalogError(f"{here}: id, name, latex and printed are strings")
    unknown = {k for k in set(raw) - _KNOWN if not _NAME_IN.fullmatch(k)}
    if unknown:
        raise CatalogError(f"{here}: {raw['id']}: unknown key(s) {', '.join(sorted(unknown))}")
    eid = raw["id"]
    if not eid.startswith(text_id + ":") or not _printable(eid):
        raise CatalogError(f"{here}: id {eid!r} does not start with {text_id}: (or holds control characters)")
    for key in ("note", "url", "kind", "semantic", "approx", *sorted(k for k in raw if _NAME_IN.fullmatch(k))):
        if key in raw and not isinstance(raw[key], str):
            raise CatalogError(f"{locate(path, 'equation', i, key)}: {eid}: {key} is a string")
    if raw.get("approx", "").strip():
        try:
            decimal_literal(raw["approx"])
        except ValueError as exc:
            raise CatalogError(f"{locate(path, 'equation', i, 'approx')}: {eid}: approx: {exc}") from None
    if "number" in raw and (not isinstance(raw["number"], (str, int)) or isinstance(raw["number"], bool)):
        raise CatalogError(f"{here}: {eid}: number is a string such as \"12\"")
    if raw.get("kind", "identity") not in KINDS:
        raise CatalogError(f"{here}: {eid}: kind is one of {', '.join(KINDS)}")
    dims = raw.get("dims", {})
    if not isinstance(dims, dict) or not all(isinstance(v, str) for v in dims.values()):
        raise CatalogError(f"{here}: {eid}: dims is a table such as {{ A = \"L^2/T\" }}")
    constraints, real = _strings(raw, "constraints", f"{here}: {eid}"), _strings(raw, "real", f"{here}: {eid}")
    rests_on = _strings(raw, "rests_on", f"{here}: {eid}")
    defines = _strings(raw, "defines", f"{here}: {eid}")
    try:
        for text in dims.values():
            parse_dim(text)
        table.check_names(raw["printed"])
        for c in constraints:
            table.check_names(c)
        for key, names in (("real", real), ("defines", defines)):
            for name in names:
                if name not in table:
                    raise SymbolError(f"{key}: {name} is not a declared symbol")
    except (SymbolError, UnitError) as exc:
        raise CatalogError(f"{transcription_line(path, i, exc)}: {eid}: {exc}") from None
    return Entry(
        id=eid, source=text_id, section=section, name=raw["name"],
        latex=raw["latex"].strip(), printed_text=raw["printed"].strip(),
        number=str(raw["number"]) if "number" in raw else None,
        dims_text=tuple(sorted((str(a), str(b)) for a, b in dims.items())),
        note=raw.get("note", "").strip(), file=path.name, order=order, symbols=table,
        constraints_text=constraints, real_names=real, url=raw.get("url", "").strip(), kind=raw.get("kind", ""),
        semantic=raw.get("semantic", "").strip(), approx=raw.get("approx", "").strip(), rests_on=rests_on,
        defines_names=defines, path=str(path),
        names=tuple(sorted((k[len("name_"):], v.strip()) for k, v in raw.items() if _NAME_IN.fullmatch(k) and v.strip())))


def transcription_line(path: Path, i: int, exc: Exception, table: str = "equation", key: str = "printed") -> str:
    """``path:line`` of the line of the ``i``-th table's transcription that ``exc`` names (the
    reader counts lines from the transcription's first)."""
    at = locate(path, table, i, key)
    m = re.match(r"line (\d+), column", str(exc).split(": ", 1)[-1]) or re.search(r"line (\d+), column", str(exc))
    if not m or ":" not in at:
        return at
    base, line = at.rsplit(":", 1)
    if not line.isdigit():
        return at
    lines = _lines(path)
    opener = lines[int(line) - 1] if int(line) - 1 < len(lines) else ""
    # a multi-line string opened on the key's line: the transcription starts on the next one
    starts_below = opener.split("=", 1)[-1].strip() in ("'" * 3, '"' * 3)
    return f"{base}:{int(line) + int(m.group(1)) - 1 + (1 if starts_below else 0)}"


def _printable(s: str) -> bool:
    return all(ch.isprintable() for ch in s)
