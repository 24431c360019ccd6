"""[Brepta1953] section 4: the small-swing spherical pendulum under linear drag R = 2κmv.

In the tangent plane (section 3) the bob at r = (x, y) = ρ(cos ψ, sin ψ) feels the central pull
−S e_ρ, S = m(g/l)ρ, and the drag −R e_v along the velocity, whose direction makes the angle α
with the x axis (fig. 5).  Newton's law in Cartesian components gives two uncoupled damped
oscillators ẍ + 2κẋ + Ω²x = 0 (Ω² = g/l), solved by dsolve: for κ < Ω with ω = √(Ω² − κ²),
at κ = Ω with the double root −κ.  The paper's start (fig. 6): distance R0 on the x axis and
speed v0 perpendicular to the radius.  The trajectory follows by eliminating t: with
c = e^{−κt} cos ωt, s = e^{−κt} sin ωt read linearly off (19), e^{−κt} = √(c² + s²) and
ωt = arccotg(c/s) + nπ, n = ⌊ωt/π⌋ the number of half-turns completed (arccotg ∈ (0, π)).
"""

from __future__ import annotations

import sympy as sp

from quasicentral.notation.domain import Domain
from quasicentral.engine.registry import derived, derives, shared
from quasicentral.notation.symbols import D, arccotg
from quasicentral.engine.texts import symbols_of

#: dsolve's method for a linear ODE with constant coefficients (named: sympy would otherwise
#: classify the equation against every method first)
LINEAR = "nth_linear_constant_coeff_homogeneous"

S_ = symbols_of(__file__)  # this text's declared symbols (text.toml)
(A, B, C, D_, K1, L1, M1, N1, Omega, R, R0, S, alpha, g, kappa, lam, m, n, omega, psi, rho, t, th, v, v0, vx, vy, x, y) = S_(
    "A B C D_ K1 L1 M1 N1 Omega R R0 S alpha g kappa lam m n omega psi rho t th v v0 vx vy x y")

EX, EY = sp.Matrix([1, 0]), sp.Matrix([0, 1])
#: κ < Ω: the oscillatory case of (18)–(20)
SMALL_DAMPING = Domain.of(constraints=(sp.StrictLessThan(kappa, Omega),))
#: (20) on (19) parametrized by θ = ωt over eight half-turns, 0 < θ < 8π; κ ≥ 0 and ω > 0 drawn
#: directly (Ω² = κ² + ω² > κ² holds by construction; κ/ω runs from 0 to 30)
HALF_TURNS = Domain.of(ranges={omega: (sp.Rational(1, 10), 10), th: (0, 8 * sp.pi)}, defaults=False)
#: κ = Ω: the limit of aperiodic motion, (21), (22)
CRITICAL = Domain.of(definitions={kappa: Omega})
#: the characteristic equation is an identity in λ: sample λ too
LAMBDA = Domain.of(ranges={lam: (-3, 3)})
#: the numerical data are numbers in SI units
FIG7 = {Omega: sp.sqrt(10), kappa: sp.Rational(4, 10), R0: sp.Rational(1, 10), v0: sp.Rational(1, 10)}
FIG8_GIVEN = {Omega: sp.sqrt(10), R0: sp.Rational(1, 10), v0: sp.Rational(1, 10)}
X0, Y0 = x.subs(t, 0), y.subs(t, 0)
VX0, VY0 = D(x).subs(t, 0), D(y).subs(t, 0)


# --- forces and Newton's law in the plane ------------------------------------------------------
def e_rho() -> sp.Matrix:
    """Unit vector of the radius vector, at the polar angle ψ."""
    return sp.Matrix([sp.cos(psi), sp.sin(psi)])


def e_velocity() -> sp.Matrix:
    """Unit vector of the velocity, at the angle α from the x axis (fig. 5)."""
    return sp.Matrix([sp.cos(alpha), sp.sin(alpha)])


def force() -> sp.Matrix:
    """−S e_ρ (towards the centre) − R e_v (against the velocity)."""
    return -S * e_rho() - R * e_velocity()


@derives("brepta1953:14", unknowns=(D(x, 2),))
def newton_x():
    """m ẍ = −S cos ψ − R cos α: the x component of m r̈ = −S e_ρ − R e_v."""
    return sp.Eq(m * D(x, 2), force().dot(EX))


