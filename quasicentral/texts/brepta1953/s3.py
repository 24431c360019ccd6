"""[Brepta1953] section 3: the spherical pendulum for small swings, without drag.

The bob sits at r = l(sin φ cos ψ, sin φ sin ψ, −cos φ) (φ from the downward vertical, ψ the
azimuth of the pendulum's plane).  Its Lagrangian L = T − V with T = ½m|ṙ|² and V = m g z gives
(6), (7) by Euler–Lagrange.  "Small swings" is an expansion in the amplitude: φ, φ̇, φ̈ are
scaled by ε (ψ and its rates are not small: for a conical pendulum ψ̇ = Ω) and each equation is
kept to its leading order in ε.  The projection of the bob onto the horizontal tangent plane at
the lowest point, ρ = l sin φ ≈ lφ, then moves as a planar harmonic oscillator under the central
force S = m(g/l)ρ, with Ω² = g/l and period T = 2π/Ω.
"""

from __future__ import annotations

import sympy as sp
from sympy.calculus.euler import euler_equations

from quasicentral.engine.registry import derived, derives, shared
from quasicentral.notation.identities import pythagorean
from quasicentral.notation.symbols import D
from quasicentral.engine.texts import symbols_of

#: dsolve's method for a linear ODE with constant coefficients (named: sympy would otherwise
#: classify the equation against every method first)
LINEAR = "nth_linear_constant_coeff_homogeneous"

S_ = symbols_of(__file__)  # this text's declared symbols (text.toml)
(C, C1, C2, C3, C4, Omega, S, Tper, g, l, m, phi, psi, rho, t) = S_(
    "C C1 C2 C3 C4 Omega S T g l m phi psi rho t")

EPS = sp.Symbol("epsilon", positive=True)  # bookkeeping parameter of the small amplitude


# --- the bob in space ---------------------------------------------------------------------------
def bob_position() -> sp.Matrix:
    """r = l(sin φ cos ψ, sin φ sin ψ, −cos φ), the pivot at the origin, z upwards."""
    return l * sp.Matrix([sp.sin(phi) * sp.cos(psi), sp.sin(phi) * sp.sin(psi), -sp.cos(phi)])


@shared
def lagrangian() -> sp.Expr:
    """L = ½m|ṙ|² − m g z = ½ m l²(φ̇² + sin²φ ψ̇²) + m g l cos φ."""
    vel = bob_position().diff(t)
    return pythagorean(m * vel.dot(vel) / 2) - m * g * bob_position()[2]


@shared
def euler_lagrange() -> tuple[sp.Expr, sp.Expr]:
    """The two Euler–Lagrange residuals (in φ and in ψ), each divided by m l²."""
    eq_phi, eq_psi = euler_equations(lagrangian(), [phi, psi], t)
    return sp.expand(eq_phi.lhs / (m * l**2)), sp.expand(eq_psi.lhs / (m * l**2))


def small(expr: sp.Expr) -> sp.Expr:
    """Scale φ and its time derivatives by ε (ψ stays finite)."""
    return expr.xreplace({D(phi, 2): EPS * D(phi, 2), D(phi): EPS * D(phi), phi: EPS * phi})


@shared
def leading_order(expr: sp.Expr, max_order: int = 4) -> sp.Expr:
    """The lowest non-vanishing Taylor coefficient of expr(ε) at ε = 0 (ε set to 1)."""
    for order in range(max_order + 1):
        coeff = sp.simplify(sp.diff(expr, EPS, order).subs(EPS, 0) / sp.factorial(order))
        if coeff != 0:
            return coeff
    raise ValueError("no term up to the requested order")


def first_order_polynomial(expr: sp.Expr) -> sp.Expr:
    """Taylor polynomial of expr(εφ) to first order in ε (ε set to 1)."""
    return sp.series(small(expr), EPS, 0, 2).removeO().subs(EPS, 1)


@derives("brepta1953:6", unknowns=(D(phi, 2),))
def equation_phi():
    """φ̈ − sin φ cos φ ψ̇² + (g/l) sin φ = 0: Euler–Lagrange in φ for L = ½ml²(φ̇² + sin²φ ψ̇²) + mgl cos φ."""
    return sp.Eq(euler_lagrange()[0], 0)


