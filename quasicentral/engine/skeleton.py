"""``quasicentral new-text DIR``: the skeleton of a text of one's own, which verifies at once.

It holds two printed equations of uniformly accelerated motion, one right and one with a typo
(a missing factor 2), their derivations, and the erratum recorded for the typo: the whole loop
of transcribing, deriving, verifying and recording, in the smallest form.
"""

from __future__ import annotations

import re
from pathlib import Path

from quasicentral.files import write_text

_ID = re.compile(r"[a-z0-9][a-z0-9_-]*\Z")


class SkeletonError(ValueError):
    """The skeleton cannot be written there (one line: why)."""


TEXT_TOML = '''\
# The text: its id prefixes every equation id; its symbols are the only names its transcriptions
# and derivations may use.  The format is described in quasicentral's texts/FORMAT.md.
id = "{id}"
title = "Uniformly accelerated motion"
authors = ["Your Name"]
year = 2026
language = "en"

# Each symbol: its LaTeX, its dimension (a formula in L, T, M, Theta such as "L/T^2", or units by
# name such as "m/s^2", "J/K"; "1" for none), its assumptions, and the range the checker samples
# it from (or a definition in other symbols instead of a range).
[symbols.t]
meaning = "time"
latex = 't'
dimension = "T"
assumptions = ["nonnegative"]
range = ["0", "10"]
dots = true   # derivatives in t print as Newton dots

[symbols.a]
meaning = "constant acceleration"
latex = 'a'
dimension = "L/T^2"
assumptions = ["real"]
range = ["-5", "5"]

[symbols.x0]
meaning = "initial position"
latex = 'x_0'
dimension = "L"
assumptions = ["real"]
range = ["-2", "2"]

[symbols.v0]
meaning = "initial velocity"
latex = 'v_0'
dimension = "L/T"
assumptions = ["real"]
range = ["-3", "3"]

# Quantities along the motion: functions of one independent variable.
[functions.x]
meaning = "position"
latex = 'x'
variable = "t"
dimension = "L"
assumptions = ["real"]

[functions.v]
meaning = "velocity"
latex = 'v'
variable = "t"
dimension = "L/T"
assumptions = ["real"]
'''

CATALOG_TOML = '''\
# What is printed, verbatim: `latex` as typeset, `printed` its transcription in sympy syntax
# (typos included: a wrong print stays wrong here; the erratum records the correction).
section = "1"
title = "Uniformly accelerated motion"

[[equation]]
id = "{id}:1"
number = "1"
name = "position under a constant acceleration"
latex = \'\'\'x = x_0 + v_0 t + \\frac{{1}}{{2}} a t^2\'\'\'
printed = \'\'\'Eq(x, x0 + v0*t + a*t**2/2)\'\'\'

[[equation]]
id = "{id}:2"
number = "2"
name = "velocity and position without the time"
latex = \'\'\'v^2 = v_0^2 + a (x - x_0)\'\'\'
printed = \'\'\'Eq(v**2, v0**2 + a*(x - x0))\'\'\'
note = "As printed, with a typo: the factor 2 of 2a(x - x0) is missing (see errata/motion.toml)."
'''

ERRATA_TOML = '''\
# The errata found in the text: the printed form must come out refuted and `corrected` must
# verify.  Each erratum names its root cause(s): one fault that reaches several displays is one
# cause.  A note quotes numbers only through {{witness}} placeholders, filled from the witness.
# A suspicion that proved right goes into a [[cleared]] table instead.
[[cause]]
id = "factor-two"
title = "The factor 2 of the work-energy relation is lost"
title_cs = "Ve vztahu práce a energie chybí činitel 2"
kind = "missing factor"
note = "Eliminating t from x(t) and v(t) gives v^2 - v0^2 = 2a(x - x0); the print drops the 2."
note_cs = "Vyloučením t z x(t) a v(t) vyjde v^2 - v0^2 = 2a(x - x0); v tisku dvojka chybí."

[[erratum]]
id = "{id}:2"
kind = "missing factor"
cause = ["factor-two"]
corrected = \'\'\'Eq(v**2, v0**2 + 2*a*(x - x0))\'\'\'
corrected_latex = \'\'\'v^2 = v_0^2 + 2 a (x - x_0)\'\'\'
note = "Eliminating t from (1) and v = dx/dt gives v^2 - v0^2 = 2a(x - x0): the printed relation lacks the factor 2.  Witness: {{witness}}."
'''

DERIVATION_PY = '''\
"""Derivations of the text, one small function per printed equation, in the text's order.

Each function returns sympy objects and is registered with @derives for the catalog id it
settles; its docstring states the formula.  See quasicentral's texts/FORMAT.md.
"""

import sympy as sp

from quasicentral.engine.registry import derived, derives
from quasicentral.engine.texts import symbols_of

S = symbols_of(__file__)  # this text's symbols, declared in text.toml
t, a, x0, v0, x, v = S("t a x0 v0 x v")


@derives("{id}:1", unknowns=(x,))
def position():
    """x = x0 + v0 t + a t^2/2: x'' = a integrated twice, with x(0) = x0 and x'(0) = v0."""
    X = sp.Function("X")
    motion = sp.dsolve(sp.Eq(X(t).diff(t, 2), a), X(t), ics={{X(0): x0, X(t).diff(t).subs(t, 0): v0}})
    return sp.Eq(x, motion.rhs)


@derives("{id}:2", mode="substitute", uses=("{id}:1",))
def velocity_squared():
    """v^2 = v0^2 + 2a(x - x0) holds on the motion (1) with v = dx/dt: the printed relation is
    checked on that motion (lhs - rhs must vanish at every time)."""
    position = derived("{id}:1").rhs
    return {{x: position, v: sp.diff(position, t)}}
'''


def write(folder: Path, text_id: str | None = None) -> list[Path]:
    """Write the skeleton into ``folder`` (new, or empty); returns the files written."""
    tid = text_id if text_id is not None else re.sub(r"[^a-z0-9_-]", "-", folder.name.lower()).strip("-_")
    if not _ID.match(tid or ""):
        raise SkeletonError(f"--id: a text's id is lower-case letters, digits, - and _ (got {tid!r}); "
                            "give one with --id")
    if folder.is_symlink() or (folder.exists() and not folder.is_dir()):
        raise SkeletonError(f"{folder}: exists and is not a folder")
    if folder.is_dir() and any(folder.iterdir()):
        raise SkeletonError(f"{folder}: not empty (new-text writes into a new or empty folder)")
    files = {
        "text.toml": TEXT_TOML, "catalog/motion.toml": CATALOG_TOML, "errata/motion.toml": ERRATA_TOML,
        "motion.py": DERIVATION_PY,
    }
    written = []
    try:
        for rel, template in files.items():
            path = folder / rel
            path.parent.mkdir(parents=True, exist_ok=True)
            write_text(path, template.format(id=tid))
            written.append(path)
    except OSError as exc:
        raise SkeletonError(f"{folder}: cannot write: {exc.strerror or exc}") from None
    return written