@derives("brepta1953:15", unknowns=(D(y, 2),))
def newton_y():
    """m ÿ = −S sin ψ − R sin α: the y component of m r̈ = −S e_ρ − R e_v."""
    return sp.Eq(m * D(y, 2), force().dot(EY))


@derives("brepta1953:pendulum-central-force", uses=("brepta1953:12",), unknowns=(S,))
def pendulum_central_force():
    """S = m (g/l) ρ, the pull of section 3, (12)."""
    return derived("brepta1953:12")


def polar_position() -> dict:
    """r = ρ e_ρ: x = ρ cos ψ, y = ρ sin ψ."""
    return dict(zip((x, y), rho * e_rho()))


def polar_velocity() -> dict:
    """(v_x, v_y) = v e_v: the velocity has the length v and the direction α."""
    return dict(zip((vx, vy), v * e_velocity()))


@derives("brepta1953:psi-components", mode="substitute")
def psi_components():
    """sin ψ = y/ρ, cos ψ = x/ρ: checked on the polar position x = ρ cos ψ, y = ρ sin ψ."""
    return polar_position()


@derives("brepta1953:alpha-components", mode="substitute")
def alpha_components():
    """sin α = v_y/v, cos α = v_x/v: checked with v = |(v_x, v_y)| and α = atan2(v_y, v_x), the
    length and the direction angle of the velocity."""
    return {v: sp.sqrt(vx**2 + vy**2), alpha: sp.atan2(vy, vx)}


def trig_of_angles() -> dict:
    """cos ψ, sin ψ, cos α, sin α solved from the polar position and velocity."""
    out = {}
    for model, angle in ((polar_position(), psi), (polar_velocity(), alpha)):
        for comp, fn in zip(model, (sp.cos, sp.sin)):
            out[fn(angle)] = sp.solve(sp.Eq(comp, model[comp]), fn(angle))[0]
    return out


def rewritten(eid: str) -> sp.Eq:
    """(14) or (15) with S from (12), R = 2κmv and the angles by the coordinates."""
    eq = derived(eid)
    subs = {S: derived("brepta1953:pendulum-central-force").rhs, R: derived("brepta1953:linear-drag-law").rhs}
    return sp.Eq(eq.lhs, eq.rhs.subs(trig_of_angles()).subs(subs))


@derives("brepta1953:rewritten-x", unknowns=(D(x, 2),),
         uses=("brepta1953:14", "brepta1953:linear-drag-law", "brepta1953:pendulum-central-force"))
def rewritten_x():
    """m ẍ = −m(g/l)ρ·x/ρ − 2κmv·v_x/v."""
    return rewritten("brepta1953:14")


@derives("brepta1953:rewritten-y", unknowns=(D(y, 2),),
         uses=("brepta1953:15", "brepta1953:linear-drag-law", "brepta1953:pendulum-central-force"))
def rewritten_y():
    """m ÿ = −m(g/l)ρ·y/ρ − 2κmv·v_y/v."""
    return rewritten("brepta1953:15")


@derives("brepta1953:velocity-components", unknowns=(vx, vy))
def velocity_components():
    """v_x = dx/dt, v_y = dy/dt: the components of ṙ."""
    vel = sp.Matrix([x, y]).diff(t)
    return [sp.Eq(vx, vel[0]), sp.Eq(vy, vel[1])]


@derives("brepta1953:omega-squared-definition", uses=("brepta1953:period-and-frequency",), unknowns=(Omega**2,))
def omega_squared_definition():
    """g/l = Ω²: Ω is the angular frequency of the undamped tangent-plane oscillator (section 3)."""
    return derived("brepta1953:period-and-frequency")[1]


def damped_equation(coord: sp.Expr, eid: str) -> sp.Eq:
    """(14)/(15) rewritten, divided by m, with v_x = ẋ (v_y = ẏ) and g = Ω² l."""
    eq = derived(eid)
    vel = {e.lhs: e.rhs for e in derived("brepta1953:velocity-components")}
    g_of_omega = sp.solve(derived("brepta1953:omega-squared-definition"), g)[0]
    rhs = sp.expand(eq.rhs.subs(vel).subs(g, g_of_omega) / m)
    return sp.Eq(D(coord, 2), rhs)


