"""Issue 29, hostile folders — a text's words go into LaTeX: they are printed, never obeyed.  A
title, an erratum's note or a cause's title holding TeX's special characters or primitives
(``&``, ``%``, ``\\input``, ``\\openout``) compiles and shows the words as written; no file is
read into the PDF, none is written in ``--out``; and a PDF that TeX cannot write is named as
such, not as an undefined reference.

Each test builds the report of a fresh skeleton with ``report --pdf`` (about three seconds) and
reads the PDF back with ``pdftotext``."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from hostile_support import Folder, no_crash, sh, skeleton_template, text  # noqa: F401 - fixtures

pytestmark = pytest.mark.skipif(shutil.which("latexmk") is None or shutil.which("pdftotext") is None,
                                reason="needs latexmk and pdftotext")

TITLE = 'title = "Uniformly accelerated motion"'
CAUSE_TITLE = 'title = "The factor 2 of the work-energy relation is lost"'
NOTE = 'note = "Eliminating t from (1)'


def pdf_text(pdf: Path) -> str:
    return subprocess.run(["pdftotext", "-enc", "UTF-8", str(pdf), "-"], check=True, capture_output=True,
                          text=True).stdout


def squeezed(s: str) -> str:
    """``s`` without white space or hyphenation, for finding a phrase however TeX broke it."""
    return re.sub(r"\s+", "", re.sub(r"-\s*\n", "", s))


def report_pdf(text: Folder, sh, out: Path):
    run = sh.run("report", "--text", text.root, "--out", out, "--pdf")
    no_crash(run)
    return run, out / f"{text.id}-report-en.pdf"


def test_title_with_ampersand_and_percent_compiles(text, sh, tmp_path):
    """a text's title `"Drag & lift at 100%"` must compile with `report --pdf`; a title / erratum note
    / cause title with `\\input{/etc/hostname}` must not print that file into the PDF (check with
    `pdftotext` that the hostname does not appear and the literal text does);
    `\\immediate\\openout\\x=versions.tex \\immediate\\write\\x{pwned}\\immediate\\closeout\\x` in a
    title must not change `versions.tex` (or any file) in `--out`.

    Here: the title `"Drag & lift at 100%"`, compiled and shown as written."""
    text.replace("text.toml", TITLE, 'title = "Drag & lift at 100%"')
    run, pdf = report_pdf(text, sh, tmp_path / "out")
    assert run.code == 0, run.err[-2000:]
    assert "Drag & lift at 100%" in pdf_text(pdf)


def _hostname() -> str | None:
    try:
        name = Path("/etc/hostname").read_text().strip()
    except OSError:
        return None
    return name or None


@pytest.mark.parametrize("place", ["title", "erratum note", "cause title"])
def test_input_in_prose_is_printed_not_read(text, sh, tmp_path, place):
    """a text's title `"Drag & lift at 100%"` must compile with `report --pdf`; a title / erratum note
    / cause title with `\\input{/etc/hostname}` must not print that file into the PDF (check with
    `pdftotext` that the hostname does not appear and the literal text does);
    `\\immediate\\openout\\x=versions.tex \\immediate\\write\\x{pwned}\\immediate\\closeout\\x` in a
    title must not change `versions.tex` (or any file) in `--out`.

    Here: `\\input{/etc/hostname}` in the title, an erratum's note or a cause's title (each
    written as a TOML literal string, as a user writes a backslash)."""
    hostname = _hostname()
    if hostname is None:
        pytest.skip("no /etc/hostname to read")
    words = r"Marker \input{/etc/hostname} here"
    if place == "title":
        text.replace("text.toml", TITLE, f"title = '{words}'")
    elif place == "erratum note":  # a literal string, as a user writes a note holding a backslash
        text.replace_line(text.errata, NOTE, f"note = '{words}.  Witness: {{witness}}.'")
    else:
        text.replace(text.errata, CAUSE_TITLE, f"title = '{words}'")
    run, pdf = report_pdf(text, sh, tmp_path / "out")
    assert run.code == 0, run.err[-2000:]
    shown = pdf_text(pdf)
    assert squeezed(words) in squeezed(shown), f"the literal {words!r} is not in the PDF"
    assert not re.search(rf"(?<![A-Za-z0-9]){re.escape(hostname)}(?![A-Za-z0-9])", shown), \
        f"the hostname {hostname!r} was read into the PDF"


OPENOUT = r"\immediate\openout\x=versions.tex \immediate\write\x{pwned}\immediate\closeout\x"


def test_openout_in_a_title_writes_no_file(text, sh, tmp_path):
    """a text's title `"Drag & lift at 100%"` must compile with `report --pdf`; a title / erratum note
    / cause title with `\\input{/etc/hostname}` must not print that file into the PDF (check with
    `pdftotext` that the hostname does not appear and the literal text does);
    `\\immediate\\openout\\x=versions.tex \\immediate\\write\\x{pwned}\\immediate\\closeout\\x` in a
    title must not change `versions.tex` (or any file) in `--out`.

    Here: the `\\openout` title; `--out` also holds a file of the user's own, which must stay as it
    was, and the title is printed as written."""
    out = tmp_path / "out"
    out.mkdir()
    (out / "precious.txt").write_text("precious")
    text.replace("text.toml", TITLE, f"title = '{OPENOUT}'")
    run, pdf = report_pdf(text, sh, out)
    assert "pwned" not in (out / "versions.tex").read_text(encoding="utf-8", errors="replace")
    assert (out / "precious.txt").read_text() == "precious"
    stem = f"{text.id}-report-en"
    # TeX's own records of the run may quote the title; nothing else may hold its words
    quoting = {f"{stem}.{ext}" for ext in ("tex", "log", "aux", "out", "toc", "fls", "fdb_latexmk", "pdf")}
    for path in out.rglob("*"):
        if path.is_file() and path.name not in quoting:
            assert b"pwned" not in path.read_bytes(), f"{path.name} was written by the title"
    made = {p.name for p in out.iterdir()}
    assert made <= quoting | {"versions.tex", "precious.txt", "figures"}, sorted(made - quoting)
    assert run.code == 0, run.err[-2000:]  # and the title is printed as written
    assert squeezed(OPENOUT) in squeezed(pdf_text(pdf))


def _immutable(path: Path, on: bool) -> bool:
    """``chattr +i`` / ``-i``: a file even root cannot write (False where the file system or the
    user cannot set it)."""
    if shutil.which("chattr") is None:
        return False
    return subprocess.run(["chattr", "+i" if on else "-i", str(path)], capture_output=True).returncode == 0


def test_a_pdf_tex_cannot_write_is_named_as_a_write_error(text, sh, tmp_path):
    """on a full disk (simulate: `--out` on a tiny tmpfs is not available; instead point `--out` at
    a folder where TeX cannot write its .pdf, e.g. a pre-existing read-only `X.pdf`) `report
    --pdf` names the write error, not an undefined reference;

    Here: a pre-existing read-only `X.pdf` (mode 0444; root writes such a file anyway, so as root
    it is also made immutable with `chattr +i`, and where that is not possible a folder takes the
    PDF's place).  The old PDF is left as it was."""
    out = tmp_path / "out"
    out.mkdir()
    blocked = out / f"{text.id}-report-en.pdf"
    old = b"%PDF-1.4 an old report\n"
    blocked.write_bytes(old)
    blocked.chmod(0o444)
    locked = os.geteuid() == 0 and _immutable(blocked, True)
    if os.geteuid() == 0 and not locked:
        blocked.unlink()
        blocked.mkdir()
    try:
        run, _ = report_pdf(text, sh, out)
    finally:
        if locked:
            _immutable(blocked, False)
    assert run.code in (1, 2), (run.code, run.out[-1000:], run.err[-2000:])
    err = run.err
    assert err.count("\n") == 1 and err.startswith("quasicentral: error:"), err
    assert blocked.name in err, err
    assert re.search(r"writ|read-only|permission|is a directory|not a regular file", err, re.I), err
    assert "undefined" not in err.lower(), err
    if blocked.is_file():
        assert blocked.read_bytes() == old  # nothing already written corrupted
