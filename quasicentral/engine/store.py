"""Derivation results kept on disk, so that each is computed once per code and texts — not once
per process (the workers of a verification, a mutation run, the documents, the tests).

A result is kept with the ids it used (:func:`quasicentral.engine.registry.actually_used`)
under a hash of what it can depend on: the checker's code and the libraries' versions
(:func:`~quasicentral.engine.fingerprint.code_fingerprint`), the files of its text as they were
when its derivations were imported, the module that derived it and its id.  A derivation may
build on another text's results, through any chain of steps: the record names the hashes of
those texts, and is read back only while they are unchanged.  Only the derivations of a text's
own modules are kept: a step registered by other code (a test's scratch derivation) has no
files to hash.

The records are pickles (sympy's own serialisation: the one that round-trips every result of
the shipped texts exactly, assumptions and undefined functions included).  Loading a pickle
runs code, so a record is read only from a folder and a file of this user that nobody else
may write; a record that cannot be read is computed anew.  A result holding a ``Dummy`` is not
kept: a dummy is told apart by a counter of the process that made it, and another process
could make an equal one.
"""

from __future__ import annotations

import hashlib
import os
import pickle
from pathlib import Path

import sympy as sp

from quasicentral.engine.fingerprint import cache_dir, code_fingerprint
from quasicentral.files import ensure_dir, read_private, write_bytes

STORE_FOLDER = "derived"
PICKLE_PROTOCOL = 5


def _basics(value) -> list[sp.Basic]:
    if isinstance(value, sp.Basic):
        return [value]
    if isinstance(value, sp.MatrixBase):
        return list(value)
    if isinstance(value, dict):
        return [b for kv in value.items() for x in kv for b in _basics(x)]
    if isinstance(value, (list, tuple, set, frozenset)):
        return [b for x in value for b in _basics(x)]
    return []


def _has_dummy(value) -> bool:
    return any(b.has(sp.Dummy) for b in _basics(value))


class DerivedStore:
    """The records of the derivations of the text modules ``modules()`` names (module-name
    prefixes, one per text folder).  ``fingerprint_of(tid)`` hashes a text's files (None: not an active
    text); a record is keyed by the code, its own text's hash and its id, and names the hashes
    of the other texts its result was built on, which must still be the same to be read."""

    def __init__(self, fingerprint_of, modules):
        self._fingerprint = fingerprint_of
        self._modules = modules  # the module prefixes of the texts (a callable: they may grow)

    @property
    def directory(self) -> Path:
        return cache_dir() / STORE_FOLDER  # where the cache is now ($QUASICENTRAL_CACHE may change)

    def keeps(self, module: str) -> bool:
        return module.rpartition(".")[0] in self._modules()

    def _path(self, eid: str, module: str) -> Path | None:
        tid = eid.split(":", 1)[0]
        own = self._fingerprint(tid)
        if own is None:
            return None
        key = hashlib.sha256("\0".join((code_fingerprint(), tid, own, module, eid)).encode()).hexdigest()
        return self.directory / f"{key}.pickle"

    def load(self, eid: str, module: str) -> tuple[object, frozenset[str], frozenset[str]] | None:
        """The kept result of ``eid`` (derived in ``module``), the ids it used and the other
        texts it was built on; None when absent, unreadable, built on a text that has changed
        since, or in a file or folder another user could have written."""
        path = self._path(eid, module)
        data = read_private(self.directory, path.name) if path is not None else None
        if data is None:
            return None
        try:
            value, used, others = pickle.loads(data)
            if any(self._fingerprint(tid) != fp for tid, fp in others.items()):
                return None
            return value, frozenset(used), frozenset(others)
        except Exception:  # noqa: BLE001 - a damaged record is no result: computed anew
            return None

    def save(self, eid: str, module: str, value: object, used, built_on) -> None:
        """Keep ``value``, which used the ids ``used`` and was built on the results of the texts
        ``built_on`` (through any chain of steps).  A result that cannot be kept (a dummy inside,
        no pickle, a read-only cache) is computed again next time."""
        path = self._path(eid, module)
        if path is None or _has_dummy(value):
            return
        own = eid.split(":", 1)[0]
        others = {tid: self._fingerprint(tid) for tid in sorted(set(built_on) - {own})}
        if any(fp is None for fp in others.values()):
            return
        try:
            data = pickle.dumps((value, sorted(used), others), protocol=PICKLE_PROTOCOL)
            ensure_dir(self.directory)
            folder = os.open(self.directory, os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW)
            try:
                os.fchmod(folder, 0o700)
            finally:
                os.close(folder)
            write_bytes(path, data)
        except Exception:  # noqa: BLE001 - keeping a result is an optimisation, never an error
            pass
