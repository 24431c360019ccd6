"""The exact period T/T0: accuracy in ulp (against 40 digits at the exact double input) and
cost per element on arrays of 10⁶, for each double-precision method; series terms needed.

    python3 benchmarks/bench_period.py
"""

import math

import numpy as np

from _timing import best_of, machine

from quasicentral.models import period as P


def ulps(method, phis=None, deltas=None):
    if deltas is not None:
        vals = P.period_ratio(delta=deltas, method=method)
        refs = np.array([float(P.period_ratio_mp(delta=float(d), dps=40)) for d in deltas])
    else:
        vals = P.period_ratio(phis, method=method)
        refs = np.array([float(P.period_ratio_mp(phi0=float(a), dps=40)) for a in phis])
    return np.max(np.abs(vals - refs) / np.spacing(refs))


def main():
    print(machine())
    rng = np.random.default_rng(1)
    phis = np.concatenate([rng.uniform(1e-6, math.pi - 1e-6, 300), math.pi - np.logspace(-15, -1, 40)])
    deltas = np.logspace(-300, 0, 120)
    for method in ("agm", "ellipk"):
        print(f"{method:7s} max error given phi0: {ulps(method, phis=phis):.2f} ulp; "
              f"given delta (1e-300..1): {ulps(method, deltas=deltas):.2f} ulp")
    big = rng.uniform(1e-3, math.pi - 1e-3, 10**6)
    for method in ("agm", "ellipk", "series"):
        P.period_ratio(big, method=method)
        best = best_of(lambda: P.period_ratio(big, method=method), 5)
        print(f"cost {method:7s}: {best / big.size * 1e9:.1f} ns per element (10^6 amplitudes)")
    for deg in (10, 45, 90, 150, 170, 179):
        print(f"series (66): {P.terms_needed(math.radians(deg), 1e-15)} terms for 1e-15 at {deg} deg")
    for n in (1, 2, 4, 10):
        a = math.degrees(P.first_amplitude_exceeding(n, 1e-3))
        print(f"series (66) with {n} terms first exceeds 1e-3 at {a:.2f} deg")



if __name__ == "__main__":
    main()
