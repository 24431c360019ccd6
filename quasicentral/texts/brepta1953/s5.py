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
Where the print has ζ (its integrals run to ζ = cos Ωt, its closed forms take ζ = cos Ωt), the
derived side is the same step taken in the amplitude, with its integrals in closed Legendre form
(exact and cheap at every t); the domains tie the printed upper limit ζ to time by declaring the
limit tuple (ζ, 1, ζ) → (ζ, 1, cos Ωt) — the integration variable keeps its name.  The closed
forms are compared with direct quadrature and with a DOP853 integration of the linearized
equations over five periods in tests/test_brepta1953_s5.py.
"""

from __future__ import annotations

import sympy as sp

from quasicentral.notation.domain import Domain
from quasicentral.engine.registry import derived, derives, shared
from quasicentral.notation.identities import pythagorean
from quasicentral.notation.symbols import D
from quasicentral.engine.texts import symbols_of

#: dsolve's method for a linear ODE with constant coefficients (named: sympy would otherwise
#: classify the equation against every method first)
LINEAR = "nth_linear_constant_coeff_homogeneous"

S_ = symbols_of(__file__)  # this text's declared symbols (text.toml)
(A_sym, B_sym, C_sym, C1, C2, C3, C4, D1, D2, D_, Omega, R0, alpha, ax, ay, g, k, l, m, psi, rho, s, t, th, u, v,
 v0, x, y, z, zeta) = S_("A B C C1 C2 C3 C4 D1 D2 D_ Omega R0 alpha ax ay g k l m psi rho s t th u v v0 x y z zeta")

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
    assert pythagorean(L.subs(polar).doit() - rho**2 * D(psi).doit()) == 0
    return L


@derives("brepta1953:23", mode="substitute",
         uses=("brepta1953:5", "brepta1953:a_x-equation", "brepta1953:a_y-equation"))
def moment_law_quadratic():
    """a_x ẏ − a_y ẋ = −(g/l) B e^{−βs}: the moment xẏ − yẋ = ρ²ψ̇ obeys (5), ρ²ψ̇ = B e^{−βs}
    (s the arc length).  Model: a_x, a_y from the equations of motion and B solved from (5)."""
    five = derived("brepta1953:5")  # Eq(rho**2*psi', B*exp(-beta*s))
    Bval = sp.solve(sp.Eq(cartesian_moment(), five.rhs), B_sym)[0]
    return {**acceleration_model(), B_sym: Bval}


# --- the undamped motion ------------------------------------------------------------------------
@shared
def undamped_initial_value() -> tuple[sp.Expr, sp.Symbol, sp.Symbol]:
    """dsolve f'' = −(g/l) f with f(0) = b, f'(0) = Ω a (Ω := √(g/l), Omega-definition), for
    placeholders a and b: solved once for every pair of initial data."""
    ff = sp.Function("f")
    a, b = sp.Dummy("a"), sp.Dummy("b")
    w2 = derived("brepta1953:Omega-definition").rhs ** 2
    sol = sp.dsolve(ff(t).diff(t, 2) + w2 * ff(t), ff(t),
                    ics={ff(0): b, ff(t).diff(t).subs(t, 0): Omega * a}, hint=LINEAR).rhs
    return sol.subs(g, Omega**2 * l), a, b  # g/l = Ω²


def undamped(c_sin, c_cos) -> sp.Expr:
    """The undamped motion with f(0) = c_cos, f'(0) = Ω c_sin (:func:`undamped_initial_value`)."""
    sol, a, b = undamped_initial_value()
    return sp.expand(sol.xreplace({a: c_sin, b: c_cos}))


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
    return [sp.Eq(x, undamped(C1, C2)), sp.Eq(y, undamped(D1, D2))]


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


@derives("brepta1953:24", uses=("brepta1953:Omega-definition", "brepta1953:initial-conditions"), unknowns=(x,))
def ideal_x():
    """x = R₀ cos Ωt (x(0) = R₀, ẋ(0) = 0)."""
    x0, _, xd0, _ = initial_values()
    return sp.Eq(x, undamped(xd0 / Omega, x0))


@derives("brepta1953:25", uses=("brepta1953:Omega-definition", "brepta1953:initial-conditions"), unknowns=(y,))
def ideal_y():
    """y = (v₀/Ω) sin Ωt (y(0) = 0, ẏ(0) = v₀)."""
    _, y0, _, yd0 = initial_values()
    return sp.Eq(y, undamped(yd0 / Omega, y0))


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


@derives("brepta1953:speed", unknowns=(D(s),), domain=SPEED_DOMAIN)
def speed():
    """ds/dt = |ṙ| (s = ∫₀ᵗ |ṙ| dt, the arc length); v is the same speed |ṙ| (each printed
    row is compared with it)."""
    tau = sp.Symbol("tau", nonnegative=True)
    integrand = sp.sqrt(D(x) ** 2 + D(y) ** 2).subs(t, tau)
    return sp.Eq(D(s), sp.Integral(integrand, (tau, 0, t)).diff(t))


