"""Reading a scene: the TOML file, its quantities with units (pint), and the checks that name
the key and its line.

A quantity is a number in SI units or a string ``"NUMBER UNIT"`` with any unit of the right
dimension that pint knows (``"1 us"``, ``"2 cm"``, ``"1.8 km/h"``, ``"0.5 1/m"``); the number
is a plain decimal (:mod:`quasicentral.notation.numbers`: ``"1_ m"`` is refused).  Inputs are
bounded: the file (1 MiB), the nesting of TOML values, the magnitudes of length, g and drag.
"""

from __future__ import annotations

import functools
import math
import re
import tomllib
import unicodedata
from dataclasses import dataclass
from pathlib import Path

from quasicentral.models.parameters import G_STANDARD
from quasicentral.notation import numbers

QUANTITIES = {"trajectory": "m", "period": "s", "decay-per-revolution": "m", "angular-momentum": "m^2/s"}
DRAGS = ("none", "linear", "quadratic")
NEEDS_DURATION = ("trajectory", "angular-momentum")
MAX_PERIODS = 1000
G_DEFAULT = G_STANDARD
MAX_BYTES = 1 << 20  # a scene file is at most 1 MiB
MAX_UNIT_CHARS = 64
LENGTH_RANGE = (1e-6, 1e6)  # m: a pendulum's length (and g in m/s² alike)
MAX_DRAG = 1e3  # κ/Ω and β·l: beyond, the swing dies within a thousandth of a period (stiff)
MIN_DEPTH = 1e-6  # Z0/l: the bob must start at least this far below the pivot's horizontal


# --- errors ----------------------------------------------------------------------------------
def printable(text: str) -> str:
    """``text`` with control characters escaped (\\x1b → '\\\\x1b'): safe for a terminal."""
    return "".join(c if unicodedata.category(c)[0] != "C" else c.encode("unicode_escape").decode("ascii")
                   for c in text)


class SceneError(ValueError):
    """Bad scene input: the key's dotted name and its line in the file."""

    def __init__(self, message: str, key: str | None = None, line: int | None = None, source: str | None = None):
        super().__init__(message)
        self.message, self.key, self.line, self.source = message, key, line, source

    def __str__(self) -> str:
        where = ":".join(str(p) for p in (self.source, self.line) if p is not None)
        parts = [p for p in (where, self.key) if p]
        return printable(": ".join(parts + [self.message]))


# --- units -------------------------------------------------------------------------------------
#: dimension name → (SI unit, pint dimensionality as a string)
DIMENSIONS = {
    "length": ("m", "[length]"),
    "time": ("s", "[time]"),
    "speed": ("m/s", "[length] / [time]"),
    "acceleration": ("m/s^2", "[length] / [time] ** 2"),
    "rate": ("1/s", "1 / [time]"),
    "inverse length": ("1/m", "1 / [length]"),
    "angle in degrees": ("deg", "dimensionless"),
    "angular momentum per mass": ("m^2/s", "[length] ** 2 / [time]"),
}
_ANGLES = ("degree", "radian", "arcminute", "arcsecond", "turn", "gradian", "milliradian")
_QUANTITY_DIMENSION = {"trajectory": "length", "period": "time", "decay-per-revolution": "length",
                       "angular-momentum": "angular momentum per mass"}
_NUMBER_UNIT = re.compile(r"^\s*([-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?)(?:\s+|(?=[^0-9.eE+\-])|$)(.*?)\s*$")


@functools.lru_cache(maxsize=1)
def units():
    """The pint unit registry (built once per process; pint's own disk cache when writable)."""
    import pint

    try:
        return pint.UnitRegistry(cache_folder=":auto:")
    except Exception:  # noqa: BLE001 - an unwritable cache: build without it
        return pint.UnitRegistry(cache_folder=None)


def _unit(text: str):
    """pint units from text; '/s' and 's-1' are read as 1/s and s⁻¹."""
    text = text.strip()
    if text.startswith("/"):
        text = "1" + text
    text = re.sub(r"([A-Za-z])-([0-9])", r"\1^-\2", text)
    return units().parse_units(text)


def _dimension_name(dimensionality) -> str:
    for name, (_, dims) in DIMENSIONS.items():
        if str(dimensionality) == dims:
            return name if name != "angle in degrees" else "pure number or an angle"
    return f"quantity of dimension {dimensionality}"


def _article(noun: str) -> str:
    return ("an " if noun[0] in "aeiou" else "a ") + noun


