"""Issue 29, hostile folders — the smaller reproductions: what a message names, what reaches the
terminal and stdout, a derivation's own symbol, an erratum whose correction is wrong too, a
large file linked into the folder, ``new-text ""``.

Each test edits a fresh skeleton and runs the command on it in a subprocess."""

from __future__ import annotations

import re
import subprocess
import sys

import pytest

from hostile_support import (by_id, names_file_and_line, no_crash, no_raw_control, one_line_error, verify_json)
from hostile_support import sh, skeleton_template, text  # noqa: F401 - fixtures


def test_a_transcription_syntax_error_names_the_folders_file_and_line(text, sh):
    """a transcription syntax error names the folder's file path and line
    (`.../catalog/motion.toml:LINE`), not `motion.toml: cpsyntax:1`;"""
    text.replace(text.catalog, "Eq(x, x0 + v0*t + a*t**2/2)", "Eq(x, x0 + v0*t +* a*t**2/2)")
    line = text.line_of(text.catalog, "+* a")
    run = sh.run("verify", "--text", text.root)
    err = one_line_error(run)
    names_file_and_line(err, text.root.resolve() / "catalog" / "motion.toml", line)
    assert "cpsyntax" not in err and "motion.toml: " not in err, err


# --- control characters never reach the terminal raw -------------------------------------------------
RAW = "\x1b]0;owned\x07\x1b[2J\r"  # set the window title, clear the screen, return the carriage
TOML_RAW = "\\u001b]0;owned\\u0007\\u001b[2J\\r"
PY_RAW = "\\x1b]0;owned\\x07\\x1b[2J\\r"


@pytest.mark.parametrize("command", ["verify", "errata", "catalog"])
def test_control_characters_in_an_entry_id_and_titles_are_escaped(text, sh, command):
    """control characters / ANSI escapes in an entry id or title never reach the terminal output
    raw (verify, errata, catalog tables: escaped);

    Here: entry 2's id, its name and its cause's title carry an OSC title sequence, a clear-screen
    and a carriage return.  The folder may also be refused (exit 2), in one line as escaped as the
    tables."""
    eid = f"{text.id}:2"
    text.replace(text.catalog, f'id = "{eid}"', f'id = "{eid}{TOML_RAW}X"')
    text.replace(text.catalog, 'name = "velocity and position without the time"',
                 f'name = "velocity{TOML_RAW} and position"')
    text.replace(text.errata, f'id = "{eid}"', f'id = "{eid}{TOML_RAW}X"')
    text.replace(text.errata, 'title = "The factor 2', f'title = "Cause{TOML_RAW}: the factor 2')
    text.replace(text.module, f'@derives("{eid}"', f'@derives("{eid}{PY_RAW}X"')
    run = sh.run(command, "--text", text.root)
    no_crash(run)
    no_raw_control(run.out)
    no_raw_control(run.err)
    if run.code == 2:
        one_line_error(run)
    else:
        assert run.code == 0, (run.code, run.out[-1500:], run.err[-1500:])
        assert "owned" in run.out  # the entry is listed, its id escaped


# --- stdout is the document ------------------------------------------------------------------------
@pytest.mark.parametrize("where", ["in a derivation", "at module level"])
def test_a_print_never_lands_in_verify_json(text, sh, where):
    """a `print()` in a derivation never lands in `verify --json`'s stdout (stdout parses as
    JSON);

    Here: in the derivation of entry 1, or at the derivation module's top level; `--jobs 1`, where
    the derivations run in the command's own process today."""
    if where == "in a derivation":
        text.in_derivation(1, "print('hello from a derivation')")
    else:
        text.at_module_level("print('hello from a derivation module')")
    run = sh.run("verify", "--text", text.root, "--json", "--jobs", "1")
    no_crash(run)
    doc = verify_json(run)
    assert run.code == 0 and doc["summary"]["ok"], (run.code, run.err[-1500:])


