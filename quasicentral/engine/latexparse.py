"""How much of the printed LaTeX sympy's own parsers can read, and whether they read it right.

Both backends of :func:`sympy.parsing.latex.parse_latex` are tried (ANTLR and Lark).  A parse
*counts* only if it agrees numerically with the hand transcription of the same entry, side by
side, at random points: a parse that reads ``\\frac{dx}{dt}`` as d·x/(d·t) does not count.
Parsed names are matched to the transcription's symbols by a normalised spelling
(``R_{0}``, ``R_o`` and ``R_0`` are all ``R0``; ``\\varrho`` is ``rho``; ``\\varphi`` is ``phi``).
"""

from __future__ import annotations

from types import MappingProxyType
import random
import re
import warnings

import mpmath
import sympy as sp

from quasicentral.notation import bridge
from quasicentral.engine.catalog import Entry

BACKENDS = ("antlr", "lark")

_PRE = tuple([
    (r"\\doteq", "="), (r"\\varrho", r"\\rho"), (r"\\varphi", r"\\phi"), (r"\\left\.|\\right\.", ""),
    (r"\\,|\\;|\\!|\\quad", " "), (r"\\text\{[^}]*\}", ""), (r"\\emptyset", "0"),
    (r"\\arccotg", r"\\operatorname{acot}"), (r"\\Big|\\big|\\Bigg|\\bigg", ""),
    (r"\\dots|\\ldots|\\cdots", ""), (r"[,.;]\s*$", ""),
])

_ALIASES = MappingProxyType({"varrho": "rho", "varphi": "phi", "vphi": "phi", "w": "psi", "th": "phi", "theta": "phi",
            "Ro": "R0", "vo": "v0", "varphi0": "phi0", "phi0": "phi0"})


def _normal(name: str) -> str:
    n = re.sub(r"[\\{}_ ]", "", name)
    n = re.sub(r"^([A-Za-z]+)o$", r"\g<1>0", n) if n in ("Ro", "vo") else n
    return _ALIASES.get(n, n)


def preprocess(latex: str) -> str:
    text = latex.strip()
    for pat, rep in _PRE:
        text = re.sub(pat, rep, text)
    return text


def _atoms_by_name(expr: sp.Basic, latex_of: dict[str, str]) -> dict[str, sp.Basic]:
    """The transcription's atoms by the normalised spelling of their name and of the LaTeX the
    text declares for them (``lam`` is also found as ``\\lambda``)."""
    out: dict[str, sp.Basic] = {}
    for a in sorted(expr.atoms(sp.Symbol) | expr.atoms(sp.core.function.AppliedUndef), key=sp.srepr):
        name = a.func.__name__ if isinstance(a, sp.core.function.AppliedUndef) else a.name
        out.setdefault(_normal(name), a)
        if name in latex_of:
            out.setdefault(_normal(preprocess(latex_of[name])), a)
    return out


def _translate(parsed: sp.Basic, ours: sp.Basic, latex_of: dict[str, str] | None = None) -> sp.Basic | None:
    names = _atoms_by_name(ours, latex_of or {})
    repl = {}
    for s in parsed.free_symbols:
        key = _normal(s.name)
        if key == "e":
            repl[s] = sp.E
        elif key in names:
            repl[s] = names[key]
        else:
            return None  # a symbol the transcription does not have: no agreement possible
    out = parsed.xreplace(repl)
    # derivatives the parser took with respect to t of a now-applied function
    return out


def _agree(a: sp.Basic, b: sp.Basic, seed: int) -> bool:
    """Both sides equal at 3 random points (20 digits), each side compiled once for mpmath."""
    from quasicentral.notation.timelimit import TimeLimitExceeded, time_limit

    a, b = bridge.to_jets(a), bridge.to_jets(b)
    syms = tuple(sorted(a.free_symbols | b.free_symbols, key=str))
    rng = random.Random(seed)
    try:
        with time_limit(3.0):
            fa, fb = bridge.mp_function(a, syms), bridge.mp_function(b, syms)
            for _ in range(3):
                vals = [bridge.mp_value(sp.Rational(rng.randrange(2000, 9000), 10000), 20) for _ in syms]
                with mpmath.workdps(20):
                    va, vb = fa(*vals), fb(*vals)
                    if not abs(va - vb) <= mpmath.mpf("1e-9") * max(1, abs(va), abs(vb)):
                        return False
    except TimeLimitExceeded:
        return False
    except Exception:  # noqa: BLE001 - a parse that cannot be evaluated does not count
        return False
    return True


def parse_agrees(entry: Entry, backend: str) -> bool:
    """True when ``backend`` parses the entry's LaTeX into something numerically equal to the
    transcription (each relation side by side)."""
    from sympy.parsing.latex import parse_latex

    ours = entry.relations()
    chunks = [c for c in re.split(r"\\\\|\n", entry.latex) if c.strip()]
    if len(chunks) != len(ours):
        chunks = [entry.latex]
        if len(ours) != 1:
            return False
    for i, (chunk, rel) in enumerate(zip(chunks, ours)):
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                parsed = parse_latex(preprocess(chunk), backend=backend)
        except Exception:  # noqa: BLE001 - any parser failure means "not read"
            return False
        if not isinstance(parsed, sp.Basic):  # lark may hand back an unresolved parse tree
            return False
        parsed = _translate(parsed, rel, {sp_.name: sp_.latex for sp_ in entry.symbols.specs} if entry.symbols else None)
        if parsed is None:
            return False
        if isinstance(rel, sp.Eq) != isinstance(parsed, sp.Eq):
            return False
        pairs = [(parsed.lhs, rel.lhs), (parsed.rhs, rel.rhs)] if isinstance(rel, sp.Eq) else [(parsed, rel)]
        if not all(_agree(p, q, seed=i) for p, q in pairs):
            return False
    return True


