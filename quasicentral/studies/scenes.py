"""Scenes: a situation and the accuracy it needs → the cheapest model that meets that accuracy.

A scene (a TOML file, see ``scenes/`` at the repository root) describes a pendulum, its start,
the medium and a question — a quantity and the largest acceptable absolute error in the
answer's unit.  The toolkit climbs a *ladder* of models, from cheapest to richest:

=========================  ====================================================================
``ellipse``                small swings, no drag: the ellipse (13), [Brepta1953] §3
``linear``                 small swings, linear drag R = 2κmv, closed form (19)/(21), §4
``quadratic-first-order``  small swings, quadratic drag R = mβv², first order in β, (28)–(30)
``quadratic``              small swings, quadratic drag, (26)–(27) integrated numerically
``spherical``              the full nonlinear spherical pendulum with drag, integrated numerically
``period-series``          planar swing without drag: the period by the series (66), N terms
``period-exact``           planar swing without drag: the exact period T0·2K(k²)/π, (60)–(61)
=========================  ====================================================================

Only the rungs that model the scene's medium are on its ladder (the ellipse, which neglects
any drag, is always the first rung).  For every rung the toolkit gives two error estimates:

* **a priori**: the orders of the terms the rung neglects, evaluated for the scene (drag:
  O(κT), O(βA·ΩT); second order in β: O((βA)²(ΩT)²); finite swings: O(ε²), O(ε²ΩT) with
  ε = A/l, the phase drift (a² + b²)/16l² and the apsidal precession 3ab/8l² per radian of
  Ωt; integration: O(rtol·ΩT)).  These are orders of magnitude with O(1) constants.
* **a posteriori**: the rung's answer is compared with the next richer rung's answer on a
  sample of the scene (32 points per period over the duration, or the first revolution), and
  the richer rung's own estimate is added (triangle inequality):
  err_i = |answer_i − answer_{i+1}| + err_{i+1}, or, when smaller, the same bound through the
  richest rung, |answer_i − answer_richest| + err_richest.  The difference to the next richer
  rung measures exactly what the rung neglects: it *confirms* the a-priori order when it is
  within ten times that estimate (plus the richer rung's own error).  The richest rung is checked by its own
  integration at two tolerances (rtol and 100·rtol); the exact period against mpmath.

The a posteriori estimate decides (it is measured on this very scene); the a priori estimate
is reported beside it and flagged when the measurement exceeds it tenfold.  The cheapest rung
whose estimate is within the tolerance answers; if none is, the decision says so.

What the quantities mean (the bob starts at X = R0, Y = 0 with the horizontal velocity v0
along +Y; positions are horizontal displacements; L is per unit mass):

* ``trajectory`` — X(t), Y(t) on [0, duration]; the error is the largest distance (m).
* ``period`` — the time of the first revolution: the azimuth turns through 2π (Y crosses zero
  upwards); for a planar swing (v0 = 0) the next turning point on the release side.  Without
  drag and for a planar swing this is the period of (60); with drag the motion is not
  periodic and the "period" is the duration of that first revolution: 2π/ω for linear drag
  (ω² = Ω² − κ², exactly), 2π/Ω to first order in β (the paper's remark before (31)).
* ``decay-per-revolution`` — R0 − R1, R1 the distance from the vertical at the end of that
  first revolution; (33) R1 = R0(1 − πβR0) in first order for the conical start R0Ω = v0.
  In the full model R1 also moves with the apsidal precession (it is what one observes).
* ``angular-momentum`` — L(t) = XẎ − YẊ on [0, duration] (m²/s).  Law (4) L = L0 e^{−2κt}
  is exact for linear drag even for the full pendulum (the drag is tangent, L̇ = −2κL), so
  the closed form answers it exactly; for quadratic drag (5) L = L0 e^{−βs} is exact but the
  path s depends on the model: the first-order rung takes s from the ideal ellipse.

Cost is the richness of the model, not CPU time (in double precision ``ellipkm1`` is as fast
as the series; the series is what one evaluates by hand).

>>> scene = parse('''
... [pendulum]
... length = 1.0
... g = 9.81
... [start]
... displacement = 0.01
... speed = 0.0
... [medium]
... drag = "none"
... [question]
... quantity = "period"
... tolerance = 1e-3
... ''')
>>> d = decide(scene)
>>> d.chosen.model, round(d.chosen.value, 6)
('ellipse', 2.006067)
"""

from __future__ import annotations

import math
import re
import time
import tomllib
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from quasicentral.models import motion

from quasicentral.models import period

from quasicentral.models import quadratic

from quasicentral.models import spherical

QUANTITIES = {"trajectory": "m", "period": "s", "decay-per-revolution": "m", "angular-momentum": "m^2/s"}
DRAGS = ("none", "linear", "quadratic")
NEEDS_DURATION = ("trajectory", "angular-momentum")

RUNGS = {
    "ellipse": "small swings without drag: the ellipse (13)",
    "linear": "small swings, linear drag R = 2κmv: the closed form (19)/(21) (overdamped too)",
    "quadratic-first-order": "small swings, quadratic drag R = mβv² to first order in β: closed form (28)–(30)",
    "quadratic": "small swings, quadratic drag: (26)–(27) integrated numerically (DOP853)",
    "spherical": "the full nonlinear spherical pendulum with drag, integrated numerically (DOP853)",
    "period-series": "planar swing without drag: the series (66) truncated after N terms",
    "period-exact": "planar swing without drag: the exact period T0·2K(sin²(φ0/2))/π, (60)–(61)",
}

POINTS_PER_PERIOD = 32
MIN_POINTS = 257
MAX_PERIODS = 1000
SERIES_MAX_TERMS = 200
FADED = 1e-6  # a revolution must end before the swing fades below this fraction of its start
G_DEFAULT = 9.81
EPS = np.finfo(float).eps


# --- errors ----------------------------------------------------------------------------------
class SceneError(ValueError):
    """Bad scene input: the key's dotted name and its line in the file."""

    def __init__(self, message: str, key: str | None = None, line: int | None = None, source: str | None = None):
        super().__init__(message)
        self.message, self.key, self.line, self.source = message, key, line, source

    def __str__(self) -> str:
        where = ":".join(str(p) for p in (self.source, self.line) if p is not None)
        parts = [p for p in (where, self.key) if p]
        return ": ".join(parts + [self.message])


