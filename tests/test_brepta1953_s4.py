"""[Brepta1953] section 4 beyond the catalog: the angular-momentum law (4) on the solutions of
(16)–(17), the constants, the trajectory with its arccotg branch, the limits κ → 0 and κ → Ω,
and the printed rounding of ω."""

import dataclasses

import pytest
import sympy as sp

import shipped
s4 = shipped.module('brepta1953', 's4')
from quasicentral.engine.checker import Options
from shipped import check
from quasicentral.notation.domain import Domain
from quasicentral.engine.registry import as_list
from shipped import derived
from quasicentral.notation.symbols import D
from quasicentral.engine.texts import symbols_of, SHIPPED_ROOT

S_ = symbols_of(SHIPPED_ROOT / "brepta1953" / "text.toml")
(A, K1, L1, M1, N1, Omega, R0, kappa, n, omega, t, th, v0, x, y) = S_(
    "A K1 L1 M1 N1 Omega R0 kappa n omega t th v0 x y")
parse = S_.parse
from quasicentral.engine.verdict import Refuted, Verified

OPTS = Options(symbolic=False, points=12)



@pytest.fixture(autouse=True)
def _shipped_context():
    """The module's helpers ask derived() for results: the shipped workspace's derivations."""
    with shipped.context():
        yield

def _solution(eid):
    return {e.lhs: e.rhs for e in derived(eid)}


def _angular_momentum(sol):
    return sol[x] * sp.diff(sol[y], t) - sol[y] * sp.diff(sol[x], t)


def test_angular_momentum_law_4_on_the_particular_solution_19():
    """x ẏ − y ẋ = A e^{−2κt} with A = R0 v0 (section 2's (4), which holds for any central force)."""
    law = derived("brepta1953:4").rhs.subs(A, R0 * v0)
    assert sp.simplify(_angular_momentum(_solution("brepta1953:19")) - law) == 0


def test_angular_momentum_law_4_on_the_general_solution_18():
    """On every solution of (16)–(17): x ẏ − y ẋ = ω(LM − KN) e^{−2κt}, its value at t = 0."""
    h = _angular_momentum(_solution("brepta1953:18"))
    h0 = sp.simplify(h.subs(t, 0))
    assert sp.simplify(h0 - omega * (L1 * M1 - K1 * N1)) == 0
    assert sp.simplify(h - derived("brepta1953:4").rhs.subs(A, h0)) == 0


def test_angular_momentum_law_4_at_critical_damping():
    law = derived("brepta1953:4").rhs.subs(A, R0 * v0)
    assert sp.simplify(_angular_momentum(_solution("brepta1953:21")) - law) == 0


def test_18_solves_16_17_for_every_kappa_and_19_is_18_with_the_constants():
    sol = _solution("brepta1953:18")
    for coord, eid in ((x, "brepta1953:16"), (y, "brepta1953:17")):
        eq = derived(eid)
        res = (eq.lhs - eq.rhs).subs(coord, sol[coord]).doit().subs(Omega, sp.sqrt(kappa**2 + omega**2))
        assert sp.simplify(res) == 0
    consts = {}
    for eid in ("brepta1953:initial-constants", "brepta1953:constant-K", "brepta1953:constant-M"):
        consts.update({e.lhs: e.rhs for e in as_list(derived(eid))})
    assert set(consts) == {K1, L1, M1, N1}
    part = _solution("brepta1953:19")
    for coord in (x, y):
        assert sp.simplify(sol[coord].subs(consts) - part[coord]) == 0


def test_21_is_the_limit_of_19_as_kappa_tends_to_omega():
    """κ → Ω means ω → 0 at fixed κ: (19) tends to (21)."""
    part, crit = _solution("brepta1953:19"), _solution("brepta1953:21")
    for coord in (x, y):
        assert sp.simplify(sp.limit(part[coord], omega, 0) - crit[coord]) == 0


def test_time_elimination_gives_the_corrected_20_and_22():
    recs, _ = shipped.records()
    pts = [{R0: sp.Rational(3, 10), v0: sp.Rational(7, 5), kappa: sp.Rational(1, 3), omega: sp.Rational(9, 4),
            n: 2, x: sp.Rational(-1, 20), y: sp.Rational(1, 30)},
           {R0: sp.Rational(1, 2), v0: sp.Rational(1, 7), kappa: sp.Rational(2, 1), omega: sp.Rational(1, 3),
            n: 0, x: sp.Rational(1, 9), y: sp.Rational(-1, 40)}]
    pairs = ((s4.eliminate_time_small_damping(), "brepta1953:20"), (s4.eliminate_time_critical(), "brepta1953:22"))
    for rel, eid in pairs:
        corr = recs[eid].corrected
        for pt in pts:
            # compare the two relations as functions of (x, y): lhs/rhs ratios agree
            ours = sp.N((rel.lhs / rel.rhs).subs(pt), 30)
            theirs = sp.N((corr.lhs / corr.rhs).subs(pt), 30)
            assert abs(ours - theirs) < 1e-20 * abs(ours)


