"""A text's exercise bank: the problems its handouts set, each held against the text's checked
results (``[[exercise]]`` tables of the folder's ``report.toml``; FORMAT.md, "Exercises").

Three kinds, graded by ``level`` (1 easy … 3 hard):

* ``derive`` — derive ``entry`` from ``premises``: the premises must be among what the entry's
  derivation uses, directly or through the entries it uses (the derivation graph), so an
  exercise never asks for a result its premises do not lead to;
* ``misprint`` — find the misprint in ``entry`` as printed: the entry must be a recorded
  erratum (the students' edition shows the printed form only, the teacher's the correction);
* ``compute`` — a number: ``unknown`` from the relation of ``entry`` at ``values`` (strings in
  the text's symbols, parsed as the catalog is — data, never executed), by sympy where it
  solves for the unknown, else by mpmath's ``findroot`` inside ``bracket``.  The entry must be
  verified (its corrected form where it is an erratum), and the answer must agree at 30 and at
  60 digits to the digits it is given in.

The bank is data: its wording (``question``, ``solution`` per language) is the documents', the
answers are computed here.  A mistake in it is a :class:`~quasicentral.engine.catalog.CatalogError`
naming the file and the exercise.

>>> ExerciseKind("compute") is ExerciseKind.COMPUTE
True
"""

from __future__ import annotations

import re
import tomllib
from dataclasses import dataclass, field
from enum import Enum
from pathlib import Path
from types import MappingProxyType

import mpmath
import sympy as sp

from quasicentral.engine.catalog import CatalogError
from quasicentral.notation import bridge
from quasicentral.notation.timelimit import TimeLimitExceeded, time_limit

BANK_FILE = "report.toml"
#: an equation cited in an exercise's words, {ref:<entry id>}: its number in the handout
REF = re.compile(r"\{ref:([^{}\s]+)\}")
#: the most significant digits an answer is given in, and the default
MAX_DIGITS = 12
DEFAULT_DIGITS = 4
#: CPU seconds sympy may spend solving for an unknown before the bracket is needed
SOLVE_SECONDS = 5.0
LEVELS = (1, 2, 3)


class ExerciseKind(str, Enum):
    DERIVE = "derive"
    MISPRINT = "misprint"
    COMPUTE = "compute"


@dataclass(frozen=True)
class ExerciseSpec:
    """One exercise as the bank states it."""

    id: str
    kind: ExerciseKind
    level: int
    entry: str
    question: MappingProxyType  # language -> LaTeX
    solution: MappingProxyType  # language -> LaTeX (the teacher's words; {answer} is filled in)
    premises: tuple[str, ...] = ()
    unknown: str = ""
    values: MappingProxyType = field(default_factory=lambda: MappingProxyType({}))
    bracket: tuple[str, str] | None = None
    unit: str = ""  # LaTeX, e.g. \mathrm{s}
    digits: int = DEFAULT_DIGITS
    where: str = ""  # "<folder>/report.toml, exercise <id>" for messages


@dataclass(frozen=True)
class Exercise:
    """An exercise with what the toolkit found for it: the computed answer (``compute``)."""

    spec: ExerciseSpec
    answer: str = ""  # the number in ``spec.digits`` significant digits ('' for other kinds)


_KEYS = frozenset({"id", "kind", "level", "entry", "question", "solution", "premises", "unknown", "values",
                   "bracket", "unit", "digits"})


def read_bank(root: Path, text_id: str) -> tuple[ExerciseSpec, ...]:
    """The exercises of the text whose folder is ``root`` (none without a bank), in the order
    of their level, then as written."""
    path = Path(root) / BANK_FILE
    if not path.is_file():
        return ()
    try:
        raw = tomllib.loads(path.read_text(encoding="utf-8")).get("exercise", [])
    except tomllib.TOMLDecodeError as exc:
        raise CatalogError(f"{text_id}/{BANK_FILE}: {exc}") from None
    if not isinstance(raw, list):
        raise CatalogError(f"{text_id}/{BANK_FILE}: 'exercise' must be an array of tables ([[exercise]])")
    specs = [_spec(r, f"{text_id}/{BANK_FILE}, exercise {i + 1}") for i, r in enumerate(raw)]
    ids = [s.id for s in specs]
    twice = sorted({i for i in ids if ids.count(i) > 1})
    if twice:
        raise CatalogError(f"{text_id}/{BANK_FILE}: exercise id {twice[0]!r} is given twice")
    return tuple(sorted(specs, key=lambda s: s.level))


