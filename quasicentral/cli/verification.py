"""The verification commands: verify, errata, mutate, catalog, report, figures, new-text.

Each works on a :class:`~quasicentral.engine.workspace.Workspace` of the texts ``--text`` names
(default: the shipped ones) and renders the engine's records; bad input is a
:class:`~quasicentral.cli.parser.UsageError` (one line, exit 2).
"""

from __future__ import annotations

import json
import sys
import time
from contextlib import contextmanager
from pathlib import Path

from quasicentral.cli.parser import EXIT_OK, EXIT_UNEXPECTED, UsageError
from quasicentral.cli.terminal import ProgressBar, entries_text, error, safe, timing, warn


def workspace_for(args):
    """A workspace holding the texts ``--text`` names (default: the shipped ones), and those
    texts; ``--source`` must be one of them."""
    from quasicentral.engine.texts import TextError
    from quasicentral.engine.workspace import Workspace

    ws = Workspace(read_kept=not getattr(args, "no_cache", False))
    try:
        selected = ws.resolve(getattr(args, "texts", None))
    except TextError as exc:
        raise UsageError(f"--text {exc}" if not str(exc).startswith("/") else str(exc)) from None
    source = getattr(args, "source", None)
    if source is not None and source not in {t.id for t in selected}:
        raise UsageError(f"--source {source}: no such text among {', '.join(t.id for t in selected)}")
    return ws, selected


def selected_entries(args, ws, texts):
    """The entries ``--source`` and ``--id`` select among ``texts``."""
    everything = [e for t in texts for e in t.entries.values()]
    source = getattr(args, "source", None)
    entries = [e for e in everything if source is None or e.source == source]
    ids = getattr(args, "ids", None)
    if ids:
        known = {e.id for e in everything}
        for i in ids:
            if i not in known:
                raise UsageError(f"--id: unknown equation id {safe(repr(i))} (see `quasicentral catalog`)")
        in_source = {e.id for e in entries}
        outside = [i for i in ids if i not in in_source]
        if outside:
            raise UsageError(f"--id {outside[0]} is not in --source {source}: the selection would leave it out")
        entries = [e for e in entries if e.id in set(ids)]
    if not entries:
        raise UsageError("nothing selected: check --text, --source and --id")
    return entries


def options(args, **overrides):
    from quasicentral.engine.options import Options

    kw = dict(overrides)
    if getattr(args, "dps", None) is not None:
        kw["dps"] = args.dps
    if getattr(args, "timeout", None) is not None:
        kw["timeout"] = args.timeout
    try:
        return Options(**kw)  # the ladder's floor is the checker's (Options.MIN_DPS)
    except ValueError as exc:
        raise UsageError(f"--dps: {exc}") from None


def _replay_key(args) -> str | None:
    """The key of a whole cached ``verify`` run with these options (None: none can apply)."""
    from quasicentral.engine import fingerprint, replay

    folders = fingerprint.text_folders(args.texts)
    if folders is None:
        return None  # the full reader says what is wrong with the names
    # the timeout too: a verdict that ran out of time is read back only under no longer a timeout
    opts = {"source": args.source, "ids": args.ids, "dps": args.dps, "json": args.json,
            "junit": args.junit is not None, "timeout": args.timeout}
    return replay.key("verify", opts, folders)


def verify(args) -> int:
    from quasicentral.engine import replay

    if args.junit is not None and not args.junit.strip():
        raise UsageError("--junit needs a file name")
    t0 = time.perf_counter()
    key = None if args.no_cache else _replay_key(args)
    if key is not None:
        try:
            rec = replay.load(key)
        except replay.ReplayError as exc:
            warn(f"cache: {exc}; discarded, recomputed")
            rec = None
        if rec is not None:  # nothing the run depends on has changed since
            if args.junit:
                write_atomic(Path(args.junit), rec.junit or "", "--junit")
            sys.stdout.write(rec.stdout)
            timing(args, f"verify: {entries_text(rec.entries)} read back in {time.perf_counter() - t0:.1f} s "
                         "(a cached run: nothing it depends on has changed)")
            return rec.exit
    return _verify_run(args, key, t0)