def equation_of_motion(i: int) -> sp.Eq:
    """(26)/(27): the component i of r̈ = −(g/l) r − β|ṙ| ṙ, with g/l = Ω²."""
    a = acceleration_field()[i].subs(SPEED).subs(g, Omega**2 * l)
    return sp.Eq((D(x, 2), D(y, 2))[i], sp.expand(a))


@derives("brepta1953:26", uses=("brepta1953:quadratic-drag-law",), unknowns=(D(x, 2),))
def eq26():
    """ẍ = −Ω²x − βẋ √(ẋ² + ẏ²)."""
    return equation_of_motion(0)


@derives("brepta1953:27", uses=("brepta1953:quadratic-drag-law",), unknowns=(D(y, 2),))
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
    return [sp.Eq(x, undamped(A_sym, B_sym)), sp.Eq(y, undamped(C_sym, D_))]


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


@shared
def varied_rates(i: int) -> tuple[sp.Expr, sp.Expr]:
    """(P', Q') from the 2×2 system of the variation of constants (sympy solve; the ideal speed
    V = √V² is held as one symbol while solving)."""
    P, Q = ((Af, Bf), (Cf, Df))[i]
    eqs = derived(("brepta1953:AB-variation", "brepta1953:CD-variation")[i])
    p, q = sp.symbols("p q")
    V = sp.Symbol("V", positive=True)
    sub = {P(t).diff(t): p, Q(t).diff(t): q}
    system = [(e.lhs - e.rhs).subs(sub).subs(sp.sqrt(speed_squared()), V) for e in eqs]
    sol = sp.solve(system, [p, q], dict=True)[0]
    back = {V: sp.sqrt(speed_squared())}
    return sp.trigsimp(sp.factor(sol[p])).subs(back), sp.trigsimp(sp.factor(sol[q])).subs(back)


@shared
def speed_squared() -> sp.Expr:
    """V² = ẋ² + ẏ² on the ellipse = R₀²Ω² sin² Ωt + v₀² cos² Ωt."""
    vel = ideal_velocity_map()
    return sp.expand(vel[D(x)] ** 2 + vel[D(y)] ** 2)


@shared
def integrate_by_speed(rate: sp.Expr) -> sp.Expr:
    """∫ rate dt for rate = h(V²)·d(V²)/dt (the substitution W = V²); returns the antiderivative
    H(V²) with no constant, verified by differentiation.  The quotient and the check are
    rational in sin Ωt, cos Ωt once the double angles are expanded: cancelled first, so that
    simplify only tidies a small rational function of the constants."""
    W = sp.Symbol("W", positive=True)
    V2 = speed_squared()
    h = sp.simplify(sp.cancel(sp.expand_trig(rate.subs(sp.sqrt(V2), sp.sqrt(W)) / V2.diff(t))))
    assert t not in h.free_symbols, h
    H = sp.integrate(h, W).subs(W, V2)
    assert sp.cancel(sp.expand_trig(H.diff(t) - rate)) == 0
    return H


@derives("brepta1953:A-integral", uses=("brepta1953:AB-variation", "brepta1953:ideal-velocities"), unknowns=(A_sym,))
def a_integral():
    """A = βR₀/(3Ω(R₀²Ω² − v₀²)) [R₀²Ω² − (R₀²Ω² − v₀²) cos² Ωt]^{3/2} + C₁:
    A' = βR₀ sin Ωt cos Ωt V = βR₀/(2Ω(R₀²Ω² − v₀²)) √W dW/dt, W = V²."""
    Ap, _ = varied_rates(0)
    return sp.Eq(A_sym, integrate_by_speed(Ap) + C1)


@derives("brepta1953:D-integral", uses=("brepta1953:CD-variation", "brepta1953:ideal-velocities"), unknowns=(D_,))
def d_integral():
    """D = βv₀/(3Ω²(u² − v₀²)) [u² − (u² − v₀²) cos² Ωt]^{3/2} + C₄ (same substitution)."""
    _, Dp = varied_rates(1)
    return sp.Eq(D_, integrate_by_speed(Dp) + C4)


def t_integral(rate: sp.Expr) -> sp.Expr:
    """∫₀ᵗ rate dt, an unevaluated Integral (the variable keeps the name t, as printed)."""
    c, f = sp.factor_terms(rate).as_independent(t)
    return c * sp.Integral(f, (t, 0, t))


@derives("brepta1953:B-integral-t", uses=("brepta1953:AB-variation", "brepta1953:ideal-velocities"), unknowns=(B_sym,))
def b_integral_t():
    """B = −βR₀ ∫₀ᵗ sin² Ωt √(R₀²Ω² − (R₀²Ω² − v₀²) cos² Ωt) dt + C₂ (B' = −f sin Ωt/Ω; B(0) = C₂)."""
    _, Bp = varied_rates(0)
    return sp.Eq(B_sym, t_integral(Bp) + C2)


