"""Reports and handouts: LaTeX regenerated from the engine's records, compiled to PDF.

Views over the same records (STYLE.md, point 9):

* the **report** of a text (:mod:`~quasicentral.documents.derivation_report`) opens with what
  its reader came for: the story in words (report.toml's abstract), what "printed" means for
  the text, what was checked and how, the counts, and one row per cause of its errata (page 1);
  then each cause explained once with the displays it affects, the cleared suspects, every
  equation of the text compactly (as printed, as re-derived in the text's notation, one short
  verdict, the step), the figures in the document's language; in appendices the method with
  the evidence for each equation, every erratum printed and corrected side by side, and the
  software note (the measured charts: about the toolkit, not the text);
* the **handout** (:mod:`~quasicentral.documents.handout`) tells the derivation to a student
  in the text's order, with the exercises of the text's bank (graded, each checked by
  :mod:`quasicentral.engine.exercises`) and no answer; the **teacher's** handout adds the
  worked solutions and the computed answers.

A text's own words (title, introductions, section titles, figure captions, Czech step texts)
come from ``<text folder>/report.toml`` (:mod:`quasicentral.documents.prose`); generic words
are in :data:`quasicentral.documents.prose.WORDS`; the engine's reasons in its wording table.
Everything here is deterministic: entries in catalog order, no timestamps, no absolute paths.
The software versions, which differ from machine to machine, go to ``versions.tex`` that the
reports ``\\input``.  Nothing here prints; the CLI does.

>>> all(name.endswith("-report-en.tex") for name in file_names(["mytext"], ("report",), ("en",)))
True
"""

from __future__ import annotations

from pathlib import Path

from quasicentral import files
from quasicentral.documents.blocks import VERSIONS_FILE, versions_tex
from quasicentral.documents.compiling import LatexError, clean_job, compile_all, compile_one, log_problems  # noqa: F401 - the commands'
from quasicentral.documents.derivation_report import report_tex
from quasicentral.documents.handout import handout_tex
from quasicentral.documents.latex import Notation, using
from quasicentral.documents.prose import LANGS
from quasicentral.documents.steps import FIGURE_DIR, FigureItem, TextRecords, figure_items, records_for  # noqa: F401
from quasicentral.files import write_atomic
from quasicentral.studies import figures as figures_mod

#: The documents of a text: the report, the students' handout, the teacher's handout.
KINDS = ("report", "handout", "teacher")
#: The two handouts: the students' (no solutions) and the teacher's (with solutions).
HANDOUT_KINDS = ("handout", "teacher")
#: The golden documents (kinds × languages) that ``quasicentral report --all`` writes.
GOLDEN = ((("report",), LANGS), (HANDOUT_KINDS, LANGS))
#: The command that regenerates every golden file under reports/.
REGENERATE = "quasicentral report --all --out reports"


def file_names(text_ids: list[str], kinds=KINDS, langs=LANGS) -> list[str]:
    """The .tex files that :func:`generate` writes for these texts, kinds and languages."""
    return [f"{tid}-{kind}-{lang}.tex" for kind in kinds for lang in langs for tid in text_ids]


def build(kind: str, rec: TextRecords, lang: str) -> str:
    """The LaTeX of one document of a text, in the text's notation (its text.toml)."""
    prose = rec.prose
    with using(Notation.of(rec.text.symbols, prose.symbols, prose.functions)):
        if kind == "report":
            return report_tex(rec, lang)
        return handout_tex(rec, lang, solutions=(kind == "teacher"))


def generate(records: list[TextRecords], kinds=("report",), langs=("en",)) -> dict[str, str]:
    """File name → LaTeX source of every document asked for, plus ``versions.tex``."""
    docs: dict[str, str] = {}
    for rec in records:
        for kind in kinds:
            for lang in langs:
                docs[f"{rec.id}-{kind}-{lang}.tex"] = build(kind, rec, lang)
    if "report" in kinds:
        docs[VERSIONS_FILE] = versions_tex()
    return {name: docs[name] for name in sorted(docs)}


def figures_needed(docs: dict[str, str], texts) -> list[FigureItem]:
    """The figures the documents include, in the order of the texts' figures."""
    return [f for f in figure_items(list(texts), LANGS) if any(f"{{{f.path}}}" in tex for tex in docs.values())]


def check_writable(out: Path) -> None:
    """Raise OSError when ``out`` cannot be created or written to (before anything is written);
    a symbolic link where a file or folder would be written is refused (files.UnsafePath)."""
    files.check_writable(out)


def write(out: Path, docs: dict[str, str], texts=(), progress=None) -> list[Path]:
    """Write the documents and the figures they include (each via a temporary file and a rename,
    so that a failure never leaves a half-written file; only inside ``out``, never through a
    symbolic link); the figures are those of ``texts`` the documents include.  ``progress`` (a
    :class:`quasicentral.progress.Progress` callback) is told of each figure drawn.  Returns the
    paths, sorted."""
    from quasicentral.progress import notify

    check_writable(out)
    written = []

    def put(path: Path, fill) -> None:
        write_atomic(path, fill)
        written.append(path)

    for name, tex in docs.items():
        put(files.inside(out, name), lambda tmp, tex=tex: tmp.write_text(tex, encoding="utf-8"))
    figs = figures_needed(docs, texts)
    if figs:
        files.ensure_dir(files.inside(out, FIGURE_DIR))
    notify(progress, 0, len(figs), "", 0, "figures")
    for i, f in enumerate(figs):
        put(files.inside(out, f.path), lambda tmp, f=f: figures_mod.draw(f.make(), tmp, f.lang, titled=False))
        notify(progress, i + 1, len(figs), f.path, 0, "figures")
    return sorted(written)