def _verify_run(args, key: str | None, t0: float) -> int:
    from quasicentral.engine import formats as output
    from quasicentral.engine import replay, run

    opts = options(args)
    ws, texts = workspace_for(args)
    entries = selected_entries(args, ws, texts)
    with ProgressBar(args, "verify") as bar:
        outcomes = run.run(ws, entries, opts, use_cache=not args.no_cache, jobs=args.jobs, progress=bar,
                           on_warning=warn)
    seconds = time.perf_counter() - t0
    doc = output.verify_document(entries, outcomes)
    junit = output.junit_xml(entries, outcomes) if args.junit else None
    if args.junit:
        write_atomic(Path(args.junit), junit, "--junit")
    shown = (json.dumps(doc, indent=2, sort_keys=False, ensure_ascii=False) if args.json
             else safe(output.verify_table(doc))) + "\n"
    sys.stdout.write(shown)
    cached = bar.last.cached if bar.last else 0
    timing(args, f"verify: checked {entries_text(len(entries))} in {seconds:.1f} s "
                 f"(computed: {len(entries) - cached}, read from the cache: {cached})")
    code = EXIT_OK if doc["summary"]["ok"] else EXIT_UNEXPECTED
    if key is not None:
        keys = run.cache_keys(ws, entries, opts)
        digests = {run.cache_file(keys[e.id]).name: replay.digest(run.cache_file(keys[e.id])) for e in entries}
        depends = replay.dependencies(ws, [e.id for e in entries])
        if all(digests.values()) and depends is not None:  # every verdict is in the cache: replayable
            replay.store(key, replay.Record(stdout=shown, exit=code, entries=len(entries), junit=junit,
                                            verdicts=digests, depends=depends))
    return code


def errata(args) -> int:
    """Exit 0 when every erratum still stands and every suspect is cleared, 1 otherwise."""
    from quasicentral.engine import formats as output
    from quasicentral.engine import run

    ws, texts = workspace_for(args)
    entries = selected_entries(args, ws, texts)
    with ProgressBar(args, "errata") as bar:
        outcomes = run.run(ws, entries, options(args), use_cache=not args.no_cache, progress=bar, on_warning=warn)
    doc = output.errata_document(entries, outcomes)
    if args.json:
        print(json.dumps(doc, indent=2, ensure_ascii=False))
    else:
        print(safe(output.errata_table(doc)))
    recorded = [o for o in outcomes if o.records is not None and (o.records.erratum or o.records.cleared)]
    return EXIT_OK if all(o.ok for o in recorded) else EXIT_UNEXPECTED


def mutate(args) -> int:
    from quasicentral.engine import mutate as mutation

    t0 = time.perf_counter()
    ws, texts = workspace_for(args)
    if getattr(args, "source", None):
        texts = [t for t in texts if t.id == args.source]
    with ProgressBar(args, "mutate") as bar:
        res = mutation.run(ws, texts, per_entry=args.per_entry, jobs=args.jobs, progress=bar,
                           timeout=options(args).timeout)
    seconds = time.perf_counter() - t0
    if args.json:
        print(json.dumps(res, indent=2, ensure_ascii=False))
    else:
        print(safe(mutation.table(res)))
    timing(args, f"mutate: {res['mutants']} mutants of {entries_text(res['entries'])} checked in {seconds:.1f} s")
    return EXIT_OK if mutation.passed(res) else EXIT_UNEXPECTED


