"""[Brepta1953] section 3 beyond the catalog: the Lagrangian, the small-angle reduction, the
errata of (8)–(10) from other sides, and (8a) as the radial equation of section 2."""

import random

import mpmath
import pytest
import sympy as sp

import shipped
s3 = shipped.module('brepta1953', 's3')
from shipped import derived
from quasicentral.notation.symbols import D
from quasicentral.engine.texts import symbols_of, SHIPPED_ROOT

S_ = symbols_of(SHIPPED_ROOT / "brepta1953" / "text.toml")
C1, C2, C3, C4, R, S, g, l, m, phi, psi, rho, t = S_("C1 C2 C3 C4 R S g l m phi psi rho t")




@pytest.fixture(autouse=True)
def _shipped_context():
    """The module's helpers ask derived() for results: the shipped workspace's derivations."""
    with shipped.context():
        yield

def _value(expr, seed=1, **fixed):
    """expr at a random point (φ jets and parameters), as a float."""
    rng = random.Random(seed)
    syms = sorted(expr.free_symbols, key=str)
    return complex(expr.subs({s_: fixed.get(str(s_), sp.Rational(rng.randint(11, 99), 37)) for s_ in syms})).real


def _jets(expr):
    """Time derivatives of φ, ψ replaced by plain symbols."""
    p1, p2, q1, q2, f = sp.symbols("p1 p2 q1 q2 f")
    return expr.subs({D(phi, 2): p2, D(psi, 2): q2}).subs({D(phi): p1, D(psi): q1}).subs(phi, f)


def test_lagrangian_is_the_spherical_pendulum():
    expected = m * l**2 / 2 * (D(phi) ** 2 + sp.sin(phi) ** 2 * D(psi) ** 2) + m * g * l * sp.cos(phi)
    assert sp.simplify(s3.lagrangian() - expected) == 0


def test_equations_6_7_agree_with_lagranges_method():
    from sympy.physics.mechanics import LagrangesMethod, dynamicsymbols

    q1, q2 = dynamicsymbols("q1 q2")
    T = dynamicsymbols._t
    L = m * l**2 / 2 * (q1.diff(T) ** 2 + sp.sin(q1) ** 2 * q2.diff(T) ** 2) + m * g * l * sp.cos(q1)
    eqs = LagrangesMethod(L, [q1, q2]).form_lagranges_equations()
    back = {q1: phi.subs(t, T), q2: psi.subs(t, T)}
    for k, eid in enumerate(("brepta1953:6", "brepta1953:7")):
        ours = derived(eid).lhs.subs(t, T)
        theirs = eqs[k].subs(back).doit() / (m * l**2)
        assert sp.simplify(ours + theirs) == 0 or sp.simplify(ours - theirs) == 0


def test_leading_order_equals_the_printed_small_angle_substitution():
    """Expanding in the amplitude gives what sin φ ≈ φ, cos φ ≈ 1 (the derived small-angle entry)
    gives when substituted into (6), (7) (for (7) after dropping the higher powers of φ)."""
    rules = {e.lhs: e.rhs for e in derived("brepta1953:small-angle")}
    sub6 = derived("brepta1953:6").lhs.subs(rules)
    assert sp.expand(sub6 - derived("brepta1953:8").lhs) == 0
    sub7 = sp.expand(derived("brepta1953:7").lhs.subs(rules))
    assert sp.expand(sub7 - s3.small_equation_psi_residual()) == 0


def test_each_slip_of_8_alone_is_still_wrong():
    """(8) needs both corrections: the factor φ moved to the left side and ψ̇ for φ̇."""
    phi2 = sp.solve(derived("brepta1953:8").lhs, D(phi, 2))[0]
    only_factor = sp.Eq(-g / l * phi, D(phi, 2) - phi * D(phi) ** 2)
    only_variable = sp.Eq(-g / l, phi * D(phi, 2) - phi * D(psi) ** 2)
    both = sp.Eq(-g / l * phi, D(phi, 2) - phi * D(psi) ** 2)
    for rel, ok in ((only_factor, False), (only_variable, False), (both, True)):
        val = sp.solve(rel, D(phi, 2))[0]
        diff = _jets(val - phi2)
        assert (sp.simplify(diff) == 0) is ok
        if not ok:
            assert abs(_value(diff)) > 1e-6


