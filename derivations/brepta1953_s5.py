"""[Brepta1953] section 5: the spherical pendulum (small swings) under quadratic drag R = mβv².

Newton's law in the tangent plane: r̈ = −Ω² r − βv ṙ with v = |ṙ| and Ω² = g/l.  The text

* combines the two components into a relation for the moment of velocity (23);
* linearizes in β: the velocities on the right are those of the undamped ellipse (24), (25),
  which gives two *forced* oscillators with the forcing f(t) = βuΩ·sin Ωt·V(t) for x and
  −βv₀·cos Ωt·V(t) for y, V(t)² = u² sin² Ωt + v₀² cos² Ωt the squared ideal speed (u = R₀Ω);
* solves them by variation of constants: x = A sin Ωt + B cos Ωt with A' sin + B' cos = 0;
  A and D integrate in closed form (substitution V²), B and C are elliptic integrals;
* substitutes Ωt = φ = π/2 − z, sin z = ζ and reduces to Legendre's F, E, K.

The substitution sin z = ζ is one-to-one only for −π/2 ≤ z ≤ π/2, i.e. the first half-period
0 ≤ Ωt ≤ π: √(1 − ζ²) stands for cos z, which changes sign every half-period, and the Jacobi
form F(k, ζ) = F(asin ζ | k²) is periodic in t where the true B(t) decreases steadily (B' ≤ 0).
The derivations therefore keep the amplitude z = π/2 − Ωt itself: the antiderivatives
a F(z | k²) + b E(z | k²) + c sin z cos z √(1 − k² sin² z) are found by matching coefficients
of their derivative with the integrand (a proof by differentiation, valid for every real z since
Legendre's F and E are the continuous, quasi-periodic extensions F(z + π) = F(z) + 2K).  The
printed ζ forms are then compared with these over four periods (ζ = cos Ωt, eq. 29).

Where the print keeps an integral in t or z, the derived side is the integral of the variation of
constants itself (transformed by the same substitution), evaluated by quadrature on the same nodes.
For the printed integrals in ζ, whose upper limit is ζ = cos Ωt, the domains below declare the
upper limit of the printed integral (the limit tuple (ζ, 1, ζ) → (ζ, 1, cos Ωt)): the integration
variable keeps its name, only the limit is tied to time.
"""

from __future__ import annotations

import sympy as sp

from quasicentral.domain import Domain
from quasicentral.registry import derived, derives
from quasicentral.symbols import (
    B as B_sym, C1, C2, C3, C4, D, D1, D2, D_, Omega, R0, A as A_sym, C as C_sym, R, S, alpha,
    ax, ay, beta, g, k, l, m, psi, rho, s, t, th, u, v, v0, x, y, z, zeta,
)

# --- domains ---------------------------------------------------------------------------------
SPEED = {v: sp.sqrt(D(x) ** 2 + D(y) ** 2)}  # v is the speed |ṙ|
K_DEF = {k: sp.sqrt(u**2 - v0**2) / u}  # k² = (u² − v₀²)/u², the paper's modulus
PAPER_K = (u > v0,)  # "za předpokladu, že u > v_o" (0 < k² < 1)
ZETA_OF_T = {zeta: sp.cos(Omega * t)}  # (29)
#: the printed integrals in ζ run to ζ = cos Ωt: tie the upper limit (not the variable) to time
ZETA_LIMITS = {sp.Tuple(zeta, 1, zeta): sp.Tuple(zeta, 1, sp.cos(Omega * t)),
               sp.Tuple(zeta, 0, zeta): sp.Tuple(zeta, 0, sp.cos(Omega * t))}
#: z = π/2 − Ωt over the default four periods 0 ≤ Ωt ≤ 8π
Z_RANGE = {z: (sp.pi / 2 - 8 * sp.pi, sp.pi / 2)}

SPEED_DOMAIN = Domain.of(definitions=SPEED)
ELLIPTIC_T = Domain.of(definitions={**ZETA_OF_T, **K_DEF}, constraints=PAPER_K)
ELLIPTIC_ZETA_INTEGRALS = Domain.of(definitions={**ZETA_LIMITS, **K_DEF}, constraints=PAPER_K)
Z_DOMAIN = Domain.of(ranges=Z_RANGE)
Z_K_DOMAIN = Domain.of(ranges=Z_RANGE, definitions=K_DEF, constraints=PAPER_K)
K_ONLY = Domain.of(definitions=K_DEF, constraints=PAPER_K)
CONICAL = Domain.of(definitions={v0: R0 * Omega})  # R₀Ω = v₀

