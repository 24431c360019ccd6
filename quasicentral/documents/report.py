"""Reports and handouts: LaTeX regenerated from the verified derivations, compiled to PDF.

Views over the same registry (STYLE.md, point 9):

* the **report** of a text opens with what its reader came for: what was checked and how, the
  counts, and the errata with their printed and corrected forms side by side (page 1); then
  each cause of error explained once with the displays it affects, the cleared suspects, every
  equation of the text compactly (as printed, as re-derived in the text's notation, one short
  verdict, the step), the figures, and the method with the evidence for each equation once, in
  an appendix;
* the **handout** tells the derivation to a student in the text's order, with exercises; the
  **teacher's** handout adds the solutions, in the language of the document and in the form
  of the text.

A text's own words (title, introductions, section titles, figure captions, Czech step texts)
come from ``<text folder>/report.toml`` (:mod:`quasicentral.documents.prose`); generic words
are in :data:`quasicentral.documents.prose.WORDS`.  Everything here is deterministic: entries
in catalog order, no timestamps, no absolute paths.  The software versions, which differ from
machine to machine, go to ``versions.tex`` that the reports ``\\input``.  Nothing here prints;
the CLI does.

>>> all(name.endswith("-report-en.tex") for name in file_names(("report",), ("en",)))
True
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

from quasicentral import files
from quasicentral.documents.latex import (
    MATH_CHARS, Notation, clean_prose, display_rows, escape, names_as_printed, notation, paper_latex, relation_lines, text,
    using,
    visible_width, with_math, wrap_row)
from quasicentral.documents.prose import KINDS_CS, LANGS, WORDS, TextProse, join_refs, prose_of
from quasicentral.engine import catalog, texts
from quasicentral.engine import errata as errata_mod
from quasicentral.engine.registry import REGISTRY, Derivation, as_list, derived
from quasicentral.engine.verdict import Outcome
from quasicentral.files import write_atomic
from quasicentral.studies import figures as figures_mod

#: The documents of a text: the report, the students' handout, the teacher's handout.
KINDS = ("report", "handout", "teacher")
FIGURE_DIR = "figures"
VERSIONS_FILE = "versions.tex"
#: The packages whose versions a report states (distribution name, import name).
PACKAGES = (("sympy", "sympy"), ("mpmath", "mpmath"), ("numpy", "numpy"), ("scipy", "scipy"),
            ("python-flint", "flint"), ("matplotlib", "matplotlib"))
#: The golden documents (kinds × languages) that ``quasicentral report --all`` writes.
#: The two handouts: the students' (no solutions) and the teacher's (with solutions).
HANDOUT_KINDS = ("handout", "teacher")
GOLDEN = ((("report",), LANGS), (HANDOUT_KINDS, LANGS))
#: The command that regenerates every golden file under reports/.
REGENERATE = "quasicentral report --all --out reports"
#: pdflang of each language.
PDFLANG = {"en": "en-GB", "cs": "cs-CZ"}


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
    index: int = 0  # running number of an unnumbered entry in its text ([1], [2], …), else 0

    @property
    def label(self) -> str:
        return label_of(self.entry.id)

    @property
    def tag(self) -> str:
        """How the text's documents refer to the entry: its number (12) or its place [3]."""
        return f"({self.entry.number})" if self.entry.number else f"[{self.index}]"

    @property
    def is_erratum(self) -> bool:
        return self.erratum is not None and self.outcome.status == "erratum"


def label_of(eid: str) -> str:
    """A LaTeX label for an entry id: letters and digits only, other characters as '.'."""
    return re.sub(r"[^A-Za-z0-9]", ".", eid)


def steps_of(source: str, outcomes: dict[str, Outcome]) -> list[Step]:
    """The steps of one text in catalog order, each with its (memoized) derivation result."""
    text_ = texts.get(source)
    errs, cleared = text_.errata, text_.cleared
    out, k = [], 0
    for e in text_.entries.values():
        d = REGISTRY.get(e.id)
        result, error = None, ""
        if d is None:
            error = "none"
        else:
            try:
                result = derived(e.id)
            except Exception as exc:  # noqa: BLE001 - a failing derivation is reported, not raised
                error = f"{type(exc).__name__}: {exc}"
        if not e.number:
            k += 1
        out.append(Step(e, outcomes[e.id], d, result, error, errs.get(e.id), cleared.get(e.id),
                        0 if e.number else k))
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
    """The printed title of every catalog section, read from the catalog files."""
    import tomllib

    out = {}
    for t in texts.active():
        for path in t.catalog_files:
            data = tomllib.loads(path.read_text(encoding="utf-8"))
            out[(t.id, str(data["section"]))] = data.get("title", "")
    return out


def section_title(prose: TextProse, section: str, lang: str) -> str:
    """The title of a section: the text's own words (report.toml), else its printed title."""
    known = prose.section_title(section, lang)
    if known:
        return known
    printed = section_titles().get((prose.id, section), "")
    return with_math(printed, letters=False) if printed else escape(section)


# --- words of one entry --------------------------------------------------------------------------
def entry_heading(st: Step, prose: TextProse, lang: str) -> str:
    """'(12) name' in English; in Czech 'Rovnice (12)' unless the text gives a Czech name."""
    W = WORDS[lang]
    own = prose.entry(st.entry.id).name.get(lang)
    if own:
        name = own
    elif lang == "en":
        name = text(clean_prose(st.entry.name))
    else:
        name = ""
    word = W["equation"] if st.entry.number else W["relation"]
    tag = escape(st.tag)
    return f"{tag}~{name}" if name else f"{word}~{tag}"


_MATH_HEAD = re.compile(r"^(.*?)(?::\s|\.\s*$|$)", re.S)
_FUNCTION_WORDS = {"sin", "cos", "tg", "cotg", "arccotg", "arctg", "arcsin", "ln", "exp", "dt", "dx", "dy",
                   "ds", "dz", "konst", "d", "const"}


