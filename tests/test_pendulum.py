"""The pendulum derivations beyond the catalog check: the period against a direct integration of
the equation of motion, pinned reference values of T/T0, the exact motion used as a model, the
general term of the series (62) and the Wallis integrals (64) at many n."""

import math

import mpmath
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

import shipped
P = shipped.module('pendulum', 'exact_period')
from shipped import derived
from quasicentral.engine.texts import symbols_of, SHIPPED_ROOT

S_ = symbols_of(SHIPPED_ROOT / "pendulum" / "text.toml")
Tper, g, l, n, phi0, w = S_("T g l n phi0 w")

G, LEN = 9.81, 0.75  # any values: T scales as sqrt(l/g)
AMPLITUDES_DEG = (1, 10, 45, 90, 135, 170)
PINNED = {  # T/T0 = 2K(m = sin²(φ0/2))/π, 30 digits, rounded to 20
    10: "1.0019071881432166070",
    90: "1.1803405990160962260",
    179: "3.9010651603890857349",
}



@pytest.fixture(autouse=True)
def _shipped_context():
    """The module's helpers ask derived() for results: the shipped workspace's derivations."""
    with shipped.context():
        yield

def _period_K(amp_deg, dps=30):
    """T from the derived closed form 4√(l/g) K(m = sin²(φ0/2)), at dps digits."""
    f = sp.lambdify((g, l, phi0), P.period(), modules=[{"elliptic_k": mpmath.ellipk}, "mpmath"])
    with mpmath.workdps(dps):
        return +f(mpmath.mpf(G), mpmath.mpf(LEN), mpmath.radians(amp_deg))


def _integrate_eom(amp_deg):
    """φ̈ = −(g/l) sin φ from φ0 at rest: times of the first zero crossing and the turning point."""
    om2 = G / LEN

    def rhs(_, y):
        return [y[1], -om2 * math.sin(y[0])]

    def crossing(_, y):
        return y[0]

    crossing.direction = -1

    def turning(t_, y):
        return y[1] if t_ > 0 else -1.0

    turning.direction = 1
    turning.terminal = True
    sol = solve_ivp(rhs, (0, 100), [math.radians(amp_deg), 0.0], method="DOP853", rtol=1e-13,
                    atol=1e-15, events=(crossing, turning), dense_output=True)
    assert sol.status == 1
    return sol.t_events[0][0], sol.t_events[1][0], sol


def _printed(eid):
    return shipped.entry(eid).relations()


@pytest.mark.parametrize("amp", AMPLITUDES_DEG)
def test_period_K_against_direct_integration(amp):
    """4 × (first zero crossing) and 2 × (turning point at −φ0) equal 4√(l/g)K(sin²(φ0/2))."""
    quarter, half, _ = _integrate_eom(amp)
    T = float(_period_K(amp))
    assert abs(4 * quarter - T) <= 1e-10 * T
    assert abs(2 * half - T) <= 1e-10 * T


@pytest.mark.parametrize("amp", (10, 90, 170))
def test_printed_60_integral_is_the_period(amp):
    """The printed (60) right side, integrated by mpmath, against the direct integration."""
    (rel,) = _printed("pendulum:60")
    f = sp.lambdify((g, l, phi0), rel.rhs, modules="mpmath")
    with mpmath.workdps(30):
        T = float(f(mpmath.mpf(G), mpmath.mpf(LEN), mpmath.radians(amp)))
    quarter, _, _ = _integrate_eom(amp)
    assert abs(4 * quarter - T) <= 1e-10 * T


@pytest.mark.parametrize("amp", sorted(PINNED))
def test_pinned_period_ratio(amp):
    """T/T0 = 2K(m = sin²(φ0/2))/π at the pinned amplitudes (modulus convention of (61))."""
    T0 = 2 * sp.pi * sp.sqrt(l / g)
    ratio = sp.simplify(P.period() / T0)
    assert not ratio.has(g, l)
    f = sp.lambdify(phi0, ratio, modules=[{"elliptic_k": mpmath.ellipk}, "mpmath"])
    with mpmath.workdps(30):
        value = +f(mpmath.radians(amp))
        pinned = mpmath.mpf(PINNED[amp])
        assert abs(value - pinned) <= mpmath.mpf("1e-19") * pinned


