"""Derivations as data: a registry of small functions that return sympy objects.

A derivation settles one catalog entry.  It is registered with :func:`derives`, which refuses
duplicates, and says how its result is compared with the printed transcription:

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

``uses`` cites the equation ids a derivation builds on.  Results are memoized: a derivation
may call :func:`derived` on another id, and each such call is recorded
(:func:`actually_used`), so that the declared ``uses`` can be checked against what was used.
"""

from __future__ import annotations

import contextlib
import copy
import functools
import inspect
from dataclasses import dataclass
from enum import Enum
from typing import Callable

import sympy as sp

from quasicentral.notation.domain import Domain


class Mode(str, Enum):
    """How a derivation's result is compared with the printed transcription."""

    SOLVE = "solve"
    SUBSTITUTE = "substitute"
    EXPRESSION = "expression"
    CONDITION = "condition"


@dataclass(frozen=True)
class Derivation:
    id: str
    func: Callable[[], object]
    mode: Mode
    domain: Domain
    uses: tuple[str, ...]
    unknowns: tuple | None
    doc: str
    module: str

    def source(self) -> str:
        return inspect.getsource(self.func)

    @property
    def text(self) -> str:
        """The id of the text the derivation belongs to (its id's prefix)."""
        return self.id.split(":", 1)[0]

    def where(self) -> str:
        """``file:line`` of the derivation's function, for messages."""
        try:
            return f"{inspect.getsourcefile(self.func)}:{inspect.getsourcelines(self.func)[1]}"
        except (OSError, TypeError):
            return self.module


REGISTRY: dict[str, Derivation] = {}
_MEMO: dict[str, object] = {}
_USED: dict[str, set[str]] = {}
_TEXTS: dict[str, set[str]] = {}  # the texts each result was built on, its own included (through any chain)
_STACK: list = []  # the derivations (and shared helpers) being computed, innermost last
_GENERATION = [0]  # counts changes of the registry: a shared helper's results are kept per generation


class RegistryError(ValueError):
    pass


def derives(eid: str, *more: str, mode: Mode | str = Mode.SOLVE, domain: Domain | None = None,
            uses: tuple[str, ...] = (), unknowns: tuple | None = None):
    """Register the decorated function as the derivation of catalog entry ``eid`` — and of the
    entries ``more``, where the text prints the same relation (or relations that hold on the
    same model) several times: one step, compared with each printed display."""
    try:
        mode = Mode(mode)
    except ValueError:
        raise RegistryError(f"{eid}: unknown mode {mode!r} (one of: {', '.join(m.value for m in Mode)})") from None

    def deco(func):
        if not (func.__doc__ or "").strip():
            raise RegistryError(f"{eid}: a derivation states its formula in a docstring")
        for one in (eid, *more):
            if one in REGISTRY:
                raise RegistryError(f"duplicate derivation for {one!r} ({func.__module__}.{func.__name__})")
            REGISTRY[one] = Derivation(one, func, mode, domain or Domain(), tuple(uses), unknowns,
                                       inspect.cleandoc(func.__doc__), func.__module__)
        _GENERATION[0] += 1
        return func

    return deco


def derived(eid: str):
    """The (memoized) result of the derivation of ``eid``."""
    if _STACK:
        _USED.setdefault(_STACK[-1], set()).add(eid)
    if eid not in _MEMO:
        if eid not in REGISTRY:
            raise RegistryError(f"no derivation registered for {eid!r}")
        func = REGISTRY[eid].func
        twin = next((e for e in _MEMO if REGISTRY[e].func is func), None)  # one step, several displays
        der = REGISTRY[eid]
        store = _STORE[0] if _STORE[0] is not None and _STORE[0].keeps(der.module) else None
        kept = store.load(eid, der.module) if store is not None and twin is None and _READ[0] else None
        if twin is not None:
            _MEMO[eid] = _MEMO[twin]
            _USED[eid] = set(_USED.get(twin, ()))
            _TEXTS[eid] = set(_TEXTS.get(twin, {der.text}))
        elif kept is not None:
            _MEMO[eid], used, built_on = kept
            _USED[eid] = set(used)
            _TEXTS[eid] = {der.text} | set(built_on)
        else:
            _STACK.append(eid)
            try:
                _MEMO[eid] = func()
            finally:
                _STACK.pop()
            _TEXTS[eid] = {der.text}.union(*(_TEXTS.get(u, {u.split(":", 1)[0]}) for u in _USED.get(eid, ())))
            if store is not None:
                store.save(eid, der.module, _MEMO[eid], _USED.get(eid, ()), _TEXTS[eid])
    return _MEMO[eid]


_STORE: list = [None]  # the DerivedStore of the active texts (quasicentral.engine.store), if any
_READ = [True]  # whether kept results are read back


def use_store(store):
    """Keep results in ``store`` (a :class:`quasicentral.engine.store.DerivedStore`) and read
    them back from it; None: compute every result in this process.  Returns the store used
    before."""
    before, _STORE[0] = _STORE[0], store
    return before


@contextlib.contextmanager
def reading_kept(read: bool):
    """With ``read=False`` (a cold run), every result is computed anew in this process (and its
    forked workers), and still kept for the next."""
    before = _READ[0]
    _READ[0] = before and read
    try:
        yield
    finally:
        _READ[0] = before


def shared(func):
    """A helper that several derivations call (a general solution, a table of constants):
    computed once per arguments, while each derivation that calls it is still recorded as
    using what the helper asked :func:`derived` for — as if it had computed it itself.  The
    helper must be a function of its (hashable) arguments and of derived results only; a
    returned dict or list is copied for each caller."""
    results: dict[tuple, tuple[object, frozenset]] = {}

    @functools.wraps(func)
    def helper(*args):
        key = (_GENERATION[0], args)
        if results and next(iter(results))[0] != key[0]:
            results.clear()  # the registry changed since: every result is computed anew
        if key not in results:
            frame = ("shared", func, args)
            _STACK.append(frame)
            try:
                value = func(*args)
            finally:
                _STACK.pop()
            results[key] = (value, frozenset(_USED.pop(frame, ())))
        value, used = results[key]
        if _STACK and used:
            _USED.setdefault(_STACK[-1], set()).update(used)
        return copy.copy(value) if isinstance(value, (dict, list)) else value
    return helper


def actually_used(eid: str) -> frozenset[str]:
    """The ids whose results the derivation of ``eid`` asked for (after it has run)."""
    derived(eid)
    return frozenset(_USED.get(eid, ()))


def unregister_module(module: str) -> None:
    """Forget the derivations a module registered (before another file of that name is
    imported in its place: a copy of a text, or the text's folder read anew)."""
    for eid in [e for e, d in REGISTRY.items() if d.module == module]:
        REGISTRY.pop(eid)
        _MEMO.pop(eid, None)
        _USED.pop(eid, None)
        _TEXTS.pop(eid, None)
    _GENERATION[0] += 1


def unregister(prefix: str) -> None:
    """Forget every derivation of the text ``prefix`` (before its modules are imported anew)."""
    for eid in [e for e in REGISTRY if e.split(":", 1)[0] == prefix]:
        REGISTRY.pop(eid)
        _MEMO.pop(eid, None)
        _USED.pop(eid, None)
        _TEXTS.pop(eid, None)
    _GENERATION[0] += 1


def as_list(obj) -> list:
    if isinstance(obj, (list, tuple, sp.Tuple)):
        return list(obj)
    return [obj]