@derives("brepta1953:16", uses=("brepta1953:rewritten-x", "brepta1953:velocity-components",
                                "brepta1953:omega-squared-definition"), unknowns=(D(x, 2),))
def damped_x():
    """ẍ = −Ω²x − 2κẋ."""
    return damped_equation(x, "brepta1953:rewritten-x")


@derives("brepta1953:17", uses=("brepta1953:rewritten-y", "brepta1953:velocity-components",
                                "brepta1953:omega-squared-definition"), unknowns=(D(y, 2),))
def damped_y():
    """ÿ = −Ω²y − 2κẏ."""
    return damped_equation(y, "brepta1953:rewritten-y")


@shared
def characteristic_polynomial() -> sp.Expr:
    """e^{−λt}·(residual of (16) on x = e^{λt}); asserted the same for (17)."""
    polys = []
    for coord, eid in ((x, "brepta1953:16"), (y, "brepta1953:17")):
        eq = derived(eid)
        res = (eq.lhs - eq.rhs).subs(coord, sp.exp(lam * t)).doit()
        polys.append(sp.expand(sp.simplify(res * sp.exp(-lam * t))))
    assert polys[0] == polys[1]
    return polys[0]


@derives("brepta1953:characteristic-equation", uses=("brepta1953:16", "brepta1953:17"),
         unknowns=(Omega**2,), domain=LAMBDA)
def characteristic_equation():
    """λ² + 2κλ + Ω² = 0: x = e^{λt} solves (16) (and (17)) exactly for these λ."""
    return sp.Eq(characteristic_polynomial(), 0)


@derives("brepta1953:characteristic-roots", uses=("brepta1953:16", "brepta1953:17"), unknowns=(lam, lam))
def characteristic_roots():
    """λ₁,₂ = −κ ± √(κ² − Ω²) (λ₁ the larger root where they are real)."""
    roots = sp.solve(characteristic_polynomial(), lam)
    probe = {kappa: 2, Omega: 1}  # overdamped: real roots, the + branch is the larger
    roots = sorted(roots, key=lambda r: -r.subs(probe))
    return [sp.Eq(lam, r) for r in roots]


@derives("brepta1953:omega-definition", uses=("brepta1953:characteristic-roots",), unknowns=(omega,),
         domain=SMALL_DAMPING)
def omega_definition():
    """ω = √(Ω² − κ²): for κ < Ω the roots are −κ ± iω; ω is the imaginary part of λ₁."""
    w = sp.Dummy("w", positive=True)
    lam1 = derived("brepta1953:characteristic-roots")[0].rhs.subs(Omega, sp.sqrt(kappa**2 + w**2))
    freq = sp.im(sp.simplify(lam1))
    assert sp.simplify(sp.re(sp.simplify(lam1)) + kappa) == 0
    w_of = sp.solve(sp.Eq(Omega**2, kappa**2 + w**2), w)[0]
    return sp.Eq(omega, freq.subs(w, w_of))


#: placeholders for the initial data x(0), ẋ(0) while (16) is solved (see oscillator_dsolve)
X_START, V_START = sp.Dummy("x_start"), sp.Dummy("v_start")


@shared
def oscillator_dsolve(critical: bool, with_start: bool) -> sp.Expr:
    """dsolve of (16) in x: for κ < Ω written with Ω² = κ² + ω² (κ > 0 while solving, so that
    sympy picks the real form; the result holds for κ = 0 too), or (``critical``) at κ = Ω.
    The general solution, or (``with_start``) the one with x(0) = X_START, ẋ(0) = V_START:
    placeholders, so that one dsolve serves every start."""
    eq = derived("brepta1953:16")
    ics = {x.subs(t, 0): X_START, x.diff(t).subs(t, 0): V_START} if with_start else None
    if critical:
        omega_c = sp.solve(sp.Eq(critical_kappa(), kappa), Omega)[0]
        return sp.expand(sp.dsolve(eq.subs(Omega, omega_c), x, ics=ics, hint=LINEAR).rhs)
    kp = sp.Dummy("kappa", positive=True)
    eq = eq.subs(Omega, sp.sqrt(kappa**2 + omega**2)).subs(kappa, kp)
    return sp.expand(sp.dsolve(eq, x, ics=ics, hint=LINEAR).rhs.subs(kp, kappa))


