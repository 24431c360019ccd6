"""Texts: everything about one text lives in one folder.

::

    mytext/
      text.toml          id, title, authors, year, language; the symbol table
      catalog/*.toml     what is printed, one file per section (read in sorted order)
      errata/*.toml      the errata found and the suspects cleared (optional)
      *.py               the derivations (every module not starting with "_", except figures.py)
      report.toml        optional prose of its report (headings, captions) in its languages
      figures.py         optional: the text's figures

The shipped texts are such folders under ``derivations/``; a user's text is any folder
(``--text DIR``).  Nothing in the package names a text: it is all read from the folder.

A derivation module finds its text's symbols with :func:`symbols_of`::

    S = symbols_of(__file__)
    x, t, a = S("x t a")
"""

from __future__ import annotations

import importlib.util
import re
import sys
import traceback
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

from quasicentral.engine import errata as errata_mod
from quasicentral.engine.fingerprint import SHIPPED_ROOT, TEXT_FILE, folder_fingerprint
from quasicentral.engine.catalog import CatalogError, Entry, load_file, read_toml, where
from quasicentral.engine.registry import REGISTRY, unregister, unregister_module, use_store
from quasicentral.engine.store import DerivedStore
from quasicentral.notation.symbols import SymbolError, SymbolTable, table_from_toml

_ID = re.compile(r"[a-z0-9][a-z0-9_-]*\Z")
_META_KEYS = {"id", "title", "title_en", "authors", "year", "language", "citation", "derivations",
              "symbols", "functions"}
LANGUAGES = ("cs", "en", "de", "fr", "sk", "pl", "it", "es", "ru")
MAX_FILE_BYTES = 4 * 2**20  # a text's TOML file is typed by hand: more is not a text


class TextError(CatalogError):
    """A text folder that cannot be read (the message names the file and line)."""


@dataclass(eq=False)
class Text:
    """One text: metadata, symbol table, catalog, errata, derivations — read from its folder."""

    id: str
    root: Path
    title: str
    authors: tuple[str, ...]
    language: str
    symbols: SymbolTable
    year: int | None = None
    title_en: str = ""
    citation: str = ""
    derivation_names: tuple[str, ...] | None = None
    _loaded: bool = field(default=False, repr=False)
    loaded_fingerprint: str | None = field(default=None, repr=False)  # see load_derivations

    # --- the files -------------------------------------------------------------------------
    @property
    def catalog_files(self) -> list[Path]:
        return sorted((self.root / "catalog").glob("*.toml"))

    @property
    def errata_files(self) -> list[Path]:
        return sorted((self.root / "errata").glob("*.toml"))

    @property
    def derivation_files(self) -> list[Path]:
        if self.derivation_names is not None:
            return [self.root / f"{n}.py" for n in self.derivation_names]
        return sorted(p for p in self.root.glob("*.py") if not p.name.startswith("_") and p.name != "figures.py")

    @property
    def is_shipped(self) -> bool:
        return self.root.parent == SHIPPED_ROOT

    @property
    def module_prefix(self) -> str:
        """The package name the text's derivation modules are imported under."""
        return (f"derivations.{self.id}" if self.is_shipped
                else f"quasicentral_text_{re.sub(r'[^A-Za-z0-9_]', '_', self.id)}")

    def fingerprint(self) -> str:
        """Hash of every file of the folder a verdict can depend on (see
        :func:`quasicentral.engine.fingerprint.folder_fingerprint`)."""
        return folder_fingerprint(self.id, self.root)

    # --- contents --------------------------------------------------------------------------
    @cached_property
    def entries(self) -> dict[str, Entry]:
        """The catalog, in the text's order; duplicate ids are refused."""
        files = self.catalog_files
        if not files:
            raise TextError(f"{self.root / 'catalog'}: no catalog file (*.toml) in the text's folder")
        out: dict[str, Entry] = {}
        for path in files:
            _check_size(path)
            for e in load_file(path, self.id, self.symbols, order0=len(out)):
                if e.id in out:
                    raise TextError(f"{where(path, chr(34) + e.id + chr(34))}: duplicate id {e.id!r}")
                out[e.id] = e
        return out

    @cached_property
    def records(self) -> errata_mod.Records:
        """The text's errata, cleared suspects and root causes."""
        for p in self.errata_files:
            _check_size(p)
        return errata_mod.load(self.errata_files, self.entries, self.symbols, self.id)

    @property
    def errata(self) -> dict[str, errata_mod.Erratum]:
        return self.records.errata

    @property
    def cleared(self) -> dict[str, errata_mod.Cleared]:
        return self.records.cleared

    @property
    def causes(self) -> dict[str, errata_mod.Cause]:
        return self.records.causes

    def figures_module(self):
        """The text's ``figures.py`` imported (None when the folder has none)."""
        path = self.root / "figures.py"
        return _import(self, path) if path.is_file() else None

    def load_derivations(self) -> None:
        """Import the text's derivation modules (they register themselves) and check that
        derivations and catalog entries match one to one."""
        if self._loaded:
            return
        entries = self.entries
        # the files as the derivations are imported: their kept results are keyed by it
        self.loaded_fingerprint = self.fingerprint()
        for path in self.derivation_files:
            if not path.is_file():
                raise TextError(f"{self.root / TEXT_FILE}: derivations: no module {path.name}")
            _import(self, path)
        self._loaded = True
        mine = {eid: d for eid, d in REGISTRY.items() if d.text == self.id}
        for eid, d in mine.items():
            if eid not in entries:
                raise TextError(f"{d.where()}: derivation of {eid!r}, which is not in the catalog")
        for eid, e in entries.items():
            if eid not in mine:
                raise TextError(f"{where(self.root / 'catalog' / e.file, chr(34) + eid + chr(34))}: "
                                f"entry {eid!r} has no derivation (register one with @derives({eid!r}, ...))")


