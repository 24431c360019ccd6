"""A whole ``verify`` run read back when nothing it depends on has changed — without
importing sympy, so that a warm run in CI or a pre-commit hook takes a fraction of a second.

The record is keyed by the checker's code, every selected text's files and the command's
options (:mod:`fingerprint`).  It holds what the run printed, its exit code, its JUnit report,
and the hash of every per-entry verdict it was built from: those verdicts stay the checked
source of truth (:func:`quasicentral.engine.run.cached_problem`), so when one of them is
edited, or missing, the record is not used and the run reads and checks them one by one.
Standard library only.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import asdict, dataclass
from pathlib import Path

from quasicentral.engine.fingerprint import cache_dir, code_fingerprint, folder_fingerprint

REPLAY_VERSION = "1"
RUNS = "runs"  # the records' folder inside the cache


class ReplayError(ValueError):
    """A record that cannot be used (wrong shape)."""


@dataclass(frozen=True)
class Record:
    stdout: str
    exit: int
    entries: int
    junit: str | None
    verdicts: dict[str, str]  # per-entry verdict file name -> sha256 of its bytes


def key(command: str, options: dict, folders: list[tuple[str, Path]]) -> str:
    """The record's key: the code, each text's files, the command and its options."""
    texts_fp = [[tid, str(root), folder_fingerprint(tid, root)] for tid, root in folders]
    # the command line prints what the engine formats: its own code is part of the key too
    cli = digest(Path(__file__).resolve().parent.parent / "cli.py")
    blob = json.dumps([REPLAY_VERSION, code_fingerprint(), cli, command, options, texts_fp], sort_keys=True)
    return hashlib.sha256(blob.encode()).hexdigest()


def _path(k: str) -> Path:
    return cache_dir() / RUNS / f"{k}.json"


def digest(path: Path) -> str | None:
    try:
        return hashlib.sha256(path.read_bytes()).hexdigest()
    except OSError:
        return None


def load(k: str) -> Record | None:
    """The record under ``k`` if there is one and every verdict it was built from is unchanged;
    raises :class:`ReplayError` for a record of the wrong shape."""
    path = _path(k)
    try:
        raw = path.read_bytes()
    except OSError:
        return None
    try:
        d = json.loads(raw.decode("utf-8"))
        rec = Record(stdout=d["stdout"], exit=d["exit"], entries=d["entries"], junit=d["junit"],
                     verdicts=dict(d["verdicts"]))
        ok = (isinstance(rec.stdout, str) and rec.exit in (0, 1) and isinstance(rec.entries, int)
              and (rec.junit is None or isinstance(rec.junit, str)) and rec.verdicts
              and all(isinstance(a, str) and isinstance(b, str) for a, b in rec.verdicts.items()))
    except (ValueError, KeyError, TypeError, AttributeError) as exc:
        raise ReplayError(f"{path}: wrong shape ({type(exc).__name__})") from None
    if not ok:
        raise ReplayError(f"{path}: wrong shape")
    folder = cache_dir()
    for name, sha in rec.verdicts.items():
        if Path(name).name != name or digest(folder / name) != sha:
            return None  # a verdict changed: read and check them one by one
    return rec


def store(k: str, rec: Record) -> None:
    from quasicentral.files import write_text

    try:
        _path(k).parent.mkdir(parents=True, exist_ok=True)
        write_text(_path(k), json.dumps(asdict(rec), sort_keys=True))
    except OSError:
        pass  # a read-only cache is not an error
