"""Figures: data first (CSV), then a plot that only reads the data.  Deterministic: fixed grids,
fixed PNG metadata, no timestamps.

A text's own figures are defined in its folder (``figures.py`` with a ``FIGURES`` tuple of
functions returning :class:`Figure` or :class:`MeasuredChart`); :func:`of_text` reads them.  The
measured charts (work–precision, stability maps, validity of the approximations) are drawn
from their committed CSV files (``quasicentral charts``).
"""

from __future__ import annotations

import csv
import io
import os
from dataclasses import dataclass, field
from enum import Enum
from pathlib import Path
from types import MappingProxyType

import numpy as np

from quasicentral.studies.png import save_png


class Kind(str, Enum):
    TRAJECTORY = "trajectory"  # columns t, x, y: the path y(x), in mm
    TIME = "time"  # columns t, x, y: x(t) and y(t), in mm
    CURVES = "curves"  # first column the abscissa; the next the reference; the rest compared with it


@dataclass(frozen=True)
class Figure:
    name: str
    title: str
    columns: tuple[str, ...]
    data: np.ndarray  # rows × columns
    kind: Kind
    labels: tuple[str, ...] = ()  # curves: the legend of each column after the first
    xlabel: str = ""
    ylabel: str = ""
    ylim: tuple[float, float] | None = None
    #: the words in other languages: {"cs": {"xlabel": …, "ylabel": …, "labels": (…)}} (English
    #: above); labels may hold matplotlib's mathtext ($T/T_0$), set in Computer Modern
    words: MappingProxyType = field(default_factory=lambda: MappingProxyType({}))

    def said(self, key: str, lang: str):
        """The figure's ``key`` (xlabel, ylabel, labels) in ``lang``, else in English."""
        return self.words.get(lang, {}).get(key, getattr(self, key))


@dataclass(frozen=True)
class MeasuredChart:
    """A work–precision chart, stability map or validity chart: drawn from the measurement CSV
    that ``quasicentral charts`` wrote (it never re-measures here)."""

    name: str
    title: str
    kind: str = "chart"

    def render(self, path: Path) -> None:
        from quasicentral.studies import charts

        charts.render(MEASUREMENTS / f"{self.name}.csv", path)


MEASUREMENTS = Path(__file__).parent.parent / "data" / "measurements"


def measured(name: str) -> MeasuredChart:
    """The committed measurement ``name`` (a CSV of data/measurements) as a chart."""
    from quasicentral.studies import charts

    path = MEASUREMENTS / f"{name}.csv"
    header, _ = charts.read_csv(path)
    return MeasuredChart(name, header.get("title", name))


def measured_names() -> list[str]:
    return [p.stem for p in sorted(MEASUREMENTS.glob("*.csv"))]


#: the most time (wall clock and CPU) a folder's ``figures.py`` may take to make its figures
FIGURE_SECONDS = 120.0


def of_text(text) -> list[Figure | MeasuredChart]:
    """The figures of a text (:class:`quasicentral.engine.texts.Text`): those its folder's
    ``figures.py`` lists in ``FIGURES``; none without one.  The module is a folder's own code:
    its import and its figures are bounded by :data:`FIGURE_SECONDS` (a loop or a sleep there
    is a :class:`~quasicentral.engine.texts.TextError` naming the file, never a hang)."""
    from quasicentral.engine.texts import TextError
    from quasicentral.notation.timelimit import CPU, WALL, TimeLimitExceeded, time_limit

    try:
        with time_limit(FIGURE_SECONDS, WALL) as wall, time_limit(FIGURE_SECONDS, CPU) as cpu:
            module = text.figures_module()
            return [make() for make in getattr(module, "FIGURES", ())] if module is not None else []
    except TimeLimitExceeded as exc:
        if (wall is not None and wall.owns(exc)) or (cpu is not None and cpu.owns(exc)):
            raise TextError(f"{text.root / 'figures.py'}: its figures took more than {FIGURE_SECONDS:g} s") from None
        raise


def to_csv(fig: Figure) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(fig.columns)
    for row in fig.data:
        w.writerow([repr(float(v)) for v in row])
    return buf.getvalue()


def draw(fig: Figure | MeasuredChart, path: Path, lang: str = "en", titled: bool = True) -> None:
    """Any figure as a PNG: a measured chart from its CSV, else :func:`render` in ``lang`` (with
    its title, or without where a caption says it) — or the PNG kept in the cache
    (``figures/``) for the same data, words, drawing code and matplotlib settings: a report drawn
    again after an edit of its prose does not redraw its 18 figures (~17 s)."""
    from quasicentral import files
    from quasicentral.engine.fingerprint import cache_dir

    folder, name = cache_dir() / FIGURE_CACHE, f"{_drawing_key(fig, lang, titled)}.png"
    kept = files.read_private(folder, name)
    if kept is not None and kept.startswith(b"\x89PNG"):
        path.write_bytes(kept)
        return
    if isinstance(fig, MeasuredChart):
        fig.render(path)
    else:
        render(fig, path, lang, titled)
    try:
        files.ensure_dir(folder)
        os.chmod(folder, 0o700)  # read back only from a folder nobody else may write
        files.write_bytes(folder / name, path.read_bytes())
    except OSError:
        pass  # a read-only cache is not an error


FIGURE_CACHE = "figures"