def _toml_type(raw) -> str:
    return {bool: "a boolean", dict: "a table", list: "an array"}.get(type(raw), type(raw).__name__)


def quantity_value(raw, dimension: str, key: str, line_of) -> float:
    """A number in SI units, or a string 'NUMBER UNIT' converted to SI with pint; a wrong
    dimension or an unknown unit is one error naming the key."""
    si, dims = DIMENSIONS[dimension]

    def fail(message):
        return SceneError(message, key, line_of(key))

    if isinstance(raw, bool) or not isinstance(raw, (int, float, str)):
        raise fail(f"must be a number ({si}) or a string like '1.5 {si}', not {_toml_type(raw)}")
    if not isinstance(raw, str):
        try:
            return numbers.to_float(raw, "the value")
        except numbers.NumberError as exc:
            raise fail(str(exc).replace("the value ", "", 1)) from None
    m = _NUMBER_UNIT.match(raw)
    if not m or len(m.group(2)) > MAX_UNIT_CHARS:
        raise fail(f"must be a number with a unit ({si}), not {raw!r}")
    try:
        number = numbers.to_float(m.group(1), "the number")
    except numbers.NumberError as exc:
        raise fail(f"{raw!r}: {str(exc).replace('the number ', '', 1)}") from None
    if not m.group(2):
        return number
    return _convert(number, m.group(2), raw, dimension, fail)


def _convert(number: float, unit_text: str, raw: str, dimension: str, fail) -> float:
    import pint

    si, dims = DIMENSIONS[dimension]
    try:
        unit = _unit(unit_text)
    except Exception:  # noqa: BLE001 - pint raises several kinds for text it cannot read
        raise fail(f"unknown unit {unit_text!r} in {raw!r}; use a unit of {_article(dimension)}, e.g. {si}") from None
    q = units().Quantity(number, unit)
    if dimension == "angle in degrees" and not (set(dict(q.unit_items())) <= set(_ANGLES) and q.unit_items()):
        raise fail(f"{raw!r} is not an angle; this key needs degrees or another angle unit")
    if str(q.dimensionality) != dims:
        raise fail(f"{raw!r} is {_article(_dimension_name(q.dimensionality))}; this key needs "
                   f"{_article(dimension)} (e.g. {si})")
    try:
        value = float(q.to(si.replace("^", "**")).magnitude)
    except (pint.errors.PintError, OverflowError, ValueError) as exc:
        raise fail(f"cannot convert {raw!r} to {si}: {exc}") from None
    if not math.isfinite(value):
        raise fail(f"{raw!r} is too large for double precision")
    return value


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

    @property
    def name(self) -> str:
        """The title, or the file's stem, safe for a terminal."""
        return printable(self.title or Path(self.source).stem)

    def line(self, key: str) -> int | None:
        return lookup_line(dict(self.lines), key)

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
    """Read and check a scene file of at most 1 MiB (see :func:`parse`)."""
    path = Path(path)
    try:
        with open(path, "rb") as fh:
            data = fh.read(MAX_BYTES + 1)
    except OSError as exc:
        raise SceneError(f"cannot read the scene: {exc.strerror or exc}", source=printable(str(path))) from None
    if len(data) > MAX_BYTES:
        raise SceneError(f"the scene is larger than {MAX_BYTES // 1024} KiB; a scene is a short TOML file",
                         source=printable(str(path)))
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        raise SceneError("the scene is not UTF-8 text", source=printable(str(path))) from None
    return parse(text, source=str(path))


def parse(text: str, source: str = "<scene>") -> Scene:
    """A :class:`Scene` from TOML text; every problem is a :class:`SceneError` naming the key
    and its line (tomllib gives none: the lines are found in the text)."""
    if len(text) > MAX_BYTES:
        raise SceneError(f"the scene is larger than {MAX_BYTES // 1024} KiB", source=source)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        msg = str(exc)
        m = re.search(r"\(at line (\d+), column \d+\)", msg)
        raise SceneError(f"not valid TOML: {re.sub(r' ?[(]at line.*$', '', msg)}", None,
                         int(m.group(1)) if m else None, source) from None
    except RecursionError:
        raise SceneError("not valid TOML for a scene: arrays or tables nested too deeply", source=source) from None
    except ValueError as exc:  # e.g. an integer beyond Python's digit limit
        raise SceneError(f"not valid TOML: {exc}", source=source) from None
    lines = key_lines(text)

    def line_of(key):
        return lookup_line(lines, key)

    try:
        return _Builder(data, line_of, source).scene(lines)
    except SceneError as exc:
        if exc.source is None:
            exc.source = source
        raise


