"""[pendulum] The exact period of the simple pendulum, eqs. (49)–(66) and the prose between.

The bob hangs on a massless rod of length l at r = l(sin φ, cos φ), the y axis pointing down
(fig. 31: y = l cos φ).  The kinetic energy comes from |ṙ|, the potential energy from the work
against the weight (0, mg); the Lagrangian L = T − V, its Euler–Lagrange equation and its
energy function h = φ̇ ∂L/∂φ̇ − L are computed here, and everything else is built from them.

Two models of the motion are used:

* on-shell jets: φ̈ replaced by the Euler–Lagrange acceleration, φ and φ̇ left free (every
  state lies on some motion) — for the equation of motion and the identities about d/dt;
* the exact motion released from rest at φ0 (the text's initial condition, E = −mgl cos φ0):
  φ(t) = Φ(Ωt), Φ(τ) = 2 asin(k sn(τ + K | k²)), Ψ(τ) = Φ'(τ) = 2k cn(τ + K | k²),
  k = sin(φ0/2).  sympy differentiates Φ and Ψ through the *derived* equation of motion
  (Φ' = Ψ, Ψ' = φ̈/Ω²); mpmath evaluates the closed forms.  That they solve the derived
  equation with Φ(0) = φ0, Ψ(0) = 0 is checked numerically before first use (and in
  tests/test_pendulum.py against a direct integration).  This model decides what holds "along
  the motion": the energy integral, and the sign of φ̇ — negative on every other half-period.

The period follows the text's route: separation of variables in the first integral, the
substitution sin(φ/2) = k sin ψ (the trigonometric substitution that squares the radicand),
and sympy's integration, which returns elliptic_k(k²) — the parameter m = k², i.e. the modulus
k of the text's K(k).  The series (62)–(66) use the general term of the formal power series of
(1 − X)^(−1/2) (sympy's fps) and the Wallis integrals from their reduction formula
(integration by parts, solved by rsolve), truncated where the print truncates.
"""

from __future__ import annotations


import mpmath
import sympy as sp

from quasicentral.notation.domain import Domain
from quasicentral.engine.registry import derived, derives, shared
from quasicentral.notation.symbols import D
from quasicentral.engine.texts import symbols_of

S_ = symbols_of(__file__)  # this text's declared symbols (text.toml)
(E_tot, Cst, Omega, T_kin, Tper, V_pot, g, l, m, n, phi, phi0, t, v, vphi, w) = S_(
    "E Cst Omega Tkin T V g l m n phi phi0 t v vphi w")

Y = sp.Symbol("y_p")  # the text's y: vertical coordinate of the bob, downward (as the catalog creates it)
DVPHI, DW = sp.Symbol("dvphi"), sp.Symbol("dw")  # the differentials of (58), as the catalog creates them
N_S = sp.Symbol("n_s")  # a sampled real; the index n = floor(n_s) runs over the integers
KMOD = sp.sin(phi0 / 2)  # the modulus k of the substitution (57)
PRINTED_TERMS = 4  # (63), (65), (66) and the display before (65) print four terms, then "+ …"

ROOT = sp.sqrt(sp.cos(vphi) - sp.cos(phi0))  # the root (54)
INTEGRAND = 1 / sp.sqrt(1 - KMOD**2 * sp.sin(w) ** 2)  # the integrand of (60)–(63)
WALLIS = sp.Integral(sp.sin(w) ** (2 * n), (w, 0, sp.pi / 2))  # the left side of (64)

