r"""Reports and handouts: the paper's notation, LaTeX that compiles, and golden files.

The golden files under ``reports/`` are the generated LaTeX, reviewed as diffs.  When the
derivations, the catalog, the errata or the rendering change, ``test_golden_reports`` fails
and names the command that regenerates them (after review):

    quasicentral report --all --out reports

The comparison is exact except for ``versions.tex`` (the machine's software) and the
arguments of ``\verdicthow{...}`` (how each verdict was reached and whether ball arithmetic
certifies it, which depend on the machine's speed through the checker's time bounds for
sympy and for ball integrals; see ``mask_how``).  Two
generations on one machine are compared byte for byte, everything included.
"""

from __future__ import annotations

import shipped

import difflib
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

import mpmath
import pytest
import sympy as sp

from quasicentral import files
from quasicentral.documents import blocks, derivation_report, report, steps as steps_mod
from quasicentral.engine.options import Options
from quasicentral.notation import bridge
from quasicentral.notation.symbols import D, Ec, Ej, Fj, Kc, arccotg
from quasicentral.cli import main
from quasicentral.documents.breaking import display_rows
from quasicentral.documents.latex import Notation, paper_latex, using
from quasicentral.documents.prosetex import clean_prose, escape, text, with_math

S = shipped.symbols("brepta1953")  # the printer speaks a text's notation: here Brepta's
P = shipped.symbols("pendulum")
WS = shipped.workspace()
TEXTS = WS.papers()

REPO = Path(__file__).resolve().parents[1]
GOLDEN = REPO / "reports"
REGENERATE = f"{report.REGENERATE}    (from the repository root, {REPO})"


# --- the printer: the paper's notation --------------------------------------------------------
@pytest.mark.parametrize("expr, expected", [
    (D(S.x), r"\dot{x}"),
    (D(S.y, 2), r"\ddot{y}"),
    (S.rho**2 * D(S.psi), r"\varrho^{2} \dot{\psi}"),
    (D(S.phi, 2) + S.phi, r"\ddot{\varphi} + \varphi"),  # the highest derivative first
    (D(S.rho, 2) - S.rho * D(S.psi) ** 2, r"\ddot{\varrho} - \varrho \dot{\psi}^{2}"),
    (Fj(S.k, S.zeta), r"F\left(k, \zeta\right)"),
    (Ej(S.k, S.zeta), r"E\left(k, \zeta\right)"),
    (Kc(S.k), "K"),
    (Ec(S.k), "E"),
    (sp.elliptic_k(sp.sin(P.phi0 / 2) ** 2), r"K\left(\sin {\frac{\varphi_0}{2}}\right)"),
    (arccotg(S.x / S.y), r"\arccotg \frac{x}{y}"),
    (bridge.jet_symbol(S.phi, 1), r"\dot{\varphi}"),  # a jet of the checker
    (sp.Subs(D(S.x), S.t, 0), r"\dot{x}\left(0\right)"),
    (sp.log(S.A), r"\ln A"),
    (sp.log(S.rho**2 * D(S.psi)), r"\ln \left(\varrho^{2} \dot{\psi}\right)"),
    (S.R0 * S.K1, r"K R_0"),  # the names the text declares
])
def test_paper_notation(expr, expected):
    with using(Notation.of(P if expr.has(P.phi0) else S)):
        assert paper_latex(expr) == expected


def test_no_function_of_t_shows_its_argument():
    expr = S.x * D(S.y) - S.y * D(S.x) + S.rho * D(S.psi, 2)
    with using(Notation.of(S)):
        tex = paper_latex(expr)
    assert "(t)" not in tex and r"\left(t \right)" not in tex and "frac{d}" not in tex


def test_a_function_of_another_variable_has_leibniz_derivatives():
    theta = sp.Symbol("theta", real=True)
    u = sp.Function("u")(theta)
    with using(Notation({"theta": r"\theta"}, {"u": "u"}, frozenset(), frozenset({theta}))):
        assert paper_latex(D(u, 2) + u) == r"\frac{d^{2}u}{d\theta^{2}} + u"


# --- the printed LaTeX: every entry can stand in one display --------------------------------
def _balanced(row: str) -> bool:
    import re

    from quasicentral.documents.breaking import _mask_nested

    depth = 0
    for m in re.finditer(r"\\left(?![A-Za-z])|\\right(?![A-Za-z])", _mask_nested(row)):
        depth += 1 if m.group(0) == r"\left" else -1
        if depth < 0:
            return False
    return depth == 0


def _all_printed_latex():
    errs, _ = shipped.records()
    out = [(e.id, e.latex) for t in TEXTS for e in t.entries.values()]
    out += [(i + "/corrected", r.corrected_latex) for i, r in errs.items()]
    return out


@pytest.mark.parametrize("eid, latex", _all_printed_latex(), ids=[i for i, _ in _all_printed_latex()])
def test_printed_rows_are_balanced(eid, latex):
    rows = display_rows(latex)
    assert rows and all(_balanced(r) for r in rows), rows
    assert not any(r.rstrip().endswith("\\\\") for r in rows)


