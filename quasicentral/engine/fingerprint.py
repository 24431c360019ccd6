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

import derivations as _shipped_package  # its __init__ is a docstring: nothing heavy

CACHE_VERSION = "2"  # 2: texts as folders, keys per text
VERDICT_LAYERS = ("notation", "engine")
DOCUMENT_FILES = ("report.toml", "figures.py")  # read by the documents only, never by the checker
TEXT_FILE = "text.toml"
SHIPPED_ROOT = Path(_shipped_package.__file__).parent


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


def folder_fingerprint(tid: str, root: Path) -> str:
    """Hash of every file of a text's folder a verdict can depend on (all but the report's
    prose and the figures, :data:`DOCUMENT_FILES`): a change there invalidates its verdicts."""
    h = hashlib.sha256(tid.encode())
    for path in sorted(root.rglob("*")):
        rel = path.relative_to(root)
        if rel.as_posix() in DOCUMENT_FILES:
            continue
        if path.is_file() and "__pycache__" not in rel.parts and not any(p.startswith(".") for p in rel.parts):
            h.update(rel.as_posix().encode())
            h.update(path.read_bytes())
    return h.hexdigest()


def _text_id(root: Path) -> str | None:
    try:
        with open(root / TEXT_FILE, "rb") as f:
            tid = tomllib.load(f).get("id")
    except (OSError, tomllib.TOMLDecodeError):
        return None
    return tid if isinstance(tid, str) else None


def _is_identity_text(root: Path) -> bool:
    try:
        with open(root / TEXT_FILE, "rb") as f:
            return tomllib.load(f).get("check") == "identity"
    except (OSError, tomllib.TOMLDecodeError):
        return False


def text_folders(specs: list[str] | None) -> list[tuple[str, Path]] | None:
    """(id, folder) of each text ``specs`` names — folders, or shipped ids; none named: the
    shipped texts — or ``None`` where a name does not resolve plainly."""
    shipped = {}
    for toml in sorted(SHIPPED_ROOT.glob(f"*/{TEXT_FILE}")):
        tid = _text_id(toml.parent)
        if tid is None:
            return None
        if _is_identity_text(toml.parent):  # left to the identity mode (texts.shipped)
            continue
        shipped[tid] = toml.parent.resolve()
    if not specs:
        return sorted(shipped.items())
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