ANGLE_RANGE = Domain.of(ranges={vphi: (-phi0, phi0)})  # the angle swings between −φ0 and φ0
ANY_ANGLE = Domain.of(ranges={vphi: (-2 * sp.pi, 2 * sp.pi)})
PSI_ALL = Domain.of(ranges={w: (-sp.pi, sp.pi)})
PSI_TEXT = Domain.of(ranges={w: (-sp.pi / 2, sp.pi / 2)})  # the text: ψ ∈ (−π/2, π/2)
PSI_WIDE = Domain.of(ranges={w: (-2 * sp.pi, 2 * sp.pi)})
DIFFERENTIALS = Domain.of(ranges={w: (-sp.pi, sp.pi), DW: (-1, 1), DVPHI: (-1, 1)})
INTEGER_N = Domain.of(ranges={N_S: (1, 41)}, definitions={n: sp.floor(N_S)})  # n = 1 … 40
#: The text's stated branch: the rising quarter-swing φ: 0 → φ0 (φ̇ ≥ 0) that (53) integrates
#: over.  On the motion released from rest at φ0, φ = 2 asin(k sn(Ωt + K | k²)) rises from 0 to
#: φ0 for 3K ≤ Ωt ≤ 4K (K = K(m = k²), parameter convention, k = sin(φ0/2)).
_K = sp.elliptic_k(KMOD**2)
RISING_QUARTER = Domain.of(ranges={t: (3 * _K / Omega, 4 * _K / Omega)})


# --- mechanics -------------------------------------------------------------------------------
def position() -> sp.Matrix:
    """r = l(sin φ, cos φ): x horizontal, y downward (fig. 31)."""
    return sp.Matrix([l * sp.sin(phi), l * sp.cos(phi)])


def velocity() -> sp.Matrix:
    return position().diff(t)


@shared
def kinetic() -> sp.Expr:
    """T = ½ m ṙ·ṙ."""
    return sp.simplify(m * velocity().dot(velocity()) / 2)


def speed() -> sp.Expr:
    """v = |ṙ|."""
    return sp.sqrt(sp.simplify(velocity().dot(velocity())))


WEIGHT_Y = m * g  # the weight (0, mg) points along +y (down)


def potential_of_y() -> sp.Expr:
    """V(y) = −∫₀^y F_y dy': the work against the weight from the level of the suspension."""
    s_ = sp.Symbol("s_", real=True)
    return -sp.integrate(WEIGHT_Y, (s_, 0, Y))


def potential() -> sp.Expr:
    """V(φ) = V(y) at y = l cos φ."""
    return potential_of_y().subs(Y, position()[1])


@shared
def lagrangian() -> sp.Expr:
    """L = T − V."""
    return kinetic() - potential()


@shared
def acceleration() -> sp.Expr:
    """φ̈ from the Euler–Lagrange equation d/dt ∂L/∂φ̇ − ∂L/∂φ = 0."""
    (el,) = sp.calculus.euler.euler_equations(lagrangian(), phi, t)
    (sol,) = sp.solve(el, D(phi, 2))
    return sol


def energy_function() -> sp.Expr:
    """h = φ̇ ∂L/∂φ̇ − L, conserved because L has no explicit t."""
    lg = lagrangian()
    return sp.expand(D(phi) * sp.diff(lg, D(phi)) - lg)


def initial_value(expr: sp.Expr) -> sp.Expr:
    """expr at t = 0 of the motion released from rest at φ0 (φ̇ = 0, φ = φ0)."""
    return expr.subs(D(phi), 0).subs(phi, phi0)


def first_integral() -> sp.Expr:
    """H = 2h/(ml²) = φ̇² − (2g/l) cos φ."""
    return sp.expand(2 * energy_function() / (m * l**2))


@shared
def angular_speed(angle: sp.Expr) -> sp.Expr:
    """φ̇ as a function of the angle on the rising quarter (0 → φ0, φ̇ ≥ 0): the root of
    h(φ, φ̇) = h(φ0, 0) that is positive inside the swing."""
    h = energy_function()
    # the two roots of a quadratic in φ̇ as they come: sympy's clean-up of each (simplify) costs
    # ten times the solve and leaves them as they are
    roots = sp.solve(sp.Eq(h, initial_value(h)), D(phi), simplify=False)
    probe = {phi: sp.Rational(1, 2), phi0: 1, g: 1, l: 1, m: 1}
    (pos,) = [r for r in roots if sp.N(r.subs(probe)) > 0]
    return pos.subs(phi, angle)


