"""What the hostile-folder contract tests (issue 29, ``tests/test_hostile_*.py``) share: a text's
folder as ``quasicentral new-text`` writes it, edited into each reproduction, and the command run
on it in a subprocess of its own — with a private verdict cache, a memory ceiling and a wall-clock
ceiling, in a session of its own so that whatever it leaves running (a worker stuck in a hostile
derivation) is killed with it.

The contract every test checks (unless the case says "the right answer"): one line on stderr,
``quasicentral: error: ...``, naming the file and line (or the entry id, or the option), exit 2;
never a traceback, never "internal error", never a wrong verdict with exit 0; nothing outside
``--out`` written; nothing already written corrupted.  The Python API raises
``quasicentral.InputError`` (a ``ValueError``) with the same message, in Python's words.
"""

from __future__ import annotations

import json
import os
import re
import resource
import shutil
import signal
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parent.parent
SKELETON_ID = "zzskel"  # the id the shared skeleton is written with; each copy gets its own
MEMORY_CEILING = 2 * 2**30  # bytes of address space: a hostile input that eats memory fails, not the machine
DEFAULT_SECONDS = 120.0  # no command of these tests takes more than a few seconds when it behaves
HANG_SECONDS = 30.0  # "each must end within ~30 s with --timeout 2"
DEEP = "deep = " + "[" * 5000 + "]" * 5000  # a TOML array nested beyond any text (and Python's recursion)
CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f\x80-\x9f]")  # what must never reach a terminal raw


@dataclass
class Run:
    code: int | None  # None: still running when the test's ceiling came (it was killed)
    out: str
    err: str
    seconds: float
    maxrss_kb: int = 0

    @property
    def hung(self) -> bool:
        return self.code is None


def env_for(cache: Path, **extra) -> dict:
    """The environment of a command: this worktree on PYTHONPATH, a private cache, no CI (so the
    output does not depend on where the tests run), no progress bar (stderr is a pipe); ``extra``
    on top (a value None unsets the variable)."""
    env = {k: v for k, v in os.environ.items() if k not in ("CI", "PYTHONWARNINGS")}
    env["PYTHONPATH"] = str(REPO)
    env["QUASICENTRAL_CACHE"] = str(cache)
    for key, value in extra.items():  # None: the variable is not set
        if value is None:
            env.pop(key, None)
        else:
            env[key] = value
    return env


def _limits() -> None:  # pragma: no cover - runs in the child before exec
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_CEILING, MEMORY_CEILING))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    # a test runner may ignore SIGINT, and an ignored signal is inherited: the command gets the
    # dispositions a shell would give it
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, signal.SIG_DFL)


