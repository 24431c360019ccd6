"""Verify the catalog: each entry's verdict against what is expected of it, cached by content.

An outcome's status is ``verified`` (printed = derived), ``erratum`` (printed refuted and the
registered correction verified), ``cleared`` (a registered suspicion that verified), or
``unexpected`` (anything else: a new mismatch, a "typo" that turned out right, an
inconclusive entry).  Verdicts are cached under a hash of the code, the entry's text and the
options; a record also names every other text its derivations were built on, with their
hashes, and is read back only while those are unchanged.  ``use_cache=False`` forces a cold
run.  Each entry is checked within its budget (``Options.timeout``, wall-clock and CPU time):
past it, or where anything fails, the entry is inconclusive with the reason — never the run.
"""

from __future__ import annotations

import hashlib
import json
import os
import pickle
import sys
from contextlib import contextmanager
from pathlib import Path

from quasicentral.engine import catalog
from quasicentral.engine.checker import Options, check
from quasicentral.engine.fingerprint import cache_dir, code_fingerprint
from quasicentral.engine.identity import identity_derivation
from quasicentral.engine.reasons import Code, Reason
from quasicentral.engine.registry import Mode
from quasicentral.engine.verdict import (NOTATION_CODES, EntryRecords, Inconclusive, Method, Outcome, Refuted, Status,
                                         Verified)
from quasicentral.engine.workers import map_grouped
from quasicentral.files import read_private, write_text
from quasicentral.notation.timelimit import CPU, WALL, TimeLimitExceeded, time_limit
from quasicentral.progress import OptionalCallback, notify

CACHE_FORMAT = "3"  # 3: typed reasons


def records_of(ws, eid: str) -> EntryRecords:
    """The text's records of entry ``eid``: its erratum, cleared suspicion and causes."""
    text = ws.text(eid.split(":", 1)[0])
    err = text.errata.get(eid)
    causes = tuple(text.causes[c] for c in err.causes if c in text.causes) if err is not None else ()
    return EntryRecords(err, text.cleared.get(eid), causes)


def _error(exc: BaseException) -> str:
    if isinstance(exc, SystemExit):
        return f"the derivation calls sys.exit({exc.code!r})"
    if isinstance(exc, TimeLimitExceeded):
        return f"ran out of its time budget ({exc})"
    return f"{type(exc).__name__}: {exc}"[:300]


def derivation_of(ws, entry: catalog.Entry):
    """The derivation that settles ``entry``: its text's, or — in an identity text, where the
    entry has none — the entry's own relation checked as it stands."""
    der = ws.derivation(entry.id)
    if der is None and ws.text(entry.source).check == "identity":
        text = ws.text(entry.source)
        der = identity_derivation(entry, tuple(text.entries[i] for i in entry.rests_on if i in text.entries))
    return der


def verify_entry(ws, entry: catalog.Entry, opts: Options) -> Outcome:
    """The outcome of one entry, within its budget; any failure is this entry's."""
    records = records_of(ws, entry.id)
    wall = cpu = None
    try:
        with time_limit(opts.timeout, WALL) as wall, time_limit(opts.timeout, CPU) as cpu:
            return _verify_entry(ws, entry, opts, records)
    except TimeLimitExceeded as exc:
        if not ((wall is not None and wall.owns(exc)) or (cpu is not None and cpu.owns(exc))):
            raise
        reason = Reason.of(Code.OUT_OF_TIME, stage="check", seconds=opts.timeout, clock=exc.limit.clock.value)
    except KeyboardInterrupt:
        raise
    except BaseException as exc:  # noqa: BLE001 - anything that fails is this entry's, never the run's
        reason = Reason.of(Code.STAGE_FAILED, stage="check", error=_error(exc))
    v = Inconclusive(Method.NONE, reason)
    return Outcome(entry.id, v, Status.UNEXPECTED, records.erratum is not None,
                   problems=(Reason.of(Code.UNEXPECTED_VERDICT, verdict=v.name, reason=v.reason),), records=records)