@pytest.mark.parametrize("amp", (10, 90, 179))
def test_quarter_period_integral_53(amp):
    """The separation integral of (53) (singular at φ0) equals √2 K(sin²(φ0/2))."""
    with mpmath.workdps(40):
        p0 = mpmath.radians(amp)
        integral = mpmath.quad(lambda x: 1 / mpmath.sqrt(mpmath.cos(x) - mpmath.cos(p0)), [0, p0])
        closed = mpmath.sqrt(2) * mpmath.ellipk(mpmath.sin(p0 / 2) ** 2)
        assert abs(integral - closed) <= mpmath.mpf("1e-15") * closed


def test_closed_form_motion_solves_the_derived_equation():
    assert P.check_closed_form(amplitudes=("0.1", "1", "2.5", "3.1"), taus=("0.3", "4", "17"), dps=40) < 1e-30


@pytest.mark.parametrize("amp", (10, 90, 170))
def test_closed_form_motion_against_direct_integration(amp):
    """The model of the exact motion, Φ(Ωt) = 2 asin(k sn(Ωt + K)), along a solve_ivp trajectory,
    and its quarter period K/Ω (first zero of Φ)."""
    _, half, sol = _integrate_eom(amp)
    om = math.sqrt(G / LEN)
    p0 = mpmath.radians(amp)
    for t_ in (0.03 * half, 0.3 * half, 0.6 * half, 0.97 * half):
        phi_ivp, rate_ivp = sol.sol(t_)
        with mpmath.workdps(30):
            phi_cf = float(P._angle_value(mpmath.mpf(om * t_), p0))
            rate_cf = float(om * P._rate_value(mpmath.mpf(om * t_), p0))
        assert abs(phi_ivp - phi_cf) <= 1e-10
        assert abs(rate_ivp - rate_cf) <= 1e-9 * om
    with mpmath.workdps(30):
        K = mpmath.ellipk(mpmath.sin(p0 / 2) ** 2)
        assert abs(P._angle_value(K, p0)) < mpmath.mpf("1e-25")
        assert abs(P._angle_value(4 * K + mpmath.mpf("0.7"), p0) - P._angle_value(mpmath.mpf("0.7"), p0)) < 1e-25


def test_substitution_maps_the_limits():
    """(57): φ(ψ) = 2 asin(sin(φ0/2) sin ψ) takes [0, π/2] increasingly onto [0, φ0]."""
    x = P.angle_of_w()
    assert sp.simplify(x.subs(w, 0)) == 0
    top = sp.lambdify(phi0, x.subs(w, sp.pi / 2))  # 2 asin(sin(φ0/2)) = φ0 for 0 < φ0 < π
    dx = sp.lambdify((phi0, w), sp.diff(x, w))
    for p0 in (0.1, 1.5, 3.1):
        assert abs(top(p0) - p0) < 1e-14
        assert all(dx(p0, 1.5707 * j / 20) > 0 for j in range(20))


def _printed_general_term():
    (rel,) = _printed("pendulum:62")
    (s,) = rel.rhs.atoms(sp.Sum)
    X = sp.Symbol("X", positive=True)
    return sp.simplify(s.function.subs(sp.sin(w), 1).subs(sp.sin(phi0 / 2), sp.sqrt(X)) / X**n)


def test_general_term_62():
    """The printed term (1/m!)(2m−1)!!/2^m is the binomial-series coefficient (1/2)_m/m! of
    (1 − X)^(−1/2): symbolically and at m = 1 … 80, and against sympy's Taylor series."""
    printed = _printed_general_term()
    assert not printed.has(sp.Symbol("X", positive=True))
    _, _, term = P.binomial_series()
    assert sp.simplify(sp.gammasimp((printed - term).rewrite(sp.gamma))) == 0
    X = sp.Symbol("X")
    taylor = sp.series((1 - X) ** sp.Rational(-1, 2), X, 0, 12).removeO()
    for j in range(1, 81):
        exact = sp.factorial2(2 * j - 1) / (sp.factorial(j) * 2**j)
        assert printed.subs(n, j) == term.subs(n, j) == exact
        if j < 12:
            assert taylor.coeff(X, j) == exact


