"""Derivation results kept on disk (quasicentral.engine.store) and the grouped worker pool
(quasicentral.engine.workers): a result is computed once per code and texts, read back only
while its inputs are unchanged and its file is safe to load; workers keep to their families."""

from __future__ import annotations

import dataclasses
import os
import pickle
import shutil
from pathlib import Path

import pytest
import sympy as sp

from quasicentral.engine import registry, texts
from quasicentral.engine.store import STORE_FOLDER, DerivedStore
from quasicentral.engine.workers import map_grouped, preference_orders

KEPLER = Path(__file__).parent / "data" / "kepler"


@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("QUASICENTRAL_CACHE", str(tmp_path / "cache"))
    yield tmp_path / "cache" / STORE_FOLDER
    texts.reset()


def _open(folder: Path) -> texts.Text:
    texts.reset()
    return texts.activate([texts.open_text(folder)])[0]


def _never(eid: str):
    """Replace the derivation of ``eid`` by one that must not run."""
    def boom():
        """Must not be computed: the kept result is read back."""
        raise AssertionError(f"{eid} was computed again")
    registry.REGISTRY[eid] = dataclasses.replace(registry.REGISTRY[eid], func=boom)


@pytest.fixture
def kepler(tmp_path) -> Path:
    folder = tmp_path / "kepler"
    shutil.copytree(KEPLER, folder)
    return folder


def test_a_result_is_kept_and_read_back_with_what_it_used(kepler, cache):
    _open(kepler)
    first = registry.derived("kepler:2")
    assert len(list(cache.glob("*.pickle"))) == 2  # kepler:2 and the kepler:1 it builds on
    _open(kepler)  # as a new process would: the derivations imported anew, nothing in memory
    _never("kepler:2")
    _never("kepler:1")
    assert registry.derived("kepler:2") == first
    assert registry.actually_used("kepler:2") == {"kepler:1"}


def test_an_edited_text_is_derived_anew(kepler, cache):
    _open(kepler)
    registry.derived("kepler:3")
    orbit = kepler / "orbit.py"
    orbit.write_text(orbit.read_text().replace("T² = 4π²a³/(GM).", "T² = 4π²a³/(GM), edited."))
    _open(kepler)
    _never("kepler:3")
    with pytest.raises(AssertionError, match="computed again"):
        registry.derived("kepler:3")


def test_a_cold_run_derives_anew_and_keeps(kepler, cache):
    _open(kepler)
    registry.derived("kepler:3")
    _open(kepler)
    _never("kepler:3")
    with registry.reading_kept(False), pytest.raises(AssertionError, match="computed again"):
        registry.derived("kepler:3")


@pytest.mark.parametrize("spoil", ["garbage", "group-writable", "symlink"])
def test_a_record_not_safe_to_load_is_computed_anew(kepler, cache, spoil):
    _open(kepler)
    registry.derived("kepler:3")
    (record,) = cache.glob("*.pickle")
    if spoil == "garbage":
        record.write_bytes(b"\x80\x05not a pickle")
    elif spoil == "group-writable":
        record.chmod(0o664)
    else:
        target = record.with_suffix(".elsewhere")
        record.rename(target)
        record.symlink_to(target)
    _open(kepler)
    _never("kepler:3")
    with pytest.raises(AssertionError, match="computed again"):  # not read: computed, no other error
        registry.derived("kepler:3")


def test_the_store_keeps_only_what_it_can_tell_apart(tmp_path, monkeypatch):
    monkeypatch.setenv("QUASICENTRAL_CACHE", str(tmp_path))
    prints = {"t": "fp-t", "u": "fp-u"}
    store = DerivedStore(prints.get, frozenset({"mod"}))
    assert store.keeps("mod.steps") and not store.keeps("other.steps")
    store.save("t:1", sp.Eq(sp.Dummy("x"), 1), (), ())  # a dummy: another process could make an equal one
    assert store.load("t:1") is None
    x = sp.Symbol("x", positive=True)
    store.save("t:2", {x: sp.sqrt(x)}, ["u:1"], ["u:1", "u:0"])
    assert store.load("t:2") == ({x: sp.sqrt(x)}, frozenset({"u:1"}))
    assert DerivedStore({"t": "fp-t", "u": "fp-u, edited"}.get, frozenset()).load("t:2") is None  # built on u
    assert DerivedStore({"t": "fp-t, edited", "u": "fp-u"}.get, frozenset()).load("t:2") is None
    (tmp_path / STORE_FOLDER).chmod(0o777)  # a folder others may write: nothing in it is loaded
    assert store.load("t:2") is None
    (tmp_path / STORE_FOLDER).chmod(0o700)
    assert store.load("t:2") is not None


def test_a_record_is_a_plain_pickle_of_value_uses_and_other_texts(tmp_path, monkeypatch):
    monkeypatch.setenv("QUASICENTRAL_CACHE", str(tmp_path))
    store = DerivedStore({"t": "fp-t", "u": "fp-u"}.get, frozenset())
    store.save("t:1", sp.Integer(3), ["u:1"], ["u:1"])
    (record,) = (tmp_path / STORE_FOLDER).glob("*.pickle")
    assert pickle.loads(record.read_bytes()) == (3, ["u:1"], {"u": "fp-u"})
    assert os.stat(tmp_path / STORE_FOLDER).st_mode & 0o777 == 0o700


# --- the grouped pool ------------------------------------------------------------------------
def test_each_worker_keeps_to_its_groups_then_takes_the_others_from_their_ends():
    orders = preference_orders([[0, 1, 2, 3], [4, 5], [6]], 2)
    assert orders == [[0, 1, 2, 3, 6, 5, 4], [4, 5, 6, 3, 2, 1, 0]]
    for jobs in (1, 2, 3, 5):
        for order in preference_orders([[0, 1, 2], [3], [4, 5, 6, 7], []], jobs):
            assert sorted(order) == list(range(8))


def _square(x: int) -> tuple[int, int]:
    return x, x * x


def test_map_grouped_returns_every_result_once():
    got: dict[int, int] = {}

    def done(item, res):
        assert item not in got
        got[item] = res[1]
    map_grouped(_square, [[1, 2, 3], [4], [5, 6]], 2, done)
    assert got == {x: x * x for x in range(1, 7)}


def _fails_at_three(x: int) -> int:
    if x == 3:
        raise ValueError("three")
    return x


def test_map_grouped_raises_a_workers_exception():
    with pytest.raises(ValueError, match="three"):
        map_grouped(_fails_at_three, [[1, 2, 3, 4], [5, 6]], 2, lambda item, res: None)