def parse_within(entry: Entry, seconds: float) -> tuple[dict[str, bool], str]:
    """Which backends read ``entry`` correctly, each within ``seconds`` of wall-clock and of CPU
    time; and why a backend could not finish ('' when each did: then the answer is kept)."""
    from quasicentral.notation.timelimit import CPU, WALL, TimeLimitExceeded, time_limit

    out, why = {}, ""
    for b in BACKENDS:
        try:
            with time_limit(seconds, WALL) as wall, time_limit(seconds, CPU) as cpu:
                out[b] = parse_agrees(entry, b)
        except TimeLimitExceeded as exc:
            if not ((wall and wall.owns(exc)) or (cpu and cpu.owns(exc))):
                raise
            out[b], why = False, f"ran out of time ({seconds:g} s each; --timeout allows more)"
        except RecursionError:
            out[b], why = False, why or "nested too deeply for the parser (recursion limit)"
    return out, why


def coverage(entries: list[Entry], progress=None, use_cache: bool = True, seconds: float = 120.0) -> dict:
    """Per entry, which backends read it correctly; and the totals.  Each entry's answer is
    kept in the verdict cache under the code (sympy's, lark's and ANTLR's versions included)
    and its text's files: a parse costs up to seconds (lark's Earley parser), and the answer
    cannot change while neither does.  Each parse is bounded by ``seconds`` (wall-clock and
    CPU): an entry that runs out is not read, says so (``out_of_time``), and is not kept.
    ``progress`` (a :class:`quasicentral.progress.Progress` callback) is told of each entry;
    the totals' ``cached`` says how many were read back."""
    from quasicentral.progress import notify

    keys = _cache_keys(entries)
    per: dict[str, dict[str, bool]] = {}
    cached = 0
    for e in entries:
        got = _read(keys[e.id]) if use_cache else None
        if got is not None:
            per[e.id] = got
            cached += 1
    notify(progress, cached, len(entries), "cache" if cached else "", cached, "entries parsed")
    out_of_time = []
    for e in entries:
        if e.id in per:
            continue
        answers, why = parse_within(e, seconds)
        if why:
            out_of_time.append(e.id)
            per[e.id] = {**answers, "why": why}
        else:
            per[e.id] = answers
            _write(keys[e.id], answers)
        notify(progress, len(per), len(entries), e.id, cached, "entries parsed")
    per = {e.id: per[e.id] for e in entries}
    summary = {"entries": len(entries), **{b: sum(v[b] for v in per.values()) for b in BACKENDS},
               "any": sum(any(v[b] for b in BACKENDS) for v in per.values())}
    if out_of_time:
        summary["out_of_time"] = out_of_time
    return {"entries": per, "summary": summary, "cached": cached}


def _cache_keys(entries: list[Entry]) -> dict[str, str]:
    import hashlib
    import json

    from pathlib import Path

    from quasicentral.engine.fingerprint import code_fingerprint, folder_fingerprint

    code = code_fingerprint()  # the checker's code and sympy's version among others
    parsers = _parser_versions()
    roots = {(e.source, Path(e.path).parent.parent) for e in entries}  # a catalog file's text folder
    text_fp = {tid: folder_fingerprint(tid, root) for tid, root in roots}
    return {e.id: hashlib.sha256(json.dumps(["latex-parser", code, parsers, text_fp[e.source], e.id, BACKENDS]
                                            ).encode()).hexdigest() for e in entries}


def _parser_versions() -> list[str]:
    """The versions of the parser runtimes sympy's backends use (a missing one is named so:
    its answers are not kept for when it is installed)."""
    from importlib import metadata

    out = []
    for dist in ("lark", "antlr4-python3-runtime"):
        try:
            out.append(f"{dist}=={metadata.version(dist)}")
        except metadata.PackageNotFoundError:
            out.append(f"{dist} missing")
    return out


def _cache_file(key: str):
    from quasicentral.engine.fingerprint import cache_dir

    return cache_dir() / "latex-parser" / f"{key}.json"


def _read(key: str) -> dict[str, bool] | None:
    """A kept answer, checked (a damaged or foreign file is parsed anew)."""
    import json

    from quasicentral.files import read_private

    path = _cache_file(key)
    data = read_private(path.parent, path.name)  # this user's own, a regular file, not a link
    if data is None:
        return None
    try:
        got = json.loads(data.decode("utf-8"))
    except (UnicodeDecodeError, ValueError):
        return None
    if isinstance(got, dict) and set(got) == set(BACKENDS) and all(isinstance(v, bool) for v in got.values()):
        return {b: got[b] for b in BACKENDS}
    return None


def _write(key: str, answer: dict[str, bool]) -> None:
    import json

    from quasicentral.files import ensure_dir, write_text

    path = _cache_file(key)
    try:
        ensure_dir(path.parent)  # never through a symbolic link
        write_text(path, json.dumps(answer, sort_keys=True))
    except OSError:
        pass  # a read-only cache is not an error