THETA = Omega * t  # the paper's φ = Ωt
Z_OF_T = sp.pi / 2 - THETA  # the amplitude z = π/2 − Ωt
R1 = sp.Symbol("R_1")  # the catalog's plain Symbol('R_1') of (33)
Af, Bf, Cf, Df = (sp.Function(name) for name in "ABCD")  # the varied constants A(t), …, D(t)


def _eq(lhs, rhs) -> sp.Eq:
    return sp.Eq(lhs, rhs, evaluate=False)


# --- Newton's law in the tangent plane -------------------------------------------------------
def central_acceleration() -> sp.Matrix:
    """−S e_ρ / m with S = m(g/l)ρ (12): the central force per unit mass, in x, y."""
    e_rho = sp.Matrix([sp.cos(psi), sp.sin(psi)])
    polar = (-g / l * rho * e_rho).subs({rho: sp.sqrt(x**2 + y**2), psi: sp.atan2(y, x)})
    return sp.simplify(polar)


def drag_acceleration() -> sp.Matrix:
    """−R v̂ / m with R = mβv² (quadratic-drag-law) and v̂ = ṙ/v."""
    law = derived("brepta1953:quadratic-drag-law")
    return -(law.rhs / m) * sp.Matrix([D(x), D(y)]) / v


def acceleration_field() -> sp.Matrix:
    return central_acceleration() + drag_acceleration()


@derives("brepta1953:a_x-equation", uses=("brepta1953:quadratic-drag-law",), unknowns=(D(x, 2), ax))
def a_x_equation():
    """ẍ = −(g/l)x − βv ẋ =: a_x (central force (12) plus the drag −mβv² ṙ/v, per unit mass)."""
    a = acceleration_field()[0]
    return [sp.Eq(D(x, 2), a), sp.Eq(ax, a)]


@derives("brepta1953:a_y-equation", uses=("brepta1953:quadratic-drag-law",), unknowns=(D(y, 2), ay))
def a_y_equation():
    """ÿ = −(g/l)y − βv ẏ =: a_y."""
    a = acceleration_field()[1]
    return [sp.Eq(D(y, 2), a), sp.Eq(ay, a)]


def acceleration_model() -> dict:
    return {ax: derived("brepta1953:a_x-equation")[1].rhs, ay: derived("brepta1953:a_y-equation")[1].rhs}


@derives("brepta1953:moment-combination", mode="substitute",
         uses=("brepta1953:a_x-equation", "brepta1953:a_y-equation"))
def moment_combination():
    """a_x ẏ − a_y ẋ = −(g/l)(xẏ − yẋ): the drag terms −βv(ẋẏ − ẏẋ) cancel (model: a_x, a_y)."""
    return acceleration_model()


def cartesian_moment() -> sp.Expr:
    """ρ²ψ̇ in Cartesian coordinates: x ẏ − y ẋ (checked by substituting x = ρ cos ψ, y = ρ sin ψ)."""
    L = x * D(y) - y * D(x)
    polar = {x: rho * sp.cos(psi), y: rho * sp.sin(psi)}
    assert sp.simplify(L.subs(polar).doit() - rho**2 * D(psi).doit()) == 0
    return L


@derives("brepta1953:23", mode="substitute",
         uses=("brepta1953:moment-combination", "brepta1953:5"))
def moment_law_quadratic():
    """a_x ẏ − a_y ẋ = −(g/l) B e^{−βs}: the moment xẏ − yẋ = ρ²ψ̇ obeys (5), ρ²ψ̇ = B e^{−βs}
    (s the arc length).  Model: a_x, a_y from the equations of motion and B solved from (5)."""
    five = derived("brepta1953:5")  # Eq(rho**2*psi', B*exp(-beta*s))
    Bval = sp.solve(sp.Eq(cartesian_moment(), five.rhs), B_sym)[0]
    return {**acceleration_model(), B_sym: Bval}