@derives("brepta1953:C-integral-t", uses=("brepta1953:CD-variation", "brepta1953:ideal-velocities"), unknowns=(C_sym,))
def c_integral_t():
    """C = −(βv₀/Ω) ∫₀ᵗ cos² Ωt √(u² − (u² − v₀²) cos² Ωt) dt + C₃ (C' = f_y cos Ωt/Ω)."""
    Cp, _ = varied_rates(1)
    return sp.Eq(C_sym, t_integral(Cp) + C3)


# --- the substitutions φ = Ωt = π/2 − z, sin z = ζ ------------------------------------------------
@derives("brepta1953:substitution-theta-z", uses=("brepta1953:B-integral-t",), unknowns=(th, th))
def substitution_theta_z():
    """φ = Ωt (the argument of the trigonometric functions in B's integrand) and φ = π/2 − z:
    of the linear maps φ = a + bz with sin φ ≡ cos z (a = π/2, b = ±1) the one that sends the
    lower limit t = 0 to z = π/2."""
    integral = derived("brepta1953:B-integral-t").rhs.atoms(sp.Integral).pop()
    (phase,) = {a.args[0] for a in integral.function.atoms(sp.sin, sp.cos)}
    a = sp.solve(sp.sin(th) - sp.cos(0), th)[0]  # sin a = cos 0
    maps = [a + b * z for b in (1, -1) if sp.simplify(sp.sin(a + b * z) - sp.cos(z)) == 0]
    (root,) = [mp for mp in maps if mp.subs(z, sp.pi / 2) == 0]
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


@derives("brepta1953:B-integral-z", uses=("brepta1953:B-integral-t",),
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
                      lambda e: sp.sqrt(sp.factor_terms(sp.expand(
                          sp.expand(e.base).subs(sp.cos(z) ** 2, 1 - sp.sin(z) ** 2)))))
        c, f = sp.factor_terms(f).as_independent(z)
        return c * sp.Integral(f, *integral.limits)

    return expr.replace(lambda e: isinstance(e, sp.Integral), change)


@derives("brepta1953:B-integral-k", uses=("brepta1953:B-integral-z", "brepta1953:k2-definition"),
         unknowns=(B_sym,), domain=Z_K_DOMAIN)
def b_integral_k():
    """B = (βR₀u/Ω) ∫_{π/2}^{z} cos² z √(1 − k² sin² z) dz + C₂."""
    return sp.Eq(B_sym, modulus_form(derived("brepta1953:B-integral-z").rhs))


@derives("brepta1953:C-integral-z", uses=("brepta1953:C-integral-t", "brepta1953:k2-definition"),
         unknowns=(C_sym,), domain=Z_K_DOMAIN)
def c_integral_z():
    """C = (βv₀u/Ω²) ∫_{π/2}^{z} sin² z √(1 − k² sin² z) dz + C₃ (t = (π/2 − z)/Ω, then k²)."""
    eq = derived("brepta1953:C-integral-t")
    return sp.Eq(C_sym, modulus_form(to_amplitude(eq.rhs, upper=z)))


# --- sin z = ζ and the reduction to Legendre's integrals -------------------------------------------
@derives("brepta1953:substitution-zeta", unknowns=(zeta,))
def substitution_zeta():
    """ζ = ∫ cos z dz = sin z (so that cos z dz = dζ, ζ = 0 at z = 0)."""
    return sp.Eq(zeta, sp.integrate(sp.cos(z), (z, 0, z)))


@derives("brepta1953:substitution-zeta-C", uses=("brepta1953:substitution-zeta",), unknowns=(zeta,))
def substitution_zeta_c():
    """ζ = sin z (the same substitution for C)."""
    return derived("brepta1953:substitution-zeta")


@derives("brepta1953:29", uses=("brepta1953:substitution-zeta", "brepta1953:substitution-theta-z"),
         unknowns=(zeta,))
def zeta_of_time():
    """ζ = sin z with z = π/2 − φ, φ = Ωt: ζ = cos Ωt."""
    phase, root = (r.rhs for r in derived("brepta1953:substitution-theta-z"))
    zz = sp.solve(sp.Eq(th, root), z)[0]
    return sp.Eq(zeta, derived("brepta1953:substitution-zeta").rhs.subs(z, zz).subs(th, phase))


def delta(var=z) -> sp.Expr:
    """Δ = √(1 − k² sin² z)."""
    return sp.sqrt(1 - k**2 * sp.sin(var) ** 2)


@shared
def legendre_antiderivative(integrand: sp.Expr, var=z) -> sp.Expr:
    """G with dG/dz = integrand for integrand = P(sin² z)/Δ, P a polynomial of degree ≤ 2:
    G = a F(z | k²) + b E(z | k²) + c sin z cos z Δ, the coefficients matched in dG/dz.
    Valid for every real z (F, E are Legendre's continuous forms in the amplitude)."""
    a, b, c, S_ = sp.symbols("a b c S_")
    G = (a * sp.elliptic_f(var, k**2) + b * sp.elliptic_e(var, k**2)
         + c * sp.sin(var) * sp.cos(var) * delta(var))
    residual = sp.expand((G.diff(var) - integrand) * delta(var))
    residual = sp.expand(residual.subs(sp.cos(var) ** 2, 1 - sp.sin(var) ** 2)).subs(sp.sin(var), S_)
    assert residual.free_symbols & {var} == set(), residual
    sol = sp.solve(sp.Poly(residual, S_).coeffs(), [a, b, c], dict=True)[0]
    G = G.subs(sol)
    check = sp.expand((G.diff(var) - integrand) * delta(var)).subs(sp.cos(var) ** 2, 1 - sp.sin(var) ** 2)
    assert sp.expand(check) == 0
    return G