# --- units -------------------------------------------------------------------------------------
_UNITS = {
    "length": ("m", {"m": 1.0, "cm": 1e-2, "mm": 1e-3, "km": 1e3}),
    "time": ("s", {"s": 1.0, "ms": 1e-3, "min": 60.0, "h": 3600.0}),
    "speed": ("m/s", {"m/s": 1.0, "cm/s": 1e-2, "mm/s": 1e-3, "km/h": 1 / 3.6}),
    "acceleration": ("m/s^2", {"m/s^2": 1.0, "m/s2": 1.0, "m/s²": 1.0}),
    "rate": ("1/s", {"1/s": 1.0, "/s": 1.0, "s^-1": 1.0, "s-1": 1.0, "s⁻¹": 1.0}),
    "inverse length": ("1/m", {"1/m": 1.0, "/m": 1.0, "m^-1": 1.0, "m-1": 1.0, "m⁻¹": 1.0}),
    "angle in degrees": ("deg", {"deg": 1.0, "°": 1.0}),
    "angular momentum per mass": ("m^2/s", {"m^2/s": 1.0, "m2/s": 1.0, "m²/s": 1.0}),
}
_QUANTITY_DIMENSION = {"trajectory": "length", "period": "time", "decay-per-revolution": "length",
                       "angular-momentum": "angular momentum per mass"}
_NUMBER_UNIT = re.compile(r"^\s*([-+]?(?:\d[\d_]*\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")


def _quantity_value(raw, dimension: str, key: str, line_of):
    """A number in SI units, or a string 'NUMBER UNIT' converted to SI; a wrong dimension or
    an unknown unit is an error naming the key."""
    si, table = _UNITS[dimension]
    if isinstance(raw, bool) or not isinstance(raw, (int, float, str)):
        raise SceneError(f"must be a number ({si}) or a string like '1.5 {si}', not {_toml_type(raw)}", key,
                         line_of(key))
    if isinstance(raw, str):
        m = _NUMBER_UNIT.match(raw)
        if not m:
            raise SceneError(f"must be a number with a unit ({si}), not {raw!r}", key, line_of(key))
        number, unit = float(m.group(1).replace("_", "")), m.group(2)
        if unit == "":
            value = number
        elif unit in table:
            value = number * table[unit]
        else:
            other = next((d for d, (_, t) in _UNITS.items() if unit in t), None)
            if other:
                raise SceneError(f"{raw!r} is {_article(other)}; this key needs {_article(dimension)} "
                                 f"({', '.join(table)})", key, line_of(key))
            raise SceneError(f"unknown unit {unit!r} in {raw!r}; use {', '.join(table)}", key, line_of(key))
    else:
        value = float(raw)
    if not math.isfinite(value):
        raise SceneError(f"must be finite, not {raw!r}", key, line_of(key))
    return value


def _article(noun: str) -> str:
    return ("an " if noun[0] in "aeiou" else "a ") + noun


def _toml_type(raw) -> str:
    return {bool: "a boolean", dict: "a table", list: "an array"}.get(type(raw), type(raw).__name__)


# --- the scene ---------------------------------------------------------------------------------
@dataclass(frozen=True)
class Scene:
    """A situation (SI units) and its question.  ``amplitude`` is set when the file gave
    ``amplitude_deg`` (then R0 = l·sin(amplitude))."""

    length: float
    g: float
    R0: float
    v0: float
    drag: str
    coefficient: float
    quantity: str
    tolerance: float
    duration: float | None = None
    amplitude: float | None = None
    title: str = ""
    source: str = "<scene>"
    lines: tuple = ()

    @property
    def Omega(self) -> float:
        return math.sqrt(self.g / self.length)

    @property
    def T0(self) -> float:
        return 2 * math.pi * math.sqrt(self.length / self.g)

    @property
    def kappa(self) -> float:
        return self.coefficient if self.drag == "linear" else 0.0

    @property
    def beta(self) -> float:
        return self.coefficient if self.drag == "quadratic" else 0.0

    @property
    def planar(self) -> bool:
        return self.v0 == 0

    @property
    def phi0(self) -> float:
        """The amplitude (rad) of the swing's start: the angle of the string with the vertical."""
        return self.amplitude if self.amplitude is not None else math.asin(self.R0 / self.length)

    @property
    def unit(self) -> str:
        return QUANTITIES[self.quantity]

    @property
    def semi_axes(self) -> tuple[float, float]:
        """(a, b) = (R0, v0/Ω): the small-swing ellipse's semi-axes along X and Y."""
        return self.R0, self.v0 / self.Omega

    def line(self, key: str) -> int | None:
        return _lookup_line(dict(self.lines), key)

    def error(self, message: str, key: str) -> SceneError:
        return SceneError(message, key, self.line(key), self.source)


_TABLES = {
    "scene": {"title", "notes"},
    "pendulum": {"length", "g"},
    "start": {"displacement", "amplitude_deg", "speed"},
    "medium": {"drag", "coefficient"},
    "question": {"quantity", "duration", "tolerance"},
}


def load(path) -> Scene:
    """Read and check a scene file (see :func:`parse`)."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise SceneError(f"cannot read the scene: {exc.strerror}", source=str(path)) from None
    except UnicodeDecodeError:
        raise SceneError("the scene is not UTF-8 text", source=str(path)) from None
    return parse(text, source=str(path))


def parse(text: str, source: str = "<scene>") -> Scene:
    """A :class:`Scene` from TOML text; every problem is a :class:`SceneError` naming the key
    and its line (tomllib gives none: the lines are found in the text)."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        msg = str(exc)
        m = re.search(r"\(at line (\d+), column \d+\)", msg)
        raise SceneError(f"not valid TOML: {re.sub(r' ?[(]at line.*$', '', msg)}", None,
                         int(m.group(1)) if m else None, source) from None
    lines = _key_lines(text)

    def line_of(key):
        return _lookup_line(lines, key)

    def err(message, key):
        return SceneError(message, key, line_of(key), source)

    try:
        return _build(data, lines, line_of, err, source)
    except SceneError as exc:
        if exc.source is None:
            exc.source = source
        raise


