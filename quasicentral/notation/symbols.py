"""The project's one namespace: every symbol and function the catalog and the derivations use.

A catalog transcription is a string of sympy syntax read in :data:`NAMESPACE`; a derivation
imports the same objects from here, so that a printed and a derived expression share symbols.

Conventions (stated once, used everywhere):

* Quantities that change along the motion are applied functions of time ``t``:
  ``x, y, rho, psi, phi, s, v`` are ``x(t)``, ...; ``D(f)`` is df/dt and ``D(f, 2)`` d²f/dt²,
  kept unevaluated so a transcription stays what was printed.
* Plain variables of integration or substitution are symbols: ``th`` (the paper's φ = Ωt in
  section 5), ``z`` (φ = π/2 − z), ``zeta`` (ζ = sin z), ``vphi`` (the pendulum's φ as an
  integration variable) and ``w`` (its ψ of substitution (57)).
* Elliptic integrals in the *paper's* (Jacobi) form take the modulus k and the sine of the
  amplitude ζ: ``Fj(k, zeta) = F(asin ζ | k²)``, ``Ej(k, zeta) = E(asin ζ | k²)``; the
  complete ones ``Kc(k) = K(k²)``, ``Ec(k) = E(k²)``.  sympy, mpmath, scipy and python-flint
  all take the *parameter* m = k², which these wrappers pass on.
* ``arccotg`` is the Czech arccotangent with values in (0, π): arccotg x = π/2 − atan x
  (sympy's ``acot`` jumps at 0 and takes values in (−π/2, π/2]).
* Dimensions are monomials in the base symbols ``L`` (length), ``T`` (time), ``M`` (mass).
"""

from __future__ import annotations

import sympy as sp

# --- base dimensions -------------------------------------------------------------------------
L, T, M = sp.symbols("L T M", positive=True)
DIMENSIONLESS = sp.Integer(1)

# --- time and the parameters of the texts ----------------------------------------------------
t = sp.Symbol("t", nonnegative=True)
m = sp.Symbol("m", positive=True)  # mass of the bob
g = sp.Symbol("g", positive=True)
l = sp.Symbol("l", positive=True)  # noqa: E741  (the paper's pendulum length)
Omega = sp.Symbol("Omega", positive=True)  # Ω = sqrt(g/l)
omega = sp.Symbol("omega", positive=True)  # ω = sqrt(Ω² − κ²), damped frequency
kappa = sp.Symbol("kappa", nonnegative=True)  # linear drag R = 2κmv, [1/s]
beta = sp.Symbol("beta", nonnegative=True)  # quadratic drag R = mβv², [1/m]
R0 = sp.Symbol("R_0", positive=True)  # initial distance from the vertical
v0 = sp.Symbol("v_0", positive=True)  # initial speed, perpendicular to R0
u = sp.Symbol("u", positive=True)  # u = R0 Ω
k = sp.Symbol("k", real=True)  # modulus, k² = (u² − v0²)/u²  (k² may be < 0 when u < v0)
k2 = sp.Symbol("k2", real=True)  # the parameter m = k², where it is used on its own
lam = sp.Symbol("lambda")  # root of the characteristic equation (complex in general)
phi0 = sp.Symbol("varphi_0", positive=True)  # amplitude of the planar pendulum
Tper = sp.Symbol("T", positive=True)  # a period
E_tot = sp.Symbol("E", real=True)  # total energy (pendulum text)
T_kin = sp.Symbol("T_kin", nonnegative=True)  # kinetic energy (pendulum text writes T)
V_pot = sp.Symbol("V", real=True)  # potential energy
# generic forces and angles of section 2 and 4
S = sp.Symbol("S", real=True)  # central force
R = sp.Symbol("R", nonnegative=True)  # drag force magnitude
alpha = sp.Symbol("alpha", real=True)  # direction angle of the velocity
vx = sp.Symbol("v_x", real=True)
vy = sp.Symbol("v_y", real=True)
ax = sp.Symbol("a_x", real=True)
ay = sp.Symbol("a_y", real=True)
# integration constants (their dimensions differ by section: see the catalog's `dims`)
A, B, C, D_, Cst = sp.symbols("A B C D Cst", real=True)
K1, L1, M1, N1 = sp.symbols("K_1 L_1 M_1 N_1", real=True)  # K, L, M, N of (18)
C1, C2, C3, C4 = sp.symbols("C_1 C_2 C_3 C_4", real=True)
D1, D2 = sp.symbols("D_1 D_2", real=True)
# variables of integration and substitution
th = sp.Symbol("theta", real=True)  # section 5: φ = Ωt
z = sp.Symbol("z", real=True)
zeta = sp.Symbol("zeta", real=True)
vphi = sp.Symbol("vphi", real=True)  # pendulum: φ as a variable
w = sp.Symbol("w", real=True)  # pendulum: ψ of (57)
n = sp.Symbol("n", integer=True, positive=True)  # summation index (the pendulum's m)

# --- quantities along the motion: applied functions of t -------------------------------------
x = sp.Function("x", real=True)(t)
y = sp.Function("y", real=True)(t)
rho = sp.Function("rho", positive=True)(t)
psi = sp.Function("psi", real=True)(t)
phi = sp.Function("phi", real=True)(t)
s = sp.Function("s", nonnegative=True)(t)  # arc length
v = sp.Function("v", positive=True)(t)  # speed
MOTION = (x, y, rho, psi, phi, s, v)