# --- a derivation's own symbol ---------------------------------------------------------------------------
def test_a_derivations_own_symbol_named_like_a_declared_one(text, sh):
    """a derivation's own `sp.Symbol("t")` (same name as a declared symbol) works or gives a clear
    message naming the entry;

    Here: entry 1's derivation puts its own t in place of the declared one (which is nonnegative:
    the derivation's own t is another symbol that prints the same)."""
    text.replace(text.module, "return sp.Eq(x, motion.rhs)", 'return sp.Eq(x, motion.rhs.subs(t, sp.Symbol("t")))')
    eid = f"{text.id}:1"
    run = sh.run("verify", "--text", text.root, "--json")
    no_crash(run)
    if run.code == 0:
        assert by_id(verify_json(run))[eid]["status"] == "verified"
        return
    if run.code == 2:
        one_line_error(run, eid, pattern=r"\bt\b")
        return
    assert run.code == 1, (run.code, run.err[-1500:])
    row = by_id(verify_json(run))[eid]
    assert row["verdict"] == "inconclusive", row  # a foreign t settles nothing: never "refuted" at a point
    assert re.search(r"\bt\b", row["detail"]) and re.search(r"symbol|declared|assumption", row["detail"], re.I), row


# --- an erratum whose correction is wrong too ----------------------------------------------------------------
@pytest.mark.parametrize("form", ["table", "json"])
def test_a_wrong_correction_is_shown_refuted(text, sh, form):
    """when an erratum's corrected form is also wrong, the table/JSON shows that the corrected form
    is refuted (not only the printed form's refutation);"""
    text.replace(text.errata, "corrected = '''Eq(v**2, v0**2 + 2*a*(x - x0))'''",
                 "corrected = '''Eq(v**2, v0**2 + 3*a*(x - x0))'''")
    eid = f"{text.id}:2"
    run = sh.run("verify", "--text", text.root, *(["--json"] if form == "json" else []))
    no_crash(run)
    assert run.code == 1, (run.code, run.err[-1500:])
    if form == "json":
        row = by_id(verify_json(run))[eid]
        assert row["corrected_verdict"] == "refuted", row
        assert any("corrected" in p and "refuted" in p for p in row["problems"]), row["problems"]
        return
    lines = [ln for ln in run.out.splitlines() if ln.startswith(eid) or "corrected" in ln]
    shown = "\n".join(lines)
    assert re.search(r"correct\w*[^\n]*refuted|refuted[^\n]*correct", shown), run.out


# --- a large file linked into the folder ----------------------------------------------------------------------
def test_a_large_file_linked_into_the_folder_is_not_read_on_every_run(text, sh, tmp_path):
    """a 1 GB sparse file symlinked into the folder is not read whole on every run (warm verify
    stays fast: < 2 s, and memory stays low — check the file is not hashed by measuring time);

    Here: the warm verify's wall time and its own peak memory (wait4), under 300 MB."""
    big = tmp_path / "big.bin"
    with open(big, "wb") as f:
        f.truncate(2**30)
    (text.root / "data.bin").symlink_to(big)
    cold = sh.run("verify", "--text", text.root)
    no_crash(cold)
    assert cold.code == 0, cold.err[-1500:]
    warm = sh.run("verify", "--text", text.root)
    no_crash(warm)
    assert warm.code == 0, warm.err[-1500:]
    assert warm.seconds < 2.0, f"a warm verify took {warm.seconds:.1f} s"
    # its own peak memory: measured from a small parent, since the harness's children fork from
    # the test process (to set their limits) and a forked child's peak counts its parent's pages
    # until exec — 300 MB of them once the test worker has run the rest of the suite
    probe = ("import resource, subprocess, sys; subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, "
             "stderr=subprocess.DEVNULL, stdin=subprocess.DEVNULL); "
             "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)")
    measured = subprocess.run([sys.executable, "-c", probe, sys.executable, "-m", "quasicentral.cli", "verify",
                               "--text", str(text.root)], capture_output=True, text=True, env=sh.env, cwd=sh.cwd,
                              timeout=120)
    own_kb = int(measured.stdout.split()[-1])
    assert own_kb < 300 * 1024, f"a warm verify took {own_kb // 1024} MB"


# --- new-text "" --------------------------------------------------------------------------------------------------
def test_new_text_with_an_empty_folder_name(sh):
    """`new-text ""` complains about the folder, not `--id`;

    Here: and writes nothing, not even into the working directory."""
    run = sh.run("new-text", "")
    err = one_line_error(run, pattern=r"folder|DIR|director")
    assert "--id" not in err, err
    assert list(sh.cwd.iterdir()) == []