def _build(data, lines, line_of, err, source) -> Scene:
    for name, value in data.items():
        if name not in _TABLES:
            raise err(f"unknown table or key; a scene has {', '.join('[' + t + ']' for t in _TABLES)}", name)
        if not isinstance(value, dict):
            raise err(f"must be a table [{name}], not {_toml_type(value)}", name)
        for key in value:
            if key not in _TABLES[name]:
                raise err(f"unknown key; [{name}] takes {', '.join(sorted(_TABLES[name]))}", f"{name}.{key}")
    for name in ("pendulum", "start", "medium", "question"):
        if name not in data:
            raise SceneError(f"the scene has no [{name}] table", name, None, source)

    def need(table, key):
        if key not in data[table]:
            raise err(f"missing: [{table}] needs {key}", f"{table}.{key}")  # the table's line
        return data[table][key]

    def text_value(table, key, choices):
        raw = need(table, key)
        if not isinstance(raw, str):
            raise err(f"must be a string, one of {', '.join(choices)}; not {_toml_type(raw)}", f"{table}.{key}")
        if raw not in choices:
            raise err(f"unknown value {raw!r}; choose from {', '.join(choices)}", f"{table}.{key}")
        return raw

    for key in ("title", "notes"):
        raw = data.get("scene", {}).get(key)
        if raw is not None and not isinstance(raw, str):
            raise err(f"must be a string, not {_toml_type(raw)}", f"scene.{key}")
    title = data.get("scene", {}).get("title", "")

    # the pendulum
    length = _quantity_value(need("pendulum", "length"), "length", "pendulum.length", line_of)
    if length <= 0:
        raise err(f"must be a positive length, not {length:g} m", "pendulum.length")
    g = G_DEFAULT
    if "g" in data["pendulum"]:
        g = _quantity_value(data["pendulum"]["g"], "acceleration", "pendulum.g", line_of)
        if g <= 0:
            raise err(f"must be positive, not {g:g} m/s^2", "pendulum.g")

    # the start
    st = data["start"]
    if ("displacement" in st) == ("amplitude_deg" in st):
        key = "start.amplitude_deg" if "amplitude_deg" in st else "start"
        raise err("give exactly one of displacement (m) and amplitude_deg", key)
    amplitude = None
    if "displacement" in st:
        R0 = _quantity_value(st["displacement"], "length", "start.displacement", line_of)
        if not 0 < R0 < length:
            raise err(f"must be between 0 and the length {length:g} m (exclusive), not {R0:g} m", "start.displacement")
    else:
        deg = _quantity_value(st["amplitude_deg"], "angle in degrees", "start.amplitude_deg", line_of)
        if not 0 < deg < 90:
            raise err(f"must be between 0 and 90 degrees (exclusive; R0 = l·sin(amplitude) is the horizontal "
                      f"distance and the bob starts below the pivot), not {deg:g}", "start.amplitude_deg")
        amplitude = math.radians(deg)
        R0 = length * math.sin(amplitude)
    v0 = _quantity_value(need("start", "speed"), "speed", "start.speed", line_of)
    if v0 < 0:
        raise err(f"must be ≥ 0 (a speed, perpendicular to the displacement), not {v0:g} m/s", "start.speed")
    z0 = math.sqrt((length - R0) * (length + R0))
    if 0.5 * v0 * v0 >= g * z0:
        raise err(f"is too large: with ½v0² ≥ g·Z0 ({0.5 * v0 * v0:.3g} ≥ {g * z0:.3g} m²/s²) the bob may rise to the "
                  "pivot's horizontal, outside every model here", "start.speed")

    # the medium
    drag = text_value("medium", "drag", DRAGS)
    coefficient = 0.0
    if drag == "none":
        if "coefficient" in data["medium"]:
            raise err("has no meaning with drag = \"none\"; remove it", "medium.coefficient")
    else:
        dim = "rate" if drag == "linear" else "inverse length"
        coefficient = _quantity_value(need("medium", "coefficient"), dim, "medium.coefficient", line_of)
        what = "kappa [1/s], R = 2·kappa·m·v" if drag == "linear" else "beta [1/m], R = m·beta·v²"
        if coefficient <= 0:
            raise err(f"must be positive ({what}); for no drag write drag = \"none\"", "medium.coefficient")

    # the question
    quantity = text_value("question", "quantity", tuple(QUANTITIES))
    tol = _quantity_value(need("question", "tolerance"), _QUANTITY_DIMENSION[quantity], "question.tolerance", line_of)
    if tol <= 0:
        raise err(f"must be positive (the largest acceptable absolute error, {QUANTITIES[quantity]}), not {tol:g}",
                  "question.tolerance")
    duration = None
    T0 = 2 * math.pi * math.sqrt(length / g)
    if quantity in NEEDS_DURATION:
        duration = _quantity_value(need("question", "duration"), "time", "question.duration", line_of)
        if duration <= 0:
            raise err(f"must be positive, not {duration:g} s", "question.duration")
        if duration > MAX_PERIODS * T0:
            raise err(f"is longer than {MAX_PERIODS} periods ({MAX_PERIODS * T0:.4g} s), the most a scene supports",
                      "question.duration")
    elif "duration" in data["question"]:
        raise err(f"has no meaning for quantity {quantity!r} (the first revolution); remove it", "question.duration")
    return Scene(length=length, g=g, R0=R0, v0=v0, drag=drag, coefficient=coefficient, quantity=quantity,
                 tolerance=tol, duration=duration, amplitude=amplitude, title=title, source=source,
                 lines=tuple(sorted(lines.items())))


# --- where a key is in the text ------------------------------------------------------------------
_BARE = r"[A-Za-z0-9_-]+"
_QUOTED = r'"(?:[^"\\]|\\.)*"' + r"|'[^']*'"
_KEY = rf"(?:{_BARE}|{_QUOTED})(?:\s*\.\s*(?:{_BARE}|{_QUOTED}))*"
_HEADER = re.compile(rf"^\[\[?\s*({_KEY})\s*\]\]?")
_ASSIGN = re.compile(rf"^({_KEY})\s*=")


def _norm_key(key: str) -> str:
    parts = re.findall(rf"{_BARE}|{_QUOTED}", key)
    return ".".join(p[1:-1] if p[:1] in "\"'" else p for p in parts)