# --- the undamped motion ------------------------------------------------------------------------
def undamped(f, c_sin, c_cos) -> sp.Expr:
    """dsolve f'' = −(g/l) f with f(0) = c_cos, f'(0) = Ω c_sin (Ω := √(g/l), Omega-definition)."""
    ff = sp.Function("f")
    w2 = derived("brepta1953:Omega-definition").rhs ** 2
    sol = sp.dsolve(ff(t).diff(t, 2) + w2 * ff(t), ff(t),
                    ics={ff(0): c_cos, ff(t).diff(t).subs(t, 0): Omega * c_sin}).rhs
    return sp.simplify(sol.subs(g, Omega**2 * l))  # g/l = Ω²


@derives("brepta1953:Omega-definition", unknowns=(Omega,))
def omega_definition():
    """Ω = √(g/l): the angular frequency of ẍ = −(g/l)x (roots ±iΩ of λ² + g/l = 0)."""
    lam = sp.Symbol("lambda")
    roots = sp.solve(lam**2 + g / l, lam)
    return sp.Eq(Omega, sp.Abs(sp.im(roots[0])))


@derives("brepta1953:ideal-general-solution", uses=("brepta1953:Omega-definition",), unknowns=(x, y))
def ideal_general_solution():
    """x = C₁ sin Ωt + C₂ cos Ωt, y = D₁ sin Ωt + D₂ cos Ωt (dsolve, constants named by their
    initial data: x(0) = C₂, ẋ(0) = ΩC₁, …)."""
    return [sp.Eq(x, undamped(x, C1, C2)), sp.Eq(y, undamped(y, D1, D2))]


@derives("brepta1953:initial-conditions",
         unknowns=(x.subs(t, 0), y.subs(t, 0), D(x).subs(t, 0), D(y).subs(t, 0)))
def initial_conditions():
    """x(0) = R₀, y(0) = 0, ẋ(0) = 0, ẏ(0) = v₀: the start of fig. 6 (ρ = R₀, ψ = 0, velocity v₀
    perpendicular to the radius: ρ̇ = 0, ρψ̇ = v₀), converted with x = ρ cos ψ, y = ρ sin ψ."""
    P, Q = sp.Function("P"), sp.Function("Q")  # ρ(t), ψ(t)
    X, Y = P(t) * sp.cos(Q(t)), P(t) * sp.sin(Q(t))
    start = {P(t).diff(t): 0, Q(t).diff(t): v0 / R0}
    at0 = {P(t): R0, Q(t): 0}

    def value(e):
        return sp.simplify(e.subs(start).subs(at0))

    return [sp.Eq(x.subs(t, 0), value(X)), sp.Eq(y.subs(t, 0), value(Y)),
            sp.Eq(D(x).subs(t, 0), value(X.diff(t))), sp.Eq(D(y).subs(t, 0), value(Y.diff(t)))]


@derives("brepta1953:initial-conditions-conical", uses=("brepta1953:initial-conditions",),
         unknowns=(x.subs(t, 0), y.subs(t, 0), D(x).subs(t, 0), D(y).subs(t, 0)))
def initial_conditions_conical():
    """The same start x = R₀, y = 0, ẋ = 0, ẏ = v₀ at t = 0."""
    return derived("brepta1953:initial-conditions")


def initial_values() -> list:
    return [r.rhs for r in derived("brepta1953:initial-conditions")]


@derives("brepta1953:24", uses=("brepta1953:initial-conditions",), unknowns=(x,))
def ideal_x():
    """x = R₀ cos Ωt (x(0) = R₀, ẋ(0) = 0)."""
    x0, _, xd0, _ = initial_values()
    return sp.Eq(x, undamped(x, xd0 / Omega, x0))


@derives("brepta1953:25", uses=("brepta1953:initial-conditions",), unknowns=(y,))
def ideal_y():
    """y = (v₀/Ω) sin Ωt (y(0) = 0, ẏ(0) = v₀)."""
    _, y0, _, yd0 = initial_values()
    return sp.Eq(y, undamped(y, yd0 / Omega, y0))