def catalog(args) -> int:
    from quasicentral.engine import formats as output
    from quasicentral.engine import latexparse

    ws, texts = workspace_for(args)
    entries = selected_entries(args, ws, texts)
    t0 = time.perf_counter()
    with ProgressBar(args, "catalog") as bar:
        cov = latexparse.coverage(entries, progress=bar, use_cache=not args.no_cache,
                                  seconds=options(args).timeout)
    seconds = time.perf_counter() - t0
    doc = output.catalog_document(entries, cov)
    if args.json:
        print(json.dumps(doc, indent=2, ensure_ascii=False))
    else:
        print(safe(output.catalog_table(doc)))
    timing(args, f"catalog: parsed the LaTeX of {entries_text(len(entries))} in {seconds:.1f} s "
                 f"(parsed: {len(entries) - cov['cached']}, read from the cache: {cov['cached']})")
    return EXIT_OK


@contextmanager
def writing(option: str, target):
    """Turn a refused or failed write into one line naming ``option`` (exit 2)."""
    from quasicentral.files import UnsafePath

    name = f"{option}: " if option else ""
    try:
        yield
    except UnsafePath as exc:
        raise UsageError(f"{name}{exc}") from None
    except OSError as exc:
        raise UsageError(f"{name}cannot write to {target}: {exc.strerror or exc}") from None


def write_atomic(path: Path, text: str, option: str = "") -> None:
    """Write via a temporary file and rename, so a failure never leaves a half-written file;
    a symbolic link at ``path`` is refused."""
    from quasicentral.files import write_text

    with writing(option, path):
        path.parent.mkdir(parents=True, exist_ok=True)
        write_text(path, text)


def out_dir(args) -> Path:
    if not args.out.strip():
        raise UsageError("--out needs a directory name")
    return Path(args.out)


def figures(args) -> int:
    from quasicentral.studies import figures as figures_mod

    out = out_dir(args)
    ws, texts = workspace_for(args)
    with writing("--out", args.out), ProgressBar(args, "figures") as bar:
        paths = figures_mod.write_all(out, texts, progress=bar)
    for p in paths:
        print(p)
    return EXIT_OK


def report(args) -> int:
    from quasicentral.documents import report as reports

    if args.all and (args.handout or args.lang is not None):
        raise UsageError("--all writes every document: leave out --handout and --lang")
    out = out_dir(args)
    with writing("--out", args.out):
        reports.check_writable(out)
    ws, texts = workspace_for(args)  # the texts named by --text (default: the shipped ones) are the ones built
    if args.all:
        jobs = list(reports.GOLDEN)
    else:
        jobs = [(reports.HANDOUT_KINDS if args.handout else ("report",), (args.lang or "en",))]
    t0 = time.perf_counter()
    with ProgressBar(args, "report") as bar:
        records = reports.records_for(ws, texts, options(args), progress=bar, on_warning=warn)
        docs: dict[str, str] = {}
        for kinds, langs in jobs:
            docs.update(reports.generate(records, kinds, langs))
        with writing("--out", args.out):
            paths = reports.write(out, dict(sorted(docs.items())), [r.text for r in records], progress=bar)
    for p in paths:
        print(p)
    if args.pdf:
        try:
            with writing("--out", args.out), ProgressBar(args, "report") as bar:
                pdfs = reports.compile_all(out, [n for n in sorted(docs) if n != reports.VERSIONS_FILE], progress=bar)
        except reports.LatexError as exc:
            error(str(exc))
            return EXIT_UNEXPECTED
        for p in pdfs:
            print(p)
    timing(args, f"report: wrote {len(paths)} files{' and compiled them' if args.pdf else ''} "
                 f"in {time.perf_counter() - t0:.1f} s")
    return EXIT_OK


def new_text(args) -> int:
    from quasicentral.engine import skeleton

    if not args.dir.strip():
        raise UsageError("new-text: DIR is an empty name (give the new text's folder)")
    try:
        paths = skeleton.write(Path(args.dir), args.text_id)
    except skeleton.SkeletonError as exc:
        raise UsageError(str(exc)) from None
    for p in paths:
        print(p)
    print(f"next: quasicentral verify --text {args.dir}", file=sys.stderr)
    return EXIT_OK
