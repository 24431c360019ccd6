"""Timing and the machine line, shared by the charts and the scripts in ``benchmarks/``."""

from __future__ import annotations

import platform
import time
from dataclasses import dataclass
from pathlib import Path

import mpmath
import numpy as np


# --- the machine --------------------------------------------------------------------------------
def machine() -> dict:
    """The machine and library versions the measurements were taken with (no timestamps)."""
    import os

    import scipy

    info = {"machine": platform.machine(), "processor": _cpu_name(), "cores": str(os.cpu_count()),
            "system": platform.system(), "python": platform.python_version(), "numpy": np.__version__,
            "scipy": scipy.__version__, "mpmath": mpmath.__version__, "mpmath_backend": mpmath.libmp.BACKEND}
    try:
        import flint

        info["python-flint"] = flint.__version__
    except Exception:  # noqa: BLE001
        info["python-flint"] = "absent"
    from quasicentral.models import reference

    if reference.heyoka_available():
        import heyoka

        info["heyoka"] = heyoka.__version__
    else:
        info["heyoka"] = "absent"
    return info


def _cpu_name() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def machine_line() -> str:
    """One comment line naming the machine (for the benchmark scripts' output)."""
    return f"# {platform.machine()} {_cpu_name()}, Python {platform.python_version()}, numpy {np.__version__}"


def best_of(f, repeat: int = 5) -> float:
    """The smallest wall time of ``repeat`` calls of ``f`` (after one warm-up call), seconds."""
    f()
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        best = min(best, time.perf_counter() - t0)
    return best


# --- timing and errors -----------------------------------------------------------------------------
@dataclass(frozen=True)
class Settings:
    """How hard to measure: ``quick`` is a coarse run for CI and tests."""

    quick: bool = False

    @property
    def budget(self) -> float:  # seconds of repeated calls per timing
        return 0.003 if self.quick else 0.05

    @property
    def periods(self) -> int:
        return 2 if self.quick else 10


def timed(fn, settings: Settings, per: int = 1):
    """(value, seconds per evaluation): one warm-up call (which also gives the value and pays
    for lazy imports and compilation), one timed call, then — if that was shorter than the
    budget — the best of three batches sized to the budget; ``per`` evaluations per call."""
    val = fn()
    t0 = time.perf_counter()
    fn()
    first = time.perf_counter() - t0
    best = first
    if first < settings.budget:
        n = max(1, min(10000, int(settings.budget / max(first, 1e-7))))
        for _ in range(3):
            t0 = time.perf_counter()
            for _ in range(n):
                fn()
            best = min(best, (time.perf_counter() - t0) / n)
    return val, best / per