@derives("brepta1953:force-x", uses=("brepta1953:quadratic-drag-law",), unknowns=(D(x, 2),))
def force_x():
    """m ẍ = −S cos ψ − R cos α (14) with S = m(g/l)ρ, ρ cos ψ = x, R = mβv²."""
    law = derived("brepta1953:quadratic-drag-law")
    Fx = -m * g / l * rho * sp.cos(psi) - law.rhs * sp.cos(alpha)
    Fx = Fx.subs(rho * sp.cos(psi), x)
    return sp.Eq(D(x, 2), Fx / m)


@derives("brepta1953:force-y", uses=("brepta1953:quadratic-drag-law",), unknowns=(D(y, 2),))
def force_y():
    """m ÿ = −S sin ψ − R sin α (15) with ρ sin ψ = y."""
    law = derived("brepta1953:quadratic-drag-law")
    Fy = -m * g / l * rho * sp.sin(psi) - law.rhs * sp.sin(alpha)
    Fy = Fy.subs(rho * sp.sin(psi), y)
    return sp.Eq(D(y, 2), Fy / m)


@derives("brepta1953:direction-cosines", unknowns=(sp.cos(alpha), sp.sin(alpha)), domain=SPEED_DOMAIN)
def direction_cosines():
    """(cos α, sin α) = ṙ/|ṙ|: α is the direction of the velocity (fig. 5)."""
    vel = sp.Matrix([D(x), D(y)])
    unit = vel / sp.sqrt(vel.dot(vel))
    return [sp.Eq(sp.cos(alpha), unit[0]), sp.Eq(sp.sin(alpha), unit[1])]


@derives("brepta1953:speed", unknowns=(D(s), D(s)), domain=SPEED_DOMAIN)
def speed():
    """ds/dt = |ṙ| (s = ∫₀ᵗ |ṙ| dt, the arc length); v is the same speed |ṙ|."""
    tau = sp.Symbol("tau", nonnegative=True)
    integrand = sp.sqrt(D(x) ** 2 + D(y) ** 2).subs(t, tau)
    rate = sp.Integral(integrand, (tau, 0, t)).diff(t)
    return [sp.Eq(D(s), rate), sp.Eq(D(s), rate)]


def equation_of_motion(i: int) -> sp.Eq:
    """(26)/(27): the component i of r̈ = −(g/l) r − β|ṙ| ṙ, with g/l = Ω²."""
    a = acceleration_field()[i].subs(SPEED).subs(g, Omega**2 * l)
    return sp.Eq((D(x, 2), D(y, 2))[i], sp.expand(a))


@derives("brepta1953:26", uses=("brepta1953:a_x-equation", "brepta1953:speed"), unknowns=(D(x, 2),))
def eq26():
    """ẍ = −Ω²x − βẋ √(ẋ² + ẏ²)."""
    return equation_of_motion(0)


@derives("brepta1953:27", uses=("brepta1953:a_y-equation", "brepta1953:speed"), unknowns=(D(y, 2),))
def eq27():
    """ÿ = −Ω²y − βẏ √(ẋ² + ẏ²)."""
    return equation_of_motion(1)


@derives("brepta1953:ideal-velocities", uses=("brepta1953:24", "brepta1953:25"), unknowns=(D(x), D(y)))
def ideal_velocities():
    """ẋ = −R₀Ω sin Ωt, ẏ = v₀ cos Ωt: (24), (25) differentiated."""
    return [sp.Eq(D(x), derived("brepta1953:24").rhs.diff(t)),
            sp.Eq(D(y), derived("brepta1953:25").rhs.diff(t))]


def ideal_velocity_map() -> dict:
    return {r.lhs: r.rhs for r in derived("brepta1953:ideal-velocities")}


def forced(i: int) -> sp.Eq:
    """(26)/(27) with the velocities of the ellipse substituted (first order in β)."""
    eq = derived(("brepta1953:26", "brepta1953:27")[i])
    return sp.Eq(eq.lhs, eq.rhs.subs(ideal_velocity_map()))


@derives("brepta1953:forced-x", uses=("brepta1953:26", "brepta1953:ideal-velocities"), unknowns=(D(x, 2),))
def forced_x():
    """ẍ = −Ω²x + βR₀Ω sin Ωt √(R₀²Ω² sin² Ωt + v₀² cos² Ωt)."""
    return forced(0)