def evaluate_amplitude_integrals(expr: sp.Expr) -> sp.Expr:
    """Replace every ∫_a^b h(z) dz in expr by G(b) − G(a) (legendre_antiderivative)."""

    def close(integral):
        (var, lo, hi), = integral.limits
        G = legendre_antiderivative(integral.function, var)
        return G.subs(var, hi) - G.subs(var, lo)

    return expr.replace(lambda e: isinstance(e, sp.Integral), close)


def along_motion(expr: sp.Expr) -> sp.Expr:
    """The upper limit z of the amplitude integrals set to z = π/2 − Ωt (the whole motion)."""
    return expr.replace(lambda e: isinstance(e, sp.Integral),
                        lambda e: sp.Integral(e.function, (e.limits[0][0], e.limits[0][1],
                                                           e.limits[0][2].subs(z, Z_OF_T))))


@shared
def amplitude_b() -> sp.Expr:
    """B(t) = (βR₀u/Ω) ∫_{π/2}^{π/2−Ωt} cos² z Δ dz + C₂ (B-integral-k along the motion)."""
    return along_motion(derived("brepta1953:B-integral-k").rhs)


@shared
def amplitude_c() -> sp.Expr:
    """C(t) = (βv₀u/Ω²) ∫_{π/2}^{π/2−Ωt} sin² z Δ dz + C₃ (C-integral-z along the motion)."""
    return along_motion(derived("brepta1953:C-integral-z").rhs)


def prefactor_and_integral(expr: sp.Expr, const) -> tuple[sp.Expr, sp.Integral]:
    rest = expr - const
    (integral,) = rest.atoms(sp.Integral)
    return sp.simplify(rest / integral), integral


def split_by_powers(expr: sp.Expr, const) -> sp.Expr:
    """∫ P(sin² z)/Δ dz → Σ_j p_j ∫ sin^{2j} z/Δ dz (the integrand with Δ moved to the
    denominator, expanded in powers of sin z)."""
    pre, integral = prefactor_and_integral(expr, const)
    (var, lo, hi), = integral.limits
    S_ = sp.Symbol("S_")
    P = sp.expand((integral.function * delta(var)).subs(sp.cos(var) ** 2, 1 - sp.sin(var) ** 2))
    P = sp.Poly(P.subs(sp.sin(var), S_), S_)
    total = sum(coef * sp.Integral(sp.sin(var) ** mon[0] / delta(var), (var, lo, hi))
                for mon, coef in zip(P.monoms(), P.coeffs()))
    return sp.expand(pre * total) + const


def split_limits(expr: sp.Expr) -> sp.Expr:
    """∫_{π/2}^{Z} = ∫_0^{Z} − ∫_0^{π/2} for every amplitude integral (the complete parts are
    the printed ∫_0^1 in ζ: on [0, π/2] the substitution ζ = sin z is one-to-one)."""

    def split(integral):
        (var, lo, hi), = integral.limits
        f = integral.function
        return sp.Integral(f, (var, 0, hi)) - sp.Integral(f, (var, 0, sp.pi / 2))

    return expr.replace(lambda e: isinstance(e, sp.Integral) and e.limits[0][1] == sp.pi / 2, split)


@shared
def closed(expr: sp.Expr) -> sp.Expr:
    """The amplitude integrals of ``expr`` in Legendre form (evaluate_amplitude_integrals), u = R₀Ω."""
    return evaluate_amplitude_integrals(expr).subs(u, R0 * Omega)


# The printed steps in ζ, derived along the whole motion: each is the same step taken in the
# amplitude z (where ζ = sin z, √(1 − ζ²) = cos z), its integrals given in closed Legendre form so
# that they are exact and cheap at every t.  The print's ζ-integrals agree for 0 ≤ Ωt ≤ π only.
@shared
def b_steps() -> dict[str, sp.Expr]:
    """B along the motion after each printed step (amplitude integrals, not yet evaluated)."""
    whole = amplitude_b()
    split = split_by_powers(whole, C2).subs(u, R0 * Omega)
    return {"zeta": whole, "split": split, "split-limits": split_limits(split)}


@shared
def c_steps() -> dict[str, sp.Expr]:
    """C along the motion after each printed step."""
    whole = amplitude_c()
    split = split_by_powers(whole, C3).subs(u, R0 * Omega)
    return {"zeta": whole, "split": split, "split-limits": split_limits(split)}


@derives("brepta1953:B-integral-zeta", uses=("brepta1953:B-integral-k",),
         unknowns=(B_sym,), domain=ELLIPTIC_ZETA_INTEGRALS)
