"""The special functions of DLMF chapters 19 and 22 (quasicentral.notation.special): every
function against itself at two precisions, against python-flint's balls and sympy's evalf, at
real and complex points (dyadic, so that mpmath and flint see the same numbers); pinned values
from independent sources (DLMF's closed forms, Carlson's 1995 tables, Boost's data); the
identities of the chapters; derivatives against numerical differentiation; the convention
traps (modulus vs parameter, flint's π-scaled theta, the branch of K′)."""

from __future__ import annotations

import os
import types

import flint
import mpmath
import pytest
import sympy as sp
from flint import acb, arb

from quasicentral.notation import special
from quasicentral.notation.special import FUNCTIONS
from quasicentral.notation.special import base, bulirsch, carlson, jacobi, legendre, theta

S = FUNCTIONS
J = 1j

# --- sample points: dyadic numbers (exact in binary), real and complex, each function ----------

INVERSE_POINTS = {
    "sn": -0.375, "cn": -0.375, "dn": 0.875, "cd": -0.375, "sd": 1.25, "nd": 1.125,
    "dc": -3.0, "nc": -3.0, "sc": 2.0, "ns": 3.0, "ds": 2.0, "cs": -2.0,
}

POINTS = {
    "EllipticK": [(0.625,), (0.5 + 0.25j,), (-0.375j,), (1.5,)],
    "EllipticE": [(0.625,), (0.5 + 0.25j,), (1.5,), (0.75, 0.625), (2.5, 0.625),
                  (0.5 + 0.25j, 0.375 + 0.125j), (-4.0, 0.875)],
    "EllipticF": [(0.75, 0.625), (2.5, 0.625), (0.5 + 0.25j, 0.375 + 0.125j), (-4.0, 0.875)],
    "EllipticD": [(0.625,), (0.5 + 0.25j,), (0.75, 0.625), (2.5, 0.625),
                  (0.5 + 0.25j, 0.375 + 0.125j), (-4.0, 0.875)],
    "EllipticPi": [(0.25, 0.625), (2.0, 0.625), (-0.5 + 0.25j, 0.375 + 0.125j), (0.75, 0.25, 0.625),
                   (2.5, 0.25, 0.625), (1.25, 2.0, 0.625), (0.5 + 0.25j, -0.5 + 0.25j, 0.375 + 0.125j)],
    "EllipticKp": [(0.625,), (0.5 + 0.25j,), (0.03125,)],
    "EllipticEp": [(0.625,), (0.5 + 0.25j,), (0.03125,)],
    "AGM": [(1.0, 0.375), (1 + 2j, -3 + 0.5j), (0.5, 0.25j)],
    "JacobiZeta": [(0.75, 0.625), (2.5, 0.875), (0.5 + 0.25j, 0.375 + 0.125j)],
    "HeumanLambda": [(0.75, 0.625), (2.5, 0.875), (0.5 + 0.25j, 0.375 + 0.125j)],
    "CarlsonRF": [(1.0, 2.0, 3.0), (0.5 + 0.25j, 2.0, 0.0), (1j, -1j, 2.0)],
    "CarlsonRD": [(0.0, 2.0, 1.0), (1j, -1j, 2.0), (2.0, 3.0, 4.0)],
    "CarlsonRJ": [(0.0, 1.0, 2.0, 3.0), (2.0, 3.0, 4.0, -0.5), (1j, -1j, 0.0, 2.0), (2.0, 3.0, 4.0, -1 + 1j)],
    "CarlsonRC": [(0.0, 0.25), (0.25, -2.0), (1j, -1.0), (-1j, 1j)],
    "CarlsonRG": [(0.0, 16.0, 16.0), (2.0, 3.0, 4.0), (-1 + 1j, 1j, 0.0)],
    "BulirschCel": [(0.625, 1.5, 1.0, 0.25), (0.625, -0.5, 1.0, 1.0), (0.5 + 0.25j, 1.25, 1.0, 0.5)],
    "BulirschEl1": [(2.0, 0.625), (0.5 + 0.25j, 0.375), (-1.5, 0.625)],
    "BulirschEl2": [(2.0, 0.625, 1.0, 0.5), (0.5 + 0.25j, 0.375, 0.5, 2.0)],
    "BulirschEl3": [(2.0, 0.625, 0.25), (2.0, 0.625, -0.5), (0.5 + 0.25j, 0.375, 0.5)],
    "JacobiAM": [(0.75, 0.625), (9.0, 0.875), (0.25 + 0.125j, 0.625)],
    "JacobiEpsilon": [(0.75, 0.625), (3.0, 0.875), (0.5 + 0.75j, 0.375 + 0.125j)],
    "JacobiZ": [(0.75, 0.625), (3.0, 0.875), (0.5 + 0.75j, 0.375 + 0.125j)],
    "EllipticNome": [(0.625,), (0.5 + 0.25j,), (0.96875,)],
    "WeierstrassP": [(0.375, 1.0, 0.25 + 1.125j), (0.25 + 0.5j, 0.75, -0.25 + 1.0j)],
    "WeierstrassZeta": [(0.375, 1.0, 0.25 + 1.125j), (0.25 + 0.5j, 0.75, -0.25 + 1.0j)],
    "WeierstrassSigma": [(0.375, 1.0, 0.25 + 1.125j), (0.25 + 0.5j, 0.75, -0.25 + 1.0j)],
}
for _name in ("SN", "CN", "DN", "NS", "NC", "ND", "SC", "SD", "CS", "CD", "DS", "DC"):
    POINTS["Jacobi" + _name] = [(0.75, 0.625), (0.5 + 0.75j, 0.375 + 0.125j), (3.5, 0.875), (0.625, 1.5),
                                (0.25 + 0.5j, -0.5j)]
    POINTS["JacobiArc" + _name] = [(INVERSE_POINTS[_name.lower()], 0.625), (0.5 + 0.25j, 0.625)]
for _j in (1, 2, 3, 4):
    POINTS["JacobiTheta%d" % _j] = [(0.375, 0.25), (0.5 + 0.25j, 0.125 + 0.25j), (1.25, -0.25), (0.75, 0.75)]