# --- the exact motion released from rest at φ0 -----------------------------------------------
def _tau_acceleration(angle: sp.Expr) -> sp.Expr:
    """d²φ/dτ² in τ = Ωt: the Euler–Lagrange acceleration divided by Ω² = g/l."""
    return (acceleration() / (g / l)).subs(phi, angle)


def _modulus(p0):
    k_ = mpmath.sin(p0 / 2)
    return k_, k_**2


def _angle_value(tau, p0):
    k_, m_ = _modulus(p0)
    return 2 * mpmath.asin(k_ * mpmath.ellipfun("sn", tau + mpmath.ellipk(m_), m=m_))


def _rate_value(tau, p0):
    k_, m_ = _modulus(p0)
    return 2 * k_ * mpmath.ellipfun("cn", tau + mpmath.ellipk(m_), m=m_)


class pendulum_angle(sp.Function):  # noqa: N801 - a sympy function name
    """Φ(τ, φ0) = 2 asin(k sn(τ + K | k²)), k = sin(φ0/2): the angle at τ = Ωt.  Φ' = Ψ."""

    nargs = 2
    _imp_ = staticmethod(_angle_value)

    def fdiff(self, argindex=1):
        if argindex != 1:
            raise sp.ArgumentIndexError(self, argindex)
        return pendulum_rate(*self.args)


class pendulum_rate(sp.Function):  # noqa: N801 - a sympy function name
    """Ψ(τ, φ0) = 2k cn(τ + K | k²) = dΦ/dτ.  Ψ' = the derived acceleration at Φ."""

    nargs = 2
    _imp_ = staticmethod(_rate_value)

    def fdiff(self, argindex=1):
        if argindex != 1:
            raise sp.ArgumentIndexError(self, argindex)
        return _tau_acceleration(pendulum_angle(*self.args))


def check_closed_form(amplitudes=("0.3", "2", "3.1"), taus=("0.7", "2.9", "11.3"), dps=30) -> float:
    """Largest residual of the closed form against the derived equation of motion:
    Φ(0) = φ0, Ψ(0) = 0, dΦ/dτ = Ψ, dΨ/dτ = φ̈/Ω² at Φ (numerical derivatives)."""
    X = sp.Symbol("X")
    acc = sp.lambdify(X, _tau_acceleration(X), modules="mpmath")
    worst = mpmath.mpf(0)
    with mpmath.workdps(dps):
        for a in amplitudes:
            p0 = mpmath.mpf(a)
            worst = max(worst, abs(_angle_value(0, p0) - p0), abs(_rate_value(0, p0)))
            for s in taus:
                tau = mpmath.mpf(s)
                dphi = mpmath.diff(lambda x: _angle_value(x, p0), tau)
                drate = mpmath.diff(lambda x: _rate_value(x, p0), tau)
                worst = max(worst, abs(dphi - _rate_value(tau, p0)),
                            abs(drate - acc(_angle_value(tau, p0))))
    return float(worst)


@shared
def exact_motion() -> sp.Expr:
    """φ(t) = Φ(Ωt, φ0), after checking the closed form against the derived equation."""
    residual = check_closed_form()
    if not residual < 1e-20:
        raise RuntimeError(f"the closed-form motion misses the equation of motion by {residual:g}")
    return pendulum_angle(Omega * t, phi0)


def on_motion(expr: sp.Expr) -> sp.Expr:
    """expr along the exact motion."""
    return sp.sympify(expr).subs(phi, exact_motion()).doit()


# --- energy (49)–(51) and the prose ----------------------------------------------------------
@derives("pendulum:49", mode="substitute")
def conservation_of_energy():
    """T + V = E = const: E is the energy function h = φ̇∂L/∂φ̇ − L, its constant the value at
    t = 0; every side is evaluated along the exact motion."""
    h = energy_function()
    return {T_kin: on_motion(kinetic()), V_pot: on_motion(potential()), E_tot: on_motion(h),
            Cst: initial_value(h), phi: exact_motion()}


