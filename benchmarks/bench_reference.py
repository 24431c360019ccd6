"""The reference integrators: time and error over 10 periods for every model, at 1e-12
(scipy alone), 1e-20 and 1e-30 (heyoka Taylor where it is installed, else mpmath), each error
measured against a run at 1e-45 (heyoka MPFR) or, without heyoka, against mpmath at 1e-25.

    python3 benchmarks/bench_reference.py [--fallback]

Targets: 1e-12 in ≤ 15 ms with scipy alone; 1e-20 and 1e-30 fast enough for tests.
``--fallback`` also times the mpmath fallback (seconds per run).
"""

import math
import platform
import sys
import time

import numpy as np

from quasicentral.studies import charts

from quasicentral.models import reference as R

from quasicentral.models.parameters import FIGURE_OMEGA as OMEGA  # noqa: E402
T = 2 * math.pi / OMEGA
CASES = [
    ("linear", {"R0": 0.1, "v0": 0.1, "omega2": 10.0, "kappa": 0.4}, "linear drag (16)-(17)"),
    ("quadratic", {"R0": 0.1, "v0": 0.2, "omega2": 10.0, "beta": 0.5}, "quadratic drag (26)-(27)"),
    ("quadratic", {"R0": 0.1, "v0": 0.0, "omega2": 10.0, "beta": 0.5}, "quadratic drag, planar (kinks)"),
    ("spherical", {"R0": 0.5, "v0": 0.8, "l": 1.0, "g": 10.0, "beta": 0.5}, "full pendulum, beta"),
    ("spherical", {"R0": 0.5, "v0": 0.0, "l": 1.0, "g": 10.0, "beta": 0.5}, "full pendulum, beta, planar"),
    ("spherical", {"R0": 0.5, "v0": 0.8, "l": 1.0, "g": 10.0, "kappa": 0.2}, "full pendulum, kappa"),
]


def best_of(fn, n=5):
    fn()
    out = []
    for _ in range(n):
        t0 = time.perf_counter()
        fn()
        out.append(time.perf_counter() - t0)
    return min(out), sorted(out)[len(out) // 2]


def main():
    info = charts.machine()
    print(f"# {info['processor']} ({info['cores']} cores), Python {info['python']}, numpy {info['numpy']}, "
          f"scipy {info['scipy']}, mpmath {info['mpmath']}, heyoka {info['heyoka']}")
    fallback = "--fallback" in sys.argv
    for end_only in (True, False):
        t = np.array([10 * T]) if end_only else np.linspace(T / 5, 10 * T, 50)
        print(f"\n10 periods, {'the end point only' if end_only else '50 output points'}")
        print(f"{'case':34s} {'tol':>7s} {'method':>7s} {'best ms':>9s} {'median ms':>9s} {'error':>9s}")
        for model, params, label in CASES:
            ref = R.solve(model, params, t, tol=1e-45 if R.heyoka_available() else 1e-25)
            runs = [(1e-12, "dop853")]
            if R.heyoka_available():
                runs += [(1e-12, "heyoka"), (1e-20, "heyoka"), (1e-30, "heyoka")]
            if fallback or not R.heyoka_available():
                runs += [(1e-20, "mpmath")]
            for tol, meth in runs:
                sol = R.solve(model, params, t, tol=tol, method=meth)
                b, m = best_of(lambda: R.solve(model, params, t, tol=tol, method=meth), 5 if meth != "mpmath" else 1)
                print(f"{label:34s} {tol:7.0e} {meth:>7s} {b * 1e3:9.2f} {m * 1e3:9.2f} {R.difference(sol, ref):9.1e}")
    print(f"\n# {platform.platform()}")


if __name__ == "__main__":
    main()