def _is_formula(s: str) -> bool:
    """Does ``s`` hold mathematics only (no word of a language)?"""
    words = re.findall(r"[A-Za-z]{2,}", s)
    return bool(s.strip()) and all(w in _FUNCTION_WORDS for w in words) and any(c in s for c in "=≈≤≥→")


def step_text(st: Step, by_id: dict[str, Step], prose: TextProse, lang: str, handout: bool) -> str:
    """The step that produces an entry, as a sentence in the document's language: the text's
    own words (report.toml) if it has them, the derivation's docstring in English, and in any
    other language the formula the docstring opens with followed by a sentence on where the
    step comes from."""
    d = st.derivation
    if d is None:
        return ""
    own = prose.entry(st.entry.id).step.get(lang)
    if own:
        return own
    W = WORDS[lang]
    uses = [u for u in d.uses if u in by_id]
    refs = join_refs([ref_of(by_id, u, handout) for u in uses], lang)
    where = (W["step_from"][d.mode].format(refs=refs) if uses else W["step_none"][d.mode])
    if lang == "en":
        return paragraphs(clean_prose(d.doc))
    head = _MATH_HEAD.match(" ".join(d.doc.split())).group(1).strip()
    formula = clean_prose(head)
    if _is_formula(formula):
        return text(formula) + ".  " + where
    return where


def erratum_note(st: Step, prose: TextProse, lang: str) -> str:
    """What a reader is told about an erratum or a cleared suspect, in the language: the text's
    own words (report.toml), the record's note in English, or nothing."""
    witness = getattr(st.outcome.verdict, "witness", None)
    own = prose.entry(st.entry.id).erratum.get(lang)
    if own:
        return errata_mod.render_note(own, witness)  # numbers only through {witness…} placeholders
    if lang == "en":
        note = st.erratum.note if st.erratum is not None else (st.cleared.note if st.cleared else "")
        return with_math(clean_prose(errata_mod.render_note(note, witness)))
    return ""


# --- causes of errata ------------------------------------------------------------------------------
@dataclass(frozen=True)
class CauseGroup:
    """One root cause and the errata it explains (an erratum without recorded causes is a
    cause of its own)."""

    key: str
    title: dict[str, str]
    kind: str
    note: dict[str, str]
    steps: tuple[Step, ...]
    recorded: bool  # a [[cause]] of the errata data (else made up from one erratum)

    @property
    def label(self) -> str:
        return "c:" + label_of(self.key)


def _causes_of(erratum) -> list:
    """The recorded causes of an erratum (``Erratum.causes`` when the errata data has them)."""
    got = getattr(erratum, "causes", None) or ()
    return [c for c in got if hasattr(c, "id")]


def cause_groups(steps: list[Step]) -> list[CauseGroup]:
    """The causes of a text's errata, in the order of their first erratum."""
    groups: dict[str, dict] = {}
    for st in steps:
        if not st.is_erratum:
            continue
        causes = _causes_of(st.erratum)
        if causes:
            for c in causes:
                g = groups.setdefault(c.id, {
                    "title": {"en": getattr(c, "title", c.id), "cs": getattr(c, "title_cs", "") or ""},
                    "kind": getattr(c, "kind", "") or st.erratum.kind,
                    "note": {"en": getattr(c, "note", "") or "", "cs": getattr(c, "note_cs", "") or ""},
                    "steps": [], "recorded": True})
                g["steps"].append(st)
        else:
            groups[st.entry.id] = {"title": {}, "kind": st.erratum.kind, "note": {}, "steps": [st],
                                   "recorded": False}
    return [CauseGroup(k, g["title"], g["kind"], g["note"], tuple(g["steps"]), g["recorded"])
            for k, g in groups.items()]


def kind_name(kind: str, lang: str) -> str:
    return escape(KINDS_CS.get(kind, kind) if lang == "cs" else kind)


def cause_title(g: CauseGroup, prose: TextProse, lang: str) -> str:
    if g.recorded:
        got = g.title.get(lang) or (g.title.get("en") if lang == "en" else "")
        if got:
            return with_math(clean_prose(got))
        return kind_name(g.kind, lang)[:1].upper() + kind_name(g.kind, lang)[1:]
    st = g.steps[0]
    return entry_heading(st, prose, lang) + ": " + kind_name(g.kind, lang)


def cause_note(g: CauseGroup, prose: TextProse, lang: str) -> str:
    if g.recorded:
        got = g.note.get(lang, "")
        return with_math(clean_prose(got)) if got else ""
    return erratum_note(g.steps[0], prose, lang)


# --- figures ---------------------------------------------------------------------------------
@dataclass(frozen=True)
class FigureItem:
    name: str
    title: str
    make: object  # builds the figure (from its text's figures.py)

    @property
    def path(self) -> str:
        return f"{FIGURE_DIR}/{self.name}.png"


def figure_items() -> tuple[FigureItem, ...]:
    """Every figure of the active texts (their folders' figures.py)."""
    items: dict[str, FigureItem] = {}
    for t in texts.active():
        for fig in figures_mod.of_text(t):
            items.setdefault(fig.name, FigureItem(fig.name, fig.title, lambda fig=fig: fig))
    return tuple(items.values())


def figures_for(prose: TextProse, role: str | None = None) -> list[tuple[FigureItem, object]]:
    """The figures of a text (its folder's figures.py, in that order), each with its prose from
    report.toml (or None); ``role`` keeps only "text" figures or "study" charts (a measured
    chart is a study unless report.toml says otherwise)."""
    said = {fp.name: fp for fp in prose.figures}
    out = []
    for fig in figures_mod.of_text(texts.get(prose.id)):
        fp = said.get(fig.name)
        kind = fp.role if fp is not None else ("study" if isinstance(fig, figures_mod.MeasuredChart) else "text")
        if role is None or kind == role:
            out.append((FigureItem(fig.name, fig.title, lambda fig=fig: fig), fp))
    return out


