"""The teaching handouts of a text: the derivation told to a student in the text's order, with
exercises; the teacher's edition adds the solutions.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

from quasicentral.documents.blocks import paragraphs, pdf_safe, preamble, printed_display, ref_of, tagged_display, \
    title_block
from quasicentral.documents.derivation_report import figures_section
from quasicentral.documents.prosetex import clean_prose, escape
from quasicentral.documents.prose import WORDS, TextProse, join_refs
from quasicentral.documents.steps import (Step, TextRecords, cause_groups, cause_note, kind_name, section_title,
                                          sections_of, step_text)
from quasicentral.engine.verdict import Status


class ExerciseKind(Enum):
    DERIVE = "derive"  # derive an equation from the ones it rests on
    ERRATUM = "erratum"  # find the misprint


@dataclass(frozen=True)
class Exercise:
    kind: ExerciseKind
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
        cand = [s for s in group if s.entry.number and s.derivation is not None and s.uses
                and not s.error and s.outcome.status in (Status.VERIFIED, Status.CLEARED)]
        if len(cand) > per:
            cand = [cand[round(i * (len(cand) - 1) / (per - 1))] for i in range(per)]
        out += [Exercise(ExerciseKind.DERIVE, s) for s in cand]
        out += [Exercise(ExerciseKind.ERRATUM, s) for s in group if s.outcome.status is Status.ERRATUM][:2]
    return out


def handout_tex(rec: TextRecords, lang: str, solutions: bool = False) -> str:
    """The students' handout, or with ``solutions`` the teacher's."""
    prose, steps, text, source = rec.prose, list(rec.steps), rec.text, rec.id
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
        parts.append(f"\\section{{{pdf_safe(section_title(text, prose, section, lang))}}}\n")
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
    parts.append(figures_section(text, prose, lang, handout=True))
    if exercises and solutions:
        parts.append(f"\\section{{{W['solutions']}}}\n")
        for n, ex in enumerate(exercises, 1):
            parts.append(f"\\subsection*{{{W['exercise']}~\\ref{{ex:{n}}}}}\n" + _solution(ex, by_id, prose, lang))
    parts.append("\\end{document}\n")
    return "".join(parts)


def _connect(st: Step, index: int, by_id: dict[str, Step], lang: str) -> str:
    """The sentence that leads to a step: where it starts from (varied, deterministically)."""
    W = WORDS[lang]
    uses = [u for u in st.uses if u in by_id]
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
    elif status is Status.CLEARED:
        out.append("\\emph{" + W["cleared"] + "}\n\n")
    elif status is Status.UNEXPECTED:
        out.append("\\emph{" + W["unverified"] + "}\n\n")
    return "".join(out)


def _exercise(ex: Exercise, by_id: dict[str, Step], lang: str) -> str:
    W, st = WORDS[lang], ex.step
    if ex.kind is ExerciseKind.ERRATUM:
        return W["ex_errata"].format(ref=ref_of(by_id, st.entry.id, handout=True)) + "\n" + printed_display(st.entry.latex)
    uses = [ref_of(by_id, u, handout=True) for u in st.uses if u in by_id]
    ref = ref_of(by_id, st.entry.id, handout=True)
    key = "ex_derive_none" if not uses else ("ex_derive_one" if len(uses) == 1 else "ex_derive")
    return W[key].format(refs=join_refs(uses, lang), ref=ref) + "\n"


def _solution(ex: Exercise, by_id: dict[str, Step], prose: TextProse, lang: str) -> str:
    """A solution in textbook form: how the step goes, in words, and the result in the text's
    form; for an erratum, the correct form, the kind of error and its explanation."""
    W, st = WORDS[lang], ex.step
    if ex.kind is ExerciseKind.ERRATUM:
        groups = [g for g in cause_groups([st])]
        note = cause_note(groups[0], prose, lang) if groups else ""
        return (W["sol_corrected"] + "\n" + printed_display(st.erratum.corrected_latex)
                + W["sol_kind"].format(kind=kind_name(st.erratum.kind, lang)) + (" " + note if note else "") + "\n\n")
    uses = [ref_of(by_id, u, handout=True) for u in st.uses if u in by_id]
    how = step_text(st, by_id, prose, lang, handout=True)
    lead = W["sol_derive"].format(refs=join_refs(uses, lang)) if uses else W["sol_derive_none"]
    return how + "\n\n" + lead + "\n" + printed_display(shown_latex(st))