def _check_size(path: Path) -> None:
    try:
        size = path.stat().st_size
    except OSError as exc:
        raise TextError(f"{path}: cannot read: {exc.strerror}") from None
    if size > MAX_FILE_BYTES:
        raise TextError(f"{path}: {size} bytes; a text's file is at most {MAX_FILE_BYTES} bytes")


def _import(text: Text, path: Path):
    """Import a module of the text's folder once (its derivations register themselves)."""
    name = f"{text.module_prefix}.{path.stem}"
    if name in sys.modules and getattr(sys.modules[name], "__file__", None) == str(path):
        # imported before (e.g. by a test): its derivations registered then
        return sys.modules[name]
    unregister_module(name)  # another file of this name was imported before: its steps go
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    try:
        spec.loader.exec_module(module)
    except (CatalogError, SymbolError) as exc:
        sys.modules.pop(name, None)
        raise TextError(f"{_frame_in(path, exc)}: {exc}") from None
    except Exception as exc:  # noqa: BLE001 - a user's module may raise anything: one line
        sys.modules.pop(name, None)
        raise TextError(f"{_frame_in(path, exc)}: {type(exc).__name__}: {exc}") from None
    return module


def _frame_in(path: Path, exc: BaseException) -> str:
    """``file:line`` of the deepest frame of ``exc`` inside ``path`` (else the file)."""
    line = None
    if isinstance(exc, SyntaxError) and exc.filename == str(path):
        line = exc.lineno
    for fr in traceback.extract_tb(exc.__traceback__):
        if fr.filename == str(path):
            line = fr.lineno
    return f"{path}:{line}" if line else str(path)


# --- reading a folder --------------------------------------------------------------------------
_OPEN: dict[Path, Text] = {}
_TABLES: dict[Path, SymbolTable] = {}


def _read_meta(root: Path) -> dict:
    path = root / TEXT_FILE
    if not root.is_dir():
        raise TextError(f"{root}: not a folder (a text is a folder holding {TEXT_FILE})")
    if not path.is_file():
        raise TextError(f"{path}: missing (a text folder holds {TEXT_FILE}; `quasicentral new-text DIR` writes one)")
    _check_size(path)
    return read_toml(path)