def oscillator_solution(coord: sp.Expr, eid: str, critical: bool, start: tuple | None = None) -> sp.Expr:
    """(16) or (17) solved (:func:`oscillator_dsolve`): (17) is (16) with y for x (asserted),
    so its solution is x's; ``start`` the initial data (coord(0), coord'(0)) put in."""
    assert derived(eid) == derived("brepta1953:16").xreplace({x: coord}), eid
    sol = oscillator_dsolve(critical, start is not None)
    return sol if start is None else sp.expand(sol.xreplace({X_START: start[0], V_START: start[1]}))


def damped_solution(coord: sp.Expr, eid: str, start: tuple | None = None) -> sp.Expr:
    """dsolve of (16)/(17) for κ < Ω."""
    return oscillator_solution(coord, eid, False, start)


@shared
def relabel(sol: sp.Expr, basis: tuple, names: tuple) -> sp.Expr:
    """Name the free constants of a general solution after the basis functions they multiply."""
    consts = sorted(sol.free_symbols - {t, kappa, omega}, key=str)
    mapping = {}
    for c in consts:
        part = sol.diff(c)  # the solution is expanded and linear in its constants
        for b, name in zip(basis, names):
            if sp.expand(part - b) == 0:
                mapping[c] = name
    assert len(mapping) == len(consts) == len(basis)
    return sol.xreplace(mapping)


@derives("brepta1953:18", uses=("brepta1953:16", "brepta1953:17"),
         unknowns=(x, y), domain=SMALL_DAMPING)
def general_solution():
    """x = e^{−κt}(K sin ωt + L cos ωt), y = e^{−κt}(M sin ωt + N cos ωt): dsolve of (16), (17)."""
    basis = (sp.exp(-kappa * t) * sp.sin(omega * t), sp.exp(-kappa * t) * sp.cos(omega * t))
    return [sp.Eq(x, relabel(damped_solution(x, "brepta1953:16"), basis, (K1, L1))),
            sp.Eq(y, relabel(damped_solution(y, "brepta1953:17"), basis, (M1, N1)))]


def initial_state() -> tuple[sp.Matrix, sp.Matrix]:
    """Fig. 6: r(0) = R0 e_ρ(ψ0), ṙ(0) = v0 e_τ(ψ0) (speed perpendicular to the radius), with
    the x axis laid through the initial position, ψ0 = 0."""
    psi0 = 0
    e_r = sp.Matrix([sp.cos(psi0), sp.sin(psi0)])
    e_tau = sp.Matrix([-sp.sin(psi0), sp.cos(psi0)])
    return R0 * e_r, v0 * e_tau


@derives("brepta1953:linear-initial-conditions", unknowns=(X0, Y0))
def linear_initial_conditions():
    """x(0) = R0, y(0) = 0 (fig. 6)."""
    pos, _ = initial_state()
    return [sp.Eq(X0, pos[0]), sp.Eq(Y0, pos[1])]


def solution_at_zero() -> tuple[sp.Expr, sp.Expr]:
    """(18) at t = 0."""
    x18, y18 = (e.rhs for e in derived("brepta1953:18"))
    return x18.subs(t, 0), y18.subs(t, 0)


@derives("brepta1953:initial-constants", uses=("brepta1953:18",),
         unknowns=(L1, N1))
def initial_constants():
    """L = R0, N = 0: (18) at t = 0 equated to the initial position."""
    pos, _ = initial_state()
    x0, y0 = solution_at_zero()
    sol = sp.solve([x0 - pos[0], y0 - pos[1]], [L1, N1], dict=True)[0]
    return [sp.Eq(L1, sol[L1]), sp.Eq(N1, sol[N1])]


def velocity_of_18(index: int) -> sp.Expr:
    """d/dt of (18) with the constants L, N of the initial position."""
    consts = {e.lhs: e.rhs for e in derived("brepta1953:initial-constants")}
    return sp.diff(derived("brepta1953:18")[index].rhs.subs(consts), t)


@derives("brepta1953:dx-dt", uses=("brepta1953:18", "brepta1953:initial-constants"), unknowns=(D(x),),
         domain=SMALL_DAMPING)
