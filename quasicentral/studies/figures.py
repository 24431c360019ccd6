"""The texts' missing figures, reproduced from the closed forms: data first (CSV), then a plot
that only reads the data.  Deterministic: fixed grids, fixed PNG metadata, no timestamps.

* fig. 7a — trajectory under linear drag, Ω = √10 1/s, κ = 0.4 1/s, R0 = 0.1 m, v0 = 0.1 m/s;
* fig. 7b — the same motion as the two damped oscillations x(t), y(t) (the print lost the
  figure; its caption gives only the parameters of 7a/7b, so 7b shows the time histories);
* fig. 8 — the aperiodic limit κ = Ω = √10 1/s;
* overdamped — κ = 2Ω, the case the paper leaves out, beside them;
* fig. 32 — T/T0 against the amplitude, with the truncations of the series (66);
* the measured charts (work–precision, stability maps, validity of the approximations), drawn
  from their committed CSV files.
"""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from quasicentral.models import motion

from quasicentral.models import period

from quasicentral.models.parameters import FIGURE_OMEGA as OMEGA  # the figures' Ω = √10

R0 = V0 = 0.1


@dataclass(frozen=True)
class Figure:
    name: str
    title: str
    columns: tuple[str, ...]
    data: np.ndarray  # rows × columns
    kind: str  # "trajectory" | "time" | "period"


def _linear_figure(name, title, kappa, t_end, n=2001) -> Figure:
    t = np.linspace(0.0, t_end, n)
    x, y = motion.linear(t, R0, V0, OMEGA, kappa)
    return Figure(name, title, ("t", "x", "y"), np.column_stack([t, x, y]), "trajectory")


def fig7a() -> Figure:
    return _linear_figure("fig7a", "Fig. 7a: linear drag, κ = 0.4 1/s, Ω = √10 1/s, R0 = v0 = 0.1", 0.4, 8.0)


def fig7b() -> Figure:
    f = _linear_figure("fig7b", "Fig. 7b: x(t) and y(t) of the same motion", 0.4, 8.0)
    return Figure(f.name, f.title, f.columns, f.data, "time")


def fig8() -> Figure:
    return _linear_figure("fig8", "Fig. 8: aperiodic limit κ = Ω = √10 1/s, R0 = v0 = 0.1", OMEGA, 3.0)


def overdamped() -> Figure:
    return _linear_figure("overdamped", "Overdamped κ = 2Ω (not in the paper)", 2 * OMEGA, 3.0)


SERIES_TERMS = (1, 2, 3, 4, 10, 50)


def fig32() -> Figure:
    deg = np.linspace(0.5, 179.5, 359)
    rad = np.radians(deg)
    exact = period.period_ratio(rad)
    m = np.sin(rad / 2) ** 2
    cols = [deg, exact] + [period.series_ratio(m, n)[0] for n in SERIES_TERMS]
    names = ("amplitude_deg", "T_over_T0") + tuple(f"series_{n}" for n in SERIES_TERMS)
    return Figure("fig32", "Fig. 32: T/T0 against the amplitude, with truncations of (66)", names,
                  np.column_stack(cols), "period")


@dataclass(frozen=True)
class MeasuredChart:
    """A work–precision chart, stability map or validity chart: drawn from the measurement CSV
    that ``quasicentral charts`` wrote (it never re-measures here)."""

    name: str
    title: str
    source: str
    kind: str = "chart"

    def render(self, path: Path) -> None:
        from quasicentral.studies import charts

        charts.render(MEASUREMENTS / f"{self.name}.csv", path)


MEASUREMENTS = Path(__file__).parent.parent / "data" / "measurements"


def measured_charts() -> list[MeasuredChart]:
    from quasicentral.studies import charts

    out = []
    for csv_path in sorted(MEASUREMENTS.glob("*.csv")):
        header, _ = charts.read_csv(csv_path)
        about_period = "period" in csv_path.stem
        out.append(MeasuredChart(csv_path.stem, header.get("title", csv_path.stem),
                                 "pendulum" if about_period else "brepta1953"))
    return out


def _measured(chart: MeasuredChart):
    def make():
        return chart

    make.__name__ = chart.name
    return make


ALL = (fig7a, fig7b, fig8, overdamped, fig32) + tuple(_measured(c) for c in measured_charts())


def to_csv(fig: Figure) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(fig.columns)
    for row in fig.data:
        w.writerow([repr(float(v)) for v in row])
    return buf.getvalue()


def draw(fig: Figure | MeasuredChart, path: Path) -> None:
    """Any figure of :data:`ALL` as a PNG: a measured chart from its CSV, else :func:`render`."""
    if isinstance(fig, MeasuredChart):
        fig.render(path)
    else:
        render(fig, path)


def render(fig: Figure, path: Path) -> None:
    """Plot ``fig`` to a PNG with fixed metadata (byte-identical for the same data)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    with matplotlib.rc_context({"svg.hashsalt": "quasicentral", "font.size": 9}):
        figure, ax = plt.subplots(figsize=(5.0, 4.0), dpi=120)
        d = fig.data
        if fig.kind == "trajectory":
            ax.plot(d[:, 1] * 1000, d[:, 2] * 1000, lw=1.0)
            ax.plot([d[0, 1] * 1000], [d[0, 2] * 1000], "o", ms=3)
            ax.set_xlabel("x [mm]")
            ax.set_ylabel("y [mm]")
            ax.set_aspect("equal", adjustable="datalim")
        elif fig.kind == "time":
            ax.plot(d[:, 0], d[:, 1] * 1000, lw=1.0, label="x(t)")
            ax.plot(d[:, 0], d[:, 2] * 1000, lw=1.0, label="y(t)")
            ax.set_xlabel("t [s]")
            ax.set_ylabel("[mm]")
            ax.legend()
        else:
            ax.plot(d[:, 0], d[:, 1], "k", lw=1.5, label="exact (AGM)")
            for j, n in enumerate(SERIES_TERMS):
                ax.plot(d[:, 0], d[:, 2 + j], lw=0.8, ls="--", label=f"(66), {n} term{'s' if n > 1 else ''}")
            ax.set_ylim(0.9, 4.0)
            ax.set_xlabel("amplitude φ0 [°]")
            ax.set_ylabel("T / T0")
            ax.legend(fontsize=7)
        ax.set_title(fig.title, fontsize=8)
        ax.grid(True, lw=0.3)
        figure.tight_layout()
        figure.savefig(path, format="png", metadata={"Software": None})
        plt.close(figure)


def write_all(out: Path, progress=None) -> list[Path]:
    """Write every figure's CSV and PNG into ``out`` (each via a temporary file and a rename,
    never through a symbolic link: quasicentral.files); returns the paths written.
    ``progress`` (a :class:`quasicentral.progress.Progress` callback) is told of each figure."""
    from quasicentral import files
    from quasicentral.progress import notify

    files.output_dir(out)
    written = []
    notify(progress, 0, len(ALL), "", 0, "figures")
    for i, make in enumerate(ALL):
        fig = make()
        csv_path, png_path = files.inside(out, f"{fig.name}.csv"), files.inside(out, f"{fig.name}.png")
        if isinstance(fig, MeasuredChart):
            files.write_bytes(csv_path, (MEASUREMENTS / f"{fig.name}.csv").read_bytes())
        else:
            files.write_text(csv_path, to_csv(fig))
        files.write_atomic(png_path, lambda tmp, fig=fig: draw(fig, tmp))
        written += [csv_path, png_path]
        notify(progress, i + 1, len(ALL), fig.name, 0, "figures")
    return written
