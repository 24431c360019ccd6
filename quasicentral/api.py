"""The Python interface, for notebooks and scripts — the way sympy and mpmath are used in teaching.

>>> import quasicentral as qc
>>> text = qc.load_text("pendulum")              # a shipped text, or the path of your text's folder
>>> text.title
'Přesné řešení matematického kyvadla'

``text.verify()`` returns :class:`Results`: a table of verdicts in Jupyter (``_repr_html_``),
and for one entry (``results["pendulum:53"]``) the printed and the re-derived form with the
verdict and, for a refutation, its witness (``_repr_latex_``).  ``text.errata()`` lists the
errata and cleared suspects; ``text.report(out)`` builds the text's report.
"""

from __future__ import annotations

import html
from dataclasses import dataclass
from pathlib import Path

import sympy as sp

from quasicentral.engine import formats, texts
from quasicentral.engine import run as engine_run
from quasicentral.engine.checker import Options
from quasicentral.engine.registry import REGISTRY, Mode, as_list, derived
from quasicentral.engine.verdict import Outcome, Refuted, Status


def load_text(text: str | Path, reload: bool = False) -> "Text":
    """A text by its folder (a ``str`` or ``Path``) or by a shipped text's id.  ``reload=True``
    reads the folder anew after you edited its files (in a running notebook)."""
    (found,) = texts.resolve([str(text)])
    if reload:
        texts.forget(found)
        (found,) = texts.resolve([str(text)])
    texts.activate([found])
    return Text(found)


def new_text(folder: str | Path, text_id: str | None = None) -> "Text":
    """Write the skeleton of a text of one's own into ``folder`` (as ``quasicentral new-text``)
    and load it."""
    from quasicentral.engine import skeleton

    skeleton.write(Path(folder), text_id)
    return load_text(Path(folder))


def shipped_texts() -> list[str]:
    """The ids of the texts that come with quasicentral."""
    return [t.id for t in texts.shipped()]


@dataclass
class Text:
    """A loaded text: its metadata, catalog, errata, and what can be done with it."""

    text: texts.Text

    @property
    def id(self) -> str:
        return self.text.id

    @property
    def title(self) -> str:
        return self.text.title

    @property
    def ids(self) -> list[str]:
        """The ids of the catalog's entries, in the text's order."""
        return list(self.text.entries)

    def verify(self, ids: list[str] | None = None, *, dps: int = 30, cache: bool = True,
               jobs: int | None = 1) -> "Results":
        """Verify the text (or the entries ``ids``); cached verdicts are read back."""
        entries = [e for e in self.text.entries.values() if ids is None or e.id in ids]
        unknown = set(ids or ()) - {e.id for e in entries}
        if unknown:
            raise KeyError(f"no entry {sorted(unknown)[0]!r} in {self.id}")
        outcomes = engine_run.run(entries, Options(dps=dps), use_cache=cache, jobs=jobs)
        return Results(self, entries, outcomes)

    def errata(self, cache: bool = True) -> dict:
        """The errata and cleared suspects with their verdicts and witnesses (as ``errata --json``)."""
        res = self.verify(cache=cache)
        return formats.errata_document(res.entries, res.outcomes)

    def report(self, out: str | Path, *, lang: str = "en", handout: bool = False, pdf: bool = False) -> list[Path]:
        """Write the text's report (or handout) into ``out``; with ``pdf`` also compile it.
        Returns the files written."""
        from quasicentral.documents import report

        out = Path(out)
        texts.activate([self.text], exclusive=True)
        outcomes = dict(zip(self.ids, self.verify().outcomes))
        docs = report.generate(("handout",) if handout else ("report",), (lang,), outcomes)
        paths = report.write(out, docs)
        if pdf:
            paths += report.compile_all(out, [n for n in sorted(docs) if n != report.VERSIONS_FILE])
        return paths

    def _repr_html_(self) -> str:
        return (f"<p><b>{html.escape(self.title)}</b> ({html.escape(self.id)}): {len(self.ids)} entries, "
                f"{len(self.text.errata)} recorded errata, {len(self.text.cleared)} cleared suspects</p>")


