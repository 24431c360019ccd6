"""Verdicts: a closed set of three outcomes, each with its reason as data, never a sentence.

* :class:`Verified` — by ``symbolic`` (a CAS proof), ``numeric`` (agreement at many in-domain
  points, stable under a precision ladder) or ``certified`` (ball arithmetic).
* :class:`Refuted` — always with a :class:`Witness`: the parameter values, both values, the
  digits they were computed to, and whether ball arithmetic certifies the difference.  A
  printed equation that is dimensionally inconsistent is refuted ``dimensional``-ly too.
* :class:`Inconclusive` — with the reason.  An honest answer; a false "verified" is the worst
  bug this project can have.

Each verdict carries a :class:`~quasicentral.engine.reasons.Reason` (a code and its fields)
and the dimension findings on its relations; :attr:`Verdict.detail` is the English sentence
the JSON documents show (:mod:`quasicentral.engine.wording`).  An :class:`Outcome` is one
entry's verdict against what its text's records expect, with those records attached, so that
it can be read, cached, rendered and compared on its own.

Combining (LaCASt's rule): refuted beats inconclusive beats verified.
"""

from __future__ import annotations

from types import MappingProxyType
from dataclasses import dataclass, field, replace
from enum import Enum

from quasicentral.engine.dimensions import DimensionCheck, summary
from quasicentral.engine.reasons import Code, Reason
from quasicentral.engine.wording import render


class Method(str, Enum):
    SYMBOLIC = "symbolic"
    NUMERIC = "numeric"
    CERTIFIED = "certified"
    DIMENSIONAL = "dimensional"
    NONE = "none"


@dataclass(frozen=True)
class Witness:
    """A reproducible point where two sides differ.

    Every digit of ``printed`` and ``corrected`` is guaranteed: each is the value correctly
    rounded to the significant digits shown, proven by a ball whose both ends round to the same
    string (``printed_certified`` / ``corrected_certified``), or else the digits on which a
    recomputation at twice the precision agrees (not a proof: the flag is then False).
    ``quantity`` says what the values are (a :class:`Reason` of a ``Q_…`` code).
    """

    parameters: dict[str, str]  # symbol name -> exact value (sympy string)
    printed: str  # value of the printed side, as a decimal string (every digit guaranteed)
    corrected: str  # value of the derived (correct) side (every digit guaranteed)
    digits: int  # significant digits guaranteed in both values (the fewer of the two)
    certified: bool  # ball arithmetic proves printed != corrected at this point
    quantity: Reason | None = None
    relative_difference: str = ""
    printed_certified: bool = False  # the printed value's digits come from a ball
    corrected_certified: bool = False  # the corrected value's digits come from a ball
    working_digits: int = 0  # precision of the ladder's top rung where the point was found

    @property
    def quantity_text(self) -> str:
        """What the values are, in English (the JSON's ``quantity``)."""
        return render(self.quantity)

    def to_json(self) -> dict:
        return {"parameters": dict(self.parameters), "printed": self.printed, "corrected": self.corrected,
                "digits": self.digits, "certified": self.certified, "printed_certified": self.printed_certified,
                "corrected_certified": self.corrected_certified, "working_digits": self.working_digits,
                "quantity": self.quantity_text, "relative_difference": self.relative_difference,
                # what the values are, typed: for views of the JSON that word it per language
                "quantity_code": self.quantity.code.value if self.quantity is not None else ""}

    def to_record(self) -> dict:
        """The witness for the verdict cache (its quantity typed)."""
        d = self.to_json()
        d["quantity"] = self.quantity.to_json() if self.quantity is not None else None
        return d

    @staticmethod
    def from_record(d: dict) -> "Witness":
        d = dict(d)
        q = d.pop("quantity", None)
        d.pop("quantity_code", None)  # the quantity's own code, said again for the JSON
        return Witness(quantity=Reason.from_json(q) if q else None, **d)