def _verify_entry(ws, entry: catalog.Entry, opts: Options, records: EntryRecords) -> Outcome:
    derivation = derivation_of(ws, entry)
    if derivation is None:
        v = Inconclusive(Method.NONE, Reason(Code.NO_DERIVATION))
        return Outcome(entry.id, v, Status.UNEXPECTED, problems=(Reason(Code.NO_DERIVATION_PROBLEM),), records=records)
    result, failed = None, None
    try:
        result = ws.result(entry.id) if derivation.func is not None else {}
    except (KeyboardInterrupt, TimeLimitExceeded):
        raise
    except BaseException as exc:  # noqa: BLE001 - a failing derivation (even its sys.exit) is this entry's
        failed = _error(exc)
    v = check(entry.relations(roundings=derivation.mode is Mode.IDENTITY), entry.dims, derivation, entry.id, opts,
              entry.symbols, result, failed)
    noted = _uses_checked(ws, derivation, failed)
    rec = records.erratum
    if rec is not None:
        # the same points as the printed form (one seed): the printed and the corrected value
        # are compared with the same derived one
        cv = check(rec.relations(), entry.dims, derivation, entry.id, opts, entry.symbols, result, failed)
        problems = []
        if not isinstance(v, Refuted):
            problems.append(Reason.of(Code.ERRATUM_NOT_REFUTED, verdict=v.name))
        if not isinstance(cv, Verified):
            problems.append(Reason.of(Code.CORRECTION_NOT_VERIFIED, verdict=cv.name, reason=cv.reason))
        status = Status.UNEXPECTED if problems else Status.ERRATUM
        return Outcome(entry.id, v, status, True, cv, tuple(problems) + noted, records)
    if records.cleared is not None:
        status = Status.CLEARED if isinstance(v, Verified) else Status.UNEXPECTED
        problems = () if status.ok else (Reason.of(Code.CLEARED_NOT_VERIFIED, verdict=v.name),)
        return Outcome(entry.id, v, status, problems=problems + noted, records=records)
    if isinstance(v, Verified):
        return Outcome(entry.id, v, Status.VERIFIED, problems=noted, records=records)
    if isinstance(v, Inconclusive) and v.reason.code in NOTATION_CODES:
        # a definition or notation: nothing to check, nothing unexpected
        return Outcome(entry.id, v, Status.NOTATION, problems=noted, records=records)
    return Outcome(entry.id, v, Status.UNEXPECTED, problems=(Reason.of(Code.UNEXPECTED_VERDICT, verdict=v.name,
                                                                      reason=v.reason),), records=records)


def _uses_checked(ws, derivation, failed) -> tuple[Reason, ...]:
    """A note where a derivation's declared ``uses=`` differs from what it used (the documents
    cite what it used; the status does not change)."""
    if failed is not None or not derivation.declared_uses or derivation.func is None \
            or not ws.derivations.known(derivation.id):
        return ()
    used = ws.used(derivation.id)
    if set(derivation.declared_uses) == used:
        return ()
    return (Reason.of(Code.USES_MISMATCH, declared=tuple(derivation.declared_uses), used=tuple(sorted(used))),)


def lost_outcome(eid: str, why: str, records: EntryRecords) -> Outcome:
    """The outcome of an entry whose worker was lost (killed past its budget, or ended)."""
    v = Inconclusive(Method.NONE, Reason.of(Code.STAGE_FAILED, stage="check", error=why))
    return Outcome(eid, v, Status.UNEXPECTED, records.erratum is not None,
                   problems=(Reason.of(Code.UNEXPECTED_VERDICT, verdict=v.name, reason=v.reason),), records=records)


class CacheWarning(UserWarning):
    """A cached verdict was discarded (wrong shape, or contradicting the errata registry)."""


def cached_problem(ws, eid: str, d: object) -> str | None:
    """Why a cached outcome cannot be trusted, or None.  The cache is checked, not trusted: an
    entry of the wrong shape, or whose status contradicts the errata registry or its own
    verdicts, is recomputed."""
    try:
        o = Outcome.from_record(d["outcome"])  # type: ignore[index]
        built_on = d["built_on"]  # type: ignore[index]
        if not isinstance(built_on, dict):
            raise TypeError("built_on")
    except (KeyError, TypeError, ValueError, AttributeError) as exc:
        return f"wrong shape ({type(exc).__name__}: {exc})"
    if o.id != eid:
        return f"it is the outcome of {o.id!r}"
    for tid, fp in built_on.items():
        try:
            if ws.text(tid).fingerprint() != fp:
                return f"it was built on text {tid!r} as it was before an edit"
        except KeyError:
            return f"it was built on text {tid!r}, which is not open"
    text = ws.text(eid.split(":", 1)[0])
    allowed = ((Status.ERRATUM,) if eid in text.errata else (Status.CLEARED,) if eid in text.cleared
               else (Status.VERIFIED, Status.NOTATION))
    if o.status not in allowed + (Status.UNEXPECTED,):
        return (f"cached status {o.status.value!r} contradicts the errata registry "
                f"(expected {' or '.join(a.value for a in allowed)})")
    if o.status is Status.NOTATION and not (isinstance(o.verdict, Inconclusive) and o.verdict.reason.code in NOTATION_CODES):
        return f"cached status 'notation' with a {o.verdict.name} verdict"
    if o.status in (Status.VERIFIED, Status.CLEARED) and not isinstance(o.verdict, Verified):
        return f"cached status {o.status.value!r} with a {o.verdict.name} verdict"
    if o.status is Status.ERRATUM and not (isinstance(o.verdict, Refuted)
                                           and isinstance(o.corrected_verdict, Verified)):
        return "cached erratum whose printed form is not refuted or whose correction is not verified"
    return None


