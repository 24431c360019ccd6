"""The command line's contract on hostile input and in hostile places (issue 16): a closed pipe,
a selection that selects nothing, symbolic links in the output directory, a broken LaTeX
auxiliary file, a parent killed with -9, progress only on a terminal, help that teaches.

Each test replays one reproduction of the issue; none runs the whole catalog (a handful of
cheap entries, in a temporary verdict cache)."""

from __future__ import annotations

import shipped

import io
import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from quasicentral import cli, files
from quasicentral.cli import main
from quasicentral.progress import Progress

CHEAP = ["--id", "brepta1953:1", "--id", "brepta1953:4"]  # symbolic, about a second each
# long enough for both workers to be seen alive (killed within seconds): the whole first text,
# ~25 s on two workers — two quadrature entries alone now take under 5 s, and a worker with
# nothing left to take could end before the test saw it
SLOW = ["--source", "brepta1953"]


@pytest.fixture
def cache(tmp_path_factory, monkeypatch):
    """A private verdict cache (shared by this module's tests, so the cheap entries are computed
    once), set for in-process calls and for the subprocesses."""
    path = tmp_path_factory.getbasetemp() / "contract-cache"
    path.mkdir(exist_ok=True)
    monkeypatch.setenv("QUASICENTRAL_CACHE", str(path))
    return path


def env_without_ci(**extra) -> dict:
    env = {k: v for k, v in os.environ.items() if k != "CI"}
    env.update(extra)
    return env


def one_line_error(code, err, *names):
    assert code == 2, err
    assert err.count("\n") == 1 and err.startswith("quasicentral: error:"), err
    assert "Traceback" not in err and "internal error" not in err
    for name in names:
        assert name in err, (name, err)


def run_cli(*args, env=None, stdout=subprocess.PIPE):
    proc = subprocess.run([sys.executable, "-m", "quasicentral.cli", *args], stdout=stdout,
                          stderr=subprocess.PIPE, text=True, env=env, timeout=300)
    return proc.returncode, proc.stdout, proc.stderr


# --- a closed pipe -----------------------------------------------------------------------------
def closed_reader_run(*args, env=None):
    """Run the command with its stdout a pipe whose reader has already gone (`| head -0`)."""
    r, w = os.pipe()
    os.close(r)
    try:
        return run_cli(*args, env=env, stdout=w)
    finally:
        os.close(w)


@pytest.mark.parametrize("args", [
    ["verify", *CHEAP],
    ["verify", "--json", *CHEAP],
    ["period", "--table"],
    ["--help"],
    ["verify", "--help"],
])
def test_closed_pipe_ends_quietly_with_the_commands_own_exit_code(args, cache):
    code, _, err = closed_reader_run(*args)
    assert code == 0, err
    assert "Traceback" not in err and "BrokenPipe" not in err and "Exception ignored" not in err, err


class _ClosedPipe(io.StringIO):
    def write(self, text):
        raise BrokenPipeError(32, "Broken pipe")

    def flush(self):
        raise BrokenPipeError(32, "Broken pipe")


@pytest.mark.parametrize("command", ["errata", "catalog", "verify"])
def test_closed_pipe_in_process(command, cache, monkeypatch, capsys):
    """errata and catalog read the whole catalog: here a small selection stands in for it."""
    from quasicentral.cli import verification

    few = [shipped.entry("brepta1953:1"), shipped.entry("brepta1953:4")]
    monkeypatch.setattr(verification, "selected_entries", lambda args, ws, texts: few)
    monkeypatch.setattr(sys, "stdout", _ClosedPipe())
    code = main([command])
    assert code == 0
    assert sys.stdout.__class__ is _ClosedPipe  # main put back what it found


def test_a_result_still_fails_when_the_pipe_is_closed(cache, monkeypatch):
    """The reader going away does not turn an unexpected result into a success."""
    from quasicentral.cli import verification
    from quasicentral.engine import run
    from quasicentral.engine.reasons import Code, Reason
    from quasicentral.engine.verdict import Inconclusive, Method, Outcome, Status

    few = [shipped.entry("brepta1953:1")]
    monkeypatch.setattr(verification, "selected_entries", lambda args, ws, texts: few)
    bad = Outcome("brepta1953:1", Inconclusive(Method.NONE, Reason(Code.NOTHING_TO_CHECK)), Status.UNEXPECTED,
                  problems=(Reason(Code.NOTHING_TO_CHECK),))
    monkeypatch.setattr(run, "run", lambda *a, **k: [bad])
    monkeypatch.setattr(sys, "stdout", _ClosedPipe())
    assert main(["verify", "--no-cache"]) == 1  # not a whole run read back: the stand-in decides


