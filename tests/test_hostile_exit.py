"""Issue 29, hostile folders — wrong answers with exit 0: a derivation module that ends the
process, a sampling range of one point, a verdict built on another text that went stale, the
exit codes of ``errata`` and ``mutate`` when there is nothing to stand on.

Each test replays one reproduction of the issue on a fresh ``quasicentral new-text`` skeleton
(tests/hostile_support.py), in a subprocess with a private cache.  A verdict is read from
``verify --json``: entry 1 of the skeleton (``ID:1``, the position) is verified, entry 2
(``ID:2``) a registered erratum."""

from __future__ import annotations

import re

import pytest

from hostile_support import by_id, no_crash, names_file_and_line, one_line_error, verify_json
from hostile_support import make_text, sh, skeleton_template, text  # noqa: F401 - fixtures

ENDS_THE_PROCESS = {
    "sys.exit(0)": "import sys\nsys.exit(0)",
    "sys.exit(3)": "import sys\nsys.exit(3)",
    "raise BaseException": "raise BaseException('a derivation that raises BaseException')",
    "os._exit(0)": "import os\nos._exit(0)",
}


def _entry_unsettled(doc: dict, eid: str) -> None:
    row = by_id(doc)[eid]
    assert row["verdict"] == "inconclusive" and row["status"] == "unexpected", row


# --- a derivation module that ends the process ------------------------------------------------------
@pytest.mark.parametrize("command", ["verify", "errata", "mutate"])
def test_sys_exit_0_at_module_level(text, sh, command):
    """`sys.exit(0)` at module level of a derivation module, and inside a derivation: verify, errata and
    mutate must not exit 0 silently; `sys.exit(3)`; `raise BaseException` (no traceback). Also
    `os._exit(0)` inside a derivation (the parent must survive and report the entry).

    Here: `sys.exit(0)` at module level, for each command.  A module that cannot be imported is a
    mistake in the folder: one line naming motion.py and the line of the exit, exit 2."""
    line = text.at_module_level("import sys\nsys.exit(0)") + 1
    run = sh.run(command, "--text", text.root)
    err = one_line_error(run)
    names_file_and_line(err, text.path("motion.py"), line)


@pytest.mark.parametrize("statement, jobs", [
    ("sys.exit(0)", 1), ("sys.exit(3)", 1), ("raise BaseException", 1), ("os._exit(0)", 1), ("os._exit(0)", 2),
], ids=["sys.exit(0)", "sys.exit(3)", "BaseException", "os._exit(0)", "os._exit(0)-jobs2"])
def test_a_derivation_that_ends_the_process_makes_its_entry_inconclusive(text, sh, statement, jobs):
    """`sys.exit(0)` at module level of a derivation module, and inside a derivation: verify, errata and
    mutate must not exit 0 silently; `sys.exit(3)`; `raise BaseException` (no traceback). Also
    `os._exit(0)` inside a derivation (the parent must survive and report the entry).

    Here: each statement inside the derivation of entry 2, under `verify` (`os._exit(0)` also with
    `--jobs 2`): that entry is inconclusive, exit 1, the rest of the table printed (entry 1
    verified)."""
    text.in_derivation(2, ENDS_THE_PROCESS[statement])
    run = sh.run("verify", "--text", text.root, "--json", "--jobs", jobs)
    no_crash(run)
    assert run.code == 1, (run.code, run.err[-2000:])
    doc = verify_json(run)
    assert by_id(doc)[f"{text.id}:1"]["status"] == "verified"
    _entry_unsettled(doc, f"{text.id}:2")
    assert doc["summary"]["ok"] is False


def test_sys_exit_0_inside_a_derivation_errata(text, sh):
    """`sys.exit(0)` at module level of a derivation module, and inside a derivation: verify, errata and
    mutate must not exit 0 silently; `sys.exit(3)`; `raise BaseException` (no traceback). Also
    `os._exit(0)` inside a derivation (the parent must survive and report the entry).

    Here: `sys.exit(0)` inside the derivation of entry 2, under `errata`: the erratum no longer
    stands, exit 1, the entry listed."""
    text.in_derivation(2, ENDS_THE_PROCESS["sys.exit(0)"])
    run = sh.run("errata", "--text", text.root)
    no_crash(run)
    assert run.code == 1, (run.code, run.out[-1500:], run.err[-1500:])
    assert f"{text.id}:2" in run.out


def test_sys_exit_0_inside_a_derivation_mutate(text, sh):
    """`sys.exit(0)` at module level of a derivation module, and inside a derivation: verify, errata and
    mutate must not exit 0 silently; `sys.exit(3)`; `raise BaseException` (no traceback). Also
    `os._exit(0)` inside a derivation (the parent must survive and report the entry).

    Here: `sys.exit(0)` inside the derivation of entry 1 (the only verified entry, the one mutate
    seeds typos into), under `mutate`: nothing is measured, so exit 1 (or 2 in one line), and no
    claim of recall."""
    text.in_derivation(1, ENDS_THE_PROCESS["sys.exit(0)"])
    run = sh.run("mutate", "--text", text.root)
    no_crash(run)
    assert run.code in (1, 2), (run.code, run.out[-1500:], run.err[-1500:])
    assert "recall 100.0 %" not in run.out
    if run.code == 2:
        one_line_error(run)


