"""Verify the catalog: each entry's verdict against what is expected of it, cached by content.

An outcome's status is ``verified`` (printed = derived), ``erratum`` (printed refuted and the
registered correction verified), ``cleared`` (a registered suspicion that verified), or
``unexpected`` (anything else: a new mismatch, a "typo" that turned out right, an
inconclusive entry).  Verdicts are cached under a hash of the code, the catalog, the errata
and the options, so a second run reads them back; ``use_cache=False`` forces a cold run.
"""

from __future__ import annotations

import hashlib
import json
import os
from dataclasses import asdict
from pathlib import Path

from quasicentral.engine import catalog, texts
from quasicentral.engine.fingerprint import cache_dir, code_fingerprint
from quasicentral.engine.checker import Options, check
from quasicentral.engine.registry import REGISTRY, reading_kept
from quasicentral.engine.workers import map_grouped
from quasicentral.engine.verdict import Inconclusive, Method, Outcome, Refuted, Status, Verdict, Verified
from quasicentral.files import write_text
from quasicentral.progress import OptionalCallback, notify


def verify_entry(entry: catalog.Entry, opts: Options) -> Outcome:
    text = texts.text_of(entry.id)
    derivation = REGISTRY.get(entry.id)
    if derivation is None:
        v = Inconclusive(Method.NONE, "no derivation registered for this entry yet")
        return Outcome(entry.id, v, Status.UNEXPECTED, problems=("no derivation",))
    v = check(entry.relations(), entry.dims, derivation, entry.id, opts, entry.symbols)
    rec = text.errata.get(entry.id)
    if rec is not None:
        # the same points as the printed form (one seed): the printed and the corrected value
        # are compared with the same derived one
        cv = check(rec.relations(), {**entry.dims}, derivation, entry.id, opts, entry.symbols)
        problems = []
        if not isinstance(v, Refuted):
            problems.append(f"the printed form is {v.name}, not refuted: the registered erratum does not stand")
        if not isinstance(cv, Verified):
            problems.append(f"the corrected form is {cv.name}: {cv.detail}")
        return Outcome(entry.id, v, Status.UNEXPECTED if problems else Status.ERRATUM, True, cv, tuple(problems))
    if entry.id in text.cleared:
        status = Status.CLEARED if isinstance(v, Verified) else Status.UNEXPECTED
        return Outcome(entry.id, v, status, problems=() if status.ok else (f"cleared suspect is {v.name}",))
    if isinstance(v, Verified):
        return Outcome(entry.id, v, Status.VERIFIED)
    return Outcome(entry.id, v, Status.UNEXPECTED, problems=(f"{v.name}: {v.detail}",))


def _outcome_json(o: Outcome) -> dict:
    return {"id": o.id, "verdict": o.verdict.to_json(), "status": o.status.value, "erratum": o.erratum,
            "corrected_verdict": o.corrected_verdict.to_json() if o.corrected_verdict else None,
            "problems": list(o.problems)}


def _outcome_from_json(d: dict) -> Outcome:
    cv = d.get("corrected_verdict")
    return Outcome(d["id"], Verdict.from_json(d["verdict"]), Status(d["status"]), d["erratum"],
                   Verdict.from_json(cv) if cv else None, tuple(d["problems"]))


def _worker(args):
    eid, opts = args
    return eid, _outcome_json(verify_entry(texts.entry(eid), opts))


class CacheWarning(UserWarning):
    """A cached verdict was discarded (wrong shape, or contradicting the errata registry)."""


def cached_problem(eid: str, d: object) -> str | None:
    """Why a cached outcome cannot be trusted, or None.  The cache is checked, not trusted: an
    entry of the wrong shape, or whose status contradicts the errata registry or its own
    verdicts, is recomputed."""
    try:
        o = _outcome_from_json(d)  # type: ignore[arg-type]
    except (KeyError, TypeError, ValueError, AttributeError) as exc:
        return f"wrong shape ({type(exc).__name__}: {exc})"
    if o.id != eid:
        return f"it is the outcome of {o.id!r}"
    text = texts.text_of(eid)
    allowed = ((Status.ERRATUM,) if eid in text.errata else (Status.CLEARED,) if eid in text.cleared
               else (Status.VERIFIED,))
    if o.status not in allowed + (Status.UNEXPECTED,):
        return (f"cached status {o.status.value!r} contradicts the errata registry "
                f"(expected {' or '.join(a.value for a in allowed)})")
    if o.status in (Status.VERIFIED, Status.CLEARED) and not isinstance(o.verdict, Verified):
        return f"cached status {o.status.value!r} with a {o.verdict.name} verdict"
    if o.status is Status.ERRATUM and not (isinstance(o.verdict, Refuted)
                                           and isinstance(o.corrected_verdict, Verified)):
        return "cached erratum whose printed form is not refuted or whose correction is not verified"
    return None