# --- selections and options that would be ignored ---------------------------------------------------
@pytest.mark.parametrize("args, names", [
    (["verify", "--source", "pendulum", "--id", "brepta1953:4"], ["--id", "--source"]),
    (["verify", "--id", "nosuch:1"], ["--id"]),
    (["verify", "--junit", ""], ["--junit"]),
    (["verify", "--junit", "  "], ["--junit"]),
    (["report", "--all", "--lang", "en"], ["--all", "--lang"]),
    (["report", "--all", "--handout"], ["--all", "--handout"]),
    (["report", "--out", ""], ["--out"]),
    (["figures", "--out", ""], ["--out"]),
    (["mutate", "--per-entry", "0"], ["--per-entry"]),
    (["mutate", "--jobs", "0"], ["--jobs"]),
    (["errata", "--source", "nosuch"], ["--source"]),
    (["catalog", "--source", "nosuch"], ["--source"]),
    (["trajectory", "--model", "nosuch", "--R0", "0.1", "--v0", "0"], ["--model", "ellipse"]),
])
def test_refused_in_one_line(args, names, capsys):
    code = main(args)
    out, err = capsys.readouterr()
    one_line_error(code, err, *names)
    assert out == ""


def test_empty_selection_writes_no_junit(tmp_path):
    """The reproduction as typed, in a subprocess."""
    target = tmp_path / "verify.xml"
    code, _, err = run_cli("verify", "--source", "pendulum", "--id", "brepta1953:4", "--junit", str(target))
    one_line_error(code, err, "--id", "--source")
    assert not target.exists()


# --- files: only inside --out, never through a symbolic link -------------------------------------------
def test_report_write_test_probe_does_not_truncate_a_link_target(tmp_path):
    from quasicentral.documents import report

    victim = tmp_path / "victim.txt"
    victim.write_text("precious")
    out = tmp_path / "out"
    out.mkdir()
    (out / ".quasicentral-write-test.tmp").symlink_to(victim)
    report.check_writable(out)
    report.write(out, {"a.tex": "new"})
    assert victim.read_text() == "precious"
    assert (out / "a.tex").read_text() == "new"


def test_report_refuses_a_symlinked_figures_folder(tmp_path):
    from quasicentral.documents import report

    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    out = tmp_path / "out"
    out.mkdir()
    (out / report.FIGURE_DIR).symlink_to(elsewhere, target_is_directory=True)
    with pytest.raises(files.UnsafePath, match="symbolic link"):
        report.write(out, {"a.tex": f"\\includegraphics{{{report.FIGURE_DIR}/fig7a.png}}"}, [shipped.text("brepta1953")])
    assert list(elsewhere.iterdir()) == []


def test_report_writes_its_figures_inside_out(tmp_path):
    from quasicentral.documents import report

    out = tmp_path / "out"
    paths = report.write(out, {"a.tex": f"\\includegraphics{{{report.FIGURE_DIR}/fig7a.png}}"}, [shipped.text("brepta1953")])
    assert paths == [out / "a.tex", out / report.FIGURE_DIR / "fig7a.png"]
    assert (out / report.FIGURE_DIR / "fig7a.png").read_bytes().startswith(b"\x89PNG")
    assert sorted(p.name for p in out.rglob("*")) == ["a.tex", "fig7a.png", report.FIGURE_DIR]


def test_report_refuses_a_symlinked_document(tmp_path):
    from quasicentral.documents import report

    victim = tmp_path / "victim.tex"
    victim.write_text("precious")
    out = tmp_path / "out"
    out.mkdir()
    (out / "a.tex").symlink_to(victim)
    with pytest.raises(files.UnsafePath):
        report.write(out, {"a.tex": "new"})
    assert victim.read_text() == "precious"
    assert (out / "a.tex").is_symlink()


def test_figures_refuses_to_overwrite_a_link_target(tmp_path, capsys):
    victim = tmp_path / "victim.csv"
    victim.write_text("precious")
    out = tmp_path / "figs"
    out.mkdir()
    (out / "fig7a.csv").symlink_to(victim)
    code = main(["figures", "--out", str(out)])
    err = capsys.readouterr().err
    one_line_error(code, err, "--out", "symbolic link")
    assert victim.read_text() == "precious"


