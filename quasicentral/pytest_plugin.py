"""A pytest plugin (entry point ``pytest11``, as nbval is for notebooks): ``pytest --texts DIR``
collects a text folder's entries as test items, so that a user's existing test run — and its
JUnit report — covers their notes.

Each entry is one item, ``DIR/text.toml::<entry id>``: it passes where the entry is verified,
a registered erratum or a cleared suspect; fails with its verdict, its problems and its witness
where the printed form is refuted unexpectedly (or an erratum no longer stands); and is skipped,
with its reason, where the verdict is inconclusive or the entry is notation (nothing to check).  The text is verified once per process (the
verdict cache of ``quasicentral verify`` is used, so a second run reads it back).  A folder that
cannot be read is one collection error naming its file and line.

``--texts`` may be repeated; the ini option ``quasicentral_texts`` lists folders too.  Nothing of
quasicentral is imported unless a text is asked for: the plugin costs any other test run nothing.
"""

from __future__ import annotations

from pathlib import Path

import pytest


def pytest_addoption(parser):
    group = parser.getgroup("quasicentral", "quasicentral: a text folder's entries as tests")
    group.addoption("--texts", action="append", default=[], metavar="DIR",
                    help="collect the entries of the text folder DIR as test items (repeatable)")
    parser.addini("quasicentral_texts", "text folders whose entries are collected as test items", type="paths",
                  default=[])


def _folders(config) -> list[Path]:
    given = [Path(p) for p in config.getoption("texts")] + list(config.getini("quasicentral_texts"))
    return list(dict.fromkeys(p.expanduser().resolve() for p in given))


@pytest.hookimpl(tryfirst=True)  # before -k and -m deselect: they apply to these items too
def pytest_collection_modifyitems(session, config, items):
    for folder in _folders(config):
        try:  # the node id: the folder as the user named it, relative to the rootdir where it lies inside
            where = folder.relative_to(config.rootpath).as_posix()
        except ValueError:
            where = folder.as_posix()
        collector = TextCollector.from_parent(session, path=folder / "text.toml", folder=folder,
                                              nodeid=f"{where}/text.toml")
        report = collector.ihook.pytest_make_collect_report(collector=collector)
        session.ihook.pytest_collectreport(report=report)
        if report.passed:
            items.extend(report.result)


class TextCollector(pytest.File):
    """A text folder: its entries, each an :class:`EntryItem`."""

    def __init__(self, *, folder: Path, **kwargs):
        super().__init__(**kwargs)
        self.folder = folder
        self._results = None

    def collect(self):
        from quasicentral.api import load_text

        self.text = load_text(self.folder)
        for eid in self.text.ids:
            yield EntryItem.from_parent(self, name=eid, eid=eid)

    def results(self):
        """The text's verdicts, computed once (every item reads its own)."""
        if self._results is None:
            self._results = self.text.verify()
        return self._results

    def repr_failure(self, excinfo):
        from quasicentral.api import InputError

        if isinstance(excinfo.value, InputError):
            return f"quasicentral: {excinfo.value}"
        return super().repr_failure(excinfo)


class EntryFailed(Exception):
    """An entry whose verdict is not what the text's records expect."""


class EntryItem(pytest.Item):
    """One catalog entry of a text."""

    def __init__(self, *, eid: str, **kwargs):
        super().__init__(**kwargs)
        self.eid = eid

    def runtest(self):
        from quasicentral.engine.verdict import Status

        result = self.parent.results()[self.eid]
        o = result.outcome
        if o.status is Status.NOTATION:
            pytest.skip(f"{self.eid}: notation: {o.verdict.detail}")
        if o.ok:
            return
        if o.verdict.name == "inconclusive":
            pytest.skip(f"{self.eid}: inconclusive: {o.verdict.detail}")
        lines = [f"{self.eid}: {o.status.value}: {o.verdict.name} ({o.verdict.method.value}): {o.verdict.detail}"]
        lines += [f"  problem: {p}" for p in o.problem_texts]
        w = result.witness
        if w is not None:
            at = ", ".join(f"{k} = {v}" for k, v in w.parameters.items()) or "(no parameters)"
            lines.append(f"  witness at {at}: printed {w.printed}, correct {w.corrected}"
                         + (" (certified)" if w.certified else ""))
        raise EntryFailed("\n".join(lines))

    def repr_failure(self, excinfo):
        if isinstance(excinfo.value, EntryFailed):
            return str(excinfo.value)
        return super().repr_failure(excinfo)

    def reportinfo(self):
        return self.path, None, f"{self.eid}"