def test_split_left_right_pairs_are_closed():
    rows = display_rows(r"C = \left[ a - \right. \\ \left. - b \left( c + \right. \right. \\ \left. \left. + d \right) \right] + e")
    assert len(rows) == 3 and all(_balanced(r) for r in rows)


# --- prose: Unicode mathematics becomes LaTeX -----------------------------------------------
_ALLOWED = set("áéíóúýčďěňřšťůžÁÉÍÓÚÝČĎĚŇŘŠŤŮŽ")


def _prose():
    errs, cleared = shipped.records()
    out = [d.doc for d in WS.derivations.by_id.values()] + [r.note for r in errs.values()]
    out += [c.note + c.suspicion for c in cleared.values()] + [e.name + e.note for t in TEXTS for e in t.entries.values()]
    return out


def test_prose_is_ascii_or_czech_after_escaping():
    for s in _prose():
        tex = with_math(s)
        bad = {ch for ch in tex if not ch.isascii() and ch not in _ALLOWED}
        assert not bad, (s, bad)


def test_text_examples():
    assert text("ρ̈") == r"\ensuremath{\ddot{\varrho}}"
    assert text("x²") == r"\ensuremath{x^{2}}"
    assert text("50% & $") == r"50\% \& \$"
    assert escape("a_b") == r"a\_b"


