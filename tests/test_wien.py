"""Issue 25's constructs end to end on a text nobody wrote for the checker (tests/data/wien):
an implicit condition sampled only where it holds, printed roundings decided by the exact value,
an integral to infinity, a limit, a coefficient in front of a logarithm."""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import mpmath
import pytest
import sympy as sp

import quasicentral as qc
from quasicentral.engine import rounding
from quasicentral.engine.options import Options
from quasicentral.engine.reasons import Code
from quasicentral.engine.verdict import Inconclusive, Refuted, Status, Verified
from quasicentral.notation.domain import on_condition
from quasicentral.notation.symbols import Approx

WIEN = Path(__file__).resolve().parent / "data" / "wien"


@pytest.fixture(scope="module")
def results():
    return qc.load_text(WIEN).verify(cache=False)


def test_the_text_verifies(results):
    assert results.ok
    assert {r.entry.id: r.status for r in results} == {
        "wien:1": Status.VERIFIED, "wien:2": Status.ERRATUM, "wien:3": Status.VERIFIED, "wien:4": Status.ERRATUM,
        "wien:5": Status.VERIFIED, "wien:6": Status.VERIFIED, "wien:7": Status.VERIFIED}


def test_the_witness_of_an_implicit_condition_satisfies_it(results):
    """The refuted peak condition's witness lies where the *printed* condition holds: no witness
    violates its premise."""
    w = results["wien:2"].witness
    assert w.certified
    with mpmath.workdps(60):
        x = mpmath.mpf(w.parameters["x"])
        assert abs((x - 4) * mpmath.exp(x) + 5) < mpmath.mpf(10) ** -50
        assert abs(5 * x**4 * (mpmath.exp(x) - 1) - x**5 * mpmath.exp(x)) > 1  # and the derivative does not vanish


def test_a_root_is_found_in_its_range_nearest_the_drawn_value():
    x, y = sp.symbols("x y", positive=True)
    got = on_condition([{x: sp.Integer(7), y: sp.Integer(2)}], x, x**2 - y, {x: (sp.Integer(0), y)})
    assert abs(got[0][x] - sp.sqrt(2)) < sp.Float("1e-70")
    both = on_condition([{x: sp.Rational(1, 10)}, {x: sp.Integer(9)}], x, (x - 1) * (x - 8), {x: (0, 10)})
    assert [round(float(p[x])) for p in both] == [1, 8]
    assert on_condition([{x: sp.Integer(3)}], x, x**2 + 1, {x: (0, 10)}) == []


@pytest.mark.parametrize("expr,printed,expected", [
    (sp.pi, "3.1416", Code.ROUNDS_TO),
    (sp.pi, "3.1415", Code.ROUNDS_OTHERWISE),  # a truncation is not a rounding
    (sp.Rational(1, 3), "0.333", Code.ROUNDS_TO),
    (sp.Rational(1, 8), "0.12", Code.ROUNDING_TIE),  # 0.125: on the half of the last place
    (sp.Rational(1, 8), "0.125", Code.ROUNDS_TO),
    (sp.zeta(3), "1.2020569031595942854", Code.ROUNDS_TO),
    (sp.EulerGamma, "0.5772156649", Code.ROUNDS_TO),  # no ball form: mpmath at two precisions
    (sp.sqrt(2) * 1000, "1414.21", Code.ROUNDS_TO),
    (-sp.E, "-2.718", Code.ROUNDS_TO),
    (sp.Symbol("a"), "1.5", Code.ROUNDING_FREE),
])
def test_a_rounding_is_decided_by_the_exact_value(expr, printed, expected):
    from quasicentral.notation.transcription import decimal_literal, decimal_places

    v = rounding.check(Approx(expr, decimal_literal(printed), decimal_places(printed)), {}, Options())
    assert v.reason.code is expected
    kind = {Code.ROUNDS_TO: Verified, Code.ROUNDS_OTHERWISE: Refuted}.get(expected, Inconclusive)
    assert isinstance(v, kind)
    if isinstance(v, Refuted):
        assert Fraction(v.witness.corrected) != Fraction(printed)


def test_an_equation_with_a_decimal_side_is_a_rounding_in_an_identity_text():
    from quasicentral.engine.catalog import Entry, _as_rounding  # noqa: PLC2701 - the module's own rule, tested

    x = sp.Symbol("x")
    rel = sp.Eq(sp.zeta(3), sp.Rational(1202, 1000), evaluate=False)
    got = _as_rounding(rel, {sp.Rational(1202, 1000): 3})
    assert isinstance(got, Approx) and got.args[2] == 3
    assert _as_rounding(sp.Eq(x, sp.Rational(1, 2), evaluate=False), {}) == sp.Eq(x, sp.Rational(1, 2), evaluate=False)
    assert Entry  # the entry applies it only where its text is an identity text (run.py)


def test_every_reason_has_every_language():
    from quasicentral.engine.reasons import Code as C
    from quasicentral.engine.wording import LANGUAGES, WORDING

    missing = [(c.value, lang) for c in C for lang in LANGUAGES if lang not in WORDING.get(c, {})]
    assert not missing, missing


def test_the_reasons_of_a_run_read_in_both_languages(results):
    from quasicentral.engine.wording import render

    for r in results:
        v = r.outcome.verdict
        en, cs = render(v.reason, "en"), render(v.reason, "cs")
        assert en and cs and en != cs, (r.entry.id, en, cs)
        if r.witness is not None and r.witness.quantity is not None:
            assert render(r.witness.quantity, "en") != render(r.witness.quantity, "cs")


