"""Why a verdict is what it is — as data: a :class:`Code` and its fields, never a sentence.

The checker returns :class:`Reason` records (the points, the digits, the ladder's rungs, the
mismatched term and its two dimensions, the stage that failed …); the documents, the API and
the command line render them per language from one wording table
(:mod:`quasicentral.engine.wording`).  Nothing anywhere parses a sentence back.

A field holds a number, a string (an expression in sympy syntax, a symbol's name), a truth
value, another :class:`Reason`, or a tuple of these; :meth:`Reason.to_json` and
:meth:`Reason.from_json` round-trip it exactly (the verdict cache stores reasons so).

>>> r = Reason.of(Code.DISAGREES, count=3, points=6, relative=0.25)
>>> r["count"], r.code.value
(3, 'disagrees')
>>> Reason.from_json(r.to_json()) == r
True
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum


class Code(str, Enum):
    """Every reason the engine gives.  Grouped by the verdict they usually come with; the
    wording table (:data:`quasicentral.engine.wording.WORDING`) has every code in every
    language."""

    # --- verified ----------------------------------------------------------------------------
    AGREES = "agrees"  # n, of, digits, confirmed, top, vacuous, zeros (points where the difference vanished with the precision)
    PROVED = "proved"  # numbers: the AGREES of the same points
    DECIDED_TRUE = "decided-true"  # sympy decides the printed relation true from the assumptions
    ROUNDS_TO = "rounds-to"  # value, printed, places: an exact value that rounds to the printed decimal
    HOLDS = "holds"  # n, of, top: an inequality that holds at every point
    LIMIT_FOUND = "limit-found"  # how ("sympy" | "sequence"), value: a limit that agrees
    ORDER_HOLDS = "order-holds"  # n, variable, point, steps: an O-term bounded along the passage
    BLOWS_UP = "blows-up"  # n, variable, point: a limit that is infinite, as printed
    # --- refuted -------------------------------------------------------------------------------
    DISAGREES = "disagrees"  # count, points, relative
    FAILS_AT = "fails-at"  # count, points: an inequality that fails at certified points
    ORDER_GROWS = "order-grows"  # variable, point, rate: |lhs − rhs|/|O-term| grows along the passage
    STAYS_BOUNDED = "stays-bounded"  # variable, point: a limit printed infinite that stays bounded
    DIVERGES = "diverges"  # why: INTEGRAND_GROWS | TERMS_GROW
    INTEGRAND_GROWS = "integrand-grows"  # variable, end, order
    TERMS_GROW = "terms-grow"  # variable, ratio100, ratio200
    NO_LIMIT = "no-limit"  # variable, point, left, right: a two-sided limit whose sides differ
    UNDEFINED_TERM = "undefined-term"  # variable, index: a sum or product with a term at a pole
    DIMENSIONAL = "dimensional"  # numbers: None (not computed) | a verdict name | a Reason
    ROUNDS_OTHERWISE = "rounds-otherwise"  # printed, exact, places
    # --- inconclusive -----------------------------------------------------------------------
    NOTHING_TO_CHECK = "nothing-to-check"
    NO_DERIVATION = "no-derivation"
    DERIVATION_FAILED = "derivation-failed"  # error
    CONDITION_NOT_EQUATION = "condition-not-equation"
    EVALUATES_TO = "evaluates-to"  # value
    RELATION_COUNT = "relation-count"  # printed, derived
    CANNOT_SOLVE = "cannot-solve"  # unknown
    NOT_EQUATION_FOR = "not-equation-for"  # unknown
    SOLVE_TIMEOUT = "solve-timeout"  # seconds
    SETUP_FAILED = "setup-failed"  # error
    NO_RANGE = "no-range"  # symbol
    TOO_FEW_POINTS = "too-few-points"
    TOO_FEW_EVALUATED = "too-few-evaluated"  # n, of, error (the first evaluation error, or "")
    UNSTABLE = "unstable"  # n, of
    PROOF_CONTRADICTED = "proof-contradicted"  # verdict, numbers
    DIMENSIONS_DISAGREE = "dimensions-disagree"  # numbers (the AGREES), finding (a DimensionFinding's reason)
    STAGE_FAILED = "stage-failed"  # stage, error
    NONSMOOTH_QUADRATURE = "nonsmooth-quadrature"  # function, count, points: uncertified differences of a rough integral
    OUT_OF_TIME = "out-of-time"  # stage, seconds, clock ("cpu" | "wall")
    NO_NUMERIC_FORM = "no-numeric-form"  # function
    ONE_POINT_DOMAIN = "one-point-domain"  # symbol
    CONDITION_UNSOLVED = "condition-unsolved"  # unknown, count
    CONDITION_UNKNOWN = "condition-unknown"  # symbols: an implicit condition in no symbol
    CONDITIONS_NOT_ELIMINATING = "conditions-not-eliminating"  # symbols: several conditions that leave what they name
    ASYMPTOTIC_WITHOUT_LIMIT = "asymptotic-without-limit"
    NOTATION_ONLY = "notation-only"
    LIMIT_UNDECIDED = "limit-undecided"  # variable, point
    DEFINES = "defines"  # symbols: a definition of what the entry introduces (notation)
    ROUNDING_FREE = "rounding-free"  # symbols: a printed rounding of a value that depends on symbols
    ROUNDING_TIE = "rounding-tie"  # printed, places: the exact value lies on a half of the last place
    ROUNDING_UNDECIDED = "rounding-undecided"  # printed, places: no precision tried decides the rounding
    ROUNDING_NO_VALUE = "rounding-no-value"  # printed, error: the value to round could not be computed
    NOT_EQUAL_ONLY = "not-equal-only"  # a printed a ≠ b: true almost everywhere, nothing to check
    # --- dimensions (the finding on one relation) -------------------------------------------
    DIM_ADDS = "dim-adds"  # first, other, sum, term
    DIM_EXPONENT = "dim-exponent"  # power
    DIM_SYMBOLIC_POWER = "dim-symbolic-power"  # power
    DIM_ARGUMENT = "dim-argument"  # function, dimension, argument
    DIM_LIMIT = "dim-limit"  # limit, dimension, variable, variable_dimension
    DIM_SIDES = "dim-sides"  # left, right
    DIM_RELATION_INSIDE = "dim-relation-inside"
    DIM_UNDECLARED_SYMBOL = "dim-undeclared-symbol"  # symbol
    DIM_UNDECLARED = "dim-undeclared"  # expression
    DIM_CANNOT = "dim-cannot"  # expression
    # --- an outcome's problems (what the records expected and did not get) ------------------
    ERRATUM_NOT_REFUTED = "erratum-not-refuted"  # verdict
    CORRECTION_NOT_VERIFIED = "correction-not-verified"  # verdict, reason
    CLEARED_NOT_VERIFIED = "cleared-not-verified"  # verdict
    UNEXPECTED_VERDICT = "unexpected-verdict"  # verdict, reason
    NO_DERIVATION_PROBLEM = "no-derivation-problem"
    USES_MISMATCH = "uses-mismatch"  # declared, used: a derivation's uses= is not what it used
    # --- what a witness's two values are -------------------------------------------------------
    Q_VALUE = "q-value"  # both sides of an expression
    Q_ROUNDING = "q-rounding"  # the printed decimal and the exact value it rounds
    Q_RESIDUAL = "q-residual"  # lhs − rhs on the derived model
    Q_EXPRESSION = "q-expression"  # a bare printed expression on the derived model
    Q_UNDER_CONDITION = "q-under-condition"  # quantity
    Q_PRINTED_RESIDUAL = "q-printed-residual"  # unknown
    Q_DERIVED_RESIDUAL = "q-derived-residual"  # unknown
    Q_ROUNDING_WINDOW = "q-rounding-window"  # |x − a formula with printed decimals|, and what they allow
    Q_UNKNOWN = "q-unknown"  # unknown: the value of the unknown, printed and derived
    Q_DIMENSIONS = "q-dimensions"
    Q_ANTIDERIVATIVE = "q-antiderivative"  # variable: d/dx of the printed antiderivative, and the integrand
    Q_SIDES = "q-sides"  # the left and the right side of a printed equation
    Q_ORDER_RATIO = "q-order-ratio"  # variable, point: |lhs − rhs|/|O-term| at the last and an earlier step
    Q_LESSER_GREATER = "q-lesser-greater"  # the side printed lesser and the side printed greater


Value = "int | float | str | bool | None | Reason | tuple"


@dataclass(frozen=True)
class Reason:
    """A code and its fields (sorted by name: two equal reasons compare and hash equal)."""

    code: Code
    fields: tuple[tuple[str, object], ...] = ()

    @staticmethod
    def of(code: Code, **fields) -> "Reason":
        return Reason(code, tuple(sorted(fields.items())))

    def __getitem__(self, name: str):
        for k, v in self.fields:
            if k == name:
                return v
        raise KeyError(f"{self.code.value} has no field {name!r}")

    def get(self, name: str, default=None):
        try:
            return self[name]
        except KeyError:
            return default

    def to_json(self) -> dict:
        return {"code": self.code.value, "fields": {k: _to_json(v) for k, v in self.fields}}

    @staticmethod
    def from_json(d: dict) -> "Reason":
        if not isinstance(d, dict) or not isinstance(d.get("fields"), dict):
            raise ValueError("a reason is {'code': ..., 'fields': {...}}")
        return Reason(Code(d["code"]), tuple(sorted((str(k), _from_json(v)) for k, v in d["fields"].items())))


def _to_json(v):
    if isinstance(v, Reason):
        return {"reason": v.to_json()}
    if isinstance(v, tuple):
        return {"tuple": [_to_json(x) for x in v]}
    if v is None or isinstance(v, (bool, int, float, str)):
        return v
    raise TypeError(f"a reason's field holds data, not {type(v).__name__}")


def _from_json(v):
    if isinstance(v, dict):
        if "reason" in v:
            return Reason.from_json(v["reason"])
        if "tuple" in v and isinstance(v["tuple"], list):
            return tuple(_from_json(x) for x in v["tuple"])
        raise ValueError("a reason's field is a number, a string, a reason or a tuple")
    if v is None or isinstance(v, (bool, int, float, str)):
        return v
    raise ValueError(f"a reason's field cannot be {type(v).__name__}")