def _drawing_key(fig: Figure | MeasuredChart, lang: str = "en", titled: bool = True) -> str:
    """What a PNG depends on: the figure's data and labels (a measured chart's CSV), the drawing
    code, matplotlib's and numpy's versions and every matplotlib setting in force."""
    import hashlib

    import matplotlib

    h = hashlib.sha256()
    for module in _drawing_modules():
        h.update(Path(module).read_bytes())
    # the backend is left out: reading it would resolve it (importing pyplot), and the PNG is
    # always Agg's
    settings = [(k, repr(matplotlib.rcParams[k])) for k in sorted(matplotlib.rcParams) if not k.startswith("backend")]
    h.update(repr((matplotlib.__version__, np.__version__, settings)).encode())
    if isinstance(fig, MeasuredChart):
        h.update(repr((fig.name, fig.title)).encode())
        h.update((MEASUREMENTS / f"{fig.name}.csv").read_bytes())
    else:
        h.update(repr((fig.name, fig.title, fig.columns, fig.kind.value, fig.labels, fig.xlabel, fig.ylabel,
                       fig.ylim, sorted((k, sorted(v.items())) for k, v in fig.words.items()), lang,
                       titled)).encode())
        h.update(to_csv(fig).encode())
    return h.hexdigest()


def _drawing_modules() -> tuple[str, ...]:
    import importlib

    # by module name: the package exports functions of the same names
    charts = ("render", "data", "maps")
    return (__file__, importlib.import_module("quasicentral.studies.png").__file__,
            *(importlib.import_module(f"quasicentral.studies.charts.{m}").__file__ for m in charts))


#: matplotlib's settings for every figure: a serif text font and Computer Modern mathematics,
#: like the LaTeX documents the figures go into
STYLE = MappingProxyType({"svg.hashsalt": "quasicentral", "font.size": 9, "font.family": "serif",
                          "mathtext.fontset": "cm", "axes.spines.top": False, "axes.spines.right": False,
                          "legend.frameon": False})


def _decimal_comma(ax) -> None:
    """Tick labels with a decimal comma (Czech), the numbers as matplotlib chooses them."""
    from matplotlib.ticker import ScalarFormatter

    class Comma(ScalarFormatter):
        def __call__(self, x, pos=None):
            return super().__call__(x, pos).replace(".", ",")

    ax.xaxis.set_major_formatter(Comma())
    ax.yaxis.set_major_formatter(Comma())


def render(fig: Figure, path: Path, lang: str = "en", titled: bool = True) -> None:
    """Plot ``fig`` to a PNG with fixed metadata (byte-identical for the same data), its words
    in ``lang`` (a decimal comma in Czech); the title only where no caption says it."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    with matplotlib.rc_context(dict(STYLE)):
        figure, ax = plt.subplots(figsize=(5.0, 4.0), dpi=120)
        d = fig.data
        if fig.kind is Kind.TRAJECTORY:
            ax.plot(d[:, 1] * 1000, d[:, 2] * 1000, lw=1.0)
            ax.plot([d[0, 1] * 1000], [d[0, 2] * 1000], "o", ms=3)
            ax.set_xlabel("$x$ [mm]")
            ax.set_ylabel("$y$ [mm]")
            ax.set_aspect("equal", adjustable="datalim")
        elif fig.kind is Kind.TIME:
            ax.plot(d[:, 0], d[:, 1] * 1000, lw=1.0, label="$x(t)$")
            ax.plot(d[:, 0], d[:, 2] * 1000, lw=1.0, label="$y(t)$")
            ax.set_xlabel("$t$ [s]")
            ax.set_ylabel("[mm]")
            ax.legend(loc="best")
        else:
            labels = fig.said("labels", lang)
            ax.plot(d[:, 0], d[:, 1], "k", lw=1.5, label=labels[0] if labels else None)
            for j, label in enumerate(labels[1:]):
                ax.plot(d[:, 0], d[:, 2 + j], lw=0.8, ls="--", label=label)
            if fig.ylim:
                ax.set_ylim(*fig.ylim)
            ax.set_xlabel(fig.said("xlabel", lang))
            ax.set_ylabel(fig.said("ylabel", lang))
            if labels:
                ax.legend(fontsize=7, loc="best")
        if titled:
            ax.set_title(fig.title, fontsize=8)
        ax.grid(True, lw=0.3)
        if lang == "cs":
            _decimal_comma(ax)
        figure.tight_layout()
        save_png(figure, path)
        plt.close(figure)


def write_all(out: Path, selected, progress=None) -> list[Path]:
    """Write every figure of the texts ``selected`` (CSV and PNG) into ``out`` (each via a
    temporary file and a rename, never through a symbolic link: quasicentral.files); returns the
    paths written.  ``progress`` (a :class:`quasicentral.progress.Progress` callback) is told of
    each figure."""
    from quasicentral import files
    from quasicentral.progress import notify

    files.output_dir(out)
    figures = list({f.name: f for t in selected for f in of_text(t)}.values())
    written = []
    notify(progress, 0, len(figures), "", 0, "figures")
    for i, fig in enumerate(figures):
        csv_path, png_path = files.inside(out, f"{fig.name}.csv"), files.inside(out, f"{fig.name}.png")
        if isinstance(fig, MeasuredChart):
            files.write_bytes(csv_path, (MEASUREMENTS / f"{fig.name}.csv").read_bytes())
        else:
            files.write_text(csv_path, to_csv(fig))
        files.write_atomic(png_path, lambda tmp, fig=fig: draw(fig, tmp))
        written += [csv_path, png_path]
        notify(progress, i + 1, len(figures), fig.name, 0, "figures")
    return written