def test_a_definition_is_notation_not_a_failure(tmp_path):
    """An identity text's definition (and a bare expression) states nothing to check: status
    'notation', which leaves the run ok — a handbook chapter verifies with its definitions."""
    (tmp_path / "catalog").mkdir()
    (tmp_path / "text.toml").write_text('id = "defs"\ntitle = "Definitions"\nlanguage = "en"\ncheck = "identity"\n\n'
                                        '[symbols.x]\nlatex = "x"\nrange = ["0", "1"]\n\n'
                                        '[symbols.c]\nlatex = "c"\nrange = ["0", "1"]\n', encoding="utf-8")
    (tmp_path / "catalog" / "a.toml").write_text(
        'section = "1"\ntitle = "One"\n\n'
        '[[equation]]\nid = "defs:1"\nnumber = "1"\nname = "a definition"\nkind = "definition"\n'
        "latex = 'c = 1 + x^2'\nprinted = 'Eq(c, 1 + x**2)'\n\n"
        '[[equation]]\nid = "defs:2"\nnumber = "2"\nname = "notation"\n'
        "latex = 'x'\nprinted = 'x'\n\n"
        '[[equation]]\nid = "defs:3"\nnumber = "3"\nname = "a relation"\n'
        "latex = '(1+x)^2 = 1 + 2x + x^2'\nprinted = 'Eq((1 + x)**2, 1 + 2*x + x**2)'\n", encoding="utf-8")
    got = qc.load_text(tmp_path).verify(cache=False)
    assert [r.status for r in got] == [Status.NOTATION, Status.NOTATION, Status.VERIFIED]
    assert got.ok


def test_an_indefinite_integral_states_its_derivative():
    """∫ f dx = F holds up to a constant: F′ = f is the claim (never an evaluation of ∫ f dx)."""
    from quasicentral.engine.claims import identity_claims

    x = sp.Symbol("x")
    (claim,) = identity_claims([sp.Eq(sp.Integral(sp.cos(x), x), sp.sin(x) + 7, evaluate=False)])
    assert claim.quantity.code is Code.Q_ANTIDERIVATIVE
    assert sp.simplify(claim.printed - claim.derived) == 0
    (plain,) = identity_claims([sp.Eq(sp.Integral(sp.cos(x), (x, 0, 1)), sp.sin(1), evaluate=False)])
    assert plain.quantity.code is Code.Q_SIDES


def test_a_folders_figures_are_bounded(tmp_path, monkeypatch):
    """figures.py is a folder's own code: a sleep there ends as a TextError naming the file."""
    import types

    from quasicentral.engine.texts import TextError
    from quasicentral.studies import figures

    class Text:
        root = tmp_path

        @staticmethod
        def figures_module():
            return types.SimpleNamespace(FIGURES=(lambda: __import__("time").sleep(30),))

    monkeypatch.setattr(figures, "FIGURE_SECONDS", 0.5)
    with pytest.raises(TextError, match="figures.py: its figures took more than"):
        figures.of_text(Text())


def test_an_o_term_has_no_dimension_of_its_own():
    from quasicentral.engine.dimensions import check_relation
    from quasicentral.notation.symbols import Landau
    from quasicentral.notation.units import parse_dim

    nu, T, u = sp.symbols("nu T u", positive=True)
    dims = {nu: parse_dim("1/s"), T: parse_dim("K"), u: parse_dim("K/s^2")}
    assert not check_relation(sp.Eq(u, nu**2 * T + Landau(nu**3, nu, 0)), dims).inconsistent
    assert check_relation(sp.Eq(u, nu * T + Landau(nu**3, nu, 0)), dims).inconsistent  # the rest still counts


def test_a_derivative_at_a_point_that_is_zero_is_judged_against_its_terms():
    """Subs(Derivative(…), t, t0) = 0 — the top of a trajectory — verifies, never 'unstable'."""
    from quasicentral.engine.claims import doit_derivatives

    t, k, g, v = sp.symbols("t k g v", positive=True)
    y = ((v + g / k) / k) * (1 - sp.exp(-k * t)) - g * t / k
    at_top = sp.Subs(sp.Derivative(y, t), t, sp.log(1 + k * v / g) / k)
    done = doit_derivatives(at_top)
    assert not done.has(sp.Subs, sp.Derivative) and sp.simplify(done) == 0


@pytest.mark.parametrize("literal", ["abc", "1e999999999", "nan", "1e1001"])
def test_a_decimal_that_is_no_number_or_too_large_is_refused(literal):
    """A decimal literal (a transcription's, or approx =) is a number of bounded size: a power
    of ten of a billion digits would hang the reader."""
    from quasicentral.notation.transcription import decimal_literal

    with pytest.raises(ValueError):
        decimal_literal(literal)
    assert decimal_literal("1.2e-3") == sp.Rational(12, 10000)


def test_a_bad_approx_names_its_file_and_line(tmp_path):
    import shutil

    from quasicentral.engine.catalog import CatalogError

    folder = tmp_path / "w"
    shutil.copytree(WIEN, folder)
    catalog = folder / "catalog" / "wien.toml"
    catalog.write_text(catalog.read_text().replace('approx = "4.965114"', 'approx = "1e999999"'), encoding="utf-8")
    with pytest.raises((CatalogError, qc.InputError), match=r"wien\.toml:\d+: wien:3: approx"):
        qc.load_text(folder, workspace_=qc.Workspace()).verify(cache=False)
