"""Issue 29, hostile folders — hangs: a derivation that never returns, a module that never ends
its import, numbers too large to compute, LaTeX too large to parse.  With the new option
``--timeout SECONDS`` (the wall-clock ceiling per entry, and a CPU budget) such an entry is
*inconclusive* naming the timeout (verify exit 1, the rest of the table printed), a number too
large is refused at load, and every command ends within ~30 s with ``--timeout 2``.  An
interrupt (``kill -INT``) or ``kill -TERM`` of the parent ends it and every process it started
within about a second."""

from __future__ import annotations

import json
import os
import re
import signal
import time

import pytest

from hostile_support import (HANG_SECONDS, alive, by_id, descendants, env_for, kill_tree, names_file_and_line,
                             no_crash, one_line_error, spawn_to_files, verify_json)
from hostile_support import sh, skeleton_template, text  # noqa: F401 - fixtures

TIMED_OUT = re.compile(r"time.?out|timed out|time limit|out of time|--timeout", re.I)
NEVER_RETURNS = {"time.sleep(1000)": "import time\ntime.sleep(1000)", "while True: pass": "while True:\n    pass"}


# --- a derivation that never returns ----------------------------------------------------------------
@pytest.mark.parametrize("body", list(NEVER_RETURNS))
def test_a_derivation_that_never_returns_times_out(text, sh, body):
    """a derivation that sleeps (`time.sleep(1000)`) or loops (`while True: pass`); a module that
    sleeps at import;  (hangs — each must end within ~30 s with `--timeout 2`)

    Here: the derivation of entry 2 sleeps or loops; that entry is inconclusive naming the
    timeout (exit 1), the rest of the table printed (entry 1 verified)."""
    text.in_derivation(2, NEVER_RETURNS[body])
    run = sh.run("verify", "--text", text.root, "--json", "--timeout", "2", seconds=HANG_SECONDS)
    no_crash(run)
    assert run.code == 1, (run.code, run.err[-2000:])
    rows = by_id(verify_json(run))
    assert rows[f"{text.id}:1"]["status"] == "verified", rows
    late = rows[f"{text.id}:2"]
    assert late["verdict"] == "inconclusive" and late["status"] == "unexpected", late
    assert TIMED_OUT.search(late["detail"]), late["detail"]


def test_a_module_that_sleeps_at_import(text, sh):
    """a derivation that sleeps (`time.sleep(1000)`) or loops (`while True: pass`); a module that
    sleeps at import;  (hangs — each must end within ~30 s with `--timeout 2`)

    Here: motion.py sleeps at import; the timeout is named — its entries inconclusive (exit 1), or
    the module refused in one line naming motion.py (exit 2)."""
    text.at_module_level("import time\ntime.sleep(1000)")
    run = sh.run("verify", "--text", text.root, "--timeout", "2", seconds=HANG_SECONDS)
    no_crash(run)
    assert run.code in (1, 2), (run.code, run.out[-1500:], run.err[-1500:])
    assert TIMED_OUT.search(run.out + run.err), (run.out[-1500:], run.err[-1500:])
    if run.code == 2:
        one_line_error(run, "motion.py")


# --- an interrupt ends the run and every process it started --------------------------------------------
END_SECONDS = 2.5  # "within about a second", with room for a loaded machine


