"""[Brepta1953] section 5 beyond the catalog: the corrected solution (28)–(30) of the linearized
quadratic-drag pendulum against direct quadrature of the variation-of-constants integrals and a
DOP853 integration of the linearized equations over five periods, its limit k → 0 (the conical
start (31)–(32)), the printed ζ forms on the first half-period only, and the sign of their F terms."""

import math

import mpmath
import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

import shipped
s5 = shipped.module('brepta1953', 's5')
from quasicentral.notation.domain import substitute_definitions
from shipped import derived
from quasicentral.engine.texts import symbols_of, SHIPPED_ROOT

S_ = symbols_of(SHIPPED_ROOT / "brepta1953" / "text.toml")
Omega, R0, beta, g, k, l, t, u, v0, z, zeta = S_("Omega R0 beta g k l t u v0 z zeta")

ERRATA, _ = shipped.records()
#: parameter sets (R0, v0, Ω, β): u = R0Ω > v0 as in the paper (moderate and near-circular and
#: strongly elliptic), and one with u < v0 (k² < 0), where the corrected form holds as well
CASES = [
    (sp.Rational(1, 2), sp.Rational(9, 10), sp.Integer(3), sp.Rational(1, 3)),
    (sp.Rational(7, 10), sp.Rational(1, 20), sp.Rational(5, 2), sp.Rational(3, 5)),
    (sp.Rational(3, 10), sp.Rational(17, 20), sp.Integer(3), sp.Rational(2, 7)),
    (sp.Rational(1, 4), sp.Rational(3, 2), sp.Integer(2), sp.Rational(1, 2)),
]



@pytest.fixture(autouse=True)
def _shipped_context():
    """The module's helpers ask derived() for results: the shipped workspace's derivations."""
    with shipped.context():
        yield

def _values(case):
    r0, vv, om, b = case
    return {R0: r0, v0: vv, Omega: om, beta: b, g: om**2, l: sp.Integer(1)}


def _as_functions(rels, case, dps):
    """x(t), y(t) of a list [Eq(x, …), Eq(y, …)] at the case's parameters (ζ = cos Ωt, k² = 1 − v0²/u²)."""
    defs = {zeta: sp.cos(Omega * t), k: sp.sqrt(u**2 - v0**2) / u, u: R0 * Omega}
    out = []
    for rel in rels:
        e = substitute_definitions(rel.rhs, defs).subs(_values(case))
        f = sp.lambdify(t, e, modules=[{"elliptic_f": mpmath.ellipf, "elliptic_e": mpmath.ellipe,
                                        "elliptic_k": mpmath.ellipk}, "mpmath"])
        out.append(f)
    return out


def _corrected_particular():
    return list(ERRATA["brepta1953:particular-solution"].relations())


def _printed_particular():
    return shipped.entry("brepta1953:particular-solution").relations()


def _quadrature_solution(case, dps=30):
    """x(t), y(t) straight from the variation of constants: A = ∫₀ᵗ A', B = R0 + ∫₀ᵗ B',
    C = v0/Ω + ∫₀ᵗ C', D = ∫₀ᵗ D' (A(0) = D(0) = 0, B(0) = R0, C(0) = v0/Ω fit the start),
    each integral by mpmath.quad between the turning points Ωt = jπ/2 of the speed, accumulated
    along the sorted times.  Returns xy(times) -> [(x, y), …]."""

    def params():
        r0, vv, om, b = (mpmath.mpf(sp.Rational(c).p) / sp.Rational(c).q for c in case)
        return r0, vv, om, b, r0 * om

    def rate(i, tt, r0, vv, om, b, uu):
        s_, c_ = mpmath.sin(om * tt), mpmath.cos(om * tt)
        V = mpmath.sqrt(uu**2 * s_**2 + vv**2 * c_**2)
        return (b * r0 * s_ * c_ * V, -b * r0 * s_**2 * V, -b * vv / om * c_**2 * V, b * vv / om * s_ * c_ * V)[i]

    def xy(times):
        with mpmath.workdps(dps):
            par = params()
            r0, vv, om, b, uu = par
            times = [mpmath.mpf(T) for T in times]
            step = mpmath.pi / (2 * om)
            turning = [j * step for j in range(1, int(max(times) / step) + 1)]
            marks = sorted(set(turning) | set(times))
            acc, last, values = mpmath.matrix([0, r0, vv / om, 0]), mpmath.mpf(0), {}
            for T in marks:
                acc += mpmath.matrix([mpmath.quad(lambda tt, i=i: rate(i, tt, *par), [last, T]) for i in range(4)])
                last = T
                values[T] = acc.copy()
            out = []
            for T in times:
                A, B, C, D = values[T]
                s_, c_ = mpmath.sin(om * T), mpmath.cos(om * T)
                out.append((A * s_ + B * c_, C * s_ + D * c_))
            return out

    return xy


