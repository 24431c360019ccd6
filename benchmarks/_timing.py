"""Shared helpers of the benchmark scripts: best-of-N wall time and the machine line."""

import platform
import time

import numpy as np


def best_of(f, repeat: int = 5) -> float:
    """The smallest wall time of ``repeat`` calls of ``f`` (after one warm-up call), seconds."""
    f()
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        f()
        best = min(best, time.perf_counter() - t0)
    return best


def machine() -> str:
    return f"# {platform.machine()} {platform.processor() or ''}, Python {platform.python_version()}, numpy {np.__version__}"