@derives("pendulum:kinetic-energy", mode="substitute")
def kinetic_energy():
    """T = ½ m ṙ·ṙ with v = |ṙ| = l|φ̇|, for r = l(sin φ, cos φ)."""
    return {T_kin: kinetic(), v: speed()}


@derives("pendulum:potential-energy", mode="substitute")
def potential_energy():
    """V = −∫ F·dr = −m g y (y downward, from the suspension), with y = l cos φ."""
    return {V_pot: potential(), Y: position()[1]}


@derives("pendulum:total-energy")
def total_energy():
    """E = h(φ0, φ̇ = 0) = −mgl cos φ0: the bob is released from rest at φ0."""
    return sp.Eq(E_tot, initial_value(energy_function()))


@derives("pendulum:50", mode="substitute")
def energy_equation():
    """½ml²φ̇² − mgl cos φ = −mgl cos φ0: h along the exact motion keeps its initial value."""
    return {phi: exact_motion()}


@derives("pendulum:51", mode="substitute", domain=RISING_QUARTER)
def angular_velocity():
    """φ̇ along the exact motion, on the text's stated branch (the rising quarter-swing).  Its
    magnitude is √(2(g/l)(cos φ − cos φ0)) by (50); its sign is that of cn(Ωt + K): positive on
    the rising quarter 3K < Ωt < 4K, negative for 0 < t < T/2 (the bob swings down from φ0)."""
    return {phi: exact_motion()}


@derives("pendulum:equation-of-motion", "pendulum:energy-product", "pendulum:energy-derivatives",
         "pendulum:energy-derivative-sum", mode="substitute")
def every_state_of_a_motion():
    """Euler–Lagrange: ml²φ̈ + mgl sin φ = 0, i.e. φ̈ = −(g/l) sin φ.  Each printed relation of
    the energy argument — the equation of motion, its product with φ̇, the derivatives
    d/dt(½φ̇²) − (g/l) d/dt(cos φ) = φ̇(φ̈ + (g/l) sin φ) and their sum — must hold on every state
    of every motion (φ̈ eliminated, φ and φ̇ free)."""
    return {D(phi, 2): acceleration()}


@derives("pendulum:energy-first-integral", mode="substitute")
def energy_first_integral():
    """H = 2h/(ml²) = φ̇² − (2g/l) cos φ is constant along the exact motion; the constant is its
    value at t = 0, −(2g/l) cos φ0."""
    return {phi: exact_motion(), Cst: initial_value(first_integral())}


@derives("pendulum:51-repeated", mode="substitute", domain=RISING_QUARTER)
def angular_velocity_repeated():
    """φ̇ along the exact motion on the rising quarter-swing (as for (51))."""
    return {phi: exact_motion()}


@derives("pendulum:separated-velocity", mode="substitute", domain=RISING_QUARTER)
def separated_velocity():
    """dφ/dt along the exact motion on the rising quarter-swing (as for (51))."""
    return {phi: exact_motion()}


@derives("pendulum:52", mode="substitute", domain=RISING_QUARTER)
def separated_differentials():
    """dt/dφ = 1/φ̇ along the exact motion (the differential relation dt = dφ/φ̇), on the rising
    quarter-swing."""
    return {phi: exact_motion()}


# --- the quarter period and the substitution (53)–(59) ---------------------------------------
@derives("pendulum:53", unknowns=(Tper,))
def quarter_period():
    """T/4 = ∫₀^φ0 dφ/φ̇(φ): the time of the rising quarter (φ from 0 to φ0, φ̇ > 0), by
    separation of variables in the first integral; T is four times it by the symmetry of the
    swing (the exact motion's period is checked against this in the tests)."""
    const, integrand = (1 / angular_speed(vphi)).as_independent(vphi, as_Add=False)
    return sp.Eq(Tper, 4 * const * sp.Integral(integrand, (vphi, 0, phi0)))


