"""Shared fixtures: one verification run of the whole catalog per test session (cold, in a
temporary cache, on all cores); the parametrized tests then read their own outcome."""

import pytest

from quasicentral import catalog
from quasicentral.check import Options


@pytest.fixture(scope="session")
def outcomes(tmp_path_factory):
    import os

    from quasicentral import verify

    os.environ["QUASICENTRAL_CACHE"] = str(tmp_path_factory.mktemp("cache"))
    entries = catalog.entries()
    return dict(zip([e.id for e in entries], verify.run(entries, Options(), use_cache=False)))
