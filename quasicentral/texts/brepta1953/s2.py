"""[Brepta1953] section 2: general laws of quasicentral motion, in polar coordinates.

Newton's law for a point at r = ρ(cos ψ, sin ψ) under a central force −S e_ρ and a drag R
opposite to the velocity.  The velocity makes the angle α with the transverse direction e_τ
(fig. 2: cos α = ρψ̇/v), so the drag is −R(sin α e_ρ + cos α e_τ).  The angular momentum
per unit mass L = ρ²ψ̇ then obeys m L̇/L = −R/v, which integrates for the two drag laws.
"""

from __future__ import annotations

import sympy as sp

from quasicentral.notation.domain import Domain
from quasicentral.engine.registry import derived, derives
from quasicentral.notation.identities import pythagorean
from quasicentral.notation.symbols import D
from quasicentral.engine.texts import symbols_of

#: dsolve's method for a linear ODE with constant coefficients (named: sympy would otherwise
#: classify the equation against every method first)
LINEAR = "nth_linear_constant_coeff_homogeneous"

S_ = symbols_of(__file__)  # this text's declared symbols (text.toml)
A, B, R, S, alpha, beta, kappa, m, psi, rho, s, t, v = S_("A B R S alpha beta kappa m psi rho s t v")

E_RHO = sp.Matrix([sp.cos(psi), sp.sin(psi)])
E_TAU = sp.Matrix([-sp.sin(psi), sp.cos(psi)])
SPEED_DOMAIN = Domain.of(definitions={v: sp.sqrt(D(rho) ** 2 + rho**2 * D(psi) ** 2)})
ANGULAR_MOMENTUM = rho**2 * D(psi)


def position() -> sp.Matrix:
    return rho * E_RHO


def acceleration() -> sp.Matrix:
    return position().diff(t, 2)


@derives("brepta1953:radial-acceleration", mode="expression")
def radial_acceleration():
    """a_ρ = r̈ · e_ρ = ρ̈ − ρψ̇²."""
    return pythagorean(acceleration().dot(E_RHO))


@derives("brepta1953:transverse-acceleration", mode="expression")
def transverse_acceleration():
    """a_τ = r̈ · e_τ = ρψ̈ + 2ρ̇ψ̇."""
    return pythagorean(acceleration().dot(E_TAU))


@derives("brepta1953:transverse-acceleration-compact", mode="expression",
         uses=("brepta1953:transverse-acceleration",))
def transverse_acceleration_compact():
    """a_τ = (1/ρ) d/dt(ρ²ψ̇), the same component written through the angular momentum."""
    return derived("brepta1953:transverse-acceleration")


def drag_direction() -> sp.Matrix:
    """Unit vector of the velocity, (sin α, cos α) in the (e_ρ, e_τ) frame."""
    return sp.sin(alpha) * E_RHO + sp.cos(alpha) * E_TAU


def newton() -> sp.Matrix:
    """m r̈ − (−S e_ρ − R v̂) = 0, the vector equation of motion."""
    return m * acceleration() + S * E_RHO + R * drag_direction()


@derives("brepta1953:1", unknowns=(D(rho, 2),))
def radial_equation():
    """m(ρ̈ − ρψ̇²) = −S − R sin α: Newton's law along e_ρ."""
    return sp.Eq(pythagorean(newton().dot(E_RHO)), 0)


@derives("brepta1953:2", unknowns=(D(psi, 2),))
def transverse_equation():
    """(m/ρ) d/dt(ρ²ψ̇) = −R cos α: Newton's law along e_τ."""
    return sp.Eq(pythagorean(newton().dot(E_TAU)), 0)


@derives("brepta1953:cos-alpha", unknowns=(sp.cos(alpha),), domain=SPEED_DOMAIN)
def cos_alpha():
    """cos α = (ṙ · e_τ)/v = ρψ̇/v, the transverse share of the velocity."""
    return sp.Eq(sp.cos(alpha), pythagorean(position().diff(t).dot(E_TAU)) / v)


def transverse_with_cos_alpha() -> sp.Eq:
    """(2) with cos α = ρψ̇/v substituted."""
    eq = derived("brepta1953:2")
    return sp.Eq(eq.lhs.subs(sp.cos(alpha), derived("brepta1953:cos-alpha").rhs), 0)


@derives("brepta1953:2-substituted", uses=("brepta1953:2", "brepta1953:cos-alpha"), unknowns=(D(psi, 2),))
def transverse_substituted():
    """(m/ρ) d/dt(ρ²ψ̇) = −R ρψ̇/v."""
    return transverse_with_cos_alpha()


@derives("brepta1953:2-divided", uses=("brepta1953:2", "brepta1953:cos-alpha"), unknowns=(D(psi, 2),))
def transverse_divided():
    """m/(ρ²ψ̇) d/dt(ρ²ψ̇) = −R/v: (2) divided by ρψ̇."""
    eq = transverse_with_cos_alpha()
    return sp.Eq(sp.expand(eq.lhs / (rho * D(psi))), 0)


@derives("brepta1953:3", uses=("brepta1953:2-divided",), unknowns=(D(psi, 2),))
def log_angular_momentum_law():
    """m d/dt ln(ρ²ψ̇) = −R/v, because d/dt ln L = L̇/L."""
    lhs = derived("brepta1953:2-divided").lhs
    return sp.Eq(lhs, 0)