_STATUS_COLOUR = {Status.VERIFIED: "#1a7f37", Status.ERRATUM: "#9a6700", Status.CLEARED: "#0969da",
                  Status.UNEXPECTED: "#cf222e"}


@dataclass
class Results:
    """The verdicts of a run: iterate, index by id, or display as a table."""

    text: Text
    entries: list
    outcomes: list[Outcome]

    def __len__(self) -> int:
        return len(self.outcomes)

    def __iter__(self):
        return (EntryResult(e, o) for e, o in zip(self.entries, self.outcomes))

    def __getitem__(self, eid: str) -> "EntryResult":
        for e, o in zip(self.entries, self.outcomes):
            if e.id == eid:
                return EntryResult(e, o)
        raise KeyError(eid)

    @property
    def ok(self) -> bool:
        """Every entry verified, a registered erratum or a cleared suspect."""
        return all(o.ok for o in self.outcomes)

    @property
    def summary(self) -> dict:
        return engine_run.summary(self.outcomes)

    def _repr_html_(self) -> str:
        rows = []
        for e, o in zip(self.entries, self.outcomes):
            colour = _STATUS_COLOUR[Status(o.status)]
            rows.append(f"<tr><td>{html.escape(e.id)}</td><td>{html.escape(e.name)}</td>"
                        f"<td style='color:{colour}'><b>{o.status.value}</b></td>"
                        f"<td>{o.verdict.name} ({o.verdict.method.value})</td>"
                        f"<td>{html.escape((o.verdict.detail or '')[:90])}</td></tr>")
        counts = ", ".join(f"{v} {k}" for k, v in self.summary["status"].items())
        return ("<table><thead><tr><th>id</th><th>equation</th><th>status</th><th>verdict</th><th>detail</th>"
                f"</tr></thead><tbody>{''.join(rows)}</tbody></table><p>{len(self)} entries: {counts}</p>")


@dataclass
class EntryResult:
    """One entry: printed against re-derived, the verdict, the witness of a refutation."""

    entry: object
    outcome: Outcome

    @property
    def status(self) -> Status:
        return Status(self.outcome.status)

    @property
    def witness(self):
        return self.outcome.verdict.witness if isinstance(self.outcome.verdict, Refuted) else None

    def derived_latex(self) -> str:
        """The re-derived relation(s) in the text's symbols (as LaTeX)."""
        d = REGISTRY.get(self.entry.id)
        if d is None:
            return ""
        result = derived(self.entry.id)
        names = {k: v for k, v in self.entry.symbols.latex_names.items() if isinstance(k, sp.Symbol)}
        if d.mode is Mode.SUBSTITUTE:
            parts = [f"{sp.latex(k, symbol_names=names)} = {sp.latex(v, symbol_names=names)}"
                     for k, v in dict(result or {}).items()]
            return r"\text{on }" + r",\ ".join(parts) if parts else r"\text{an identity}"
        return r",\quad ".join(sp.latex(r, symbol_names=names) for r in as_list(result))

    def _repr_latex_(self) -> str:
        v, o = self.outcome.verdict, self.outcome
        lines = [rf"\text{{{self.entry.id}: {self.entry.name}}}",
                 rf"\text{{printed: }}\ {self.entry.latex}",
                 rf"\text{{re-derived: }}\ {self.derived_latex()}",
                 rf"\text{{{o.status.value} — {v.name} ({v.method.value})}}"]
        w = self.witness
        if w is not None:
            at = ", ".join(f"{k} = {val}" for k, val in w.parameters.items())
            lines.append(rf"\text{{witness at {at}: printed {w.printed[:18]}, derived {w.corrected[:18]}"
                         rf"{' (certified)' if w.certified else ''}}}")
        return "$$\\begin{array}{l}" + r"\\ ".join(lines) + r"\end{array}$$"
