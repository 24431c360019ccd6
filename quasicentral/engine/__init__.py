"""The engine: derivations registry, checker, verdicts, catalog, errata, the run, mutation."""