# --- golden files -----------------------------------------------------------------------------
@pytest.fixture(scope="module")
def generated(outcomes, verdict_cache, tmp_path_factory):
    """Every golden document generated in-process, written with its figures to a tmp dir; then
    a second generation in a fresh process (see test_generation_is_byte_identical), which
    overlaps with the compilation.  It starts after this one has drawn the figures: it copies
    those the session's cache keeps for the same data (keyed by the data, so a figure whose data
    depended on the hash seed would be drawn anew, and differ)."""
    records = report.records_for(WS, TEXTS, Options())  # the golden documents are the shipped texts'
    docs: dict[str, str] = {}
    for kinds, langs in report.GOLDEN:
        docs.update(report.generate(records, kinds, langs))
    out = tmp_path_factory.mktemp("reports")
    report.write(out, docs, TEXTS)
    second = tmp_path_factory.mktemp("second")
    # the session's cache: verdicts, derivations and figures read back (a derivation whose result
    # depended on the hash seed would show against the golden files: each session draws its own)
    env = {**os.environ, "PYTHONHASHSEED": "12345", "QUASICENTRAL_CACHE": str(verdict_cache)}
    proc = subprocess.Popen([sys.executable, "-m", "quasicentral.cli", "report", "--all", "--out", str(second)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env, cwd=second)
    yield out, docs, (proc, second)
    if proc.poll() is None:
        proc.kill()
    proc.communicate()


def mask_how(tex: str) -> str:
    r"""``tex`` with the argument of every ``\verdicthow{...}`` emptied.

    How a verdict was reached depends on the machine: the checker gives sympy a time bound, so
    a proof that finishes on a quiet machine may time out on a loaded one and the entry is then
    settled numerically (same verdict, another method, more points).  Ball integrals are
    bounded by counted evaluations, not time, so whether a witness is certified, and its
    digits, are compared exactly — as is everything else: the verdicts themselves, the
    printed and derived forms, the witnesses' points and values.
    """
    out, i, key = [], 0, "\\verdicthow{"
    while True:
        j = tex.find(key, i)
        if j < 0:
            out.append(tex[i:])
            return "".join(out)
        out.append(tex[i:j] + key + "}")
        depth, k = 1, j + len(key)
        while k < len(tex) and depth:
            if tex[k] == "\\":
                k += 2
                continue
            depth += {"{": 1, "}": -1}.get(tex[k], 0)
            k += 1
        i = k


def test_mask_how():
    assert mask_how(r"a \verdicthow{x {y} \} z}. b \verdicthow{}.") == r"a \verdicthow{}. b \verdicthow{}."


def test_golden_reports(generated):
    """The committed reports/ are what the code generates now (versions.tex aside: it states
    the machine's software; \verdicthow{...} aside: see mask_how).  On failure: review the
    diff, then regenerate."""
    _, docs, _ = generated
    names = sorted(n for n in docs if n != report.VERSIONS_FILE)
    committed = sorted(p.name for p in GOLDEN.glob("*.tex") if p.name != report.VERSIONS_FILE) if GOLDEN.is_dir() else []
    problems, diffs = [], []
    for name in names:
        path = GOLDEN / name
        if not path.is_file():
            problems.append(f"missing: reports/{name}")
            continue
        old, new = mask_how(path.read_text(encoding="utf-8")), mask_how(docs[name])
        if old != new:
            problems.append(f"differs: reports/{name}")
            diffs += list(difflib.unified_diff(old.splitlines(), new.splitlines(), f"reports/{name}",
                                               "generated", n=1, lineterm=""))[:40]
    problems += [f"stale (no longer generated): reports/{n}" for n in committed if n not in names]
    for fig in report.figures_needed(docs, TEXTS):
        if not (GOLDEN / fig.path).is_file():
            problems.append(f"missing figure: reports/{fig.path}")
    if not (GOLDEN / report.VERSIONS_FILE).is_file():
        problems.append(f"missing: reports/{report.VERSIONS_FILE}")
    assert not problems, (
        "the golden reports disagree with the code:\n  " + "\n  ".join(problems)
        + "\n" + "\n".join(diffs[:120])
        + f"\n\nReview the differences, then regenerate the golden files with:\n    {REGENERATE}\n")


def test_versions_file_names_the_software():
    tex = blocks.versions_tex()
    for name in ("Python", "sympy", "mpmath", "numpy", "scipy", "python-flint", "matplotlib"):
        assert name in tex
    golden = GOLDEN / report.VERSIONS_FILE
    if golden.is_file():
        assert all(n in golden.read_text(encoding="utf-8") for n, _ in blocks.PACKAGES)


def test_generation_is_byte_identical(generated):
    """A second generation, in a fresh process with another hash seed (set orders differ),
    through the CLI, gives the same bytes."""
    out, docs, (proc, tmp_path) = generated
    _, stderr = proc.communicate()
    assert proc.returncode == 0, stderr
    for name, tex in docs.items():
        assert (tmp_path / name).read_text(encoding="utf-8") == tex, name
    assert sorted(p.name for p in tmp_path.glob("*.tex")) == sorted(docs)
    for text_ in docs.values():
        assert str(REPO) not in text_ and str(tmp_path) not in text_  # no absolute paths
    for fig in report.figures_needed(docs, TEXTS):  # figures are deterministic too
        assert (tmp_path / fig.path).read_bytes() == (out / fig.path).read_bytes(), fig.path


def test_every_figure_is_included(generated):
    from quasicentral.studies import figures

    _, docs, _ = generated
    names = {f.name for f in report.figures_needed(docs, TEXTS)}
    assert names == {f.name for t in TEXTS for f in figures.of_text(t)}


# --- compiling: every document once per test run, then the done-when checks on the PDFs ---------
pytestmark_latex = pytest.mark.skipif(
    shutil.which("latexmk") is None or shutil.which("pdftotext") is None or shutil.which("pdftoppm") is None,
    reason="needs latexmk, pdftotext and pdftoppm (./setup.sh installs them)")


@pytest.fixture(scope="module")
def compiled(generated, tmp_path_factory):
    """Every report and handout compiled once (latexmk, in parallel); name -> (pdf, log text,
    pdftotext of the PDF, pdftotext of page 1)."""
    if shutil.which("latexmk") is None or shutil.which("pdftotext") is None:
        pytest.skip("needs latexmk and pdftotext (./setup.sh installs them)")
    src, docs, _ = generated
    out = tmp_path_factory.mktemp("pdf")
    shutil.copytree(src, out, dirs_exist_ok=True)
    names = [n for n in docs if n != report.VERSIONS_FILE]
    t0 = time.perf_counter()
    pdfs = report.compile_all(out, names)
    print(f"\ncompiled {len(pdfs)} documents in {time.perf_counter() - t0:.1f} s")
    result = {}
    for name, pdf in zip(names, pdfs):
        log = pdf.with_suffix(".log").read_text(encoding="utf-8", errors="replace")
        full = subprocess.run(["pdftotext", "-enc", "UTF-8", str(pdf), "-"], capture_output=True, text=True,
                              check=True).stdout
        first = subprocess.run(["pdftotext", "-enc", "UTF-8", "-f", "1", "-l", "1", str(pdf), "-"],
                               capture_output=True, text=True, check=True).stdout
        result[name] = (pdf, log, full, first)
    return result


def _flat(s: str) -> str:
    """Text of a PDF with hyphenation at line ends undone and all white space single spaces."""
    return " ".join(re.sub(r"-\n(?=[a-zá-ž])", "", s).split())


@pytestmark_latex
@pytest.mark.slow  # compiles every document (latexmk): about a minute on 2 cores; CI runs it
def test_every_document_compiles(compiled, tmp_path):
    """latexmk builds every report and handout without a LaTeX error or undefined reference,
    and the first page of each PDF has ink on it."""
    import matplotlib.image as mpimg

    for name, (pdf, _, _, _) in compiled.items():
        assert pdf.is_file() and pdf.stat().st_size > 10_000, pdf
        subprocess.run(["pdftoppm", "-png", "-r", "40", "-f", "1", "-l", "1", str(pdf), str(tmp_path / pdf.stem)],
                       check=True)
        (png,) = tmp_path.glob(pdf.stem + "-*.png")
        img = mpimg.imread(png)
        ink = (img[..., :3].min(axis=-1) < 0.8).mean()
        assert ink > 0.005, f"{pdf.name}: first page looks blank ({ink:.4f} of the pixels inked)"


@pytestmark_latex
@pytest.mark.slow  # compiles every document (latexmk): about a minute on 2 cores; CI runs it
def test_logs_have_no_overfull_box_and_no_warning(compiled):
    bad = {}
    for name, (_, log, _, _) in compiled.items():
        found = [line for line in log.splitlines() if "Overfull" in line or "Warning" in line]
        if found:
            bad[name] = found[:5]
    assert not bad, bad


#: What must never reach a reader: code, raw LaTeX, code points.
RAW_MARKERS = ("**", "Symbol(", ".subs(", "\\left", "\\right", "\\frac", "[U+", "Eq(", "Derivative(",
               "tests/", ".py", "sympy.", "'\\", "mode=")
_IDENTIFIER = re.compile(r"\b[A-Za-z][A-Za-z0-9]*_[A-Za-z0-9_]+\b")


@pytestmark_latex
@pytest.mark.slow  # compiles every document (latexmk): about a minute on 2 cores; CI runs it
def test_pdfs_hold_no_raw_code(compiled):
    bad = {}
    for name, (_, _, full, _) in compiled.items():
        found = [m for m in RAW_MARKERS if m in full] + _IDENTIFIER.findall(full)
        if found:
            bad[name] = sorted(set(found))[:10]
    assert not bad, bad


def english_phrases() -> list[str]:
    """Every English sentence or label the documents can emit (report.WORDS, the verdict details
    of the checker, the prose of the derivations and the errata), as plain text to look for."""
    from quasicentral.documents.prose import WORDS

    def strings(v):
        if isinstance(v, str):
            yield v
        elif isinstance(v, dict):
            for x in v.values():
                yield from strings(x)
        elif isinstance(v, (list, tuple)):
            for x in v:
                yield from strings(x)

    cs = set(strings(WORDS["cs"]))
    out = set()
    for s in strings(WORDS["en"]):
        if s in cs or s.startswith("^"):
            continue
        words = re.sub(r"\{[^{}]*\}", " ", blocks.plain(s)).split()
        words = [w for w in words if re.fullmatch(r"[A-Za-z'’,.:;()-]+", w)]
        if len(words) >= 3:
            out.add(" ".join(words[:3]))
        elif len(words) == 1 and len(words[0].strip(".,:")) >= 5:
            out.add(words[0].strip(".,:"))
    out |= {"sympy proves", "points disagree", "agrees at", "consistent", "anglicky", "Dimensions",
            "As printed", "Re-derived", "Verdict", "Step", "Witness", "Exercise", "Solution", "the", "with",
            "which", "from", "printed"}
    for d in WS.derivations.by_id.values():
        for m in re.finditer(r"\b(?:the|from|with|which|where|gives|since) [a-z]+ [a-z]+\b", d.doc):
            out.add(m.group(0))
    return sorted(out)


@pytestmark_latex
@pytest.mark.slow  # compiles every document (latexmk): about a minute on 2 cores; CI runs it
def test_czech_documents_hold_no_english(compiled):
    phrases = english_phrases()
    assert len(phrases) > 50
    bad = {}
    for name, (_, _, full, _) in compiled.items():
        if not name.endswith("-cs.tex"):
            continue
        flat = _flat(full)
        found = [p for p in phrases if re.search(r"(?<![A-Za-zá-žÁ-Ž])" + re.escape(p) + r"(?![A-Za-zá-ž])", flat)]
        if found:
            bad[name] = found[:15]
    assert not bad, bad


@pytestmark_latex
@pytest.mark.slow  # compiles every document (latexmk): about a minute on 2 cores; CI runs it
def test_page_one_of_a_report_has_the_summary_and_the_errata_table(compiled):
    from quasicentral.documents.prose import WORDS

    for name, (_, _, _, first) in compiled.items():
        if "-report-" not in name:
            continue
        W = WORDS[name[-6:-4]]
        flat = _flat(first)
        for key in ("summary", "count_checked", "count_errata", "found_title"):
            assert blocks.plain(W[key]) in flat, (name, key)
        assert blocks.plain(W["col_cause"]) in flat and blocks.plain(W["col_kind"]) in flat, name


def _counts(tex: str) -> tuple[int, ...]:
    return tuple(tex.count(k) for k in ("\\section{", "\\subsection{", "\\subsection*{", "\\includegraphics",
                                        "\\begin{equation}", "\\begin{center}", "\\item", "\\begin{landscape}"))


def test_english_and_czech_documents_have_the_same_parts(generated):
    _, docs, _ = generated
    for name, tex in docs.items():
        if name.endswith("-en.tex"):
            assert _counts(tex) == _counts(docs[name[:-7] + "-cs.tex"]), name


def test_handouts_for_students_and_teachers(generated):
    from quasicentral.documents.prose import WORDS

    _, docs, _ = generated
    for name, tex in docs.items():
        if name == report.VERSIONS_FILE:
            continue
        kind, lang = name.rsplit("-", 2)[1], name[-6:-4]
        if kind not in ("handout", "teacher"):
            continue
        solutions = f"\\section{{{WORDS[lang]['solutions']}}}"
        assert (solutions in tex) == (kind == "teacher"), name
        assert "-report-" + lang + ".pdf" in tex and "-report-" + lang + ".tex" not in tex, name


def test_pdf_metadata_is_set(generated):
    _, docs, _ = generated
    for name, tex in docs.items():
        if name == report.VERSIONS_FILE:
            continue
        lang = name[-6:-4]
        assert f"pdflang={{{blocks.PDFLANG[lang]}}}" in tex, name
        assert re.search(r"pdftitle=\{[^}]{20,}", tex) and "pdfauthor={quasicentral" in tex, name


# --- a text's own prose --------------------------------------------------------------------------
def test_a_text_without_report_toml_gets_generic_words(tmp_path):
    from quasicentral.documents.prose import WORDS, load_prose

    p = load_prose(tmp_path / "mytext", title="My text")
    assert p.id == "mytext" and p.title == {"en": "My text", "cs": "My text"}
    assert not p.figures and not p.sections and p.intro["cs"] and "lost" not in p.figures_intro["en"]
    assert p.section_title("1", "en") is None and WORDS["en"]["report"]


def test_report_toml_is_read(tmp_path):
    from quasicentral.documents.prose import load_prose, prose_of

    (tmp_path / "report.toml").write_text(
        "[title]\nen = 'A'\ncs = 'B'\n[sections.\"1\".title]\nen = 'One'\ncs = 'Jedna'\n"
        "[figures.f1]\nrole = 'study'\nlandscape = true\ncaption = {en = 'x', cs = 'y'}\n"
        "[entries.\"t:1\"]\nstep = {cs = 'Krok.'}\n[notation.functions]\nmyfun = '\\Phi'\n", encoding="utf-8")
    p = load_prose(tmp_path, "t")
    assert p.title["cs"] == "B" and p.section_title("1", "cs") == "Jedna"
    assert p.figure("f1").landscape and p.figure("f1").role == "study" and p.figure("f1").caption["cs"] == "y"
    assert p.entry("t:1").step["cs"] == "Krok." and p.entry("t:2").step == {}
    assert p.functions == {"myfun": "\\Phi"}

    class Text:  # the lead's Text objects carry .root and .id
        root, id, title = tmp_path, "t", "A"

    assert prose_of(Text()).title["en"] == "A"


def test_no_module_of_documents_names_a_shipped_text():
    names = {t.id for t in TEXTS}
    for path in (REPO / "quasicentral" / "documents").glob("*.py"):
        src = path.read_text(encoding="utf-8")
        assert not [n for n in names if n in src], path.name


@pytest.mark.parametrize("raw, clean", [
    ("R0 = v0 at Omega t = 2 pi (tests/test_a.py)", "R₀ = v₀ at Ω t = 2 π"),
    ("see test_sign_of_the_F_terms_is_right", "see a test"),
    ("elliptic_k(m) (legendre_antiderivative)", "K(m)"),
    ("the suspicion 'exponents 3/4' and \"α = 0\", Newton's C'", "the suspicion ‘exponents 3/4’ and “α = 0”, Newton's C′"),
])
def test_clean_prose(raw, clean):
    from quasicentral.documents.prosetex import clean_prose

    assert clean_prose(raw) == clean


def test_dimension_findings_are_sentences():
    from quasicentral.engine.dimensions import CONSISTENT, DimensionCheck, DimensionStatus
    from quasicentral.engine.reasons import Code, Reason

    finding = DimensionCheck(DimensionStatus.INCONSISTENT, Reason.of(Code.DIM_ADDS, first="L/T", other="L",
                                                                    sum="-kappa*y(t) + x(t)", term="x(t)"))
    with using(Notation.of(S)):
        for lang in ("en", "cs"):
            s = blocks.dimension_sentence((finding,), lang)
            assert "inconsistent" not in s and "*" not in s and "adds" not in s and s.endswith(".")
            assert "mathsf{L}" in s
    assert blocks.dimension_sentence((CONSISTENT,), "cs") == ""


def test_printer_names_are_one_overridable_mapping():
    from quasicentral.documents.latex import PaperLatexPrinter, names_as_printed

    assert PaperLatexPrinter(names={"rho": r"\rho"}).doprint(sp.Symbol("rho")) == r"\rho"
    with using(Notation.of(S)):
        assert PaperLatexPrinter(function_names={"rho": r"\rho"}).doprint(S.rho) == r"\rho"
        assert paper_latex(S.rho) == r"\varrho"
        assert names_as_printed(r"\rho \frac{d\psi}{dt}", Notation.of(S).functions)["rho"] == r"\rho"


def test_latex_error_names_the_log(tmp_path):
    (tmp_path / "broken.tex").write_text("\\documentclass{article}\\begin{document}\\undefinedmacro\\end{document}\n")
    if shutil.which("latexmk") is None:
        pytest.skip("latexmk not installed")
    with pytest.raises(report.LatexError) as info:
        report.compile_one(tmp_path, "broken.tex")
    assert str(tmp_path / "broken.log") in str(info.value)


def test_log_problems_finds_undefined_references():
    log = ("LaTeX Warning: Reference `e:x' on page 2 undefined on input line 7.\n"
           "./a.tex:12: Undefined control sequence.\n"
           "LaTeX Warning: There were undefined references.\n")
    assert len(report.log_problems(log)) == 3
    assert report.log_problems("Package hyperref Warning: Token not allowed in a PDF string\n") == []


# --- the command ------------------------------------------------------------------------------
def _run(*args, cwd=None):
    proc = subprocess.run([sys.executable, "-m", "quasicentral.cli", *args], capture_output=True, text=True, cwd=cwd)
    return proc.returncode, proc.stdout, proc.stderr


@pytest.mark.parametrize("args", [["report", "--lang", "de"], ["report", "--all", "--handout"],
                                  ["report", "--bogus"]])
def test_report_bad_usage(args, tmp_path):
    code, out, err = _run(*args, "--out", str(tmp_path / "r"))
    assert code == 2 and err.count("\n") == 1 and err.startswith("quasicentral: error:"), err
    assert not (tmp_path / "r").exists()


def test_report_unwritable_out(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("keep me")
    code, out, err = _run("report", "--out", str(blocker / "sub"))
    assert code == 2 and err.count("\n") == 1 and "cannot write" in err, err
    assert blocker.read_text() == "keep me"


def test_failed_write_leaves_old_files_whole(tmp_path, monkeypatch):
    (tmp_path / "a.tex").write_text("old a")
    docs = {"a.tex": "new a", "b.tex": "new b"}
    calls = []

    real = files.write_atomic

    def fail_second(path, fill):
        calls.append(path)
        if len(calls) == 2:
            def failing(tmp):
                fill(tmp)
                raise OSError(28, "No space left on device")
            return real(path, failing)
        return real(path, fill)

    monkeypatch.setattr(report, "write_atomic", fail_second)
    with pytest.raises(OSError):
        report.write(tmp_path, docs)
    assert (tmp_path / "a.tex").read_text() in ("old a", "new a")
    assert not (tmp_path / "b.tex").exists()
    assert not [p for p in tmp_path.iterdir() if p.name.endswith(".tmp")]


def test_pdf_failure_is_exit_1_with_log(tmp_path, monkeypatch, capsys):
    if shutil.which("latexmk") is None:
        pytest.skip("latexmk not installed")
    monkeypatch.setattr(report, "records_for", lambda *a, **k: [])
    monkeypatch.setattr(report, "generate", lambda records, kinds, langs: {
        "broken-report-en.tex": "\\documentclass{article}\\begin{document}\\ref{nowhere}\\end{document}\n"})
    code = main(["report", "--pdf", "--out", str(tmp_path)])
    err = capsys.readouterr().err
    assert code == 1 and err.count("\n") == 1 and "broken-report-en.log" in err, err


def test_errata_with_one_cause_are_explained_once():
    """Errata sharing a root cause (``[[cause]]`` in the errata data, ``Erratum.causes``) are
    grouped under it: its title and note once, then the displays it affects; an erratum without
    recorded causes is a group of its own."""
    from types import MappingProxyType as M

    from quasicentral.documents.prose import generic_prose
    from quasicentral.engine import errata
    from quasicentral.engine.verdict import EntryRecords, Method, Outcome, Refuted, Status

    entries = [e for t in TEXTS for e in t.entries.values()][:3]
    cause = errata.Cause("zeta-branch", "t", errata.Kind.RANGE, 0,
                         M({"": "The branch of the root", "cs": "Větev odmocniny"}),
                         M({"": "Holds on the first half-period only.", "cs": "Platí jen na první půlperiodě."}))

    def step(e, causes):
        err = errata.Erratum(e.id, errata.Kind.RANGE, "x", "x = 1", M({"": "n"}), tuple(c.id for c in causes))
        outcome = Outcome(e.id, Refuted(Method.NUMERIC), Status.ERRATUM, True, records=EntryRecords(err, None, causes))
        return steps_mod.Step(e, outcome, None, None, None)

    steps = [step(entries[0], (cause,)), step(entries[1], (cause,)), step(entries[2], ())]
    groups = steps_mod.cause_groups(steps)
    assert [len(g.steps) for g in groups] == [2, 1] and groups[0].recorded and not groups[1].recorded
    by_id = {s.entry.id: s for s in steps}
    for lang, title, note in (("en", "The branch of the root", "first half-period"), ("cs", "Větev odmocniny", "půlperiodě")):
        tex = derivation_report._causes_section(groups, by_id, generic_prose("t"), lang)
        assert tex.count(title) == 1 and tex.count(note) == 1
        assert f"\\ref{{e:{steps[0].label}}}" in tex and f"\\ref{{e:{steps[1].label}}}" in tex



# --- documents judged by reading: what a reader can check mechanically ------------------------
@pytest.fixture(scope="module")
def records():
    return report.records_for(WS, TEXTS, Options())


def _found_rows(tex: str) -> list[str]:
    """The cause labels of page 1's table, in order."""
    from quasicentral.documents.prose import WORDS

    lang = "cs" if "\\usepackage[czech]{babel}" in tex else "en"
    start = tex.index("\\subsection*{" + WORDS[lang]["found_title"] + "}")
    end = tex.index("\\end{longtable}", start)
    return re.findall(r"\(\\S\\,\\ref\{(c:[^{}]+)\}\)", tex[start:end])


def test_page_one_has_one_row_per_cause_as_errata_json(generated, records):
    """The causes on page 1 are those of ``errata --json`` (one row each), in both languages."""
    from quasicentral.engine.formats import errata_document

    _, docs, _ = generated
    for rec in records:
        doc = errata_document([s.entry for s in rec.steps], [s.outcome for s in rec.steps])
        expected = [steps_mod.label_of(c["id"]) for c in doc["causes"]]
        expected += [steps_mod.label_of(e["id"]) for e in doc["errata"] if not e["cause"]]
        for lang in ("en", "cs"):
            rows = _found_rows(docs[f"{rec.id}-report-{lang}.tex"])
            assert sorted(r[2:] for r in rows) == sorted(expected), (rec.id, lang)


def test_no_caret_no_internal_id_in_any_document(generated, records):
    """A reader meets neither TeX's escaped caret nor the toolkit's ids of unnumbered displays."""
    _, docs, _ = generated
    for name, tex in docs.items():
        assert "\\textasciicircum" not in tex, name
        assert "\\textasciitilde" not in tex, name
    for rec in records:
        tags = steps_mod.citing(rec.steps)
        pattern = re.compile(r"(?<![\w.:{/-])(" + "|".join(map(re.escape, tags)) + r")(?![\w-])")
        for name, tex in docs.items():
            if name.startswith(rec.id):
                body = re.sub(r"\\(?:label|ref|hyperref|entrylabel)\{[^{}]*\}", "", tex)
                assert not pattern.findall(body), (name, sorted(set(pattern.findall(body)))[:5])


def _sections(tex: str) -> list[tuple[str, str]]:
    """(title, body) of each section of a document, the body's visible text roughly."""
    body = tex[tex.index("\\begin{document}"):]
    out = []
    for part in re.split(r"\\section\*?\{", body)[1:]:
        title = part[:part.find("}")]
        if "\\input{" in part:  # the software's versions, written apart (versions.tex)
            continue
        words = re.sub(r"\\[A-Za-z]+\*?(\[[^\]]*\])?", " ", part[part.find("}") + 1:])
        out.append((title, " ".join(re.sub(r"[{}$\\&%~^_]", " ", words).split())))
    return out


def test_every_section_has_content_and_czech_says_what_english_says(generated):
    """No section is a heading alone, and each Czech section is within a third of the length
    of its English one (the same content, not a summary of it)."""
    _, docs, _ = generated
    for name, tex in docs.items():
        if not name.endswith("-en.tex"):
            continue
        en, cs = _sections(tex), _sections(docs[name[:-7] + "-cs.tex"])
        assert len(en) == len(cs), name
        for (title, a), (_, b) in zip(en, cs):
            assert len(a) > 20 and len(b) > 20, (name, title)
            assert 2 / 3 <= len(b) / len(a) <= 3 / 2, (name, title, len(a), len(b))


def test_students_handout_gives_no_answer(generated, records):
    """The students' edition holds no corrected form of a misprint it sets and no computed
    answer; the teacher's holds both."""
    from quasicentral.documents.handout import exercises_for
    from quasicentral.engine.exercises import ExerciseKind

    _, docs, _ = generated
    for rec in records:
        exercises = exercises_for(rec)
        assert rec.exercises, f"{rec.id} has an exercise bank"
        for lang in ("en", "cs"):
            students, teacher = docs[f"{rec.id}-handout-{lang}.tex"], docs[f"{rec.id}-teacher-{lang}.tex"]
            for ex in exercises:
                if ex.kind is ExerciseKind.MISPRINT:
                    corrected = blocks.printed_display(ex.step.erratum.corrected_latex)
                    assert corrected not in students and corrected in teacher, (rec.id, ex.spec.id)
                if ex.kind is ExerciseKind.COMPUTE:
                    shown = blocks.number(ex.answer, lang, ex.spec.digits)
                    assert shown not in students and shown in teacher, (rec.id, ex.spec.id, shown)


def test_exercise_answers_are_the_physics(records):
    """The banks' answers, recomputed here from the physics by hand (mpmath): the period at 30°
    and 90°, the amplitude at which T0 errs by 1 %, the halving time and length of the angular
    momentum, the damped frequency of figs. 7 and 8, the critical damping."""
    expected = {
        "period-30": 4 * mpmath.sqrt(1 / mpmath.mpf("9.81")) * mpmath.ellipk(mpmath.sin(mpmath.pi / 12) ** 2),
        "period-90": 4 * mpmath.sqrt(1 / mpmath.mpf("9.81")) * mpmath.ellipk(mpmath.mpf(1) / 2),
        "one-percent": mpmath.findroot(lambda p: 2 / mpmath.pi * mpmath.ellipk(mpmath.sin(p / 2) ** 2) - 1.01, 0.4),
        "half-time-linear": mpmath.log(2) / (2 * mpmath.mpf("0.4")),
        "half-length-quadratic": mpmath.log(2) / mpmath.mpf("0.5"),
        "damped-frequency": mpmath.sqrt(mpmath.mpf("9.84")),
        "critical-damping": mpmath.sqrt(mpmath.mpf("9.81")),
    }
    got = {}
    for rec in records:
        for ex in rec.exercises:
            if ex.answer:
                got[ex.spec.id] = ex
    assert set(got) == set(expected)
    for eid, value in expected.items():
        assert got[eid].answer == mpmath.nstr(value, got[eid].spec.digits, min_fixed=-4, max_fixed=6), eid


def test_a_bank_that_does_not_hold_is_refused(tmp_path, records):
    """A derive exercise whose premises the result does not rest on, a misprint that is no
    erratum, a compute exercise on an entry without its unknown: each one error naming the
    file and the exercise."""
    from quasicentral.engine.catalog import CatalogError
    from quasicentral.engine.exercises import read_bank, settle

    rec = next(r for r in records if r.id == "pendulum")
    entries = dict(rec.text.entries)
    statuses = {s.entry.id: s.outcome.status for s in rec.steps}
    uses = {s.entry.id: s.uses for s in rec.steps}
    bad = {
        "derive": 'kind = "derive"\nentry = "pendulum:60"\npremises = ["pendulum:53"]',
        "misprint": 'kind = "misprint"\nentry = "pendulum:60"',
        "compute": 'kind = "compute"\nentry = "pendulum:60"\nunknown = "m"\nvalues = { l = "1", g = "9" }',
        "no-entry": 'kind = "misprint"\nentry = "pendulum:nothing"',
        "ref": 'kind = "misprint"\nentry = "pendulum:equation-of-motion"\nquestion.cs = "{ref:pendulum:zz}"',
    }
    for what, body in bad.items():
        (tmp_path / "report.toml").write_text(f'[[exercise]]\nid = "x"\nquestion.en = "?"\n{body}\n')
        with pytest.raises(CatalogError, match=r"report.toml, exercise 'x'"):
            settle(read_bank(tmp_path, "mytext"), entries, statuses, uses, {})


def test_figures_speak_the_documents_language(generated):
    """A text's own figures are drawn per language (its axes and legend in Czech, a decimal
    comma) and each document includes its own; the measured charts are the software note's."""
    from quasicentral.studies import figures

    _, docs, _ = generated
    for t in TEXTS:
        own = [f for f in figures.of_text(t) if isinstance(f, figures.Figure)]
        assert own, t.id
        for f in own:
            for kind in ("report", "handout", "teacher"):
                assert f"{{figures/{f.name}-cs.png}}" in docs[f"{t.id}-{kind}-cs.tex"], (t.id, f.name, kind)
                assert f"{{figures/{f.name}.png}}" in docs[f"{t.id}-{kind}-en.tex"], (t.id, f.name, kind)
            if f.kind is figures.Kind.CURVES:
                assert f.said("labels", "cs") != f.labels and f.said("xlabel", "cs") != f.xlabel, f.name


def test_a_witness_in_a_document_has_its_units_names_and_powers_of_ten():
    """A newcomer's Czech heat-conduction text: the witness read "lam = 109, a = 9,189e−5" in
    the checker's names, without units, beside a verdict line in the text's.  Both now write the
    point as the text does — λ, T₀ = 254,5 K, a = 9,189·10⁻⁵ m² s⁻¹ — and a limit without bound
    as ∞."""
    from quasicentral.engine.notes import render_note
    from quasicentral.engine.reasons import Code, Reason
    from quasicentral.engine.verdict import Witness

    w = Witness({"T0": "509/2", "a": "0.00009189", "lam": "109"}, "10650.2", "18880.1", 4, True, Reason(Code.Q_SIDES))
    units = {"T0": r"\mathrm{K}", "a": r"\mathrm{m}^{2}\,\mathrm{s}^{-1}"}
    with using(Notation({"T0": "T_0", "a": "a", "lam": r"\lambda"}, units=units)):
        short = blocks.witness_short(w, "cs")
        note = with_math(clean_prose(steps_mod.reader_note("Svědek: {witness}.", w, "cs")), lang="cs")
    assert r"$T_0 = 254{,}5\,\mathrm{K}$" in short and r"$\lambda = 109$" in short, short
    assert r"$T_0$ = 254,5 $\mathrm{K}$" in note and r"$\lambda$ = 109" in note, note
    assert r"\ensuremath{9{,}189\cdot 10^{-5}} $\mathrm{m}^{2}\,\mathrm{s}^{-1}$" in note, note
    assert "lam =" not in note and "e-5" not in note and "e−5" not in note, note
    assert render_note("{witness}", w, "cs").count("e-5") == 1  # the JSON's notes keep every digit as computed
    assert blocks.number("inf", "en") == r"\infty" and blocks.number("-inf", "cs") == r"-\infty"