def _key_lines(text: str) -> dict[str, int]:
    """The first line of every table header and key assignment, by dotted name."""
    lines: dict[str, int] = {}
    table, inside = "", None  # inside: the delimiter of an open multi-line string
    for no, raw in enumerate(text.splitlines(), 1):
        line = raw.strip()
        if inside:
            if inside in line:
                inside = None
            continue
        if not line or line.startswith("#"):
            continue
        m = _HEADER.match(line)
        if m:
            table = _norm_key(m.group(1))
            lines.setdefault(table, no)
            continue
        m = _ASSIGN.match(line)
        if m:
            key = _norm_key(m.group(1))
            lines.setdefault(f"{table}.{key}" if table else key, no)
            rest = line[m.end():]
            for delim in ('"""', "'''"):
                if rest.count(delim) == 1:
                    inside = delim
    return lines


def _lookup_line(lines: dict, key: str) -> int | None:
    """The line of ``key``, else of its nearest enclosing table."""
    parts = key.split(".")
    while parts:
        got = lines.get(".".join(parts))
        if got is not None:
            return got
        parts.pop()
    return None


# --- the ladder ------------------------------------------------------------------------------------
def ladder(scene: Scene) -> list[str]:
    """The rungs that model this scene, cheapest first."""
    if scene.quantity == "period" and scene.planar and scene.drag == "none":
        return ["ellipse", "period-series", "period-exact"]
    middle = {"none": [], "linear": ["linear"], "quadratic": ["quadratic-first-order", "quadratic"]}[scene.drag]
    return ["ellipse", *middle, "spherical"]


@dataclass(frozen=True)
class Rating:
    """One rung's answer for the scene and its error estimates (in the answer's unit)."""

    model: str
    value: object  # float, or an array: (2, n) positions, (n,) angular momenta; None: no answer
    a_priori: float
    neglects: str
    estimated_error: float  # a posteriori: difference + the richer rung's own estimate
    checked_against: str
    difference: float  # |answer − the richer rung's answer| on the sample (or the two tolerances')
    confirmed: bool  # the difference is within ten times the a-priori estimate (plus the richer's error)
    seconds: float
    terms: int | None = None  # for period-series

    @property
    def label(self) -> str:
        return f"{self.model} ({self.terms} terms)" if self.terms else self.model


@dataclass(frozen=True)
class Decision:
    scene: Scene
    ratings: tuple  # Rating, cheapest first (for the series: the failing N − 1, the chosen N)
    chosen: Rating
    meets: bool
    times: np.ndarray | None  # the sample of the scene (trajectory, angular momentum)
    seconds: float

    @property
    def rejected(self) -> list[Rating]:
        return self.ratings[: self.ratings.index(self.chosen)] if self.meets else list(self.ratings[:-1])

    @property
    def richest(self) -> Rating:
        return self.ratings[-1]


def sample_times(scene: Scene) -> np.ndarray:
    """The sample of the scene: POINTS_PER_PERIOD points per small-swing period over the duration."""
    n = max(MIN_POINTS, int(math.ceil(POINTS_PER_PERIOD * scene.duration / scene.T0)) + 1)
    return np.linspace(0.0, scene.duration, n)


def _rtol(scene: Scene) -> float:
    """The integration tolerance the numerical rungs need: a thousandth of the asked relative
    accuracy, within [1e-12, 1e-8] (model no more than the scene needs — the integrator too)."""
    return float(min(1e-8, max(1e-12, 1e-3 * scene.tolerance / _scale(scene))))


def _scale(scene: Scene) -> float:
    a, b = scene.semi_axes
    return {"trajectory": max(a, b), "decay-per-revolution": scene.R0, "period": scene.T0,
            "angular-momentum": max(scene.R0 * scene.v0, EPS * scene.R0 * scene.R0 * scene.Omega)}[scene.quantity]


def distance(quantity: str, a, b) -> float:
    """How far apart two answers are: the largest distance between two trajectories, the
    largest difference of two L(t), the difference of two numbers; ∞ if one has no answer."""
    if a is None or b is None:
        return math.inf
    if quantity == "trajectory":
        return float(np.max(np.hypot(a[0] - b[0], a[1] - b[1])))
    if quantity == "angular-momentum":
        return float(np.max(np.abs(a - b)))
    return abs(float(a) - float(b))