def test_figures_refuses_a_symlinked_png(tmp_path, capsys):
    victim = tmp_path / "victim.png"
    victim.write_bytes(b"precious")
    out = tmp_path / "figs"
    out.mkdir()
    (out / "fig7a.png").symlink_to(victim)
    code = main(["figures", "--out", str(out)])
    one_line_error(code, capsys.readouterr().err, "--out")
    assert victim.read_bytes() == b"precious"
    assert not [p for p in out.iterdir() if p.name.endswith(".tmp")]


def test_junit_through_a_link_is_refused(tmp_path, cache, capsys):
    victim = tmp_path / "victim.xml"
    victim.write_text("precious")
    link = tmp_path / "verify.xml"
    link.symlink_to(victim)
    code = main(["verify", *CHEAP, "--junit", str(link)])
    one_line_error(code, capsys.readouterr().err, "--junit", "symbolic link")
    assert victim.read_text() == "precious"


def test_files_module(tmp_path):
    victim = tmp_path / "victim"
    victim.write_text("precious")
    (tmp_path / "link").symlink_to(victim)
    for write in (lambda p: files.write_text(p, "x"), lambda p: files.write_bytes(p, b"x"),
                  lambda p: files.write_atomic(p, lambda tmp: tmp.write_text("x")), files.ensure_dir):
        with pytest.raises(files.UnsafePath):
            write(tmp_path / "link")
    assert victim.read_text() == "precious"
    with pytest.raises(files.UnsafePath):
        files.inside(tmp_path, "../escape")
    with pytest.raises(files.UnsafePath):
        files.inside(tmp_path, "/etc/passwd")
    with pytest.raises(files.UnsafePath):
        files.inside(tmp_path, "link/below")
    files.write_text(tmp_path / "ok.txt", "é")
    assert (tmp_path / "ok.txt").read_text(encoding="utf-8") == "é"
    assert oct((tmp_path / "ok.txt").stat().st_mode & 0o777) == oct(0o644)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link", "ok.txt", "victim"]


def test_out_may_itself_be_a_link_to_a_directory(tmp_path):
    """The directory the user names is the user's choice; what is created below it is checked."""
    real = tmp_path / "real"
    real.mkdir()
    (tmp_path / "out").symlink_to(real, target_is_directory=True)
    files.check_writable(tmp_path / "out")
    files.write_text(files.inside(tmp_path / "out", "a.txt"), "x")
    assert (real / "a.txt").read_text() == "x"
    (tmp_path / "file").write_text("")
    with pytest.raises(OSError):
        files.output_dir(tmp_path / "file")


def test_latex_never_writes_through_a_link(tmp_path):
    from quasicentral.documents import report

    victim = tmp_path / "victim.pdf"
    victim.write_bytes(b"precious")
    out = tmp_path / "out"
    out.mkdir()
    (out / "doc.tex").write_text("\\documentclass{article}\\begin{document}x\\end{document}\n")
    (out / "doc.pdf").symlink_to(victim)
    with pytest.raises(files.UnsafePath):
        report.compile_one(out, "doc.tex")
    assert victim.read_bytes() == b"precious"


# --- LaTeX: a failed run cleans what blocks the next one ----------------------------------------------
@pytest.mark.skipif(shutil.which("latexmk") is None, reason="latexmk not installed")
def test_garbage_aux_does_not_block_the_pdf(tmp_path):
    from quasicentral.documents import report

    (tmp_path / "doc.tex").write_text("\\documentclass{article}\\begin{document}\\section{A}\\label{a}"
                                      "See \\ref{a}.\\end{document}\n")
    (tmp_path / "doc.aux").write_text("\\relax\n\\garbage{\\newlabel{a}{{\n\\@@@\n")
    (tmp_path / "doc.fdb_latexmk").write_bytes(b"\x00\xff not a database")
    pdf = report.compile_one(tmp_path, "doc.tex")
    assert pdf.is_file()
    pdf2 = report.compile_one(tmp_path, "doc.tex")  # and again, from what the first run left
    assert pdf2.is_file()


def test_clean_job_removes_links_without_following_them(tmp_path):
    from quasicentral.documents import report

    victim = tmp_path / "victim"
    victim.write_text("precious")
    (tmp_path / "doc.aux").symlink_to(victim)
    (tmp_path / "doc.toc").write_text("x")
    (tmp_path / "doc.log").write_text("kept")
    (tmp_path / "other.aux").write_text("kept")
    removed = report.clean_job(tmp_path, "doc")
    assert sorted(p.name for p in removed) == ["doc.aux", "doc.toc"]
    assert victim.read_text() == "precious"
    assert (tmp_path / "doc.log").exists() and (tmp_path / "other.aux").exists()