def spawn(args, env: dict, cwd: Path | None = None) -> subprocess.Popen:
    """``quasicentral ARGS`` started (not waited for), in a session of its own."""
    return subprocess.Popen([sys.executable, "-m", "quasicentral.cli", *map(str, args)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, stdin=subprocess.DEVNULL, env=env, cwd=cwd,
                            start_new_session=True, preexec_fn=_limits)


def spawn_to_files(args, env: dict, cwd: Path, out: Path, err: Path) -> subprocess.Popen:
    """As :func:`spawn`, its output into files (a test that watches the process while it runs
    never blocks it on a full pipe)."""
    with open(out, "wb") as o, open(err, "wb") as e:
        return subprocess.Popen([sys.executable, "-m", "quasicentral.cli", *map(str, args)], stdout=o, stderr=e,
                                stdin=subprocess.DEVNULL, env=env, cwd=cwd, start_new_session=True,
                                preexec_fn=_limits)


def kill_tree(proc: subprocess.Popen, extra: set[int] = frozenset()) -> None:
    """SIGKILL what is left of the command: its process group (the session it was started in),
    and every process in ``extra`` or below it that is still in that session — and nothing
    else, so that a pid reused by another process is never touched."""
    below = descendants(proc.pid) if proc.returncode is None else set()
    for pid in set(extra) | below:
        if _session(pid) == proc.pid:
            _kill(pid)
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except OSError:
        pass
    if proc.returncode is None:
        _kill(proc.pid)


def _kill(pid: int) -> None:
    try:
        os.kill(pid, signal.SIGKILL)
    except OSError:
        pass


def finish(proc: subprocess.Popen, seconds: float, t0: float | None = None) -> Run:
    """Wait for ``proc`` at most ``seconds``; a command still running then is killed (``code``
    None).  ``maxrss_kb`` is the command's own peak memory (``wait4``)."""
    t0 = time.monotonic() if t0 is None else t0
    import threading

    chunks: dict[str, list[bytes]] = {"out": [], "err": []}

    def drain(stream, key):
        for block in iter(lambda: stream.read(65536), b""):
            chunks[key].append(block)

    readers = [threading.Thread(target=drain, args=(proc.stdout, "out"), daemon=True),
               threading.Thread(target=drain, args=(proc.stderr, "err"), daemon=True)]
    for r in readers:
        r.start()
    code, rss = None, 0
    deadline = t0 + seconds
    while True:
        pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
        if pid == proc.pid:
            code = os.waitstatus_to_exitcode(status)
            rss = usage.ru_maxrss
            proc.returncode = code
            break
        if time.monotonic() > deadline:
            break
        time.sleep(0.02)
    elapsed = time.monotonic() - t0
    kill_tree(proc)  # still running: all of it; else a worker that outlived its parent
    if code is None:
        try:
            os.waitpid(proc.pid, 0)
        except ChildProcessError:
            pass
        proc.returncode = -9
    for r in readers:
        r.join(timeout=5)
    return Run(code, b"".join(chunks["out"]).decode("utf-8", "replace"),
               b"".join(chunks["err"]).decode("utf-8", "replace"), elapsed, rss)


def qc(*args, cache: Path, cwd: Path | None = None, seconds: float = DEFAULT_SECONDS, **env_extra) -> Run:
    """Run ``quasicentral ARGS`` to its end (at most ``seconds``)."""
    t0 = time.monotonic()
    return finish(spawn(args, env_for(cache, **env_extra), cwd), seconds, t0)


# --- the folder ---------------------------------------------------------------------------------
def make_skeleton(folder: Path, cache: Path) -> Path:
    """``quasicentral new-text FOLDER --id zzskel``, as a user types it."""
    run = qc("new-text", folder, "--id", SKELETON_ID, cache=cache)
    assert run.code == 0, run.err
    return folder


def copy_text(template: Path, dest: Path, tid: str) -> Path:
    """A copy of the skeleton as the text ``tid`` (its id, equation ids and module names)."""
    shutil.copytree(template, dest, ignore=shutil.ignore_patterns("__pycache__"))
    for path in dest.rglob("*"):
        if path.is_file():
            path.write_text(path.read_text(encoding="utf-8").replace(SKELETON_ID, tid), encoding="utf-8")
    return dest


class Folder:
    """A text's folder being edited into a reproduction."""

    def __init__(self, root: Path, tid: str):
        self.root = root
        self.id = tid

    def path(self, rel: str) -> Path:
        return self.root / rel

    def read(self, rel: str) -> str:
        return self.path(rel).read_text(encoding="utf-8")

    def write(self, rel: str, text: str) -> Path:
        p = self.path(rel)
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text(text, encoding="utf-8")
        return p

    def replace(self, rel: str, old: str, new: str, count: int = 1) -> None:
        text = self.read(rel)
        assert old in text, (rel, old)
        self.write(rel, text.replace(old, new, count))

    def replace_line(self, rel: str, start: str, new: str) -> int:
        """Replace the first line of ``rel`` that starts with ``start`` by ``new``; its number."""
        lines = self.read(rel).splitlines(keepends=True)
        for i, line in enumerate(lines):
            if line.startswith(start):
                lines[i] = new.rstrip("\n") + "\n"
                self.write(rel, "".join(lines))
                return i + 1
        raise AssertionError(f"no line of {rel} starts with {start!r}")

    def append(self, rel: str, text: str) -> None:
        self.write(rel, self.read(rel) + text)

    def line_of(self, rel: str, needle: str) -> int:
        """The first line of ``rel`` holding ``needle`` (1-based)."""
        for i, line in enumerate(self.read(rel).splitlines(), 1):
            if needle in line:
                return i
        raise AssertionError(f"{needle!r} not in {rel}")

    # the skeleton's own lines, for the edits of the reproductions
    @property
    def catalog(self) -> str:
        return "catalog/motion.toml"

    @property
    def errata(self) -> str:
        return "errata/motion.toml"

    @property
    def module(self) -> str:
        return "motion.py"

    def in_derivation(self, entry: int, code: str) -> None:
        """Put ``code`` (one or more lines) at the start of the derivation of ``ID:entry`` (1:
        position, 2: velocity_squared), after its docstring."""
        anchor = {1: "x'' = a integrated twice, with x(0) = x0 and x'(0) = v0.\"\"\"\n",
                  2: "checked on that motion (lhs - rhs must vanish at every time).\"\"\"\n"}[entry]
        body = "".join(f"    {line}\n" for line in code.splitlines())
        self.replace(self.module, anchor, anchor + body)

    def at_module_level(self, code: str) -> int:
        """Put ``code`` after the module's imports; the line it starts on."""
        anchor = "S = symbols_of(__file__)"
        before = self.read(self.module).split(anchor, 1)[0]
        self.replace(self.module, anchor, code.rstrip("\n") + "\n" + anchor)
        return before.count("\n") + 1


# --- the contract ---------------------------------------------------------------------------------
def no_crash(run: Run) -> None:
    """Never a traceback, never "internal error", never still running."""
    assert not run.hung, f"still running after {run.seconds:.0f} s (killed); stderr: {run.err[-2000:]}"
    text = run.out + run.err
    assert "Traceback (most recent call last)" not in text, run.err[-3000:]
    assert "internal error" not in text, run.err[-3000:]


def one_line_error(run: Run, *names: str, pattern: str | None = None) -> str:
    """Exit 2 and exactly one line on stderr, ``quasicentral: error: ...``, naming ``names``
    (and matching ``pattern``, a regular expression); the message."""
    no_crash(run)
    assert run.code == 2, f"exit {run.code}, not 2; stdout: {run.out[-1500:]!r}; stderr: {run.err[-1500:]!r}"
    err = run.err
    assert err.count("\n") == 1 and err.startswith("quasicentral: error:"), err
    for name in names:
        assert name in err, (name, err)
    if pattern is not None:
        assert re.search(pattern, err, re.I), (pattern, err)
    return err


def names_file_and_line(message: str, path: Path, lines) -> None:
    """``message`` names ``path`` (its full path, as given or with its folder resolved) at one of
    ``lines``."""
    lines = {lines} if isinstance(lines, int) else set(lines)
    spellings = {str(path), str(path.parent.resolve() / path.name)}  # as given, or its folder resolved
    found = [int(m.group(1)) for spelling in spellings
             for m in re.finditer(re.escape(spelling) + r":(\d+)", message)]
    assert found, f"{path}:LINE not in {message!r}"
    assert set(found) & lines, f"{message!r} names line(s) {found} of {path.name}, expected one of {sorted(lines)}"


def verify_json(run: Run) -> dict:
    """The JSON document ``verify --json`` printed (stdout must be exactly one)."""
    try:
        return json.loads(run.out)
    except ValueError as exc:
        raise AssertionError(f"stdout is not one JSON document ({exc}): {run.out[:1500]!r}") from None


def by_id(doc: dict) -> dict[str, dict]:
    return {e["id"]: e for e in doc["equations"]}


def no_raw_control(text: str) -> None:
    bad = sorted({repr(c) for c in CONTROL.findall(text)})
    assert not bad, f"raw control characters {bad} reach the terminal: {text[:1500]!r}"


def input_error_type():
    """``quasicentral.InputError``: the one documented exception type of the Python API."""
    import quasicentral

    exc = getattr(quasicentral, "InputError", None)
    if exc is None:
        pytest.fail("quasicentral.InputError is not defined (the API's one documented exception type)")
    assert isinstance(exc, type) and issubclass(exc, ValueError), exc
    return exc


# --- processes --------------------------------------------------------------------------------------
def _fields(pid: int) -> list[str] | None:
    """/proc/PID/stat after the command name: state, ppid, pgrp, session, ..."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return None
    return stat.rsplit(")", 1)[1].split()


def _stat(pid: int) -> tuple[str, int] | None:
    fields = _fields(pid)
    return None if fields is None else (fields[0], int(fields[1]))


def _session(pid: int) -> int | None:
    fields = _fields(pid)
    return None if fields is None else int(fields[3])


def descendants(pid: int) -> set[int]:
    """Every process below ``pid`` (children, grandchildren …), from the ppid chains of /proc."""
    parent_of: dict[int, int] = {}
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            got = _stat(int(entry.name))
            if got is not None:
                parent_of[int(entry.name)] = got[1]
    out: set[int] = set()
    frontier = {pid}
    while frontier:
        frontier = {p for p, pp in parent_of.items() if pp in frontier and p not in out}
        out |= frontier
    return out


def alive(pid: int) -> bool:
    got = _stat(pid)
    return got is not None and got[0] not in ("Z", "X")


# --- fixtures (imported by each tests/test_hostile_*.py) ---------------------------------------------
@pytest.fixture(scope="session")
def skeleton_template(tmp_path_factory) -> Path:
    """One ``quasicentral new-text`` per worker; each test edits a copy of it (``text``)."""
    base = tmp_path_factory.mktemp("hostile-skeleton")
    return make_skeleton(base / SKELETON_ID, base / "cache")


class Shell:
    """The commands of one test: its own cache, its own working directory (where a stray
    relative write would land)."""

    def __init__(self, tmp_path: Path):
        self.tmp = tmp_path
        self.cache = tmp_path / "cache"
        self.cwd = tmp_path / "cwd"
        self.cwd.mkdir(exist_ok=True)

    @property
    def env(self) -> dict:
        return env_for(self.cache)

    def run(self, *args, seconds: float = DEFAULT_SECONDS, **env_extra) -> Run:
        return qc(*args, cache=self.cache, cwd=self.cwd, seconds=seconds, **env_extra)

    def spawn(self, *args) -> subprocess.Popen:
        return spawn(args, self.env, self.cwd)


@pytest.fixture
def sh(tmp_path) -> Shell:
    return Shell(tmp_path)


def text_id_for(nodeid: str) -> str:
    import hashlib

    return "h" + hashlib.sha1(nodeid.encode()).hexdigest()[:8]


@pytest.fixture
def text(skeleton_template, tmp_path, request) -> Folder:
    """A fresh copy of the ``new-text`` skeleton, under an id of this test's own (so that texts
    loaded in the test process never share an id)."""
    tid = text_id_for(request.node.nodeid)
    return Folder(copy_text(skeleton_template, tmp_path / tid, tid), tid)


@pytest.fixture
def make_text(skeleton_template, tmp_path):
    """More copies of the skeleton, under the ids the test names."""
    def make(tid: str) -> Folder:
        return Folder(copy_text(skeleton_template, tmp_path / tid, tid), tid)

    return make