# --- a priori: the orders of what a rung neglects ---------------------------------------------------
def a_priori(scene: Scene, model: str, rtol: float = 1e-12, terms: int | None = None) -> tuple[float, str]:
    """(estimate, what is neglected) for a rung on this scene, from the orders of the neglected
    terms (O(1) constants; see the module's docstring)."""
    q, Om, T0, R0, l = scene.quantity, scene.Omega, scene.T0, scene.R0, scene.length
    a, b = scene.semi_axes
    A, eps2 = max(a, b), (max(a, b) / l) ** 2
    k, beta = scene.kappa, scene.beta
    T = scene.duration or T0
    L0 = R0 * scene.v0
    w = math.sqrt(max(0.0, (Om - k) * (Om + k)))
    speed = Om * math.sqrt((a * a + b * b) / 2)  # rms speed of the ellipse
    x = beta * A * Om * T / 2  # the fraction of the amplitude lost to quadratic drag over T
    # the duration over which the finite-swing phase drift accumulates (amplitude decays)
    t_eff = T if k == 0 else -math.expm1(-2 * k * T) / (2 * k)
    t_eff = t_eff / (1 + x)
    drift = ((a * a + b * b) / 16 + 3 * a * b / 8) / l**2  # phase drift + apsidal precession per rad
    rounding = 4 * EPS * _scale(scene)
    capped = min  # an error of positions never exceeds twice the swing
    if q == "trajectory":
        effects = {
            "drag-linear": ("the drag, O(κT)", capped(A * (-math.expm1(-k * T) + k * k * T / (2 * Om)), 2 * A)),
            "drag-quadratic": ("the drag, O(βA·ΩT)", capped(A * x, 2 * A)),
            "drag-second-order": ("second order in β, O((βA)²(1 + ΩT)²)",
                                  capped(A * (beta * A) ** 2 * (1 + (Om * T / 2) ** 2), 2 * A)),
            "finite-swing": ("finite swings, O(ε²) + O(ε²ΩT)", capped(A * (eps2 / 8 + Om * t_eff * drift), 2 * A)),
            "integration": ("the integration, O(rtol·ΩT)", A * rtol * (10 + Om * T)),
        }
    elif q == "period":
        m = math.sin(scene.phi0 / 2) ** 2
        tail = (lambda n: T0 * float(period.series_coefficients(n + 1)[-1]) * m**n / (1 - m))
        effects = {
            "drag-linear": ("the drag, O(κ²/Ω²)", T0 * (Om / w - 1) if w > 0 else math.inf),
            "drag-quadratic": ("the drag, O((βA)²) (no first-order change)", T0 * (beta * A) ** 2),
            "drag-second-order": ("second order in β, O((βA)²)", T0 * (beta * A) ** 2),
            "finite-swing": ("finite swings, O(ε²)", T0 * drift),
            "integration": ("the integration, O(rtol)", T0 * rtol * 10),
            "series-1": ("the terms of (66) after the first, O(k²)", tail(1)),
            "series": (f"the tail of (66) after {terms} terms", tail(terms or 1)),
            "rounding": ("rounding only", rounding),
        }
    elif q == "decay-per-revolution":
        d_lin = -R0 * math.expm1(-2 * math.pi * k / w) if w > 0 else R0
        d_quad = min(R0, math.pi * beta * R0 * R0)
        precession = R0 * abs(a * a - b * b) * a * a * (9 * math.pi**2 / 32) / l**4 if not scene.planar else 0.0
        effects = {
            "drag-linear": ("the drag, O(κ/Ω)", d_lin),
            "drag-quadratic": ("the drag, O(βR0)", d_quad),
            "drag-second-order": ("second order in β, O((βR0)²)", min(R0, R0 * (math.pi * beta * R0) ** 2)),
            "finite-swing": ("finite swings, O(ε²) and the precession, O(ε⁴)",
                             (d_lin if k else d_quad) * eps2 + precession),
            "integration": ("the integration, O(rtol)", R0 * rtol * 10),
        }
    else:  # angular-momentum
        s = speed * T
        effects = {
            "drag-linear": ("the drag, O(κT) (law (4))", -L0 * math.expm1(-2 * k * T)),
            "drag-quadratic": ("the drag, O(βs) (law (5))", -L0 * math.expm1(-beta * s)),
            "drag-second-order": ("the path's change by the drag, O(βs·βA·ΩT)", L0 * min(1.0, beta * s * x)),
            "finite-swing": ("the path's change by finite swings, O(βs·ε²) (laws (4), (5) are exact)",
                             L0 * min(1.0, beta * s * eps2)),
            "integration": ("the integration, O(rtol·ΩT)", L0 * rtol * (10 + Om * T)),
            "rounding": ("nothing: the law is exact (rounding only)", rounding),
        }
    if model == "ellipse":
        if scene.quantity == "period" and scene.planar and scene.drag == "none":
            keys = ["series-1"]
        elif q == "angular-momentum" and scene.drag != "quadratic":
            keys = ["drag-linear"] if scene.drag == "linear" else ["rounding"]
        else:
            keys = {"none": [], "linear": ["drag-linear"], "quadratic": ["drag-quadratic"]}[scene.drag] + \
                ["finite-swing"]
    elif model == "linear":
        keys = ["rounding"] if q == "angular-momentum" else ["finite-swing"]
    elif model == "quadratic-first-order":
        keys = ["drag-second-order", "finite-swing"]
    elif model == "quadratic":
        keys = ["finite-swing", "integration"]
    elif model == "spherical":
        keys = ["integration"]
    elif model == "period-series":
        keys = ["series"]
    elif model == "period-exact":
        keys = ["rounding"]
    else:
        raise ValueError(f"unknown model {model!r}")
    value = sum(effects[k_][1] for k_ in keys)
    return max(value, 4 * EPS * _scale(scene)), "; ".join(effects[k_][0] for k_ in keys)


# --- the rungs' answers -------------------------------------------------------------------------------
def _small_rhs(Omega: float, beta: float):
    """(26)–(27) as a first-order system for (x, y, ẋ, ẏ) (the same equations as
    :func:`quadratic.integrate_full`, which returns positions only)."""
    w2 = Omega * Omega

    def f(_t, s):
        sp = math.hypot(s[2], s[3])
        return (s[2], s[3], -w2 * s[0] - beta * s[2] * sp, -w2 * s[1] - beta * s[3] * sp)

    return f


def _full_rhs(scene: Scene):
    return spherical.rhs_factory(scene.length, scene.g, scene.kappa, scene.beta)


def _atol(scene: Scene, rtol: float) -> float:
    a, b = scene.semi_axes
    return rtol * max(a, b) * min(1.0, scene.Omega) * 1e-2


def _states(f, scene: Scene, t: np.ndarray, rtol: float) -> np.ndarray:
    """(X, Y, Ẋ, Ẏ) at times t (a swing with v0 > 0: the speed never vanishes, no kink)."""
    from scipy.integrate import solve_ivp

    sol = solve_ivp(f, (0.0, float(t[-1])), (scene.R0, 0.0, 0.0, scene.v0), method="DOP853", t_eval=t, rtol=rtol,
                    atol=_atol(scene, rtol))
    if not sol.success or sol.y.shape[1] != t.size:
        raise ArithmeticError(f"integration failed: {sol.message}")
    return sol.y


def first_revolution(f, scene: Scene, rtol: float, t_max: float):
    """(t, state) at the end of the first revolution of the system ``f``: the azimuth has turned
    through 2π (Y crosses zero upwards), or for a planar swing the bob is back at a turning point
    on the release side (Ẋ crosses zero downwards, after the far turning point).  The integration
    restarts at the far turning point, so a drag with a kink where the speed vanishes is never
    stepped across.  None when no revolution completes before ``t_max``, or before the swing
    has faded below FADED of its start (overdamped: there the integration only follows noise)."""
    from scipy.integrate import solve_ivp

    atol = _atol(scene, rtol)
    a, b = scene.semi_axes
    floor, w2 = FADED * max(a, b), scene.Omega**2

    def faded(_t, s):  # the swing's size √(X² + Y² + v²/Ω²), zero only at rest
        return math.sqrt(s[0] * s[0] + s[1] * s[1] + (s[2] * s[2] + s[3] * s[3]) / w2) - floor

    faded.terminal, faded.direction = True, -1
    # leave the start, where the event functions vanish
    t0 = scene.T0 / 8
    sol = solve_ivp(f, (0.0, t0), (scene.R0, 0.0, 0.0, scene.v0), method="DOP853", rtol=rtol, atol=atol)
    state = sol.y[:, -1].copy()
    crossings = ((2, 1), (2, -1)) if scene.planar else ((1, 1),)
    for index, direction in crossings:
        def event(_t, s, i=index):
            return s[i]

        event.terminal, event.direction = True, direction
        sol = solve_ivp(f, (t0, t_max), state, method="DOP853", rtol=rtol, atol=atol, events=(event, faded))
        if sol.status == -1:
            raise ArithmeticError(f"integration failed: {sol.message}")
        if sol.status != 1 or not sol.t_events[0].size:
            return None
        t0, state = float(sol.t_events[0][0]), sol.y_events[0][0].copy()
        state[index] = 0.0
    return t0, state