@derives("brepta1953:forced-y", uses=("brepta1953:27", "brepta1953:ideal-velocities"), unknowns=(D(y, 2),))
def forced_y():
    """ÿ = −Ω²y − βv₀ cos Ωt √(R₀²Ω² sin² Ωt + v₀² cos² Ωt)."""
    return forced(1)


def forcing(i: int) -> sp.Expr:
    """The right side of the forced equation less −Ω²·(x or y)."""
    eq = derived(("brepta1953:forced-x", "brepta1953:forced-y")[i])
    return sp.expand(eq.rhs + Omega**2 * (x, y)[i])


@derives("brepta1953:homogeneous-solution", uses=("brepta1953:Omega-definition",), unknowns=(x, y))
def homogeneous_solution():
    """x = A sin Ωt + B cos Ωt, y = C sin Ωt + D cos Ωt (dsolve of ẍ + Ω²x = 0)."""
    return [sp.Eq(x, undamped(x, A_sym, B_sym)), sp.Eq(y, undamped(y, C_sym, D_))]


# --- variation of constants ------------------------------------------------------------------
def lagrange(P, Q, i: int) -> list:
    """x = P(t) sin Ωt + Q(t) cos Ωt into the forced equation i: Lagrange's condition (the part
    of ẋ carried by P', Q' vanishes) and the remaining equation Ω(P' cos − Q' sin) = f."""
    hom = derived("brepta1953:homogeneous-solution")[i].rhs
    c_sin, c_cos = ((A_sym, B_sym), (C_sym, D_))[i]
    X = hom.subs({c_sin: P(t), c_cos: Q(t)})
    frozen = hom.diff(t).subs({c_sin: P(t), c_cos: Q(t)})  # ẋ with P, Q held constant
    condition = sp.expand(X.diff(t) - frozen)
    second = frozen.diff(t)  # ẍ once the condition holds
    residual = sp.expand(second + Omega**2 * X)
    return [sp.Eq(condition, 0), sp.Eq(residual, forcing(i))]


@derives("brepta1953:AB-variation", uses=("brepta1953:homogeneous-solution", "brepta1953:forced-x"),
         unknowns=(Af(t).diff(t), Af(t).diff(t)))
def ab_variation():
    """A' sin Ωt + B' cos Ωt = 0, Ω(A' cos Ωt − B' sin Ωt) = βR₀Ω sin Ωt V(t)."""
    return lagrange(Af, Bf, 0)


@derives("brepta1953:CD-variation", uses=("brepta1953:homogeneous-solution", "brepta1953:forced-y"),
         unknowns=(Cf(t).diff(t), Cf(t).diff(t)))
def cd_variation():
    """C' sin Ωt + D' cos Ωt = 0, Ω(C' cos Ωt − D' sin Ωt) = −βv₀ cos Ωt V(t)."""
    return lagrange(Cf, Df, 1)


def varied_rates(i: int) -> tuple[sp.Expr, sp.Expr]:
    """(P', Q') from the 2×2 system of the variation of constants (sympy solve)."""
    P, Q = ((Af, Bf), (Cf, Df))[i]
    eqs = derived(("brepta1953:AB-variation", "brepta1953:CD-variation")[i])
    p, q = sp.symbols("p q")
    sub = {P(t).diff(t): p, Q(t).diff(t): q}
    sol = sp.solve([e.lhs.subs(sub) - e.rhs for e in eqs], [p, q], dict=True)[0]
    return sp.trigsimp(sp.factor(sol[p])), sp.trigsimp(sp.factor(sol[q]))


def speed_squared() -> sp.Expr:
    """V² = ẋ² + ẏ² on the ellipse = R₀²Ω² sin² Ωt + v₀² cos² Ωt."""
    vel = ideal_velocity_map()
    return sp.expand(vel[D(x)] ** 2 + vel[D(y)] ** 2)


def integrate_by_speed(rate: sp.Expr) -> sp.Expr:
    """∫ rate dt for rate = h(V²)·d(V²)/dt (the substitution W = V²); returns the antiderivative
    H(V²) with no constant, verified by differentiation."""
    W = sp.Symbol("W", positive=True)
    V2 = speed_squared()
    h = sp.simplify(rate.subs(sp.sqrt(V2), sp.sqrt(W)) / V2.diff(t))
    assert t not in h.free_symbols, h
    H = sp.integrate(h, W).subs(W, V2)
    assert sp.simplify(H.diff(t) - rate) == 0
    return H