def _times(case, n=10, turns=5):
    om = float(case[2])
    return [turns * 2 * math.pi / om * (j + 0.37) / n for j in range(n)]


@pytest.mark.parametrize("case", CASES)
def test_corrected_solution_equals_the_quadrature_of_the_variation_of_constants(case):
    """The corrected (28)–(30) with the constants, in Legendre form with the amplitude z = π/2 − Ωt,
    equals the variation-of-constants integrals evaluated by quadrature over 0 ≤ Ωt ≤ 10π."""
    xs, ys = _as_functions(_corrected_particular(), case, 30)
    truth = _quadrature_solution(case)
    times = _times(case)
    with mpmath.workdps(30):
        for T, (xq, yq) in zip(times, truth(times)):
            assert abs(xs(mpmath.mpf(T)) - xq) < mpmath.mpf(10) ** -22
            assert abs(ys(mpmath.mpf(T)) - yq) < mpmath.mpf(10) ** -22


def _linearized_ivp(case, t_end, t_eval):
    """DOP853 on ẍ = −Ω²x + βR0Ω sin Ωt V, ÿ = −Ω²y − βv0 cos Ωt V (the first-order equations,
    V² = R0²Ω² sin² Ωt + v0² cos² Ωt the squared speed on the ellipse (24)–(25))."""
    r0, vv, om, b = (float(c) for c in case)

    def rhs(tt, q):
        V = math.sqrt((r0 * om * math.sin(om * tt)) ** 2 + (vv * math.cos(om * tt)) ** 2)
        return [q[1], -om**2 * q[0] + b * r0 * om * math.sin(om * tt) * V,
                q[3], -om**2 * q[2] - b * vv * math.cos(om * tt) * V]

    sol = solve_ivp(rhs, (0.0, t_end), [r0, 0.0, 0.0, vv], method="DOP853", rtol=1e-12, atol=1e-14,
                    t_eval=t_eval)
    assert sol.success
    return sol.y[0], sol.y[2]


@pytest.mark.parametrize("case", CASES)
def test_corrected_solution_equals_a_dop853_integration_of_the_linearized_equations(case):
    om = float(case[2])
    t_end = 10 * math.pi / om
    grid = np.linspace(0.0, t_end, 61)
    xi, yi = _linearized_ivp(case, t_end, grid)
    xs, ys = _as_functions(_corrected_particular(), case, 20)
    with mpmath.workdps(20):
        xc = np.array([float(xs(mpmath.mpf(float(T)))) for T in grid])
        yc = np.array([float(ys(mpmath.mpf(float(T)))) for T in grid])
    scale = float(case[0]) + float(case[1]) / om
    assert np.max(np.abs(xc - xi)) < 1e-9 * scale
    assert np.max(np.abs(yc - yi)) < 1e-9 * scale


