"""The view model of the documents: each catalog entry with everything known about it, built
from the engine's records (the outcome with its text's records, the derivation, its result
and the ids it used) — the documents never call back into the engine.

:func:`records_for` verifies the texts (or reads their verdicts back from the cache) and
collects the derivations' results (from the store, or computed within the entry's budget);
everything else here turns those records into the words of one entry.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace
from functools import cached_property

import sympy as sp

from quasicentral.documents.latex import parameter_latex, parameter_unit
from quasicentral.documents.prosetex import clean_prose, escape, text, with_math
from quasicentral.documents.prose import KINDS_CS, WORDS, TextProse, join_refs, prose_of
from quasicentral.engine import catalog
from quasicentral.engine import errata as errata_mod
from quasicentral.engine.notes import render_note
from quasicentral.engine.registry import Derivation, Mode
from quasicentral.engine.verdict import Outcome, Status
from quasicentral.studies import figures as figures_mod

FIGURE_DIR = "figures"


@dataclass(frozen=True)
class Step:
    """One catalog entry with everything known about it."""

    entry: catalog.Entry
    outcome: Outcome
    derivation: Derivation | None
    result: object  # the derivation's result (None when there is none)
    error: str | None  # why there is no result (None when there is one, or no derivation)
    uses: tuple[str, ...] = ()  # the ids the derivation built on, in the text's order
    index: int = 0  # running number of an unnumbered entry in its text ([1], [2], …), else 0
    memo: dict = field(default_factory=dict, compare=False, repr=False)  # per-entry results of the views

    @property
    def erratum(self) -> errata_mod.Erratum | None:
        return self.outcome.records.erratum if self.outcome.records is not None else None

    @property
    def cleared(self) -> errata_mod.Cleared | None:
        return self.outcome.records.cleared if self.outcome.records is not None else None

    @property
    def label(self) -> str:
        return label_of(self.entry.id)

    @property
    def tag(self) -> str:
        """How the text's documents refer to the entry: its number (12) or its place [3]."""
        return f"({self.entry.number})" if self.entry.number else f"[{self.index}]"

    @property
    def is_erratum(self) -> bool:
        return self.erratum is not None and self.outcome.status is Status.ERRATUM

    @cached_property
    def mode(self) -> Mode | None:
        return self.derivation.mode if self.derivation is not None else None


def label_of(eid: str) -> str:
    """A LaTeX label for an entry id: letters and digits only, other characters as '.'."""
    return re.sub(r"[^A-Za-z0-9]", ".", eid)


@dataclass(frozen=True)
class TextRecords:
    """One text and the steps of its catalog, in order: what its documents are made of."""

    text: object  # quasicentral.engine.texts.Text
    steps: tuple[Step, ...]
    exercises: tuple = ()  # quasicentral.engine.exercises.Exercise: the text's bank, checked

    @property
    def id(self) -> str:
        return self.text.id

    @cached_property
    def prose(self) -> TextProse:
        return prose_of(self.text)


def steps_of(ws, text, outcomes: dict[str, Outcome]) -> list[Step]:
    """The steps of one text in catalog order, each with its derivation's result (read back
    from the store, or computed within the entry's budget)."""
    from quasicentral.engine.run import derivation_of, quiet_stdout

    order = {eid: i for i, eid in enumerate(text.entries)}
    out, k = [], 0
    for e in text.entries.values():
        d = derivation_of(ws, e)
        result, error, uses = None, None, ()
        # a folder's own code ran in workers: its results were brought back (run.derive_all)
        if d is not None and (d.func is not None or ws.derivations.known(e.id)):
            try:
                with quiet_stdout():
                    result = ws.result(e.id)
                    used = ws.used(e.id)
                # as declared where the declaration is right (its order), else as used, in the text's order
                uses = (tuple(d.declared_uses) if set(d.declared_uses) == used
                        else tuple(sorted(used, key=lambda u: (order.get(u, len(order)), u))))
            except (Exception, SystemExit) as exc:  # noqa: BLE001 - a failing derivation is reported, not raised
                error = f"{type(exc).__name__}: {exc}"
        if not e.number:
            k += 1
        out.append(Step(e, outcomes[e.id], d, result, error, uses, 0 if e.number else k))
    labels = [s.label for s in out]
    if len(set(labels)) != len(labels):
        raise ValueError(f"{text.id}: two entry ids map to the same LaTeX label")
    return out


def records_for(ws, texts: list, opts, progress=None, on_warning=None) -> list[TextRecords]:
    """The records of ``texts``: each entry verified (or read back from the verdict cache) and
    its derivation's result."""
    from quasicentral.engine import run

    entries = [e for t in texts for e in t.entries.values()]
    outcomes = dict(zip([e.id for e in entries], run.run(ws, entries, opts, use_cache=True, progress=progress,
                                                          on_warning=on_warning)))
    run.derive_all(ws, [e.id for e in entries], opts)  # the folders' code runs in workers, not here
    out = []
    for t in texts:
        steps = tuple(steps_of(ws, t, outcomes))
        out.append(TextRecords(t, steps, exercises_for(t, steps)))
    return out