@derives("pendulum:54", mode="expression", domain=ANGLE_RANGE)
def root_of_integrand():
    """√(cos φ − cos φ0) = √(l/2g)·φ̇(φ): the root left in the integrand of (53)."""
    return sp.sqrt(sp.expand(sp.simplify(l / (2 * g) * angular_speed(vphi) ** 2)))


@shared
def double_angle() -> sp.Eq:
    """cos φ = cos(2·φ/2) = 2cos²(φ/2) − 1 = 1 − 2 sin²(φ/2) (expand_trig, then sin² + cos² = 1)."""
    a = sp.Symbol("a", real=True)
    expanded = sp.expand_trig(sp.cos(2 * a))
    expanded = expanded.subs(sp.cos(a) ** 2, 1 - sp.sin(a) ** 2)
    return sp.Eq(sp.cos(vphi), sp.expand(expanded).subs(a, vphi / 2))


@derives("pendulum:55", domain=ANY_ANGLE, unknowns=(sp.sin(vphi / 2) ** 2,))
def half_angle_identity():
    """sin²(φ/2) = (1 − cos φ)/2, from the double-angle formula."""
    return double_angle()


@derives("pendulum:cos-half-angle", domain=ANY_ANGLE)
def cos_half_angle():
    """cos φ = 1 − 2 sin²(φ/2), from the double-angle formula."""
    return double_angle()


def half_angle_form(expr: sp.Expr) -> sp.Expr:
    """Every cos(x) in expr rewritten as 1 − 2 sin²(x/2) (the derived double-angle formula)."""
    rel = derived("pendulum:cos-half-angle")
    lam = sp.Lambda(vphi, rel.rhs)
    return expr.replace(sp.cos, lambda x: lam(x))


@derives("pendulum:56", domain=ANGLE_RANGE, uses=("pendulum:54", "pendulum:cos-half-angle"), unknowns=(ROOT,))
def root_half_angles():
    """√(cos φ − cos φ0) = √(2(sin²(φ0/2) − sin²(φ/2))): both cosines in half angles."""
    root = derived("pendulum:54")
    return sp.Eq(root, sp.sqrt(sp.factor_terms(sp.expand(half_angle_form(root**2)))))


def radicand_target() -> sp.Expr:
    """What the substitution must achieve: sin²(φ0/2) − sin²(φ/2) = sin²(φ0/2) cos²ψ, the
    trigonometric substitution for √(a² − x²) with a = sin(φ0/2), x = sin(φ/2)."""
    rhs = derived("pendulum:56").rhs
    radicand = sp.factor_terms(rhs**2) / 2  # sin²(φ0/2) − sin²(φ/2)
    return sp.expand(radicand) - KMOD**2 * sp.cos(w) ** 2


@derives("pendulum:57", mode="condition", domain=PSI_ALL, uses=("pendulum:56",))
def substitution():
    """sin(φ/2) = sin(φ0/2) sin ψ must turn the radicand of (56) into sin²(φ0/2) cos²ψ:
    returns sin²(φ0/2) − sin²(φ/2) − sin²(φ0/2) cos²ψ, which the printed substitution must
    make vanish."""
    return radicand_target()


@shared
def angle_of_w() -> sp.Expr:
    """φ(ψ) solved from (57) on the branch with φ(0) = 0: 2 asin(sin(φ0/2) sin ψ); it maps
    ψ ∈ [0, π/2] increasingly onto [0, φ0]."""
    (rel,) = derived_substitution()
    sols = sp.solve(rel, vphi, simplify=False)  # the inverse sine's two branches, as they come
    (branch,) = [s_ for s_ in sols if sp.simplify(s_.subs(w, 0)) == 0]
    return branch


