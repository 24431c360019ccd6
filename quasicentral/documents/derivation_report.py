"""The derivation report of a text: page 1 says what was checked and what was found; then the
causes of the errata, the cleared suspects, every equation as printed and re-derived with its
verdict and step, the figures, and the method with the evidence for each equation.
"""

from __future__ import annotations

from quasicentral.documents.blocks import (VERSIONS_FILE, aligned, certified_mark, derived_rows, detail_text,
                                           dim_latex, dimension_sentence, display, gathered, pdf_safe, preamble, printed_display,
                                           printed_rows, ref_of, same_as_printed, title_block, verdict_short,
                                           witness_short)
from quasicentral.documents.latex import paper_latex
from quasicentral.documents.prosetex import clean_prose, escape, with_math
from quasicentral.documents.prose import WORDS, TextProse, join_refs
from quasicentral.documents.steps import (CauseGroup, FigureItem, Step, TextRecords, caption, cause_groups, cause_note,
                                          cite, citing, cleared_note,
                                          cause_title, entry_heading, erratum_note, figures_for, kind_name,
                                          section_title, sections_of, step_text)
from quasicentral.engine.registry import Mode
from quasicentral.engine.verdict import Method, Status
from quasicentral.notation.units import dim_text, unit_latex


def report_tex(rec: TextRecords, lang: str) -> str:
    prose, steps, text = rec.prose, list(rec.steps), rec.text
    W = WORDS[lang]
    title = prose.title[lang]
    by_id = {s.entry.id: s for s in steps}
    groups = cause_groups(steps)
    parts = [preamble(lang, title, W["report"], prose), "\\begin{document}\n",
             title_block(title, W["report"])]
    parts.append(_summary(steps, groups, prose, lang))
    parts.append(_found_table(groups, prose, lang))
    parts.append(_numbering(steps, lang))
    parts.append("\\clearpage\n\\tableofcontents\n\n")
    parts.append(_causes_section(groups, by_id, prose, lang))
    parts.append(_cleared_section(steps, prose, lang))
    for section, group in sections_of(steps):
        parts.append(f"\\section{{{pdf_safe(section_title(text, prose, section, lang))}}}\n")
        if section == sections_of(steps)[0][0]:
            identity = all(st.mode is Mode.IDENTITY for st in steps)
            parts.append(W["report_intro_identity" if identity else "report_intro"] + "\n\n")
        for st in group:
            parts.append(_report_entry(st, by_id, groups, prose, lang))
    parts.append(figures_section(text, prose, lang))
    parts.append("\\appendix\n")
    parts.append(_notation_section(text, steps, lang))
    parts.append(_method_section(steps, lang))
    parts.append(_errata_table(steps, lang))
    parts.append(software_note(text, prose, lang))
    parts.append(f"\\section{{{W['versions']}}}\n\\input{{{VERSIONS_FILE[:-4]}}}\n")
    parts.append("\\end{document}\n")
    return "".join(parts)


def _summary(steps: list[Step], groups: list[CauseGroup], prose: TextProse, lang: str) -> str:
    W = WORDS[lang]
    counts: dict[str, int] = {}
    methods: dict[str, int] = {}
    for s in steps:
        counts[s.outcome.status.value] = counts.get(s.outcome.status.value, 0) + 1
        if s.outcome.status is Status.VERIFIED:
            m = s.outcome.verdict.method.value
            methods[m] = methods.get(m, 0) + 1
    inconclusive = counts.get("unexpected", 0)
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
    if counts.get("notation"):  # the rows add up to the entries checked
        rows.append(f"\\quad {W['count_notation']} & {counts['notation']} & \\\\")
    story = [p for p in (prose.abstract.get(lang) or prose.intro.get(lang, ""),
                         prose.source.get(lang) or W["source_generic"]) if p]
    out = [f"\\section*{{{W['summary']}}}\n\\phantomsection\\addcontentsline{{toc}}{{section}}{{{W['summary']}}}\n",
           "".join(p + "\n\\medskip\n\n" for p in story),
           W[_checked_key(steps)].format(n=len(steps))
           + "\n\n",
           "\\begin{center}\n\\begin{tabular}{@{}lr>{\\raggedright\\arraybackslash}p{0.34\\linewidth}@{}}\n\\toprule\n" + "\n".join(rows)
           + "\n\\bottomrule\n\\end{tabular}\n\\end{center}\n"]
    unexpected = [s for s in steps if s.outcome.status is Status.UNEXPECTED]
    if unexpected:
        out.append(W["status"]["unexpected"] + ": " + ", ".join(f"\\ref{{e:{s.label}}}" for s in unexpected)
                   + ".\n\n")
    return "".join(out)


