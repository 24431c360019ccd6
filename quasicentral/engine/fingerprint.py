"""What verdicts depend on, hashed — with the standard library only, so that a run whose
inputs have not changed can be recognised before sympy is imported (:mod:`replay`).

* :func:`code_fingerprint`: the checker's source (:data:`VERDICT_LAYERS`) and the versions
  of the libraries whose answers are the verdicts;
* :func:`folder_fingerprint`: a text's folder, all but the files only the documents read
  (:data:`DOCUMENT_FILES`);
* :func:`text_folders`: the folders a ``--text`` list names, without parsing them (``None``
  where one does not resolve plainly: the full reader then says what is wrong).
"""

from __future__ import annotations

import hashlib
import os
import tomllib
from functools import lru_cache
from pathlib import Path

CACHE_VERSION = "3"  # 3: typed records, shipped texts inside the package
VERDICT_LAYERS = ("notation", "engine")
DOCUMENT_FILES = ("report.toml", "figures.py")  # read by the documents only, never by the checker
TEXT_FILE = "text.toml"
SHIPPED_ROOT = Path(__file__).resolve().parent.parent / "texts"  # the shipped texts: package data


def cache_dir() -> Path:
    base = os.environ.get("QUASICENTRAL_CACHE") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "quasicentral")
    return Path(base)


@lru_cache(maxsize=1)
def code_fingerprint() -> str:
    """Hash of the source files verdicts are computed by (:data:`VERDICT_LAYERS`) and of the
    versions of the libraries that compute them (each text's own files are hashed by
    :func:`folder_fingerprint`)."""
    from importlib import metadata

    h = hashlib.sha256(CACHE_VERSION.encode())
    for dist in ("sympy", "mpmath", "python-flint", "numpy", "scipy"):  # their answers are the verdicts'
        try:
            h.update(f"{dist}={metadata.version(dist)}".encode())
        except metadata.PackageNotFoundError:
            h.update(dist.encode())
    pkg = Path(__file__).resolve().parent.parent
    for layer in VERDICT_LAYERS:  # the code a verdict depends on (not the documents, models, CLI)
        for path in sorted((pkg / layer).rglob("*.py")):
            if "__pycache__" not in path.parts:
                h.update(path.relative_to(pkg).as_posix().encode())
                h.update(path.read_bytes())
    return h.hexdigest()


#: the most bytes of one file a fingerprint reads (a text's files are typed by hand; a larger one
#: is refused when the text is read, and hashed here by its size and time alone)
MAX_HASHED_BYTES = 4 * 2**20


def text_files(root: Path) -> list[Path]:
    """The files a verdict of the text in ``root`` can depend on: ``text.toml``, the catalog and
    errata files, and its derivation modules (every other file of the folder — the report's
    prose, the figures, a data file linked in — is not read by the checker)."""
    out = [root / TEXT_FILE] if (root / TEXT_FILE).exists() else []
    for sub in ("catalog", "errata"):
        out += sorted((root / sub).glob("*.toml"))
    out += sorted(p for p in root.glob("*.py") if p.name not in DOCUMENT_FILES and not p.name.startswith("_"))
    return out


def folder_fingerprint(tid: str, root: Path) -> str:
    """Hash of every file of a text's folder a verdict can depend on (:func:`text_files`): a
    change there invalidates its verdicts.  Only regular files are read, each up to
    :data:`MAX_HASHED_BYTES` (a pipe or a device is named by its kind, a larger file by its size
    and time: the reader of the text refuses both)."""
    import stat as stat_mod

    h = hashlib.sha256(tid.encode())
    for path in text_files(root):
        h.update(path.relative_to(root).as_posix().encode())
        try:
            st = path.stat()
        except OSError as exc:
            h.update(f"unreadable {exc.errno}".encode())
            continue
        if not stat_mod.S_ISREG(st.st_mode) or st.st_size > MAX_HASHED_BYTES:
            h.update(f"special {st.st_mode} {st.st_size} {st.st_mtime_ns}".encode())
            continue
        try:
            with open(path, "rb") as f:
                h.update(f.read(MAX_HASHED_BYTES + 1))
        except OSError as exc:
            h.update(f"unreadable {exc.errno}".encode())
    return h.hexdigest()


def _text_head(root: Path) -> tuple[str, str] | None:
    """(id, check) of the folder's ``text.toml``, or None where it is not a text's file (the full
    reader says why)."""
    path = root / TEXT_FILE
    try:
        if not path.is_file() or path.stat().st_size > 4 * 2**20:
            return None
        with open(path, "rb") as f:
            data = tomllib.load(f)
    except (OSError, ValueError, RecursionError, tomllib.TOMLDecodeError):
        return None
    tid, check = data.get("id"), data.get("check", "derivation")
    return (tid, check) if isinstance(tid, str) and isinstance(check, str) else None


def _text_id(root: Path) -> str | None:
    head = _text_head(root)
    return head[0] if head else None


def shipped_folders(collections: bool = True) -> list[Path]:
    """The folders of the texts shipped with the package; ``collections=False`` leaves out the
    formula collections (``check = "identity"``: DLMF's chapters), which a command works on
    only when they are named — with no ``--text``, a command works on the shipped papers."""
    out = []
    for toml in sorted(SHIPPED_ROOT.glob(f"*/{TEXT_FILE}")):
        head = _text_head(toml.parent)
        if collections or head is None or head[1] != "identity":
            out.append(toml.parent)
    return out


def text_folders(specs: list[str] | None) -> list[tuple[str, Path]] | None:
    """(id, folder) of each text ``specs`` names — folders, or shipped ids; none named: the
    shipped papers — or ``None`` where a name does not resolve plainly."""
    shipped = {}
    for folder in shipped_folders():
        tid = _text_id(folder)
        if tid is None:
            return None
        shipped[tid] = folder.resolve()
    if not specs:
        papers = {folder.resolve() for folder in shipped_folders(collections=False)}
        return sorted((tid, root) for tid, root in shipped.items() if root in papers)
    out: list[tuple[str, Path]] = []
    for spec in specs:
        path = Path(spec).expanduser()
        if spec.strip() and (path.exists() or "/" in spec or spec.startswith(".")):
            root = path.resolve()
            tid = _text_id(root)
        elif spec in shipped:
            tid, root = spec, shipped[spec]
        else:
            return None
        if tid is None or any(t == tid and r != root for t, r in out):
            return None
        if (tid, root) not in out:
            out.append((tid, root))
    return out
