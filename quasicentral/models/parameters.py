"""The parameters of a swing, validated in one place, and the figures' parameters.

Conventions (as in [Brepta1953]): the bob starts at x = R0, y = 0 with the horizontal velocity
v0 along +y; Ω² = g/l; linear drag R = 2κmv (κ in 1/s), quadratic drag R = mβv² (β in 1/m).

>>> Swing(R0=0.1, v0=0.1, omega2=10.0, kappa=0.4).kappa
0.4
>>> Swing(R0=5.0, v0=0.0, omega2=9.81, length=1.0, g=9.81)
Traceback (most recent call last):
...
quasicentral.models.parameters.ParameterError: R0 must be below the length l = 1 (the bob starts below the pivot's horizontal), not 5
"""

from __future__ import annotations

import math
from dataclasses import dataclass

#: the figures' pendulum: Ω² = 10 1/s² (Ω = √10), and standard gravity for the scenes
FIGURE_OMEGA2 = 10.0
FIGURE_OMEGA = math.sqrt(FIGURE_OMEGA2)
G_STANDARD = 9.81


class ParameterError(ValueError):
    """A parameter outside its domain; ``name`` is the parameter (R0, v0, omega2, kappa, …)."""

    def __init__(self, message: str, name: str | None = None):
        super().__init__(message)
        self.name = name


def _fmt(x) -> str:
    try:
        return f"{float(x):g}"
    except (TypeError, ValueError, OverflowError):
        return str(x)


@dataclass(frozen=True)
class Swing:
    """One start of the pendulum.  Numbers are floats or mpmath numbers (never mixed with
    strings: read text with :mod:`quasicentral.notation.numbers` first).  ``length`` and ``g``
    are optional for the small-swing models (only Ω² = g/l enters them); when given, R0 must
    be below the length, and the start must keep the bob below the pivot's horizontal."""

    R0: object
    v0: object
    omega2: object
    kappa: object = 0
    beta: object = 0
    length: object = None
    g: object = None

    def __post_init__(self):
        checks = (("R0", self.R0, "a positive length"), ("omega2", self.omega2, "positive (Ω² = g/l)"))
        for name, val, what in checks:
            if not val > 0:
                raise ParameterError(f"{name} must be {what}, not {_fmt(val)}", name)
        for name in ("v0", "kappa", "beta"):
            val = getattr(self, name)
            if not val >= 0:
                raise ParameterError(f"{name} must be ≥ 0, not {_fmt(val)}", name)
        if self.kappa and self.beta:
            raise ParameterError("give one drag law: kappa (linear) or beta (quadratic)", "beta")
        for name in ("length", "g"):
            val = getattr(self, name)
            if val is not None and not val > 0:
                raise ParameterError(f"{name} must be positive, not {_fmt(val)}", name)
        if self.length is not None and not self.R0 < self.length:
            raise ParameterError(f"R0 must be below the length l = {_fmt(self.length)} (the bob starts below "
                                 f"the pivot's horizontal), not {_fmt(self.R0)}", "R0")
        if self.length is not None and self.g is not None:
            z0 = ((self.length - self.R0) * (self.length + self.R0)) ** 0.5
            if not self.v0 * self.v0 / 2 < self.g * z0:
                raise ParameterError("v0 is so large that the bob could rise to the pivot's horizontal "
                                     f"(½v0² ≥ g·Z0 = {_fmt(self.g * z0)} m²/s²)", "v0")

    @property
    def scale(self):
        """The size of the motion, max(R0, v0/Ω): the semi-axes of the small-swing ellipse."""
        return max(self.R0, self.v0 / self.omega2 ** 0.5)