@dataclass(frozen=True)
class Verdict:
    """Base of the closed verdict type (use the three subclasses)."""

    method: Method
    reason: Reason = field(default_factory=lambda: Reason(Code.NOTHING_TO_CHECK))
    points: int = 0  # in-domain points evaluated
    digits: tuple[int, ...] = ()  # the precision ladder used
    dimensions: tuple[DimensionCheck, ...] = ()  # the findings on each relation that is not consistent

    name = "verdict"

    @property
    def detail(self) -> str:
        """The reason in English (the JSON documents' ``detail``)."""
        return render(self.reason)

    @property
    def dimensions_text(self) -> str:
        return summary(self.dimensions)

    def to_record(self) -> dict:
        """The verdict for the verdict cache: typed, every field round-trips."""
        d = {"verdict": self.name, "method": self.method.value, "reason": self.reason.to_json(),
             "points": self.points, "digits": list(self.digits),
             "dimensions": [c.to_json() for c in self.dimensions]}
        w = getattr(self, "witness", None)
        d["witness"] = w.to_record() if w is not None else None
        return d

    @staticmethod
    def from_record(d: dict) -> "Verdict":
        kind = {"verified": Verified, "refuted": Refuted, "inconclusive": Inconclusive}[d["verdict"]]
        args = dict(method=Method(d["method"]), reason=Reason.from_json(d["reason"]), points=int(d["points"]),
                    digits=tuple(int(x) for x in d["digits"]),
                    dimensions=tuple(DimensionCheck.from_json(c) for c in d["dimensions"]))
        if kind is Refuted:
            args["witness"] = Witness.from_record(d["witness"]) if d.get("witness") else None
        return kind(**args)


@dataclass(frozen=True)
class Verified(Verdict):
    name = "verified"


@dataclass(frozen=True)
class Refuted(Verdict):
    witness: Witness | None = None
    name = "refuted"


@dataclass(frozen=True)
class Inconclusive(Verdict):
    name = "inconclusive"


_RANK = MappingProxyType({Verified: 0, Inconclusive: 1, Refuted: 2})


def combine(verdicts: list[Verdict]) -> Verdict:
    """Refuted beats inconclusive beats verified; among verified the weakest method stands."""
    if not verdicts:
        return Inconclusive(Method.NONE, Reason(Code.NOTHING_TO_CHECK))
    worst = max(verdicts, key=lambda v: _RANK[type(v)])
    if isinstance(worst, Verified):
        order = [Method.NUMERIC, Method.CERTIFIED, Method.SYMBOLIC]
        return min(verdicts, key=lambda v: order.index(v.method) if v.method in order else -1)
    return worst


def with_dimensions(v: Verdict, dims: tuple[DimensionCheck, ...]) -> Verdict:
    return replace(v, dimensions=dims)


#: the reasons of an entry that states nothing to check (its status is NOTATION, not unexpected)
NOTATION_CODES = frozenset({Code.DEFINES, Code.NOTATION_ONLY, Code.NOT_EQUAL_ONLY})


class Status(str, Enum):
    """What an entry's verdict means against what the text's records expect of it."""

    VERIFIED = "verified"  # printed = derived
    ERRATUM = "erratum"  # printed refuted, the registered correction verified
    CLEARED = "cleared"  # a registered suspicion that verified
    NOTATION = "notation"  # an entry that states nothing to check: a definition, notation only
    UNEXPECTED = "unexpected"  # anything else

    @property
    def ok(self) -> bool:
        return self is not Status.UNEXPECTED


@dataclass(frozen=True)
class Outcome:
    """What the verification of one catalog entry came to, against what was expected.

    ``records`` are the text's records of the entry — its erratum, its cleared suspicion and
    the causes the erratum names (:mod:`quasicentral.engine.errata`) — attached when the
    outcome is made or read back, so that nothing needs the text to read it."""

    id: str
    verdict: Verdict
    status: Status
    erratum: bool = False
    corrected_verdict: Verdict | None = None
    problems: tuple[Reason, ...] = field(default_factory=tuple)
    records: "EntryRecords | None" = field(default=None, compare=False)

    @property
    def ok(self) -> bool:
        return self.status.ok

    @property
    def problem_texts(self) -> list[str]:
        return [render(p) for p in self.problems]

    @property
    def causes(self) -> tuple:
        return self.records.causes if self.records is not None else ()

    def to_record(self) -> dict:
        return {"id": self.id, "verdict": self.verdict.to_record(), "status": self.status.value,
                "erratum": self.erratum,
                "corrected_verdict": self.corrected_verdict.to_record() if self.corrected_verdict else None,
                "problems": [p.to_json() for p in self.problems]}

    @staticmethod
    def from_record(d: dict, records: "EntryRecords | None" = None) -> "Outcome":
        cv = d.get("corrected_verdict")
        return Outcome(d["id"], Verdict.from_record(d["verdict"]), Status(d["status"]), bool(d["erratum"]),
                       Verdict.from_record(cv) if cv else None, tuple(Reason.from_json(p) for p in d["problems"]),
                       records)


@dataclass(frozen=True)
class EntryRecords:
    """An entry's records in its text's errata files: its erratum (or None), its cleared
    suspicion (or None) and the causes its erratum names, in the text's order."""

    erratum: object = None
    cleared: object = None
    causes: tuple = ()