def _table(root: Path, data: dict | None = None) -> SymbolTable:
    root = root.resolve()
    if root not in _TABLES:
        data = data if data is not None else _read_meta(root)
        try:
            _TABLES[root] = table_from_toml(data, str(root / TEXT_FILE))
        except SymbolError as exc:
            raise TextError(_with_line(root / TEXT_FILE, str(exc))) from None
    return _TABLES[root]


def _with_line(path: Path, message: str) -> str:
    """Add the line of the ``symbols.NAME`` / ``functions.NAME`` table a message names."""
    m = re.search(r": (symbols|functions)\.([A-Za-z0-9_]+)", message)
    if not m:
        return message
    header = f"[{m.group(1)}.{m.group(2)}]"
    line = None
    try:
        for i, text in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            if text.strip().startswith(header) or re.match(rf"\s*{m.group(2)}\s*=", text):
                line = i
                break
    except OSError:
        pass
    return message.replace(f"{path}:", f"{path}:{line}:", 1) if line else message


def symbols_of(module_file: str) -> SymbolTable:
    """The symbol table of the text whose folder holds ``module_file`` (for derivation modules)."""
    return _table(Path(module_file).resolve().parent)


def open_text(folder: str | Path) -> Text:
    """The text in ``folder`` (read once per process)."""
    root = Path(folder).expanduser().resolve()
    if root in _OPEN:
        return _OPEN[root]
    data = _read_meta(root)
    here = root / TEXT_FILE
    unknown = set(data) - _META_KEYS
    if unknown:
        raise TextError(f"{where(here, sorted(unknown)[0])}: unknown key(s) {', '.join(sorted(unknown))}")
    tid = data.get("id")
    if not isinstance(tid, str) or not _ID.match(tid):
        raise TextError(f"{where(here, 'id')}: id is a short name of lower-case letters, digits, - and _ "
                        f"(it prefixes every equation id), not {tid!r}")
    for key in ("title", "language"):
        if not isinstance(data.get(key), str) or not data[key].strip():
            raise TextError(f"{where(here, key)}: '{key}' is required (a string)")
    if data["language"] not in LANGUAGES:
        raise TextError(f"{where(here, 'language')}: language is an ISO 639-1 code ({', '.join(LANGUAGES)}), "
                        f"not {data['language']!r}")
    authors = data.get("authors", [])
    if not (isinstance(authors, list) and all(isinstance(a, str) for a in authors)):
        raise TextError(f"{where(here, 'authors')}: authors is a list of strings")
    year = data.get("year")
    if year is not None and (not isinstance(year, int) or isinstance(year, bool) or not 0 < year < 10000):
        raise TextError(f"{where(here, 'year')}: year is a whole number such as 1953")
    names = data.get("derivations")
    if names is not None and not (isinstance(names, list) and all(isinstance(n, str) and n.isidentifier() for n in names)):
        raise TextError(f"{where(here, 'derivations')}: derivations lists module names such as [\"section1\"]")
    text = Text(id=tid, root=root, title=data["title"].strip(), authors=tuple(authors), language=data["language"],
                symbols=_table(root, data), year=year, title_en=str(data.get("title_en", "")).strip(),
                citation=str(data.get("citation", "")).strip(),
                derivation_names=tuple(names) if names is not None else None)
    _OPEN[root] = text
    return text


def forget(text: Text) -> None:
    """Drop ``text`` from this process (its modules, derivations and parsed files), so that the
    next :func:`open_text` reads the folder anew — after its files were edited."""
    _OPEN.pop(text.root, None)
    _TABLES.pop(text.root, None)
    if _ACTIVE.get(text.id) is text:
        _ACTIVE.pop(text.id)
    for name, module in list(sys.modules.items()):
        if str(getattr(module, "__file__", "") or "").startswith(str(text.root) + "/"):
            sys.modules.pop(name)
    unregister(text.id)


