"""Derivation results kept on disk (quasicentral.engine.store) and the grouped worker pool
(quasicentral.engine.workers): a result is computed once per code and texts, read back only
while its inputs are unchanged and its file is safe to load; workers keep to their families."""

from __future__ import annotations

import dataclasses
import os
import pickle
from pathlib import Path

import pytest
import sympy as sp

from quasicentral.engine import registry
from quasicentral.engine.registry import Derivations
from quasicentral.engine.store import STORE_FOLDER, DerivedStore
from quasicentral.engine.workspace import Workspace
from quasicentral.notation.domain import Domain
from quasicentral.engine.workers import map_grouped, preference_orders



@pytest.fixture
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("QUASICENTRAL_CACHE", str(tmp_path / "cache"))
    yield tmp_path / "cache" / STORE_FOLDER


def _open(folder: Path, read_kept: bool = True) -> Workspace:
    """The text in a new workspace, as a new process would open it: nothing in memory."""
    ws = Workspace(read_kept=read_kept)
    ws.load([ws.open(folder)])
    return ws


def _never(ws: Workspace, eid: str):
    """Replace the derivation of ``eid`` by one that must not run."""
    def boom():
        """Must not be computed: the kept result is read back."""
        raise AssertionError(f"{eid} was computed again")
    ws.derivations.by_id[eid] = dataclasses.replace(ws.derivations.by_id[eid], func=boom)


def test_a_result_is_kept_and_read_back_with_what_it_used(kepler, cache):
    first = _open(kepler).result("kepler:2")
    assert len(list(cache.glob("*.pickle"))) == 2  # kepler:2 and the kepler:1 it builds on
    ws = _open(kepler)  # as a new process would: the derivations imported anew, nothing in memory
    _never(ws, "kepler:2")
    _never(ws, "kepler:1")
    assert ws.result("kepler:2") == first
    assert ws.used("kepler:2") == {"kepler:1"}


def test_an_edited_text_is_derived_anew(kepler, cache):
    _open(kepler).result("kepler:3")
    orbit = kepler / "orbit.py"
    orbit.write_text(orbit.read_text().replace("T² = 4π²a³/(GM).", "T² = 4π²a³/(GM), edited."))
    ws = _open(kepler)
    _never(ws, "kepler:3")
    with pytest.raises(AssertionError, match="computed again"):
        ws.result("kepler:3")


def test_a_cold_run_derives_anew_and_keeps(kepler, cache):
    _open(kepler).result("kepler:3")
    ws = _open(kepler, read_kept=False)
    _never(ws, "kepler:3")
    with pytest.raises(AssertionError, match="computed again"):
        ws.result("kepler:3")


@pytest.mark.parametrize("spoil", ["garbage", "group-writable", "symlink"])
def test_a_record_not_safe_to_load_is_computed_anew(kepler, cache, spoil):
    _open(kepler).result("kepler:3")
    (record,) = cache.glob("*.pickle")
    if spoil == "garbage":
        record.write_bytes(b"\x80\x05not a pickle")
    elif spoil == "group-writable":
        record.chmod(0o664)
    else:
        target = record.with_suffix(".elsewhere")
        record.rename(target)
        record.symlink_to(target)
    ws = _open(kepler)
    _never(ws, "kepler:3")
    with pytest.raises(AssertionError, match="computed again"):  # not read: computed, no other error
        ws.result("kepler:3")


def test_the_store_keeps_only_what_it_can_tell_apart(tmp_path, monkeypatch):
    monkeypatch.setenv("QUASICENTRAL_CACHE", str(tmp_path))
    prints = {"t": "fp-t", "u": "fp-u"}
    store = DerivedStore(prints.get, lambda: frozenset({"mod"}))
    assert store.keeps("mod.steps") and not store.keeps("other.steps")
    store.save("t:1", "mod.steps", sp.Eq(sp.Dummy("x"), 1), (), ())  # another process could make an equal dummy
    store.save("t:3", "mod.steps", sp.Matrix([[sp.Dummy("y")]]), (), ())
    assert store.load("t:1", "mod.steps") is None and store.load("t:3", "mod.steps") is None
    x = sp.Symbol("x", positive=True)
    store.save("t:2", "mod.steps", {x: sp.sqrt(x)}, ["u:1"], {"t", "u"})
    assert store.load("t:2", "mod.steps") == ({x: sp.sqrt(x)}, frozenset({"u:1"}), frozenset({"u"}))
    assert store.load("t:2", "copy.steps") is None  # a copy of the text under another module name
    assert DerivedStore({"t": "fp-t", "u": "fp-u, edited"}.get, frozenset).load("t:2", "mod.steps") is None
    assert DerivedStore({"t": "fp-t, edited", "u": "fp-u"}.get, frozenset).load("t:2", "mod.steps") is None
    (tmp_path / STORE_FOLDER).chmod(0o777)  # a folder others may write: nothing in it is loaded
    assert store.load("t:2", "mod.steps") is None
    (tmp_path / STORE_FOLDER).chmod(0o700)
    assert store.load("t:2", "mod.steps") is not None


def test_a_record_is_a_plain_pickle_of_value_uses_and_other_texts(tmp_path, monkeypatch):
    monkeypatch.setenv("QUASICENTRAL_CACHE", str(tmp_path))
    store = DerivedStore({"t": "fp-t", "u": "fp-u"}.get, frozenset)
    store.save("t:1", "m.s", sp.Integer(3), ["u:1"], ["t", "u"])
    (record,) = (tmp_path / STORE_FOLDER).glob("*.pickle")
    assert pickle.loads(record.read_bytes()) == (3, ["u:1"], {"u": "fp-u"})
    assert os.stat(tmp_path / STORE_FOLDER).st_mode & 0o777 == 0o700