#: the functions whose derivatives this suite checks need no quadrature at every point
CASES = [(name, args) for name, points in POINTS.items() for args in points]


def test_every_function_has_points_and_only_carlson_r_lacks_a_ball():
    assert set(POINTS) | {"CarlsonR"} == set(FUNCTIONS)
    assert [name for name, cls in FUNCTIONS.items() if cls.ball is None] == ["CarlsonR"]


def mp_args(args):
    return [mpmath.mpmathify(a) for a in args]


def acb_args(args):
    return [acb(complex(a)) if isinstance(a, complex) else acb(a) for a in args]


def sympy_args(args):
    out = []
    for a in args:
        a = complex(a)
        out.append(sp.Float(a.real) + sp.I * sp.Float(a.imag) if a.imag else sp.Float(a.real))
    return out


def to_mp(x):
    """An arb's midpoint (or an exact arb such as a radius) as an mpf, exactly."""
    man, exp = x.mid().man_exp()
    return mpmath.mpf((int(man), int(exp)))


def ball_mid(ball):
    return mpmath.mpc(to_mp(ball.real), to_mp(ball.imag))


def close(a, b, tol):
    return abs(a - b) <= tol * max(1, abs(a), abs(b))


@pytest.mark.parametrize("name,args", CASES, ids=[f"{n}{a}" for n, a in CASES])
def test_mpmath_ladder_sympy_evalf_and_flint_ball_agree(name, args):
    cls = FUNCTIONS[name]
    with mpmath.workdps(30):
        v30 = cls.mp(*mp_args(args))
    with mpmath.workdps(60):
        v60 = cls.mp(*mp_args(args))
        assert mpmath.isfinite(v60)
        assert close(v30, v60, mpmath.mpf(10) ** -28), (v30, v60)
    # sympy's N at 30 digits goes through the same route
    n30 = sp.N(cls(*sympy_args(args)), 30)
    with mpmath.workdps(30):
        assert close(mpmath.mpmathify(complex(n30)) if n30.has(sp.I) else mpmath.mpf(str(n30)), v30, 1e-14)
    # the ball at 200 bits contains the 60-digit value and is narrow
    before = flint.ctx.prec
    flint.ctx.prec = 200
    try:
        ball = cls.ball(*acb_args(args))
        assert flint.ctx.prec == 200
    finally:
        flint.ctx.prec = before
    assert ball.is_finite(), ball
    with mpmath.workdps(60):
        mid = ball_mid(ball)
        rad = to_mp(ball.rad())
        assert abs(v60 - mid) <= rad + mpmath.mpf(10) ** -55 * max(1, abs(v60)), (v60, ball)
        assert rad <= mpmath.mpf(10) ** -45 * max(1, abs(v60)), ball


def test_evalf_at_30_digits_as_the_brief_writes_it():
    value = sp.N(special.JacobiSN(sp.Rational(1, 3), sp.Rational(1, 2)), 30)
    with mpmath.workdps(30):
        assert mpmath.almosteq(mpmath.mpf(str(value)), mpmath.ellipfun("sn", mpmath.mpf(1) / 3, m=0.25), 1e-29)
    assert special.JacobiSN(sp.Symbol("z"), sp.Symbol("k")).evalf() == special.JacobiSN(sp.Symbol("z"), sp.Symbol("k"))


# --- pinned values from independent sources ----------------------------------------------------

#: K(1/√2) = Γ(1/4)²/(4√π) and E(1/√2) = Γ(1/4)²/(8√π) + π^{3/2}/Γ(1/4)² (DLMF 19.20.2 area,
#: the lemniscatic case), θ₃(0, e^{−π}) = π^{1/4}/Γ(3/4) (DLMF 20.?): 60 digits
K_LEMNISCATE = "1.85407467730137191843385034719526004621759882352176690558593"
E_LEMNISCATE = "1.35064388104767550252017473533872584134952236692435454532325"
THETA3_E_PI = "1.08643481121330801457531612151022345707020570724521888592079"
#: the lemniscate constant ϖ = π/M(1, √2) (DLMF 19.8 with 23.17 area)
VARPI = "2.62205755429211981046483958989111941368275495143162316281682"


def test_lemniscatic_closed_forms_at_60_digits():
    with mpmath.workdps(60):
        k = 1 / mpmath.sqrt(2)
        K, E = mpmath.mpf(K_LEMNISCATE), mpmath.mpf(E_LEMNISCATE)
        tol = mpmath.mpf(10) ** -57
        g = mpmath.gamma(mpmath.mpf(1) / 4)
        assert mpmath.almosteq(K, g ** 2 / (4 * mpmath.sqrt(mpmath.pi)), tol)  # the literal is the closed form
        for value, expected in [
            (S["EllipticK"].mp(k), K), (S["EllipticE"].mp(k), E), (S["EllipticKp"].mp(k), K),
            (S["EllipticEp"].mp(k), E), (S["EllipticF"].mp(mpmath.pi / 2, k), K),
            (S["CarlsonRF"].mp(0, mpmath.mpf(1) / 2, 1), K), (2 * S["CarlsonRG"].mp(0, mpmath.mpf(1) / 2, 1), E),
            (S["BulirschCel"].mp(k, 1, 1, 1), K), (S["BulirschCel"].mp(k, 1, 1, k ** 2), E),
            (S["JacobiArcSN"].mp(1, k), K), (S["JacobiArcCN"].mp(0, k), K), (S["JacobiArcCD"].mp(0, k), K),
            (S["JacobiEpsilon"].mp(K, k), E), (2 * S["JacobiAM"].mp(K, k), mpmath.pi),
            (S["EllipticNome"].mp(k), mpmath.exp(-mpmath.pi)),  # K′ = K
            (S["JacobiTheta3"].mp(0, mpmath.exp(-mpmath.pi)), mpmath.mpf(THETA3_E_PI)),
            (mpmath.pi / S["AGM"].mp(1, mpmath.sqrt(2)), mpmath.mpf(VARPI)),
            (S["CarlsonRF"].mp(0, 1, 2), mpmath.mpf(VARPI) / 2),
            # DLMF 22.5.2: sn, cn, dn at K/2
            (S["JacobiSN"].mp(K / 2, k), 1 / mpmath.sqrt(1 + k)),
            (S["JacobiCN"].mp(K / 2, k), mpmath.sqrt(k / (1 + k))),
            (S["JacobiDN"].mp(K / 2, k), mpmath.sqrt(k)),
        ]:
            assert mpmath.almosteq(value, expected, tol), (value, expected)