@pytest.mark.skipif(not os.path.exists("/proc/self/stat"), reason="needs /proc (Linux)")
@pytest.mark.parametrize("signame, jobs", [("INT", 1), ("INT", 2), ("TERM", 1), ("TERM", 2)])
def test_a_signal_ends_the_run_and_its_workers(text, sh, tmp_path, signame, jobs):
    """`kill -INT` on the parent during such a run ends it and all its worker processes within
    about a second (find the children through `/proc/*/stat` ppid chains; test `--jobs 2` too),
    also `kill -TERM`;

    Here: the derivation of entry 1, which entry 2 builds on, sleeps (with `--jobs 2` both workers
    are in it; no `--timeout`, so only the signal can end the run).  Every process below the
    parent just before the signal must be gone 2.5 s after it, and the run is no success."""
    started = tmp_path / "started"
    started.mkdir()
    text.in_derivation(1, f"import os, pathlib, time\npathlib.Path({str(started)!r}, str(os.getpid())).touch()\n"
                          "time.sleep(1000)")
    proc = spawn_to_files(["verify", "--text", text.root, "--no-cache", "--jobs", jobs], env_for(sh.cache), sh.cwd,
                          tmp_path / "stdout", tmp_path / "stderr")
    seen: set[int] = set()
    try:
        deadline = time.monotonic() + 60
        while not any(started.iterdir()) and time.monotonic() < deadline and proc.poll() is None:
            time.sleep(0.05)
        assert any(started.iterdir()), f"the derivation never started: {(tmp_path / 'stderr').read_text()[-1500:]}"
        deadline = time.monotonic() + (2.0 if jobs > 1 else 0.3)  # the second worker into its sleep too
        while len(list(started.iterdir())) < jobs and time.monotonic() < deadline:
            time.sleep(0.05)
        time.sleep(0.3)  # settled in its sleep
        seen = descendants(proc.pid)
        t0 = time.monotonic()
        os.kill(proc.pid, getattr(signal, f"SIG{signame}"))
        while proc.poll() is None and time.monotonic() - t0 < END_SECONDS:
            time.sleep(0.02)
        parent_ended = proc.poll() is not None
        while any(alive(p) for p in seen) and time.monotonic() - t0 < END_SECONDS:
            time.sleep(0.02)
        left = sorted(p for p in seen if alive(p))
        assert parent_ended, f"the parent still runs {END_SECONDS} s after SIG{signame}"
        assert not left, f"processes {left} outlived the parent by {END_SECONDS} s after SIG{signame}"
        assert proc.returncode != 0, "an interrupted run is no success"
        err = (tmp_path / "stderr").read_text(errors="replace")
        assert "Traceback" not in err and "internal error" not in err, err[-2000:]
    finally:
        kill_tree(proc, seen)
        proc.wait(timeout=10)


# --- numbers too large to compute -----------------------------------------------------------------------------
def test_a_tower_of_powers_in_a_range(text, sh):
    """`10**10**10` in a range and in a transcription (refused: exponent too large);

    Here: the range of the symbol a."""
    line = text.replace_line("text.toml", 'range = ["-5", "5"]', 'range = ["-5", "10**10**10"]')
    run = sh.run("verify", "--text", text.root, "--timeout", "2", seconds=HANG_SECONDS)
    err = one_line_error(run, pattern=r"exponent|too large")
    names_file_and_line(err, text.path("text.toml"), [line, text.line_of("text.toml", "[symbols.a]")])


def test_a_tower_of_powers_in_a_transcription(text, sh):
    """`10**10**10` in a range and in a transcription (refused: exponent too large);

    Here: the transcription of entry 1."""
    text.replace(text.catalog, "Eq(x, x0 + v0*t + a*t**2/2)", "Eq(x, x0 + v0*t + a*t**2/2 + 10**10**10)")
    line = text.line_of(text.catalog, "10**10**10")
    run = sh.run("verify", "--text", text.root, "--timeout", "2", seconds=HANG_SECONDS)
    err = one_line_error(run, pattern=r"exponent|too large")
    names_file_and_line(err, text.path(text.catalog), line)


# --- LaTeX too large to parse -----------------------------------------------------------------------------------
LATEX_1 = "latex = '''x = x_0 + v_0 t + \\frac{1}{2} a t^2'''"


@pytest.mark.parametrize("display", ["20,000 terms", "\\frac nested 3,000 deep"])
def test_catalog_on_a_display_too_large_to_parse_is_bounded(text, sh, display):
    """`catalog` on a display of 20,000 terms and on `\\frac` nested 3,000 deep (bounded: finishes,
    the entry's LaTeX-parser result says it ran out of time, exit 0 or the documented code).

    Here: entry 1's LaTeX replaced, `--timeout 2`.  For the nesting, a result that names the depth
    as the limit (too deep, recursion) is taken as saying so too."""
    if display.startswith("20"):
        latex = "x = x_0" + " + v_0 t" * 20000
        said = TIMED_OUT
    else:
        latex = "x = " + "\\frac{1}{" * 3000 + "2" + "}" * 3000
        said = re.compile(TIMED_OUT.pattern + r"|too deep|depth|nest|recursion", re.I)
    text.replace_line(text.catalog, "latex = '''x = x_0 + v_0 t", f"latex = '''{latex}'''")
    run = sh.run("catalog", "--text", text.root, "--json", "--timeout", "2", seconds=HANG_SECONDS)
    no_crash(run)
    assert run.code in (0, 1), (run.code, run.err[-1500:])
    row = by_id(json.loads(run.out))[f"{text.id}:1"]
    assert said.search(json.dumps(row["latex_parser"])), row["latex_parser"]
