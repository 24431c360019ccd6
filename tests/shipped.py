"""The shipped texts for the tests: one workspace per test process, their modules and results.

A test that calls a shipped derivation module's helpers (which ask ``derived()`` for results)
runs inside :func:`context`, the workspace's derivations made current.
"""

from __future__ import annotations

from functools import lru_cache

from quasicentral.engine.workspace import Workspace


@lru_cache(maxsize=1)
def workspace() -> Workspace:
    ws = Workspace()
    ws.load(ws.papers())
    return ws


def text(tid: str):
    return workspace().text(tid)


def module(tid: str, stem: str):
    """A shipped text's derivation module, as the workspace imported it."""
    t = text(tid)
    return t.module(t.root / f"{stem}.py")


def derived(eid: str):
    return workspace().result(eid)


def symbols(tid: str):
    return text(tid).symbols


def context():
    """The shipped workspace's derivations made current (for a module's helpers)."""
    return workspace().derivations.current()


def entry(eid: str):
    return workspace().entry(eid)


def derivation(eid: str):
    return workspace().derivation(eid)


def records():
    """The errata and the cleared suspects of the shipped texts, merged (by id)."""
    errata, cleared = {}, {}
    for t in workspace().papers():
        errata.update(t.errata)
        cleared.update(t.cleared)
    return errata, cleared


def check(printed, dims, der, label, opts, table):
    """The checker on ``printed`` against a shipped derivation (its result computed here)."""
    from quasicentral.engine.checker import check as checker

    return checker(printed, dims, der, label, opts, table, derived(der.id))