# --- worker processes end with their parent -----------------------------------------------------------
def _children(pid: int) -> set[int]:
    kids = set()
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                stat = (entry / "stat").read_text()
            except OSError:
                continue
            ppid = int(stat.rsplit(")", 1)[1].split()[1])
            if ppid == pid:
                kids.add(int(entry.name))
    return kids


def _alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="needs /proc (Linux)")
def test_kill_9_of_verify_ends_its_workers(tmp_path):
    env = dict(os.environ, QUASICENTRAL_CACHE=str(tmp_path / "cache"))
    proc = subprocess.Popen([sys.executable, "-m", "quasicentral.cli", "verify", *SLOW, "--no-cache", "--jobs", "2"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    workers: set[int] = set()
    try:
        deadline = time.monotonic() + 120
        while len(workers) < 2 and time.monotonic() < deadline and proc.poll() is None:
            time.sleep(0.2)
            workers = _children(proc.pid)
        assert len(workers) == 2, "the pool did not start"
        time.sleep(0.5)  # let the initializers arm the parent-death signal
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait(timeout=10)
        deadline = time.monotonic() + 10
        while any(_alive(w) for w in workers) and time.monotonic() < deadline:
            time.sleep(0.1)
        assert not [w for w in workers if _alive(w)], "workers outlived their parent"
    finally:
        if proc.poll() is None:
            proc.kill()
        for w in workers | _children(proc.pid):  # never leave a stray worker, pass or fail
            if _alive(w):
                os.kill(w, signal.SIGKILL)


def test_die_with_parent_exits_when_already_orphaned():
    """The initializer's own check: a worker whose parent is not the expected one ends."""
    from quasicentral.engine import workers

    pid = os.fork()
    if pid == 0:  # pragma: no cover - the child
        try:
            workers.die_with_parent(parent=os.getppid() + 10**7)
        finally:
            os._exit(0)
    _, status = os.waitpid(pid, 0)
    assert os.WEXITSTATUS(status) == 1


# --- progress ---------------------------------------------------------------------------------------
class _Tty(io.StringIO):
    def isatty(self):
        return True


class _Args:
    json = False


@pytest.mark.parametrize("stream, environ, json_, shown", [
    (_Tty(), {}, False, True),
    (_Tty(), {"CI": "true"}, False, False),
    (_Tty(), {"CI": "1"}, False, False),
    (_Tty(), {"CI": ""}, False, True),
    (_Tty(), {"CI": "false"}, False, True),
    (_Tty(), {}, True, False),
    (io.StringIO(), {}, False, False),
])
def test_progress_only_on_a_terminal_outside_ci_without_json(stream, environ, json_, shown):
    args = _Args()
    args.json = json_
    assert cli.show_progress(args, stream, environ) is shown


def test_progress_bar_draws_done_total_current_elapsed_remaining():
    tty = _Tty()
    bar = cli.ProgressBar(None, "verify", stream=tty, enabled=True)
    bar.mininterval = 0
    with bar:
        bar(Progress(2, 5, "cache", 2, "entries"))
        bar(Progress(3, 5, "brepta1953:23", 2, "entries"))
        bar(Progress(5, 5, "brepta1953:24", 2, "entries"))
    text = tty.getvalue()
    assert "verify" in text and "3/5" in text and "brepta1953:23" in text
    assert "<" in text  # elapsed<remaining
    assert bar.last.cached == 2


def test_progress_bar_disabled_draws_nothing_but_keeps_the_count():
    tty = io.StringIO()
    bar = cli.ProgressBar(None, "verify", stream=tty, enabled=False)
    bar(Progress(1, 2, "x", 1, "entries"))
    assert tty.getvalue() == "" and bar.last.done == 1


def test_verify_reports_progress(cache):
    from quasicentral.engine import run
    from quasicentral.engine.checker import Options

    ws = shipped.workspace()
    entries = [shipped.entry("brepta1953:1"), shipped.entry("brepta1953:4")]
    seen: list[Progress] = []
    run.run(ws, entries, Options(), use_cache=False, jobs=1, progress=seen.append)
    assert [(p.done, p.total) for p in seen] == [(0, 2), (1, 2), (2, 2)]
    assert [p.current for p in seen[1:]] == ["brepta1953:1", "brepta1953:4"]
    seen.clear()
    run.run(ws, entries, Options(), use_cache=True, progress=seen.append)
    assert [(p.done, p.total, p.cached, p.current) for p in seen] == [(2, 2, 2, "cache")]


def test_mutate_reports_progress():
    from quasicentral.engine import mutate

    seen: list[Progress] = []
    res = mutate.run(shipped.workspace(), [shipped.text("brepta1953")], ids=["brepta1953:1"], per_entry=1, jobs=1,
                     progress=seen.append)
    assert res["entries"] == 1
    assert [(p.done, p.total) for p in seen] == [(0, 1), (1, 1)] and seen[-1].current == "brepta1953:1"


@pytest.mark.skipif(sys.platform == "win32", reason="needs a pty")
def forget_runs(cache) -> None:
    """Forget the whole runs read back (the per-entry verdicts stay): the next run reads them."""
    for record in cache.glob("runs/*.json"):
        record.unlink()


def test_progress_shown_under_a_pty_and_not_in_a_pipe(cache):
    import pty

    forget_runs(cache)
    cmd = [sys.executable, "-m", "quasicentral.cli", "verify", *CHEAP]
    master, slave = pty.openpty()
    chunks = []
    try:
        proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=slave, env=env_without_ci())
        os.close(slave)  # the child holds the only other end: reading ends (EIO) when it exits
        while True:  # read while it runs, so that it never blocks on a full terminal buffer
            try:
                data = os.read(master, 65536)
            except OSError:
                break
            if not data:
                break
            chunks.append(data)
        proc.wait(timeout=300)
    finally:
        os.close(master)
    assert proc.returncode == 0
    drawn = b"".join(chunks).decode("utf-8", "replace")
    assert "verify: 2/2" in drawn, drawn
    assert "verify: checked 2 entries in" in drawn
    forget_runs(cache)
    code, out, err = run_cli("verify", *CHEAP, env=env_without_ci())  # stderr a pipe: no bar
    assert code == 0 and "2/2" not in err and err.startswith("verify: checked 2 entries in"), err
    code, out, err = run_cli("verify", *CHEAP, "--json", env=env_without_ci())
    assert code == 0 and err == "" and json.loads(out)["summary"]["ok"]


# --- help that teaches --------------------------------------------------------------------------------
MINE = ("verify", "errata", "mutate", "catalog", "report", "figures")


@pytest.mark.parametrize("command", MINE)
def test_help_has_a_description_an_example_and_every_option_explained(command):
    parser = cli.build_parser()
    sub = next(a for a in parser._actions if isinstance(a, __import__("argparse")._SubParsersAction))
    p = sub.choices[command]
    assert p.description and len(p.description) > 60
    assert p.epilog and f"quasicentral {command}" in p.epilog
    for action in p._actions:
        if action.dest != "help":
            assert action.help, f"{command} {action.option_strings} has no help"
            if action.choices:
                assert all(str(c) in action.help for c in action.choices), action.help
    text = p.format_help()
    assert "examples:" in text


def test_mutate_help_documents_its_exit_codes():
    code, out, _ = run_cli("mutate", "--help")
    assert code == 0 and "exit codes" in out and "recall" in out


def test_version():
    from importlib import metadata

    code, out, _ = run_cli("--version")
    assert code == 0 and out.strip() == f"quasicentral {metadata.version('quasicentral')}"


def test_model_choices_listed():
    from quasicentral.models.motion import MODELS

    code, out, _ = run_cli("trajectory", "--help")
    assert code == 0
    for name in MODELS:
        assert name in out


def test_a_temporary_file_swapped_mid_write_is_not_renamed_into_place(tmp_path):
    target = tmp_path / "a.txt"
    target.write_text("old")

    def swap(tmp):
        tmp.unlink()
        tmp.write_text("someone else's")

    with pytest.raises(files.UnsafePath):
        files.write_atomic(target, swap)
    assert target.read_text() == "old"
    assert [p.name for p in tmp_path.iterdir()] == ["a.txt"]


def test_a_special_file_is_never_replaced(tmp_path):
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    (tmp_path / "dir").mkdir()
    for target in (fifo, tmp_path / "dir"):
        with pytest.raises(files.UnsafePath, match="refusing to replace"):
            files.write_text(target, "x")
        with pytest.raises(files.UnsafePath):
            files.write_atomic(target, lambda tmp: tmp.write_text("x"))
    assert fifo.is_fifo() and (tmp_path / "dir").is_dir()