def _spec(raw, where: str) -> ExerciseSpec:
    if not isinstance(raw, dict):
        raise CatalogError(f"{where}: an exercise is a table")
    unknown = sorted(set(raw) - _KEYS)
    if unknown:
        raise CatalogError(f"{where}: unknown key {unknown[0]!r} (known: {', '.join(sorted(_KEYS))})")
    for key in ("id", "kind", "entry", "question"):
        if key not in raw:
            raise CatalogError(f"{where}: needs {key!r}")
    where = f"{where.rsplit(',', 1)[0]}, exercise {raw['id']!r}"
    try:
        kind = ExerciseKind(raw["kind"])
    except ValueError:
        raise CatalogError(f"{where}: kind {raw['kind']!r} is none of "
                           f"{', '.join(k.value for k in ExerciseKind)}") from None
    level = raw.get("level", 1)
    if level not in LEVELS:
        raise CatalogError(f"{where}: level is 1, 2 or 3, not {level!r}")
    digits = raw.get("digits", DEFAULT_DIGITS)
    if not isinstance(digits, int) or isinstance(digits, bool) or not 1 <= digits <= MAX_DIGITS:
        raise CatalogError(f"{where}: digits is an integer from 1 to {MAX_DIGITS}, not {digits!r}")
    bracket = raw.get("bracket")
    if bracket is not None and not (isinstance(bracket, list) and len(bracket) == 2
                                    and all(isinstance(b, str) for b in bracket)):
        raise CatalogError(f"{where}: bracket is two strings, [\"low\", \"high\"]")
    values = raw.get("values", {})
    if not isinstance(values, dict) or not all(isinstance(v, str) for v in values.values()):
        raise CatalogError(f"{where}: values is a table of strings, {{ l = \"1\", g = \"981/100\" }}")
    premises = raw.get("premises", [])
    if not isinstance(premises, list) or not all(isinstance(p, str) for p in premises):
        raise CatalogError(f"{where}: premises is a list of entry ids")
    if kind is ExerciseKind.COMPUTE and not raw.get("unknown"):
        raise CatalogError(f"{where}: a compute exercise names its 'unknown'")
    if kind is ExerciseKind.DERIVE and not premises:
        raise CatalogError(f"{where}: a derive exercise names its 'premises'")
    return ExerciseSpec(str(raw["id"]), kind, level, str(raw["entry"]), _languages(raw["question"], where, "question"),
                        _languages(raw.get("solution", {}), where, "solution"), tuple(premises),
                        str(raw.get("unknown", "")), MappingProxyType(dict(values)),
                        tuple(bracket) if bracket else None, str(raw.get("unit", "")), digits, where)


def _languages(raw, where: str, key: str) -> MappingProxyType:
    if not isinstance(raw, dict) or not all(isinstance(v, str) for v in raw.values()):
        raise CatalogError(f"{where}: {key} is a table of strings per language, {key}.en = '...'")
    return MappingProxyType({k: " ".join(v.split()) for k, v in raw.items()})


def settle(specs, entries: dict, statuses: dict, uses: dict, corrected: dict) -> tuple[Exercise, ...]:
    """Each exercise checked against the text: ``entries`` maps an id to its catalog entry,
    ``statuses`` to its outcome's status, ``uses`` to the ids its derivation used (the graph),
    ``corrected`` an erratum's id to its corrected form (the transcription's text); a compute
    exercise gets its answer."""
    from quasicentral.engine.verdict import Status

    out = []
    for spec in specs:
        entry = entries.get(spec.entry)
        if entry is None:
            raise CatalogError(f"{spec.where}: entry {spec.entry!r} is not in the catalog")
        cited = [m for words in (*spec.question.values(), *spec.solution.values()) for m in REF.findall(words)]
        unknown = [c for c in cited + list(spec.premises) if c not in entries]
        if unknown:
            raise CatalogError(f"{spec.where}: {unknown[0]!r} is not an entry of the catalog")
        status = statuses.get(spec.entry)
        if spec.kind is ExerciseKind.MISPRINT:
            if status is not Status.ERRATUM:
                raise CatalogError(f"{spec.where}: {spec.entry} is no standing erratum (its status is "
                                   f"{status.value if status else 'unknown'}): there is no misprint to find")
            out.append(Exercise(spec))
        elif spec.kind is ExerciseKind.DERIVE:
            reach = _reach(spec.entry, uses)
            missing = [p for p in spec.premises if p not in reach]
            if missing:
                raise CatalogError(f"{spec.where}: {spec.entry} does not rest on {missing[0]} (its derivation "
                                   f"uses {', '.join(sorted(reach)) or 'nothing'}): the premises must lead to it")
            out.append(Exercise(spec))
        else:
            if status not in (Status.VERIFIED, Status.CLEARED, Status.ERRATUM):
                raise CatalogError(f"{spec.where}: {spec.entry} is not verified (its status is "
                                   f"{status.value if status else 'unknown'}): an answer needs a checked relation")
            out.append(Exercise(spec, compute(spec, entry, corrected.get(spec.entry) if status is Status.ERRATUM
                                              else None)))
    return tuple(out)


