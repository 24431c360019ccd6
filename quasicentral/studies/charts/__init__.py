"""Speed against accuracy, and where methods fail: work–precision charts, stability maps and
the validity of the paper's approximations.  Data first, then pictures:

* ``measure_*`` functions time and check every method and return rows (dicts);
* :func:`write_csv` writes them with a header naming the machine and the library versions
  (``# key: value`` lines; no timestamps, so the only run-to-run differences are the timings);
* :func:`render` draws a PNG from a CSV *file* — it never recomputes anything — with fixed
  sizes and metadata, byte-identical for the same CSV.

Work–precision (one chart per quantity, one panel per case; cost per evaluation against the
maximum error over the case, errors computed in mpmath so that they show below 1e-16):

* ``period`` — T/T0 at 60° and 170°: ellipk, agm (double); series (66) truncated after N terms;
  quadrature (scipy at several tolerances); ODE to the lowest point (several tolerances);
  mpmath ellipk / agm / quad at several precisions; python-flint balls correctly rounded;
* ``elliptic`` — K(m), (K − E)/m and E(φ|m), the integrals the closed forms use;
* ``linear`` — the linear-drag trajectory over 10 periods: closed form in double and mpmath,
  the reference integrators at several tolerances, the project's solve_ivp cross-check;
* ``quadratic`` — the first-order quadratic-drag closed form: double, mpmath, and the
  linearized forced equations integrated at several tolerances;
* ``quadratic-full`` and ``spherical`` — (26)–(27) and the full pendulum with drag: every
  integrator the project has, at several tolerances.

Stability maps (error against the parameter that drives a method into trouble; the project's
default beside the naive route): ``period-near-pi`` (k² → 1, amplitude → π), ``k2-to-0``
((K − E)/m and the printed ζ-form as u → v0), ``kappa-to-omega`` (ω = √(Ω² − κ²) formed
naively), ``zeta-beyond-pi`` (the printed ζ-form past Ωt = π), ``beta-r0-omega-t`` (first
order in β once βR0·Ωt is not small), ``long-times`` (phase rounding, ODE error growth).

Layout: :mod:`.timing` (the machine, timing), :mod:`.naive` (the routes the maps show
failing), :mod:`.workprecision` and :mod:`.maps` (measuring), :mod:`.data` (CSV, checked when
read back), :mod:`.render` (PNG from CSV only); this module lists the charts and builds them.

Validity (``validity``): the error of each approximation of the paper against the full
nonlinear pendulum with drag, over amplitude × drag after 1 and 10 periods, with the contours
1 %, 0.1 % and 1e-6 of R0; and the first-order error fitted as C·(βR0)^p.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from quasicentral import files
from quasicentral.studies.charts import maps as _maps
from quasicentral.studies.charts import workprecision as _wp
from quasicentral.studies.charts.common import OMEGA
from quasicentral.studies.charts.data import ChartError, read_csv, read_table, write_csv
from quasicentral.studies.charts.maps import beta_fit, measure_validity
from quasicentral.studies.charts.naive import (
    default_k_minus_e, naive_k_minus_e, naive_linear, naive_period, naive_phase_linear, zeta_form,
)
from quasicentral.studies.charts.render import YES, render
from quasicentral.studies.charts.timing import Settings, machine
from quasicentral.models.parameters import G_STANDARD

__all__ = ["CHARTS", "MAPS", "QUANTITIES", "ChartError", "Settings", "build", "render", "render_all", "read_csv",
           "read_table", "write_csv", "machine", "beta_fit", "measure_validity", "default_k_minus_e",
           "naive_k_minus_e", "naive_linear", "naive_period", "naive_phase_linear", "zeta_form", "OMEGA"]


@dataclass(frozen=True)
class WorkPrecision:
    """A work–precision chart: its measurement and title."""

    measure: Callable
    title: str

    def header(self) -> dict:
        return {"title": self.title,
                "columns": "seconds per evaluation (best of 3 batches); error = max relative error over the case"}


@dataclass(frozen=True)
class StabilityMap:
    """A stability map: its measurement and axes."""

    measure: Callable
    title: str
    xlabel: str
    ylabel: str
    log_x: bool
    invert_x: bool

    def header(self) -> dict:
        return {"title": self.title, "xlabel": self.xlabel, "ylabel": self.ylabel,
                "xscale": "log" if self.log_x else "linear", "invert_x": YES if self.invert_x else "no"}


WORK_PRECISION = {
    "period": WorkPrecision(_wp.measure_period, "Work–precision: the pendulum period T/T0"),
    "elliptic": WorkPrecision(_wp.measure_elliptic, "Work–precision: the elliptic integrals of the closed forms"),
    "linear": WorkPrecision(_wp.measure_linear, "Work–precision: the linear-drag trajectory (16)–(17)"),
    "quadratic": WorkPrecision(_wp.measure_quadratic, "Work–precision: the first-order quadratic-drag closed form"),
    "quadratic-full": WorkPrecision(lambda s: _wp.measure_full(s, "quadratic-full"),
                                    "Work–precision: the full small-swing motion (26)–(27)"),
    "spherical": WorkPrecision(lambda s: _wp.measure_full(s, "spherical"),
                               "Work–precision: the full spherical pendulum with drag"),
}

STABILITY = {
    "period-near-pi": StabilityMap(_maps.map_period_near_pi, "T/T0 as the amplitude → π (k² → 1)", "δ = π − φ0 [rad]",
                                   "relative error", True, True),
    "k2-to-0": StabilityMap(_maps.map_k2_to_0, "k² → 0 (u → v0): (K − E)/m and the first-order solution on "
                            "0 ≤ Ωt ≤ π", "k² = 1 − (v0/u)²", "relative error (trajectory: / scale)", True, True),
    "kappa-to-omega": StabilityMap(_maps.map_kappa_to_omega, "Linear drag as κ → Ω (aperiodic limit), 3 periods",
                                   "|κ/Ω − 1|", "max error / scale", True, True),
    "zeta-beyond-pi": StabilityMap(_maps.map_zeta_beyond_pi, "First-order quadratic solution: the printed ζ-form "
                                   "beyond Ωt = π", "Ωt", "error / scale (against the exact first-order solution)",
                                   False, False),
    "beta-r0-omega-t": StabilityMap(_maps.map_beta_r0_omega_t, "Quadratic drag once βR0·Ωt is not small (against "
                                    "(26)–(27) exactly)", "βR0·Ωt", "error / R0", True, False),
    "long-times": StabilityMap(_maps.map_long_times, "Linear drag (κ = 1e-4 1/s) over long times", "periods",
                               "error / scale", True, False),
}

QUANTITIES = tuple(WORK_PRECISION)
MAPS = tuple(STABILITY)
CHARTS = tuple(f"workprecision-{q}" for q in QUANTITIES) + tuple(f"stability-{m}" for m in MAPS) + ("validity",)
VALIDITY_TITLE = ("Validity of the paper's approximations against the full pendulum with drag "
                  f"(v0 = R0Ω/2, l = 1 m, g = {G_STANDARD} m/s²)")


def _chart(name: str):
    """(measurement, header fields) of one chart."""
    if name.startswith("workprecision-"):
        spec = WORK_PRECISION[name.removeprefix("workprecision-")]
        return spec.measure, spec.header()
    if name.startswith("stability-"):
        spec = STABILITY[name.removeprefix("stability-")]
        return spec.measure, spec.header()
    return measure_validity, {"title": VALIDITY_TITLE}


def build(out: Path, quick: bool = False, only: list[str] | None = None, progress=None) -> list[Path]:
    """Measure, write each CSV, then render each PNG from its CSV.  Returns the paths written.
    ``progress`` (a :class:`quasicentral.progress.Progress` callback) is told of each chart."""
    from quasicentral.progress import notify

    settings = Settings(quick=quick)
    wanted = list(only) if only else list(CHARTS)
    for w in wanted:
        if w not in CHARTS:
            raise ChartError(f"unknown chart {w!r}; choose from {', '.join(CHARTS)}")
    files.output_dir(out)
    base = machine()
    base["mode"] = "quick" if quick else "full"
    written = []
    notify(progress, 0, len(wanted), "", 0, "charts")
    for name in wanted:
        measure, fields = _chart(name)
        rows = measure(settings)
        csv_path, png_path = files.inside(out, f"{name}.csv"), files.inside(out, f"{name}.png")
        write_csv(csv_path, rows, dict(base, chart=name, **fields))
        files.write_atomic(png_path, lambda tmp, c=csv_path: render(c, tmp))
        written += [csv_path, png_path]
        notify(progress, len(written) // 2, len(wanted), name, 0, "charts")
    return written


def render_all(folder: Path) -> list[Path]:
    """Re-render every chart's PNG from the CSVs in ``folder`` (nothing is measured); every CSV
    is checked first, so a bad file stops the run before any PNG is written."""
    paths = sorted(Path(folder).glob("*.csv"))
    for csv_path in paths:
        from quasicentral.studies.charts.data import check

        check(csv_path, read_table(csv_path))
    written = []
    for csv_path in paths:
        png = files.inside(folder, csv_path.with_suffix(".png").name)
        files.write_atomic(png, lambda tmp, c=csv_path: render(c, tmp))  # never through a link
        written.append(png)
    return written