#: Carlson (1995), arXiv:math/9409227 §3, as scipy's TestEllipCarlson and mpmath's tests carry them
CARLSON_1995 = [
    ("CarlsonRF", (1, 2, 0), 1.3110287771461), ("CarlsonRF", (1j, -1j, 0), 1.8540746773014),
    ("CarlsonRF", (-1 + 1j, 1j, 0), 0.79612586584234 - 1.2138566698365j),
    ("CarlsonRF", (2, 3, 4), 0.58408284167715), ("CarlsonRF", (1j, -1j, 2), 1.0441445654064),
    ("CarlsonRF", (-1 + 1j, 1j, 1 - 1j), 0.93912050218619 - 0.53296252018635j),
    ("CarlsonRC", (0, 0.25), 3.14159265358979), ("CarlsonRC", (0, 1j), 1.1107207345396 * (1 - 1j)),
    ("CarlsonRC", (-1j, 1j), 1.2260849569072 - 0.34471136988768j),
    ("CarlsonRC", (0.25, -2), 0.23104906018665), ("CarlsonRC", (1j, -1), 0.77778596920447 + 0.19832484993429j),
    ("CarlsonRJ", (0, 1, 2, 3), 0.77688623778582), ("CarlsonRJ", (2, 3, 4, 5), 0.14297579667157),
    ("CarlsonRJ", (2, 3, 4, -1 + 1j), 0.13613945827771 - 0.38207561624427j),
    ("CarlsonRJ", (1j, -1j, 0, 2), 1.6490011662711), ("CarlsonRJ", (-1 + 1j, -1 - 1j, 1, 2), 0.94148358841220),
    ("CarlsonRJ", (1j, -1j, 0, 1 - 1j), 1.8260115229009 + 1.2290661908643j),
    ("CarlsonRJ", (-1 + 1j, -1 - 1j, 1, -3 + 1j), -0.61127970812028 - 1.0684038390007j),
    ("CarlsonRJ", (2, 3, 4, -0.5), 0.24723819703052), ("CarlsonRJ", (2, 3, 4, -5), -0.12711230042964),
    ("CarlsonRD", (0, 2, 1), 1.7972103521034), ("CarlsonRD", (2, 3, 4), 0.16510527294261),
    ("CarlsonRD", (1j, -1j, 2), 0.65933854154220), ("CarlsonRD", (0, 1j, -1j), 1.2708196271910 + 2.7811120159521j),
    ("CarlsonRD", (0, -1 + 1j, 1j), -1.8577235439239 - 0.96193450888839j),
    ("CarlsonRD", (-2 - 1j, -1j, -1 + 1j), 1.8249027393704 - 1.2218475784827j),
    ("CarlsonRG", (0, 16, 16), 3.14159265358979), ("CarlsonRG", (2, 3, 4), 1.7255030280692),
    ("CarlsonRG", (0, 1j, -1j), 0.42360654239699), ("CarlsonRG", (-1 + 1j, 1j, 0), 0.44660591677018 + 0.70768352357515j),
    ("CarlsonRG", (-1j, -1 + 1j, 1j), 0.36023392184473 + 0.40348623401722j), ("CarlsonRG", (0, 0.0796, 4), 1.0284758090288),
]


@pytest.mark.parametrize("name,args,expected", CARLSON_1995, ids=[f"{n}{a}" for n, a, _ in CARLSON_1995])
def test_carlson_1995_tables(name, args, expected):
    with mpmath.workdps(30):
        value = FUNCTIONS[name].mp(*mp_args(args))
        assert abs(value - expected) <= 1e-12 * abs(expected)
    if all(not isinstance(a, float) or a == int(a) or a in (0.25, -0.5) for a in args):
        ball = FUNCTIONS[name].ball(*acb_args(args))
        assert abs(complex(ball.mid()) - expected) <= 1e-12 * abs(expected)


