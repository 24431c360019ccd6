"""Derivations of both texts, one module per section, in the texts' order.

Each module registers its steps with :func:`quasicentral.registry.derives`; importing
:func:`load` imports them all.
"""

import importlib

MODULES = (
    "derivations.brepta1953_s2",
    "derivations.brepta1953_s3",
    "derivations.brepta1953_s4",
    "derivations.brepta1953_s5",
    "derivations.pendulum",
)


def load() -> None:
    for name in MODULES:
        importlib.import_module(name)
