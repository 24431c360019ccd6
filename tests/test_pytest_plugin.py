"""The pytest plugin: ``pytest --texts DIR`` collects a text folder's entries as items — passing
where the records are met, failing with the witness where a printed form is refuted
unexpectedly, skipped where inconclusive; a folder that cannot be read is a collection error
naming its file; -k selects entries; the JUnit report lists them."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
WIEN = REPO / "tests" / "data" / "wien"


def _pytest(tmp_path: Path, *args: str) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if k not in ("PYTEST_ADDOPTS", "PYTEST_XDIST_WORKER")}
    env.update(QUASICENTRAL_CACHE=str(tmp_path / "cache"), PYTHONPATH=str(REPO))
    run_in = tmp_path / "run"
    run_in.mkdir(exist_ok=True)
    return subprocess.run([sys.executable, "-m", "pytest", "-p", "no:cacheprovider",
                           "-q", "-rfs", "-n", "0", *args], cwd=run_in, env=env, capture_output=True, text=True,
                          timeout=300)


def test_a_text_folder_is_a_test_suite(tmp_path):
    broken = tmp_path / "wien-broken"
    shutil.copytree(WIEN, broken)
    for f in [broken / "text.toml", *broken.glob("*/*.toml"), broken / "wien.py"]:  # a text of its own id
        f.write_text(f.read_text().replace('"wien', '"wienb'), encoding="utf-8")
    catalog = broken / "catalog" / "wien.toml"
    catalog.write_text(catalog.read_text().replace("pi**4/15)", "pi**4/16)"), encoding="utf-8")  # wienb:5
    junit = tmp_path / "junit.xml"
    r = _pytest(tmp_path, "--texts", str(WIEN), "--texts", str(broken), f"--junitxml={junit}")
    assert r.returncode == 1, r.stdout + r.stderr
    assert "13 passed" in r.stdout and "1 failed" in r.stdout, r.stdout
    assert "FAILED" in r.stdout and "text.toml::wienb:5" in r.stdout
    assert "witness at" in r.stdout and "correct" in r.stdout  # the failure shows its witness
    assert junit.read_text().count("<testcase") == 14
    only = _pytest(tmp_path, "--texts", str(WIEN), "-k", "wien:3 or wien:4")
    assert only.returncode == 0 and "2 passed" in only.stdout, only.stdout


def test_an_unreadable_folder_is_one_collection_error(tmp_path):
    bad = tmp_path / "bad"
    shutil.copytree(WIEN, bad)
    (bad / "text.toml").write_text((WIEN / "text.toml").read_text() + "\nbogus = [\n", encoding="utf-8")
    r = _pytest(tmp_path, "--texts", str(bad))
    assert r.returncode == 2, r.stdout
    assert "ERROR collecting" in r.stdout and "text.toml" in r.stdout
    assert "Traceback" not in r.stdout + r.stderr


def test_inconclusive_entries_are_skipped_with_their_reason(tmp_path):
    folder = tmp_path / "open"
    shutil.copytree(WIEN, folder)
    catalog = folder / "catalog" / "wien.toml"  # (7) of a function the text never defines: no numbers
    catalog.write_text(catalog.read_text().replace("Eq(Derivative(log(1 + k*t)/k, t), 1/(1 + k*t))",
                                                   'Eq(Function("u")(k), 1/(1 + k*t))'), encoding="utf-8")
    r = _pytest(tmp_path, "--texts", str(folder))
    assert "1 skipped" in r.stdout and "inconclusive" in r.stdout, r.stdout