def b_integral_zeta():
    """B = (βR₀u/Ω) ∫_{π/2}^{z} cos² z Δ dz + C₂ with z = π/2 − Ωt over the whole motion (in closed
    form).  With ζ = sin z this is ∫₁^ζ √((1−ζ²)(1−k²ζ²)) dζ only while cos z = √(1 − ζ²) ≥ 0,
    i.e. for 0 ≤ Ωt ≤ π."""
    return sp.Eq(B_sym, closed(b_steps()["zeta"]))


@derives("brepta1953:B-integral-denominator", uses=("brepta1953:B-integral-k",),
         unknowns=(B_sym,), domain=ELLIPTIC_ZETA_INTEGRALS)
def b_integral_denominator():
    """The same B: moving the root to the denominator, cos² z Δ = cos² z Δ²/Δ, changes nothing."""
    pre, integral = prefactor_and_integral(amplitude_b(), C2)
    (var, lo, hi), = integral.limits
    moved = sp.Mul(sp.cos(var) ** 2 * delta(var) ** 2, 1 / delta(var))  # evaluates back to cos²Δ
    return sp.Eq(B_sym, closed(pre * sp.Integral(moved, (var, lo, hi)) + C2))


@derives("brepta1953:B-split", uses=("brepta1953:B-integral-k",),
         unknowns=(B_sym,), domain=ELLIPTIC_ZETA_INTEGRALS)
def b_split():
    """B = βR₀² {∫ dz/Δ − (1+k²) ∫ sin² z dz/Δ + k² ∫ sin⁴ z dz/Δ} + C₂, from π/2 to π/2 − Ωt:
    cos² z Δ² = 1 − (1+k²) sin² z + k² sin⁴ z (each integral in closed form)."""
    return sp.Eq(B_sym, closed(b_steps()["split"]))


@derives("brepta1953:B-split-limits", uses=("brepta1953:B-integral-k",),
         unknowns=(B_sym,), domain=ELLIPTIC_ZETA_INTEGRALS)
def b_split_limits():
    """Each ∫_{π/2}^{Z} = ∫_0^{Z} − ∫_0^{π/2} (each in closed form)."""
    return sp.Eq(B_sym, closed(b_steps()["split-limits"]))


@derives("brepta1953:integral-limits", mode="substitute")
def integral_limits():
    """∫₁^ζ = ∫₁⁰ + ∫₀^ζ = ∫₀^ζ − ∫₀¹ (additivity), applied to the integrand of B-split,
    f(ζ) = (1 − (1+k²)ζ² + k²ζ⁴)/√((1−ζ²)(1−k²ζ²))."""
    f = sp.Function("f")
    R_ = sp.sqrt((1 - zeta**2) * (1 - k**2 * zeta**2))
    return {f(zeta): (1 - (1 + k**2) * zeta**2 + k**2 * zeta**4) / R_}


@derives("brepta1953:C-integral-zeta", uses=("brepta1953:C-integral-z",),
         unknowns=(C_sym,), domain=ELLIPTIC_ZETA_INTEGRALS)
def c_integral_zeta():
    """C = (βv₀u/Ω²) ∫_{π/2}^{z} sin² z Δ dz + C₃ with z = π/2 − Ωt (closed form); in ζ = sin z
    this is (βv₀R₀/Ω) ∫₁^ζ (ζ² − k²ζ⁴)/√((1−ζ²)(1−k²ζ²)) dζ only for 0 ≤ Ωt ≤ π."""
    return sp.Eq(C_sym, closed(c_steps()["zeta"]))


@derives("brepta1953:C-split", uses=("brepta1953:C-integral-z",),
         unknowns=(C_sym,), domain=ELLIPTIC_ZETA_INTEGRALS)
def c_split():
    """C = (βv₀R₀/Ω) {∫ sin² z dz/Δ − k² ∫ sin⁴ z dz/Δ} + C₃ (from π/2 to π/2 − Ωt):
    sin² z Δ² = sin² z − k² sin⁴ z (each integral in closed form)."""
    return sp.Eq(C_sym, closed(c_steps()["split"]))


@derives("brepta1953:C-split-limits", uses=("brepta1953:C-integral-z",),
         unknowns=(C_sym,), domain=ELLIPTIC_ZETA_INTEGRALS)
def c_split_limits():
    """Each ∫_{π/2}^{Z} = ∫_0^{Z} − ∫_0^{π/2} (each in closed form)."""
    return sp.Eq(C_sym, closed(c_steps()["split-limits"]))


# --- the closed forms (Legendre, in the amplitude z = π/2 − Ωt) --------------------------------
@derives("brepta1953:F-definition", mode="substitute")
def f_definition():
    """F(k, ζ) := ∫₀^ζ dζ/√((1−ζ²)(1−k²ζ²)) = F(asin ζ | k²): the printed integral must equal the
    toolkit's Fj (sympy/mpmath elliptic_f with the parameter m = k²) — a test of the convention."""
    return {}


@derives("brepta1953:E-definition", mode="substitute")
def e_definition():
    """E(k, ζ) := ∫₀^ζ √((1−k²ζ²)/(1−ζ²)) dζ = E(asin ζ | k²) (convention test of Ej)."""
    return {}


