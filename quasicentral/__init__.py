"""quasicentral: re-derive every equation of a text with sympy, check it with mpmath and
python-flint, record the errata.  The layers, from the bottom:

* :mod:`quasicentral.notation` — symbols, dimensions, domains, the sympy → numbers bridge, time limits;
* :mod:`quasicentral.engine` — texts, catalog, derivations registry, checker, verdicts, the run, mutation;
* :mod:`quasicentral.models` — the physical models and their evaluators;
* :mod:`quasicentral.studies` — charts, scenes, figures built on the models;
* :mod:`quasicentral.documents` — the LaTeX printer, reports and handouts;
* :mod:`quasicentral.api` (for notebooks) and :mod:`quasicentral.cli` (the command) on top.
"""

__all__ = ["load_text", "new_text", "shipped_texts"]


def __getattr__(name: str):
    # lazily: importing a low layer (quasicentral.models, say) must not import the API's engine
    if name in __all__:
        from quasicentral import api

        return getattr(api, name)
    raise AttributeError(f"module 'quasicentral' has no attribute {name!r}")
