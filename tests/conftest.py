"""Shared fixtures: one verification run of the whole catalog per test session (cold, in a
temporary cache, on all cores); the parametrized tests then read their own outcome.  Under
pytest-xdist the first worker computes it and the others read the same verdict cache."""

import os
import shutil
from pathlib import Path

import pytest
from hypothesis import settings

from quasicentral.engine.checker import Options

# tests/data holds texts (a derivation module registers itself when imported): never collected,
# not even for doctests
collect_ignore = ["data"]

# Property tests explore at random on a developer's machine (where they found, e.g., the loss of
# digits of mpmath's ellipe near m = 1) and replay a fixed sequence in CI, so that a landing never
# depends on the draw.  Their failures are kept as @example regressions.
settings.register_profile("ci", derandomize=True, print_blob=True)
settings.load_profile("ci" if os.environ.get("CI") else "default")

# pytest-xdist (--dist loadfile) hands out whole files in the order they were collected: the
# longest file (every document generated and compiled, about a third of the run) goes first, so
# that the other worker works through the rest meanwhile instead of waiting for it at the end
LONGEST_FIRST = ("test_report.py",)


def pytest_collection_modifyitems(config, items):
    items.sort(key=lambda item: item.path.name not in LONGEST_FIRST)  # stable: otherwise as collected


@pytest.fixture(scope="session", autouse=True)
def session_cache(tmp_path_factory, worker_id):
    """One cache for the whole session, shared by the xdist workers and the processes they
    start (never the user's own): a derivation computed by one of them is read back by the
    others (quasicentral.engine.store); a test that needs a cold cache sets its own."""
    path = _session_dir(tmp_path_factory, worker_id) / "verdict-cache"
    before = os.environ.get("QUASICENTRAL_CACHE")
    os.environ["QUASICENTRAL_CACHE"] = str(path)
    yield path
    if before is None:
        os.environ.pop("QUASICENTRAL_CACHE", None)
    else:
        os.environ["QUASICENTRAL_CACHE"] = before


@pytest.fixture(scope="session")
def outcomes(session_cache, tmp_path_factory, worker_id):
    from filelock import FileLock

    from quasicentral.engine import run
    import shipped

    shared = _session_dir(tmp_path_factory, worker_id)
    ws = shipped.workspace()
    entries = [e for t in ws.papers() for e in t.entries.values()]
    with FileLock(str(shared / "verdict-cache.lock")):
        # cold verdicts for the first worker (derivations other tests kept are read back),
        # read back by the others
        got = run.run(ws, entries, Options(), use_cache=True)
    return dict(zip([e.id for e in entries], got))


@pytest.fixture(scope="session")
def verdict_cache(outcomes, tmp_path_factory, worker_id):
    """The session's cache, holding every shipped entry's verdict (see ``outcomes``): a test
    that needs the shipped texts' verdicts but does not test their computation reads them back
    from here."""
    return _session_dir(tmp_path_factory, worker_id) / "verdict-cache"


def _session_dir(tmp_path_factory, worker_id):
    """One directory for the whole session: the parent of the xdist workers' own folders."""
    return tmp_path_factory.getbasetemp() if worker_id == "master" else tmp_path_factory.getbasetemp().parent


@pytest.fixture
def kepler(tmp_path) -> Path:
    """A copy of the third text (tests/data/kepler), the user's own, to edit at will."""
    folder = tmp_path / "kepler"
    shutil.copytree(Path(__file__).parent / "data" / "kepler", folder)
    return folder
