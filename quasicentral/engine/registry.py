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
may call :func:`derived` on another id.
"""

from __future__ import annotations

import inspect
from dataclasses import dataclass
from typing import Callable

import sympy as sp

from quasicentral.notation.domain import Domain

MODES = ("solve", "substitute", "expression", "condition")


@dataclass(frozen=True)
class Derivation:
    id: str
    func: Callable[[], object]
    mode: str
    domain: Domain
    uses: tuple[str, ...]
    unknowns: tuple | None
    doc: str
    module: str

    def source(self) -> str:
        return inspect.getsource(self.func)


REGISTRY: dict[str, Derivation] = {}
_MEMO: dict[str, object] = {}


class RegistryError(ValueError):
    pass


def derives(eid: str, *, mode: str = "solve", domain: Domain | None = None, uses: tuple[str, ...] = (),
            unknowns: tuple | None = None):
    """Register the decorated function as the derivation of catalog entry ``eid``."""
    if mode not in MODES:
        raise RegistryError(f"{eid}: unknown mode {mode!r}")

    def deco(func):
        if eid in REGISTRY:
            raise RegistryError(f"duplicate derivation for {eid!r} ({func.__module__}.{func.__name__})")
        if not (func.__doc__ or "").strip():
            raise RegistryError(f"{eid}: a derivation states its formula in a docstring")
        REGISTRY[eid] = Derivation(eid, func, mode, domain or Domain(), tuple(uses), unknowns,
                                   inspect.cleandoc(func.__doc__), func.__module__)
        return func

    return deco


def derived(eid: str):
    """The (memoized) result of the derivation of ``eid``."""
    if eid not in _MEMO:
        if eid not in REGISTRY:
            raise RegistryError(f"no derivation registered for {eid!r}")
        _MEMO[eid] = REGISTRY[eid].func()
    return _MEMO[eid]


def load_all() -> dict[str, Derivation]:
    """Import every derivation module (they register themselves)."""
    import derivations  # noqa: F401

    derivations.load()
    return REGISTRY


def as_list(obj) -> list:
    if isinstance(obj, (list, tuple, sp.Tuple)):
        return list(obj)
    return [obj]