def _checked_key(steps: list[Step]) -> str:
    """How page 1 says the entries were checked: all re-derived, all as printed, or both."""
    identities = sum(s.mode is Mode.IDENTITY for s in steps)
    return "checked_identity" if identities == len(steps) else "checked_mixed" if identities else "checked"


def _cell(latex: str, width: int = 30) -> str:
    """Printed LaTeX in a table cell: rows broken at ``width`` glyphs, shrunk to the cell."""
    return "\\fit{$\\displaystyle " + gathered(printed_rows(latex, width)) + "$}"


def _found_table(groups: list[CauseGroup], prose: TextProse, lang: str) -> str:
    """Page 1's table: one row per cause (as ``errata --json`` lists them), its kind, the
    displays it reaches and one witness in a few digits."""
    W = WORDS[lang]
    out = [f"\\subsection*{{{W['found_title']}}}\n"]
    if not groups:
        return "".join(out) + W["none_found"] + "\n\n"
    out.append("{\\small\n\\begin{longtable}{@{}>{\\raggedright}p{0.36\\linewidth}>{\\raggedright}p{0.15\\linewidth}"
               ">{\\raggedright}p{0.17\\linewidth}>{\\raggedright\\arraybackslash}p{0.24\\linewidth}@{}}\n\\toprule\n"
               f"{W['col_cause']} & {W['col_kind']} & {W['col_displays']} & {W['table_witness']} "
               "\\\\\n\\midrule\n\\endhead\n")
    for g in groups:
        title = cause_title(g, prose, lang)
        refs = join_refs([f"\\ref{{e:{s.label}}}" for s in g.steps], lang)
        shown = next(((s, s.outcome.verdict.witness) for s in g.steps
                      if getattr(s.outcome.verdict, "witness", None) is not None), None)
        wit = ""
        if shown is not None:
            wit = W["witness_in"].format(ref=f"\\ref{{e:{shown[0].label}}}",
                                         values=witness_short(shown[1], lang, point=False))
        out.append(f"{title} (\\S\\,\\ref{{{g.label}}}) & {kind_name(g.kind, lang)} & {refs} & {wit} \\\\\n")
    out.append("\\bottomrule\n\\end{longtable}\n}\n")
    out.append(W["found_more"].format() + "\n\n")
    return "".join(out)


def _numbering(steps: list[Step], lang: str) -> str:
    """How the report names the displays, explained once with an example of each kind (a text
    that numbers every display needs no word on it)."""
    numbered = next((s.tag for s in steps if s.entry.number), None)
    unnumbered = next((s.tag for s in steps if not s.entry.number), None)
    if numbered is None or unnumbered is None:
        return ""
    return WORDS[lang]["numbering"].format(numbered=numbered, unnumbered=unnumbered) + "\n\n"


def _errata_table(steps: list[Step], lang: str) -> str:
    W = WORDS[lang]
    errata = [s for s in steps if s.is_erratum]
    # a heading with at least its table's first rows below it, never alone at the foot of a page
    out = [f"\\needspace{{10\\baselineskip}}\\section{{{W['errata_table']}}}\\label{{sec:sidebyside}}\n"]
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


