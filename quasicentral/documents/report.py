"""Reports and handouts: LaTeX regenerated from the verified derivations, compiled to PDF.

Two views over the same registry (STYLE.md, point 9):

* the **report** of a text lists every catalog entry in the order of the paper — as printed
  (the catalog's verbatim LaTeX), as re-derived (the derivation's sympy result through
  :class:`quasicentral.latex.PaperLatexPrinter`), the verdict and how it was reached, and the
  step that produces it (its docstring and the ids it ``uses``) — then the errata table, the
  cleared suspects, the reproduced figures and the software versions;
* the **handout** tells the derivation to a student: the steps in order with their equations
  (corrected where the print is wrong), few verification details, exercises taken from the
  steps with their solutions at the end, and the figures.  English or Czech.

Everything here is deterministic: entries in catalog order, models sorted by their printed
key, no timestamps, no absolute paths.  The software versions, which differ from machine to
machine, go to ``versions.tex`` that the reports ``\\input``.  Nothing here prints; the CLI
does.

>>> sorted(file_names(("report",), ("en",)))
['brepta1953-report-en.tex', 'pendulum-report-en.tex']
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import sympy as sp

from quasicentral.engine import catalog

from quasicentral.engine import errata as errata_mod

from quasicentral.studies import figures as figures_mod

from quasicentral.engine import formats as output
from quasicentral.files import write_atomic
from quasicentral.documents.latex import display_rows, escape, paper_latex, relation_lines, text, with_math, wrap_row
from quasicentral.documents.prose import FIGURE_CAPTIONS, KINDS_CS, LANGS, SECTIONS, TEXTS, WORDS, join_refs
from quasicentral.engine.registry import REGISTRY, Derivation, as_list, derived, load_all
from quasicentral.engine.verdict import Outcome, Verdict

KINDS = ("report", "handout")
FIGURE_DIR = "figures"
VERSIONS_FILE = "versions.tex"
#: The packages whose versions a report states (distribution name, import name).
PACKAGES = (("sympy", "sympy"), ("mpmath", "mpmath"), ("numpy", "numpy"), ("scipy", "scipy"),
            ("python-flint", "flint"), ("matplotlib", "matplotlib"))
#: The golden documents (kinds × languages) that ``quasicentral report --all`` writes.
GOLDEN = ((("report",), LANGS), (("handout",), LANGS))
#: The command that regenerates every golden file under reports/.
REGENERATE = "quasicentral report --all --out reports"

#: Which text a figure belongs to when the figure does not say (``Figure.source``).
FIGURE_SOURCES = {"fig7a": "brepta1953", "fig7b": "brepta1953", "fig8": "brepta1953",
                  "overdamped": "brepta1953", "fig32": "pendulum"}


class LatexError(RuntimeError):
    """A document did not compile (or has undefined references); ``log`` names the log file."""

    def __init__(self, message: str, log: Path):
        super().__init__(message)
        self.log = log


# --- the data a document is made of ----------------------------------------------------------
@dataclass(frozen=True)
class Step:
    """One catalog entry with everything known about it."""

    entry: catalog.Entry
    outcome: Outcome
    derivation: Derivation | None
    result: object  # the derivation's result (None when there is none)
    error: str  # why there is no result ("" when there is one)
    erratum: errata_mod.Erratum | None
    cleared: errata_mod.Cleared | None

    @property
    def label(self) -> str:
        return label_of(self.entry.id)


def label_of(eid: str) -> str:
    """A LaTeX label for an entry id: letters and digits only, other characters as '.'."""
    return re.sub(r"[^A-Za-z0-9]", ".", eid)


def steps_of(source: str, outcomes: dict[str, Outcome]) -> list[Step]:
    """The steps of one text in catalog order, each with its (memoized) derivation result."""
    load_all()
    errs, cleared = errata_mod.load()
    out = []
    for e in catalog.entries(source):
        d = REGISTRY.get(e.id)
        result, error = None, ""
        if d is None:
            error = "none"
        else:
            try:
                result = derived(e.id)
            except Exception as exc:  # noqa: BLE001 - a failing derivation is reported, not raised
                error = f"{type(exc).__name__}: {exc}"
        out.append(Step(e, outcomes[e.id], d, result, error, errs.get(e.id), cleared.get(e.id)))
    labels = [s.label for s in out]
    if len(set(labels)) != len(labels):
        raise ValueError(f"{source}: two entry ids map to the same LaTeX label")
    return out


def sections_of(steps: list[Step]) -> list[tuple[str, list[Step]]]:
    """Steps grouped by section, in the order the sections first appear."""
    groups: dict[str, list[Step]] = {}
    for s in steps:
        groups.setdefault(s.entry.section, []).append(s)
    return list(groups.items())


@lru_cache(maxsize=None)
def section_titles() -> dict[tuple[str, str], str]:
    """The printed (Czech) title of every catalog section, read from the catalog files."""
    import tomllib

    out = {}
    root = catalog._catalog_root()
    for source in catalog.SOURCES:
        for path in sorted((root / source).glob("*.toml")):
            data = tomllib.loads(path.read_text(encoding="utf-8"))
            out[(data["source"], str(data["section"]))] = data.get("title", "")
    return out


def section_title(source: str, section: str, lang: str) -> str:
    known = SECTIONS.get((source, section))
    if known:
        return known[lang][0]
    printed = section_titles().get((source, section), "")
    return with_math(printed, letters=False) if printed else escape(section)


# --- figures ---------------------------------------------------------------------------------
@dataclass(frozen=True)
class FigureItem:
    name: str
    title: str
    sources: tuple[str, ...]
    make: object  # the function of quasicentral.figures.ALL that builds it

    @property
    def path(self) -> str:
        return f"{FIGURE_DIR}/{self.name}.png"


@lru_cache(maxsize=None)
def figure_items() -> tuple[FigureItem, ...]:
    """Every figure that :data:`quasicentral.figures.ALL` offers, with the text(s) it belongs to."""
    items = []
    for make in figures_mod.ALL:
        fig = make()
        src = getattr(fig, "source", None) or FIGURE_SOURCES.get(fig.name)
        if src is None and getattr(fig, "kind", "") == "period":
            src = "pendulum"
        sources = (src,) if src in catalog.SOURCES else tuple(catalog.SOURCES)
        items.append(FigureItem(fig.name, fig.title, sources, make))
    return tuple(items)


def figures_for(source: str) -> list[FigureItem]:
    return [f for f in figure_items() if source in f.sources]


def caption(fig: FigureItem, lang: str) -> str:
    return FIGURE_CAPTIONS[lang].get(fig.name) or text(fig.title)


# --- versions --------------------------------------------------------------------------------
def versions() -> list[tuple[str, str]]:
    """(name, version) of Python and of each package in :data:`PACKAGES`."""
    from importlib import metadata

    out = [("Python", sys.version.split()[0])]
    for dist, module in PACKAGES:
        try:
            ver = metadata.version(dist)
        except metadata.PackageNotFoundError:
            ver = getattr(sys.modules.get(module) or __import__(module), "__version__", "unknown")
        out.append((dist, ver))
    return out


def versions_tex() -> str:
    rows = "\n".join(rf"{escape(n)} & {escape(v)} \\" for n, v in versions())
    return ("% The software that produced the reports (machine-dependent, hence a file of its own).\n"
            "\\begin{tabular}{ll}\n\\toprule\n" + rows + "\n\\bottomrule\n\\end{tabular}\n")


# --- LaTeX building blocks -------------------------------------------------------------------
PREAMBLE = r"""\documentclass[11pt,a4paper]{article}
\usepackage[T1]{fontenc}
\usepackage[utf8]{inputenc}
\usepackage{lmodern}
\usepackage[%(babel)s]{babel}
\usepackage[a4paper,margin=2.2cm]{geometry}
\usepackage{amsmath,amssymb}
\usepackage{graphicx}
\usepackage{array,booktabs,longtable}
\usepackage[hidelinks]{hyperref}
%% the paper's notation
\DeclareMathOperator{\arccotg}{arccotg}
%% a box that shrinks to the given width only when it is wider
\newsavebox{\qcbox}
\newcommand{\fit}[2][\linewidth]{\sbox{\qcbox}{#2}%%
  \ifdim\wd\qcbox>#1\resizebox{#1}{!}{\usebox{\qcbox}}\else\usebox{\qcbox}\fi}
%% how a verdict was reached and whether balls certify it (both time-bounded, hence
%% machine-dependent: the golden test does not compare them)
\newcommand{\verdicthow}[1]{#1}
%% a label whose \ref prints #2 (an equation's number or name)
\makeatletter
\newcommand{\entrylabel}[2]{\phantomsection\def\@currentlabel{#2}\label{#1}}
\makeatother
\allowdisplaybreaks
\emergencystretch=3em
\setlength{\parindent}{0pt}
\setlength{\parskip}{0.6ex plus 0.3ex}
\hypersetup{pdftitle={%(pdftitle)s}}
"""


def preamble(lang: str, pdftitle: str) -> str:
    return PREAMBLE % {"babel": "czech" if lang == "cs" else "english", "pdftitle": pdftitle.replace("~", " ")}


def gathered(rows: list[str]) -> str:
    return "\\begin{gathered}\n" + " \\\\\n".join(rows) + "\n\\end{gathered}"


def aligned(rows: list[str]) -> str:
    return "\\begin{aligned}\n" + " \\\\\n".join(rows) + "\n\\end{aligned}"


def display(body: str, width: str = r"\linewidth") -> str:
    """An unnumbered display that shrinks to the line when it is wider."""
    return f"\\begin{{center}}\n\\fit[{width}]{{$\\displaystyle\n{body}\n$}}\n\\end{{center}}\n"


def printed_rows(latex: str, width: int = 74) -> list[str]:
    """The rows of a printed display, rows wider than ``width`` glyphs broken (see wrap_row)."""
    return [wrap_row(r, width) for r in display_rows(latex)]


def printed_display(latex: str) -> str:
    return display(gathered(printed_rows(latex)))


def tagged_display(latex: str, tag: str, label: str) -> str:
    """A numbered display (handout): the printed rows, the paper's tag, a label."""
    return ("\\begin{equation}\n\\fit[0.86\\linewidth]{$\\displaystyle\n" + gathered(printed_rows(latex, 62))
            + f"\n$}}\n{tag}\\label{{{label}}}\n\\end{{equation}}\n")


def derived_rows(step: Step) -> list[str] | None:
    """The derivation's result as rows of an ``aligned`` display (None: nothing to display)."""
    res, mode = step.result, step.derivation.mode if step.derivation else ""
    if res is None:
        return None
    if mode == "substitute" or isinstance(res, dict):
        model = dict(res or {})
        if not model:
            return None
        pairs = sorted(model.items(), key=lambda kv: paper_latex(kv[0]))
        return [row for k, v in pairs for row in relation_lines((k, v))]
    rows = []
    for rel in as_list(res):
        if isinstance(rel, sp.Basic):
            rows += relation_lines(rel)
        else:
            rows.append(r"\text{" + escape(str(rel)) + "}")
    return rows


def paragraphs(doc: str) -> str:
    """A docstring as LaTeX paragraphs (blank lines separate them)."""
    paras = [" ".join(p.split()) for p in re.split(r"\n\s*\n", doc.strip()) if p.strip()]
    return "\n\n".join(text(p) for p in paras)


def _digits(digits: tuple[int, ...], lang: str) -> str:
    return join_refs([str(d) for d in digits], lang).replace("~", " ")


def verdict_sentence(v: Verdict, lang: str) -> str:
    W = WORDS[lang]
    how = "" if v.method.value == "none" else W["methods"][v.method.value]
    if v.points and v.digits:
        how += " (" + W["points"].format(n=v.points, digits=_digits(v.digits, lang)) + ")"
    if v.detail:
        how += ": " + text(v.detail)
    how = how.strip()
    # how a verdict was reached depends on the checker's time bound for sympy (a proof that
    # times out on a slow machine is settled numerically): marked \verdicthow{...} for the golden test
    return W["verdicts"][v.name] + (f" \\verdicthow{{{how}}}" if how else "") + ("" if how.endswith(".") else ".")


def witness_text(w, lang: str) -> str:
    """A witness (dict from :func:`quasicentral.output.errata_document` or a Witness) as text."""
    W = WORDS[lang]
    if w is None:
        return ""
    get = (lambda k: w.get(k)) if isinstance(w, dict) else (lambda k: getattr(w, k))
    params = get("parameters") or {}
    if get("quantity") == "dimensions":
        return escape(str(get("printed")))
    pts = ", ".join(f"${_param_name(k)} = {_param_value(v)}$" for k, v in sorted(params.items()))
    out = []
    if pts:
        out.append(f"{W['at']} {pts}")
    q = get("quantity")
    if q:
        out.append(f"{W['quantity']} {text(q)}")
    out.append(f"{W['printed_value']} {code(str(get('printed')))}, "
               f"{W['derived_value']} {code(str(get('corrected')))}"
               + (f" ({get('digits')} digits)" if get("digits") else ""))
    # certification, like the method, is time-bounded upstream (ball integrals have a deadline)
    out.append("\\verdicthow{" + (W["certified_yes"] if get("certified") else W["certified_no"]) + "}")
    return "; ".join(out)


def _param_name(name: str) -> str:
    return paper_latex(sp.Symbol(name))


def _param_value(value: str) -> str:
    try:
        return paper_latex(sp.sympify(value, rational=True))
    except (sp.SympifyError, SyntaxError, TypeError, ValueError):
        return r"\text{" + escape(value) + "}"


def ref_of(step_by_id: dict[str, Step], eid: str, handout: bool) -> str:
    """A reference to entry ``eid``: its number or its tag, linked; an id outside the
    document is written out."""
    st = step_by_id.get(eid)
    if st is None:
        return code(eid)
    if handout:
        prefix = "h:"
        return f"\\eqref{{{prefix}{st.label}}}" if st.entry.number else f"\\ref{{{prefix}{st.label}}}"
    return f"\\ref{{e:{st.label}}}"


_URL_SAFE = re.compile(r"[A-Za-z0-9_.:/=+*()\[\], -]*")


def code(s: str) -> str:
    """Monospaced text that may break at '.', '_', '-' …: identifiers, module paths, numbers."""
    return f"\\nolinkurl{{{s}}}" if _URL_SAFE.fullmatch(s) else f"\\texttt{{{escape(s)}}}"


def _number_or_name(e: catalog.Entry) -> str:
    return f"({escape(e.number)})" if e.number else "[" + text(e.name) + "]"


# --- the report ------------------------------------------------------------------------------
def report_tex(source: str, lang: str, steps: list[Step]) -> str:
    W, T = WORDS[lang], TEXTS[source][lang]
    by_id = {s.entry.id: s for s in steps}
    parts = [preamble(lang, f"{source}: {T['report']}")]
    parts.append(f"\\title{{{T['title']}\\\\[1ex]\\large {T['report']}}}\n\\author{{}}\n\\date{{}}\n")
    parts.append("\\begin{document}\n\\maketitle\n")
    parts.append(W["report_intro"] + "\n\n")
    parts.append(_summary(steps, lang))
    parts.append("\\tableofcontents\n")
    for section, group in sections_of(steps):
        parts.append(f"\\section{{{section_title(source, section, lang)}}}\n")
        for st in group:
            parts.append(_report_entry(st, by_id, lang))
    parts.append(_errata_section(source, steps, lang))
    parts.append(_figures_section(source, lang))
    parts.append(f"\\section{{{W['versions']}}}\n\\input{{{VERSIONS_FILE[:-4]}}}\n")
    parts.append("\\end{document}\n")
    return "".join(parts)


def _summary(steps: list[Step], lang: str) -> str:
    W = WORDS[lang]
    counts: dict[str, int] = {}
    methods: dict[str, int] = {}
    for s in steps:
        counts[s.outcome.status] = counts.get(s.outcome.status, 0) + 1
        m = s.outcome.verdict.method.value
        methods[m] = methods.get(m, 0) + 1
    rows = [f"{W['status'][k]} & {counts[k]} \\\\" for k in ("verified", "erratum", "cleared", "unexpected")
            if k in counts]
    how = ", ".join(f"{W['methods'][k]} {methods[k]}" for k in sorted(methods))
    out = [f"\\section*{{{W['summary']}}}\n{len(steps)} {W['entries']}.\n\n",
           "\\begin{tabular}{lr}\n\\toprule\n" + "\n".join(rows) + "\n\\bottomrule\n\\end{tabular}\n\n",
           f"{W['how_reached']}: \\verdicthow{{{how}}}.\n\n"]
    unexpected = [s for s in steps if s.outcome.status == "unexpected"]
    if unexpected:
        out.append(W["status"]["unexpected"] + ": " + ", ".join(f"\\ref{{e:{s.label}}}" for s in unexpected)
                   + ".\n\n")
    return "".join(out)


def _report_entry(st: Step, by_id: dict[str, Step], lang: str) -> str:
    W, e, o = WORDS[lang], st.entry, st.outcome
    head = (f"({escape(e.number)})~" if e.number else "") + text(e.name)
    out = [f"\\subsection*{{{head}}}\n\\entrylabel{{e:{st.label}}}{{{_number_or_name(e)}}}%\n",
           f"{code(e.id)} --- \\textbf{{{W['status'][o.status]}}}\n\n",
           f"\\textbf{{{W['printed']}.}}\n" + printed_display(e.latex)]
    # as re-derived
    out.append(f"\\textbf{{{W['derived']}.}}")
    rows = derived_rows(st)
    mode = st.derivation.mode if st.derivation else ""
    if st.derivation is None:
        out.append(" " + W["no_derivation"] + "\n\n")
    elif st.error:
        out.append(" " + W["derivation_failed"] + " \\texttt{" + escape(st.error[:300]) + "}\n\n")
    elif rows is None:
        out.append(" " + W["identity"] + ".\n\n")
    else:
        if mode == "substitute":
            out.append(" " + W["model"] + ":")
        elif mode == "condition":
            out.append(" " + W["condition"] + ":")
        out.append("\n" + display(aligned(rows)))
    # verdict
    v = o.verdict
    out.append(f"\\textbf{{{W['verdict']}.}} " + verdict_sentence(v, lang) + " "
               + W["dimensions"].format(d=text(v.dimensions)))
    w = getattr(v, "witness", None)
    if w is not None:
        out.append(f" \\textbf{{{W['witness']}:}} " + witness_text(w, lang) + ".")
    if o.problems:
        out.append(f" \\textbf{{{W['problems']}:}} " + text("; ".join(o.problems)) + ".")
    out.append("\n\n")
    if st.erratum is not None:
        out.append(f"\\textbf{{{W['corrected']}}} ({escape(st.erratum.kind)}):\n" + printed_display(st.erratum.corrected_latex))
        if o.corrected_verdict is not None:
            out.append(f"{W['corrected_form']}: " + verdict_sentence(o.corrected_verdict, lang) + "\n\n")
    # the step
    if st.derivation is not None:
        d = st.derivation
        uses = [ref_of(by_id, u, handout=False) + ("\\,{\\footnotesize " + code(u) + "}" if u in by_id else "")
                for u in d.uses]
        out.append(f"\\textbf{{{W['step']}.}} " + paragraphs(d.doc) + "\n\n")
        out.append(f"\\textbf{{{W['uses']}:}} " + (", ".join(uses) if uses else W["nothing"]) + ". "
                   + f"\\textbf{{{W['code']}:}} {code(d.module + '.' + d.func.__name__)} "
                   + f"({code('mode=' + d.mode)}).\n\n")
    if e.note:
        out.append(f"\\textbf{{{W['note']}.}} " + with_math(e.note) + "\n\n")
    return "".join(out)


def _heading(r: dict) -> str:
    """A subsection title for a row of the errata document: '(8)~name' or 'name'."""
    return (f"({escape(r['number'])})~" if r.get("number") else "") + text(r["name"])


def _errata_section(source: str, steps: list[Step], lang: str) -> str:
    W = WORDS[lang]
    entries = [s.entry for s in steps]
    doc = output.errata_document(entries, [s.outcome for s in steps])
    label = {s.entry.id: s.label for s in steps}
    out = [f"\\section{{{W['errata']}}}\n"]
    if not doc["errata"]:
        out.append(W["none_found"] + "\n\n")
    else:
        out.append("\\begin{longtable}{@{}p{0.2\\linewidth}p{0.76\\linewidth}@{}}\n\\toprule\n"
                   f"{W['table_eq']} & {W['table_printed']} / {W['table_corrected']} / {W['table_witness']} "
                   "\\\\\n\\midrule\n\\endhead\n")
        for n, r in enumerate(doc["errata"]):
            w = r["witness"] or {}
            kind = KINDS_CS.get(r["kind"], r["kind"]) if lang == "cs" else r["kind"]
            cert = "\\verdicthow{" + (W["certified_yes"] if w.get("certified") else W["certified_no"]) + "}"
            cell = lambda latex: "\\fit{$\\displaystyle " + gathered(printed_rows(latex, 54)) + "$}"  # noqa: E731
            out.append(("\\midrule\n" if n else "")
                       + f"\\ref{{e:{label[r['id']]}}} & \\textbf{{{W['table_printed']}:}}\\newline "
                       + cell(r["printed_latex"]) + " \\\\\n"
                       + f"{escape(kind)} & \\textbf{{{W['table_corrected']}:}}\\newline "
                       + cell(r["corrected_latex"]) + " \\\\\n"
                       + f"{cert}; {W['status'][r['status']]} & \\textbf{{{W['table_witness']}:}} "
                       + witness_text(r["witness"], lang) + " \\\\\n")
        out.append("\\bottomrule\n\\end{longtable}\n\n")
        for r in doc["errata"]:
            out.append(f"\\subsection*{{{_heading(r)}}}\n")
            out.append(f"\\textbf{{{W['evidence']}:}} " + text(r["evidence"] or "") + "\n\n")
            out.append(f"\\textbf{{{W['note']}.}} " + with_math(r["note"]) + "\n\n")
    out.append(f"\\section{{{W['cleared_title']}}}\n")
    if not doc["cleared"]:
        out.append(W["none_found"] + "\n\n")
    for r in doc["cleared"]:
        out.append(f"\\subsection*{{{_heading(r)}}}\n")
        out.append(f"\\textbf{{{W['suspicion']}:}} " + with_math(r["suspicion"]) + "\n\n")
        out.append(f"\\textbf{{{W['evidence']}:}} " + text(r["evidence"]) + " ("
                   + W["status"][r["status"]] + ")\n\n")
        out.append(f"\\textbf{{{W['note']}.}} " + with_math(r["note"]) + "\n\n")
    return "".join(out)


def _figure_env(fig: FigureItem, lang: str) -> str:
    # the paper's own figure numbers are in the caption: no LaTeX figure counter
    return ("\\begin{figure}[htbp]\n\\centering\n"
            f"\\includegraphics[width=0.62\\linewidth]{{{fig.path}}}\n\n"
            f"\\small {caption(fig, lang)}\n\\end{{figure}}\n")


def _figures_section(source: str, lang: str) -> str:
    W = WORDS[lang]
    figs = figures_for(source)
    out = [f"\\section{{{W['figures']}}}\n{W['figures_intro']}\n\n"]
    out += [_figure_env(f, lang) for f in figs]
    if not figs:
        out.append(W["none_found"] + "\n")
    out.append("\\clearpage\n")
    return "".join(out)


# --- the handout -----------------------------------------------------------------------------
@dataclass(frozen=True)
class Exercise:
    kind: str  # "derive" | "errata"
    step: Step


def shown_latex(st: Step) -> str:
    """What the handout shows for a step: the corrected form of an erratum, else the print."""
    return st.erratum.corrected_latex if st.erratum is not None and st.outcome.status == "erratum" else st.entry.latex


def exercises_of(steps: list[Step]) -> list[Exercise]:
    """Exercises taken from the steps: per section, a few verified numbered equations that a
    derivation produces from others (evenly spread), and up to two printed errata to find."""
    secs = sections_of(steps)
    per = max(3, -(-6 // max(len(secs), 1)))
    out = []
    for _, group in secs:
        cand = [s for s in group if s.entry.number and s.derivation is not None and s.derivation.uses
                and not s.error and s.outcome.status in ("verified", "cleared")]
        if len(cand) > per:
            cand = [cand[round(i * (len(cand) - 1) / (per - 1))] for i in range(per)]
        out += [Exercise("derive", s) for s in cand]
        out += [Exercise("errata", s) for s in group if s.outcome.status == "erratum"][:2]
    return out


def handout_tex(source: str, lang: str, steps: list[Step]) -> str:
    W, T = WORDS[lang], TEXTS[source][lang]
    by_id = {s.entry.id: s for s in steps}
    tags: dict[str, str] = {}
    k = 0
    for s in steps:
        if s.entry.number:
            tags[s.entry.id] = f"\\tag{{{escape(s.entry.number)}}}"
        else:
            k += 1
            tags[s.entry.id] = f"\\tag*{{[{k}]}}"
    parts = [preamble(lang, f"{source}: {T['handout']}")]
    parts.append(f"\\title{{{T['title']}\\\\[1ex]\\large {T['handout']}}}\n\\author{{}}\n\\date{{}}\n")
    parts.append("\\begin{document}\n\\maketitle\n")
    parts.append(T["intro"] + "\n\n")
    parts.append(W["verified_by"].format(report=f"{source}-report-{lang}") + "\n\n")
    for section, group in sections_of(steps):
        known = SECTIONS.get((source, section), {}).get(lang)
        parts.append(f"\\section{{{section_title(source, section, lang)}}}\n")
        if known:
            parts.append(known[1] + "\n\n")
        for i, st in enumerate(group):
            parts.append(_handout_step(st, i, by_id, tags[st.entry.id], lang))
    exercises = exercises_of(steps)
    if exercises:
        parts.append(f"\\section{{{W['exercises']}}}\n\\begin{{enumerate}}\n")
        for n, ex in enumerate(exercises, 1):
            parts.append(f"\\item\\label{{ex:{n}}} " + _exercise(ex, by_id, lang))
        parts.append("\\end{enumerate}\n")
    parts.append(_figures_section(source, lang))
    if exercises:
        parts.append(f"\\section{{{W['solutions']}}}\n")
        for n, ex in enumerate(exercises, 1):
            parts.append(f"\\subsection*{{{W['exercise']}~\\ref{{ex:{n}}}}}\n" + _solution(ex, lang))
    parts.append("\\end{document}\n")
    return "".join(parts)


def _connect(st: Step, index: int, by_id: dict[str, Step], lang: str) -> str:
    """The sentence that leads to a step: where it starts from (varied, deterministically)."""
    W = WORDS[lang]
    uses = [u for u in (st.derivation.uses if st.derivation else ()) if u in by_id]
    if not uses:
        return W["start"] if index == 0 else W["states"][index % len(W["states"])]
    refs = join_refs([ref_of(by_id, u, handout=True) for u in uses], lang)
    choices = W["from_one"] if len(uses) == 1 else W["from_many"]
    return choices[index % len(choices)].format(refs=refs)


def _handout_step(st: Step, index: int, by_id: dict[str, Step], tag: str, lang: str) -> str:
    W = WORDS[lang]
    out = [_connect(st, index, by_id, lang) + "\n" + tagged_display(shown_latex(st), tag, f"h:{st.label}")]
    if lang == "en" and st.derivation is not None:
        out.append(paragraphs(st.derivation.doc) + "\n\n")
    status = st.outcome.status
    if status == "erratum" and st.erratum is not None:
        kind = KINDS_CS.get(st.erratum.kind, st.erratum.kind) if lang == "cs" else st.erratum.kind
        out.append("\\emph{" + W["erratum"].format(kind=escape(kind)) + "}\n" + printed_display(st.entry.latex))
    elif status == "cleared":
        out.append("\\emph{" + W["cleared"] + "}\n\n")
    elif status == "unexpected":
        out.append("\\emph{" + W["unverified"] + "}\n\n")
    return "".join(out)


def _exercise(ex: Exercise, by_id: dict[str, Step], lang: str) -> str:
    W, st = WORDS[lang], ex.step
    if ex.kind == "errata":
        return W["ex_errata"].format(ref=ref_of(by_id, st.entry.id, handout=True)) + "\n" + printed_display(st.entry.latex)
    uses = [ref_of(by_id, u, handout=True) for u in st.derivation.uses if u in by_id]
    ref = ref_of(by_id, st.entry.id, handout=True)
    key = "ex_derive_none" if not uses else ("ex_derive_one" if len(uses) == 1 else "ex_derive")
    return W[key].format(refs=join_refs(uses, lang), ref=ref) + "\n" + printed_display(shown_latex(st))


def _solution(ex: Exercise, lang: str) -> str:
    W, st = WORDS[lang], ex.step
    if ex.kind == "errata":
        kind = KINDS_CS.get(st.erratum.kind, st.erratum.kind) if lang == "cs" else st.erratum.kind
        return (W["sol_corrected"] + "\n" + printed_display(st.erratum.corrected_latex)
                + W["sol_kind"].format(kind=escape(kind)) + " " + W["sol_note"] + " "
                + with_math(errata_mod.render_note(st.erratum.note, getattr(st.outcome.verdict, "witness", None)))
                + "\n\n")
    out = [W["sol_step"] + " " + paragraphs(st.derivation.doc) + "\n\n"]
    rows = derived_rows(st)
    if rows:
        out.append(W["sol_result"] + "\n" + display(aligned(rows)))
    return "".join(out)


# --- generating and writing ------------------------------------------------------------------
def file_names(kinds=KINDS, langs=LANGS) -> list[str]:
    """The .tex files that :func:`generate` writes for these kinds and languages."""
    return [f"{source}-{kind}-{lang}.tex" for kind in kinds for lang in langs for source in catalog.SOURCES]


def outcomes_for_all() -> dict[str, Outcome]:
    """Verdicts of every catalog entry (read from the verification cache when it is warm)."""
    from quasicentral.engine import run as verify
    from quasicentral.engine.checker import Options

    entries = catalog.entries()
    return dict(zip([e.id for e in entries], verify.run(entries, Options(), use_cache=True)))


def generate(kinds=("report",), langs=("en",), outcomes: dict[str, Outcome] | None = None) -> dict[str, str]:
    """File name → LaTeX source of every document asked for, plus ``versions.tex``."""
    outcomes = outcomes if outcomes is not None else outcomes_for_all()
    docs: dict[str, str] = {}
    for source in catalog.SOURCES:
        steps = steps_of(source, outcomes)
        for kind in kinds:
            for lang in langs:
                build = report_tex if kind == "report" else handout_tex
                docs[f"{source}-{kind}-{lang}.tex"] = build(source, lang, steps)
    if "report" in kinds:
        docs[VERSIONS_FILE] = versions_tex()
    return {name: docs[name] for name in sorted(docs)}


def figures_needed(docs: dict[str, str]) -> list[FigureItem]:
    """The figures the documents include, in the order of quasicentral.figures.ALL."""
    return [f for f in figure_items() if any(f"{{{f.path}}}" in tex for tex in docs.values())]


def check_writable(out: Path) -> None:
    """Raise OSError when ``out`` cannot be created or written to (before anything is written)."""
    out.mkdir(parents=True, exist_ok=True)
    probe = out / ".quasicentral-write-test.tmp"
    probe.write_text("")
    probe.unlink()


def write(out: Path, docs: dict[str, str]) -> list[Path]:
    """Write the documents and the figures they include (each via a temporary file and a rename,
    so that a failure never leaves a half-written file).  Returns the paths, sorted."""
    check_writable(out)
    written = []

    def put(path: Path, fill) -> None:
        write_atomic(path, fill)
        written.append(path)

    for name, tex in docs.items():
        put(out / name, lambda tmp, tex=tex: tmp.write_text(tex, encoding="utf-8"))
    figs = figures_needed(docs)
    if figs:
        (out / FIGURE_DIR).mkdir(exist_ok=True)
    for f in figs:
        put(out / f.path, lambda tmp, f=f: figures_mod.draw(f.make(), tmp))
    return sorted(written)


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


def compile_one(out: Path, name: str) -> Path:
    """``latexmk -pdf`` one document in ``out``; raise :class:`LatexError` on any LaTeX error
    or undefined reference.  Returns the PDF's path."""
    stem = name[:-4]
    log = out / f"{stem}.log"
    env = {**os.environ, "SOURCE_DATE_EPOCH": "0", "FORCE_SOURCE_DATE": "1"}
    cmd = ["latexmk", "-norc", "-pdf", "-interaction=nonstopmode", "-halt-on-error", "-file-line-error",
           "-silent", name]
    try:
        proc = subprocess.run(cmd, cwd=out, capture_output=True, text=True, env=env, timeout=600)
    except FileNotFoundError:
        raise LatexError("latexmk is not installed (run ./setup.sh)", log) from None
    except subprocess.TimeoutExpired:
        raise LatexError(f"LaTeX did not finish within 600 s: see {log}", log) from None
    problems = log_problems(log.read_text(encoding="utf-8", errors="replace")) if log.is_file() else []
    if proc.returncode != 0 or problems:
        first = problems[0] if problems else f"latexmk exited with {proc.returncode}"
        raise LatexError(f"LaTeX failed on {name} ({first[:160]}): see {log}", log)
    return out / f"{stem}.pdf"


def compile_all(out: Path, names: list[str], jobs: int | None = None) -> list[Path]:
    """Compile the documents (in parallel); the first failure raises :class:`LatexError`."""
    names = [n for n in names if n != VERSIONS_FILE]
    jobs = jobs or min(len(names), os.cpu_count() or 1) or 1
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = [pool.submit(compile_one, out, n) for n in names]
        return [f.result() for f in futures]