class _Builder:
    """The checks of a parsed scene, table by table; every error names the key and its line."""

    def __init__(self, data: dict, line_of, source: str):
        self.data, self.line_of, self.source = data, line_of, source

    def err(self, message: str, key: str) -> SceneError:
        return SceneError(message, key, self.line_of(key), self.source)

    def need(self, table: str, key: str):
        if key not in self.data[table]:
            raise self.err(f"missing: [{table}] needs {key}", f"{table}.{key}")  # the table's line
        return self.data[table][key]

    def quantity(self, table: str, key: str, dimension: str, raw=None) -> float:
        raw = self.need(table, key) if raw is None else raw
        return quantity_value(raw, dimension, f"{table}.{key}", self.line_of)

    def choice(self, table: str, key: str, choices) -> str:
        raw = self.need(table, key)
        if not isinstance(raw, str):
            raise self.err(f"must be a string, one of {', '.join(choices)}; not {_toml_type(raw)}", f"{table}.{key}")
        if raw not in choices:
            raise self.err(f"unknown value {printable(repr(raw))}; choose from {', '.join(choices)}", f"{table}.{key}")
        return raw

    def scene(self, lines) -> Scene:
        self.tables()
        title = self.texts()
        length, g = self.pendulum()
        R0, amplitude, v0 = self.start(length, g)
        drag, coefficient = self.medium(length, g)
        quantity, tol, duration = self.question(length, g)
        return Scene(length=length, g=g, R0=R0, v0=v0, drag=drag, coefficient=coefficient, quantity=quantity,
                     tolerance=tol, duration=duration, amplitude=amplitude, title=title, source=self.source,
                     lines=tuple(sorted(lines.items())))

    def tables(self) -> None:
        for name, value in self.data.items():
            if name not in _TABLES:
                raise self.err(f"unknown table or key; a scene has {', '.join('[' + t + ']' for t in _TABLES)}",
                               printable(name))
            if not isinstance(value, dict):
                raise self.err(f"must be a table [{name}], not {_toml_type(value)}", name)
            for key in value:
                if key not in _TABLES[name]:
                    raise self.err(f"unknown key; [{name}] takes {', '.join(sorted(_TABLES[name]))}",
                                   printable(f"{name}.{key}"))
        for name in ("pendulum", "start", "medium", "question"):
            if name not in self.data:
                raise SceneError(f"the scene has no [{name}] table", name, None, self.source)

    def texts(self) -> str:
        for key in ("title", "notes"):
            raw = self.data.get("scene", {}).get(key)
            if raw is not None and not isinstance(raw, str):
                raise self.err(f"must be a string, not {_toml_type(raw)}", f"scene.{key}")
            allowed = "\n\t" if key == "notes" else ""
            if raw and any(unicodedata.category(c)[0] == "C" and c not in allowed for c in raw):
                raise self.err("must not contain control characters", f"scene.{key}")
        return self.data.get("scene", {}).get("title", "")

    def pendulum(self) -> tuple[float, float]:
        lo, hi = LENGTH_RANGE
        length = self.quantity("pendulum", "length", "length")
        if length <= 0:
            raise self.err(f"must be a positive length, not {length:g} m", "pendulum.length")
        if not lo <= length <= hi:
            raise self.err(f"must be between {lo:g} m and {hi:g} m (a pendulum), not {length:g} m", "pendulum.length")
        g = G_DEFAULT
        if "g" in self.data["pendulum"]:
            g = self.quantity("pendulum", "g", "acceleration")
            if g <= 0:
                raise self.err(f"must be positive, not {g:g} m/s^2", "pendulum.g")
            if not lo <= g <= hi:
                raise self.err(f"must be between {lo:g} and {hi:g} m/s^2, not {g:g}", "pendulum.g")
        return length, g

    def start(self, length: float, g: float):
        st = self.data["start"]
        if ("displacement" in st) == ("amplitude_deg" in st):
            key = "start.amplitude_deg" if "amplitude_deg" in st else "start"
            raise self.err("give exactly one of displacement (m) and amplitude_deg", key)
        amplitude = None
        if "displacement" in st:
            key = "start.displacement"
            R0 = self.quantity("start", "displacement", "length")
            if not 0 < R0 < length:
                raise self.err(f"must be between 0 and the length {length:g} m (exclusive), not {R0:g} m", key)
            z0 = math.sqrt(length - R0) * math.sqrt(length + R0)
        else:
            key = "start.amplitude_deg"
            deg = self.quantity("start", "amplitude_deg", "angle in degrees")
            if not 0 < deg < 90:
                raise self.err(f"must be between 0 and 90 degrees (exclusive; R0 = l·sin(amplitude) is the "
                               f"horizontal distance and the bob starts below the pivot), not {deg:g}", key)
            amplitude = math.radians(deg)
            R0, z0 = length * math.sin(amplitude), length * math.cos(amplitude)
        if z0 < MIN_DEPTH * length:
            raise self.err(f"puts the bob {z0:.2g} m below the pivot's horizontal (less than {MIN_DEPTH:g} of the "
                           "length): outside every model here", key)
        v0 = self.quantity("start", "speed", "speed")
        if v0 < 0:
            raise self.err(f"must be ≥ 0 (a speed, perpendicular to the displacement), not {v0:g} m/s", "start.speed")
        if 0.5 * v0 * v0 >= g * z0:
            raise self.err(f"is too large: with ½v0² ≥ g·Z0 ({0.5 * v0 * v0:.3g} ≥ {g * z0:.3g} m²/s²) the bob may "
                           "rise to the pivot's horizontal, outside every model here", "start.speed")
        return R0, amplitude, v0

    def medium(self, length: float, g: float):
        drag = self.choice("medium", "drag", DRAGS)
        if drag == "none":
            if "coefficient" in self.data["medium"]:
                raise self.err("has no meaning with drag = \"none\"; remove it", "medium.coefficient")
            return drag, 0.0
        dim = "rate" if drag == "linear" else "inverse length"
        coefficient = self.quantity("medium", "coefficient", dim)
        what = "kappa [1/s], R = 2·kappa·m·v" if drag == "linear" else "beta [1/m], R = m·beta·v²"
        if coefficient <= 0:
            raise self.err(f"must be positive ({what}); for no drag write drag = \"none\"", "medium.coefficient")
        ratio = coefficient / math.sqrt(g / length) if drag == "linear" else coefficient * length
        if ratio > MAX_DRAG:
            name = "kappa/Omega" if drag == "linear" else "beta·l"
            raise self.err(f"is too large: {name} = {ratio:.3g} > {MAX_DRAG:g}, the swing dies within a thousandth "
                           "of a period and the integrators cannot follow it", "medium.coefficient")
        return drag, coefficient

    def question(self, length: float, g: float):
        quantity = self.choice("question", "quantity", tuple(QUANTITIES))
        tol = self.quantity("question", "tolerance", _QUANTITY_DIMENSION[quantity])
        if tol <= 0:
            raise self.err(f"must be positive (the largest acceptable absolute error, {QUANTITIES[quantity]}), "
                           f"not {tol:g}", "question.tolerance")
        duration = None
        T0 = 2 * math.pi * math.sqrt(length / g)
        if quantity in NEEDS_DURATION:
            duration = self.quantity("question", "duration", "time")
            if duration <= 0:
                raise self.err(f"must be positive, not {duration:g} s", "question.duration")
            if duration > MAX_PERIODS * T0:
                raise self.err(f"is longer than {MAX_PERIODS} periods ({MAX_PERIODS * T0:.4g} s), the most a scene "
                               "supports", "question.duration")
        elif "duration" in self.data["question"]:
            raise self.err(f"has no meaning for quantity {quantity!r} (the first revolution); remove it",
                           "question.duration")
        return quantity, tol, duration


# --- where a key is in the text ------------------------------------------------------------------
_BARE = r"[A-Za-z0-9_-]+"
_QUOTED = r'"(?:[^"\\]|\\.)*"' + r"|'[^']*'"
_KEY = rf"(?:{_BARE}|{_QUOTED})(?:\s*\.\s*(?:{_BARE}|{_QUOTED}))*"
_HEADER = re.compile(rf"^\[\[?\s*({_KEY})\s*\]\]?")
_ASSIGN = re.compile(rf"^({_KEY})\s*=")


def _norm_key(key: str) -> str:
    parts = re.findall(rf"{_BARE}|{_QUOTED}", key)
    return ".".join(p[1:-1] if p[:1] in "\"'" else p for p in parts)


def key_lines(text: str) -> dict[str, int]:
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


def lookup_line(lines: dict, key: str) -> int | None:
    """The line of ``key``, else of its nearest enclosing table."""
    parts = key.split(".")
    while parts:
        got = lines.get(".".join(parts))
        if got is not None:
            return got
        parts.pop()
    return None