@derives("brepta1953:K-definition", mode="substitute")
def k_definition():
    """K := ∫₀¹ dζ/√((1−ζ²)(1−k²ζ²)) = K(k²) (convention test of Kc)."""
    return {}


@derives("brepta1953:Ec-definition", mode="substitute")
def ec_definition():
    """E := ∫₀¹ √((1−k²ζ²)/(1−ζ²)) dζ = E(k²) (convention test of Ec)."""
    return {}


@derives("brepta1953:B-reduced", uses=("brepta1953:B-integral-k",), unknowns=(B_sym,), domain=ELLIPTIC_T)
def b_reduced():
    """B-split with each ∫_{π/2}^{Z} sin^{2j} z dz/Δ reduced to Legendre's F(Z), E(Z), K, E and
    sin Z cos Z Δ(Z) (legendre_antiderivative), Z = π/2 − Ωt; the paper's ζ-form equals this for
    0 ≤ Ωt ≤ π only."""
    return sp.Eq(B_sym, closed(b_steps()["split-limits"]))


@derives("brepta1953:B-final", uses=("brepta1953:B-integral-k",), unknowns=(B_sym,), domain=ELLIPTIC_T)
def b_final():
    """B = βR₀² {(k²−1)/(3k²) F(Z) + (1+k²)/(3k²) E(Z) + sin Z cos Z Δ(Z)/3 + (1−k²)/(3k²) K
    − (1+k²)/(3k²) E} + C₂, Z = π/2 − Ωt: the antiderivative of cos² z Δ found by matching
    coefficients (a proof by differentiation), taken from π/2 to Z."""
    return sp.Eq(B_sym, closed(amplitude_b()))


@derives("brepta1953:C-reduced", uses=("brepta1953:C-integral-z",), unknowns=(C_sym,), domain=ELLIPTIC_T)
def c_reduced():
    """C-split with ∫_{π/2}^{Z} sin² z dz/Δ and ∫ sin⁴ z dz/Δ reduced to F, E, K, E."""
    return sp.Eq(C_sym, closed(c_steps()["split-limits"]))


@derives("brepta1953:C-final", uses=("brepta1953:C-integral-z",), unknowns=(C_sym,), domain=ELLIPTIC_T)
def c_final():
    """C = (βv₀R₀/Ω) {(1−k²)/(3k²) F(Z) + (2k²−1)/(3k²) E(Z) − sin Z cos Z Δ(Z)/3 − (1−k²)/(3k²) K
    − (2k²−1)/(3k²) E} + C₃, Z = π/2 − Ωt (antiderivative of sin² z Δ from π/2 to Z)."""
    return sp.Eq(C_sym, closed(amplitude_c()))


def general_x() -> sp.Expr:
    """x = A sin Ωt + B cos Ωt with A (A-integral) and B (B-final), constants C₁, C₂ free."""
    A_ = derived("brepta1953:A-integral").rhs
    B_ = derived("brepta1953:B-final").rhs
    return A_ * sp.sin(THETA) + B_ * sp.cos(THETA)


def general_y() -> sp.Expr:
    """y = C sin Ωt + D cos Ωt with C (C-final) and D (D-integral), constants C₃, C₄ free."""
    C_ = derived("brepta1953:C-final").rhs
    D__ = derived("brepta1953:D-integral").rhs
    return C_ * sp.sin(THETA) + D__ * sp.cos(THETA)


@derives("brepta1953:28", uses=("brepta1953:A-integral", "brepta1953:B-final"), unknowns=(x,),
         domain=ELLIPTIC_T)
def eq28():
    """x = {βR₀/(3Ω(u²−v₀²)) V³ + C₁} sin Ωt + (βR₀²{…}(Z) + C₂) cos Ωt, V² = u² − (u²−v₀²)cos² Ωt."""
    return sp.Eq(x, general_x())


@derives("brepta1953:30", uses=("brepta1953:C-final", "brepta1953:D-integral"), unknowns=(y,),
         domain=ELLIPTIC_T)
def eq30():
    """y = ((βv₀R₀/Ω){…}(Z) + C₃) sin Ωt + {βv₀/(3Ω²(u²−v₀²)) V³ + C₄} cos Ωt."""
    return sp.Eq(y, general_y())


@shared
def conditions_at_start(xg: sp.Expr, yg: sp.Expr) -> dict:
    """The four constants from x(0) = R₀, y(0) = 0, ẋ(0) = 0, ẏ(0) = v₀ (initial-conditions)."""
    x0, y0, xd0, yd0 = initial_values()
    eqs = [sp.Eq(xg.subs(t, 0), x0), sp.Eq(yg.subs(t, 0), y0),
           sp.Eq(xg.diff(t).subs(t, 0), xd0), sp.Eq(yg.diff(t).subs(t, 0), yd0)]
    eqs = [sp.Eq(sp.simplify(e.lhs), e.rhs) for e in eqs]
    sol = sp.solve(eqs, [C1, C2, C3, C4], dict=True)
    assert len(sol) == 1, sol
    return {c: sp.factor(v) for c, v in sol[0].items()}


