"""Shared helpers of the benchmark scripts: best-of-N wall time and the machine line (the same
helpers the charts use: :mod:`quasicentral.studies.charts.timing`)."""

from quasicentral.studies.charts.timing import best_of, machine_line as machine

__all__ = ["best_of", "machine"]