def exercises_for(text, steps) -> tuple:
    """The text's exercise bank (its report.toml), each exercise checked against its steps."""
    from quasicentral.engine.exercises import read_bank, settle

    bank = read_bank(text.root, text.id)
    if not bank:
        return ()
    return settle(bank, dict(text.entries), {s.entry.id: s.outcome.status for s in steps},
                  {s.entry.id: s.uses for s in steps},
                  {s.entry.id: s.erratum.corrected_text for s in steps if s.is_erratum})


def sections_of(steps) -> list[tuple[str, list[Step]]]:
    """Steps grouped by section, in the order the sections first appear."""
    groups: dict[str, list[Step]] = {}
    for s in steps:
        groups.setdefault(s.entry.section, []).append(s)
    return list(groups.items())


def section_title(text, prose: TextProse, section: str, lang: str) -> str:
    """The title of a section: the text's own words (report.toml), else its printed title."""
    known = prose.section_title(section, lang)
    if known:
        return known
    printed = text.section_titles.get(section, "")
    return with_math(printed, letters=False) if printed else escape(section)


# --- words of one entry --------------------------------------------------------------------------
def entry_heading(st: Step, prose: TextProse, lang: str) -> str:
    """'(12) name' where the text names the entry in the language; else 'Equation (12)'."""
    W = WORDS[lang]
    own = prose.entry(st.entry.id).name.get(lang)
    # report.toml's words first, then the catalog's name in the language (name_cs; name is English)
    name = own or text(clean_prose(st.entry.name_in(lang)))
    word = W["equation"] if st.entry.number else W["relation"]
    tag = escape(st.tag)
    return f"{tag}~{name}" if name else f"{word}~{tag}"


_MATH_HEAD = re.compile(r"^(.*?)(?::\s|\.\s*$|$)", re.S)
_FUNCTION_WORDS = frozenset({"sin", "cos", "tg", "cotg", "arccotg", "arctg", "arcsin", "ln", "exp", "dt", "dx", "dy",
                   "ds", "dz", "konst", "d", "const"})


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
    uses = [u for u in st.uses if u in by_id]
    refs = join_refs([ref_of(by_id, u, handout) for u in uses], lang)
    where = (W["step_from"][d.mode].format(refs=refs) if uses else W["step_none"][d.mode])
    if lang == "en":
        return paragraphs(cite(clean_prose(d.doc), citing(by_id.values())))
    head = _MATH_HEAD.match(" ".join(d.doc.split())).group(1).strip()
    formula = clean_prose(head)
    if _is_formula(formula):
        return text(formula) + ".  " + where
    return where


#: significant digits of a witness's values in a document's prose (the appendix's table and the
#: JSON keep every digit)
WITNESS_DIGITS = 4


def citing(steps) -> dict[str, str]:
    """How a note may name another display of its text — by the local part of its id
    (``D-integral`` for mytext:D-integral) — and how a reader is told it: its tag, [82]."""
    out = {}
    for st in steps:
        local = st.entry.id.split(":", 1)[-1]
        parts = local.split("-")
        # an id, not an English compound ("small-angle"): a capital, a digit or a one-letter part
        if len(parts) > 1 and any(c.isalpha() for c in local) and (
                any(c.isupper() or c.isdigit() for c in local) or any(len(p) == 1 for p in parts)):
            out[local] = st.tag
    return out


def cite(tex: str, tags: dict[str, str]) -> str:
    """``tex`` (a note's plain words) with every display it names by id given by its tag
    instead: an internal id is no word for a reader."""
    if not tags or not tex:
        return tex
    names = "|".join(re.escape(k) for k in sorted(tags, key=len, reverse=True))
    return re.sub(rf"(?<![\w.:/\\-])({names})(?![\w-])", lambda m: tags[m.group(1)], tex)


def _math_name(name: str) -> str:
    """A witness's parameter in a note as the text writes it: $\\lambda$ for the checker's lam."""
    return f"${parameter_latex(name)}$"


def _math_unit(name: str) -> str:
    """The units after a witness's value in a note, where the text declared them by name."""
    unit = parameter_unit(name)
    return f" ${unit[2:]}$" if unit else ""


def reader_note(note: str, witness, lang: str) -> str:
    """A record's note for a reader: its witness in a few digits, in the text's names and units."""
    return render_note(note, witness, lang, WITNESS_DIGITS, _math_name, _math_unit)


def cleared_note(st: Step, lang: str, tags: dict[str, str] | None = None) -> str:
    """What a reader is told about a cleared suspicion: its record's note in the language."""
    note = st.cleared.note_in(lang) if st.cleared is not None else ""
    witness = getattr(st.outcome.verdict, "witness", None)
    return with_math(cite(clean_prose(reader_note(note, witness, lang)), tags), lang=lang) if note else ""


def erratum_note(st: Step, prose: TextProse, lang: str, tags: dict[str, str] | None = None) -> str:
    """What a reader is told about an erratum or a cleared suspect, in the language: the text's
    own words (report.toml), the record's note in English, or nothing."""
    witness = getattr(st.outcome.verdict, "witness", None)
    own = prose.entry(st.entry.id).erratum.get(lang)
    if own:
        return reader_note(own, witness, lang)  # numbers only through {witness…} placeholders
    record = st.erratum if st.erratum is not None else st.cleared
    note = record.note_in(lang) if record is not None else ""
    return with_math(cite(clean_prose(reader_note(note, witness, lang)), tags), letters=True,
                     lang=lang) if note else ""


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