@derives("brepta1953:7", unknowns=(D(psi, 2),))
def equation_psi():
    """d/dt(sin²φ ψ̇) = 0: Euler–Lagrange in the cyclic coordinate ψ (∂L/∂ψ = 0)."""
    return sp.Eq(euler_lagrange()[1], 0)


@derives("brepta1953:small-angle", unknowns=(sp.sin(phi), sp.cos(phi)))
def small_angle():
    """sin φ ≈ φ, cos φ ≈ 1: the Taylor polynomials of sin, cos to first order in φ."""
    return [sp.Eq(sp.sin(phi), first_order_polynomial(sp.sin(phi))),
            sp.Eq(sp.cos(phi), first_order_polynomial(sp.cos(phi)))]


@derives("brepta1953:8", uses=("brepta1953:6",), unknowns=(D(phi, 2),))
def small_equation_phi():
    """φ̈ − φψ̇² + (g/l)φ = 0, i.e. −(g/l)φ = φ̈ − φψ̇²: (6) to first order in the amplitude."""
    return sp.Eq(leading_order(small(derived("brepta1953:6").lhs)), 0)


def small_angular_momentum() -> sp.Expr:
    """φ²ψ̇: the conserved ∂L/∂ψ̇ /(ml²) = sin²φ ψ̇ to leading (second) order in the amplitude."""
    p_psi = sp.diff(lagrangian(), D(psi)) / (m * l**2)
    return leading_order(small(p_psi))


def small_angle_motion() -> dict:
    """The general small-swing motion: the tangent-plane oscillator of (12), r̈ = −(g/l) r, solved
    by dsolve with four free constants, read back as φ = ρ/l and ψ = atan2(Y, X).  (Used by the
    tests: it satisfies the reduced equations (8), (9) identically.)"""
    Xf, Yf = sp.Function("X"), sp.Function("Y")
    force_per_mass = -derived("brepta1953:12").rhs / (m * rho)  # S/(mρ) along −e_ρ: −(g/l)
    solx = sp.dsolve(sp.Eq(Xf(t).diff(t, 2), force_per_mass * Xf(t)), Xf(t), hint=LINEAR).rhs
    soly = sp.dsolve(sp.Eq(Yf(t).diff(t, 2), force_per_mass * Yf(t)), Yf(t), hint=LINEAR).rhs
    c1, c2 = sorted(solx.free_symbols - {t, g, l}, key=str)
    solx = solx.xreplace({c1: C1, c2: C2})
    soly = soly.xreplace({c1: C3, c2: C4})
    rho_model = sp.sqrt(solx**2 + soly**2)
    phi_model = sp.solve(sp.Eq(derived("brepta1953:rho-projection").rhs, rho_model), phi)[0]
    return {phi: phi_model, psi: sp.atan2(soly, solx)}


def small_equation_psi_residual() -> sp.Expr:
    """(7) to leading (second) order in the amplitude: 2φφ̇ψ̇ + φ²ψ̈ (up to a constant factor)."""
    return leading_order(small(derived("brepta1953:7").lhs))


def small_motion_jets() -> dict:
    """Every small-swing motion, on its jets: φ, φ̇, ψ̇ free, the second derivatives fixed by
    the reduced equations — φ̈ from (8), ψ̈ from (7) to leading order."""
    phi2 = sp.solve(derived("brepta1953:8").lhs, D(phi, 2))[0]
    psi2 = sp.solve(small_equation_psi_residual(), D(psi, 2))[0]
    return {D(phi, 2): phi2, D(psi, 2): psi2}


@derives("brepta1953:9", mode="substitute", uses=("brepta1953:7", "brepta1953:8"))
def small_equation_psi():
    """d/dt(φ²ψ̇) = 0: (7) to leading order in the amplitude.  Checked on the small-swing
    motions (second derivatives from the reduced equations): the printed relation must follow."""
    return small_motion_jets()


@derives("brepta1953:10", uses=("brepta1953:7",), unknowns=(C,))
def small_integral_psi():
    """φ²ψ̇ = C: (9) integrated once; C is the value of φ²ψ̇ at t = 0."""
    q = small_angular_momentum()
    # (9) says d/dt of this quantity vanishes: its residual is a constant multiple of dq/dt
    ratio = sp.simplify(q.diff(t) / small_equation_psi_residual())
    assert ratio.is_number and ratio != 0
    Qf = sp.Function("Q")
    sol = sp.dsolve(sp.Eq(Qf(t).diff(t), 0), Qf(t)).rhs  # Q(t) = C1, a constant
    (const,) = sol.free_symbols
    return sp.Eq(sol.xreplace({const: C}), q)  # the constant is named C: C = φ²ψ̇