def cache_keys(entries: list[catalog.Entry], opts: Options) -> dict[str, str]:
    """Each entry's key in the verdict cache: the code, its text's files, its id, the options."""
    fp = code_fingerprint()
    text_fp = {t.id: t.fingerprint() for t in {texts.text_of(e.id) for e in entries}}
    return {e.id: hashlib.sha256(json.dumps([fp, text_fp[e.text], e.id, asdict(opts)], sort_keys=True).encode()
                                 ).hexdigest() for e in entries}


def cache_file(key: str) -> Path:
    return cache_dir() / f"{key}.json"


def run(entries: list[catalog.Entry], opts: Options, use_cache: bool = True, jobs: int | None = None,
        progress: OptionalCallback = None, on_warning=None) -> list[Outcome]:
    """Outcomes for ``entries`` in catalog order (cached ones read back, the rest computed).

    ``progress``, if given, is called with a :class:`quasicentral.progress.Progress` once the
    cache has been read (``done`` = ``cached`` = the entries read back) and after each computed
    entry (``current`` = its id); it is called in this process, never in a worker.  A cached
    outcome that fails :func:`cached_problem` is discarded and recomputed; each such event is
    reported once through ``on_warning(text)`` (default: :class:`CacheWarning` via
    :mod:`warnings`) — the library never prints."""
    import warnings

    def warn(text: str) -> None:
        if on_warning is not None:
            on_warning(text)
        else:
            warnings.warn(text, CacheWarning, stacklevel=3)

    key_of = cache_keys(entries, opts)
    results: dict[str, dict] = {}
    cdir = cache_dir()
    if use_cache:
        for e in entries:
            f = cache_file(key_of[e.id])
            if f.is_file():
                try:
                    d = json.loads(f.read_text())
                except (OSError, ValueError):
                    warn(f"cache: {e.id}: unreadable cached verdict discarded, recomputed")
                    continue
                problem = cached_problem(e.id, d)
                if problem:
                    warn(f"cache: {e.id}: {problem}; discarded, recomputed")
                    continue
                results[e.id] = d
    todo = [e.id for e in entries if e.id not in results]
    cached = len(results)
    notify(progress, cached, len(entries), "cache" if cached else "", cached, "entries")
    with reading_kept(use_cache):
        _compute(todo, opts, jobs, results, progress, len(entries), cached)
    if todo:
        try:
            cdir.mkdir(parents=True, exist_ok=True)
            for eid in todo:
                write_text(cache_file(key_of[eid]), json.dumps(results[eid], sort_keys=True))
        except OSError:
            pass  # a read-only cache is not an error
    return [_outcome_from_json(results[e.id]) for e in entries]


def _compute(todo: list[str], opts: Options, jobs: int | None, results: dict, progress: OptionalCallback,
             total: int, cached: int) -> None:
    """The outcomes of ``todo`` into ``results``, on ``jobs`` forked workers."""
    if not todo:
        return
    jobs = jobs or min(len(todo), os.cpu_count() or 1)
    if jobs > 1 and len(todo) > 1:
        def done(_args, got) -> None:
            eid, res = got
            results[eid] = res
            notify(progress, len(results), total, eid, cached, "entries")

        map_grouped(_worker, [[(i, opts) for i in g] for g in families(todo)], jobs, done)
    else:
        for eid in todo:
            results[eid] = _worker((eid, opts))[1]
            notify(progress, len(results), total, eid, cached, "entries")


def families(ids: list[str]) -> list[list[str]]:
    """``ids`` grouped by the module of their derivations (entries of one family build on the
    same steps: a worker that keeps to one derives them once), in catalog order."""
    out: dict[str, list[str]] = {}
    for eid in ids:
        der = REGISTRY.get(eid)
        out.setdefault(der.module if der is not None else "", []).append(eid)
    return list(out.values())


def summary(outcomes: list[Outcome]) -> dict:
    by_status: dict[str, int] = {}
    by_verdict: dict[str, int] = {}
    by_method: dict[str, int] = {}
    for o in outcomes:
        by_status[o.status.value] = by_status.get(o.status.value, 0) + 1
        by_verdict[o.verdict.name] = by_verdict.get(o.verdict.name, 0) + 1
        by_method[o.verdict.method.value] = by_method.get(o.verdict.method.value, 0) + 1
    causes = sorted({(o.id.split(":", 1)[0], c) for o in outcomes if o.status is Status.ERRATUM
                     for c in texts.text_of(o.id).errata[o.id].causes})
    return {
        "entries": len(outcomes),
        "causes": len(causes),
        "status": dict(sorted(by_status.items())),
        "verdicts": dict(sorted(by_verdict.items())),
        "methods": dict(sorted(by_method.items())),
        "unexpected": [o.id for o in outcomes if not o.ok],
        "ok": all(o.ok for o in outcomes),
    }