def shipped() -> list[Text]:
    """The texts shipped with the package (folders under ``derivations/``), by id.  Identity
    texts (``check = "identity"``, the DLMF chapters) are left to the identity mode, which
    this loader does not read yet."""
    return sorted((open_text(p.parent) for p in SHIPPED_ROOT.glob(f"*/{TEXT_FILE}")
                   if read_toml(p).get("check") != "identity"), key=lambda t: t.id)


def resolve(specs: list[str] | None) -> list[Text]:
    """Texts named by folder or by a shipped text's id; none named: the shipped texts."""
    if not specs:
        return shipped()
    by_id = {t.id: t for t in shipped()}
    out: list[Text] = []
    for spec in specs:
        if not spec.strip():
            raise TextError("--text: an empty name (give a text's folder or a shipped text's id)")
        path = Path(spec).expanduser()
        if path.exists() or "/" in spec or spec.startswith("."):
            text = open_text(path)
        elif spec in by_id:
            text = by_id[spec]
        else:
            raise TextError(f"--text {spec}: no such folder, and no shipped text is called so "
                            f"({', '.join(by_id)})")
        if any(t.id == text.id and t.root != text.root for t in out):
            raise TextError(f"--text {spec}: two texts have the id {text.id!r}")
        if text not in out:
            out.append(text)
    return out


# --- the texts of a run ------------------------------------------------------------------------
_ACTIVE: dict[str, Text] = {}


def activate(texts: list[Text], exclusive: bool = False) -> list[Text]:
    """Make ``texts`` the ones ids are looked up in (their derivations imported); with
    ``exclusive``, the only ones :func:`active` lists."""
    if exclusive:
        _ACTIVE.clear()
    for t in texts:
        other = _ACTIVE.get(t.id)
        if other is not None and other.root != t.root:
            raise TextError(f"{t.root / TEXT_FILE}: id {t.id!r} is already the id of {other.root}")
    for t in texts:
        t.load_derivations()
        _ACTIVE[t.id] = t
    # derivation results are kept on disk per text (quasicentral.engine.store), keyed by the
    # files of the texts active now
    active_now = dict(_ACTIVE)
    use_store(DerivedStore(lambda tid: active_now[tid].loaded_fingerprint if tid in active_now else None,
                           frozenset(t.module_prefix for t in active_now.values())))
    return texts


def text_of(eid: str) -> Text:
    tid = eid.split(":", 1)[0]
    if tid not in _ACTIVE:
        activate([t for t in shipped() if t.id == tid])
    if tid not in _ACTIVE:
        raise KeyError(f"no text {tid!r} is loaded")
    return _ACTIVE[tid]


def entry(eid: str) -> Entry:
    """The catalog entry ``eid`` of a loaded text."""
    text = text_of(eid)
    if eid not in text.entries:
        raise KeyError(f"unknown equation id {eid!r}")
    return text.entries[eid]


def entries(texts: list[Text]) -> list[Entry]:
    return [e for t in texts for e in t.entries.values()]


def get(tid: str) -> Text:
    """The loaded text ``tid`` (a shipped one is loaded on first use)."""
    return text_of(tid + ":")


def active() -> list[Text]:
    """The texts loaded in this run, in the order they were activated (the shipped ones if none)."""
    if not _ACTIVE:
        activate(shipped())
    return list(_ACTIVE.values())


def records(selected: list[Text] | None = None) -> tuple[dict, dict]:
    """The errata and the cleared suspects of ``selected`` (default: the active texts), merged."""
    errata: dict = {}
    cleared: dict = {}
    for t in selected if selected is not None else active():
        errata.update(t.errata)
        cleared.update(t.cleared)
    return errata, cleared


def causes(selected: list[Text] | None = None) -> dict:
    """The root causes of ``selected`` (default: the active texts), merged (ids are the texts')."""
    out: dict = {}
    for t in selected if selected is not None else active():
        out.update(t.causes)
    return out


def reset() -> None:
    """Forget every text that is not shipped (a long-lived process reading several user texts)."""
    for text in list(_OPEN.values()):
        if not text.is_shipped:
            forget(text)
