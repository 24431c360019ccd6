"""Brepta's figures 7a, 7b and 8 (lost in the print), reproduced from the closed form of the
linear-drag motion, the overdamped case beside them, and the measured charts of the small
swings.  Parameters as in the paper's example: Ω = √10 1/s, R0 = v0 = 0.1."""

from __future__ import annotations

import numpy as np

from quasicentral.models import motion
from quasicentral.models.parameters import FIGURE_OMEGA as OMEGA
from quasicentral.studies.figures import Figure, Kind, measured, measured_names

R0 = V0 = 0.1


def _linear(name, title, kappa, t_end, kind=Kind.TRAJECTORY, n=2001) -> Figure:
    t = np.linspace(0.0, t_end, n)
    x, y = motion.linear(t, R0, V0, OMEGA, kappa)
    return Figure(name, title, ("t", "x", "y"), np.column_stack([t, x, y]), kind)


def fig7a() -> Figure:
    return _linear("fig7a", "Fig. 7a: linear drag, κ = 0.4 1/s, Ω = √10 1/s, R0 = v0 = 0.1", 0.4, 8.0)


def fig7b() -> Figure:
    return _linear("fig7b", "Fig. 7b: x(t) and y(t) of the same motion", 0.4, 8.0, Kind.TIME)


def fig8() -> Figure:
    return _linear("fig8", "Fig. 8: aperiodic limit κ = Ω = √10 1/s, R0 = v0 = 0.1", OMEGA, 3.0)


def overdamped() -> Figure:
    return _linear("overdamped", "Overdamped κ = 2Ω (not in the paper)", 2 * OMEGA, 3.0)


def _measured(name):
    def make():
        return measured(name)

    make.__name__ = name
    return make


#: the text's figures, in the order its report shows them
FIGURES = (fig7a, fig7b, fig8, overdamped) + tuple(_measured(n) for n in measured_names() if "period" not in n)
