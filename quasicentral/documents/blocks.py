"""LaTeX building blocks of the documents: the preamble, displays, numbers, witnesses, and the
engine's reasons rendered per language (from the wording table, typed: no sentence is parsed).
"""

from __future__ import annotations

from types import MappingProxyType
import re
import sys

import sympy as sp

from quasicentral.documents.breaking import display_rows, relation_lines, visible_width, wrap_row
from quasicentral.documents.latex import names_as_printed, notation, paper_latex, parameter_latex, parameter_unit
from quasicentral.documents.prosetex import MATH_CHARS, escape, text
from quasicentral.documents.prose import WORDS, TextProse
from quasicentral.documents.steps import Step, paragraphs, ref_of  # noqa: F401 - re-exported
from quasicentral.engine.reasons import Code
from quasicentral.engine.registry import Mode, as_list
from quasicentral.engine.verdict import Method, Status
from quasicentral.engine.wording import render
from quasicentral.notation import transcription
from quasicentral.notation.units import DIM_I, DIM_J, DIM_L, DIM_M, DIM_N, DIM_T, DIM_THETA, UnitError, parse_dim

VERSIONS_FILE = "versions.tex"
#: The packages whose versions a report states (distribution name, import name).
PACKAGES = (("sympy", "sympy"), ("mpmath", "mpmath"), ("numpy", "numpy"), ("scipy", "scipy"),
            ("python-flint", "flint"), ("matplotlib", "matplotlib"))
#: pdflang of each language.
PDFLANG = MappingProxyType({"en": "en-GB", "cs": "cs-CZ"})


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
\usepackage{needspace}
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

_PLAIN_MATH = MappingProxyType({v.strip(): k for k, v in MATH_CHARS.items() if v.startswith("\\") and len(k) == 1}
                               | {r"\varrho": "ϱ", r"\varphi": "φ", r"\to": "→", r"\sqrt": "√", r"\dot": "", r"\ldots": "…"})
_SUP = str.maketrans("0123456789+-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻")
_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def plain(tex: str) -> str:
    """LaTeX prose as plain Unicode text (PDF metadata and bookmarks): R~$R_0\\kappa^2$ → R R₀κ²."""
    s = tex.replace("~", " ").replace("---", "—").replace("--", "–").replace(r"\,", " ")
    s = re.sub(r"\^\{?([0-9+-]+)\}?", lambda m: m.group(1).translate(_SUP), s)
    s = re.sub(r"_\{?([0-9]+)\}?", lambda m: m.group(1).translate(_SUB), s)
    s = re.sub(r"\\[A-Za-z]+", lambda m: _PLAIN_MATH.get(m.group(0), ""), s)
    s = s.replace("$", "").replace("{", "").replace("}", "").replace("\\", "")
    s = "".join(ch for ch in s if ch.isprintable())
    # what TeX would still read as markup in a PDF string: escaped
    return " ".join(s.split()).replace("%", r"\%").replace("#", r"\#").replace("&", r"\&")


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


def _memo(kind: str, st: Step, make):
    """Per entry: the same answer for every document of a text (kept on the step)."""
    if kind not in st.memo:
        st.memo[kind] = make()
    return st.memo[kind]


def same_as_printed(st: Step) -> bool:
    """Is the re-derived result the printed relation itself (rearranged at most)?"""
    return _memo("same", st, lambda: _same_as_printed(st))


def _same_as_printed(st: Step) -> bool:
    if st.result is None or st.is_erratum or (st.derivation and st.derivation.mode not in (Mode.SOLVE, Mode.EXPRESSION)):
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
    res, mode = step.result, step.mode
    if res is None:
        return None
    current = notation()
    names = names_as_printed(step.entry.latex, {**current.names, **(prose.symbols if prose else {})})
    # a function (ϱ(t), φ(t)) in the form of its letter that the display prints
    functions = names_as_printed(step.entry.latex, {**current.functions, **(prose.functions if prose else {})})
    if mode is Mode.SUBSTITUTE or isinstance(res, dict):
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


