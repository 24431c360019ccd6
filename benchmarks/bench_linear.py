"""Linear-drag closed form: accuracy (ulp of the solution's scale, against a 40-digit
evaluation at the exact double inputs) across κ/Ω, and cost per point on arrays of 10⁶.

    python3 benchmarks/bench_linear.py
"""


import mpmath
import numpy as np

from _timing import best_of, machine

from quasicentral.models import motion

from quasicentral.models.parameters import FIGURE_OMEGA as OMEGA  # noqa: E402


def ulp_error(kappa, n=400, t_end=12.0):
    t = np.linspace(0, t_end, n)
    x, y = motion.linear(t, 0.1, 0.1, OMEGA, kappa)
    with mpmath.workdps(40):
        xr, yr = motion.linear([mpmath.mpf(float(a)) for a in t], mpmath.mpf(0.1), mpmath.mpf(0.1),
                               mpmath.mpf(OMEGA), mpmath.mpf(kappa), ops=motion.MP)
        xr = np.array([float(a) for a in xr])
        yr = np.array([float(a) for a in yr])
    return (np.max(np.abs(x - xr)) / np.spacing(0.1), np.max(np.abs(y - yr)) / np.spacing(0.1 / OMEGA))


def main():
    print(machine())
    print("kappa/Omega        max err x [ulp of R0]   max err y [ulp of v0/Omega]")
    for r in (0, 0.1, 0.5, 1 - 1e-6, 1 - 1e-12, 1.0, 1 + 1e-12, 1 + 1e-6, 2, 10, 1000):
        ex, ey = ulp_error(r * OMEGA)
        print(f"{r:<18.12g} {ex:10.2f}              {ey:10.2f}")
    t = np.linspace(0, 20, 10**6)
    for r in (0.1, 1.0, 2.0):
        motion.linear(t, 0.1, 0.1, OMEGA, r * OMEGA)
        best = best_of(lambda: motion.linear(t, 0.1, 0.1, OMEGA, r * OMEGA), 5)
        print(f"cost, kappa/Omega = {r}: {best / t.size * 1e9:.1f} ns per point (10^6 points)")



if __name__ == "__main__":
    main()
