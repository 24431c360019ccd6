"""The workspace: the state of one session — the texts it opened, their derivations and
results, the caches — as mpmath hangs everything on its context.

Nothing is kept in module globals: a notebook may hold several workspaces, and each holds
any number of texts at once; a command line run makes one.  Texts are opened by folder or by
a shipped text's id; their ``.py`` modules run only when their derivations are needed
(:meth:`Workspace.load`).

>>> ws = Workspace()
>>> [t.id for t in ws.shipped()]
['brepta1953', 'dlmf-19', 'dlmf-22', 'pendulum']
>>> [t.id for t in ws.papers()]   # what a command works on when no text is named
['brepta1953', 'pendulum']
"""

from __future__ import annotations

import os
from dataclasses import replace
from pathlib import Path

from quasicentral.engine import catalog
from quasicentral.engine.registry import Derivation, Derivations
from quasicentral.engine.store import DerivedStore
from quasicentral.engine.fingerprint import shipped_folders
from quasicentral.engine.texts import Text, TextError, open_text


class Workspace:
    """Texts, their derivations and results, and where results are kept.

    ``keep`` (default True) keeps derivation results on disk for the next process (the cache's
    ``derived/`` folder); ``read_kept=False`` computes every result anew in this process (a
    cold run) and still keeps it."""

    def __init__(self, keep: bool = True, read_kept: bool = True):
        self._by_root: dict[Path, Text] = {}
        self._by_id: dict[str, Text] = {}
        self._loaded: set[str] = set()
        self._surveyed: dict[str, dict[str, Derivation]] = {}  # text id -> its derivations described, by a child
        self._survey_pid: int | None = None
        store = DerivedStore(self._fingerprint_of, self._module_prefixes) if keep else None
        self.derivations = Derivations(store, read_kept, loader=self._load_text)

    # --- texts ---------------------------------------------------------------------------------
    def open(self, folder: str | Path) -> Text:
        """The text in ``folder`` (read once per workspace)."""
        root = Path(folder).expanduser().resolve()
        if root in self._by_root:
            return self._by_root[root]
        text = open_text(root)
        other = self._by_id.get(text.id)
        if other is not None:
            raise TextError(f"{root / 'text.toml'}: id {text.id!r} is already the id of {other.root}")
        self._by_root[root] = text
        self._by_id[text.id] = text
        return text

    def shipped(self) -> list[Text]:
        """The texts shipped with the package, by id."""
        return sorted((self.open(p) for p in shipped_folders()), key=lambda t: t.id)

    def papers(self) -> list[Text]:
        """The shipped texts a command works on when none is named: all but the formula
        collections (DLMF's chapters, ``check = "identity"``), which are named with ``--text``."""
        return sorted((self.open(p) for p in shipped_folders(collections=False)), key=lambda t: t.id)

    def resolve(self, specs: list[str] | None) -> list[Text]:
        """Texts named by folder or by a shipped text's id; none named: the shipped papers."""
        if not specs:
            return self.papers()
        out: list[Text] = []
        for spec in specs:
            if not isinstance(spec, (str, Path)) or not str(spec).strip():
                raise TextError("an empty name: give a text's folder or a shipped text's id")
            spec = str(spec)
            path = Path(spec).expanduser()
            if path.exists() or "/" in spec or spec.startswith("."):
                text = self.open(path)
            else:
                text = self._shipped_by_id(spec)
                if text is None:
                    raise TextError(f"{spec}: no such folder, and no shipped text is called so "
                                    f"({', '.join(sorted(t.id for t in self.shipped()))})")
            if text not in out:
                out.append(text)
        return out

    def _shipped_by_id(self, tid: str) -> Text | None:
        if tid in self._by_id:
            return self._by_id[tid]
        return next((t for t in self.shipped() if t.id == tid), None)

    def text(self, tid: str) -> Text:
        """The open text ``tid`` (a shipped text is opened on first use)."""
        found = self._by_id.get(tid) or self._shipped_by_id(tid)
        if found is None:
            raise KeyError(f"no text {tid!r} is open")
        return found

    @property
    def texts(self) -> list[Text]:
        """The texts open in this workspace, in the order they were opened."""
        return list(self._by_id.values())

    def entry(self, eid: str) -> catalog.Entry:
        """The catalog entry ``eid`` of an open text."""
        text = self.text(eid.split(":", 1)[0])
        if eid not in text.entries:
            raise KeyError(f"unknown equation id {eid!r}")
        return text.entries[eid]

    # --- derivations ---------------------------------------------------------------------------
    def load(self, texts: list[Text]) -> list[Text]:
        """Import the derivation modules of ``texts`` (once) and add their derivations."""
        for t in texts:
            if t.id not in self._loaded:
                t.import_modules(self.derivations)
                self._loaded.add(t.id)
        return texts

    def survey(self, texts: list[Text], seconds: float = 120.0) -> None:
        """Learn which entries of ``texts`` have derivations, and in which modules, without
        running a folder's code in this process: a user's modules are imported in a child
        process (bounded by ``seconds``; a module that ends the process, hangs or fails is a
        :class:`TextError` naming it), the shipped texts' here (they are the package's own)."""
        from quasicentral.engine.registry import Derivations as Fresh
        from quasicentral.engine.workers import GRACE_SECONDS, Lost, in_child
        from quasicentral.notation.timelimit import CPU, WALL, time_limit

        for t in texts:
            if t.id in self._loaded or t.id in self._surveyed:
                continue
            if t.is_shipped:
                self.load([t])
                continue

            def collect(t=t):
                ds = Fresh()
                with time_limit(seconds, WALL), time_limit(seconds, CPU):
                    t.import_modules(ds)
                # what this process may know of each derivation: everything but its function
                return {eid: replace(d, func=None) for eid, d in ds.by_id.items()}
            try:
                self._surveyed[t.id] = in_child(collect, seconds + GRACE_SECONDS)
            except Lost as exc:
                raise TextError(f"{t.root}: importing the text's modules {exc} (--timeout bounds it)") from None
            self._survey_pid = os.getpid()
            t.loaded_fingerprint = t.fingerprint()

    def _runs_code_here(self, tid: str) -> bool:
        """A surveyed text's modules are imported only in other processes (the workers forked
        from this one), never in the process that surveyed them."""
        return tid not in self._surveyed or os.getpid() != self._survey_pid

    def module_of(self, eid: str) -> str | None:
        """The module of the derivation of ``eid`` (surveyed or loaded), else None."""
        d = self.derivation(eid)
        return d.module if d is not None else None

    def has_derivation(self, eid: str) -> bool:
        return self.module_of(eid) is not None

    def derivation(self, eid: str) -> Derivation | None:
        """The derivation of ``eid``: the one its module defines, or — in the process that
        surveyed its text without running its code — its description (``func`` None)."""
        tid = eid.split(":", 1)[0]
        if not self._runs_code_here(tid):
            return self._surveyed[tid].get(eid)
        self._ensure(eid)
        return self.derivations.get(eid)

    def result(self, eid: str):
        """The result of the derivation of ``eid`` (computed, brought back from a worker, or read
        back from the store)."""
        if not self.derivations.known(eid):
            self._ensure(eid)
        return self.derivations.result(eid)

    def used(self, eid: str) -> frozenset[str]:
        if not self.derivations.known(eid):
            self._ensure(eid)
        return self.derivations.used(eid)

    def built_on(self, eid: str) -> frozenset[str]:
        if not self.derivations.known(eid):
            self._ensure(eid)
        return self.derivations.built_on(eid)

    def _ensure(self, eid: str) -> None:
        tid = eid.split(":", 1)[0]
        if tid not in self._loaded:
            if not self._runs_code_here(tid):
                raise TextError(f"{eid}: the result is not at hand, and the text's code does not run in "
                                "this process (its workers compute it)")
            try:
                self.load([self.text(tid)])
            except KeyError:
                pass  # no such text: the derivations say so

    def _load_text(self, tid: str) -> None:
        """A text another's derivation builds on: its derivations loaded where they may run."""
        try:
            text = self.text(tid)
        except KeyError:
            return
        if tid not in self._loaded and self._runs_code_here(tid):
            self.load([text])

    def forget(self, text: Text) -> None:
        """Drop ``text`` (its derivations and results, and every result built on it), so that
        the next :meth:`open` reads the folder anew — after its files were edited."""
        self._by_root.pop(text.root, None)
        if self._by_id.get(text.id) is text:
            self._by_id.pop(text.id)
        self._loaded.discard(text.id)
        self._surveyed.pop(text.id, None)
        self.derivations.remove_text(text.id)

    # --- what the store keys results by ----------------------------------------------------
    def _fingerprint_of(self, tid: str) -> str | None:
        t = self._by_id.get(tid)
        if t is None or tid not in self._loaded:
            return None
        return t.loaded_fingerprint

    def _module_prefixes(self) -> frozenset[str]:
        return frozenset(t.module_prefix for t in self._by_id.values())
