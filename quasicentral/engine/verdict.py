"""Verdicts: a closed set of three outcomes, never a string to parse.

* :class:`Verified` — by ``symbolic`` (a CAS proof), ``numeric`` (agreement at many in-domain
  points, stable under a precision ladder) or ``certified`` (ball arithmetic).
* :class:`Refuted` — always with a :class:`Witness`: the parameter values, both values, the
  digits they were computed to, and whether ball arithmetic certifies the difference.  A
  printed equation that is dimensionally inconsistent is refuted ``dimensional``-ly too.
* :class:`Inconclusive` — with the reason.  An honest answer; a false "verified" is the worst
  bug this project can have.

Combining (LaCASt's rule): refuted beats inconclusive beats verified.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from enum import Enum


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
    """

    parameters: dict[str, str]  # symbol name -> exact value (sympy string)
    printed: str  # value of the printed side, as a decimal string (every digit guaranteed)
    corrected: str  # value of the derived (correct) side (every digit guaranteed)
    digits: int  # significant digits guaranteed in both values (the fewer of the two)
    certified: bool  # ball arithmetic proves printed != corrected at this point
    quantity: str = ""  # what the values are (e.g. "x(t)", "lhs - rhs on the derived solution")
    relative_difference: str = ""
    printed_certified: bool = False  # the printed value's digits come from a ball
    corrected_certified: bool = False  # the corrected value's digits come from a ball
    working_digits: int = 0  # precision of the ladder's top rung where the point was found


@dataclass(frozen=True)
class Verdict:
    """Base of the closed verdict type (use the three subclasses)."""

    method: Method
    detail: str = ""
    points: int = 0  # in-domain points evaluated
    digits: tuple[int, ...] = ()  # the precision ladder used
    dimensions: str = "consistent"

    name = "verdict"

    def to_json(self) -> dict:
        d = asdict(self)
        d["verdict"] = self.name
        d["method"] = self.method.value
        d["digits"] = list(self.digits)
        return d

    @staticmethod
    def from_json(d: dict) -> "Verdict":
        d = dict(d)
        kind = {"verified": Verified, "refuted": Refuted, "inconclusive": Inconclusive}[d.pop("verdict")]
        d["method"] = Method(d["method"])
        d["digits"] = tuple(d.get("digits", ()))
        if d.get("witness"):
            d["witness"] = Witness(**d["witness"])
        return kind(**d)


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


_RANK = {Verified: 0, Inconclusive: 1, Refuted: 2}


def combine(verdicts: list[Verdict]) -> Verdict:
    """Refuted beats inconclusive beats verified; among verified the weakest method stands."""
    if not verdicts:
        return Inconclusive(Method.NONE, "nothing to check")
    worst = max(verdicts, key=lambda v: _RANK[type(v)])
    if isinstance(worst, Verified):
        order = [Method.NUMERIC, Method.CERTIFIED, Method.SYMBOLIC]
        return min(verdicts, key=lambda v: order.index(v.method) if v.method in order else -1)
    return worst


class Status(str, Enum):
    """What an entry's verdict means against what the text's records expect of it."""

    VERIFIED = "verified"  # printed = derived
    ERRATUM = "erratum"  # printed refuted, the registered correction verified
    CLEARED = "cleared"  # a registered suspicion that verified
    UNEXPECTED = "unexpected"  # anything else

    @property
    def ok(self) -> bool:
        return self is not Status.UNEXPECTED


@dataclass(frozen=True)
class Outcome:
    """What the verification of one catalog entry came to, against what was expected."""

    id: str
    verdict: Verdict
    status: Status
    erratum: bool = False
    corrected_verdict: Verdict | None = None
    problems: tuple[str, ...] = field(default_factory=tuple)

    @property
    def ok(self) -> bool:
        return Status(self.status).ok