def dx_dt():
    """ẋ = −κe^{−κt}(K sin ωt + R0 cos ωt) + ωe^{−κt}(K cos ωt − R0 sin ωt)."""
    return sp.Eq(D(x), velocity_of_18(0))


@derives("brepta1953:dy-dt", uses=("brepta1953:18", "brepta1953:initial-constants"), unknowns=(D(y),),
         domain=SMALL_DAMPING)
def dy_dt():
    """ẏ = −κe^{−κt}M sin ωt + ωe^{−κt}M cos ωt."""
    return sp.Eq(D(y), velocity_of_18(1))


@derives("brepta1953:initial-velocity", unknowns=(VX0, VY0))
def initial_velocity():
    """ẋ(0) = 0, ẏ(0) = v0 (fig. 6)."""
    _, vel = initial_state()
    return [sp.Eq(VX0, vel[0]), sp.Eq(VY0, vel[1])]


@derives("brepta1953:constant-K", uses=("brepta1953:dx-dt",),
         unknowns=(K1,), domain=SMALL_DAMPING)
def constant_K():
    """0 = −κR0 + ωK, so K = R0κ/ω: ẋ(0) = 0 (each printed form of K is compared with it)."""
    _, vel = initial_state()
    return sp.Eq(K1, sp.solve(derived("brepta1953:dx-dt").rhs.subs(t, 0) - vel[0], K1)[0])


@derives("brepta1953:constant-M", uses=("brepta1953:dy-dt",),
         unknowns=(M1,), domain=SMALL_DAMPING)
def constant_M():
    """v0 = ωM, so M = v0/ω: ẏ(0) = v0 (each printed form of M is compared with it)."""
    _, vel = initial_state()
    return sp.Eq(M1, sp.solve(derived("brepta1953:dy-dt").rhs.subs(t, 0) - vel[1], M1)[0])


def start_of(index: int) -> tuple[sp.Expr, sp.Expr]:
    """Fig. 6's initial position and velocity in coordinate ``index`` (0: x, 1: y)."""
    pos, vel = initial_state()
    return pos[index], vel[index]


@derives("brepta1953:19", uses=("brepta1953:16", "brepta1953:17"), unknowns=(x, y), domain=SMALL_DAMPING)
def particular_solution():
    """x = (R0/ω)e^{−κt}(κ sin ωt + ω cos ωt), y = (v0/ω)e^{−κt} sin ωt: dsolve with fig. 6's data."""
    return [sp.Eq(x, damped_solution(x, "brepta1953:16", start_of(0))),
            sp.Eq(y, damped_solution(y, "brepta1953:17", start_of(1)))]


def half_turns() -> sp.Expr:
    """n = ⌊ωt/π⌋: the half-turns completed (y of (19) changes sign at each ωt = kπ)."""
    return sp.floor(omega * t / sp.pi)


@derives("brepta1953:20", mode="substitute", uses=("brepta1953:19",), domain=HALF_TURNS)
def trajectory_small_damping():
    """√(R0²ω²y² + v0²X²) = R0v0 exp(−(κ/ω)[arccotg(v0X/(R0ωy)) + nπ]), X = x − (R0κ/v0)y,
    n = ⌊ωt/π⌋: checked on the points of (19), written with θ = ωt, over eight half-turns."""
    x19, y19 = (e.rhs for e in derived("brepta1953:19"))
    at = {t: th / omega}
    return {x: x19.subs(at), y: y19.subs(at), n: half_turns().subs(at)}


def eliminate_time_small_damping() -> sp.Eq:
    """The trajectory of (19) with t eliminated (n = ⌊ωt/π⌋ the branch of arccotg)."""
    c, s_ = sp.symbols("c s", real=True)  # e^{−κt} cos ωt, e^{−κt} sin ωt
    rows = []
    for coord, e in zip((x, y), derived("brepta1953:19")):
        trig = sp.expand(e.rhs * sp.exp(kappa * t))
        rows.append(coord - (trig.coeff(sp.cos(omega * t)) * c + trig.coeff(sp.sin(omega * t)) * s_))
    sol = sp.solve(rows, [c, s_], dict=True)[0]
    cc, ss = sol[c], sol[s_]
    lhs = sp.sqrt(sp.expand(sp.factor((R0 * v0) ** 2 * (cc**2 + ss**2))))  # R0 v0 e^{−κt}
    angle = arccotg(sp.simplify(cc / ss)) + n * sp.pi  # ωt
    return sp.Eq(lhs, R0 * v0 * sp.exp(-kappa / omega * angle))