def cause_groups(steps) -> list[CauseGroup]:
    """The causes of a text's errata, in the order of their first erratum."""
    groups: dict[str, dict] = {}
    for st in steps:
        if not st.is_erratum:
            continue
        causes = st.outcome.causes
        if causes:
            for c in causes:
                g = groups.setdefault(c.id, {
                    "title": {"en": c.title_in("en") or c.id, "cs": c.title_in("cs")},
                    "kind": c.kind.value,
                    "note": {"en": c.note_in("en"), "cs": c.note_in("cs")},
                    "steps": [], "recorded": True})
                g["steps"].append(st)
        else:
            groups[st.entry.id] = {"title": {}, "kind": st.erratum.kind.value, "note": {}, "steps": [st],
                                   "recorded": False}
    return [CauseGroup(k, g["title"], g["kind"], g["note"], tuple(g["steps"]), g["recorded"])
            for k, g in groups.items()]


def kind_name(kind, lang: str) -> str:
    kind = getattr(kind, "value", kind)
    return escape(KINDS_CS.get(kind, kind) if lang == "cs" else kind)


def cause_title(g: CauseGroup, prose: TextProse, lang: str) -> str:
    if g.recorded:
        got = g.title.get(lang) or (g.title.get("en") if lang == "en" else "")
        if got:  # in Czech a lone letter is a preposition (k, v, s, u), not a variable
            return with_math(clean_prose(got), letters=True, lang=lang)
        return kind_name(g.kind, lang)[:1].upper() + kind_name(g.kind, lang)[1:]
    st = g.steps[0]
    return entry_heading(st, prose, lang) + ": " + kind_name(g.kind, lang)


def cause_note(g: CauseGroup, prose: TextProse, lang: str, tags: dict[str, str] | None = None) -> str:
    if g.recorded:
        got = g.note.get(lang, "")
        return with_math(cite(clean_prose(got), tags), letters=True, lang=lang) if got else ""
    return erratum_note(g.steps[0], prose, lang, tags)


# --- figures ---------------------------------------------------------------------------------
@dataclass(frozen=True)
class FigureItem:
    """A figure as a document includes it: in its language where it is drawn per language (a
    text's own figure: its axes, legend and decimal separator), else as it is (a measured chart)."""

    name: str
    title: str
    make: object  # builds the figure (from its text's figures.py)
    localized: bool = True
    lang: str = "en"

    @property
    def path(self) -> str:
        own = self.localized and self.lang != "en"
        return f"{FIGURE_DIR}/{self.name}{'-' + self.lang if own else ''}.png"

    def in_lang(self, lang: str) -> "FigureItem":
        return replace(self, lang=lang)


def _item(fig) -> FigureItem:
    return FigureItem(fig.name, fig.title, lambda fig=fig: fig, not isinstance(fig, figures_mod.MeasuredChart))


def figure_items(texts: list, langs=("en",)) -> tuple[FigureItem, ...]:
    """Every figure of ``texts`` (their folders' figures.py), in each of ``langs`` where it is
    drawn per language."""
    items: dict[str, FigureItem] = {}
    for t in texts:
        for fig in figures_mod.of_text(t):
            for lang in langs:
                item = _item(fig).in_lang(lang)
                items.setdefault(item.path, item)
    return tuple(items.values())


def figures_for(text, prose: TextProse, role: str | None = None) -> list[tuple[FigureItem, object]]:
    """The figures of a text (its folder's figures.py, in that order), each with its prose from
    report.toml (or None); ``role`` keeps only "text" figures or "study" charts (a measured
    chart is a study unless report.toml says otherwise)."""
    said = {fp.name: fp for fp in prose.figures}
    out = []
    for fig in figures_mod.of_text(text):
        fp = said.get(fig.name)
        kind = fp.role if fp is not None else ("study" if isinstance(fig, figures_mod.MeasuredChart) else "text")
        if role is None or kind == role:
            out.append((_item(fig), fp))
    return out


def caption(fig: FigureItem, fp, lang: str) -> str:
    got = fp.caption.get(lang) if fp is not None else None
    return got or text(clean_prose(fig.title))


def paragraphs(doc: str) -> str:
    """A docstring as LaTeX paragraphs (blank lines separate them)."""
    paras = [" ".join(p.split()) for p in re.split(r"\n\s*\n", doc.strip()) if p.strip()]
    return "\n\n".join(text(p) for p in paras)


def ref_of(step_by_id: dict[str, Step], eid: str, handout: bool) -> str:
    """A reference to entry ``eid``: its number or its place, linked."""
    st = step_by_id.get(eid)
    if st is None:
        return ""
    if handout:
        return f"\\eqref{{h:{st.label}}}" if st.entry.number else f"\\ref{{h:{st.label}}}"
    return f"\\ref{{e:{st.label}}}"