def caption(fig: FigureItem, fp, lang: str) -> str:
    got = fp.caption.get(lang) if fp is not None else None
    return got or text(clean_prose(fig.title))


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
\usepackage{pdflscape}
\usepackage{array,booktabs,longtable}
\usepackage[hidelinks,unicode,bookmarksnumbered]{hyperref}
%% the paper's notation
\DeclareMathOperator{\arccotg}{arccotg}
%% a box that shrinks to the given width only when it is wider
\newsavebox{\qcbox}
\newcommand{\fit}[2][\linewidth]{\sbox{\qcbox}{#2}%%
  \ifdim\wd\qcbox>#1\resizebox{#1}{!}{\usebox{\qcbox}}\else\usebox{\qcbox}\fi}
%% how a verdict was reached and whether balls certify it (both time-bounded, hence
%% machine-dependent: the golden test does not compare them)
\newcommand{\verdicthow}[1]{#1}
%% a label whose \ref prints #2 (an equation's number or place)
\makeatletter
\newcommand{\entrylabel}[2]{\phantomsection\def\@currentlabel{#2}\label{#1}}
\makeatother
\allowdisplaybreaks
\emergencystretch=3em
\setlength{\parindent}{0pt}
\setlength{\parskip}{0.6ex plus 0.3ex}
\setlength{\LTpre}{0.5ex}
%% compact headings of the entries
\makeatletter
\renewcommand\subsection{\@startsection{subsection}{2}{\z@}{-2.2ex plus -0.6ex minus -0.2ex}%%
  {0.6ex plus 0.2ex}{\normalfont\large\bfseries}}
\makeatother
\setlength{\LTpost}{0.5ex}
\hypersetup{pdftitle={%(pdftitle)s}, pdfauthor={%(pdfauthor)s}, pdfsubject={%(pdfsubject)s},
  pdflang={%(pdflang)s}, pdfcreator={quasicentral}}
"""

_PLAIN_MATH = {v.strip(): k for k, v in MATH_CHARS.items() if v.startswith("\\") and len(k) == 1}
_PLAIN_MATH.update({r"\varrho": "ϱ", r"\varphi": "φ", r"\to": "→", r"\sqrt": "√", r"\dot": "", r"\ldots": "…"})
_SUP = str.maketrans("0123456789+-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻")
_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def plain(tex: str) -> str:
    """LaTeX prose as plain Unicode text (PDF metadata and bookmarks): R~$R_0\\kappa^2$ → R R₀κ²."""
    s = tex.replace("~", " ").replace("---", "—").replace("--", "–").replace(r"\,", " ")
    s = re.sub(r"\^\{?([0-9+-]+)\}?", lambda m: m.group(1).translate(_SUP), s)
    s = re.sub(r"_\{?([0-9]+)\}?", lambda m: m.group(1).translate(_SUB), s)
    s = re.sub(r"\\[A-Za-z]+", lambda m: _PLAIN_MATH.get(m.group(0), ""), s)
    s = s.replace("$", "").replace("{", "").replace("}", "").replace("\\", "")
    return " ".join(s.split())


def pdf_safe(title: str) -> str:
    """A heading whose mathematics has a plain-text form for the PDF's bookmarks."""
    if "$" not in title and "\\" not in title:
        return title
    return f"\\texorpdfstring{{{title}}}{{{plain(title)}}}"


def preamble(lang: str, title: str, subtitle: str, prose: TextProse) -> str:
    meta = lambda s: plain(s).replace(",", "{,}")  # noqa: E731 - a comma would end the key's value
    author = "quasicentral" + (f" ({prose.author})" if prose.author else "")
    return PREAMBLE % {"babel": "czech" if lang == "cs" else "english", "pdftitle": meta(f"{title}: {subtitle}"),
                       "pdfauthor": meta(author), "pdfsubject": meta(title), "pdflang": PDFLANG[lang]}


def title_block(title: str, subtitle: str) -> str:
    return ("\\begin{center}\n{\\Large\\bfseries " + title + "\\par}\n\\vspace{0.8ex}\n{\\large " + subtitle
            + "\\par}\n\\end{center}\n")


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


def _relation(rel) -> sp.Expr | None:
    if isinstance(rel, sp.Eq):
        return rel.lhs - rel.rhs
    if isinstance(rel, sp.Expr):
        return rel
    return None


def _same(a, b) -> bool:
    """Are two relations the same up to rearrangement (their lhs − rhs equal or opposite after
    expansion)?  Cheap: large expressions are not compared."""
    da, db = _relation(a), _relation(b)
    if da is None or db is None or sp.count_ops(da) > 250 or sp.count_ops(db) > 250:
        return False
    try:
        return sp.expand(da - db) == 0 or sp.expand(da + db) == 0
    except Exception:  # noqa: BLE001 - a comparison sympy cannot do is no match
        return False


_MEMO: dict[tuple, object] = {}


def _memo(kind: str, st: Step, make):
    """Per entry and derivation result: the same answer for every document of a text."""
    key = (kind, st.entry.id, id(st.result))
    if key not in _MEMO:
        _MEMO[key] = make()
    return _MEMO[key]


def same_as_printed(st: Step) -> bool:
    """Is the re-derived result the printed relation itself (rearranged at most)?"""
    return _memo("same", st, lambda: _same_as_printed(st))


def _same_as_printed(st: Step) -> bool:
    if st.result is None or st.is_erratum or (st.derivation and st.derivation.mode not in ("solve", "expression")):
        return False
    try:
        printed = as_list(st.entry.printed)
    except Exception:  # noqa: BLE001 - an unreadable transcription is no match
        return False
    got = [r for r in as_list(st.result) if isinstance(r, sp.Basic)]
    return bool(got) and all(any(_same(r, p) for p in printed) for r in got)


def _oriented(rel, printed: list):
    """A derived ``Eq`` with its sides in the order of the printed relation it matches (the
    printed lhs on the left), so that the reader compares like with like."""
    if not isinstance(rel, sp.Eq):
        return rel
    for p in printed:
        if isinstance(p, sp.Eq) and (rel.rhs == p.lhs or (rel.rhs.free_symbols == p.lhs.free_symbols
                                                           and rel.lhs.free_symbols == p.rhs.free_symbols
                                                           and rel.lhs.free_symbols != rel.rhs.free_symbols)):
            return sp.Eq(rel.rhs, rel.lhs, evaluate=False)
    return rel


def derived_rows(step: Step, width: int = 70, prose: TextProse | None = None) -> list[str] | None:
    """The derivation's result as rows of an ``aligned`` display, in the symbols the text
    prints (ρ or ϱ as printed) and with each side where the print has it (None: nothing)."""
    return _memo(f"rows{width}", step, lambda: _derived_rows(step, width, prose))


def _derived_rows(step: Step, width: int, prose: TextProse | None) -> list[str] | None:
    res, mode = step.result, step.derivation.mode if step.derivation else ""
    if res is None:
        return None
    current = notation()
    names = names_as_printed(step.entry.latex, {**current.names, **(prose.symbols if prose else {})})
    # a function (ϱ(t), φ(t)) in the form of its letter that the display prints
    functions = names_as_printed(step.entry.latex, {**current.functions, **(prose.functions if prose else {})})
    if mode == "substitute" or isinstance(res, dict):
        model = dict(res or {})
        if not model:
            return None
        pairs = sorted(model.items(), key=lambda kv: paper_latex(kv[0]))
        return [row for k, v in pairs for row in relation_lines((k, v), width, names, functions)]
    try:
        printed = as_list(step.entry.printed)
    except Exception:  # noqa: BLE001
        printed = []
    rows = []
    for rel in as_list(res):
        if isinstance(rel, sp.Basic):
            rows += relation_lines(_oriented(rel, printed), width, names, functions)
    return rows or None


def paragraphs(doc: str) -> str:
    """A docstring as LaTeX paragraphs (blank lines separate them)."""
    paras = [" ".join(p.split()) for p in re.split(r"\n\s*\n", doc.strip()) if p.strip()]
    return "\n\n".join(text(p) for p in paras)


def number(value: str, lang: str, digits: int = 4) -> str:
    """A decimal in a few significant digits, with the decimal comma in Czech (math mode)."""
    try:
        x = float(sp.N(sp.sympify(value, rational=True), 20))
    except (sp.SympifyError, SyntaxError, TypeError, ValueError):
        return r"\text{" + escape(value) + "}"
    s = f"{x:.{digits}g}"
    if "e" in s:
        m, e = s.split("e")
        s = f"{m} \\cdot 10^{{{int(e)}}}"
    s = s.replace("-", "-")
    return s.replace(".", "{,}") if lang == "cs" else s


def _wget(w, key):
    return w.get(key) if isinstance(w, dict) else getattr(w, key, None)


def witness_short(w, lang: str, point: bool = True) -> str:
    """A witness in a few digits: the point (with ``point``), then the printed and the correct
    value."""
    W = WORDS[lang]
    if w is None:
        return ""
    if _wget(w, "quantity") == "dimensions":
        return W["dims_bad"] + "."
    params = (_wget(w, "parameters") or {}) if point else {}
    pts = ", ".join(f"${_param_name(k)} = {number(v, lang)}$" for k, v in sorted(params.items()))
    vals = W["vs"].format(p=f"${number(str(_wget(w, 'printed')), lang)}$",
                          c=f"${number(str(_wget(w, 'corrected')), lang)}$")
    return (f"{W['at']} {pts}: " if pts else "") + vals


def certified_mark(w, lang: str) -> str:
    W = WORDS[lang]
    if w is None:
        return ""
    # not in \verdicthow: whether a witness is certified does not depend on the machine
    # (its balls are bounded by counted evaluations, not time)
    return W["certified_yes"] if _wget(w, "certified") else W["certified_no"]


def _param_name(name: str) -> str:
    return paper_latex(sp.Symbol(name))


def detail_text(detail: str, lang: str) -> str:
    """The checker's detail of a verdict in the document's language (a closed set of
    sentences); a detail the table does not know is left out of a Czech document."""
    for pattern, words in WORDS[lang]["details"]:
        m = re.match(pattern, detail)
        if m:
            groups = [g.replace(".", ",") if lang == "cs" else g for g in m.groups()]
            return words.format(*groups)
    return text(detail) if lang == "en" else ""


def _dim_latex(d: str) -> str:
    try:
        expr = sp.sympify(d, locals={n: sp.Symbol(n) for n in ("L", "T", "M", "K", "I")})
    except (sp.SympifyError, SyntaxError, TypeError):
        return r"\text{" + escape(d) + "}"
    return "1" if expr == 1 else sp.latex(expr, mul_symbol="dot").replace("L", r"\mathsf{L}").replace(
        "T", r"\mathsf{T}").replace("M", r"\mathsf{M}")


def _expr_latex(s: str) -> str:
    """An expression of a checker's message (sympy syntax, the text's names) in the notation."""
    try:
        names = notation().names
        ns = {n: sp.Symbol(n) for n in names}
        ns.update({n: sp.Function(n) for n in notation().functions})
        expr = sp.parse_expr(s, local_dict=ns)
        return paper_latex(expr)
    except Exception:  # noqa: BLE001 - an unreadable expression is named in words
        return ""


def _inline(tex: str) -> str:
    """Mathematics inside a sentence; a long formula gets a line of its own."""
    if visible_width(tex) <= 24:
        return f"${tex}$"
    return "\n\\begin{center}\\fit{$\\displaystyle " + tex + "$}\\end{center}\n"


_DIM_ADD = re.compile(r"^inconsistent: adds \[(.+?)\] to \[(.+?)\] in (.+): term (.+)$")
_DIM_EXP = re.compile(r"^inconsistent: exp of \[(.+?)\] argument (.+)$")
_DIM_LIMIT = re.compile(r"^inconsistent: limit (.+?) \[(.+?)\] of d(\w+) \[(.+?)\]$")


def dimension_sentence(msg: str, lang: str) -> str:
    """The checker's dimension message as a sentence in the document's language ('' when the
    dimensions are consistent)."""
    W = WORDS[lang]
    if not msg or msg == "consistent":
        return ""
    m = _DIM_ADD.match(msg)
    if m and _expr_latex(m.group(4)):
        return (W["dims_bad"] + ": " + W["dims_add"].format(
            term=_inline(_expr_latex(m.group(4))), a=f"${_dim_latex(m.group(2))}$", b=f"${_dim_latex(m.group(1))}$")
            + ".")
    m = _DIM_EXP.match(msg)
    if m and _expr_latex(m.group(2)):
        return W["dims_bad"] + ": " + W["dims_exp"].format(arg=_inline(_expr_latex(m.group(2))),
                                                           a=f"${_dim_latex(m.group(1))}$") + "."
    m = _DIM_LIMIT.match(msg)
    if m:
        return W["dims_bad"] + ": " + W["dims_limit"].format(
            lim=f"${_expr_latex(m.group(1)) or escape(m.group(1))}$", a=f"${_dim_latex(m.group(2))}$",
            b=f"${_dim_latex(m.group(4))}$") + "."
    return W["dims_bad"] + "."


def verdict_short(st: Step, lang: str) -> str:
    """One short verdict: 'verified symbolically.', 'refuted (erratum, see …).'"""
    W, o = WORDS[lang], st.outcome
    v = o.verdict
    how = "" if v.method.value == "none" else W["methods"][v.method.value]
    out = W["verdicts"][v.name] + (f" \\verdicthow{{{how}}}" if how else "")
    if o.status == "cleared":
        out += " (" + W["status"]["cleared"] + ")"
    elif o.status == "unexpected":
        out += " (" + W["status"]["unexpected"] + ")"
    return out + "."


def ref_of(step_by_id: dict[str, Step], eid: str, handout: bool) -> str:
    """A reference to entry ``eid``: its number or its place, linked."""
    st = step_by_id.get(eid)
    if st is None:
        return ""
    if handout:
        return f"\\eqref{{h:{st.label}}}" if st.entry.number else f"\\ref{{h:{st.label}}}"
    return f"\\ref{{e:{st.label}}}"


# --- the report ------------------------------------------------------------------------------
def report_tex(source: str, lang: str, steps: list[Step], prose: TextProse | None = None) -> str:
    prose = prose or prose_of(source)
    W = WORDS[lang]
    title = prose.title[lang]
    by_id = {s.entry.id: s for s in steps}
    groups = cause_groups(steps)
    parts = [preamble(lang, title, W["report"], prose), "\\begin{document}\n",
             title_block(title, W["report"])]
    parts.append(_summary(steps, groups, lang))
    parts.append(_errata_table(steps, lang))
    parts.append("\\clearpage\n\\tableofcontents\n\n")
    parts.append(_causes_section(groups, by_id, prose, lang))
    parts.append(_cleared_section(steps, prose, lang))
    for section, group in sections_of(steps):
        parts.append(f"\\section{{{pdf_safe(section_title(prose, section, lang))}}}\n")
        if section == sections_of(steps)[0][0]:
            parts.append(W["report_intro"] + "\n\n")
        for st in group:
            parts.append(_report_entry(st, by_id, groups, prose, lang))
    parts.append(_figures_section(prose, lang, handout=False))
    parts.append("\\appendix\n")
    parts.append(_method_section(steps, lang))
    parts.append(f"\\section{{{W['versions']}}}\n\\input{{{VERSIONS_FILE[:-4]}}}\n")
    parts.append("\\end{document}\n")
    return "".join(parts)


def _summary(steps: list[Step], groups: list[CauseGroup], lang: str) -> str:
    W = WORDS[lang]
    counts: dict[str, int] = {}
    methods: dict[str, int] = {}
    for s in steps:
        counts[s.outcome.status] = counts.get(s.outcome.status, 0) + 1
        if s.outcome.status == "verified":
            m = s.outcome.verdict.method.value
            methods[m] = methods.get(m, 0) + 1
    inconclusive = counts.get("unexpected", 0) + sum(
        1 for s in steps if s.outcome.status == "verified" and s.outcome.verdict.name == "inconclusive")
    how = ", ".join(f"{W['methods'][k]} {methods[k]}" for k in sorted(methods))
    n_err = counts.get("erratum", 0)
    causes = W["count_cause"] if len(groups) == 1 else W["count_causes"].format(n=len(groups))
    rows = [
        f"{W['count_checked']} & {len(steps)} & \\\\",
        f"\\quad {W['count_verified']} & {counts.get('verified', 0)} & ({W['how_reached']} \\verdicthow{{{how}}}) \\\\",
        f"\\quad {W['count_errata']} & {n_err} & " + (f"({causes}, {W['section']}~\\ref{{sec:errata}})" if n_err else "") + " \\\\",
        f"\\quad {W['count_cleared']} & {counts.get('cleared', 0)} & " + (
            f"({W['section']}~\\ref{{sec:cleared}})" if counts.get("cleared") else "") + " \\\\",
        f"\\quad {W['count_inconclusive']} & {inconclusive} & \\\\",
    ]
    out = [f"\\section*{{{W['summary']}}}\n\\phantomsection\\addcontentsline{{toc}}{{section}}{{{W['summary']}}}\n",
           W["checked"].format(n=len(steps)) + "\n\n",
           "\\begin{center}\n\\begin{tabular}{@{}lrl@{}}\n\\toprule\n" + "\n".join(rows)
           + "\n\\bottomrule\n\\end{tabular}\n\\end{center}\n"]
    unexpected = [s for s in steps if s.outcome.status == "unexpected"]
    if unexpected:
        out.append(W["status"]["unexpected"] + ": " + ", ".join(f"\\ref{{e:{s.label}}}" for s in unexpected)
                   + ".\n\n")
    return "".join(out)


def _cell(latex: str, width: int = 30) -> str:
    """Printed LaTeX in a table cell: rows broken at ``width`` glyphs, shrunk to the cell."""
    return "\\fit{$\\displaystyle " + gathered(printed_rows(latex, width)) + "$}"


def _errata_table(steps: list[Step], lang: str) -> str:
    W = WORDS[lang]
    errata = [s for s in steps if s.is_erratum]
    out = [f"\\subsection*{{{W['errata_table']}}}\n"]
    if not errata:
        return "".join(out) + W["none_found"] + "\n\n"
    out.append("{\\small\n\\begin{longtable}{@{}>{\\raggedright}p{0.09\\linewidth}p{0.31\\linewidth}"
               "p{0.33\\linewidth}>{\\raggedright\\arraybackslash}p{0.18\\linewidth}@{}}\n\\toprule\n"
               f"{W['table_eq']} & {W['table_printed']} & {W['table_corrected']} & {W['table_witness']} "
               "\\\\\n\\midrule\n\\endhead\n")
    for n, st in enumerate(errata):
        w = getattr(st.outcome.verdict, "witness", None)
        wit = witness_short(w, lang, point=False)
        cert = certified_mark(w, lang)
        out.append(("\\midrule\n" if n else "")
                   + f"\\ref{{e:{st.label}}} & {_cell(st.entry.latex)} & {_cell(st.erratum.corrected_latex)} & "
                   + (f"{wit}; {cert}" if wit else cert) + " \\\\\n")
    out.append("\\bottomrule\n\\end{longtable}\n}\n")
    out.append(W["errata_more"].format() + "\n\n")
    return "".join(out)


def _causes_section(groups: list[CauseGroup], by_id: dict[str, Step], prose: TextProse, lang: str) -> str:
    W = WORDS[lang]
    out = [f"\\section{{{W['errata']}}}\\label{{sec:errata}}\n"]
    if not groups:
        return "".join(out) + W["none_found"] + "\n\n"
    for g in groups:
        out.append(f"\\subsection{{{pdf_safe(cause_title(g, prose, lang))}}}\\label{{{g.label}}}\n")
        refs = join_refs([f"\\ref{{e:{s.label}}}" for s in g.steps], lang)
        out.append(f"\\textbf{{{W['cause_affects']}:}} {refs}.  \\textbf{{{W['cause_kind']}:}} "
                   f"{kind_name(g.kind, lang)}.\n\n")
        note = cause_note(g, prose, lang)
        if note:
            out.append(note + "\n\n")
    return "".join(out)


def _cleared_section(steps: list[Step], prose: TextProse, lang: str) -> str:
    W = WORDS[lang]
    cleared = [s for s in steps if s.cleared is not None]
    out = [f"\\section{{{W['cleared_title']}}}\\label{{sec:cleared}}\n"]
    if not cleared:
        return "".join(out) + W["none_found"] + "\n\n"
    for st in cleared:
        out.append(f"\\subsection*{{{pdf_safe(entry_heading(st, prose, lang))}}}\n")
        own = prose.entry(st.entry.id).erratum.get(lang)
        if lang == "en":
            out.append(f"\\textbf{{{W['suspicion']}:}} " + with_math(clean_prose(st.cleared.suspicion)) + "\n\n")
        note = own or (with_math(clean_prose(st.cleared.note)) if lang == "en" else "")
        out.append(f"\\textbf{{{W['verdict']}:}} " + verdict_short(st, lang) + (" " + note if note else "") + "\n\n")
    return "".join(out)


def _report_entry(st: Step, by_id: dict[str, Step], groups: list[CauseGroup], prose: TextProse,
                  lang: str) -> str:
    W, e = WORDS[lang], st.entry
    out = [f"\\subsection*{{{pdf_safe(entry_heading(st, prose, lang))}}}"
           f"\\entrylabel{{e:{st.label}}}{{{escape(st.tag)}}}%\n",
           f"\\textbf{{{W['printed']}:}}\n" + printed_display(e.latex)]
    # as re-derived
    out.append(f"\\textbf{{{W['derived']}:}}")
    mode = st.derivation.mode if st.derivation else ""
    if st.derivation is None:
        out.append(" " + W["no_derivation"] + "\n\n")
    elif st.error:
        out.append(" " + W["derivation_failed"] + "\n\n")
    elif same_as_printed(st):
        out.append(" " + W["same_as_printed"] + "\n")
    else:
        rows = derived_rows(st, prose=prose)
        if rows is None:
            out.append(" " + W["same_as_printed"] + "\n\n")
        else:
            if mode == "substitute":
                out.append(" " + W["model"] + ":")
            elif mode == "condition":
                out.append(" " + W["condition"])
            out.append("\n" + display(aligned(rows)))
    if st.is_erratum:
        out.append(f"\\textbf{{{W['corrected']}:}}\n" + printed_display(st.erratum.corrected_latex))
    # the verdict, short
    v = st.outcome.verdict
    verdict = f"\\textbf{{{W['verdict']}:}} " + verdict_short(st, lang)
    dims = dimension_sentence(v.dimensions, lang)
    if dims:
        verdict += " " + dims
    if st.is_erratum:
        w = getattr(v, "witness", None)
        if w is not None and _wget(w, "quantity") != "dimensions":
            verdict += f" {W['witness']}: " + witness_short(w, lang) + " (" + certified_mark(w, lang) + ")."
        mine = [g for g in groups if st in g.steps]
        if mine:
            verdict += " " + W["cause_of"] + ": " + "; ".join(
                W["see_cause"].format(label=g.label) for g in mine) + "."
    out.append(verdict + "\n\n")
    # the step
    if st.derivation is not None:
        uses = [ref_of(by_id, u, handout=False) for u in st.derivation.uses if u in by_id]
        body = step_text(st, by_id, prose, lang, handout=False)
        src = (f"({W['uses']} " + join_refs(uses, lang) + ")") if uses and lang == "en" else ""
        out.append(f"\\textbf{{{W['step']}:}} " + body + (" " + src if src else "") + "\n\n")
    return "".join(out)


def _method_section(steps: list[Step], lang: str) -> str:
    W = WORDS[lang]
    out = [f"\\section{{{W['method']}}}\\label{{sec:method}}\n", W["method_text"] + "\n\n",
           f"\\subsection*{{{W['evidence_table']}}}\n",
           "{\\small\n\\begin{longtable}{@{}>{\\raggedright}p{0.12\\linewidth}>{\\raggedright}p{0.16\\linewidth}"
           ">{\\raggedright\\arraybackslash}p{0.66\\linewidth}@{}}\n\\toprule\n"
           f"{W['col_eq']} & {W['col_status']} & {W['col_evidence']} \\\\\n\\midrule\n\\endhead\n"]
    for st in steps:
        v = st.outcome.verdict
        ev = []
        how = "" if v.method.value == "none" else W["methods"][v.method.value]
        detail = detail_text(v.detail, lang) if v.detail else ""
        if how or detail:
            ev.append("\\verdicthow{" + how + (": " + detail if detail and how else detail) + "}")
        dims = dimension_sentence(v.dimensions, lang)
        if dims:
            ev.append(dims)
        if st.outcome.corrected_verdict is not None:
            cv = st.outcome.corrected_verdict
            chow = "" if cv.method.value == "none" else W["methods"][cv.method.value]
            ev.append(W["corrected_form"] + " " + W["verdicts"][cv.name] + (f" \\verdicthow{{{chow}}}" if chow else ""))
        out.append(f"\\ref{{e:{st.label}}} & {W['status'][st.outcome.status]} & " + "; ".join(ev) + " \\\\\n")
    out.append("\\bottomrule\n\\end{longtable}\n}\n")
    return "".join(out)


def _figure_env(fig: FigureItem, fp, lang: str) -> str:
    # the paper's own figure numbers are in the caption: no LaTeX figure counter
    if fp is not None and fp.landscape:
        return ("\\begin{landscape}\n\\centering\n"
                f"\\includegraphics[width=\\linewidth,height=0.82\\textheight,keepaspectratio]{{{fig.path}}}\n\n"
                f"\\small {caption(fig, fp, lang)}\n\\end{{landscape}}\n")
    width = "0.62\\linewidth" if fp is not None and fp.role == "text" else "0.9\\linewidth"
    return ("\\begin{figure}[htbp]\n\\centering\n"
            f"\\includegraphics[width={width},height=0.6\\textheight,keepaspectratio]{{{fig.path}}}\n\n"
            f"\\small {caption(fig, fp, lang)}\n\\end{{figure}}\n")


def _figures_section(prose: TextProse, lang: str, handout: bool) -> str:
    W = WORDS[lang]
    own = figures_for(prose, "text")
    studies = [] if handout else figures_for(prose, "study")
    if not own and not studies:
        return ""  # a text without figures has no such section
    out = [f"\\section{{{W['figures']}}}\n"]
    if own:
        if studies:
            out.append(f"\\subsection{{{W['text_figures']}}}\n")
        out.append(prose.figures_intro[lang] + "\n\n")
        out += [_figure_env(f, fp, lang) for f, fp in own]
        out.append("\\clearpage\n")
    if studies:
        out.append(f"\\subsection{{{W['studies']}}}\n{W['studies_intro']}\n\n")
        out += [_figure_env(f, fp, lang) for f, fp in studies]
        out.append("\\clearpage\n")
    return "".join(out)


# --- the handouts ------------------------------------------------------------------------------
@dataclass(frozen=True)
class Exercise:
    kind: str  # "derive" | "errata"
    step: Step


def shown_latex(st: Step) -> str:
    """What the handout shows for a step: the corrected form of an erratum, else the print."""
    return st.erratum.corrected_latex if st.is_erratum else st.entry.latex


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


def handout_tex(source: str, lang: str, steps: list[Step], prose: TextProse | None = None,
                solutions: bool = False) -> str:
    """The students' handout, or with ``solutions`` the teacher's."""
    prose = prose or prose_of(source)
    W = WORDS[lang]
    title = prose.title[lang]
    subtitle = W["teacher" if solutions else "handout"]
    by_id = {s.entry.id: s for s in steps}
    tags = {s.entry.id: (f"\\tag{{{escape(s.entry.number)}}}" if s.entry.number else f"\\tag*{{[{s.index}]}}")
            for s in steps}
    parts = [preamble(lang, title, subtitle, prose), "\\begin{document}\n", title_block(title, subtitle)]
    parts.append(prose.intro[lang] + "\n\n")
    pdf = f"{source}-report-{lang}.pdf"
    parts.append(W["verified_by"].format(report=f"\\href{{{pdf}}}{{\\nolinkurl{{{pdf}}}}}") + "\n\n")
    if solutions:
        parts.append("\\emph{" + W["teacher_note"] + "}\n\n")
    for section, group in sections_of(steps):
        parts.append(f"\\section{{{pdf_safe(section_title(prose, section, lang))}}}\n")
        intro = prose.section_intro(section, lang)
        if intro:
            parts.append(intro + "\n\n")
        for i, st in enumerate(group):
            parts.append(_handout_step(st, i, by_id, tags[st.entry.id], prose, lang))
    exercises = exercises_of(steps)
    if exercises:
        parts.append(f"\\section{{{W['exercises']}}}\n\\begin{{enumerate}}\n")
        for n, ex in enumerate(exercises, 1):
            parts.append(f"\\item\\label{{ex:{n}}} " + _exercise(ex, by_id, lang))
        parts.append("\\end{enumerate}\n")
    parts.append(_figures_section(prose, lang, handout=True))
    if exercises and solutions:
        parts.append(f"\\section{{{W['solutions']}}}\n")
        for n, ex in enumerate(exercises, 1):
            parts.append(f"\\subsection*{{{W['exercise']}~\\ref{{ex:{n}}}}}\n" + _solution(ex, by_id, prose, lang))
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


def _handout_step(st: Step, index: int, by_id: dict[str, Step], tag: str, prose: TextProse, lang: str) -> str:
    W = WORDS[lang]
    out = [_connect(st, index, by_id, lang) + "\n" + tagged_display(shown_latex(st), tag, f"h:{st.label}")]
    own = prose.entry(st.entry.id).step.get(lang)
    if own or (lang == "en" and st.derivation is not None):
        out.append((own or paragraphs(clean_prose(st.derivation.doc))) + "\n\n")
    status = st.outcome.status
    if st.is_erratum:
        out.append("\\emph{" + W["erratum"].format(kind=kind_name(st.erratum.kind, lang)) + "}\n"
                   + printed_display(st.entry.latex))
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
    return W[key].format(refs=join_refs(uses, lang), ref=ref) + "\n"


def _solution(ex: Exercise, by_id: dict[str, Step], prose: TextProse, lang: str) -> str:
    """A solution in textbook form: how the step goes, in words, and the result in the text's
    form; for an erratum, the correct form, the kind of error and its explanation."""
    W, st = WORDS[lang], ex.step
    if ex.kind == "errata":
        groups = [g for g in cause_groups([st])]
        note = cause_note(groups[0], prose, lang) if groups else ""
        return (W["sol_corrected"] + "\n" + printed_display(st.erratum.corrected_latex)
                + W["sol_kind"].format(kind=kind_name(st.erratum.kind, lang)) + (" " + note if note else "") + "\n\n")
    uses = [ref_of(by_id, u, handout=True) for u in st.derivation.uses if u in by_id]
    how = step_text(st, by_id, prose, lang, handout=True)
    lead = W["sol_derive"].format(refs=join_refs(uses, lang)) if uses else W["sol_derive_none"]
    return how + "\n\n" + lead + "\n" + printed_display(shown_latex(st))


# --- generating and writing ------------------------------------------------------------------
def file_names(kinds=KINDS, langs=LANGS) -> list[str]:
    """The .tex files that :func:`generate` writes for these kinds and languages."""
    return [f"{t.id}-{kind}-{lang}.tex" for kind in kinds for lang in langs for t in texts.active()]


def outcomes_for_all(progress=None) -> dict[str, Outcome]:
    """Verdicts of every catalog entry (read from the verification cache when it is warm);
    ``progress`` is passed to :func:`quasicentral.engine.run.run`."""
    from quasicentral.engine import run as verify
    from quasicentral.engine.checker import Options

    entries = texts.entries(texts.active())
    return dict(zip([e.id for e in entries], verify.run(entries, Options(), use_cache=True, progress=progress)))


def build(kind: str, source: str, lang: str, steps: list[Step]) -> str:
    """The LaTeX of one document of a text, in the text's notation (its text.toml)."""
    prose = prose_of(source)
    with using(Notation.of(texts.get(source).symbols, prose.symbols, prose.functions)):
        if kind == "report":
            return report_tex(source, lang, steps, prose)
        return handout_tex(source, lang, steps, prose, solutions=(kind == "teacher"))


def generate(kinds=("report",), langs=("en",), outcomes: dict[str, Outcome] | None = None) -> dict[str, str]:
    """File name → LaTeX source of every document asked for, plus ``versions.tex``."""
    outcomes = outcomes if outcomes is not None else outcomes_for_all()
    docs: dict[str, str] = {}
    for source in [t.id for t in texts.active()]:
        steps = steps_of(source, outcomes)
        for kind in kinds:
            for lang in langs:
                docs[f"{source}-{kind}-{lang}.tex"] = build(kind, source, lang, steps)
    if "report" in kinds:
        docs[VERSIONS_FILE] = versions_tex()
    return {name: docs[name] for name in sorted(docs)}


def figures_needed(docs: dict[str, str]) -> list[FigureItem]:
    """The figures the documents include, in the order of the texts' figures."""
    return [f for f in figure_items() if any(f"{{{f.path}}}" in tex for tex in docs.values())]


def check_writable(out: Path) -> None:
    """Raise OSError when ``out`` cannot be created or written to (before anything is written);
    a symbolic link where a file or folder would be written is refused (files.UnsafePath)."""
    files.check_writable(out)


def write(out: Path, docs: dict[str, str], progress=None) -> list[Path]:
    """Write the documents and the figures they include (each via a temporary file and a rename,
    so that a failure never leaves a half-written file; only inside ``out``, never through a
    symbolic link).  ``progress`` (a :class:`quasicentral.progress.Progress` callback) is told
    of each figure drawn.  Returns the paths, sorted."""
    from quasicentral.progress import notify

    check_writable(out)
    written = []

    def put(path: Path, fill) -> None:
        write_atomic(path, fill)
        written.append(path)

    for name, tex in docs.items():
        put(files.inside(out, name), lambda tmp, tex=tex: tmp.write_text(tex, encoding="utf-8"))
    figs = figures_needed(docs)
    if figs:
        files.ensure_dir(files.inside(out, FIGURE_DIR))
    notify(progress, 0, len(figs), "", 0, "figures")
    for i, f in enumerate(figs):
        put(files.inside(out, f.path), lambda tmp, f=f: figures_mod.draw(f.make(), tmp))
        notify(progress, i + 1, len(figs), f.path, 0, "figures")
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
    for suffix in (".pdf", ".log") + AUX_SUFFIXES:  # LaTeX would write through a link
        files.inside(out, stem + suffix)
    log = out / f"{stem}.log"
    env = {**os.environ, "SOURCE_DATE_EPOCH": "0", "FORCE_SOURCE_DATE": "1"}
    cmd = ["latexmk", "-norc", "-pdf", "-interaction=nonstopmode", "-halt-on-error", "-file-line-error",
           "-silent", name]
    for _attempt in (1, 2):
        try:
            proc = subprocess.run(cmd, cwd=out, capture_output=True, text=True, env=env, timeout=600)
        except FileNotFoundError:
            raise LatexError("latexmk is not installed (run ./setup.sh)", log) from None
        except subprocess.TimeoutExpired:
            clean_job(out, stem)
            raise LatexError(f"LaTeX did not finish within 600 s: see {log}", log) from None
        problems = log_problems(log.read_text(encoding="utf-8", errors="replace")) if log.is_file() else []
        if proc.returncode == 0 and not problems:
            break
        # a stale or broken .aux (or latexmk's database) from an earlier run makes every later
        # run fail: remove this job's auxiliary files (the log is kept) and try once from scratch
        clean_job(out, stem)
    if proc.returncode != 0 or problems:
        first = problems[0] if problems else f"latexmk exited with {proc.returncode}"
        raise LatexError(f"LaTeX failed on {name} ({first[:160]}): see {log}", log)
    return out / f"{stem}.pdf"


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
