"""The teaching handouts of a text: the derivation told to a student in the text's order, with
exercises; the teacher's edition adds the solutions.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from quasicentral.documents.blocks import number, paragraphs, pdf_safe, preamble, printed_display, ref_of, \
    tagged_display, title_block
from quasicentral.documents.derivation_report import figures_section
from quasicentral.documents.latex import paper_latex
from quasicentral.documents.prosetex import clean_prose, escape, with_math
from quasicentral.documents.prose import WORDS, TextProse, join_refs
from quasicentral.documents.steps import (Step, TextRecords, cause_groups, cause_note, cite, citing, kind_name,
                                          section_title, sections_of, step_text)
from quasicentral.engine.exercises import REF, ExerciseKind, ExerciseSpec
from quasicentral.engine.registry import Mode
from quasicentral.engine.verdict import Status


@dataclass(frozen=True)
class Exercise:
    """An exercise as the handout sets it: of the text's bank (``spec``, with its checked
    ``answer``) or, for a text without one, chosen from its steps."""

    kind: ExerciseKind
    step: Step
    spec: ExerciseSpec | None = None
    answer: str = ""

    @property
    def level(self) -> int:
        return self.spec.level if self.spec is not None else 1


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
        out += [Exercise(ExerciseKind.MISPRINT, s) for s in group if s.outcome.status is Status.ERRATUM][:2]
    return out


def exercises_for(rec: TextRecords) -> list[Exercise]:
    """The text's own bank where it has one (graded, checked by the engine), else exercises
    chosen from its steps."""
    if not rec.exercises:
        return exercises_of(list(rec.steps))
    by_id = {s.entry.id: s for s in rec.steps}
    return [Exercise(ex.spec.kind, by_id[ex.spec.entry], ex.spec, ex.answer) for ex in rec.exercises]


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
    # in the students' edition an erratum set as an exercise is shown as printed, its correction
    # left to them (the teacher's edition corrects it in place)
    exercises = exercises_for(rec)
    hidden = {} if solutions else _hidden(exercises, steps)
    # nor does it say how a display it asks the students to derive follows
    asked = {} if solutions else {ex.step.entry.id: n for n, ex in enumerate(exercises, 1)
                                  if ex.kind is ExerciseKind.DERIVE}
    for section, group in sections_of(steps):
        parts.append(f"\\section{{{pdf_safe(section_title(text, prose, section, lang))}}}\n")
        intro = prose.section_intro(section, lang)
        if intro:
            parts.append(intro + "\n\n")
        told = ""  # the step said last: a derivation that covers several displays is told once
        for i, st in enumerate(group):
            step, told = _handout_step(st, i, by_id, tags[st.entry.id], prose, lang, hidden.get(st.entry.id), told,
                                       asked.get(st.entry.id))
            parts.append(step)
    if exercises:
        parts.append(f"\\section{{{W['exercises']}}}\n\\begin{{enumerate}}\n")
        for n, ex in enumerate(exercises, 1):
            parts.append(f"\\item\\label{{ex:{n}}} " + _exercise(ex, by_id, lang))
        parts.append("\\end{enumerate}\n")
    parts.append(figures_section(text, prose, lang))
    if exercises and solutions:
        parts.append(f"\\section{{{W['solutions']}}}\n")
        for n, ex in enumerate(exercises, 1):
            parts.append(f"\\subsection*{{{W['exercise']}~\\ref{{ex:{n}}}}}\n" + _solution(ex, by_id, prose, lang))
    parts.append("\\end{document}\n")
    return "".join(parts)


def _hidden(exercises: list[Exercise], steps: list[Step]) -> dict[str, int]:
    """The errata the students' edition shows as printed, each with the number of the exercise
    that asks for it: a misprint set as an exercise, and every display of the same cause (its
    correction would give the answer away)."""
    groups = cause_groups(steps)
    out: dict[str, int] = {}
    for n, ex in enumerate(exercises, 1):
        if ex.kind is ExerciseKind.MISPRINT:
            for g in groups:
                if ex.step in g.steps:
                    for s in g.steps:
                        out.setdefault(s.entry.id, n)
            out.setdefault(ex.step.entry.id, n)
    return out


def _connect(st: Step, index: int, by_id: dict[str, Step], lang: str) -> str:
    """The sentence that leads to a step: where it starts from (varied, deterministically)."""
    W = WORDS[lang]
    uses = [u for u in st.uses if u in by_id]
    if not uses:
        return W["start"] if index == 0 else W["states"][index % len(W["states"])]
    refs = join_refs([ref_of(by_id, u, handout=True) for u in uses], lang)
    choices = W["from_one"] if len(uses) == 1 else W["from_many"]
    return choices[index % len(choices)].format(refs=refs)


def _handout_step(st: Step, index: int, by_id: dict[str, Step], tag: str, prose: TextProse, lang: str,
                  exercise: int | None = None, told: str = "", asked: int | None = None) -> tuple[str, str]:
    """One step told to a student, and the words of its step; ``exercise``, the number of the
    exercise that asks for this erratum's correction (then the display is shown as printed,
    and nothing more is said); ``told``, the words of the step before (not said twice); ``asked``,
    the number of the exercise that asks to derive it (its words are then left to it)."""
    W = WORDS[lang]
    shown = st.entry.latex if exercise is not None else shown_latex(st)
    out = [_connect(st, index, by_id, lang) + "\n" + tagged_display(shown, tag, f"h:{st.label}")]
    if exercise is not None:
        return out[0] + "\\emph{" + W["erratum_exercise"].format(ref=f"\\ref{{ex:{exercise}}}") + "}\n\n", told
    own = prose.entry(st.entry.id).step.get(lang)
    words = own or (paragraphs(cite(clean_prose(st.derivation.doc), citing(by_id.values())))
                    if lang == "en" and st.derivation is not None else "")
    if asked is not None:
        out.append(W["derive_exercise"].format(ref=f"\\ref{{ex:{asked}}}") + "\n\n")
    elif words and st.mode is not Mode.IDENTITY:  # an identity's generic words say nothing here
        out.append((W["same_step"] if words == told else words) + "\n\n")
    status = st.outcome.status
    if st.is_erratum:
        out.append("\\emph{" + W["erratum"].format(kind=kind_name(st.erratum.kind, lang)) + "}\n"
                   + printed_display(st.entry.latex))
    elif status is Status.CLEARED:
        doubt = st.cleared.suspicion_in(lang).rstrip(". ") if st.cleared is not None else ""
        out.append("\\emph{" + (W["cleared_doubt"].format(doubt=with_math(clean_prose(doubt), lang=lang))
                                 if doubt else W["cleared"]) + "}\n\n")
    elif status is Status.UNEXPECTED:
        out.append("\\emph{" + W["unverified"] + "}\n\n")
    return "".join(out), words or told


def _words(ex: Exercise, which: str, by_id: dict[str, Step], lang: str) -> str:
    """An exercise's own question or solution in the language, its {ref:…} as the handout's
    equation numbers."""
    if ex.spec is None:
        return ""
    words = getattr(ex.spec, which).get(lang, "")
    return REF.sub(lambda m: ref_of(by_id, m.group(1), handout=True), words)


def _exercise(ex: Exercise, by_id: dict[str, Step], lang: str) -> str:
    W, st = WORDS[lang], ex.step
    # the level, graded from easy (one star) to hard (three)
    stars = "\\textsuperscript{" + "$\\star$" * ex.level + "}~" if ex.spec is not None else ""
    own = _words(ex, "question", by_id, lang)
    if ex.kind is ExerciseKind.MISPRINT:
        ask = own or W["ex_errata"].format(ref=ref_of(by_id, st.entry.id, handout=True))
        return stars + ask + "\n" + printed_display(st.entry.latex)
    if own:
        return stars + own + "\n"
    uses = [ref_of(by_id, u, handout=True) for u in st.uses if u in by_id]
    ref = ref_of(by_id, st.entry.id, handout=True)
    key = "ex_derive_none" if not uses else ("ex_derive_one" if len(uses) == 1 else "ex_derive")
    return W[key].format(refs=join_refs(uses, lang), ref=ref) + "\n"


def _solution(ex: Exercise, by_id: dict[str, Step], prose: TextProse, lang: str) -> str:
    """A solution in textbook form: how the step goes, in words, and the result in the text's
    form; for an erratum, the correct form, the kind of error and its explanation."""
    W, st = WORDS[lang], ex.step
    own = _words(ex, "solution", by_id, lang)
    if ex.kind is ExerciseKind.COMPUTE:
        value = (f"${paper_latex(sp.Symbol(ex.spec.unknown))} = {number(ex.answer, lang, ex.spec.digits)}"
                 + (f"\\,{ex.spec.unit}" if ex.spec.unit else "") + "$")
        said = own.replace("{answer}", value) if own else ""
        return ((said + "\n\n") if said else "") + W["sol_answer"].format(
            answer=value, ref=ref_of(by_id, st.entry.id, handout=True)) + "\n\n"
    if ex.kind is ExerciseKind.MISPRINT:
        groups = [g for g in cause_groups([st])]
        note = cause_note(groups[0], prose, lang, citing(by_id.values())) if groups else ""
        return (W["sol_corrected"] + "\n" + printed_display(st.erratum.corrected_latex)
                + W["sol_kind"].format(kind=kind_name(st.erratum.kind, lang)) + (" " + note if note else "")
                + (" " + own if own else "") + "\n\n")
    if own:
        return own + "\n" + printed_display(shown_latex(st))
    uses = [ref_of(by_id, u, handout=True) for u in st.uses if u in by_id]
    how = step_text(st, by_id, prose, lang, handout=True)
    lead = W["sol_derive"].format(refs=join_refs(uses, lang)) if uses else W["sol_derive_none"]
    return how + "\n\n" + lead + "\n" + printed_display(shown_latex(st))


