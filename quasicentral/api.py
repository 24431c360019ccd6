"""The Python interface, for notebooks and scripts — the way sympy and mpmath are used in teaching.

>>> import quasicentral as qc
>>> text = qc.load_text("pendulum")              # a shipped text, or the path of your text's folder
>>> text.title
'Přesné řešení matematického kyvadla'

``text.verify()`` returns :class:`Results`: a table of verdicts in Jupyter (``_repr_html_``) or
as text, and for one entry (``results["pendulum:53"]``) the printed and the re-derived form
with the verdict and, for a refutation, its witness (``_repr_latex_``, in the report's own
notation).  ``text.errata()`` lists the errata and cleared suspects; ``text.report(out)``
builds the text's report.

Texts live in a :class:`~quasicentral.engine.workspace.Workspace`: ``load_text`` uses the
session's default one (a notebook may load any number of texts into it, and one may build on
another); ``qc.Workspace()`` makes a fresh one.  Bad input raises :class:`InputError` (a
``ValueError``) with a message that names the file and line, or the argument.
"""

from __future__ import annotations

import html
from dataclasses import dataclass
from pathlib import Path

import sympy as sp

from quasicentral.engine import formats
from quasicentral.engine import run as verification
from quasicentral.engine.catalog import CatalogError
from quasicentral.engine.options import Options
from quasicentral.engine.registry import Mode, as_list
from quasicentral.engine.texts import Text
from quasicentral.engine.verdict import Outcome, Refuted, Status
from quasicentral.engine.workspace import Workspace

LANGUAGES = ("en", "cs")


class InputError(ValueError):
    """Bad input to the Python interface: a text folder that cannot be read, an id that is not
    in the text, an argument of the wrong kind.  The message names the file and line, the
    entry or the argument."""


_DEFAULT: list = []  # the session's default workspace, made on first use (the API's only state)


def workspace() -> Workspace:
    """The session's default workspace (made on first use)."""
    if not _DEFAULT:
        _DEFAULT.append(Workspace())
    return _DEFAULT[0]


def _folder(text) -> str:
    if isinstance(text, bytes):
        try:
            text = text.decode()
        except UnicodeDecodeError:
            raise InputError(f"load_text({text!r}): a folder's name that is not UTF-8") from None
    if isinstance(text, Path):
        return str(text)
    if not isinstance(text, str):
        raise InputError(f"load_text: a text is a folder (str or Path) or a shipped text's id, not {type(text).__name__}")
    if not text.strip():
        raise InputError("load_text: an empty name (give a text's folder or a shipped text's id)")
    return text


def load_text(text: str | Path, reload: bool = False, workspace_: Workspace | None = None) -> "LoadedText":
    """A text by its folder (a ``str`` or ``Path``) or by a shipped text's id, in the default
    workspace (or ``workspace_``).  ``reload=True`` reads the folder anew after you edited its
    files (in a running notebook)."""
    ws = workspace_ or workspace()
    spec = _folder(text)
    try:
        (found,) = ws.resolve([spec])
        if reload:
            ws.forget(found)
            (found,) = ws.resolve([spec])
        found.validate()
        ws.survey([found])
    except CatalogError as exc:
        raise InputError(str(exc)) from None
    return LoadedText(found, ws)


def new_text(folder: str | Path, text_id: str | None = None) -> "LoadedText":
    """Write the skeleton of a text of one's own into ``folder`` (as ``quasicentral new-text``)
    and load it."""
    from quasicentral.engine import skeleton

    try:
        skeleton.write(Path(_folder(folder)), text_id)
    except skeleton.SkeletonError as exc:
        raise InputError(str(exc)) from None
    return load_text(Path(folder))


def shipped_texts() -> list[str]:
    """The ids of the texts that come with quasicentral."""
    return [t.id for t in Workspace().shipped()]


def _ids(ids) -> list[str] | None:
    if ids is None:
        return None
    if isinstance(ids, str):
        return [ids]  # one id, not its characters
    if not all(isinstance(i, str) for i in ids):
        raise InputError("verify(ids=...): the ids are strings such as 'mynotes:2'")
    return list(ids)


def _dps(dps) -> int:
    if isinstance(dps, bool) or not isinstance(dps, int):
        raise InputError(f"verify(dps=...): a whole number of digits, not {dps!r}")
    if not Options.MIN_DPS <= dps <= 300:
        raise InputError(f"verify(dps=...): between {Options.MIN_DPS} and 300 digits, not {dps}")
    return dps


