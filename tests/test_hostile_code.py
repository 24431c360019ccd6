"""Issue 29, hostile folders — a transcription, a range or a definition is mathematics, never
code: a payload that reaches Python's builtins through a function's globals, ``__import__``,
attribute access, a lambda or a comprehension runs nothing (no ``PWNED`` file anywhere) and is
refused in one line naming the file and line.  And ``catalog`` runs none of the folder's code:
only verify, errata, mutate and report import its ``.py`` modules.  Beyond the issue's list, two
more ways a folder's code could run or a run could write into the folder: a planted
``__pycache__`` bytecode file taken for motion.py's, and the ``__pycache__`` an import leaves.

Each command runs in a working directory of the test's own, where ``touch PWNED`` would land;
the whole temporary folder of the test, the text's folder and the repository are searched for
it afterwards."""

from __future__ import annotations

from pathlib import Path

import pytest

from hostile_support import REPO, Folder, names_file_and_line, no_crash, one_line_error
from hostile_support import sh, skeleton_template, text  # noqa: F401 - fixtures

TOUCH = '("os").system("touch PWNED")'
PAYLOADS = {
    "Eq.__globals__": 'Eq.__globals__["__builtins__"]["__import__"]' + TOUCH,
    "__import__": "__import__" + TOUCH,
    "attribute access": 'D.__globals__["sp"].sympify("__import__(\'os\').system(\'touch PWNED\')")',
    # a lambda's or a comprehension's own scope sees the parser's globals (Rational), not its locals
    "lambda": '(lambda: Rational.__new__.__globals__["__builtins__"]["__import__"]' + TOUCH + ")()",
    "comprehension": '[Rational.__new__.__globals__["__builtins__"]["__import__"]' + TOUCH + " for t in (0,)]",
}


def _nothing_ran(sh, text: Folder) -> None:
    found = [str(p) for p in sh.tmp.rglob("PWNED")] + [str(p) for p in (REPO / "PWNED", text.root / "PWNED")
                                                       if p.exists()]
    assert not found, f"the folder's payload ran: {found}"


def _in_transcription(text: Folder, payload: str) -> tuple[str, list[int]]:
    line = text.replace_line(text.catalog, "printed = '''Eq(x, x0 + v0*t + a*t**2/2)'''",
                             f"printed = '''Eq(x, {payload})'''")
    return text.catalog, [line]


def _in_range(text: Folder, payload: str) -> tuple[str, list[int]]:
    line = text.replace_line("text.toml", 'range = ["-5", "5"]', f"range = ['-5', '''{payload}''']")
    return "text.toml", [line, text.line_of("text.toml", "[symbols.a]")]


def _in_definition(text: Folder, payload: str) -> tuple[str, list[int]]:
    text.replace("text.toml", "# Quantities along the motion",
                 f"[symbols.g]\nlatex = 'g'\nassumptions = [\"positive\"]\ndefinition = '''{payload}'''\n\n"
                 "# Quantities along the motion")
    return "text.toml", [text.line_of("text.toml", "definition = '''"), text.line_of("text.toml", "[symbols.g]")]


PLACES = {"transcription": _in_transcription, "range": _in_range, "definition": _in_definition}
CASES = ([("transcription", p) for p in PAYLOADS]
         + [("range", p) for p in ("Eq.__globals__", "comprehension")]
         + [("definition", p) for p in ("lambda", "attribute access")])


@pytest.mark.parametrize("place, payload", CASES, ids=[f"{a}-{b}" for a, b in CASES])
def test_code_in_the_mathematics_runs_nothing(text, sh, place, payload):
    """a catalog transcription `Eq.__globals__["__builtins__"]["__import__"]("os").system("touch
    PWNED")` runs nothing (no PWNED file in any folder) and is refused naming the file and line;
    likewise `__import__`, attribute access, lambda, comprehension in a transcription or a
    symbol's range/definition; `catalog` and `report` of such a folder run no code of it (a
    folder whose `motion.py` creates a file at import: `catalog` must not create it — only
    verify/errata/mutate/report run the folder's `.py` modules).

    Here: under `verify`, each payload in a transcription, and some in a range and a definition.
    "Attribute access" is the access to a function's or a module's insides (`__globals__`, a
    module's `sympify`), not sympy's own methods such as `x.subs(t, 0)`, which the shipped
    catalog uses."""
    rel, lines = PLACES[place](text, PAYLOADS[payload])
    run = sh.run("verify", "--text", text.root)
    _nothing_ran(sh, text)
    err = one_line_error(run)
    names_file_and_line(err, text.path(rel), lines)