def derived_substitution():
    """The substitution (57) as derived: the root x of a² − x² = a² cos²ψ (a = sin(φ0/2),
    x = sin(φ/2)) that rises with ψ — sympy gives ±a|sin ψ| — continued analytically through
    ψ = 0 (|sin ψ| = sin ψ on [0, π/2]): sin(φ/2) = sin(φ0/2) sin ψ."""
    x = sp.Symbol("x")
    roots = sp.solve(sp.Eq(KMOD**2 - x**2, KMOD**2 * sp.cos(w) ** 2), x)
    (root,) = [r for r in roots if sp.N(r.subs({w: sp.Rational(1, 3), phi0: 1})) > 0]
    root = root.replace(sp.Abs, lambda a: a)
    return (sp.Eq(sp.sin(vphi / 2), root),)


@derives("pendulum:58", mode="substitute", domain=DIFFERENTIALS)
def substitution_differential():
    """dφ = φ'(ψ) dψ with φ(ψ) = 2 asin(sin(φ0/2) sin ψ): the differential of (57), computed."""
    x = angle_of_w()
    return {vphi: x, DVPHI: sp.diff(x, w) * DW}


@derives("pendulum:59-derivation", mode="substitute", domain=PSI_ALL)
def root_substituted_steps():
    """The chain of (56) with φ = φ(ψ) from (57) substituted."""
    return {vphi: angle_of_w()}


@derives("pendulum:59", mode="substitute", domain=PSI_TEXT)
def root_substituted():
    """√(cos φ − cos φ0) at φ = φ(ψ): √(2 sin²(φ0/2) cos²ψ) = √2 sin(φ0/2)|cos ψ|, which is
    √2 sin(φ0/2) cos ψ on the text's range ψ ∈ (−π/2, π/2)."""
    return {vphi: angle_of_w()}


def pythagoras_root() -> sp.Eq:
    """√(1 − sin²ψ) = √(cos²ψ) = |cos ψ| (sin² + cos² = 1, ψ real)."""
    lhs = sp.sqrt(1 - sp.sin(w) ** 2)
    return sp.Eq(lhs, sp.sqrt((1 - sp.sin(w) ** 2).subs(sp.sin(w) ** 2, 1 - sp.cos(w) ** 2)))


@derives("pendulum:sqrt-cos-step", domain=PSI_TEXT, unknowns=(sp.sqrt(1 - sp.sin(w) ** 2),))
def sqrt_cos_step():
    """√(1 − sin²ψ) = |cos ψ|, checked on the text's range ψ ∈ (−π/2, π/2) where |cos ψ| = cos ψ."""
    return pythagoras_root()


@derives("pendulum:sqrt-abs-cos", domain=PSI_WIDE, unknowns=(sp.sqrt(1 - sp.sin(w) ** 2),))
def sqrt_abs_cos():
    """√(1 − sin²ψ) = |cos ψ| for every real ψ."""
    return pythagoras_root()


# --- the period as an elliptic integral (60)–(61) --------------------------------------------
@shared
def period_integrand() -> sp.Expr:
    """dT/dψ: 4·(dt/dφ)(dφ/dψ) with dt/dφ = 1/φ̇(φ) (53) and φ = φ(ψ) (57), simplified with
    the radicand √(cos φ − cos φ0) = √2 sin(φ0/2) cos ψ (cos ψ ≥ 0 on [0, π/2])."""
    kp = sp.Symbol("kappa_p", positive=True)  # sin(φ0/2) > 0 for 0 < φ0 < π
    c = sp.Symbol("c_p", positive=True)  # cos ψ > 0 inside [0, π/2]
    x = angle_of_w()
    dx = sp.diff(x, w)
    speed_ = angular_speed(x)
    # cos φ(ψ) by the double angle, cos φ0 by the half angle
    speed_ = speed_.replace(sp.cos, lambda a: sp.expand_trig(half_angle_form(sp.cos(a))))
    expr = 4 * dx / speed_
    expr = expr.subs(KMOD, kp).subs(sp.cos(w), c)
    expr = expr.subs(sp.sin(w) ** 2, 1 - c**2)
    expr = sp.simplify(sp.powdenest(sp.factor(expr), force=True))
    return sp.expand(expr.subs(c, sp.sqrt(1 - sp.sin(w) ** 2)).subs(kp, KMOD))


