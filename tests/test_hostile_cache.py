"""Issue 29, hostile folders — the cache as a way in: records another user could have written
(in a group- or world-writable ``$QUASICENTRAL_CACHE``, or owned by someone else) are never
replayed, and nothing is written through a cache subfolder that is a symbolic link.

The forged records are made once per module: a text whose entry 1 is mistyped (verify exits 1)
is verified cold, then its run record (``runs/``) and per-entry verdicts are edited by hand into
a success — a forged "verified" verdict, a forged witness, a forged run saying so with exit 0,
and the digests that bind them recomputed.  Each test copies that cache, makes it hostile in one
way, and verifies again: the run must be recomputed, with the right exit code."""

from __future__ import annotations

import hashlib
import json
import os
import shutil
from pathlib import Path

import pytest

from hostile_support import Folder, by_id, copy_text, no_crash, one_line_error, qc, verify_json
from hostile_support import sh, skeleton_template, text  # noqa: F401 - fixtures

FORGED_DETAIL = "FORGED-VERDICT: sympy proves the difference zero"
FORGED_RUN = "FORGED-RUN: every entry verified\n"
FORGED_WITNESS = "-4242.4242"


@pytest.fixture(scope="module")
def forged(skeleton_template, tmp_path_factory):
    base = tmp_path_factory.mktemp("forged")
    folder = Folder(copy_text(skeleton_template, base / "hforged", "hforged"), "hforged")
    folder.replace(folder.catalog, "Eq(x, x0 + v0*t + a*t**2/2)", "Eq(x, x0 + v0*t + a*t**2)")
    cache = base / "cache"
    first = qc("verify", "--text", folder.root, "--json", cache=cache, cwd=base)
    assert first.code == 1, first.err[-2000:]  # the premise: entry 1 is refuted
    verdicts = {json.loads(p.read_text())["outcome"]["id"]: p for p in cache.glob("*.json")}
    assert set(verdicts) == {"hforged:1", "hforged:2"}, verdicts
    one = json.loads(verdicts["hforged:1"].read_text())
    # a verified verdict whose reason carries the forged words (the records are typed: a reason
    # is a code and its fields)
    forged_reason = {"code": "proved", "fields": {"numbers": {"reason": {
        "code": "setup-failed", "fields": {"error": FORGED_DETAIL}}}}}
    one["outcome"].update(status="verified", problems=[], verdict={
        "verdict": "verified", "method": "symbolic", "reason": forged_reason, "points": 20, "digits": [30, 60],
        "dimensions": [], "witness": None})
    verdicts["hforged:1"].write_text(json.dumps(one, sort_keys=True))
    two = json.loads(verdicts["hforged:2"].read_text())
    two["outcome"]["verdict"]["witness"]["printed"] = FORGED_WITNESS
    verdicts["hforged:2"].write_text(json.dumps(two, sort_keys=True))
    (record,) = cache.glob("runs/*.json")
    rec = json.loads(record.read_text())
    rec.update(stdout=FORGED_RUN, exit=0,
               verdicts={p.name: hashlib.sha256(p.read_bytes()).hexdigest() for p in verdicts.values()})
    record.write_text(json.dumps(rec, sort_keys=True))
    return folder, cache, [record, *verdicts.values()]


def _group_world_writable(path: Path) -> None:
    os.chmod(path, os.stat(path).st_mode | 0o022)  # chmod g+w,o+w


@pytest.mark.parametrize("how", ["cache folder g+w,o+w", "records g+w,o+w", "records owned by uid 12345"])
def test_records_another_user_could_write_are_not_replayed(forged, tmp_path, how):
    """cache records owned by another user or in a group/world-writable `$QUASICENTRAL_CACHE` are
    not replayed (a run record or per-entry verdict edited to "verified"/a forged witness):
    simulate with `chmod g+w,o+w` on the cache folder and on a record (you are root: also try
    `os.chown` to uid 12345) and assert the run recomputes (the forged verdict does not appear,
    correct exit code).

    Here: the forged run record and both forged verdicts (module fixture ``forged``), made
    hostile in one of the three ways; verify must print none of them and exit 1."""
    folder, template, records = forged
    cache = tmp_path / "cache"
    shutil.copytree(template, cache, symlinks=True)
    mine = [cache / r.relative_to(template) for r in records]
    if how.startswith("cache folder"):
        _group_world_writable(cache)
    elif how.startswith("records g+w"):
        for r in mine:
            _group_world_writable(r)
    else:
        if os.geteuid() != 0:
            pytest.skip("chown to another user needs root")
        for r in mine:
            os.chown(r, 12345, 12345)
    run = qc("verify", "--text", folder.root, "--json", cache=cache, cwd=tmp_path)
    no_crash(run)
    assert "FORGED" not in run.out and FORGED_WITNESS not in run.out, run.out[:1500]
    assert run.code == 1, (run.code, run.err[-1500:])
    rows = by_id(verify_json(run))
    assert (rows["hforged:1"]["status"], rows["hforged:1"]["verdict"]) == ("unexpected", "refuted")
    assert rows["hforged:2"]["status"] == "erratum"


FIGURES_PY = '''\
"""One small figure, so that `quasicentral figures` draws (and keeps) a PNG."""

import numpy as np

from quasicentral.studies.figures import Figure, Kind


def fig1():
    x = np.linspace(0.0, 1.0, 11)
    return Figure("fig1", "Fig. 1: a line", ("x", "y"), np.column_stack([x, 2 * x]), Kind.CURVES, ("y = 2x",), "x", "y")


FIGURES = (fig1,)
'''


@pytest.mark.parametrize("sub", ["runs", "latex-parser", "derived", "figures"])
def test_nothing_is_written_through_a_linked_cache_subfolder(text, sh, tmp_path, sub):
    """cache subfolders (`runs/`, `latex-parser/`, `derived/`, `figures/`) that are symbolic links
    to a folder elsewhere: nothing is written through them.

    Here: the command that keeps records there (verify: runs/ and derived/; catalog:
    latex-parser/; figures, with a one-figure figures.py: figures/) still does its work, or
    refuses in one line naming the folder."""
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    sh.cache.mkdir()
    (sh.cache / sub).symlink_to(elsewhere, target_is_directory=True)
    if sub == "figures":
        text.write("figures.py", FIGURES_PY)
        args = ("figures", "--text", text.root, "--out", tmp_path / "figs")
    elif sub == "latex-parser":
        args = ("catalog", "--text", text.root)
    else:
        args = ("verify", "--text", text.root)
    run = sh.run(*args)
    no_crash(run)
    assert sorted(p.name for p in elsewhere.rglob("*")) == [], f"written through {sub}/ -> {elsewhere}"
    if run.code != 0:
        one_line_error(run, sub)
    elif sub == "figures":  # the premise: a figure was drawn (and would have been kept)
        assert (tmp_path / "figs" / "fig1.png").is_file(), run.out
    assert (sh.cache / sub).is_symlink()  # and the link itself is left as it was