@pytest.mark.parametrize("command", ["catalog", "report"])
def test_catalog_and_report_run_no_code_of_the_mathematics(text, sh, tmp_path, command):
    """a catalog transcription `Eq.__globals__["__builtins__"]["__import__"]("os").system("touch
    PWNED")` runs nothing (no PWNED file in any folder) and is refused naming the file and line;
    likewise `__import__`, attribute access, lambda, comprehension in a transcription or a
    symbol's range/definition; `catalog` and `report` of such a folder run no code of it (a
    folder whose `motion.py` creates a file at import: `catalog` must not create it — only
    verify/errata/mutate/report run the folder's `.py` modules).

    Here: `catalog` and `report` of the folder with the `Eq.__globals__` transcription: nothing
    ran, and the transcription is refused naming the file and line."""
    rel, lines = _in_transcription(text, PAYLOADS["Eq.__globals__"])
    args = ("--out", tmp_path / "out") if command == "report" else ()
    run = sh.run(command, "--text", text.root, *args)
    _nothing_ran(sh, text)
    err = one_line_error(run)
    names_file_and_line(err, text.path(rel), lines)


def test_catalog_imports_no_module_of_the_folder(text, sh, tmp_path):
    """a catalog transcription `Eq.__globals__["__builtins__"]["__import__"]("os").system("touch
    PWNED")` runs nothing (no PWNED file in any folder) and is refused naming the file and line;
    likewise `__import__`, attribute access, lambda, comprehension in a transcription or a
    symbol's range/definition; `catalog` and `report` of such a folder run no code of it (a
    folder whose `motion.py` creates a file at import: `catalog` must not create it — only
    verify/errata/mutate/report run the folder's `.py` modules).

    Here: the folder whose motion.py creates a file at import; `catalog` lists it (exit 0)
    without creating the file."""
    marker = tmp_path / "imported"
    text.at_module_level(f"open({str(marker)!r}, 'w').close()")
    run = sh.run("catalog", "--text", text.root)
    no_crash(run)
    assert not marker.exists(), "catalog imported the folder's motion.py"
    assert run.code == 0, (run.code, run.err[-1500:])


# --- beyond the list: the folder's own files are input, never output -----------------------
def _files(root: Path) -> dict[str, bytes]:
    return {p.relative_to(root).as_posix(): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


def test_verify_writes_nothing_into_the_texts_folder(text, sh):
    """Beyond issue 29's list, the contract's "nothing outside `--out` written" for the folder
    itself (someone else's notes, a read-only checkout): importing its derivation modules leaves
    no `__pycache__` there, in an environment without PYTHONDONTWRITEBYTECODE as a user has."""
    before = _files(text.root)
    run = sh.run("verify", "--text", text.root, PYTHONDONTWRITEBYTECODE=None)
    no_crash(run)
    assert run.code == 0, run.err[-1500:]
    assert _files(text.root) == before, sorted(set(_files(text.root)) - set(before))


def test_a_planted_bytecode_file_is_not_run_instead_of_the_source(text, sh, tmp_path):
    """Beyond issue 29's list: a folder that ships `__pycache__/motion.cpython-XY.pyc` compiled from
    other code, stamped with motion.py's own modification time and size, so that Python's import
    takes it for motion.py's: the code run is the source the reader reviewed, never the planted
    bytecode (here the planted code would create a file)."""
    import importlib.util
    from importlib import _bootstrap_external

    marker = tmp_path / "planted-code-ran"
    source = text.path(text.module)
    planted = f"open({str(marker)!r}, 'w').close()\n" + source.read_text()
    st = source.stat()
    code = compile(planted, str(source), "exec")
    pyc = Path(importlib.util.cache_from_source(str(source)))
    pyc.parent.mkdir()
    pyc.write_bytes(bytes(_bootstrap_external._code_to_timestamp_pyc(code, int(st.st_mtime), st.st_size)))
    run = sh.run("verify", "--text", text.root)
    no_crash(run)
    assert not marker.exists(), "the planted bytecode ran instead of motion.py"
    assert run.code == 0, run.err[-1500:]