@derives("brepta1953:undamped-ellipse", uses=("brepta1953:19",), unknowns=(y**2,))
def undamped_ellipse():
    """y²/(v0²/Ω²) + x²/R0² = 1: the trajectory (20) at κ = 0 (ω = Ω), squared."""
    rel = eliminate_time_small_damping()
    rel = rel.subs(omega, sp.sqrt(Omega**2 - kappa**2)).subs(kappa, 0)
    Y2 = sp.Dummy("Y2", nonnegative=True)
    squared = sp.Eq(sp.expand(rel.lhs**2).subs(y**2, Y2), rel.rhs**2)
    return sp.Eq(y**2, sp.solve(squared, Y2)[0])


@shared
def discriminant() -> sp.Expr:
    """The discriminant of the characteristic polynomial in λ: 4κ² − 4Ω²."""
    return sp.discriminant(characteristic_polynomial(), lam)


@derives("brepta1953:critical-condition", mode="condition", uses=("brepta1953:16", "brepta1953:17"))
def critical_condition():
    """κ = Ω: the discriminant 4(κ² − Ω²) of the characteristic equation vanishes (double root)."""
    return discriminant()


@shared
def critical_kappa() -> sp.Expr:
    """The non-negative κ at which the discriminant vanishes."""
    (kc,) = [r for r in sp.solve(discriminant(), kappa) if r.is_nonnegative is not False]
    return kc


@derives("brepta1953:critical-double-root", unknowns=(lam,),
         uses=("brepta1953:16", "brepta1953:17"))
def critical_double_root():
    """λ₁,₂ = −κ at κ = Ω."""
    omega_c = sp.solve(sp.Eq(critical_kappa(), kappa), Omega)[0]
    roots = sp.roots(sp.Poly(characteristic_polynomial().subs(Omega, omega_c), lam))
    ((root, mult),) = roots.items()
    assert mult == 2
    return sp.Eq(lam, root)


def critical_solution(coord: sp.Expr, eid: str, start: tuple | None = None) -> sp.Expr:
    """dsolve of (16)/(17) at κ = Ω."""
    return oscillator_solution(coord, eid, True, start)


@derives("brepta1953:critical-general-solution", unknowns=(x, y),
         uses=("brepta1953:16", "brepta1953:17"))
def critical_general_solution():
    """x = e^{−κt}(A + Bt), y = e^{−κt}(C + Dt): dsolve of (16), (17) at κ = Ω."""
    basis = (sp.exp(-kappa * t), t * sp.exp(-kappa * t))
    return [sp.Eq(x, relabel(critical_solution(x, "brepta1953:16"), basis, (A, B))),
            sp.Eq(y, relabel(critical_solution(y, "brepta1953:17"), basis, (C, D_)))]


@derives("brepta1953:critical-initial-conditions", unknowns=(X0, Y0, vx, vy))
def critical_initial_conditions():
    """x(0) = R0, y(0) = 0, v_x(0) = 0, v_y(0) = v0: the same start as fig. 6."""
    pos, vel = initial_state()
    return [sp.Eq(X0, pos[0]), sp.Eq(Y0, pos[1]), sp.Eq(vx, vel[0]), sp.Eq(vy, vel[1])]


def critical_constants() -> dict:
    """A, B, C, D from the critical general solution and the initial state."""
    pos, vel = initial_state()
    eqs = []
    for e, p0, v0_ in zip(derived("brepta1953:critical-general-solution"), pos, vel):
        eqs += [e.rhs.subs(t, 0) - p0, e.rhs.diff(t).subs(t, 0) - v0_]
    return sp.solve(eqs, [A, B, C, D_], dict=True)[0]


@derives("brepta1953:critical-constants-AC", uses=("brepta1953:critical-general-solution",), unknowns=(A, C))
def critical_constants_AC():
    """A = R0, C = 0: the initial position."""
    sol = critical_constants()
    return [sp.Eq(A, sol[A]), sp.Eq(C, sol[C])]