def boost_rows():
    """A few rows of Boost.Math's tables (scipy's boost.npz; the argument is the modulus k)."""
    path = None
    try:
        import scipy
        path = os.path.join(os.path.dirname(scipy.__file__), "special", "tests", "data", "boost.npz")
    except ImportError:
        pass
    if not path or not os.path.exists(path):
        return []
    import numpy as np
    data = np.load(path)
    rows = []

    def take(key, n=12):
        table = data[key]
        return table[:: max(1, len(table) // n)]

    for k, value in take("ellint_k_data_ipp-ellint_k_data"):
        rows.append(("EllipticK", (float(k),), float(value)))
    for k, value in take("ellint_e_data_ipp-ellint_e_data"):
        rows.append(("EllipticE", (float(k),), float(value)))
    for phi, k, value in take("ellint_f_data_ipp-ellint_f_data"):
        rows.append(("EllipticF", (float(phi), float(k)), float(value)))
    for phi, k, value in take("ellint_e2_data_ipp-ellint_e2_data"):
        rows.append(("EllipticE", (float(phi), float(k)), float(value)))
    for n, k, value in take("ellint_pi2_data_ipp-ellint_pi2_data"):
        rows.append(("EllipticPi", (float(n), float(k)), float(value)))
    for n, phi, k, value in take("ellint_pi3_data_ipp-ellint_pi3_data"):
        rows.append(("EllipticPi", (float(phi), float(n), float(k)), float(value)))
    rj = [r for r in data["ellint_rj_data_ipp-ellint_rj_data"] if r[3] > 0]
    for x, y, z, p, value in rj[:: max(1, len(rj) // 8)]:
        rows.append(("CarlsonRJ", (float(x), float(y), float(z), float(p)), float(value)))
    return rows


BOOST = boost_rows()


@pytest.mark.skipif(not BOOST, reason="scipy's boost.npz is not installed")
def test_boost_tables_at_double_precision():
    """Boost's values (modulus k; its tables hold no Π with n > 1) to 1e-13."""
    seen = set()
    for name, args, expected in BOOST:
        with mpmath.workdps(25):
            value = FUNCTIONS[name].mp(*mp_args(args))
        assert abs(value - expected) <= 1e-13 * abs(expected), (name, args, value, expected)
        seen.add(name)
    assert {"EllipticK", "EllipticE", "EllipticF", "EllipticPi"} <= seen


# --- identities ----------------------------------------------------------------------------

COMPLEX_K = [0.375, 0.875, 0.5 + 0.25j, -0.25 + 0.75j, 1.25 + 0.5j, 0.125 - 0.625j]
COMPLEX_Z = [0.75, 2.5 - 0.5j, 0.25 + 1.25j]


@pytest.mark.parametrize("k", COMPLEX_K)
def test_chapter_19_identities(k):
    with mpmath.workdps(40):
        k = mpmath.mpmathify(k)
        tol = mpmath.mpf(10) ** -36
        kc2 = 1 - k ** 2
        K, E = S["EllipticK"].mp(k), S["EllipticE"].mp(k)
        Kp, Ep = S["EllipticKp"].mp(k), S["EllipticEp"].mp(k)
        assert mpmath.almosteq(E * Kp + Ep * K - K * Kp, mpmath.pi / 2, tol)  # Legendre, 19.7.1
        assert mpmath.almosteq(K, S["CarlsonRF"].mp(0, kc2, 1), tol)  # 19.25.1
        assert mpmath.almosteq(E, 2 * S["CarlsonRG"].mp(0, kc2, 1), tol)
        assert mpmath.almosteq(K - E, k ** 2 * S["CarlsonRD"].mp(0, kc2, 1) / 3, tol)
        n = mpmath.mpf(1) / 4 + 0.125j
        assert mpmath.almosteq(S["EllipticPi"].mp(n, k), K + n / 3 * S["CarlsonRJ"].mp(0, kc2, 1, 1 - n), tol)  # 19.25.2
        assert mpmath.almosteq(S["AGM"].mp(1, mpmath.sqrt(kc2)), mpmath.pi / (2 * K), tol)  # 19.8.5
        for phi in (mpmath.mpf(0.75), mpmath.mpc(0.5, 0.25)):
            s, c = mpmath.sin(phi), mpmath.cos(phi)
            d2 = 1 - k ** 2 * s ** 2
            F, Ei = S["EllipticF"].mp(phi, k), S["EllipticE"].mp(phi, k)
            assert mpmath.almosteq(F, s * S["CarlsonRF"].mp(c ** 2, d2, 1), tol)  # 19.25.5
            assert mpmath.almosteq(Ei, F - k ** 2 * s ** 3 * S["CarlsonRD"].mp(c ** 2, d2, 1) / 3, tol)  # 19.25.9
            assert mpmath.almosteq(S["EllipticD"].mp(phi, k), (F - Ei) / k ** 2, tol)
            assert mpmath.almosteq(S["JacobiZeta"].mp(phi, k), Ei - E / K * F, tol)
            kp = mpmath.sqrt(kc2)
            heuman = 2 / mpmath.pi * (E * mpmath.ellipf(phi, kp ** 2) + K * mpmath.ellipe(phi, kp ** 2)
                                      - K * mpmath.ellipf(phi, kp ** 2))
            assert mpmath.almosteq(S["HeumanLambda"].mp(phi, k), heuman, tol)
            x = mpmath.tan(phi)
            assert mpmath.almosteq(S["BulirschEl1"].mp(x, kp), F, tol)
            assert mpmath.almosteq(S["BulirschEl2"].mp(x, kp, 1, kc2), Ei, tol)
            assert mpmath.almosteq(S["BulirschEl3"].mp(x, kp, 1 - n), S["EllipticPi"].mp(phi, n, k), tol)
        assert mpmath.almosteq(S["BulirschCel"].mp(mpmath.sqrt(kc2), 1 - n, 1, 1), S["EllipticPi"].mp(n, k), tol)


def test_quasi_periodicity_and_principal_values():
    with mpmath.workdps(30):
        k, tol = mpmath.mpf(0.625), mpmath.mpf(10) ** -27
        K, E = S["EllipticK"].mp(k), S["EllipticE"].mp(k)
        for phi in (mpmath.mpf(0.75), mpmath.mpc(0.5, 0.25)):
            assert mpmath.almosteq(S["EllipticF"].mp(phi + 3 * mpmath.pi, k), S["EllipticF"].mp(phi, k) + 6 * K, tol)
            assert mpmath.almosteq(S["EllipticD"].mp(phi - 2 * mpmath.pi, k),
                                   S["EllipticD"].mp(phi, k) - 4 * S["EllipticD"].mp(k), tol)
            assert mpmath.almosteq(S["JacobiZeta"].mp(phi + mpmath.pi, k), S["JacobiZeta"].mp(phi, k), tol)
            assert mpmath.almosteq(S["HeumanLambda"].mp(phi + mpmath.pi, k), S["HeumanLambda"].mp(phi, k) + 2, tol)
        # Π with 1 < α²: a real principal value, K − Π(k²/α²) (DLMF 19.6.5), and by quadrature
        for n in (mpmath.mpf(2), mpmath.mpf(5)):
            pv = S["EllipticPi"].mp(n, k)
            assert isinstance(pv, mpmath.mpf)
            assert mpmath.almosteq(pv, K - S["EllipticPi"].mp(k ** 2 / n, k), tol)
            # the real part of mpmath's own one-sided ellippi (a route independent of ours; mpmath's
            # complete Π is good to ~1e-25 only there) and of flint's rigorous one-sided ball
            assert mpmath.almosteq(pv, mpmath.re(mpmath.ellippi(n, k ** 2)), 1e-22)
            flint.ctx.prec, before = 200, flint.ctx.prec
            try:
                side = acb.elliptic_pi(acb(float(n)), acb(float(k)) ** 2)
            finally:
                flint.ctx.prec = before
            assert abs(to_mp(side.real) - pv) <= to_mp(side.rad()) + 1e-27
            phi = mpmath.mpf(1.25)  # sin²φ > 1/n: the pole inside the incomplete integral
            assert mpmath.almosteq(S["EllipticPi"].mp(phi, n, k), mpmath.re(mpmath.ellippi(n, phi, k ** 2)), tol)


@pytest.mark.parametrize("k", COMPLEX_K)
@pytest.mark.parametrize("z", COMPLEX_Z)
def test_chapter_22_identities(z, k):
    with mpmath.workdps(30):
        z, k = mpmath.mpmathify(z), mpmath.mpmathify(k)
        tol = mpmath.mpf(10) ** -25
        sn, cn, dn = (S["Jacobi" + n].mp(z, k) for n in ("SN", "CN", "DN"))
        assert mpmath.almosteq(sn ** 2 + cn ** 2, 1, tol)  # 22.6.1
        assert mpmath.almosteq(dn ** 2 + k ** 2 * sn ** 2, 1, tol)
        letters = {"s": sn, "c": cn, "d": dn, "n": 1}
        for p in "scdn":
            for q in "scdn":
                if p != q:
                    assert mpmath.almosteq(S["Jacobi" + (p + q).upper()].mp(z, k), letters[p] / letters[q], tol)
        # 22.17.2 (k > 1 or complex): sn(z, k) = sn(kz, 1/k)/k
        assert mpmath.almosteq(sn, S["JacobiSN"].mp(k * z, 1 / k) / k, tol)
        # ℰ = Z + (E/K) x (22.16.32) and dℰ/dz = dn² by quadrature along the segment
        eps = S["JacobiEpsilon"].mp(z, k)
        K, E = S["EllipticK"].mp(k), S["EllipticE"].mp(k)
        assert mpmath.almosteq(eps, S["JacobiZ"].mp(z, k) + E / K * z, tol)
        if abs(mpmath.im(z)) < 1:
            quad = mpmath.quad(lambda t: z * mpmath.ellipfun("dn", t * z, m=k ** 2) ** 2, [0, 0.5, 1])
            assert mpmath.almosteq(eps, quad, 1e-20)


@pytest.mark.parametrize("k", [0.375, 0.875, 0.5 + 0.25j])
def test_am_inverts_f_and_inverses_invert(k):
    with mpmath.workdps(30):
        k = mpmath.mpmathify(k)
        tol = mpmath.mpf(10) ** -25
        for phi in (mpmath.mpf(0.75), mpmath.mpf(7.5), mpmath.mpc(0.5, 0.125)):
            assert mpmath.almosteq(S["JacobiAM"].mp(S["EllipticF"].mp(phi, k), k), phi, tol)  # 22.16.11
        for name, x in INVERSE_POINTS.items():
            for point in (mpmath.mpf(x), mpmath.mpc(0.5, 0.25)):
                u = S["JacobiArc" + name.upper()].mp(point, k)
                assert mpmath.almosteq(S["Jacobi" + name.upper()].mp(u, k), point, tol), (name, point)


def test_principal_ranges_of_the_inverses_on_the_real_line():
    """DLMF 22.15(i): the ranges of the principal values (k = 5/8)."""
    with mpmath.workdps(30):
        k = mpmath.mpf(0.625)
        K = S["EllipticK"].mp(k)
        ranges = {"sn": (-K, K), "cn": (0, 2 * K), "dn": (0, K), "cd": (0, 2 * K), "sd": (-K, K),
                  "nd": (0, K), "dc": (0, 2 * K), "nc": (0, 2 * K), "sc": (-K, K), "ns": (-K, K),
                  "ds": (-K, K), "cs": (0, 2 * K)}
        for name, x in INVERSE_POINTS.items():
            u = S["JacobiArc" + name.upper()].mp(mpmath.mpf(x), k)
            assert isinstance(u, mpmath.mpf), (name, u)
            lo, hi = ranges[name]
            assert lo <= u <= hi, (name, u)


def test_theta_functions():
    with mpmath.workdps(30):
        tol = mpmath.mpf(10) ** -27
        for q in (mpmath.mpf(0.25), mpmath.mpc(0.125, 0.25), mpmath.mpf(-0.25)):
            t2, t3, t4 = (S["JacobiTheta%d" % j].mp(0, q) for j in (2, 3, 4))
            assert mpmath.almosteq(t3 ** 4, t2 ** 4 + t4 ** 4, tol)  # 20.7.3
            d1 = mpmath.diff(lambda z: S["JacobiTheta1"].mp(z, q), 0)
            assert mpmath.almosteq(d1, t2 * t3 * t4, 1e-20)  # 20.4.6
        # sn as the theta quotient 22.2.4 with the nome 22.2.1
        z, k = mpmath.mpf(0.75), mpmath.mpf(0.625)
        q, K = S["EllipticNome"].mp(k), S["EllipticK"].mp(k)
        zeta = mpmath.pi * z / (2 * K)
        th = lambda j, u: S["JacobiTheta%d" % j].mp(u, q)
        assert mpmath.almosteq(S["JacobiSN"].mp(z, k), th(3, 0) * th(1, zeta) / (th(2, 0) * th(4, zeta)), tol)


def test_carlson_r_contains_the_others():
    h = mpmath.mpf(1) / 2
    with mpmath.workdps(30):
        tol = mpmath.mpf(10) ** -26
        x, y, z, p = mpmath.mpf(1), mpmath.mpc(2, 1), mpmath.mpf(3), mpmath.mpf(0.5)
        R = S["CarlsonR"].mp
        assert mpmath.almosteq(R(h, (h, h, h), (x, y, z)), mpmath.elliprf(x, y, z), tol)
        assert mpmath.almosteq(R(3 * h, (h, h, 3 * h), (x, y, z)), mpmath.elliprd(x, y, z), tol)
        assert mpmath.almosteq(R(3 * h, (h, h, h, 1), (x, y, z, p)), mpmath.elliprj(x, y, z, p), tol)
        assert mpmath.almosteq(R(h, (h, 1), (x, y)), mpmath.elliprc(x, y), tol)
        assert mpmath.almosteq(R(-h, (h, h, h), (x, y, z)), mpmath.elliprg(x, y, z), tol)
        assert mpmath.almosteq(R(h, (1,), (y,)), y ** -h, tol)
    with pytest.raises(ValueError):
        special.CarlsonR(h, sp.Tuple(1, 2), sp.Tuple(1))


@pytest.mark.parametrize("perm", [(1, 0, 2), (2, 1, 0), (1, 2, 0)])
def test_symmetries(perm):
    with mpmath.workdps(30):
        args = [mpmath.mpf(1), mpmath.mpc(2, 1), mpmath.mpf(3)]
        shuffled = [args[i] for i in perm]
        for name in ("CarlsonRF", "CarlsonRG"):
            assert mpmath.almosteq(S[name].mp(*args), S[name].mp(*shuffled), 1e-28)
        p = mpmath.mpf(0.5)
        assert mpmath.almosteq(S["CarlsonRJ"].mp(*args, p), S["CarlsonRJ"].mp(*shuffled, p), 1e-28)
        assert mpmath.almosteq(S["AGM"].mp(args[1], args[2]), S["AGM"].mp(args[2], args[1]), 1e-28)


# --- derivatives -------------------------------------------------------------------------------

DERIVATIVE_POINTS = {
    name: [points[0], next((p for p in points if any(isinstance(a, complex) for a in p)), points[0])]
    for name, points in POINTS.items() if not name.startswith("JacobiTheta")
}
# away from the branch points (R_F, R_C at a zero argument) and off R_C's cut y < 0, where the
# principal value 19.2.20 is not R_F(x, y, y) and the derivative formulas do not apply
DERIVATIVE_POINTS["CarlsonRF"] = [(1.0, 2.0, 3.0), (0.5 + 0.25j, 2.0, 0.75)]
DERIVATIVE_POINTS["CarlsonRC"] = [(0.5, 0.25), (1j, 0.5 + 0.25j)]
DERIVATIVE_CASES = [(name, args, i) for name, pts in DERIVATIVE_POINTS.items() for args in pts
                    for i in range(len(args))
                    # Weierstrass's functions: ζ′ = −℘ and σ′ = ζσ in z only (℘′ and the half-periods'
                    # derivatives have no closed form in these functions)
                    if not (name.startswith("Weierstrass") and (i > 0 or name == "WeierstrassP"))]
#: derivatives that go through CarlsonR's quadrature: a few only (each costs ~0.5 s)
SLOW = {"CarlsonRD", "CarlsonRJ", "BulirschCel", "BulirschEl2", "BulirschEl3"}


def derivative_params(slow):
    cases = [c for c in DERIVATIVE_CASES if (c[0] in SLOW and (c[0] != "BulirschEl2" or c[2] != 0)) == slow]
    return pytest.mark.parametrize("name,args,i", cases, ids=[f"{n}{a}d{i}" for n, a, i in cases])


@derivative_params(False)
def test_fdiff_against_numerical_differentiation(name, args, i):
    check_derivative(name, args, i)


@pytest.mark.slow
@derivative_params(True)
def test_fdiff_through_carlson_r_quadrature(name, args, i):
    check_derivative(name, args, i)


def test_one_derivative_through_carlson_r():
    """∂R_D/∂z = −(9/10) R_{−5/2}(½, ½, 5/2; x, y, z) (§19.18(i)); the sweep is marked slow."""
    check_derivative("CarlsonRD", (2.0, 3.0, 4.0), 2)


def check_derivative(name, args, i):
    cls = FUNCTIONS[name]
    symbols = sp.symbols("a0:%d" % len(args))
    derivative = cls(*symbols).diff(symbols[i])
    assert not derivative.has(sp.Derivative), derivative
    value = sp.N(derivative.subs(dict(zip(symbols, sympy_args(args)))), 20)
    with mpmath.workdps(25):
        point = mp_args(args)

        def f(t):
            return cls.mp(*(point[:i] + [t] + point[i + 1:]))

        numeric = mpmath.diff(f, point[i])
        assert close(mpmath.mpmathify(complex(value)), numeric, 1e-12), (value, numeric)


def test_functions_without_a_closed_derivative_stay_unevaluated():
    z, q = sp.symbols("z q")
    assert special.JacobiTheta1(z, q).diff(z).has(sp.Derivative)
    h = sp.Rational(1, 2)
    x, y = sp.symbols("x y")
    r = special.CarlsonR(h, sp.Tuple(h, h), sp.Tuple(x, y))
    assert r.diff(x).has(special.CarlsonR)  # ∂/∂z_j by §19.18(i)
    assert special.CarlsonR(z, sp.Tuple(h, h), sp.Tuple(x, y)).diff(z).has(sp.Derivative)


# --- convention traps --------------------------------------------------------------------------

@pytest.mark.parametrize("k", [sp.Rational(3, 5), sp.Rational(1, 2) + sp.I / 4])
def test_modulus_not_parameter(k):
    phi, n = sp.Rational(3, 4), sp.Rational(1, 4)
    pairs = [(special.EllipticK(k), sp.elliptic_k(k ** 2)), (special.EllipticE(k), sp.elliptic_e(k ** 2)),
             (special.EllipticF(phi, k), sp.elliptic_f(phi, k ** 2)),
             (special.EllipticE(phi, k), sp.elliptic_e(phi, k ** 2)),
             (special.EllipticPi(n, k), sp.elliptic_pi(n, k ** 2)),
             (special.EllipticPi(phi, n, k), sp.elliptic_pi(n, phi, k ** 2))]
    for ours, sympys in pairs:
        assert abs(complex(sp.N(ours - sympys, 30))) < 1e-28
    assert abs(complex(sp.N(special.EllipticK(k) - sp.elliptic_k(k), 15))) > 1e-3


def test_flint_theta_is_scaled_by_pi_and_ours_is_not():
    z, q = 0.375, 0.25
    flint.ctx.prec, before = 120, flint.ctx.prec
    try:
        tau = acb(q).log() / (acb.pi() * acb(0, 1))
        raw = acb.modular_theta(acb(z), tau)[0]
        ours = special.JacobiTheta1.ball(acb(z), acb(q))
    finally:
        flint.ctx.prec = before
    with mpmath.workdps(30):
        expected = mpmath.jtheta(1, z, q)
        assert abs(ball_mid(ours) - expected) < 1e-25
        assert abs(ball_mid(raw) - mpmath.jtheta(1, mpmath.pi * z, q)) < 1e-25
        assert abs(ball_mid(raw) - expected) > 0.1


def test_branch_of_k_prime_for_complex_modulus():
    """DLMF 19.2.9: K′(k) = K(k′) for |ph k| ≤ π/2, K(k′) ∓ 2iK(k) for π/2 < ±ph k < π (E′ with
    K − E): analytic across the imaginary axis, not even in k."""
    with mpmath.workdps(30):
        for k in (mpmath.mpc(0.5, 0.25), mpmath.mpc(0.25, -2), mpmath.mpc(2, 0.5)):
            # right half-plane: only k′² = 1 − k² enters, either root of 1 − k² gives K(k′)
            kp = mpmath.sqrt(1 - k ** 2)
            assert mpmath.almosteq(S["EllipticKp"].mp(k), mpmath.ellipk(kp ** 2), 1e-27)
            assert mpmath.almosteq(S["EllipticKp"].mp(k), S["EllipticK"].mp(-kp), 1e-27)
        for k, sign in ((mpmath.mpc(-0.5, 0.25), -1), (mpmath.mpc(-0.625, -1.25), 1)):
            K, E = S["EllipticK"].mp(k), S["EllipticE"].mp(k)
            assert mpmath.almosteq(S["EllipticKp"].mp(k), mpmath.ellipk(1 - k ** 2) + sign * 2j * K, 1e-27)
            assert mpmath.almosteq(S["EllipticEp"].mp(k), mpmath.ellipe(1 - k ** 2) + sign * 2j * (K - E), 1e-27)
            # Legendre's relation 19.7.1 holds on the continuation
            Kp, Ep = S["EllipticKp"].mp(k), S["EllipticEp"].mp(k)
            assert mpmath.almosteq(E * Kp + Ep * K - K * Kp, mpmath.pi / 2, 1e-27)
        # k imaginary: k′ > 1 lies on K's cut, where the value is mpmath's ellipk(1 − k²)
        k = mpmath.mpc(0, 0.75)
        assert mpmath.almosteq(S["EllipticKp"].mp(k), mpmath.ellipk(1 - k ** 2), 1e-27)
        # continuous across the imaginary axis; not even in k
        for f in (S["EllipticKp"], S["EllipticEp"]):
            assert mpmath.almosteq(f.mp(mpmath.mpc(1e-20, 0.75)), f.mp(mpmath.mpc(-1e-20, 0.75)), 1e-15)
        k = mpmath.mpc(0.25, 0.75)
        assert not mpmath.almosteq(S["EllipticKp"].mp(k), S["EllipticKp"].mp(-k), 1e-3)
        # the ball route takes the same branch
        flint.ctx.prec, before = 120, flint.ctx.prec
        try:
            ball = S["EllipticKp"].ball(flint.acb(-0.5, 0.25))
        finally:
            flint.ctx.prec = before
        assert abs(ball_mid(ball) - S["EllipticKp"].mp(mpmath.mpc(-0.5, 0.25))) < 1e-25
        # near k = 0 K′ ≈ ln(4/k) without the cancellation of K(√(1 − k²))
        k = mpmath.mpf(2) ** -80
        assert mpmath.almosteq(S["EllipticKp"].mp(k), mpmath.log(4 / k) + k ** 2 / 4 * (mpmath.log(4 / k) - 1), 1e-25)


def test_agm_is_the_analytic_one_not_mpmaths_principal_root_iteration():
    a, b = mpmath.mpc(1, 2), mpmath.mpc(-3, 0.5)
    with mpmath.workdps(30):
        ours = S["AGM"].mp(a, b)
        assert not mpmath.almosteq(ours, mpmath.agm(a, b), 1e-3)
        assert abs(ours - complex(acb(complex(a)).agm(acb(complex(b))).mid())) < 1e-14
        # the optimal iteration: pick the root with |a' - b'| <= |a' + b'|
        x, y = a, b
        for _ in range(200):
            x, y = (x + y) / 2, mpmath.sqrt(x * y)
            if abs(x - y) > abs(x + y):
                y = -y
        assert mpmath.almosteq(ours, x, 1e-25)


# --- balls: precision, cuts, integration -------------------------------------------------------

def test_balls_restore_the_precision_even_when_they_fail():
    before = flint.ctx.prec
    special.EllipticK.ball(acb(0.5))
    assert flint.ctx.prec == before
    with pytest.raises(Exception):
        special.EllipticK.ball("not a number")
    assert flint.ctx.prec == before
    prec = mpmath.mp.prec
    special.EllipticK.mp(mpmath.mpf(0.5))
    assert mpmath.mp.prec == prec


@pytest.mark.parametrize("name,args,cut_index", [
    ("EllipticK", (1.25,), 0), ("EllipticE", (1.25,), 0), ("EllipticKp", (0.5j,), 0),
    ("EllipticF", (1.0, 2.0), 1), ("EllipticPi", (1.25, 0.5), 0), ("CarlsonRF", (-1.0, 1.0, 2.0), 0),
    ("CarlsonRC", (1.0, -1.0), 1), ("CarlsonRJ", (1.0, 2.0, 3.0, -0.5), 3), ("AGM", (1.0, -0.5), 1),
    ("JacobiTheta1", (0.5, -0.25), 1), ("JacobiArcSN", (1.5, 0.5), 0), ("JacobiArcSC", (1.5j, 0.5), 0),
    ("EllipticNome", (-0.5j,), 0), ("BulirschCel", (0.5, -0.5, 1.0, 1.0), 1), ("JacobiAM", (0.5, 1.25), 1),
])
def test_analytic_balls_are_non_finite_on_cuts_and_finite_off(name, args, cut_index):
    """A ball across the cut (the real axis, or for arctan and K′ the imaginary axis) is
    non-finite with analytic=True; the same ball moved off the cut is finite."""
    cls = FUNCTIONS[name]

    def moved(shift):
        balls = acb_args(args)
        a = balls[cut_index]
        if isinstance(args[cut_index], complex):  # a cut on the imaginary axis
            balls[cut_index] = acb(arb(shift, 1e-6), a.imag)
        else:
            balls[cut_index] = acb(a.real, arb(shift, 1e-6))
        return balls

    assert not cls.ball(*moved(0), analytic=True).is_finite()
    assert cls.ball(*moved(0.25), analytic=True).is_finite()


def test_meromorphic_functions_need_no_cut_check_but_poles_are_non_finite():
    k = acb(0.625)
    K = special.EllipticK.ball(k)
    near_pole = acb(arb(0), arb(0, 1e-8))
    assert not special.JacobiNS.ball(near_pole, k, analytic=True).is_finite()
    assert special.JacobiSN.ball(K + acb(0, 0.5), k, analytic=True).is_finite()


def test_acb_integral_of_a_ball_route():
    """∫₀^{1/2} K(k) dk by flint's rigorous integrator against mpmath's quadrature."""
    before = flint.ctx.prec
    flint.ctx.prec = 100
    try:
        value = acb.integral(lambda k, analytic: special.EllipticK.ball(k, analytic=analytic), 0, 0.5)
        phi_value = acb.integral(lambda p, analytic: special.EllipticF.ball(p, acb(0.75), analytic=analytic), 0, 3)
    finally:
        flint.ctx.prec = before
    with mpmath.workdps(30):
        assert abs(ball_mid(value) - mpmath.quad(lambda k: mpmath.ellipk(k * k), [0, 0.5])) < 1e-25
        expected = mpmath.quad(lambda p: mpmath.ellipf(p, 0.5625), [0, mpmath.pi / 2, 3])
        assert abs(ball_mid(phi_value) - expected) < 1e-25
    assert value.rad() < 1e-25 and phi_value.rad() < 1e-25


def test_ball_straddling_the_reduction_line_still_encloses():
    """A ball across Re φ = π/2 (where the quasi-periodic continuation switches) encloses F, E, D
    and Π on both sides."""
    flint.ctx.prec, before = 100, flint.ctx.prec
    try:
        phi = acb(arb(arb.pi() / 2, 1e-3))
        balls = {name: FUNCTIONS[name].ball(phi, *rest) for name, rest in
                 [("EllipticF", (acb(0.625),)), ("EllipticE", (acb(0.625),)), ("EllipticD", (acb(0.625),)),
                  ("EllipticPi", (acb(0.25), acb(0.625)))]}
    finally:
        flint.ctx.prec = before
    with mpmath.workdps(30):
        for d in (-1e-3, 0, 1e-3):
            p = mpmath.pi / 2 + d
            for name, ball in balls.items():
                rest = (0.625,) if name != "EllipticPi" else (0.25, 0.625)
                value = FUNCTIONS[name].mp(p, *mp_args(rest))
                assert ball.contains(acb(arb(str(value)))), (name, d)


# --- the module's surface ----------------------------------------------------------------------

def test_latex_in_dlmf_notation():
    z, k, phi, x, y, q = sp.symbols("z k phi x y q")
    assert sp.latex(special.JacobiSN(z, k)) == r"\operatorname{sn}\left(z, k\right)"
    assert sp.latex(special.EllipticK(k)) == r"K\left(k\right)"
    assert sp.latex(special.EllipticKp(k)) == r"{K'}\left(k\right)"
    assert sp.latex(special.EllipticF(phi, k)) == r"F\left(\phi, k\right)"
    assert sp.latex(special.EllipticPi(phi, x, k)) == r"\Pi\left(\phi, x, k\right)"
    assert sp.latex(special.CarlsonRF(x, y, z)) == r"R_{F}\left(x, y, z\right)"
    assert sp.latex(special.JacobiTheta1(z, q)) == r"\theta_{1}\left(z, q\right)"
    assert sp.latex(special.JacobiZ(x, k)) == r"\mathrm{Z}\left(x\middle|k\right)"
    assert sp.latex(special.JacobiArcDC(x, k)) == r"\operatorname{arcdc}\left(x, k\right)"
    assert sp.latex(special.HeumanLambda(phi, k)) == r"\Lambda_{0}\left(\phi, k\right)"
    assert sp.latex(special.JacobiCN(z, k) ** 2) == r"\operatorname{cn}^{2}\left(z, k\right)"


def test_exact_special_values_only_where_dlmf_states_them():
    k, z = sp.symbols("k z")
    assert special.EllipticK(0) == sp.pi / 2 and special.EllipticE(1) == 1
    assert special.JacobiSN(0, k) == 0 and special.JacobiCN(0, k) == 1 and special.JacobiDC(0, k) == 1
    assert isinstance(special.JacobiNS(0, k), special.JacobiNS)  # a pole: left alone
    assert isinstance(special.EllipticK(1), special.EllipticK)
    assert isinstance(special.JacobiSN(z, 0), special.JacobiSN)


def test_module_state_is_read_only():
    assert isinstance(FUNCTIONS, types.MappingProxyType)
    assert sorted(special.__all__) == sorted(list(FUNCTIONS) + ["FUNCTIONS"])
    for module in (special, base, bulirsch, carlson, jacobi, legendre, theta):
        for name, value in vars(module).items():
            if not name.startswith("__"):
                assert not isinstance(value, (dict, list, set)), (module.__name__, name)