def _poly_coeffs(expr, var_expr, degree):
    s_ = sp.Symbol("s_")
    poly = sp.expand(expr.subs(var_expr, s_))
    return [poly.coeff(s_, j) for j in range(degree + 1)]


def test_truncated_series_63_65_66_coefficients():
    """The printed coefficients of (63), (65), (66) against the derived truncations, exactly; the
    truncation error of (63) starts at X⁴ with a(4) = 35/128."""
    _, _, term = P.binomial_series()
    a = [term.subs(n, j) for j in range(P.PRINTED_TERMS)]
    (p63,) = _printed("pendulum:63")
    assert _poly_coeffs(p63.rhs.subs(sp.sin(w), 1), sp.sin(phi0 / 2) ** 2, 3) == a
    rest = sp.series(P.INTEGRAND.subs(sp.sin(w), 1).subs(sp.sin(phi0 / 2), sp.sqrt(sp.Symbol("Z"))),
                     sp.Symbol("Z"), 0, 5).removeO()
    assert sp.expand(rest - P.truncated_integrand().subs(sp.sin(w), 1).subs(sp.sin(phi0 / 2) ** 2, sp.Symbol("Z"))) \
        == sp.Rational(35, 128) * sp.Symbol("Z") ** 4
    wal = [P.wallis().subs(n, j) for j in range(P.PRINTED_TERMS)]
    pref = sp.sqrt(l / g)
    (p65,) = _printed("pendulum:65")
    c65 = _poly_coeffs(sp.expand(p65.rhs / (4 * pref)), sp.sin(phi0 / 2) ** 2, 3)
    assert c65 == [a[j] * wal[j] for j in range(4)] == [sp.pi / 2, sp.pi / 8, 9 * sp.pi / 128, 25 * sp.pi / 512]
    (p66,) = _printed("pendulum:66")
    c66 = _poly_coeffs(sp.expand(p66.rhs / (2 * sp.pi * pref)), sp.sin(phi0 / 2) ** 2, 3)
    assert c66 == [a[j] * wal[j] * 2 / sp.pi for j in range(4)]


def test_wallis_64():
    """∫₀^{π/2} sin^{2m}ψ dψ = π(2m−1)!!/(2(2m)!!): printed closed form = the derived reduction
    formula symbolically, = sympy's integral at m = 0 … 8, = mpmath.quad at m up to 60."""
    ((lhs, rhs),) = [r.args for r in _printed("pendulum:64")]
    derived_ = P.wallis()
    assert sp.simplify(sp.gammasimp((rhs - derived_).rewrite(sp.gamma))) == 0
    for j in range(0, 9):
        assert sp.simplify(sp.integrate(sp.sin(w) ** (2 * j), (w, 0, sp.pi / 2)) - rhs.subs(n, j)) == 0
    with mpmath.workdps(30):
        for j in (1, 5, 17, 33, 60):
            q = mpmath.quad(lambda x: mpmath.sin(x) ** (2 * j), [0, mpmath.pi / 2])
            closed = mpmath.mpf(sp.N(rhs.subs(n, j), 40))
            assert abs(q - closed) <= mpmath.mpf("1e-25") * closed


def test_period_derivations_agree():
    """(60)'s integral form, sympy's closed form K and the separation integral (53) are one period."""
    rel60 = derived("pendulum:60")
    assert rel60.lhs == Tper
    f60 = sp.lambdify((g, l, phi0), rel60.rhs, modules="mpmath")
    f53 = sp.lambdify((g, l, phi0), derived("pendulum:53").rhs, modules="mpmath")
    with mpmath.workdps(30):
        for amp in (5, 60, 150):
            T = _period_K(amp)
            args = (mpmath.mpf(G), mpmath.mpf(LEN), mpmath.radians(amp))
            assert abs(f60(*args) - T) <= mpmath.mpf("1e-25") * T
            assert abs(f53(*args) - T) <= mpmath.mpf("1e-14") * T