def paper_radicand(expr: sp.Expr) -> sp.Expr:
    """Write V² = R₀²Ω² sin² + v₀² cos² as R₀²Ω² − (R₀²Ω² − v₀²) cos² Ωt (sin² = 1 − cos²)."""
    V2 = speed_squared()
    c2 = sp.Symbol("c2")
    alt = sp.expand(V2.subs(sp.sin(THETA) ** 2, 1 - c2)).subs(c2, sp.cos(THETA) ** 2)
    assert sp.simplify(alt - V2) == 0
    return expr.subs(V2, alt)


@derives("brepta1953:A-integral", uses=("brepta1953:AB-variation",), unknowns=(A_sym,))
def a_integral():
    """A = βR₀/(3Ω(R₀²Ω² − v₀²)) [R₀²Ω² − (R₀²Ω² − v₀²) cos² Ωt]^{3/2} + C₁:
    A' = βR₀ sin Ωt cos Ωt V = βR₀/(2Ω(R₀²Ω² − v₀²)) √W dW/dt, W = V²."""
    Ap, _ = varied_rates(0)
    return sp.Eq(A_sym, integrate_by_speed(Ap) + C1)


@derives("brepta1953:D-integral", uses=("brepta1953:CD-variation",), unknowns=(D_,))
def d_integral():
    """D = βv₀/(3Ω²(u² − v₀²)) [u² − (u² − v₀²) cos² Ωt]^{3/2} + C₄ (same substitution)."""
    _, Dp = varied_rates(1)
    return sp.Eq(D_, integrate_by_speed(Dp) + C4)


def t_integral(rate: sp.Expr) -> sp.Expr:
    """∫₀ᵗ rate dt, an unevaluated Integral (the variable keeps the name t, as printed)."""
    c, f = sp.factor_terms(rate).as_independent(t)
    return c * sp.Integral(paper_radicand(f), (t, 0, t))


@derives("brepta1953:B-integral-t", uses=("brepta1953:AB-variation",), unknowns=(B_sym,))
def b_integral_t():
    """B = −βR₀ ∫₀ᵗ sin² Ωt √(R₀²Ω² − (R₀²Ω² − v₀²) cos² Ωt) dt + C₂ (B' = −f sin Ωt/Ω; B(0) = C₂)."""
    _, Bp = varied_rates(0)
    return sp.Eq(B_sym, t_integral(Bp) + C2)


@derives("brepta1953:C-integral-t", uses=("brepta1953:CD-variation",), unknowns=(C_sym,))
def c_integral_t():
    """C = −(βv₀/Ω) ∫₀ᵗ cos² Ωt √(u² − (u² − v₀²) cos² Ωt) dt + C₃ (C' = f_y cos Ωt/Ω)."""
    Cp, _ = varied_rates(1)
    return sp.Eq(C_sym, t_integral(Cp) + C3)


# --- the substitutions φ = Ωt = π/2 − z, sin z = ζ ------------------------------------------------
@derives("brepta1953:substitution-theta-z", uses=("brepta1953:B-integral-t",), unknowns=(th, th))
def substitution_theta_z():
    """φ = Ωt (the argument of the trigonometric functions in B's integrand) and φ = π/2 − z
    (the root of sin φ = cos z that maps the lower limit t = 0 to z = π/2)."""
    integral = derived("brepta1953:B-integral-t").rhs.atoms(sp.Integral).pop()
    args = {a.args[0] for a in integral.function.atoms(sp.sin, sp.cos)}
    (phase,) = args
    roots = sp.solve(sp.Eq(sp.sin(th), sp.cos(z)), th)
    (root,) = [r for r in roots if r.subs(z, sp.pi / 2) == 0]
    return [sp.Eq(th, phase), sp.Eq(th, root)]


