"""Derivations as data: small functions that return sympy objects, collected from each text's
modules as pytest collects marked tests.

:func:`derives` only *tags* a function with the catalog ids it settles and how its result
meets the printed form; a text collects the tagged functions of its modules when it is loaded
(:func:`collect`), and a :class:`Derivations` — one per workspace — holds them and their
results.  The modes:

* ``mode="solve"`` — the function returns the derived relation(s) ``Eq(unknown, value)``;
  the printed relation is solved for the same unknown and the two values are compared.
* ``mode="substitute"`` — the function returns a *model*: a dict mapping the motion's functions
  (or symbols) to derived expressions; the printed relation must hold on it (lhs − rhs = 0).
  An empty model checks the printed relation as an identity.
* ``mode="expression"`` — the printed entry is a bare expression; the function returns the
  derived expression.
* ``mode="condition"`` — the printed entry is a condition (``Eq(symbol, value)``); the function
  returns a quantity that must vanish under it (e.g. the torque that a "no drag" condition
  must remove).
* ``mode="identity"`` — the printed relations are checked as they stand, on the entry's
  constraints (an equation side against side, an inequality one-sidedly, an O-term along its
  passage): what a formula collection's entries need no derivation for
  (:mod:`quasicentral.engine.identity`); the function's result is not used.

A derivation calls :func:`derived` for the results it builds on; each call is recorded, so
what a derivation uses is known (``uses=`` may still be declared: it is then checked against
what was used).  :func:`shared` marks a helper that several derivations call: computed once per
arguments per workspace, each caller still recorded as using what the helper used.
"""

from __future__ import annotations

import contextlib
import contextvars
import copy
import functools
import inspect
from dataclasses import dataclass
from enum import Enum
from typing import Callable

import sympy as sp

from quasicentral.notation.domain import Domain

TAG = "__quasicentral_derives__"  # the attribute derives() puts on a function


class Mode(str, Enum):
    """How a derivation's result is compared with the printed transcription."""

    SOLVE = "solve"
    SUBSTITUTE = "substitute"
    EXPRESSION = "expression"
    CONDITION = "condition"
    IDENTITY = "identity"


class RegistryError(ValueError):
    pass


@dataclass(frozen=True)
class Spec:
    """What :func:`derives` says of a function (the tag)."""

    ids: tuple[str, ...]
    mode: Mode
    domain: Domain
    uses: tuple[str, ...]
    unknowns: tuple | None


@dataclass(frozen=True)
class Derivation:
    id: str
    func: Callable[[], object]
    mode: Mode
    domain: Domain
    declared_uses: tuple[str, ...]  # as written in derives(uses=...) (checked against what is used)
    unknowns: tuple | None
    doc: str
    module: str

    @property
    def source(self) -> str:
        """The id of the text the derivation belongs to (its id's prefix)."""
        return self.id.split(":", 1)[0]

    def where(self) -> str:
        """``file:line`` of the derivation's function, for messages."""
        try:
            return f"{inspect.getsourcefile(self.func)}:{inspect.getsourcelines(self.func)[1]}"
        except (OSError, TypeError):
            return self.module


def derives(eid: str, *more: str, mode: Mode | str = Mode.SOLVE, domain: Domain | None = None,
            uses: tuple[str, ...] = (), unknowns: tuple | None = None):
    """Tag the decorated function as the derivation of catalog entry ``eid`` — and of the
    entries ``more``, where the text prints the same relation (or relations that hold on the
    same model) several times: one step, compared with each printed display."""
    try:
        mode = Mode(mode)
    except ValueError:
        raise RegistryError(f"{eid}: unknown mode {mode!r} (one of: {', '.join(m.value for m in Mode)})") from None
    if isinstance(uses, str):
        uses = (uses,)

    def deco(func):
        if not (func.__doc__ or "").strip():
            raise RegistryError(f"{eid}: a derivation states its formula in a docstring")
        tags = getattr(func, TAG, ())
        setattr(func, TAG, tags + (Spec((eid, *more), mode, domain or Domain(), tuple(uses), unknowns),))
        return func

    return deco