def _revolution_limit(scene: Scene) -> float:
    w2 = (scene.Omega - scene.kappa) * (scene.Omega + scene.kappa)
    base = 50 * scene.T0
    return max(base, 3 * 2 * math.pi / math.sqrt(w2)) if w2 > 0 else base


def answer(scene: Scene, model: str, rtol: float = 1e-12, times: np.ndarray | None = None, terms: int | None = None):
    """The answer of one rung to the scene's question (None: the rung has no answer, e.g. no
    revolution completes)."""
    q, Om, R0, v0 = scene.quantity, scene.Omega, scene.R0, scene.v0
    k, beta, T0 = scene.kappa, scene.beta, scene.T0
    if q in NEEDS_DURATION and times is None:
        times = sample_times(scene)
    w2 = (Om - k) * (Om + k)
    if model in ("period-series", "period-exact"):
        if model == "period-exact":
            return T0 * float(period.period_ratio(scene.phi0))
        m = math.sin(scene.phi0 / 2) ** 2
        return T0 * float(period.series_ratio(np.array([m]), terms)[0][0])
    if model == "ellipse":
        return {"trajectory": lambda: np.array(motion.linear(times, R0, v0, Om, 0.0)),
                "period": lambda: T0,
                "decay-per-revolution": lambda: 0.0,
                "angular-momentum": lambda: np.full(times.shape, R0 * v0)}[q]()
    if model == "linear":
        if q == "trajectory":
            return np.array(motion.linear(times, R0, v0, Om, k))
        if q == "angular-momentum":  # law (4), exact in this model
            return R0 * v0 * np.exp(-2 * k * times)
        if w2 <= 0:
            return None  # aperiodic: no revolution
        w = math.sqrt(w2)
        return 2 * math.pi / w if q == "period" else -R0 * math.expm1(-2 * math.pi * k / w)
    if model == "quadratic-first-order":
        if q == "trajectory":
            return np.array(quadratic.first_order(times, R0, v0, Om, beta))
        if q == "period":  # the first-order revolution ends at Ωt = 2π exactly (G(2π) = 0)
            return T0
        if q == "decay-per-revolution":
            x, _ = quadratic.first_order(np.array([T0]), R0, v0, Om, beta)
            return R0 - float(x[0])
        return R0 * v0 * np.exp(-beta * ellipse_path(scene, times))  # (5) along the ideal ellipse
    if model in ("quadratic", "spherical"):
        f = _small_rhs(Om, beta) if model == "quadratic" else _full_rhs(scene)
        if q == "trajectory":
            if model == "quadratic":
                return np.array(quadratic.integrate_full(times, R0, v0, Om, beta, rtol=rtol))
            return np.array(spherical.integrate(times, R0, v0, scene.length, scene.g, k, beta, rtol=rtol))
        if q == "angular-momentum":
            if scene.planar:
                return np.zeros(times.shape)
            X, Y, U, W = _states(f, scene, times, rtol)
            return X * W - Y * U
        rev = first_revolution(f, scene, rtol, _revolution_limit(scene))
        if rev is None:
            return None
        t_rev, state = rev
        return t_rev if q == "period" else R0 - float(state[0])
    raise ValueError(f"unknown model {model!r}")


def ellipse_path(scene: Scene, t) -> np.ndarray:
    """The path length s0(t) along the ideal ellipse (24)–(25):
    s0 = (u/Ω)∫₀^{Ωt} √(1 − m cos²φ) dφ = R0 [E(Ωt − π/2 | m) + E(m)], u = R0Ω, m = (u² − v0²)/u²."""
    from scipy.special import ellipe, ellipeinc

    u = scene.R0 * scene.Omega
    m = (u - scene.v0) * (u + scene.v0) / (u * u)
    return scene.R0 * (ellipeinc(scene.Omega * np.asarray(t, dtype=float) - math.pi / 2, m) + ellipe(m))


# --- the decision ------------------------------------------------------------------------------------
def decide(scene: Scene) -> Decision:
    """Rate every rung of the scene's ladder and choose the cheapest within the tolerance."""
    import scipy.integrate  # noqa: F401 - imported before the clocks start: each rung's seconds are its own
    import scipy.special  # noqa: F401

    start = time.perf_counter()
    rtol = _rtol(scene)
    times = sample_times(scene) if scene.quantity in NEEDS_DURATION else None
    names = ladder(scene)
    if names[-1] == "period-exact":
        ratings = _decide_planar_period(scene)
    else:
        values, seconds = [], []
        for name in names:
            t0 = time.perf_counter()
            values.append(answer(scene, name, rtol=rtol, times=times))
            seconds.append(time.perf_counter() - t0)
        if values[-1] is None:
            raise scene.error(f"has no answer for this scene: the bob does not complete a revolution before its "
                              f"swing fades below {FADED:g} of its start (overdamped: κ ≥ Ω)", "question.quantity")
        # the richest rung: its own integration at two tolerances
        t0 = time.perf_counter()
        loose = answer(scene, names[-1], rtol=min(1e-6, 100 * rtol), times=times)
        seconds[-1] += time.perf_counter() - t0
        n = len(names)
        diffs = [distance(scene.quantity, values[i], values[i + 1]) for i in range(n - 1)]
        diffs.append(max(distance(scene.quantity, values[-1], loose), 4 * EPS * _scale(scene)))
        errors = [0.0] * n
        errors[-1] = diffs[-1]
        for i in range(n - 2, -1, -1):
            # two triangle bounds, both measured: via the next richer rung, and via the richest
            errors[i] = min(diffs[i] + errors[i + 1], distance(scene.quantity, values[i], values[-1]) + errors[-1])
        ratings = []
        for i, name in enumerate(names):
            # the richest rung's estimate measures the run at 100·rtol: its a priori is that run's
            pri, neglects = a_priori(scene, name, rtol=rtol if i < n - 1 else min(1e-6, 100 * rtol))
            against = names[i + 1] if i < n - 1 else \
                f"itself at rtol {min(1e-6, 100 * rtol):.0e} (answer at rtol {rtol:.0e})"
            richer = errors[i + 1] if i < n - 1 else 0.0
            ratings.append(Rating(name, values[i], pri, neglects, errors[i], against, diffs[i],
                                  diffs[i] <= 10 * pri + richer, seconds[i]))
    ratings = tuple(ratings)
    chosen = next((r for r in ratings if r.estimated_error <= scene.tolerance), None)
    meets = chosen is not None
    return Decision(scene, ratings, chosen if meets else ratings[-1], meets, times, time.perf_counter() - start)