def to_amplitude(expr: sp.Expr, upper: sp.Expr | None = None) -> sp.Expr:
    """Every ∫₀ᵀ h(t) dt in expr → ∫_{π/2}^{π/2−ΩT} h((π/2 − z)/Ω) (−dz/Ω): the substitution
    Ωt = φ = π/2 − z.  ``upper`` replaces π/2 − ΩT when given (the printed upper limit z)."""

    def change(integral):
        (var, lo, hi), = integral.limits
        assert var == t and lo == 0
        h = integral.function.subs(t, (sp.pi / 2 - z) / Omega)
        top = sp.pi / 2 - Omega * hi if upper is None else upper
        c, f = sp.factor_terms(-h / Omega).as_independent(z)
        return c * sp.Integral(f, (z, sp.pi / 2, top))

    return expr.replace(lambda e: isinstance(e, sp.Integral), change)


@derives("brepta1953:B-integral-z", uses=("brepta1953:B-integral-t", "brepta1953:substitution-theta-z"),
         unknowns=(B_sym,), domain=Z_DOMAIN)
def b_integral_z():
    """B = (βR₀/Ω) ∫_{π/2}^{z} cos² z √(u² − (u² − v₀²) sin² z) dz + C₂ (t = (π/2 − z)/Ω)."""
    eq = derived("brepta1953:B-integral-t")
    return sp.Eq(B_sym, to_amplitude(eq.rhs, upper=z))


@derives("brepta1953:u-definition", uses=("brepta1953:ideal-velocities",), unknowns=(u,))
def u_definition():
    """u = R₀Ω, the amplitude of ẋ on the ellipse (ẋ = −u sin Ωt)."""
    xd = derived("brepta1953:ideal-velocities")[0].rhs
    return sp.Eq(u, -xd.coeff(sp.sin(THETA)))


@derives("brepta1953:k2-definition", unknowns=(k**2,))
def k2_definition():
    """k² = (u² − v₀²)/u²: u² cos² z + v₀² sin² z = u²(1 − k² sin² z) for all z."""
    S2, k2 = sp.symbols("S2 k2")
    poly = sp.expand(u**2 * (1 - S2) + v0**2 * S2 - u**2 * (1 - k2 * S2))
    sol = sp.solve(sp.Poly(poly, S2).coeffs(), k2, dict=True)[0]
    return sp.Eq(k**2, sol[k2])


@derives("brepta1953:k2-definition-C", uses=("brepta1953:k2-definition",), unknowns=(k**2,))
def k2_definition_c():
    """k² = (u² − v₀²)/u² (the same modulus for C)."""
    return derived("brepta1953:k2-definition")


def modulus_form(expr: sp.Expr) -> sp.Expr:
    """Write the radicands with u = R₀Ω and v₀² = u²(1 − k²) (k2-definition): √(u²(1 − k² sin² z))
    = u √(1 − k² sin² z), and pull the constants out of the integrals."""
    v02 = sp.solve(derived("brepta1953:k2-definition"), v0**2)[0]

    def change(integral):
        f = integral.function.subs(R0, u / Omega).subs(v0**2, v02)
        f = f.replace(lambda e: isinstance(e, sp.Pow) and e.exp == sp.Rational(1, 2),
                      lambda e: sp.sqrt(sp.factor(sp.trigsimp(sp.expand(e.base)))))
        c, f = sp.factor_terms(f).as_independent(z)
        return c * sp.Integral(f, *integral.limits)

    return expr.replace(lambda e: isinstance(e, sp.Integral), change)


@derives("brepta1953:B-integral-k", uses=("brepta1953:B-integral-z", "brepta1953:k2-definition"),
         unknowns=(B_sym,), domain=Z_K_DOMAIN)
def b_integral_k():
    """B = (βR₀u/Ω) ∫_{π/2}^{z} cos² z √(1 − k² sin² z) dz + C₂."""
    return sp.Eq(B_sym, modulus_form(derived("brepta1953:B-integral-z").rhs))


@derives("brepta1953:C-integral-z", uses=("brepta1953:C-integral-t", "brepta1953:substitution-theta-z",
                                        "brepta1953:k2-definition-C"),
         unknowns=(C_sym,), domain=Z_K_DOMAIN)
def c_integral_z():
    """C = (βv₀u/Ω²) ∫_{π/2}^{z} sin² z √(1 − k² sin² z) dz + C₃ (t = (π/2 − z)/Ω, then k²)."""
    eq = derived("brepta1953:C-integral-t")
    return sp.Eq(C_sym, modulus_form(to_amplitude(eq.rhs, upper=z)))