def _model_20():
    return derived("brepta1953:20")


def _residual_20(relation, theta, values=None):
    """lhs − rhs of a trajectory relation on (19) at θ = ωt (relative to |lhs| + |rhs|)."""
    model = _model_20()
    pt = {R0: sp.Rational(1, 5), v0: sp.Rational(3, 5), kappa: sp.Rational(1, 4), omega: sp.Rational(3, 2),
          th: theta, **(values or {})}
    lhs = relation.lhs.subs(model).subs(pt)
    rhs = relation.rhs.subs(model).subs(pt)
    lv, rv = sp.N(lhs, 40), sp.N(rhs, 40)
    return abs(lv - rv) / (abs(lv) + abs(rv))


def test_20_branch_the_corrected_form_without_n_holds_on_the_first_half_turn_only():
    recs, _ = shipped.records()
    corr = recs["brepta1953:20"].corrected
    no_branch = corr.subs(n, 0)
    for k in range(8):
        theta = sp.pi * (k + sp.Rational(3, 7))
        assert _residual_20(corr, theta) < 1e-30
        if k == 0:
            assert _residual_20(no_branch, theta) < 1e-30
        else:
            assert _residual_20(no_branch, theta) > 1e-3


def test_20_branch_through_the_engine():
    """The check itself sees the branch: the dimension-fixed form without nπ verifies on the first
    half-turn, and is refuted over eight half-turns."""
    recs, _ = shipped.records()
    no_branch = [recs["brepta1953:20"].corrected.subs(n, 0)]
    entry = shipped.entry("brepta1953:20")
    der = shipped.derivation("brepta1953:20")
    first = dataclasses.replace(der, domain=Domain.of(ranges={omega: (sp.Rational(1, 10), 10), th: (0, sp.pi)},
                                                      defaults=False))
    assert isinstance(check(no_branch, entry.dims, first, "test-20-first", OPTS, S_), Verified)
    assert isinstance(check(no_branch, entry.dims, der, "test-20-all", OPTS, S_), Refuted)


def test_printed_20_and_22_hold_when_R0_equals_v0_numerically():
    """The print's x − κy coincides with x − (R0κ/v0)y when R0 = v0 (the data of figs. 7, 8):
    the printed forms are then right on the first half-turn (and always for (22))."""
    p20 = shipped.entry("brepta1953:20").relations()[0]
    assert _residual_20(p20, sp.pi / 3, {v0: sp.Rational(1, 5)}) < 1e-30
    assert _residual_20(p20, sp.pi / 3) > 1e-3
    crit = _solution("brepta1953:21")
    p22 = shipped.entry("brepta1953:22").relations()[0]
    pt = {R0: sp.Rational(1, 10), v0: sp.Rational(1, 10), kappa: sp.sqrt(10), t: sp.Rational(3, 10)}
    res = (p22.lhs - p22.rhs).subs(crit).subs(pt)
    assert abs(sp.N(res, 40)) < 1e-35


def test_undamped_limit_lies_on_the_ellipse():
    part = _solution("brepta1953:19")
    ellipse = derived("brepta1953:undamped-ellipse")
    at0 = {c: part[c].subs(kappa, 0).subs(omega, Omega) for c in (x, y)}
    assert sp.simplify(ellipse.lhs.subs(at0) - ellipse.rhs.subs(at0)) == 0


def test_printed_rounding_of_omega_is_a_real_comparison():
    """√9.84 = 3.13688 rounds to 3.137 at three decimals; a wrong last digit is refuted."""
    w = sp.sqrt(sp.Rational(984, 100))
    assert s4.round_half_up(w, 3) == sp.Rational(3137, 1000)
    assert abs(sp.N(w - sp.Rational(3137, 1000), 30)) < sp.Rational(5, 10000)
    entry = shipped.entry("brepta1953:example-fig7")
    der = shipped.derivation("brepta1953:example-fig7")
    good = entry.relations()
    assert isinstance(check(good, entry.dims, der, "test-fig7", OPTS, S_), Verified)
    for wrong in ("3136/1000", "3138/1000"):
        bad = good[:-1] + [parse(f"Eq(omega, Rational({wrong.replace('/', ',')}))")]
        assert isinstance(check(bad, entry.dims, der, "test-fig7-bad", OPTS, S_), Refuted)


def test_fig8_is_the_critical_case():
    data = {e.lhs: e.rhs for e in derived("brepta1953:example-fig8")}
    assert data[kappa] == data[Omega]
    assert s4.discriminant().subs(data) == 0


@pytest.mark.parametrize("eid", ["brepta1953:16", "brepta1953:17"])
def test_16_17_are_newton_with_linear_drag(eid):
    """The same equations straight from m r̈ = −m(g/l) r − 2κm ṙ."""
    coord = x if eid.endswith("16") else y
    eq = derived(eid)
    newton = D(coord, 2) + Omega**2 * coord + 2 * kappa * D(coord)
    assert sp.expand(eq.lhs - eq.rhs - newton) == 0
