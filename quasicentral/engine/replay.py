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

REPLAY_VERSION = "2"  # 2: the texts a run was built on, beyond those it selected
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
    depends: list = None  # [id, folder, hash] of every other text the verdicts were built on


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
    """The record under ``k`` if there is one of this user's own, and every verdict and text it
    was built from is unchanged; raises :class:`ReplayError` for a record of the wrong shape."""
    from quasicentral.files import read_private

    path = _path(k)
    raw = read_private(path.parent, path.name)
    if raw is None:
        return None
    try:
        d = json.loads(raw.decode("utf-8"))
        rec = Record(stdout=d["stdout"], exit=d["exit"], entries=d["entries"], junit=d["junit"],
                     verdicts=dict(d["verdicts"]), depends=list(d["depends"]))
        ok = (isinstance(rec.stdout, str) and rec.exit in (0, 1) and isinstance(rec.entries, int)
              and (rec.junit is None or isinstance(rec.junit, str)) and rec.verdicts
              and all(isinstance(a, str) and isinstance(b, str) for a, b in rec.verdicts.items())
              and all(isinstance(x, list) and len(x) == 3 and all(isinstance(y, str) for y in x) for x in rec.depends))
    except (ValueError, KeyError, TypeError, AttributeError) as exc:
        raise ReplayError(f"{path}: wrong shape ({type(exc).__name__})") from None
    if not ok:
        raise ReplayError(f"{path}: wrong shape")
    folder = cache_dir()
    for name, sha in rec.verdicts.items():
        if Path(name).name != name or private_digest(folder, name) != sha:
            return None  # a verdict changed: read and check them one by one
    for tid, root, fp in rec.depends:
        if folder_fingerprint(tid, Path(root)) != fp:
            return None  # a text the verdicts were built on changed
    return rec


def private_digest(folder: Path, name: str) -> str | None:
    """The hash of a record that only this user can have written (else None)."""
    from quasicentral.files import read_private

    data = read_private(folder, name)
    return hashlib.sha256(data).hexdigest() if data is not None else None


def dependencies(ws, ids: list[str]) -> list | None:
    """[id, folder, hash] of every text the results of ``ids`` were built on beyond their
    own (None when that cannot be known: the run is then not kept for replay)."""
    out = {}
    for eid in ids:
        own = eid.split(":", 1)[0]
        built = ws.derivations.known_built_on(eid)  # from the verdicts' records: nothing is derived here
        if built is None:
            return None
        for tid in sorted(built - {own}):
            try:
                t = ws.text(tid)
            except KeyError:
                return None
            out[tid] = [tid, str(t.root), t.fingerprint()]
    return [out[k] for k in sorted(out)]


def store(k: str, rec: Record) -> None:
    from quasicentral.files import write_text

    from quasicentral.files import ensure_dir

    try:
        ensure_dir(_path(k).parent)  # never through a symbolic link
        write_text(_path(k), json.dumps(asdict(rec), sort_keys=True))
    except OSError:
        pass  # a read-only cache is not an error