def test_a_result_read_back_passes_on_the_texts_it_was_built_on(tmp_path, monkeypatch):
    """t:A uses t:B, which another process built (through t:C) on the text u: A's record must
    name u too, though neither A nor B asked u for anything — or A would outlive an edit of u."""
    monkeypatch.setenv("QUASICENTRAL_CACHE", str(tmp_path))
    value_of_d = [1]

    def new_process(fingerprints) -> Derivations:
        ds = Derivations(DerivedStore(fingerprints.get, lambda: frozenset({"fake_t", "fake_u"})))
        steps = {"u:D": lambda: sp.Integer(value_of_d[0]),
                 "t:C": lambda: registry.derived("u:D"),
                 "t:B": lambda: registry.derived("t:C") + 1,
                 "t:A": lambda: registry.derived("t:B") + 1}
        for eid, body in steps.items():
            def step(body=body):
                """One step of the chain."""
                return body()
            ds.add(registry.Derivation(eid, step, registry.Mode.SOLVE, Domain(), (), None, "One step.",
                                       f"fake_{eid[0]}.steps"))
        return ds

    assert new_process({"t": "t1", "u": "u1"}).result("t:B") == 2  # process 1: B (and C, D) kept
    assert new_process({"t": "t1", "u": "u1"}).result("t:A") == 3  # process 2: B read back, A computed and kept
    value_of_d[0] = 100
    assert new_process({"t": "t1", "u": "u2"}).result("t:A") == 102  # process 3: the text u was edited


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


def _big_or_fails(x: int) -> bytes:
    if x == 0:
        raise ValueError("zero")
    return bytes(200_000)  # more than a pipe holds: a worker must not block on it after a failure


def test_map_grouped_raises_even_with_results_nobody_reads():
    with pytest.raises(ValueError, match="zero"):
        map_grouped(_big_or_fails, [[0, 1, 2], [3, 4, 5, 6]], 2, lambda item, res: None)


def _logged(args) -> int:
    import time

    path, x = args
    time.sleep(0.01)  # 400 items: seconds of work, of which the first result stops the rest
    with open(path, "a") as f:
        f.write(f"{x}\n")
    return x


def test_an_error_in_the_callback_stops_the_workers(tmp_path):
    log = tmp_path / "done.txt"
    items = [(str(log), x) for x in range(400)]

    def stop(item, res):
        raise KeyError("enough")
    with pytest.raises(KeyError, match="enough"):
        map_grouped(_logged, [items[:200], items[200:]], 2, stop)
    assert len(log.read_text().splitlines()) < len(items)  # the rest was never started


def _unpicklable(x: int):
    return lambda: x


def test_a_result_that_cannot_be_sent_is_an_error_not_a_hang():
    with pytest.raises(Exception, match="pickle"):
        map_grouped(_unpicklable, [[1, 2], [3]], 2, lambda item, res: None)


# --- drawn figures kept (quasicentral.studies.figures.draw) ----------------------------------------
def _small_figure(scale: float = 1.0):
    import numpy as np

    from quasicentral.studies.figures import Figure, Kind

    x = np.linspace(0.0, 1.0, 5)
    return Figure("tiny", "a tiny figure", ("x", "y"), np.column_stack([x, scale * x**2]), Kind.CURVES,
                  labels=("y",), xlabel="x", ylabel="y")


def test_a_figure_is_drawn_once_per_data(tmp_path, monkeypatch):
    from quasicentral.studies import figures

    monkeypatch.setenv("QUASICENTRAL_CACHE", str(tmp_path / "cache"))
    drawn = []
    real_render = figures.render
    monkeypatch.setattr(figures, "render", lambda fig, path, *how: drawn.append(fig.name) or real_render(fig, path, *how))
    figures.draw(_small_figure(), tmp_path / "a.png")
    figures.draw(_small_figure(), tmp_path / "b.png")
    assert drawn == ["tiny"] and (tmp_path / "a.png").read_bytes() == (tmp_path / "b.png").read_bytes()
    figures.draw(_small_figure(scale=2.0), tmp_path / "c.png")  # other data: drawn
    assert drawn == ["tiny", "tiny"] and (tmp_path / "c.png").read_bytes() != (tmp_path / "a.png").read_bytes()


@pytest.mark.parametrize("spoil", ["group-writable file", "symlinked file", "foreign folder mode", "not a PNG"])
def test_a_kept_figure_others_could_have_written_is_drawn_anew(tmp_path, monkeypatch, spoil):
    from quasicentral.studies import figures

    monkeypatch.setenv("QUASICENTRAL_CACHE", str(tmp_path / "cache"))
    figures.draw(_small_figure(), tmp_path / "a.png")
    folder = tmp_path / "cache" / figures.FIGURE_CACHE
    (kept,) = folder.glob("*.png")
    if spoil == "group-writable file":
        kept.chmod(0o664)
    elif spoil == "symlinked file":
        other = tmp_path / "elsewhere.png"
        other.write_bytes(kept.read_bytes())
        kept.unlink()
        kept.symlink_to(other)
    elif spoil == "foreign folder mode":
        folder.chmod(0o777)
    else:
        kept.write_bytes(b"GIF89a not a png")
    drawn = []
    real_render = figures.render
    monkeypatch.setattr(figures, "render", lambda fig, path, *how: drawn.append(1) or real_render(fig, path, *how))
    figures.draw(_small_figure(), tmp_path / "b.png")
    assert drawn == [1] and (tmp_path / "b.png").read_bytes() == (tmp_path / "a.png").read_bytes()