def D(f, order: int = 1):
    """d^order f / dt^order, unevaluated (a transcription keeps what was printed)."""
    return sp.Derivative(f, (t, order))


# --- the paper's elliptic notation -----------------------------------------------------------
def Fj(kk, zz):
    """F(k, ζ) = ∫₀^ζ dζ/√((1−ζ²)(1−k²ζ²)) = F(asin ζ | m = k²)  (Jacobi form, modulus k)."""
    return sp.elliptic_f(sp.asin(zz), kk**2)


def Ej(kk, zz):
    """E(k, ζ) = ∫₀^ζ √((1−k²ζ²)/(1−ζ²)) dζ = E(asin ζ | m = k²)."""
    return sp.elliptic_e(sp.asin(zz), kk**2)


def Kc(kk):
    """K = F(k, 1) = K(m = k²), the complete integral of the first kind, modulus k."""
    return sp.elliptic_k(kk**2)


def Ec(kk):
    """E = E(k, 1) = E(m = k²), the complete integral of the second kind, modulus k."""
    return sp.elliptic_e(kk**2)


def arccotg(a):
    """Czech arccotg with values in (0, π): π/2 − atan a."""
    return sp.pi / 2 - sp.atan(a)


# --- dimensions ------------------------------------------------------------------------------
DIMS: dict[sp.Basic, sp.Expr] = {
    t: T, m: M, g: L / T**2, l: L, Omega: 1 / T, omega: 1 / T, kappa: 1 / T, beta: 1 / L,
    R0: L, v0: L / T, u: L / T, k: DIMENSIONLESS, k2: DIMENSIONLESS, lam: 1 / T,
    phi0: DIMENSIONLESS, Tper: T, E_tot: M * L**2 / T**2, T_kin: M * L**2 / T**2,
    V_pot: M * L**2 / T**2, S: M * L / T**2, R: M * L / T**2, alpha: DIMENSIONLESS,
    vx: L / T, vy: L / T, ax: L / T**2, ay: L / T**2,
    A: L**2 / T, B: L**2 / T, C: 1 / T, D_: L / T, Cst: 1 / T,
    K1: L, L1: L, M1: L, N1: L, C1: L, C2: L, C3: L, C4: L, D1: L, D2: L,
    th: DIMENSIONLESS, z: DIMENSIONLESS, zeta: DIMENSIONLESS, vphi: DIMENSIONLESS,
    w: DIMENSIONLESS, n: DIMENSIONLESS,
    x: L, y: L, rho: L, psi: DIMENSIONLESS, phi: DIMENSIONLESS, s: L, v: L / T,
}


def parse_dim(text: str) -> sp.Expr:
    """'L^2/T' -> L**2/T; '1' -> 1."""
    return sp.sympify(text.replace("^", "**"), locals={"L": L, "T": T, "M": M})


# --- the namespace a transcription is read in -----------------------------------------------
def _names() -> dict[str, object]:
    ns: dict[str, object] = {}
    for sym in DIMS:
        if isinstance(sym, sp.Symbol):
            ns[sym.name] = sym
    ns.update({
        "R0": R0, "v0": v0, "phi0": phi0, "vx": vx, "vy": vy, "ax": ax, "ay": ay,
        "T": Tper, "E": E_tot, "Tkin": T_kin, "V": V_pot, "D_": D_, "th": th,
        "K1": K1, "L1": L1, "M1": M1, "N1": N1, "C1": C1, "C2": C2, "C3": C3, "C4": C4,
        "D1": D1, "D2": D2, "lam": lam,
        "x": x, "y": y, "rho": rho, "psi": psi, "phi": phi, "s": s, "v": v,
        "D": D, "Fj": Fj, "Ej": Ej, "Kc": Kc, "Ec": Ec, "arccotg": arccotg,
        "Eq": sp.Eq, "Integral": sp.Integral, "Derivative": sp.Derivative, "Sum": sp.Sum,
        "sqrt": sp.sqrt, "sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "exp": sp.exp,
        "log": sp.log, "asin": sp.asin, "acos": sp.acos, "atan": sp.atan, "pi": sp.pi,
        "oo": sp.oo, "I": sp.I, "Rational": sp.Rational, "factorial": sp.factorial,
        "factorial2": sp.factorial2, "elliptic_k": sp.elliptic_k, "elliptic_f": sp.elliptic_f,
        "elliptic_e": sp.elliptic_e, "Abs": sp.Abs, "n": n,
    })
    return ns


NAMESPACE = _names()


def parse(text: str) -> sp.Basic:
    """Read a transcription (sympy syntax) in the project's namespace, without evaluation
    of derivatives or integrals (``Derivative``/``Integral`` stay unevaluated)."""
    from sympy.parsing.sympy_parser import auto_number, parse_expr

    # no auto_symbol: an unknown name is an error, not a fresh symbol
    return parse_expr(text, local_dict=dict(NAMESPACE), transformations=(auto_number,),
                      global_dict={"__builtins__": {}, **_GLOBALS}, evaluate=True)


_GLOBALS = {"Integer": sp.Integer, "Float": sp.Float, "Symbol": sp.Symbol, "Rational": sp.Rational,
            "Function": sp.Function}