def collect(module) -> list[Derivation]:
    """The derivations a module's functions are tagged with, in the order they are defined."""
    found = []
    for obj in vars(module).values():
        if callable(obj) and getattr(obj, "__module__", None) == module.__name__ and getattr(obj, TAG, None):
            found.append(obj)
    found.sort(key=lambda f: getattr(getattr(f, "__code__", None), "co_firstlineno", 0))
    out = []
    for func in found:
        for spec in getattr(func, TAG):
            for one in spec.ids:
                out.append(Derivation(one, func, spec.mode, spec.domain, spec.uses, spec.unknowns,
                                      inspect.cleandoc(func.__doc__), module.__name__))
    return out


#: the Derivations whose derivation is being computed in this context (derived() asks it)
_CURRENT: contextvars.ContextVar["Derivations | None"] = contextvars.ContextVar("quasicentral_derivations",
                                                                                default=None)


def derived(eid: str):
    """The result of the derivation of ``eid`` (inside a derivation, or while a workspace's
    derivations are being computed)."""
    current = _CURRENT.get()
    if current is None:
        raise RegistryError(f"derived({eid!r}) is called inside a derivation: open the text in a workspace "
                            "(quasicentral.load_text) and ask it for the result")
    return current.result(eid)


def shared(func):
    """A helper that several derivations call (a general solution, a table of constants):
    computed once per arguments in a workspace, while each derivation that calls it is still
    recorded as using what the helper asked :func:`derived` for — as if it had computed it
    itself.  The helper must be a function of its (hashable) arguments and of derived results
    only; a returned dict or list is copied for each caller."""
    @functools.wraps(func)
    def helper(*args):
        current = _CURRENT.get()
        if current is None:
            return func(*args)
        return current.shared(helper, func, args)
    return helper