def software_note(text, prose: TextProse, lang: str) -> str:
    """The toolkit's measurements (work–precision charts, timings) as an appendix of their own,
    marked as being about the software, not the text."""
    W = WORDS[lang]
    studies = figures_for(text, prose, "study")
    if not studies:
        return ""
    return (f"\\clearpage\n\\section{{{W['software_note']}}}\\label{{sec:software}}\n{W['software_note_intro']}  "
            f"{W['studies_intro']}\n\n" + "".join(_figure_env(f, fp, lang) for f, fp in studies) + "\\clearpage\n")


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
        note = cause_note(g, prose, lang, citing(by_id.values()))
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
        suspicion = st.cleared.suspicion_in(lang)
        if suspicion:
            out.append(f"\\textbf{{{W['suspicion']}:}} " + with_math(cite(clean_prose(suspicion), citing(steps)), lang=lang)
                       + "\n\n")
        tags = citing(steps)
        note = cleared_note(st, lang, tags) if st.is_erratum else erratum_note(st, prose, lang, tags)
        if st.is_erratum:  # the suspicion is unfounded, and the display wrong for another reason
            verdict = W["cleared_yet_erratum"].format(ref=f"\\ref{{e:{st.label}}}")
        else:
            verdict = verdict_short(st, lang)
        out.append(f"\\textbf{{{W['verdict']}:}} " + verdict + (" " + note if note else "") + "\n\n")
    return "".join(out)


def _report_entry(st: Step, by_id: dict[str, Step], groups: list[CauseGroup], prose: TextProse,
                  lang: str) -> str:
    W, e = WORDS[lang], st.entry
    out = [f"\\subsection*{{{pdf_safe(entry_heading(st, prose, lang))}}}"
           f"\\entrylabel{{e:{st.label}}}{{{escape(st.tag)}}}%\n",
           f"\\textbf{{{W['printed']}:}}\n" + printed_display(e.latex)]
    # as re-derived: an identity is checked as printed (the summary says so), nothing to show
    mode = st.mode
    if mode is not Mode.IDENTITY:
        out.append(f"\\textbf{{{W['derived']}:}}")
    if mode is Mode.IDENTITY:
        pass
    elif st.derivation is None:
        out.append(" " + W["no_derivation"] + "\n\n")
    elif st.error:
        out.append(" " + W["derivation_failed"] + "\n\n")
    elif same_as_printed(st):
        out.append(" " + W["same_as_printed"] + "\n\n")
    else:
        rows = derived_rows(st, prose=prose)
        if rows is None and mode is Mode.SUBSTITUTE and st.result == {}:
            out.append(" " + W["as_it_stands"] + "\n\n")
        elif rows is None:
            out.append(" " + W["same_as_printed"] + "\n\n")
        else:
            if mode is Mode.SUBSTITUTE:
                out.append(" " + W["model"] + ":")
            elif mode is Mode.CONDITION:
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
        if w is not None:
            verdict += f" {W['witness']}: " + witness_short(w, lang) + " (" + certified_mark(w, lang) + ")."
        mine = [g for g in groups if st in g.steps]
        if mine:
            verdict += " " + W["cause_of"] + ": " + "; ".join(
                W["see_cause"].format(label=g.label) for g in mine) + "."
    out.append(verdict + "\n\n")
    if st.is_erratum and any(g.recorded for g in groups if st in g.steps):
        note = erratum_note(st, prose, lang, citing(by_id.values()))  # its own words (the cause's are in its section)
        if note:
            out.append(note + "\n\n")
    # the step: an identity's only where it rests on other entries or the text says more
    plain_identity = (mode is Mode.IDENTITY and not [u for u in st.uses if u in by_id]
                      and not prose.entry(st.entry.id).step.get(lang))
    if st.derivation is not None and not plain_identity:
        uses = [ref_of(by_id, u, handout=False) for u in st.uses if u in by_id]
        body = step_text(st, by_id, prose, lang, handout=False)
        src = (f"({W['uses']} " + join_refs(uses, lang) + ")") if uses else ""
        out.append(f"\\textbf{{{W['step']}:}} " + body + (" " + src if src else "") + "\n\n")
    return "".join(out)


def _sentences(parts: list[str]) -> str:
    """The pieces of evidence as sentences, each ended by one full stop (a detail that ends in
    its own — "do not match." — gets no second one, and no semicolon runs on into the next)."""
    out = []
    for p in parts:
        p = p.rstrip()
        closed = p.endswith(".") or p.endswith(".}")
        out.append(p if closed else p + ".")
    return " ".join(out)


#: the notation's elliptic functions in Jacobi's form with the modulus k, as a transcription
#: writes them: their convention is stated under the notation table of a text that uses one
_ELLIPTIC = ("Fj(", "Ej(", "Kc(", "Ec(")