def test_printed_solution_holds_on_the_first_half_period_only():
    """The printed particular solution (ζ = cos Ωt) agrees with the quadrature for 0 < Ωt < π and
    fails after: at Ωt = 2π it gives x = R0 (no loss), while the motion has lost βR0∫ sin²Ωt V dt."""
    case = CASES[0]
    om = float(case[2])
    xs, ys = _as_functions(_printed_particular(), case, 30)
    truth = _quadrature_solution(case)
    with mpmath.workdps(30):
        early = [mpmath.mpf(theta) / om for theta in (0.3, 1.1, 2.0, 3.0)]
        for T, (xq, yq) in zip(early, truth(early)):
            assert abs(xs(T) - xq) < mpmath.mpf(10) ** -22
            assert abs(ys(T) - yq) < mpmath.mpf(10) ** -22
        late = [mpmath.mpf(theta) / om for theta in (3.6, 5.0, 2 * mpmath.pi, 9.0, 4 * mpmath.pi)]
        for T, (xq, _) in zip(late, truth(late)):
            assert abs(xs(T) - xq) > 1e-4
        two_pi = mpmath.mpf(2) * mpmath.pi / om
        assert abs(xs(two_pi) - mpmath.mpf(1) / 2) < mpmath.mpf(10) ** -25  # printed: x(2π/Ω) = R0
        assert truth([two_pi])[0][0] < mpmath.mpf(1) / 2 - mpmath.mpf(10) ** -3


def _flip_F(rel):
    """The relation with the sign of every F(k, ζ) term reversed."""
    return rel.replace(lambda e: isinstance(e, sp.elliptic_f) and e.args[0] == sp.asin(zeta),
                       lambda e: -e)


def test_sign_of_the_F_terms_is_right():
    """On 0 < Ωt < π, where the ζ forms are valid, the printed F coefficients −(1−k²)/(3k²) (x) and
    +(1−k²)/(3k²) (y) agree with the quadrature; with either sign reversed they do not."""
    case = CASES[0]
    om = float(case[2])
    printed = _printed_particular()
    flipped = [_flip_F(r) for r in printed]
    assert flipped[0] != printed[0] and flipped[1] != printed[1]
    xs, ys = _as_functions(printed, case, 30)
    xf, yf = _as_functions(flipped, case, 30)
    truth = _quadrature_solution(case)
    with mpmath.workdps(30):
        pts = [mpmath.mpf(theta) / om for theta in (0.7, 1.9, 2.8)]
        for T, (xq, yq) in zip(pts, truth(pts)):
            assert abs(xs(T) - xq) < mpmath.mpf(10) ** -22 and abs(ys(T) - yq) < mpmath.mpf(10) ** -22
            assert abs(xf(T) - xq) > 1e-6 and abs(yf(T) - yq) > 1e-6


def test_limit_k_to_zero_is_the_conical_solution():
    """u = v0(1 + ε), ε → 0 (k² ≈ 2ε): the corrected general solution tends to the conical
    particular solution (31)–(32) with R0Ω = v0; the difference is O(ε)."""
    conical = shipped.entry("brepta1953:conical-particular-solution").relations()
    vv, om, b = sp.Rational(4, 5), sp.Integer(2), sp.Rational(1, 3)
    for eps, tol in ((sp.Rational(1, 10**12), 1e-10), (sp.Rational(1, 10**20), 1e-18)):
        r0 = vv * (1 + eps) / om
        gen = _as_functions(_corrected_particular(), (r0, vv, om, b), 60)
        con = _as_functions(conical, (vv / om, vv, om, b), 60)
        with mpmath.workdps(60):
            for theta in (0.4, 2.5, 3.9, 7.0, 12.0, 10 * math.pi - 0.2):
                T = mpmath.mpf(theta) / om
                for fg, fc in zip(gen, con):
                    assert abs(fg(T) - fc(T)) < tol