@shared
def general_constants() -> dict:
    return conditions_at_start(general_x(), general_y())


@derives("brepta1953:C2-C4-conditions", uses=("brepta1953:A-integral", "brepta1953:B-final", "brepta1953:C-final", "brepta1953:D-integral", "brepta1953:initial-conditions"),
         unknowns=(C2, C4), domain=K_ONLY)
def c2_c4_conditions():
    """x(0) = B(0) = C₂ = R₀ (the elliptic part vanishes at Z = π/2); y(0) = D(0) = 0 gives
    βv₀·v₀³/(3Ω²(u²−v₀²)) + C₄ = 0 (V(0) = v₀)."""
    x0, y0, _, _ = initial_values()
    eqs = [sp.Eq(sp.simplify(general_x().subs(t, 0)), x0), sp.Eq(sp.simplify(general_y().subs(t, 0)), y0)]
    return [sp.Eq(C2, sp.solve(eqs[0], C2)[0]), sp.Eq(C4, sp.solve(eqs[1], C4)[0])]


@derives("brepta1953:C4", uses=("brepta1953:A-integral", "brepta1953:B-final", "brepta1953:C-final", "brepta1953:D-integral", "brepta1953:initial-conditions"), unknowns=(C4,))
def c4():
    """C₄ = −βv₀⁴/(3Ω²(u²−v₀²))."""
    return sp.Eq(C4, general_constants()[C4])


@derives("brepta1953:dxdt-condition", uses=("brepta1953:A-integral", "brepta1953:B-final", "brepta1953:initial-conditions"),
         unknowns=(D(x), C1), domain=K_ONLY)
def dxdt_condition():
    """ẋ(0) = 0 (the start), and ẋ(0) = ΩA(0) = Ω[βR₀v₀³/(3Ω(u²−v₀²)) + C₁] (B'(0) = 0)."""
    _, _, xd0, _ = initial_values()
    rate = sp.simplify(general_x().diff(t).subs(t, 0))
    return [sp.Eq(D(x), xd0), sp.Eq(C1, sp.solve(sp.Eq(rate, xd0), C1)[0])]


@derives("brepta1953:C1", uses=("brepta1953:A-integral", "brepta1953:B-final", "brepta1953:C-final", "brepta1953:D-integral", "brepta1953:initial-conditions"), unknowns=(C1,))
def c1():
    """C₁ = −βR₀v₀³/(3Ω(u²−v₀²))."""
    return sp.Eq(C1, general_constants()[C1])


@derives("brepta1953:C3", uses=("brepta1953:A-integral", "brepta1953:B-final", "brepta1953:C-final", "brepta1953:D-integral", "brepta1953:initial-conditions"),
         unknowns=(D(y), C3, C3), domain=K_ONLY)
def c3():
    """ẏ(0) = v₀ and ẏ(0) = ΩC(0) = ΩC₃ (the elliptic part of C vanishes at t = 0): C₃ = v₀/Ω."""
    _, _, _, yd0 = initial_values()
    rate = sp.simplify(general_y().diff(t).subs(t, 0))
    value = sp.solve(sp.Eq(rate, yd0), C3)[0]
    return [sp.Eq(D(y), yd0), sp.Eq(C3, value), sp.Eq(C3, general_constants()[C3])]


@derives("brepta1953:particular-solution", uses=("brepta1953:A-integral", "brepta1953:B-final", "brepta1953:C-final", "brepta1953:D-integral", "brepta1953:initial-conditions"),
         unknowns=(x, y), domain=ELLIPTIC_T)
def particular_solution():
    """(28), (30) with C₁ … C₄ from the start: x(t), y(t) to first order in β, every t ≥ 0."""
    consts = general_constants()
    return [sp.Eq(x, general_x().subs(consts)), sp.Eq(y, general_y().subs(consts))]


# --- the conical start R₀Ω = v₀ ------------------------------------------------------------------
@derives("brepta1953:conical-condition", mode="condition", uses=("brepta1953:ideal-velocities",))
def conical_condition():
    """The speed on the ellipse is constant, V² − v₀² = (R₀²Ω² − v₀²) sin² Ωt = 0, exactly when
    R₀Ω = v₀ (a circle: the conical pendulum)."""
    return sp.expand(speed_squared() - v0**2)


@shared
def conical(expr: sp.Expr) -> sp.Expr:
    """expr at v₀ = R₀Ω (the radicand V² becomes R₀²Ω²)."""
    return pythagorean(expr.subs(v0, R0 * Omega))


@derives("brepta1953:conical-x", uses=("brepta1953:forced-x",),
         unknowns=(D(x, 2),), domain=CONICAL)
def conical_x():
    """ẍ = −Ω²x + βR₀²Ω² sin Ωt (forced-x at v₀ = R₀Ω)."""
    eq = derived("brepta1953:forced-x")
    return sp.Eq(eq.lhs, conical(eq.rhs))