def test_small_motion_satisfies_the_corrected_8_9_10():
    """The tangent-plane oscillator (dsolve of (12), four constants) solves the corrected reduced
    equations, with C = φ²ψ̇ constant; the printed (9), (10) fail on it."""
    model = s3.small_angle_motion()
    args = (C1, C2, C3, C4, g, l, t)

    def compiled(expr):
        return sp.lambdify(args, expr.subs(model).doit(), modules="mpmath")

    q = derived("brepta1953:10").rhs  # φ²ψ̇
    corrected = [compiled(derived("brepta1953:8").lhs), compiled(D(phi**2 * D(psi)).doit()),
                 compiled(D(q).doit())]
    printed = [compiled(D(phi**2 * D(phi)).doit()), compiled(D(phi**2 * D(phi)))]
    rng = random.Random(7)
    with mpmath.workdps(30):
        for _ in range(5):
            pt = [mpmath.mpf(rng.randint(-90, 90)) / 97 for _ in range(4)]
            pt += [mpmath.mpf(rng.randint(100, 2500)) / 100, mpmath.mpf(rng.randint(10, 1000)) / 100,
                   mpmath.mpf(rng.randint(1, 1000)) / 97]
            for f in corrected:
                assert abs(f(*pt)) < 1e-20
            for f in printed:
                assert abs(f(*pt)) > 1e-8


def test_8a_is_8_times_ml_and_the_radial_equation_of_section_2():
    corrected8 = derived("brepta1953:8").lhs  # φ̈ − φψ̇² + (g/l)φ, up to sign
    printed8a = m * (l * D(phi, 2) - l * phi * D(psi) ** 2) + m * g * phi
    assert sp.expand(printed8a + m * l * corrected8) == 0 or sp.expand(printed8a - m * l * corrected8) == 0
    # the printed (8) times m l is not (8a)
    printed8 = -g / l - (phi * D(phi, 2) - phi * D(phi) ** 2)
    assert sp.simplify(_jets(sp.expand(m * l * printed8) + printed8a)) != 0
    assert sp.simplify(_jets(sp.expand(m * l * printed8) - printed8a)) != 0
    # section 2's (1): m(ρ̈ − ρψ̇²) = −S − R sin α with ρ = lφ, S = mgφ, R = 0
    radial = derived("brepta1953:1").lhs  # m(ρ̈ − ρψ̇²) + S + R sin α
    radial = radial.subs(R, 0).subs(S, derived("brepta1953:11").rhs)
    radial = radial.subs(rho, derived("brepta1953:rho-projection").rhs).doit()
    assert sp.simplify(radial - printed8a) == 0


def test_period_repeats_the_motion_and_is_13():
    T = s3.oscillator_period()
    assert sp.simplify(T - 2 * sp.pi * sp.sqrt(l / g)) == 0
    model = s3.small_angle_motion()
    later = {k: v.subs(t, t + T) for k, v in model.items()}
    pt = {C1: sp.Rational(1, 3), C2: sp.Rational(-2, 7), C3: sp.Rational(1, 5), C4: sp.Rational(3, 11),
          g: sp.Rational(981, 100), l: sp.Rational(3, 2), t: sp.Rational(5, 7)}
    assert abs(sp.N((later[phi] - model[phi]).subs(pt), 30)) < 1e-25


def test_tension_is_mg_to_leading_order():
    """N = mg cos φ + ml(φ̇² + sin²φ ψ̇²) = mg + O(ε²): the projected pull is mgφ + O(ε³)."""
    n = s3.thread_tension()
    assert sp.simplify(n - (m * g * sp.cos(phi) + m * l * (D(phi) ** 2 + sp.sin(phi) ** 2 * D(psi) ** 2))) == 0
    assert s3.leading_order(s3.small(n)) == m * g