# --- a range of one point --------------------------------------------------------------------------
def test_an_empty_range_verifies_nothing(text, sh):
    """an empty range `range = ["0", "0"]` on `t` with both printed forms mistyped (`x0 + 5*v0*t +
    7*a*t**2`): must not be "verified" (refused, exit 2 naming the range, or inconclusive saying
    the domain is one point).

    Here: entry 1 printed as `x0 + 5*v0*t + 7*a*t**2`, entry 2 as `v0**2 + 7*a*(x - x0)`, and no
    erratum recorded, so that a sampler that only ever tries t = 0 "verifies" both, exit 0."""
    text.replace("text.toml", 'range = ["0", "10"]', 'range = ["0", "0"]')
    line = text.line_of("text.toml", 'range = ["0", "0"]')
    header = text.line_of("text.toml", "[symbols.t]")
    text.replace(text.catalog, "Eq(x, x0 + v0*t + a*t**2/2)", "Eq(x, x0 + 5*v0*t + 7*a*t**2)")
    text.replace(text.catalog, "Eq(v**2, v0**2 + a*(x - x0))", "Eq(v**2, v0**2 + 7*a*(x - x0))")
    text.path(text.errata).unlink()
    run = sh.run("verify", "--text", text.root, "--json")
    no_crash(run)
    if run.code == 2:
        err = one_line_error(run, "range")
        names_file_and_line(err, text.path("text.toml"), {line, header})
        return
    assert run.code == 1, (run.code, run.out[-2000:], run.err[-1500:])
    for row in verify_json(run)["equations"]:
        assert row["verdict"] != "verified", row
        assert re.search(r"one point|single point|empty|degenerate|zero width", row["detail"], re.I), row


# --- a verdict built on another text ---------------------------------------------------------------
TA_MODULE = '''\
"""Text ta: its position is text tb's."""

import sympy as sp

from quasicentral.engine.registry import derived, derives
from quasicentral.engine.texts import symbols_of

S = symbols_of(__file__)
t, a, x0, v0, x, v = S("t a x0 v0 x v")


@derives("ta:1", unknowns=(x,), uses=("tb:1",))
def position():
    """x = x0 + v0 t + a t^2/2, as text tb derives it."""
    return derived("tb:1")


@derives("ta:2", mode="substitute", uses=("ta:1",))
def velocity_squared():
    """v^2 = v0^2 + 2a(x - x0) on the motion (1)."""
    position = derived("ta:1").rhs
    return {x: position, v: sp.diff(position, t)}
'''


def test_a_verdict_built_on_another_text_goes_stale_with_it(make_text, sh):
    """verdicts that build on another text go stale: text `ta` derives from `derived("tb:1")`;
    after `tb`'s derivation is changed (to something wrong), `verify --text ta --text tb` (with
    the cache warm from before) must refute as `--no-cache` does."""
    ta, tb = make_text("ta"), make_text("tb")
    ta.write(ta.module, TA_MODULE)
    both = ("--text", ta.root, "--text", tb.root, "--json")
    before = sh.run("verify", *both)
    no_crash(before)
    assert before.code == 0, before.err[-2000:]
    tb.replace(tb.module, "return sp.Eq(x, motion.rhs)", "return sp.Eq(x, motion.rhs + a*t**2/2)")
    warm = sh.run("verify", *both)
    cold = sh.run("verify", *both, "--no-cache")
    no_crash(warm)
    no_crash(cold)
    assert cold.code == 1, cold.err[-2000:]
    got = {i: (r["status"], r["verdict"]) for i, r in by_id(verify_json(warm)).items()}
    want = {i: (r["status"], r["verdict"]) for i, r in by_id(verify_json(cold)).items()}
    assert want["ta:1"] == ("unexpected", "refuted"), want
    assert got == want
    assert warm.code == cold.code == 1


# --- the exit codes of errata and mutate -------------------------------------------------------------
def test_errata_exits_1_when_a_cleared_suspect_is_refuted(text, sh):
    """`errata` exits 1 when a cleared suspect is refuted; `mutate` on a text with no verified
    entry must not print "recall 100.0 %" with exit 0.

    Here: the first half — entry 1 recorded as a cleared suspect, and printed mistyped."""
    text.append(text.errata, f'\n[[cleared]]\nid = "{text.id}:1"\nsuspicion = "the factor 1/2 of the last term"\n'
                             'note = "the derivation agrees with the print"\n')
    text.replace(text.catalog, "Eq(x, x0 + v0*t + a*t**2/2)", "Eq(x, x0 + v0*t + a*t**2)")
    run = sh.run("errata", "--text", text.root)
    no_crash(run)
    assert run.code == 1, (run.code, run.out[-2000:])
    assert f"{text.id}:1" in run.out


def test_mutate_with_no_verified_entry_claims_no_recall(text, sh):
    """`errata` exits 1 when a cleared suspect is refuted; `mutate` on a text with no verified
    entry must not print "recall 100.0 %" with exit 0.

    Here: the second half — both entries are registered errata (verify passes on the folder, exit
    0: checked when this test was written, not on every run), so nothing is left to mutate: no recall is claimed, and nothing measured is no success (exit 1,
    or 2 in one line)."""
    text.replace(text.catalog, "Eq(x, x0 + v0*t + a*t**2/2)", "Eq(x, x0 + v0*t + a*t**2)")
    text.append(text.errata, f'''
[[erratum]]
id = "{text.id}:1"
kind = "missing factor"
cause = ["factor-two"]
corrected = \'\'\'Eq(x, x0 + v0*t + a*t**2/2)\'\'\'
corrected_latex = \'\'\'x = x_0 + v_0 t + \\frac{{1}}{{2}} a t^2\'\'\'
note = "The factor 1/2 is lost.  Witness: {{witness}}."
''')
    run = sh.run("mutate", "--text", text.root)  # (verify passes on this folder: both entries are errata)
    no_crash(run)
    assert not (run.code == 0 and "recall 100.0 %" in run.out), run.out
    assert run.code in (1, 2), (run.code, run.out[-1500:])
    assert "100.0 %" not in run.out
    if run.code == 2:
        one_line_error(run)
