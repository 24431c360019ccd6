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
from concurrent.futures import ProcessPoolExecutor
from dataclasses import asdict
from multiprocessing import get_context
from pathlib import Path

from quasicentral.engine import catalog

from quasicentral.engine import errata
from quasicentral.engine.checker import Options, check
from quasicentral.files import write_text
from quasicentral.engine.registry import REGISTRY, load_all
from quasicentral.engine.verdict import Inconclusive, Method, Outcome, Refuted, Verdict, Verified

CACHE_VERSION = "1"


def cache_dir() -> Path:
    base = os.environ.get("QUASICENTRAL_CACHE") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "quasicentral")
    return Path(base)


def code_fingerprint() -> str:
    """Hash of every source and data file of the library and the derivations, and of the
    versions of the libraries that compute the verdicts."""
    import derivations

    from importlib import metadata

    h = hashlib.sha256(CACHE_VERSION.encode())
    for dist in ("sympy", "mpmath", "python-flint", "numpy", "scipy"):  # their answers are the verdicts'
        try:
            h.update(f"{dist}={metadata.version(dist)}".encode())
        except metadata.PackageNotFoundError:
            h.update(dist.encode())
    for pkg in (Path(__file__).parent.parent, Path(derivations.__file__).parent):
        for path in sorted(pkg.rglob("*")):
            if path.suffix in (".py", ".toml") and "__pycache__" not in path.parts:
                h.update(path.relative_to(pkg.parent).as_posix().encode())
                h.update(path.read_bytes())
    return h.hexdigest()


def verify_entry(entry: catalog.Entry, opts: Options) -> Outcome:
    load_all()
    errs, cleared = errata.load()
    derivation = REGISTRY.get(entry.id)
    if derivation is None:
        v = Inconclusive(Method.NONE, "no derivation registered for this entry yet")
        return Outcome(entry.id, v, "unexpected", problems=("no derivation",))
    v = check(entry.relations(), entry.dims, derivation, entry.id, opts)
    rec = errs.get(entry.id)
    if rec is not None:
        # the same points as the printed form (one seed): the printed and the corrected value
        # are compared with the same derived one
        cv = check(rec.relations(), {**entry.dims}, derivation, entry.id, opts)
        problems = []
        if not isinstance(v, Refuted):
            problems.append(f"the printed form is {v.name}, not refuted: the registered erratum does not stand")
        if not isinstance(cv, Verified):
            problems.append(f"the corrected form is {cv.name}: {cv.detail}")
        return Outcome(entry.id, v, "unexpected" if problems else "erratum", True, cv, tuple(problems))
    if entry.id in cleared:
        status = "cleared" if isinstance(v, Verified) else "unexpected"
        return Outcome(entry.id, v, status, problems=() if status == "cleared" else (f"cleared suspect is {v.name}",))
    if isinstance(v, Verified):
        return Outcome(entry.id, v, "verified")
    return Outcome(entry.id, v, "unexpected", problems=(f"{v.name}: {v.detail}",))


def _outcome_json(o: Outcome) -> dict:
    return {"id": o.id, "verdict": o.verdict.to_json(), "status": o.status, "erratum": o.erratum,
            "corrected_verdict": o.corrected_verdict.to_json() if o.corrected_verdict else None,
            "problems": list(o.problems)}


def _outcome_from_json(d: dict) -> Outcome:
    cv = d.get("corrected_verdict")
    return Outcome(d["id"], Verdict.from_json(d["verdict"]), d["status"], d["erratum"],
                   Verdict.from_json(cv) if cv else None, tuple(d["problems"]))


def _worker(args):
    eid, opts = args
    return eid, _outcome_json(verify_entry(catalog.get(eid), opts))


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
    errs, cleared = errata.load()
    allowed = ("erratum",) if eid in errs else ("cleared",) if eid in cleared else ("verified",)
    if o.status not in allowed + ("unexpected",):
        return f"cached status {o.status!r} contradicts the errata registry (expected {' or '.join(allowed)})"
    if o.status in ("verified", "cleared") and not isinstance(o.verdict, Verified):
        return f"cached status {o.status!r} with a {o.verdict.name} verdict"
    if o.status == "erratum" and not (isinstance(o.verdict, Refuted) and isinstance(o.corrected_verdict, Verified)):
        return "cached erratum whose printed form is not refuted or whose correction is not verified"
    return None


def run(entries: list[catalog.Entry], opts: Options, use_cache: bool = True, jobs: int | None = None,
        on_warning=None) -> list[Outcome]:
    """Outcomes for ``entries`` in catalog order (cached ones read back, the rest computed).

    A cached outcome that fails :func:`cached_problem` is discarded and recomputed; each such
    event is reported once through ``on_warning(text)`` (default: :class:`CacheWarning` via
    :mod:`warnings`) — the library never prints."""
    import warnings

    def warn(text: str) -> None:
        if on_warning is not None:
            on_warning(text)
        else:
            warnings.warn(text, CacheWarning, stacklevel=3)

    fp = code_fingerprint()
    key_of = {e.id: hashlib.sha256(json.dumps([fp, e.id, asdict(opts)], sort_keys=True).encode()).hexdigest()
              for e in entries}
    results: dict[str, dict] = {}
    cdir = cache_dir()
    if use_cache:
        for e in entries:
            f = cdir / f"{key_of[e.id]}.json"
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
    if todo:
        load_all()
        jobs = jobs or min(len(todo), os.cpu_count() or 1)
        if jobs > 1 and len(todo) > 1:
            # the costly entries (quadratures) first, so that the workers finish together
            import sympy as sp

            by_cost = sorted(todo, key=lambda i: not catalog.get(i).printed.has(sp.Integral))
            with ProcessPoolExecutor(max_workers=jobs, mp_context=get_context("fork")) as pool:
                for eid, res in pool.map(_worker, [(i, opts) for i in by_cost], chunksize=1):
                    results[eid] = res
        else:
            for eid in todo:
                results[eid] = _worker((eid, opts))[1]
        try:
            cdir.mkdir(parents=True, exist_ok=True)
            for eid in todo:
                write_text(cdir / f"{key_of[eid]}.json", json.dumps(results[eid], sort_keys=True))
        except OSError:
            pass  # a read-only cache is not an error
    return [_outcome_from_json(results[e.id]) for e in entries]


def summary(outcomes: list[Outcome]) -> dict:
    by_status: dict[str, int] = {}
    by_verdict: dict[str, int] = {}
    by_method: dict[str, int] = {}
    for o in outcomes:
        by_status[o.status] = by_status.get(o.status, 0) + 1
        by_verdict[o.verdict.name] = by_verdict.get(o.verdict.name, 0) + 1
        by_method[o.verdict.method.value] = by_method.get(o.verdict.method.value, 0) + 1
    errs, _ = errata.load()
    causes = sorted({c for o in outcomes if o.status == "erratum" for c in errs[o.id].causes})
    return {
        "entries": len(outcomes),
        "causes": len(causes),
        "status": dict(sorted(by_status.items())),
        "verdicts": dict(sorted(by_verdict.items())),
        "methods": dict(sorted(by_method.items())),
        "unexpected": [o.id for o in outcomes if not o.ok],
        "ok": all(o.ok for o in outcomes),
    }