def _reach(eid: str, uses: dict) -> set[str]:
    """Every entry ``eid`` rests on, through the derivation graph."""
    seen, todo = set(), list(uses.get(eid, ()))
    while todo:
        u = todo.pop()
        if u not in seen:
            seen.add(u)
            todo += list(uses.get(u, ()))
    return seen


def compute(spec: ExerciseSpec, entry, corrected: str | None = None) -> str:
    """The answer of a compute exercise, in ``spec.digits`` significant digits: ``unknown`` from
    the entry's relation (its erratum's ``corrected`` form) at ``values``."""
    table = entry.symbols

    def parse(s: str, what: str):
        try:
            return table.parse(s)
        except Exception as exc:  # noqa: BLE001 - a bad string in the bank is the bank's error
            raise CatalogError(f"{spec.where}: {what} {s!r}: {exc}") from None

    if corrected is not None:
        got = parse(corrected, "the corrected form")
        relations = list(got) if isinstance(got, (sp.Tuple, list, tuple)) else [got]
    else:
        relations = entry.relations()
    rel = next((r for r in relations if isinstance(r, sp.Eq)), None)
    if rel is None:
        raise CatalogError(f"{spec.where}: {spec.entry} states no equation to solve")
    unknown = parse(spec.unknown, "unknown")
    values = {parse(k, "symbol"): parse(v, f"the value of {k}") for k, v in spec.values.items()}
    f = sp.sympify(rel.lhs - rel.rhs)
    for _ in range(len(values) + 1):  # a value may be given through others (T = 1.01·2π√(l/g))
        f = f.xreplace(values)
    # the unknown may be a quantity of the motion, s(t): solved for as a number
    u = sp.Dummy(spec.unknown)
    f = f.xreplace({unknown: u})
    free = sorted((f.free_symbols - {u}), key=str)
    if free:
        raise CatalogError(f"{spec.where}: no value for {', '.join(map(str, free))}")
    if u not in f.free_symbols:
        raise CatalogError(f"{spec.where}: {spec.entry} does not hold {spec.unknown}")
    unknown = u
    bracket = tuple(parse(b, "the bracket's end") for b in spec.bracket) if spec.bracket else None
    found = [_solve(f, unknown, bracket, spec, dps) for dps in (30, 60)]
    shown = [mpmath.nstr(v, spec.digits, min_fixed=-4, max_fixed=6) for v in found]
    if shown[0] != shown[1]:
        raise CatalogError(f"{spec.where}: the answer is not stable ({shown[0]} at 30 digits, {shown[1]} at 60)")
    return shown[1]


def _solve(f: sp.Expr, unknown: sp.Symbol, bracket, spec: ExerciseSpec, dps: int):
    if bracket is None:
        try:
            with time_limit(SOLVE_SECONDS):
                roots = [r for r in sp.solve(f, unknown) if r.is_real is not False]
        except TimeLimitExceeded:
            roots = []
        if len(roots) != 1:
            raise CatalogError(f"{spec.where}: sympy finds {len(roots)} solutions for {spec.unknown}: give a bracket")
        return bridge.mp_value(roots[0], dps)
    lo, hi = (bridge.mp_value(end, dps) for end in bracket)
    g = bridge.mp_function(f, (unknown,))
    with mpmath.workdps(dps + 10):
        try:
            root = mpmath.findroot(g, (lo, hi), solver="anderson")
        except (ValueError, ZeroDivisionError) as exc:
            raise CatalogError(f"{spec.where}: no root of {spec.entry} for {spec.unknown} in {list(spec.bracket)}: "
                               f"{exc}") from None
    if not (min(lo, hi) <= mpmath.re(root) <= max(lo, hi)) or abs(mpmath.im(root)) > 0:
        raise CatalogError(f"{spec.where}: the root of {spec.entry} for {spec.unknown} is outside the bracket")
    return +mpmath.re(root)