def number(value: str, lang: str, digits: int = 4) -> str:
    """A decimal in a few significant digits, with the decimal comma in Czech (math mode)."""
    from quasicentral.notation.symbols import FUNCTIONS

    if str(value).strip() in ("inf", "-inf"):  # a limit without bound (the witness's own spelling)
        return "-\\infty" if str(value).strip() == "-inf" else "\\infty"
    try:
        x = float(sp.N(transcription.parse(str(value), dict(FUNCTIONS)), 20))
    except (transcription.TranscriptionError, TypeError, ValueError):
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
    value, in as many digits as it takes to tell them apart."""
    W = WORDS[lang]
    if w is None:
        return ""
    q = getattr(w, "quantity", None) if not isinstance(w, dict) else w.get("quantity")
    code = _wget(w, "quantity_code") if isinstance(w, dict) else getattr(getattr(q, "code", None), "value", "")
    if code == Code.Q_DIMENSIONS.value:
        return W["dims_bad"] + "."
    params = (_wget(w, "parameters") or {}) if point else {}
    pts = ", ".join(f"${parameter_latex(k)} = {number(v, lang)}{parameter_unit(k)}$" for k, v in sorted(params.items()))
    printed, corrected = str(_wget(w, "printed")), str(_wget(w, "corrected"))
    digits = 4  # a few digits — as many more as it takes to tell the two values apart (a rounding)
    while digits < 15 and number(printed, lang, digits) == number(corrected, lang, digits):
        digits += 1
    # an identity's witness holds its two sides, not a printed and a correct value
    sides = code == Code.Q_SIDES.value
    ratio = code == Code.Q_ORDER_RATIO.value  # an O-term's ratio at two steps of its passage
    vals = W["vs_ratio" if ratio else "vs_sides" if sides else "vs"].format(p=f"${number(printed, lang, digits)}$",
                                                   c=f"${number(corrected, lang, digits)}$")
    return (f"{W['at']} {pts}: " if pts else "") + vals


def certified_mark(w, lang: str) -> str:
    W = WORDS[lang]
    if w is None:
        return ""
    # not in \verdicthow: whether a witness is certified does not depend on the machine
    # (its balls are bounded by counted evaluations, not time)
    return W["certified_yes"] if _wget(w, "certified") else W["certified_no"]


def detail_text(reason, lang: str) -> str:
    """The checker's reason for a verdict in the document's language (the wording table)."""
    return text(render(reason, lang), lang=lang) if reason is not None else ""


_DIM_NAMES = MappingProxyType({DIM_L: r"\mathsf{L}", DIM_T: r"\mathsf{T}", DIM_M: r"\mathsf{M}", DIM_THETA: r"\Theta",
              DIM_I: r"\mathsf{I}", DIM_N: r"\mathsf{N}", DIM_J: r"\mathsf{J}"})


def dim_latex(d: str, inline: bool = False) -> str:
    """A dimension as the engine writes it ('L^2/T') in sans-serif base letters (``inline``: a
    quotient with a slash, for a table's line)."""
    try:
        expr = parse_dim(d)
    except UnitError:
        return r"\text{" + escape(d) + "}"
    return "1" if expr == 1 else sp.latex(expr, mul_symbol="dot", symbol_names=_DIM_NAMES, fold_short_frac=inline)


def expr_latex(s: str) -> str:
    """An expression of a checker's reason (sympy syntax, the text's names) in the notation, read
    by the safe reader ('' where it cannot be read)."""
    current = notation()
    ns = {n: sp.Symbol(n) for n in current.names}
    heads = {n: sp.Function(n) for n in current.functions}
    try:
        from quasicentral.notation.symbols import FUNCTIONS

        return paper_latex(transcription.parse(s, {**FUNCTIONS, **ns, **heads}, calls=heads))
    except (transcription.TranscriptionError, TypeError, ValueError, AttributeError):
        return ""


def _inline(tex: str) -> str:
    """Mathematics inside a sentence; a long formula gets a line of its own."""
    if visible_width(tex) <= 24:
        return f"${tex}$"
    return "\n\\begin{center}\\fit{$\\displaystyle " + tex + "$}\\end{center}\n"



def dimension_sentence(findings, lang: str) -> str:
    """The dimension findings of a verdict as a sentence in the document's language ('' when
    its relations are consistent)."""
    W = WORDS[lang]
    bad = [c.problem for c in findings if c.inconsistent]
    if not bad:
        return ""
    p = bad[0]
    if p.code is Code.DIM_ADDS and expr_latex(p["term"]):
        return (W["dims_bad"] + ": " + W["dims_add"].format(
            term=_inline(expr_latex(p["term"])), a=f"${dim_latex(p['other'])}$", b=f"${dim_latex(p['first'])}$")
            + ".")
    if p.code is Code.DIM_ARGUMENT and p["function"] == "exp" and expr_latex(p["argument"]):
        return W["dims_bad"] + ": " + W["dims_exp"].format(arg=_inline(expr_latex(p["argument"])),
                                                           a=f"${dim_latex(p['dimension'])}$") + "."
    if p.code is Code.DIM_LIMIT:
        return W["dims_bad"] + ": " + W["dims_limit"].format(
            lim=f"${expr_latex(p['limit']) or escape(p['limit'])}$", a=f"${dim_latex(p['dimension'])}$",
            b=f"${dim_latex(p['variable_dimension'])}$") + "."
    return W["dims_bad"] + "."


def verdict_short(st: Step, lang: str) -> str:
    """One short verdict: 'verified symbolically.', 'refuted (erratum, see …).'"""
    W, o = WORDS[lang], st.outcome
    v = o.verdict
    if o.status is Status.NOTATION:  # notation, nothing to check: no verdict to qualify
        return W["status"]["notation"] + "."
    how = "" if v.method is Method.NONE else W["methods"][v.method.value]
    out = W["verdicts"][v.name] + (f" \\verdicthow{{{how}}}" if how else "")
    if o.status is Status.CLEARED:
        out += " (" + W["status"]["cleared"] + ")"
    elif o.status is Status.UNEXPECTED:
        out += " (" + W["status"][o.status.value] + ")"
    return out + "."
