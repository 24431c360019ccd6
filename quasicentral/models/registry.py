"""The one registry of model names, from cheapest to richest.

Every list of models in the package is a selection of :class:`Model`: the trajectories of the
command line (:data:`TRAJECTORY`), the systems the reference integrators solve
(:data:`REFERENCE`), the paper's approximations measured against the full pendulum
(:data:`APPROXIMATIONS`) and the scene ladder (all of them).

>>> Model("quadratic-first-order").description.startswith("small swings, quadratic drag")
True
>>> [m.value for m in REFERENCE]
['linear', 'quadratic', 'spherical']
"""

from __future__ import annotations

from enum import Enum


class Model(str, Enum):
    """A model of the pendulum; the value is its name on the command line and in files."""

    ELLIPSE = "ellipse"
    LINEAR = "linear"
    QUADRATIC_FIRST_ORDER = "quadratic-first-order"
    QUADRATIC = "quadratic"
    SPHERICAL = "spherical"
    PERIOD_SERIES = "period-series"
    PERIOD_EXACT = "period-exact"

    def __str__(self) -> str:
        return self.value

    @property
    def description(self) -> str:
        return DESCRIPTIONS[self]

    @property
    def drag(self) -> str | None:
        """The drag law the model takes: ``"kappa"`` (linear), ``"beta"`` (quadratic), or None."""
        return {Model.LINEAR: "kappa", Model.QUADRATIC_FIRST_ORDER: "beta", Model.QUADRATIC: "beta"}.get(self)


DESCRIPTIONS = {
    Model.ELLIPSE: "small swings without drag: the ellipse (13)",
    Model.LINEAR: "small swings, linear drag R = 2κmv: the closed form (19)/(21) (overdamped too)",
    Model.QUADRATIC_FIRST_ORDER: "small swings, quadratic drag R = mβv² to first order in β: closed form (28)–(30)",
    Model.QUADRATIC: "small swings, quadratic drag: (26)–(27) integrated numerically (DOP853)",
    Model.SPHERICAL: "the full nonlinear spherical pendulum with drag, integrated numerically (DOP853)",
    Model.PERIOD_SERIES: "planar swing without drag: the series (66) truncated after N terms",
    Model.PERIOD_EXACT: "planar swing without drag: the exact period T0·2K(sin²(φ0/2))/π, (60)–(61)",
}

#: models of ``quasicentral trajectory`` (closed forms and the small-swing integration)
TRAJECTORY = (Model.ELLIPSE, Model.LINEAR, Model.QUADRATIC_FIRST_ORDER, Model.QUADRATIC)
#: systems the reference integrators solve (:mod:`quasicentral.models.reference`)
REFERENCE = (Model.LINEAR, Model.QUADRATIC, Model.SPHERICAL)
#: the paper's approximations, measured against the full pendulum
APPROXIMATIONS = (Model.ELLIPSE, Model.LINEAR, Model.QUADRATIC, Model.QUADRATIC_FIRST_ORDER)


class PeriodMethod(str, Enum):
    """A route to the period's T/T0 (:mod:`quasicentral.models.period`; the value is its name
    on the command line)."""

    AGM = "agm"
    SERIES = "series"
    ELLIPK = "ellipk"
    QUAD = "quad"
    ODE = "ode"


PERIOD_METHODS = tuple(m.value for m in PeriodMethod)
SERIES_MAX_TERMS = 10**6  # the one limit of the series (66), in every context and on the command line


def names(models) -> str:
    """'a, b, c' for an error message."""
    return ", ".join(m.value for m in models)


def lookup(name, among=tuple(Model), error=ValueError) -> Model:
    """The model called ``name`` among ``among``; an unknown name raises ``error`` listing them."""
    try:
        model = Model(name)
    except ValueError:
        model = None
    if model not in among:
        raise error(f"unknown model {name!r}; choose from {names(among)}")
    return model
