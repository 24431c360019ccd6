"""Quadratic drag: accuracy of the first-order closed form (relative to the solution's scale,
against 40 digits) over 0 ≤ Ωt ≤ 10π and −2 ≤ k² ≤ 0.999, and beyond it k² → 1 (1 − k² down
to 10⁻³⁰) and the planar swing k² = 1; cost per point on arrays; the first-order error
against the full motion, fitted as C·β^p.

    python3 benchmarks/bench_quadratic.py
"""

import math
import time

import mpmath
import numpy as np

from _timing import best_of, machine

from quasicentral.models import quadratic as Q

from quasicentral.models.parameters import FIGURE_OMEGA as OMEGA  # noqa: E402

R0 = 0.1


def main():
    print(machine())
    t = np.linspace(0, 10 * math.pi / OMEGA, 101)
    worst = 0.0
    cases = [(f"{k2:g}", math.sqrt(1 - k2)) for k2 in (-2, -1, -1e-6, -1e-12, -1e-15, 0, 1e-15, 1e-12, 1e-6,
                                                       0.5, 0.9, 0.99, 0.999)]
    # beyond the target's range: k² → 1 given by v0/u = √(1 − k²) (1 − 10⁻³⁰ is no double), and k² = 1
    cases += [(f"1 - {r * r:g}", r) for r in (1e-4, 1e-8, 1e-15)] + [("1", 0.0)]
    for label, ratio in cases:
        v0 = R0 * OMEGA * ratio
        x, y = Q.first_order(t, R0, v0, OMEGA, 0.5)
        with mpmath.workdps(40):
            xm, ym = Q.first_order([mpmath.mpf(float(a)) for a in t], mpmath.mpf(R0), mpmath.mpf(v0),
                                   mpmath.mpf(OMEGA), mpmath.mpf(0.5), ops=Q.MP)
        scale = max(R0, v0 / OMEGA)
        err = max(max(abs(float(a) - b) for a, b in zip(xm, x)), max(abs(float(a) - b) for a, b in zip(ym, y))) / scale
        worst = max(worst, err)
        print(f"k2 = {label:<10} max error / scale = {err:.2e}")
    print(f"worst: {worst:.2e} (target 1e-13)")
    big = np.linspace(0, 10 * math.pi / OMEGA, 10**6)
    Q.first_order(big, R0, 0.2, OMEGA, 0.5)
    best = best_of(lambda: Q.first_order(big, R0, 0.2, OMEGA, 0.5), 3)
    print(f"cost: {best / big.size * 1e9:.0f} ns per point (10^6 points; target 2000)")
    tt = np.linspace(0, 4 * math.pi / OMEGA, 400)
    betas = np.geomspace(0.01, 0.5, 8)
    errs = []
    for b in betas:
        x1, y1 = Q.first_order(tt, R0, 0.2, OMEGA, b)
        xf, yf = Q.integrate_full(tt, R0, 0.2, OMEGA, b, rtol=1e-13)
        errs.append(max(np.max(np.abs(x1 - xf)), np.max(np.abs(y1 - yf))))
    p, logc = np.polyfit(np.log(betas), np.log(errs), 1)
    print(f"first-order error over 0..4pi (R0 = 0.1 m, v0 = 0.2 m/s): {math.exp(logc):.3g} * beta^{p:.3f} m")
    t0 = time.perf_counter()
    Q.integrate_full(tt, R0, 0.2, OMEGA, 0.5, rtol=1e-12)
    print(f"full motion (DOP853, rtol 1e-12, 2 periods): {1e3 * (time.perf_counter() - t0):.1f} ms")



if __name__ == "__main__":
    main()