def test_limit_k_to_zero_symbolically_for_the_closed_B():
    """βR0²{…}(z) of B-final → βR0²(sin 2Ωt/4 − Ωt/2) of (31) as k → 0 (series in k, order k⁰)."""
    Bclosed = derived("brepta1953:B-final").rhs - S_.C2
    m = sp.Symbol("m", positive=True)
    expr = Bclosed.subs(k, sp.sqrt(m))
    # F(φ|m) = φ + m(φ − sin φ cos φ)/4 + O(m²), E(φ|m) = φ − m(φ − sin φ cos φ)/4 + O(m²),
    # K(m) = π/2 (1 + m/4) + O(m²), E(m) = π/2 (1 − m/4) + O(m²); the bracket carries 1/m, so O(m²) drops out
    series = {
        sp.elliptic_f: lambda a, mm: a + mm * (a - sp.sin(a) * sp.cos(a)) / 4,
        sp.elliptic_e: lambda *a: (a[0] - a[1] * (a[0] - sp.sin(a[0]) * sp.cos(a[0])) / 4) if len(a) == 2
        else sp.pi / 2 * (1 - a[0] / 4),
        sp.elliptic_k: lambda mm: sp.pi / 2 * (1 + mm / 4),
    }
    approx = expr.replace(lambda e: isinstance(e, (sp.elliptic_f, sp.elliptic_e, sp.elliptic_k)),
                          lambda e: series[type(e)](*e.args))
    limit = sp.limit(sp.simplify(approx), m, 0)
    expected = beta * R0**2 * (sp.sin(2 * Omega * t) / 4 - Omega * t / 2)
    assert sp.simplify(sp.expand_trig(limit - expected)) == 0


@pytest.mark.parametrize("integrand", [
    sp.cos(z) ** 2 * s5.delta(), sp.sin(z) ** 2 * s5.delta(), 1 / s5.delta(), sp.sin(z) ** 2 / s5.delta(),
    sp.sin(z) ** 4 / s5.delta()])
def test_legendre_antiderivatives_by_differentiation(integrand):
    """dG/dz = integrand identically (so G(z) − G(π/2) is the integral for every real z) and G(0) = 0."""
    G = s5.legendre_antiderivative(integrand)
    assert sp.simplify(G.diff(z) - integrand) == 0
    assert G.subs(z, 0) == 0
    with mpmath.workdps(30):
        f = sp.lambdify((z, k), integrand, "mpmath")
        Gf = sp.lambdify((z, k), G, modules=[{"elliptic_f": mpmath.ellipf, "elliptic_e": mpmath.ellipe}, "mpmath"])
        kk = mpmath.mpf("0.83")
        for zz in (mpmath.mpf("-7.5"), mpmath.mpf("-2.2"), mpmath.mpf("1.3")):
            pts = sorted({zz, mpmath.mpf(0)} | {j * mpmath.pi / 2 for j in range(-5, 1) if zz < j * mpmath.pi / 2 < 0})
            q = mpmath.quad(lambda w: f(w, kk), pts)
            q = q if zz > 0 else -q
            assert abs(Gf(zz, kk) - q) < mpmath.mpf(10) ** -25


def test_decay_per_revolution_33_from_the_conical_solution():
    """(33): x(2π/Ω) = R0 − πβR0² on the conical particular solution; the general solution gives
    R0 − βR0²·(4/(3k²))[(1+k²)E − (1−k²)K], which tends to R0 − πβR0² as k → 0."""
    xp = derived("brepta1953:conical-particular-solution")[0].rhs
    assert sp.simplify(xp.subs(t, 2 * sp.pi / Omega) - (R0 - sp.pi * beta * R0**2)) == 0
    xg = ERRATA["brepta1953:particular-solution"].relations()[0].rhs
    at = sp.simplify(xg.subs(t, 2 * sp.pi / Omega))
    m = sp.Symbol("m", positive=True)
    expected = R0 - beta * R0**2 * 4 / (3 * m) * ((1 + m) * sp.elliptic_e(m) - (1 - m) * sp.elliptic_k(m))
    with mpmath.workdps(30):
        for kk in ("0.3", "0.8"):
            vals = {k: sp.Float(kk, 40), R0: sp.Rational(1, 2), beta: sp.Rational(1, 3), Omega: 2}
            got = sp.N(at.subs(vals), 30)
            want = sp.N(expected.subs({m: sp.Float(kk, 40) ** 2, R0: sp.Rational(1, 2), beta: sp.Rational(1, 3)}), 30)
            assert abs(got - want) < 1e-25
    small = expected.subs(m, sp.Rational(1, 10**12)).subs({R0: sp.Rational(1, 2), beta: sp.Rational(1, 3)})
    assert abs(sp.N(small - (sp.Rational(1, 2) - sp.pi * sp.Rational(1, 3) / 4), 40)) < 1e-10