@derives("brepta1953:linear-drag-law", unknowns=(R,))
def linear_drag_law():
    """R = 2κmv (the paper's linear law; κ in 1/s)."""
    return sp.Eq(R, 2 * kappa * m * v)


@derives("brepta1953:quadratic-drag-law", unknowns=(R,))
def quadratic_drag_law():
    """R = mβv² (the paper's quadratic law; β in 1/m)."""
    return sp.Eq(R, m * beta * v**2)


def law3_with(drag: sp.Eq) -> sp.Eq:
    """(3) with the drag law substituted: m d/dt ln L + R/v = 0."""
    eq = derived("brepta1953:3")
    return sp.Eq(sp.expand(eq.lhs.subs(R, drag.rhs)), 0)


@derives("brepta1953:linear-drag-ode", uses=("brepta1953:3", "brepta1953:linear-drag-law"),
         unknowns=(D(psi, 2),))
def linear_drag_ode():
    """m d/dt ln(ρ²ψ̇) = −2κm."""
    return law3_with(derived("brepta1953:linear-drag-law"))


@derives("brepta1953:linear-drag-separated", uses=("brepta1953:3", "brepta1953:linear-drag-law"), unknowns=(D(psi, 2),))
def linear_drag_separated():
    """d ln(ρ²ψ̇) = −2κ dt, i.e. d/dt ln(ρ²ψ̇) = −2κ."""
    return law3_with(derived("brepta1953:linear-drag-law"))


def angular_momentum_solution(rate: sp.Expr, var: sp.Symbol, const: sp.Symbol) -> sp.Expr:
    """Solve dL/dvar = rate·L with L(0) = const (dsolve), returning L(var)."""
    Lf = sp.Function("L")
    sol = sp.dsolve(sp.Eq(Lf(var).diff(var), rate * Lf(var)), Lf(var), ics={Lf(0): const}, hint=LINEAR)
    return sol.rhs


@derives("brepta1953:linear-drag-integrated", unknowns=(A,))
def linear_drag_integrated():
    """ln(ρ²ψ̇) = −2κt + ln A, with A = ρ²ψ̇ at t = 0."""
    return sp.Eq(sp.log(ANGULAR_MOMENTUM), sp.expand_log(sp.log(angular_momentum_solution(-2 * kappa, t, A)), force=True))


@derives("brepta1953:4", unknowns=(D(psi),))
def angular_momentum_linear():
    """ρ²ψ̇ = A e^{−2κt}: the angular momentum decays exponentially, whatever the law of S."""
    return sp.Eq(ANGULAR_MOMENTUM, angular_momentum_solution(-2 * kappa, t, A))


@derives("brepta1953:no-drag-condition", mode="condition", uses=("brepta1953:linear-drag-law",))
def no_drag_condition():
    """The torque −R cos α of (2), with R = 2κmv, must vanish for the central-motion law."""
    return -derived("brepta1953:linear-drag-law").rhs * sp.cos(alpha)


@derives("brepta1953:quadratic-drag-ode", uses=("brepta1953:3", "brepta1953:quadratic-drag-law"),
         unknowns=(D(psi, 2),))
def quadratic_drag_ode():
    """d/dt ln(ρ²ψ̇) = −βv."""
    eq = law3_with(derived("brepta1953:quadratic-drag-law"))
    return sp.Eq(sp.expand(eq.lhs / m), 0)


@derives("brepta1953:quadratic-drag-separated", uses=("brepta1953:quadratic-drag-ode",), unknowns=(D(psi, 2),))
def quadratic_drag_separated():
    """d ln(ρ²ψ̇) = −βv dt, i.e. d/dt ln(ρ²ψ̇) = −βv."""
    return derived("brepta1953:quadratic-drag-ode")


@derives("brepta1953:arc-length-rate", unknowns=(D(s),), domain=SPEED_DOMAIN)
def arc_length_rate():
    """ds/dt = |ṙ| = v."""
    return sp.Eq(D(s), sp.sqrt(pythagorean(position().diff(t).dot(position().diff(t)))))


@derives("brepta1953:quadratic-drag-separated-ds", uses=("brepta1953:quadratic-drag-ode",),
         unknowns=(D(psi, 2),))
def quadratic_drag_ds():
    """d ln(ρ²ψ̇) = −β ds, with v dt = ds."""
    eq = derived("brepta1953:quadratic-drag-ode")
    return sp.Eq(eq.lhs.subs(v, D(s)), 0)


@derives("brepta1953:quadratic-drag-integrated", unknowns=(B,))
def quadratic_drag_integrated():
    """ln(ρ²ψ̇) = −βs + ln B: the law integrates in the arc length s, with B = ρ²ψ̇ at s = 0."""
    ssym = sp.Symbol("s_", nonnegative=True)
    sol = angular_momentum_solution(-beta, ssym, B).subs(ssym, s)
    return sp.Eq(sp.log(ANGULAR_MOMENTUM), sp.expand_log(sp.log(sol), force=True))


@derives("brepta1953:5", unknowns=(D(psi),))
def angular_momentum_quadratic():
    """ρ²ψ̇ = B e^{−βs}."""
    ssym = sp.Symbol("s_", nonnegative=True)
    return sp.Eq(ANGULAR_MOMENTUM, angular_momentum_solution(-beta, ssym, B).subs(ssym, s))