def _decide_planar_period(scene: Scene) -> list[Rating]:
    """Planar swing, no drag: T0, the series (66) with the fewest terms that meets the tolerance
    (and the one term fewer, rejected), and the exact period, itself checked against mpmath."""
    import mpmath

    t0 = time.perf_counter()
    exact = answer(scene, "period-exact")
    with mpmath.workdps(40):
        t_mp = 2 * mpmath.pi * mpmath.sqrt(mpmath.mpf(scene.length) / mpmath.mpf(scene.g)) * \
            period.period_ratio_mp(phi0=scene.phi0, dps=30)
        err_exact = float(abs(mpmath.mpf(exact) - t_mp)) + 2 * EPS * exact
    sec_exact = time.perf_counter() - t0
    pri, neg = a_priori(scene, "period-exact")
    exact_rating = Rating("period-exact", exact, pri, neg, err_exact, "mpmath, 30 digits", err_exact,
                          err_exact <= 10 * pri, sec_exact)

    def rate(model, value, seconds, terms=None):
        pri, neg = a_priori(scene, model, terms=terms)
        diff = abs(value - exact)
        return Rating(model, value, pri, neg, diff + err_exact, "period-exact", diff, diff <= 10 * pri + err_exact,
                      seconds, terms)

    t0 = time.perf_counter()
    ellipse_rating = rate("ellipse", scene.T0, time.perf_counter() - t0)
    ratings = [ellipse_rating]
    if ellipse_rating.estimated_error > scene.tolerance:
        # the fewest terms of (66) within the tolerance; the series converges like mⁿ/n with
        # m = sin²(φ0/2) < ½ (amplitudes below 90°): it reaches rounding before 60 terms
        m = math.sin(scene.phi0 / 2) ** 2
        series = []
        for n in range(2, SERIES_MAX_TERMS + 1):
            t0 = time.perf_counter()
            series.append(rate("period-series", answer(scene, "period-series", terms=n), time.perf_counter() - t0,
                               terms=n))
            if series[-1].estimated_error <= scene.tolerance or m**n < 1e-3 * EPS:
                break
        # the rejected one term fewer (if it is not the ellipse) and the last one tried
        ratings += series[-2:]
    ratings.append(exact_rating)
    return ratings


# --- views -------------------------------------------------------------------------------------------
def meaning(scene: Scene) -> str:
    """What the asked quantity means for this scene, in a sentence."""
    q = scene.quantity
    if q == "trajectory":
        return "X(t), Y(t): the bob's horizontal displacement from the vertical (m)"
    if q == "angular-momentum":
        return "L(t) = XẎ − YẊ: the vertical angular momentum per unit mass (m²/s)"
    end = ("the bob is back at its turning point on the release side" if scene.planar else
           "its azimuth has turned through 2π")
    if q == "period":
        if scene.drag == "none":
            return f"the period (s): the time until {end}"
        return (f"the duration of the first revolution (s), until {end}; with drag the motion is not "
                "periodic and each revolution lasts a little differently")
    return f"R0 − R1 (m): how much closer to the vertical the bob is when {end}"


def _num(x) -> float | None:
    return float(x) if x is not None and math.isfinite(x) else None


def answer_document(decision: Decision) -> dict:
    scene, value = decision.scene, decision.chosen.value
    if scene.quantity == "trajectory":
        return {"t": decision.times.tolist(), "x": value[0].tolist(), "y": value[1].tolist()}
    if scene.quantity == "angular-momentum":
        return {"t": decision.times.tolist(), "L": value.tolist()}
    return {"value": float(value)}


def document(decision: Decision) -> dict:
    """The decision as JSON-ready data (deterministic except the keys named "seconds")."""
    scene, chosen = decision.scene, decision.chosen

    def rating(r: Rating) -> dict:
        out = {"model": r.model}
        if r.terms:
            out["terms"] = r.terms
        out.update({"estimated_error": _num(r.estimated_error), "a_priori_error": _num(r.a_priori),
                    "confirmed": r.confirmed, "checked_against": r.checked_against, "neglects": r.neglects})
        if not isinstance(r.value, np.ndarray):
            out["value"] = _num(r.value) if r.value is not None else None
        out["seconds"] = r.seconds
        return out

    doc = {"scene": scene.title or Path(scene.source).stem, "source": scene.source, "quantity": scene.quantity,
           "meaning": meaning(scene), "unit": scene.unit, "tolerance": scene.tolerance, "model": chosen.model}
    if chosen.terms:
        doc["terms"] = chosen.terms
    doc.update({"description": RUNGS[chosen.model], "meets_tolerance": decision.meets,
                "estimated_error": _num(chosen.estimated_error), "a_priori_error": _num(chosen.a_priori),
                "checked_against": chosen.checked_against,
                "rejected": [{"model": r.model, **({"terms": r.terms} if r.terms else {}),
                              "estimated_error": _num(r.estimated_error), "a_priori_error": _num(r.a_priori),
                              "neglects": r.neglects} for r in decision.rejected],
                "ladder": [rating(r) for r in decision.ratings],
                "answer": answer_document(decision), "seconds": decision.seconds})
    return doc


def _fmt(x: float | None, unit: str) -> str:
    if x is None or math.isnan(x):
        return "none (no answer)"
    return f"{x:.3g} {unit}" if math.isfinite(x) else "unbounded"