def cache_keys(ws, entries: list[catalog.Entry], opts: Options) -> dict[str, str]:
    """Each entry's key in the verdict cache: the code, its text's files, its id, the options."""
    fp = code_fingerprint()
    text_fp = {t.id: t.fingerprint() for t in {ws.text(e.source) for e in entries}}
    return {e.id: hashlib.sha256(json.dumps([CACHE_FORMAT, fp, text_fp[e.source], e.id, opts.cache_key()],
                                            sort_keys=True).encode()).hexdigest() for e in entries}


def _out_of_time(record: dict) -> bool:
    """Whether an outcome's record is the timeout's (the check or its corrected form ran out of
    time).  The cache key leaves the timeout out (it bounds the work); such a record keeps the
    timeout it ran under and is read back only by a run with no longer a timeout."""
    o = record.get("outcome", {})
    return any((v or {}).get("reason", {}).get("code") == Code.OUT_OF_TIME.value
               for v in (o.get("verdict"), o.get("corrected_verdict")))


def cache_file(key: str) -> Path:
    return cache_dir() / f"{key}.json"


def _read_cached(ws, entries, key_of, warn, timeout: float) -> dict[str, dict]:
    results = {}
    for e in entries:
        data = read_private(cache_dir(), cache_file(key_of[e.id]).name)
        if data is None:
            continue
        try:
            d = json.loads(data)
        except ValueError:
            warn(f"cache: {e.id}: unreadable cached verdict discarded, recomputed")
            continue
        problem = cached_problem(ws, e.id, d)
        if problem:
            warn(f"cache: {e.id}: {problem}; discarded, recomputed")
            continue
        if isinstance(d, dict) and _out_of_time(d) and not (isinstance(d.get("timeout"), (int, float))
                                                             and d["timeout"] >= timeout):
            continue  # it ran out of a shorter time than this run allows: a longer one may settle it
        results[e.id] = d
    return results


def run(ws, entries: list[catalog.Entry], opts: Options, use_cache: bool = True, jobs: int | None = None,
        progress: OptionalCallback = None, on_warning=None, isolate: bool = True) -> list[Outcome]:
    """Outcomes for ``entries`` in catalog order (cached ones read back, the rest computed).

    ``progress``, if given, is called with a :class:`quasicentral.progress.Progress` once the
    cache has been read (``done`` = ``cached`` = the entries read back) and after each computed
    entry (``current`` = its id); it is called in this process, never in a worker.  A cached
    outcome that fails :func:`cached_problem` is discarded and recomputed; each such event is
    reported once through ``on_warning(text)`` (default: :class:`CacheWarning` via
    :mod:`warnings`) — the library never prints.  ``isolate`` (default) runs the texts' code in
    supervised worker processes (a text's ``sys.exit``, crash or hang ends only its entry); with
    ``isolate=False`` and one job, everything runs in this process."""
    import warnings

    def warn(text: str) -> None:
        if on_warning is not None:
            on_warning(text)
        else:
            warnings.warn(text, CacheWarning, stacklevel=3)

    selected = list(dict.fromkeys(ws.text(e.source) for e in entries))
    for t in selected:
        t.validate()  # a mistake in a folder's data is named now (file and line), not in a worker
    ws.survey(selected, opts.timeout)  # a folder's modules run in a child: never in this process
    key_of = cache_keys(ws, entries, opts)
    results = _read_cached(ws, entries, key_of, warn, opts.timeout) if use_cache else {}
    todo = [e.id for e in entries if e.id not in results]
    cached = len(results)
    notify(progress, cached, len(entries), "cache" if cached else "", cached, "entries")
    ws.derivations.read_kept = ws.derivations.read_kept and use_cache
    _compute(ws, todo, opts, jobs, results, progress, len(entries), cached, isolate)
    if todo:
        try:
            cache_dir().mkdir(parents=True, exist_ok=True)
            for eid in todo:
                # a verdict the timeout decided is kept with that timeout: a longer one recomputes it
                kept = {**results[eid], "timeout": opts.timeout} if _out_of_time(results[eid]) else results[eid]
                write_text(cache_file(key_of[eid]), json.dumps(kept, sort_keys=True))
        except OSError:
            pass  # a read-only cache is not an error
    for e in entries:
        ws.derivations.note_built_on(e.id, set(results[e.id].get("built_on", {})) | {e.source})
    return [Outcome.from_record(results[e.id]["outcome"], records_of(ws, e.id)) for e in entries]


