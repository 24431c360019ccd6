"""Texts: everything about one text lives in one folder.

::

    mytext/
      text.toml          id, title, authors, year, language; the symbol table
      catalog/*.toml     what is printed, one file per section (read in sorted order)
      errata/*.toml      the errata found and the suspects cleared (optional)
      *.py               the derivations (every module not starting with "_", except figures.py)
      report.toml        optional prose of its report (headings, captions) in its languages
      figures.py         optional: the text's figures

The shipped texts are such folders inside the package; a user's text is any folder
(``--text DIR``).  Nothing in the package names a text: it is all read from the folder.  A
:class:`Text` reads its data files (which never execute anything); its ``.py`` modules run
only when a workspace loads its derivations (:meth:`Text.import_modules`).

A derivation module finds its text's symbols with :func:`symbols_of`::

    S = symbols_of(__file__)
    x, t, a = S("x t a")
"""

from __future__ import annotations

import contextvars
import hashlib
import re
import sys
import traceback
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

from quasicentral.engine import errata as errata_mod
from quasicentral.engine.catalog import CatalogError, Entry, load_file, locate_key, read_bytes, read_toml, where
from quasicentral.engine.fingerprint import SHIPPED_ROOT, TEXT_FILE, folder_fingerprint
from quasicentral.engine.registry import Derivations, RegistryError, collect
from quasicentral.notation.symbols import SymbolError, SymbolTable, table_from_toml
from quasicentral.notation.timelimit import TimeLimitExceeded

_ID = re.compile(r"[a-z0-9][a-z0-9_-]*\Z")
_META_KEYS = frozenset({"id", "title", "title_en", "authors", "year", "language", "citation", "derivations",
              "symbols", "functions", "check"})
LANGUAGES = ("cs", "en", "de", "fr", "sk", "pl", "it", "es", "ru")
CHECKS = ("derivation", "identity")  # how a text's entries are checked (text.toml: check)


class TextError(CatalogError):
    """A text folder that cannot be read (the message names the file and line)."""


#: the text whose modules are being imported in this context (symbols_of answers from it)
_LOADING: contextvars.ContextVar["Text | None"] = contextvars.ContextVar("quasicentral_loading_text", default=None)


@dataclass(eq=False)
class Text:
    """One text: metadata, symbol table, catalog, errata — read from its folder."""

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
    check: str = "derivation"  # "identity": entries are self-contained relations, no modules needed
    loaded_fingerprint: str | None = field(default=None, repr=False)  # the files as the modules were imported

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
        """The package name the text's modules are imported under."""
        return f"quasicentral_text_{re.sub(r'[^A-Za-z0-9_]', '_', self.id)}"

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
            for e in load_file(path, self.id, self.symbols, order0=len(out)):
                if e.id in out:
                    raise TextError(f"{where(path, chr(34) + e.id + chr(34))}: duplicate id {e.id!r}")
                out[e.id] = e
        return out

    @cached_property
    def section_titles(self) -> dict[str, str]:
        """The printed title of each catalog section (the catalog files' ``title``)."""
        out = {}
        for path in self.catalog_files:
            data = read_toml(path)
            out[str(data.get("section", ""))] = str(data.get("title", ""))
        return out

    @cached_property
    def records(self) -> errata_mod.Records:
        """The text's errata, cleared suspects and root causes."""
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

    def validate(self) -> None:
        """Read every data file of the folder and every transcription in it, so that a mistake is
        named (file and line) before any work begins."""
        for e in self.entries.values():
            e.validate()
            unknown = [r for r in e.rests_on if r not in self.entries]
            if unknown:
                raise TextError(f"{locate_key(e, 'rests_on')}: {e.id}: rests_on names {unknown[0]!r}, "
                                "which is not an entry of this text")
        for rec in self.errata.values():
            rec.corrected

    # --- its code ----------------------------------------------------------------------------
    def import_modules(self, derivations: Derivations) -> None:
        """Import the text's derivation modules and add their derivations to ``derivations``;
        derivations and catalog entries must match one to one (an identity text's entries
        need none)."""
        entries = self.entries
        self.loaded_fingerprint = self.fingerprint()  # the files as imported: their kept results are keyed by it
        mine = []
        for path in self.derivation_files:
            if not path.is_file():
                raise TextError(f"{self.root / TEXT_FILE}: derivations: no module {path.name}")
            mine += collect(self.module(path))
        for d in mine:
            if d.id not in entries:
                raise TextError(f"{d.where()}: derivation of {d.id!r}, which is not in the catalog")
            try:
                derivations.add(d)
            except RegistryError as exc:
                raise TextError(str(exc)) from None
        if self.check == "identity":
            return
        have = {d.id for d in mine}
        for eid, e in entries.items():
            if eid not in have:
                raise TextError(f"{where(self.root / 'catalog' / e.file, chr(34) + eid + chr(34))}: "
                                f"entry {eid!r} has no derivation (register one with @derives({eid!r}, ...))")

    def module(self, path: Path):
        """The text's module at ``path`` imported (once per content: the same file is the same
        module for every workspace of the process)."""
        return _import(self, Path(path))

    def figures_module(self):
        """The text's ``figures.py`` imported (None when the folder has none)."""
        path = self.root / "figures.py"
        return self.module(path) if path.is_file() else None