def report(decision: Decision) -> str:
    """A plain-text account: the choice, why the cheaper models were rejected, the evidence."""
    s, c, u = decision.scene, decision.chosen, decision.scene.unit
    what = f"{s.quantity} over {s.duration:g} s" if s.duration else s.quantity
    drag = {"none": "no drag", "linear": f"linear drag κ = {s.coefficient:g} 1/s",
            "quadratic": f"quadratic drag β = {s.coefficient:g} 1/m"}[s.drag]
    lines = [f"scene     {s.title or Path(s.source).stem}  ({s.source})",
             f"pendulum  l = {s.length:g} m, g = {s.g:g} m/s^2 (Ω = {s.Omega:.6g} 1/s, T0 = {s.T0:.6g} s); "
             f"R0 = {s.R0:.6g} m (φ0 = {math.degrees(s.phi0):.4g}°), v0 = {s.v0:g} m/s; {drag}",
             f"question  {what}, tolerance {s.tolerance:g} {u}",
             f"          {meaning(s)}"]
    if decision.meets:
        lines.append(f"model     {c.label}: {RUNGS[c.model]}")
    else:
        lines.append(f"model     none meets the tolerance; the best is {c.label}: {RUNGS[c.model]}")
    lines.append(f"          estimated error {_fmt(c.estimated_error, u)} (checked against {c.checked_against}); "
                 f"a priori {_fmt(c.a_priori, u)}")
    if decision.rejected:
        lines.append("rejected")
        for r in decision.rejected:
            lines.append(f"  {r.label:<26} estimated error {_fmt(r.estimated_error, u):<18} > {s.tolerance:g} {u}; "
                         f"neglects {r.neglects} (a priori {_fmt(r.a_priori, u)})")
    lines.append("ladder    (a posteriori: against the next richer rung plus its own error)")
    for r in decision.ratings:
        mark = "*" if r is c else " "
        flag = "" if r.confirmed else "  [a priori NOT confirmed]"
        lines.append(f" {mark} {r.label:<26} {_fmt(r.estimated_error, u):<18} a priori {_fmt(r.a_priori, u):<12}"
                     f" vs {r.checked_against}{flag}")
    if s.quantity == "trajectory":
        x, y = c.value
        lines.append(f"answer    {decision.times.size} points; at t = {s.duration:g} s: x = {x[-1]:.9g} m, "
                     f"y = {y[-1]:.9g} m  (--json for all)")
    elif s.quantity == "angular-momentum":
        lines.append(f"answer    {decision.times.size} points; L(0) = {c.value[0]:.9g}, L({s.duration:g} s) = "
                     f"{c.value[-1]:.9g} m^2/s (per unit mass; --json for all)")
    else:
        lines.append(f"answer    {s.quantity} = {float(c.value):.12g} {u}")
    lines.append(f"time      {decision.seconds:.2f} s")
    return "\n".join(lines)


def plot(decision: Decision, path) -> None:
    """The evidence as a PNG (fixed metadata: byte-identical for the same decision): the answer
    (for curves) and each rung's error against the next richer rung, with the tolerance."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    s, c = decision.scene, decision.chosen
    curves = s.quantity in NEEDS_DURATION
    with matplotlib.rc_context({"svg.hashsalt": "quasicentral", "font.size": 8}):
        fig, axes = plt.subplots(1, 2 if curves else 1, figsize=(10.0 if curves else 5.5, 4.0), dpi=110,
                                 squeeze=False)
        axes = axes[0]
        if curves:
            ax = axes[0]
            rich = decision.richest.value
            if s.quantity == "trajectory":
                ax.plot(rich[0] * 1e3, rich[1] * 1e3, "k--", lw=0.6, label=f"{decision.richest.label} (richest)")
                ax.plot(c.value[0] * 1e3, c.value[1] * 1e3, lw=0.9, label=f"{c.label} (chosen)")
                ax.set_xlabel("x [mm]")
                ax.set_ylabel("y [mm]")
                ax.set_aspect("equal", adjustable="datalim")
            else:
                ax.plot(decision.times, rich, "k--", lw=0.6, label=f"{decision.richest.label} (richest)")
                ax.plot(decision.times, c.value, lw=0.9, label=f"{c.label} (chosen)")
                ax.set_xlabel("t [s]")
                ax.set_ylabel("L [m²/s]")
            ax.legend(fontsize=7)
            ax.grid(True, lw=0.3)
            ax = axes[1]
            for lower, upper in zip(decision.ratings, decision.ratings[1:]):
                if s.quantity == "trajectory":
                    d = np.hypot(lower.value[0] - upper.value[0], lower.value[1] - upper.value[1])
                else:
                    d = np.abs(lower.value - upper.value)
                ax.semilogy(decision.times, np.where(d > 0, d, np.nan), lw=0.8 if lower is not c else 1.4,
                            label=f"{lower.label} − {upper.label}")
            ax.axhline(s.tolerance, color="r", lw=0.8, ls=":", label="tolerance")
            ax.axhline(decision.richest.estimated_error, color="k", lw=0.6, ls="--",
                       label=f"{decision.richest.label}: own error")
            low, high = ax.get_ylim()
            ax.set_ylim(max(low, 1e-6 * min(s.tolerance, decision.richest.estimated_error)), high)
            ax.set_xlabel("t [s]")
            ax.set_ylabel(f"difference [{s.unit}]")
            ax.legend(fontsize=7)
            ax.grid(True, lw=0.3)
        else:
            ax = axes[0]
            labels = [r.label for r in decision.ratings]
            errs = [r.estimated_error if math.isfinite(r.estimated_error) else np.nan for r in decision.ratings]
            colors = ["tab:green" if r is c and decision.meets else "tab:gray" for r in decision.ratings]
            ax.bar(range(len(labels)), errs, color=colors, log=True)
            ax.scatter(range(len(labels)), [r.a_priori for r in decision.ratings], marker="_", s=200, color="k",
                       label="a priori", zorder=3)
            ax.axhline(s.tolerance, color="r", lw=0.8, ls=":", label="tolerance")
            ax.set_xticks(range(len(labels)), labels, rotation=20, fontsize=7)
            ax.set_ylabel(f"estimated error [{s.unit}]")
            ax.legend(fontsize=7)
            ax.grid(True, lw=0.3, axis="y")
        fig.suptitle(f"{s.title or Path(s.source).stem}: {s.quantity} → {c.label}", fontsize=9)
        fig.tight_layout()
        fig.savefig(path, format="png", metadata={"Software": None})
        plt.close(fig)