@shared
def period_integral() -> sp.Expr:
    """T = ∫₀^{π/2} dT/dψ dψ, the constant factor taken out of the integral."""
    const, integrand = period_integrand().as_independent(w, as_Add=False)
    return const * sp.Integral(integrand, (w, 0, sp.pi / 2))


@shared
def period() -> sp.Expr:
    """T = ∫₀^{π/2} dT/dψ dψ integrated by sympy: 4√(l/g) K(m = sin²(φ0/2)) (sympy's
    elliptic_k takes the parameter m = k²).  The tests compare it with a direct integration of
    the equation of motion and with the exact motion's period."""
    kp = sp.Symbol("kappa_p", positive=True)
    f = period_integrand().subs(KMOD, kp)
    return sp.integrate(f, (w, 0, sp.pi / 2)).subs(kp, KMOD)


@derives("pendulum:quarter-period-substituted", mode="substitute", uses=("pendulum:cos-half-angle",))
def quarter_period_substituted():
    """T/4 with (58), (59) substituted: φ in the ψ-integrand is φ(ψ) of (57); T is the derived
    period."""
    return {Tper: period_integral(), vphi: angle_of_w()}


@derives("pendulum:quarter-period-cos", mode="substitute", uses=("pendulum:cos-half-angle",))
def quarter_period_cos():
    """T/4 = √(l/g)∫ dψ / cos(φ/2) = √(l/g)∫ dψ/√(1 − sin²(φ/2)), φ = φ(ψ) of (57)."""
    return {Tper: period_integral(), vphi: angle_of_w()}


@derives("pendulum:60", uses=("pendulum:cos-half-angle",))
def period_elliptic():
    """T = 4√(l/g) ∫₀^{π/2} dψ/√(1 − sin²(φ0/2) sin²ψ): the integral of the substituted
    integrand (53) → (57)–(59), computed by the chain rule."""
    return sp.Eq(Tper, period_integral())


@derives("pendulum:61", mode="substitute")
def elliptic_k_definition():
    """K(k) = ∫₀^{π/2} dψ/√(1 − k² sin²ψ) with the modulus k (Kc(k) = elliptic_k(m = k²)).  A
    definition: the check confronts the printed modulus notation with sympy's elliptic_k(m)."""
    return {}


# --- the series (62)–(66) --------------------------------------------------------------------
@shared
def binomial_series():
    """The formal power series of (1 − X)^(−1/2) (sympy fps) and its general term a(n)."""
    X = sp.Symbol("X")
    ser = sp.fps((1 - X) ** sp.Rational(-1, 2), X)
    formula = ser.ak.formula
    if isinstance(formula, sp.Piecewise):
        formula = formula.args[0][0]  # the branch for integer index
    term = formula.subs(ser.ak.variables[0], n)
    return X, ser, term


def series_argument() -> sp.Expr:
    """X = (sin(φ0/2) sin ψ)², the integrand being (1 − X)^(−1/2)."""
    return (KMOD * sp.sin(w)) ** 2


@derives("pendulum:62", unknowns=(INTEGRAND,))
def integrand_series():
    """(1 − X)^(−1/2) = 1 + Σ_{n≥1} a(n) Xⁿ, a(n) = (1/2)_n / n! (the binomial series)."""
    X, _, term = binomial_series()
    return sp.Eq(INTEGRAND, 1 + sp.Sum(term * series_argument() ** n, (n, 1, sp.oo)))


def truncated_integrand() -> sp.Expr:
    """The binomial series truncated after PRINTED_TERMS terms (fps.truncate)."""
    X, ser, _ = binomial_series()
    return ser.truncate(PRINTED_TERMS).removeO().subs(X, series_argument())


@derives("pendulum:63", unknowns=(INTEGRAND,))
def integrand_series_terms():
    """(1 − X)^(−1/2) ≈ Σ_{n<4} a(n) Xⁿ, truncated where the print truncates."""
    return sp.Eq(INTEGRAND, truncated_integrand())


