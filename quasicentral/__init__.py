"""quasicentral: re-derive every equation of a text with sympy, check it with mpmath and
python-flint, record the errata.  The layers, from the bottom:

* :mod:`quasicentral.notation` — symbols, dimensions, domains, the sympy → numbers bridge, time limits;
* :mod:`quasicentral.engine` — texts, catalog, derivations registry, checker, verdicts, the run, mutation;
* :mod:`quasicentral.models` — the physical models and their evaluators;
* :mod:`quasicentral.studies` — charts, scenes, figures built on the models;
* :mod:`quasicentral.documents` — the LaTeX printer, reports and handouts;
* :mod:`quasicentral.api` (for notebooks) and :mod:`quasicentral.cli` (the command) on top.
"""

import os

__all__ = ["load_text", "new_text", "shipped_texts", "workspace", "Workspace", "InputError",
           "derives", "derived", "shared", "symbols_of", "Domain", "D"]

#: where each public name lives (imported on first use: a low layer must not pull the API in)
_HOMES = {"load_text": "quasicentral.api", "new_text": "quasicentral.api", "shipped_texts": "quasicentral.api",
          "workspace": "quasicentral.api", "InputError": "quasicentral.api",
          "Workspace": "quasicentral.engine.workspace",
          # what a text's derivation module needs, in one import line
          "derives": "quasicentral.engine.registry", "derived": "quasicentral.engine.registry",
          "shared": "quasicentral.engine.registry", "symbols_of": "quasicentral.engine.texts",
          "Domain": "quasicentral.notation.domain", "D": "quasicentral.notation.symbols"}

# sympy reads the size of its expression cache (an LRU, 1000 entries by default) once, when it is
# first imported.  A derivation or a verification meets the same sub-expressions far more often
# than that: 100 000 entries took a cold verify about 8 % less CPU for ~50 MB more memory.  A
# size the user has set is kept.
SYMPY_CACHE_SIZE = "100000"
os.environ.setdefault("SYMPY_CACHE_SIZE", SYMPY_CACHE_SIZE)


def __getattr__(name: str):
    # lazily: importing a low layer (quasicentral.models, say) must not import the API's engine
    if name in _HOMES:
        import importlib

        return getattr(importlib.import_module(_HOMES[name]), name)
    raise AttributeError(f"module 'quasicentral' has no attribute {name!r}")
