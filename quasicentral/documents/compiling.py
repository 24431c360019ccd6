"""Compiling the documents: latexmk, its log read for errors and undefined references, a
failed job's auxiliary files removed so that the next run starts clean.
"""

from __future__ import annotations

from types import MappingProxyType
import os
import re
import shutil
import subprocess
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from quasicentral import files
from quasicentral.documents.blocks import VERSIONS_FILE


class LatexError(RuntimeError):
    """A document did not compile (or has undefined references); ``log`` names the log file."""

    def __init__(self, message: str, log: Path):
        super().__init__(message)
        self.log = log



# --- compiling -------------------------------------------------------------------------------
_LOG_PROBLEMS = (
    re.compile(r"^! .*", re.M),
    re.compile(r"^[^\s:()]+\.(?:tex|sty|cls|aux|toc|out):\d+: .*", re.M),  # -file-line-error
    re.compile(r"LaTeX Warning: Reference .* undefined.*"),
    re.compile(r"LaTeX Warning: There were undefined references.*"),
    re.compile(r"LaTeX Warning: Label .* multiply defined.*"),
    re.compile(r"pdfTeX warning \(dest\): name\{.*\} has been referenced but does not exist.*"),
)


def log_problems(log_text: str) -> list[str]:
    """Errors and undefined or duplicate references in a LaTeX log."""
    found = []
    for pat in _LOG_PROBLEMS:
        found += [m.group(0).strip() for m in pat.finditer(log_text)]
    return found


#: TeX's own file access for a document built from a folder someone sent: it may read and write
#: only inside its build folder (paranoid), and run no program
SANDBOX = MappingProxyType({"openin_any": "p", "openout_any": "p", "shell_escape": "f"})


def compile_one(out: Path, name: str) -> Path:
    """``latexmk -pdf`` one document of ``out`` in a build folder of its own (a fresh folder
    inside ``out``, holding copies of the document, ``versions.tex`` and the figures), TeX kept
    to that folder (:data:`SANDBOX`: no ``\\input`` of a file elsewhere, no ``\\openout`` of a
    file of ``out``, no shell); the PDF and the log then written into ``out`` through a
    temporary file and a rename.  Raises :class:`LatexError` on any LaTeX error or undefined
    reference.  Returns the PDF's path."""
    stem = name[:-4]
    for suffix in (".pdf", ".log"):  # a link there is refused before anything is built
        files.inside(out, stem + suffix)
    clean_job(out, stem)  # what an earlier build left beside the document
    log = out / f"{stem}.log"
    build = Path(tempfile.mkdtemp(prefix=f"quasicentral-build-{stem}-", dir=out))
    try:
        _stage(out, build, name)
        proc, problems = _latexmk(build, name, log)
        built_log = build / f"{stem}.log"
        if built_log.is_file():
            files.write_bytes(log, built_log.read_bytes())
        if proc.returncode != 0 or problems:
            first = problems[0] if problems else f"latexmk exited with {proc.returncode}"
            raise LatexError(f"LaTeX failed on {name} ({first[:160]}): see {log}", log)
        pdf = build / f"{stem}.pdf"
        try:
            files.write_bytes(out / f"{stem}.pdf", pdf.read_bytes())
        except OSError as exc:
            raise LatexError(f"cannot write {out / (stem + '.pdf')}: {exc.strerror or exc}", log) from None
    finally:
        shutil.rmtree(build, ignore_errors=True)
    return out / f"{stem}.pdf"


def _stage(out: Path, build: Path, name: str) -> None:
    """Copy what a document includes into its build folder (regular files only)."""
    import stat

    def copy(src: Path, dst: Path) -> None:
        st = os.lstat(src)
        if stat.S_ISREG(st.st_mode):
            shutil.copyfile(src, dst)

    copy(out / name, build / name)
    if (out / VERSIONS_FILE).is_file():
        copy(out / VERSIONS_FILE, build / VERSIONS_FILE)
    figures = out / "figures"
    if figures.is_dir() and not figures.is_symlink():
        (build / "figures").mkdir()
        for f in sorted(figures.iterdir()):
            copy(f, build / "figures" / f.name)


#: the last pass's word that the cross-references have not settled, and how often to go on then
UNSETTLED = "Rerun to get cross-references right"
UNSETTLED_RERUNS = 2


def _latexmk(build: Path, name: str, log: Path):
    env = {**os.environ, "SOURCE_DATE_EPOCH": "0", "FORCE_SOURCE_DATE": "1", **SANDBOX}
    cmd = ["latexmk", "-norc", "-pdf", "-interaction=nonstopmode", "-halt-on-error", "-file-line-error",
           "-silent", name]
    built_log = build / f"{name[:-4]}.log"
    for attempt in range(1 + UNSETTLED_RERUNS):
        try:
            proc = subprocess.run(cmd if attempt == 0 else cmd[:1] + ["-g"] + cmd[1:], cwd=build, capture_output=True,
                                  text=True, env=env, timeout=600)
        except FileNotFoundError:
            raise LatexError("latexmk is not installed (run ./setup.sh)", log) from None
        except subprocess.TimeoutExpired:
            raise LatexError(f"LaTeX did not finish within 600 s: see {log}", log) from None
        # latexmk may stop while the cross-references still move (seen now and then on a busy
        # machine, never on a quiet one): one more pass, forced, settles them
        if proc.returncode != 0 or not built_log.is_file() or \
                UNSETTLED not in built_log.read_text(encoding="utf-8", errors="replace"):
            break
    problems = log_problems(built_log.read_text(encoding="utf-8", errors="replace")) if built_log.is_file() else []
    return proc, problems


#: What a LaTeX run leaves beside the document that a later run reads back (the log is kept).
AUX_SUFFIXES = (".aux", ".toc", ".out", ".lof", ".lot", ".nav", ".snm", ".bbl", ".blg", ".fls", ".fdb_latexmk",
                ".synctex.gz")


def clean_job(out: Path, stem: str) -> list[Path]:
    """Remove the auxiliary files of the job ``stem`` in ``out`` (what would make the next run
    fail again); returns those removed.  Symbolic links are removed, never followed."""
    removed = []
    for suffix in AUX_SUFFIXES:
        path = out / f"{stem}{suffix}"
        if os.path.lexists(path) and not path.is_dir():
            path.unlink()
            removed.append(path)
    return removed


def compile_all(out: Path, names: list[str], jobs: int | None = None, progress=None) -> list[Path]:
    """Compile the documents (in parallel); the first failure raises :class:`LatexError`.
    ``progress`` (a :class:`quasicentral.progress.Progress` callback) is told of each PDF."""
    from quasicentral.progress import notify

    names = [n for n in names if n != VERSIONS_FILE]
    jobs = jobs or min(len(names), os.cpu_count() or 1) or 1
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = [pool.submit(compile_one, out, n) for n in names]
        pdfs = []
        notify(progress, 0, len(names), "", 0, "PDFs")
        for name, f in zip(names, futures):
            pdfs.append(f.result())
            notify(progress, len(pdfs), len(names), name, 0, "PDFs")
        return pdfs