@derives("brepta1953:conical-y", uses=("brepta1953:forced-y",),
         unknowns=(D(y, 2),), domain=CONICAL)
def conical_y():
    """ÿ = −Ω²y − βv₀² cos Ωt (forced-y at v₀ = R₀Ω, written with v₀)."""
    eq = derived("brepta1953:forced-y")
    return sp.Eq(eq.lhs, conical(eq.rhs))


@shared
def conical_general(i: int) -> sp.Expr:
    """Variation of constants for the conical forcing: P = C + ∫₀ᵗ P' dt, Q = C' + ∫₀ᵗ Q' dt
    (elementary: sympy integrate)."""
    Pp, Qp = (conical(r) for r in varied_rates(i))
    tau = sp.Symbol("tau", nonnegative=True)
    P = sp.integrate(Pp.subs(t, tau), (tau, 0, t))
    Q = sp.integrate(Qp.subs(t, tau), (tau, 0, t))
    c_sin, c_cos = ((C1, C2), (C3, C4))[i]
    return (P + c_sin) * sp.sin(THETA) + (Q + c_cos) * sp.cos(THETA)


@derives("brepta1953:31", uses=("brepta1953:AB-variation", "brepta1953:ideal-velocities"), unknowns=(x,),
         domain=CONICAL)
def eq31():
    """x = (βR₀²/2 sin² Ωt + C₁) sin Ωt + [βR₀²(¼ sin 2Ωt − Ωt/2) + C₂] cos Ωt."""
    return sp.Eq(x, conical_general(0))


@derives("brepta1953:32", uses=("brepta1953:CD-variation", "brepta1953:ideal-velocities"), unknowns=(y,),
         domain=CONICAL)
def eq32():
    """y = [−βv₀²/Ω² (Ωt/2 + ¼ sin 2Ωt) + C₃] sin Ωt + (βv₀²/(2Ω²) sin² Ωt + C₄) cos Ωt."""
    return sp.Eq(y, conical_general(1))


@shared
def conical_constants() -> dict:
    return conditions_at_start(conical_general(0), conical_general(1))


@derives("brepta1953:conical-C2-C4", uses=("brepta1953:AB-variation", "brepta1953:CD-variation", "brepta1953:ideal-velocities", "brepta1953:initial-conditions"),
         unknowns=(C2, C4), domain=CONICAL)
def conical_c2_c4():
    """x(0) = C₂ = R₀, y(0) = C₄ = 0."""
    consts = conical_constants()
    return [sp.Eq(C2, consts[C2]), sp.Eq(C4, consts[C4])]


@derives("brepta1953:conical-C1-C3", uses=("brepta1953:AB-variation", "brepta1953:CD-variation", "brepta1953:ideal-velocities", "brepta1953:initial-conditions"),
         unknowns=(C1, C1, C3, C3), domain=CONICAL)
def conical_c1_c3():
    """ẋ(0) = ΩC₁ = 0 → C₁ = 0; ẏ(0) = ΩC₃ = v₀ → C₃ = v₀/Ω."""
    _, _, xd0, yd0 = initial_values()
    c1_ = sp.solve(sp.Eq(conical_general(0).diff(t).subs(t, 0), xd0), C1)[0]
    c3_ = sp.solve(sp.Eq(conical_general(1).diff(t).subs(t, 0), yd0), C3)[0]
    consts = conical_constants()
    return [sp.Eq(C1, c1_), sp.Eq(C1, consts[C1]), sp.Eq(C3, c3_), sp.Eq(C3, consts[C3])]


@shared
def conical_particular() -> tuple[sp.Expr, sp.Expr]:
    consts = conical_constants()
    return conical_general(0).subs(consts), conical_general(1).subs(consts)


@derives("brepta1953:conical-particular-solution", uses=("brepta1953:AB-variation", "brepta1953:CD-variation", "brepta1953:ideal-velocities", "brepta1953:initial-conditions"),
         unknowns=(x, y), domain=CONICAL)
def conical_particular_solution():
    """x = R₀ cos Ωt + βR₀²(¼ sin 2Ωt − Ωt/2) cos Ωt + βR₀²/2 sin³ Ωt,
    y = (v₀/Ω) sin Ωt − βv₀²/Ω² (Ωt/2 + ¼ sin 2Ωt) sin Ωt + βv₀²/(2Ω²) sin² Ωt cos Ωt."""
    xp, yp = conical_particular()
    return [sp.Eq(x, xp), sp.Eq(y, yp)]


@derives("brepta1953:33", mode="substitute", uses=("brepta1953:AB-variation", "brepta1953:CD-variation", "brepta1953:ideal-velocities", "brepta1953:initial-conditions"),
         domain=CONICAL)
def after_one_turn():
    """x(2π/Ω) = R₀ − πβR₀² =: R₁: the conical particular x after one revolution (only the secular
    term −βR₀²(Ωt/2) cos Ωt survives).  Model: the function x and R₁ := x(2π/Ω)."""
    xp, _ = conical_particular()
    return {x.func: sp.Lambda(t, xp), R1: sp.simplify(xp.subs(t, 2 * sp.pi / Omega))}