def _import(text: Text, path: Path):
    """The module compiled from its source itself: a bytecode file beside it is never read (a
    folder could plant one that is not its source) and none is written into the folder."""
    import types

    name = f"{text.module_prefix}.{path.stem}"
    source = read_bytes(path)  # a regular file of a text's size, or a TextError naming it
    digest = hashlib.sha256(source).hexdigest()
    known = sys.modules.get(name)
    if known is not None and getattr(known, "__file__", None) == str(path) and \
            getattr(known, "__quasicentral_digest__", None) == digest:
        return known
    module = types.ModuleType(name)
    module.__file__ = str(path)
    module.__quasicentral_digest__ = digest
    sys.modules[name] = module  # classes defined there pickle by this name
    token = _LOADING.set(text)
    try:
        exec(compile(source, str(path), "exec", dont_inherit=True), module.__dict__)  # noqa: S102 - the folder's own module
    except TimeLimitExceeded as exc:
        sys.modules.pop(name, None)
        raise TextError(f"{_frame_in(path, exc)}: the module did not finish importing within its time "
                        f"({exc}; --timeout allows more)") from None
    except (CatalogError, SymbolError, RegistryError) as exc:
        sys.modules.pop(name, None)
        raise TextError(f"{_frame_in(path, exc)}: {exc}") from None
    except (Exception, SystemExit, GeneratorExit) as exc:  # noqa: BLE001 - a user's module may raise anything: one line
        sys.modules.pop(name, None)
        raise TextError(f"{_frame_in(path, exc)}: {_what(exc)}") from None
    finally:
        _LOADING.reset(token)
    return module


def _what(exc: BaseException) -> str:
    if isinstance(exc, SystemExit):
        return f"the module calls sys.exit({exc.code!r}) while it is imported"
    return f"{type(exc).__name__}: {exc}"


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
def read_meta(root: Path) -> dict:
    path = root / TEXT_FILE
    if not root.is_dir():
        raise TextError(f"{root}: not a folder (a text is a folder holding {TEXT_FILE})")
    if not path.is_file():
        raise TextError(f"{path}: missing (a text folder holds {TEXT_FILE}; `quasicentral new-text DIR` writes one)")
    return read_toml(path)


def table_of(root: Path, data: dict | None = None) -> SymbolTable:
    """The symbol table a text folder declares."""
    data = data if data is not None else read_meta(root)
    try:
        return table_from_toml(data, str(root / TEXT_FILE))
    except SymbolError as exc:
        raise TextError(_with_line(root / TEXT_FILE, str(exc))) from None


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
    root = Path(module_file).resolve().parent
    loading = _LOADING.get()
    if loading is not None and loading.root == root:
        return loading.symbols
    return table_of(root)


def open_text(folder: str | Path) -> Text:
    """The text in ``folder``, read from its data files (its modules are not imported)."""
    root = Path(folder).expanduser().resolve()
    data = read_meta(root)
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
    check = data.get("check", "derivation")
    if check not in CHECKS:
        raise TextError(f"{where(here, 'check')}: check is one of {', '.join(CHECKS)}, not {check!r}")
    for key in ("title_en", "citation"):
        if key in data and not isinstance(data[key], str):
            raise TextError(f"{where(here, key)}: '{key}' is a string")
    return Text(id=tid, root=root, title=data["title"].strip(), authors=tuple(authors), language=data["language"],
                symbols=table_of(root, data), year=year, title_en=str(data.get("title_en", "")).strip(),
                citation=str(data.get("citation", "")).strip(),
                derivation_names=tuple(names) if names is not None else None, check=check)