@shared
def wallis() -> sp.Expr:
    """I(n) = ∫₀^{π/2} sin^{2n}ψ dψ by the reduction formula: d/dψ(sin^{2n−1}ψ cos ψ) =
    (2n−1) sin^{2n−2}ψ − 2n sin^{2n}ψ integrates to 0 = (2n−1)I(n−1) − 2n I(n); rsolve with
    I(0) = π/2."""
    s_ = sp.sin(w)
    boundary = s_ ** (2 * n - 1) * sp.cos(w)
    rate = sp.expand(sp.diff(boundary, w).subs(sp.cos(w) ** 2, 1 - s_**2))
    claim = (2 * n - 1) * s_ ** (2 * n - 2) - 2 * n * s_ ** (2 * n)
    if sp.simplify(sp.powsimp(sp.expand(rate - claim))) != 0:
        raise RuntimeError("the integration by parts of sin^(2n) does not reduce")
    ends = boundary.subs(w, sp.pi / 2) - boundary.subs(w, 0)  # 0 for n ≥ 1
    Ifn = sp.Function("I")
    rec = ends - ((2 * n - 1) * Ifn(n - 1) - 2 * n * Ifn(n))
    return sp.rsolve(rec, Ifn(n), {Ifn(0): sp.integrate(1, (w, 0, sp.pi / 2))})


@derives("pendulum:64", domain=INTEGER_N, unknowns=(WALLIS,))
def wallis_integral():
    """∫₀^{π/2} sin^{2n}ψ dψ = (π/2)·(1/2)_n / n!, for symbolic n (reduction formula)."""
    return sp.Eq(WALLIS, wallis())


@derives("pendulum:double-factorial-even", domain=INTEGER_N, unknowns=(sp.factorial2(2 * n),))
def double_factorial_even():
    """(2n)!! = 2·4·…·2n = ∏_{j=1}^n 2j."""
    j = sp.Symbol("j", integer=True, positive=True)
    return sp.Eq(sp.factorial2(2 * n), sp.product(2 * j, (j, 1, n)))


def truncated_period() -> sp.Expr:
    """T truncated where the print truncates: the prefactor of the integrand times
    Σ_{n<4} a(n) sin^{2n}(φ0/2)·I(n), the series integrated term by term."""
    _, _, term = binomial_series()
    prefactor = sp.simplify(period_integrand() / INTEGRAND)
    if prefactor.has(w):
        raise RuntimeError("the period integrand is not a multiple of (1 − k² sin²ψ)^(−1/2)")
    total = sum(term.subs(n, j) * KMOD ** (2 * j) * wallis().subs(n, j) for j in range(PRINTED_TERMS))
    return prefactor * total


@derives("pendulum:period-series-integral", unknowns=(Tper,), uses=("pendulum:cos-half-angle",))
def period_series_integral():
    """T ≈ 4√(l/g) ∫₀^{π/2} Σ_{n<4} a(n) (sin(φ0/2) sin ψ)^{2n} dψ: the period integral with
    the integrand replaced by its truncated binomial series."""
    const, integrand = period_integrand().as_independent(w, as_Add=False)
    if sp.simplify(integrand - INTEGRAND) != 0:
        raise RuntimeError("the period integrand is not a multiple of (1 − k² sin²ψ)^(−1/2)")
    return sp.Eq(Tper, const * sp.Integral(truncated_integrand(), (w, 0, sp.pi / 2)))


@derives("pendulum:65", unknowns=(Tper,), uses=("pendulum:cos-half-angle",))
def period_series():
    """T ≈ 4√(l/g) Σ_{n<4} a(n) I(n) sin^{2n}(φ0/2)."""
    return sp.Eq(Tper, truncated_period())


@derives("pendulum:66", unknowns=(Tper,), uses=("pendulum:cos-half-angle",))
def period_series_factored():
    """T ≈ 2π√(l/g) Σ_{n<4} a(n) (2I(n)/π) sin^{2n}(φ0/2): (65) with π/2 taken out."""
    return sp.Eq(Tper, truncated_period())