def _record(ws, eid: str, outcome: Outcome) -> dict:
    """An outcome as the cache keeps it, with the hashes of the other texts it was built on."""
    known = ws.derivations.known_built_on(eid)  # nothing is derived here: a failure is built on nothing
    others = sorted((known or set()) - {eid.split(":", 1)[0]})
    built = {}
    for tid in others:
        try:
            built[tid] = ws.text(tid).fingerprint()
        except KeyError:
            pass
    return {"outcome": outcome.to_record(), "built_on": built}


def _compute(ws, todo: list[str], opts: Options, jobs: int | None, results: dict, progress: OptionalCallback,
             total: int, cached: int, isolate: bool) -> None:
    """The outcomes of ``todo`` into ``results``, on ``jobs`` forked workers (at least one
    when ``isolate``)."""
    if not todo:
        return
    jobs = jobs or min(len(todo), os.cpu_count() or 1)

    def work(eid: str):
        with quiet_stdout():
            return eid, _record(ws, eid, verify_entry(ws, ws.entry(eid), opts))

    def lost(eid: str, why: str):
        return eid, {"outcome": lost_outcome(eid, why, records_of(ws, eid)).to_record(), "built_on": {}}

    def done(_eid, got) -> None:
        eid, res = got
        results[eid] = res
        notify(progress, len(results), total, eid, cached, "entries")

    if isolate or jobs > 1:
        map_grouped(work, families(ws, todo), max(jobs, 1), done, timeout=opts.timeout, on_lost=lost)
    else:
        for eid in todo:
            done(eid, work(eid))


@contextmanager
def quiet_stdout():
    """What a text's code prints goes to standard error, never into a command's output."""
    before = sys.stdout
    sys.stdout = sys.stderr
    try:
        yield
    finally:
        sys.stdout = before


def derive_all(ws, ids: list[str], opts: Options, jobs: int | None = None) -> None:
    """The results of the derivations of ``ids`` computed in supervised workers (each within its
    budget) and brought into this process's workspace — so that a folder's code runs nowhere
    else.  A result that cannot be brought back (it holds a class of the folder's own module) is
    left to be computed here when it is asked for; a derivation that fails is recorded so."""
    todo = [eid for eid in ids if not ws.derivations.known(eid) and ws.has_derivation(eid)]
    if not todo:
        return

    def work(eid: str):
        with quiet_stdout():
            with time_limit(opts.timeout, WALL), time_limit(opts.timeout, CPU):
                try:
                    value = ws.result(eid)
                except (Exception, SystemExit, GeneratorExit) as exc:  # noqa: BLE001 - the entry's failure
                    return eid, {"error": _error(exc)}
            try:
                blob = pickle.dumps(value, protocol=pickle.HIGHEST_PROTOCOL)
            except Exception:  # noqa: BLE001 - not sendable: computed where it is needed
                return eid, {"local": True}
            return eid, {"result": blob, "used": sorted(ws.used(eid)), "built_on": sorted(ws.built_on(eid))}

    def done(_eid, got) -> None:
        eid, res = got
        if "error" in res:
            ws.derivations.note_failure(eid, res["error"])
        elif "result" in res:
            try:
                value = pickle.loads(res["result"])
            except Exception:  # noqa: BLE001 - a class this process does not know: computed here if asked
                return
            ws.derivations.inject(eid, value, res["used"], res["built_on"])

    map_grouped(work, families(ws, todo), jobs or min(len(todo), os.cpu_count() or 1), done, timeout=opts.timeout,
                on_lost=lambda eid, why: (eid, {"error": f"the derivation's worker was lost: {why}"}))


def families(ws, ids: list[str]) -> list[list[str]]:
    """``ids`` grouped by the module of their derivations (entries of one family build on the
    same steps: a worker that keeps to one derives them once), in catalog order."""
    out: dict[str, list[str]] = {}
    for eid in ids:
        out.setdefault(ws.module_of(eid) or "", []).append(eid)
    return list(out.values())


def summary(outcomes: list[Outcome]) -> dict:
    by_status: dict[str, int] = {}
    by_verdict: dict[str, int] = {}
    by_method: dict[str, int] = {}
    for o in outcomes:
        by_status[o.status.value] = by_status.get(o.status.value, 0) + 1
        by_verdict[o.verdict.name] = by_verdict.get(o.verdict.name, 0) + 1
        by_method[o.verdict.method.value] = by_method.get(o.verdict.method.value, 0) + 1
    causes = sorted({(o.id.split(":", 1)[0], c.id) for o in outcomes if o.status is Status.ERRATUM for c in o.causes})
    return {
        "entries": len(outcomes),
        "causes": len(causes),
        "status": dict(sorted(by_status.items())),
        "verdicts": dict(sorted(by_verdict.items())),
        "methods": dict(sorted(by_method.items())),
        "unexpected": [o.id for o in outcomes if not o.ok],
        "ok": all(o.ok for o in outcomes),
    }