@derives("brepta1953:critical-constants-BD", uses=("brepta1953:critical-general-solution",), unknowns=(B, D_))
def critical_constants_BD():
    """B = R0κ, D = v0: the initial velocity."""
    sol = critical_constants()
    return [sp.Eq(B, sol[B]), sp.Eq(D_, sol[D_])]


@derives("brepta1953:21", uses=("brepta1953:16", "brepta1953:17"),
         unknowns=(x, y), domain=CRITICAL)
def critical_particular_solution():
    """x = R0e^{−κt}(1 + κt), y = v0 t e^{−κt}: dsolve at κ = Ω with fig. 6's data."""
    return [sp.Eq(x, critical_solution(x, "brepta1953:16", start_of(0))),
            sp.Eq(y, critical_solution(y, "brepta1953:17", start_of(1)))]


@derives("brepta1953:22", mode="substitute", uses=("brepta1953:21",), domain=CRITICAL)
def trajectory_critical():
    """X = R0 exp(−(R0κ/v0) y/X), X = x − (R0κ/v0)y: checked on the points of (21)."""
    x21, y21 = (e.rhs for e in derived("brepta1953:21"))
    return {x: x21, y: y21}


def eliminate_time_critical() -> sp.Eq:
    """The trajectory of (21) with t eliminated: e^{−κt} and t e^{−κt} read linearly off (21)."""
    c, s_ = sp.symbols("c s", real=True)  # e^{−κt}, t e^{−κt}
    rows = []
    for coord, e in zip((x, y), derived("brepta1953:21")):
        poly = sp.Poly(sp.expand(e.rhs * sp.exp(kappa * t)), t)
        rows.append(coord - (poly.coeff_monomial(1) * c + poly.coeff_monomial(t) * s_))
    sol = sp.solve(rows, [c, s_], dict=True)[0]
    tt = sp.simplify(sol[s_] / sol[c])  # t = (t e^{−κt})/e^{−κt}
    return sp.Eq(R0 * sol[c], R0 * sp.exp(-kappa * tt))


def round_half_up(value: sp.Expr, decimals: int) -> sp.Rational:
    """value rounded to `decimals` decimal places (exact: floor(10^d·value + ½)/10^d)."""
    q = sp.Integer(10) ** decimals
    return sp.Rational(sp.floor(value * q + sp.Rational(1, 2)), q)


@derives("brepta1953:example-fig7", uses=("brepta1953:period-and-frequency", "brepta1953:omega-definition"),
         unknowns=(Omega, Omega, kappa, R0, v0, omega, omega, omega), domain=SMALL_DAMPING)
def example_fig7():
    """Ω = √(g/l) = √10, κ = 0.4, R0 = v0 = 0.1 (the figure's data), ω = √(Ω² − κ²) = √9.84, and
    ω rounded to the three decimals printed: 3.137 (√9.84 = 3.13688, within half a unit of the
    last printed digit)."""
    omega_def = derived("brepta1953:omega-definition").rhs
    omega_val = omega_def.subs(FIG7)
    return [sp.Eq(Omega, sp.sqrt(derived("brepta1953:period-and-frequency")[1].rhs)),
            sp.Eq(Omega, FIG7[Omega]), sp.Eq(kappa, FIG7[kappa]), sp.Eq(R0, FIG7[R0]), sp.Eq(v0, FIG7[v0]),
            sp.Eq(omega, omega_def), sp.Eq(omega, omega_val), sp.Eq(omega, round_half_up(omega_val, 3))]


@derives("brepta1953:example-fig8", uses=("brepta1953:16", "brepta1953:17"), unknowns=(Omega, R0, kappa, v0))
def example_fig8():
    """Ω = √10, R0 = v0 = 0.1 (the figure's data) and κ = √10: the critical κ = Ω of (21), (22)."""
    kc = critical_kappa().subs(FIG8_GIVEN)
    return [sp.Eq(Omega, FIG8_GIVEN[Omega]), sp.Eq(R0, FIG8_GIVEN[R0]), sp.Eq(kappa, kc), sp.Eq(v0, FIG8_GIVEN[v0])]