class Derivations:
    """The derivations of a workspace's texts and their results, each computed once.

    ``store`` (a :class:`quasicentral.engine.store.DerivedStore`, or None) keeps results on
    disk for the next process; ``read_kept=False`` computes every result anew (a cold run) and
    still keeps it."""

    def __init__(self, store=None, read_kept: bool = True, loader=None):
        self.by_id: dict[str, Derivation] = {}
        self.store = store
        self.read_kept = read_kept
        self.loader = loader  # loader(text id): make that text's derivations known (a text built on)
        self._results: dict[str, object] = {}
        self._failed: dict[str, BaseException] = {}
        self._used: dict[str, set[str]] = {}
        self._texts: dict[str, set[str]] = {}  # the texts each result was built on, its own included
        self._stack: list = []  # the derivations (and shared helpers) being computed, innermost last
        self._shared: dict = {}

    # --- the derivations -----------------------------------------------------------------
    def add(self, derivation: Derivation) -> None:
        if derivation.id in self.by_id:
            other = self.by_id[derivation.id]
            raise RegistryError(f"{derivation.where()}: a second derivation for {derivation.id!r} "
                                f"(the first: {other.where()})")
        self.by_id[derivation.id] = derivation

    def remove_text(self, tid: str) -> None:
        """Forget the derivations and results of the text ``tid`` (and every result built on it)."""
        for eid in [e for e in self.by_id if e.split(":", 1)[0] == tid]:
            self.by_id.pop(eid)
        for eid in [e for e, built in self._texts.items() if tid in built] + [
                e for e in list(self._results) if e.split(":", 1)[0] == tid]:
            for memo in (self._results, self._used, self._texts, self._failed):
                memo.pop(eid, None)
        self._shared.clear()

    def get(self, eid: str) -> Derivation | None:
        return self.by_id.get(eid)

    def __contains__(self, eid: str) -> bool:
        return eid in self.by_id

    # --- results ---------------------------------------------------------------------------
    @contextlib.contextmanager
    def current(self):
        """Make this the collection :func:`derived` asks, for the block."""
        token = _CURRENT.set(self)
        try:
            yield self
        finally:
            _CURRENT.reset(token)

    def result(self, eid: str):
        """The (memoized) result of the derivation of ``eid``; the exception it raised, again,
        where it failed."""
        if self._stack:
            self._used.setdefault(self._stack[-1], set()).add(eid)
        if eid in self._failed:
            raise self._failed[eid]
        if eid not in self._results:
            der = self.by_id.get(eid)
            if der is None and self.loader is not None:
                self.loader(eid.split(":", 1)[0])
                der = self.by_id.get(eid)
            if der is None:
                raise RegistryError(f"no derivation registered for {eid!r}")
            with self.current():
                self._compute(der)
        return self._results[eid]

    def _compute(self, der: Derivation) -> None:
        eid = der.id
        twin = next((e for e in self._results if self.by_id.get(e) is not None and self.by_id[e].func is der.func), None)
        if twin is not None:  # one step, several displays
            self._results[eid] = self._results[twin]
            self._used[eid] = set(self._used.get(twin, ()))
            self._texts[eid] = set(self._texts.get(twin, {der.source}))
            return
        store = self.store if self.store is not None and self.store.keeps(der.module) else None
        kept = store.load(eid, der.module) if store is not None and self.read_kept else None
        if kept is not None:
            self._results[eid], used, built_on = kept
            self._used[eid] = set(used)
            self._texts[eid] = {der.source} | set(built_on)
            return
        self._stack.append(eid)
        try:
            value = der.func()
        except KeyboardInterrupt:
            raise
        except BaseException as exc:  # its failure (an exception, sys.exit, its time running out) stands
            self._failed[eid] = exc
            raise
        finally:
            self._stack.pop()
        self._results[eid] = value
        self._texts[eid] = {der.source}.union(*(self._texts.get(u, {u.split(":", 1)[0]})
                                                for u in self._used.get(eid, ())))
        if store is not None:
            store.save(eid, der.module, value, self._used.get(eid, ()), self._texts[eid])

    def shared(self, helper, func, args):
        key = (helper, args)
        if key not in self._shared:
            frame = ("shared", helper, args)
            self._stack.append(frame)
            try:
                value = func(*args)
            finally:
                self._stack.pop()
            self._shared[key] = (value, frozenset(self._used.pop(frame, ())))
        value, used = self._shared[key]
        if self._stack and used:
            self._used.setdefault(self._stack[-1], set()).update(used)
        return copy.copy(value) if isinstance(value, (dict, list)) else value

    def known(self, eid: str) -> bool:
        """Whether the result of ``eid`` (or its failure) is at hand, without computing it."""
        return eid in self._results or eid in self._failed

    def inject(self, eid: str, value, used, built_on) -> None:
        """A result computed elsewhere (a worker process), with what it used and was built on."""
        self._results[eid] = value
        self._used[eid] = set(used)
        self._texts[eid] = set(built_on)

    def note_failure(self, eid: str, error: str) -> None:
        """A derivation that failed elsewhere: asking for its result raises that failure."""
        self._failed[eid] = RuntimeError(error)

    def note_built_on(self, eid: str, texts) -> None:
        """The texts a result was built on, as its verdict's record says (where the result itself
        was not computed in this process)."""
        if eid not in self._texts:
            self._texts[eid] = set(texts)

    def known_built_on(self, eid: str) -> frozenset[str] | None:
        """The texts the result of ``eid`` was built on, if known here (nothing is computed)."""
        got = self._texts.get(eid)
        return frozenset(got) if got is not None else None

    def used(self, eid: str) -> frozenset[str]:
        """The ids whose results the derivation of ``eid`` asked for (after it has run)."""
        self.result(eid)
        return frozenset(self._used.get(eid, ()))

    def built_on(self, eid: str) -> frozenset[str]:
        """The texts the result of ``eid`` was built on (its own included), through any chain."""
        self.result(eid)
        return frozenset(self._texts.get(eid, {eid.split(":", 1)[0]}))


def as_list(obj) -> list:
    if isinstance(obj, (list, tuple, sp.Tuple)):
        return list(obj)
    return [obj]