@dataclass
class LoadedText:
    """A loaded text: its metadata, catalog, errata, and what can be done with it."""

    text: Text
    ws: Workspace

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

    def verify(self, ids: list[str] | str | None = None, *, dps: int = 30, cache: bool = True,
               jobs: int | None = 1, timeout: float = 120.0) -> "Results":
        """Verify the text (or the entries ``ids``); cached verdicts are read back."""
        wanted = _ids(ids)
        entries = [e for e in self.text.entries.values() if wanted is None or e.id in wanted]
        unknown = set(wanted or ()) - {e.id for e in entries}
        if unknown:
            raise InputError(f"verify(ids=...): no entry {sorted(unknown)[0]!r} in {self.id}")
        if not isinstance(timeout, (int, float)) or isinstance(timeout, bool) or not 0 < timeout <= 86_400:
            raise InputError(f"verify(timeout=...): a number of seconds, not {timeout!r}")
        outcomes = verification.run(self.ws, entries, Options(dps=_dps(dps), timeout=float(timeout)),
                                    use_cache=cache, jobs=jobs)
        return Results(self, entries, outcomes)

    def errata(self, cache: bool = True) -> dict:
        """The errata and cleared suspects with their verdicts and witnesses (as ``errata --json``)."""
        res = self.verify(cache=cache)
        return formats.errata_document(res.entries, res.outcomes)

    def report(self, out: str | Path, *, lang: str = "en", handout: bool = False, pdf: bool = False) -> list[Path]:
        """Write the text's report (or handout) into ``out``; with ``pdf`` also compile it.
        Returns the files written."""
        from quasicentral.documents import report

        if lang not in LANGUAGES:
            raise InputError(f"report(lang=...): one of {', '.join(LANGUAGES)}, not {lang!r}")
        out = Path(_folder(out))
        records = report.records_for(self.ws, [self.text], Options())
        docs = report.generate(records, report.HANDOUT_KINDS if handout else ("report",), (lang,))
        paths = report.write(out, docs, [self.text])
        if pdf:
            paths += report.compile_all(out, [n for n in sorted(docs) if n != report.VERSIONS_FILE])
        return paths

    def _repr_html_(self) -> str:
        return (f"<p><b>{html.escape(self.title)}</b> ({html.escape(self.id)}): {len(self.ids)} entries, "
                f"{len(self.text.errata)} recorded errata, {len(self.text.cleared)} cleared suspects</p>")

    def __repr__(self) -> str:
        return (f"<text {self.id}: {self.title!r}, {len(self.ids)} entries, {len(self.text.errata)} recorded errata, "
                f"{len(self.text.cleared)} cleared suspects>")


_STATUS_COLOUR = {Status.VERIFIED: "#1a7f37", Status.ERRATUM: "#9a6700", Status.CLEARED: "#0969da", Status.NOTATION: "#57606a",
                  Status.UNEXPECTED: "#cf222e"}


@dataclass
class Results:
    """The verdicts of a run: iterate, index by id, or display as a table."""

    text: LoadedText
    entries: list
    outcomes: list[Outcome]

    def __len__(self) -> int:
        return len(self.outcomes)

    def __iter__(self):
        return (EntryResult(e, o, self.text) for e, o in zip(self.entries, self.outcomes))

    def __getitem__(self, eid: str) -> "EntryResult":
        for e, o in zip(self.entries, self.outcomes):
            if e.id == eid:
                return EntryResult(e, o, self.text)
        raise KeyError(eid)

    @property
    def ok(self) -> bool:
        """Every entry verified, a registered erratum or a cleared suspect."""
        return all(o.ok for o in self.outcomes)

    @property
    def summary(self) -> dict:
        return verification.summary(self.outcomes)

    def __repr__(self) -> str:
        return formats.verify_table(formats.verify_document(self.entries, self.outcomes))

    def _repr_html_(self) -> str:
        rows = []
        for e, o in zip(self.entries, self.outcomes):
            colour = _STATUS_COLOUR[o.status]
            rows.append(f"<tr><td>{html.escape(e.id)}</td><td>{html.escape(e.name)}</td>"
                        f"<td style='color:{colour}'><b>{o.status.value}</b></td>"
                        f"<td>{o.verdict.name} ({o.verdict.method.value})</td>"
                        f"<td>{html.escape(o.verdict.detail or '')}</td></tr>")
        counts = ", ".join(f"{v} {k}" for k, v in self.summary["status"].items())
        return ("<table><thead><tr><th>id</th><th>equation</th><th>status</th><th>verdict</th><th>detail</th>"
                f"</tr></thead><tbody>{''.join(rows)}</tbody></table><p>{len(self)} entries: {counts}</p>")


@dataclass
class EntryResult:
    """One entry: printed against re-derived, the verdict, the witness of a refutation."""

    entry: object
    outcome: Outcome
    text: LoadedText | None = None

    @property
    def status(self) -> Status:
        return self.outcome.status

    @property
    def witness(self):
        return self.outcome.verdict.witness if isinstance(self.outcome.verdict, Refuted) else None

    def derived_latex(self) -> str:
        """The re-derived relation(s) in the text's notation, by the printer of the reports."""
        from quasicentral.documents.latex import Notation, paper_latex, using

        if self.text is None:
            return ""
        ws = self.text.ws
        d = ws.derivation(self.entry.id)
        if d is None:
            return ""
        try:
            result = ws.result(self.entry.id)
        except Exception as exc:  # noqa: BLE001 - a failed derivation is shown as such
            return rf"\text{{the derivation failed: {html.escape(type(exc).__name__)}}}"
        with using(Notation.of(self.entry.symbols)):
            if d.mode is Mode.SUBSTITUTE:
                parts = [f"{paper_latex(k)} = {paper_latex(v)}" for k, v in dict(result or {}).items()]
                return r"\text{on }" + r",\ ".join(parts) if parts else r"\text{an identity}"
            return r",\quad ".join(paper_latex(r) for r in as_list(result) if isinstance(r, sp.Basic))

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