def thread_tension() -> sp.Expr:
    """N = m g·e_r − m r̈·e_r (Newton along the thread, e_r = r/l outwards): m g cos φ + ml(φ̇² + sin²φψ̇²)."""
    r = bob_position()
    e_r = r / l
    gravity = sp.Matrix([0, 0, -m * g])
    return pythagorean(gravity.dot(e_r) - m * r.diff(t, 2).dot(e_r))


@derives("brepta1953:11", unknowns=(S,))
def tangent_plane_force():
    """S = m g φ: the horizontal component N sin φ of the thread's pull, to first order in the
    amplitude (gravity is vertical and has no share in the tangent plane)."""
    e_r = bob_position() / l
    # |horizontal part of e_r| = |sin φ| = sin φ for the polar angle 0 < φ < π
    share = sp.sqrt(sp.simplify(e_r[0] ** 2 + e_r[1] ** 2)).replace(sp.Abs, lambda a: a)
    return sp.Eq(S, leading_order(small(thread_tension() * share)))


@derives("brepta1953:rho-projection", unknowns=(rho,))
def rho_projection():
    """ρ = lφ: the bob's distance from the vertical, √(X² + Y²) = l sin φ (0 ≤ φ ≤ π), to first order."""
    r = bob_position()
    rho2 = sp.simplify(r[0] ** 2 + r[1] ** 2)  # l² sin²φ
    root = sp.sqrt(sp.factor(rho2)).replace(sp.Abs, lambda a: a)
    return sp.Eq(rho, leading_order(small(root)))


@derives("brepta1953:12", uses=("brepta1953:11", "brepta1953:rho-projection"), unknowns=(S,))
def central_force():
    """S = m (g/l) ρ: φ = ρ/l eliminated from (11)."""
    phi_of_rho = sp.solve(derived("brepta1953:rho-projection"), phi)[0]
    return sp.Eq(S, derived("brepta1953:11").rhs.subs(phi, phi_of_rho))


@shared
def oscillator_frequency() -> sp.Expr:
    """The angular frequency of ẍ = −(S/(mρ)) x from (12), read off dsolve's solution."""
    Xf = sp.Function("X")
    force_per_mass = -derived("brepta1953:12").rhs / (m * rho)
    sol = sp.dsolve(sp.Eq(Xf(t).diff(t, 2), force_per_mass * Xf(t)), Xf(t), hint=LINEAR).rhs
    freqs = {sp.simplify(a.args[0] / t) for a in sol.atoms(sp.sin, sp.cos)}
    (freq,) = freqs
    return freq


@shared
def oscillator_period() -> sp.Expr:
    """The period 2π/freq; asserted: the general solution repeats after it."""
    freq = oscillator_frequency()
    period = 2 * sp.pi / freq
    Xf = sp.Function("X")
    sol = sp.dsolve(sp.Eq(Xf(t).diff(t, 2), -freq**2 * Xf(t)), Xf(t), hint=LINEAR).rhs
    assert sp.simplify(sp.expand_trig(sol.subs(t, t + period) - sol)) == 0
    return period


@derives("brepta1953:period-and-frequency", uses=("brepta1953:12",), unknowns=(Tper, Omega**2))
def period_and_frequency():
    """T = 2π/Ω, Ω² = g/l: the frequency and the period of the tangent-plane oscillator."""
    return [sp.Eq(Tper, oscillator_period()), sp.Eq(Omega**2, oscillator_frequency() ** 2)]


@derives("brepta1953:13", uses=("brepta1953:12",), unknowns=(Tper,))
def period():
    """T = 2π √(l/g)."""
    return sp.Eq(Tper, sp.powsimp(sp.simplify(oscillator_period()), force=True))


@derives("brepta1953:8a", uses=("brepta1953:8",), unknowns=(D(phi, 2),))
def radial_equation_tangent_plane():
    """m[lφ̈ − lφψ̇²] = −m g φ: the reduced equation (8), φ̈ − φψ̇² + (g/l)φ = 0, times m l."""
    return sp.Eq(sp.expand(m * l * derived("brepta1953:8").lhs), 0)