def _notation_section(text, steps: list[Step], lang: str) -> str:
    """The text's symbols as it writes them: what each stands for (in the document's language,
    where the text says), its dimension or units, and where the checker draws it from (its
    range) or what defines it; the elliptic convention where the text uses elliptic functions."""
    W = WORDS[lang]
    rows = []
    for spec in text.symbols.specs:
        sym = paper_latex(spec.obj)
        unit = unit_latex(spec.units)
        dim = f"${unit}$" if unit else (f"${dim_latex(dim_text(spec.dimension), inline=True)}$"
                                        if spec.dimension is not None else "")
        if spec.definition is not None:
            where = f"${sym} = {paper_latex(spec.definition, fold_short_frac=True)}$"
        elif spec.range is not None:
            lo, hi = (paper_latex(e, fold_short_frac=True) for e in spec.range)
            where = f"$[{lo},\\ {hi}]$"
        else:
            where = ""
        meaning = with_math(clean_prose(spec.meaning_in(lang)), lang=lang)
        rows.append(f"${sym}$ & {meaning} & {dim} & {where} \\\\")
    out = [f"\\section{{{W['notation_title']}}}\\label{{sec:notation}}\n", W["notation_text"] + "\n\n",
           "{\\small\n\\begin{longtable}{@{}>{\\raggedright}p{0.12\\linewidth}>{\\raggedright}p{0.38\\linewidth}"
           ">{\\raggedright}p{0.12\\linewidth}>{\\raggedright\\arraybackslash}p{0.24\\linewidth}@{}}\n\\toprule\n"
           f"{W['notation_symbol']} & {W['notation_meaning']} & {W['notation_dimension']} & {W['notation_where']}"
           " \\\\\n\\midrule\n\\endhead\n", "\n".join(rows), "\n\\bottomrule\n\\end{longtable}\n}\n"]
    if any(any(f in st.entry.printed_text for f in _ELLIPTIC) for st in steps):
        out.append(W["notation_elliptic"] + "\n\n")
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
        how = "" if v.method is Method.NONE else W["methods"][v.method.value]
        detail = detail_text(v.reason, lang)
        if how or detail:
            ev.append("\\verdicthow{" + how + (": " + detail if detail and how else detail) + "}")
        dims = dimension_sentence(v.dimensions, lang)
        if dims:
            ev.append(dims)
        if st.outcome.corrected_verdict is not None:
            cv = st.outcome.corrected_verdict
            chow = "" if cv.method is Method.NONE else W["methods"][cv.method.value]
            ev.append(W["corrected_form"] + " " + W["verdicts"][cv.name] + (f" \\verdicthow{{{chow}}}" if chow else ""))
        out.append(f"\\ref{{e:{st.label}}} & {W['status'][st.outcome.status.value]} & " + _sentences(ev) + " \\\\\n")
    out.append("\\bottomrule\n\\end{longtable}\n}\n")
    return "".join(out)


def _figure_env(fig: FigureItem, fp, lang: str) -> str:
    fig = fig.in_lang(lang)
    # the paper's own figure numbers are in the caption: no LaTeX figure counter
    if fp is not None and fp.landscape:
        return ("\\begin{landscape}\n\\centering\n"
                f"\\includegraphics[width=\\linewidth,height=0.82\\textheight,keepaspectratio]{{{fig.path}}}\n\n"
                f"\\small {caption(fig, fp, lang)}\n\\end{{landscape}}\n")
    width = "0.62\\linewidth" if fp is not None and fp.role == "text" else "0.9\\linewidth"
    return ("\\begin{figure}[htbp]\n\\centering\n"
            f"\\includegraphics[width={width},height=0.6\\textheight,keepaspectratio]{{{fig.path}}}\n\n"
            f"\\small {caption(fig, fp, lang)}\n\\end{{figure}}\n")


def figures_section(text, prose: TextProse, lang: str) -> str:
    """The figures of the text (the toolkit's charts are the software note's)."""
    W = WORDS[lang]
    own = figures_for(text, prose, "text")
    if not own:
        return ""  # a text without figures has no such section
    return (f"\\section{{{W['figures']}}}\n{prose.figures_intro[lang]}\n\n"
            + "".join(_figure_env(f, fp, lang) for f, fp in own) + "\\clearpage\n")
