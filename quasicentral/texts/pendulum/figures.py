"""Figure 32 of the pendulum text: T/T0 against the amplitude, with the truncations of the
series (66); and the measured charts of the period."""

from __future__ import annotations

from types import MappingProxyType

import numpy as np

from quasicentral.models import period
from quasicentral.studies.figures import Figure, Kind, measured, measured_names

SERIES_TERMS = (1, 2, 3, 4, 10, 50)


def fig32() -> Figure:
    deg = np.linspace(0.5, 179.5, 359)
    rad = np.radians(deg)
    exact = period.period_ratio(rad)
    m = np.sin(rad / 2) ** 2
    cols = [deg, exact] + [period.series_ratio(m, n)[0] for n in SERIES_TERMS]
    names = ("amplitude_deg", "T_over_T0") + tuple(f"series_{n}" for n in SERIES_TERMS)
    labels = ("exact",) + tuple(f"(66), {n} term{'s' if n > 1 else ''}" for n in SERIES_TERMS)
    czech = {"xlabel": r"amplituda $\varphi_0$ [°]", "ylabel": r"$T/T_0$",
             "labels": ("přesně",) + tuple(f"(66), {_terms_cs(n)}" for n in SERIES_TERMS)}
    return Figure("fig32", "Fig. 32: T/T0 against the amplitude, with truncations of (66)", names,
                  np.column_stack(cols), Kind.CURVES, labels, r"amplitude $\varphi_0$ [°]", r"$T/T_0$", (0.9, 4.0),
                  MappingProxyType({"cs": MappingProxyType(czech)}))


def _terms_cs(n: int) -> str:
    """'1 člen', '2 členy', '10 členů' (Czech plurals)."""
    return f"{n} člen" if n == 1 else (f"{n} členy" if 2 <= n <= 4 else f"{n} členů")


def _measured(name):
    def make():
        return measured(name)

    make.__name__ = name
    return make


#: the text's figures, in the order its report shows them
FIGURES = (fig32,) + tuple(_measured(n) for n in measured_names() if "period" in n)
