"""What a reader relies on: errata by root cause, the text's own branch, guaranteed witness
digits, notes that quote their witness, a checked cache, and guards that bite."""

import shipped
import json
import re
from dataclasses import replace
from fractions import Fraction

import mpmath
import pytest
import sympy as sp

from quasicentral.engine import errata, notes, run
from quasicentral.engine.catalog import CatalogError
from quasicentral.engine.checker import Options, claims_for
from quasicentral.engine.witness import round_significant
from shipped import check, derived
from quasicentral.engine.verdict import Refuted
from quasicentral.notation import bridge
from quasicentral.notation.domain import Domain, substitute_definitions

ERRATA, CLEARED = shipped.records()
CAUSES = {cid: c for t in shipped.workspace().papers() for cid, c in t.causes.items()}
BREPTA = shipped.text("brepta1953").records
WS = shipped.workspace()
ZETA = ["B-integral-zeta", "B-integral-denominator", "B-split", "B-split-limits", "B-reduced", "B-final",
        "C-integral-zeta", "C-split-limits", "C-final", "28", "30", "particular-solution"]
BRANCH = ["pendulum:51", "pendulum:51-repeated", "pendulum:separated-velocity", "pendulum:52"]


# --- 1. root causes -------------------------------------------------------------------------
def test_every_erratum_names_known_causes_of_its_text():
    for t in WS.papers():
        for rec in t.errata.values():
            assert rec.causes
            for c in rec.causes:
                assert t.causes[c].source == t.id
        for c in t.causes.values():
            assert c.title and c.title_cs and c.note and c.note_cs and c.kind in errata.KINDS
            assert t.records.displays_of(c.id), f"cause {c.id} affects no display"


def test_section_5_range_fault_is_one_cause():
    displays = BREPTA.displays_of("zeta-range")
    assert set(displays) >= {f"brepta1953:{z}" for z in ZETA}
    # C-split and C-reduced carry the range fault on top of their own
    assert set(displays) - {f"brepta1953:{z}" for z in ZETA} == {"brepta1953:C-split", "brepta1953:C-reduced"}
    assert len(ERRATA["brepta1953:C-split"].causes) == 2


@pytest.mark.parametrize("bad, message", [
    ('cause = ["no-such-cause"]', "unknown cause"),
    ("cause = []", "non-empty list"),
    ("", "lacks cause"),
])
def test_an_erratum_without_a_known_cause_is_refused(tmp_path, bad, message):
    text = f'''[[cause]]
id = "c1"
title = "t"
title_cs = "t"
kind = "sign"
note = "n"
note_cs = "n"

[[erratum]]
id = "pendulum:equation-of-motion"
kind = "sign"
{bad}
corrected = "Eq(D(phi, 2) + g/l*sin(phi), 0)"
corrected_latex = "x"
note = "n"
'''
    (tmp_path / "x.toml").write_text(text, encoding="utf-8")
    pendulum = shipped.text("pendulum")
    with pytest.raises(CatalogError, match=message):
        errata.load([tmp_path / "x.toml"], pendulum.entries, pendulum.symbols, pendulum.id)


def test_errata_json_lists_causes(outcomes, capsys):
    from quasicentral.cli import main

    assert main(["errata", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    by_id = {c["id"]: c for c in doc["causes"]}
    assert set(by_id) == set(CAUSES)
    z = by_id["zeta-range"]
    assert {"id", "title", "title_cs", "kind", "note", "note_cs", "displays", "witness"} <= set(z)
    assert len(z["displays"]) == 14 and z["witness"]["display"] in z["displays"]
    for r in doc["errata"]:
        assert r["cause"] and all(c in by_id for c in r["cause"])
    cleared = {r["id"]: r for r in doc["cleared"]}
    for eid in BRANCH:
        assert eid not in {r["id"] for r in doc["errata"]}
        assert cleared[eid]["branch"] and "rising quarter-swing" in cleared[eid]["branch"]


# --- 2. the text's stated branch ------------------------------------------------------------
@pytest.mark.parametrize("eid", BRANCH)
def test_branch_is_cleared_on_the_rising_quarter(eid, outcomes):
    assert outcomes[eid].status == "cleared"
    assert eid in CLEARED and CLEARED[eid].branch


@pytest.mark.parametrize("eid", ["pendulum:51", "pendulum:52"])
def test_the_plus_root_fails_on_the_descending_half_swing(eid):
    """The branch matters: on the descending half-swing (0 < Ωt < 2K) the printed + root is
    refuted, so clearing it names the branch it holds on."""
    _K = shipped.module("pendulum", "exact_period")._K

    e = shipped.entry(eid)
    Omega, t = e.symbols("Omega t")
    der = replace(shipped.derivation(eid), domain=Domain.of(ranges={t: (_K / 4 / Omega, 7 * _K / 4 / Omega)}))
    v = check(e.relations(), e.dims, der, eid, Options(points=8, symbolic=False, certify=False), e.symbols)
    assert isinstance(v, Refuted)


# --- 3. every printed digit guaranteed --------------------------------------------------------
def test_round_significant_is_exact():
    assert round_significant(Fraction(-224734634730228191822, 10**20), 17) == "-2.2473463473022819"
    assert round_significant(Fraction(5, 2), 1) == "2"  # half to even
    assert round_significant(Fraction(35, 10), 1) == "4"
    assert round_significant(Fraction(9999, 1000), 3) == "10.0"
    assert round_significant(Fraction(1, 10**7), 2) == "1.0e-7"


def _sides(eid, w):
    der = shipped.derivation(eid)
    defs = der.domain.definition_map(shipped.entry(eid).symbols)
    for claim in claims_for(shipped.entry(eid).relations(), der, derived(eid)):
        if claim.quantity != w.quantity:
            continue
        p = bridge.to_jets(bridge.close_infinite_sums(substitute_definitions(claim.printed, defs)))
        d = bridge.to_jets(bridge.close_infinite_sums(substitute_definitions(claim.derived, defs)))
        names = {str(s): s for s in p.free_symbols | d.free_symbols}
        if set(names) <= set(w.parameters):
            return p, d, {s: sp.sympify(w.parameters[n]) for n, s in names.items()}
    return None


def _digits_ok(shown: str, value, n: int) -> bool:
    if shown == "0":
        return abs(value) < mpmath.mpf(10) ** -60
    with mpmath.workdps(200):
        v = value.real if isinstance(value, mpmath.mpc) else value
        sgn, man, exp, _ = mpmath.mpf(v)._mpf_
        frac = Fraction((-1) ** sgn * man * 2**exp) if exp >= 0 else Fraction((-1) ** sgn * man, 2**-exp)
    return round_significant(frac, n) == shown


@pytest.mark.parametrize("eid", sorted(ERRATA))
def test_every_witness_digit_survives_an_independent_recomputation(eid, outcomes):
    """Both values of every witness recomputed in mpmath at 2.5× the working precision (+20):
    each digit shown is the correctly rounded one."""
    w = getattr(outcomes[eid].verdict, "witness", None)
    if w is None:
        return  # dimensional refutation: no numbers
    assert 1 <= w.digits <= 20
    sides = _sides(eid, w)
    assert sides is not None, "the witness's point does not fit its claim"
    p, d, pt = sides
    dps = int(2.5 * w.working_digits) + 20
    for shown, expr, cert in ((w.printed, p, w.printed_certified), (w.corrected, d, w.corrected_certified)):
        n = len(re.sub(r"[^0-9]", "", shown.split("e")[0]).lstrip("0")) or 1
        value = bridge.mp_eval(expr, pt, dps)
        assert _digits_ok(shown, value, max(n, 1)), f"{shown} vs {mpmath.nstr(value, 30)}"


def test_witness_of_B_integral_t_is_right_past_the_16th_digit(outcomes):
    """Its corrected value was printed −2.24734634730228104… (60 digits claimed, wrong from the
    16th); quadrature at 120 digits and the closed form agree on …28191822.  Whether a ball
    certifies it within its CPU budget or the doubled recomputation does, each digit shown is
    the truth's."""
    w = outcomes["brepta1953:B-integral-t"].verdict.witness
    truth = Fraction("-2.24734634730228191822190385565")
    assert w.corrected == round_significant(truth, w.digits if w.corrected_certified is False else len(
        re.sub(r"[^0-9]", "", w.corrected)))
    assert not w.corrected.startswith("-2.247346347302281038")


# --- 4. notes cannot drift ------------------------------------------------------------------
NUMBER = re.compile(r"(?<![A-Za-z_0-9{])[−-]?\d+\.\d+(?:e[−-]?\d+)?")


def test_erratum_and_cause_notes_quote_no_literal_numbers():
    """A decimal number in an erratum's or a cause's note would describe some point the
    witness does not: numbers come from the witness through placeholders."""
    for rec in ERRATA.values():
        assert not NUMBER.findall(rec.note), (rec.id, NUMBER.findall(rec.note))
    for c in CAUSES.values():
        assert not NUMBER.findall(c.note) and not NUMBER.findall(c.note_cs), c.id


@pytest.mark.parametrize("eid", sorted(ERRATA))
def test_rendered_notes_quote_the_witness(eid, outcomes):
    w = getattr(outcomes[eid].verdict, "witness", None)
    text = notes.render_note(ERRATA[eid].note, w)
    assert "{witness" not in text
    if w is not None and "{witness" in ERRATA[eid].note:
        assert w.printed in text or w.corrected in text
    # every decimal the rendered note quotes is one of the witness's own numbers
    allowed = set() if w is None else {w.printed, w.corrected, w.relative_difference,
                                        *notes.parameters_text(w).values()}
    for num in NUMBER.findall(text):
        assert any(num.replace("−", "-") in a for a in allowed), num


def test_unknown_placeholder_is_refused():
    with pytest.raises(CatalogError):
        errata.check_placeholders("see {witness.nonsense}", "here")


# --- 6. the cache is checked, not trusted ------------------------------------------------------
def test_cache_contradicting_the_registry_is_recomputed(tmp_path, monkeypatch):
    monkeypatch.setenv("QUASICENTRAL_CACHE", str(tmp_path))
    entries = [shipped.entry("pendulum:equation-of-motion")]
    opts = Options(points=6, symbolic=False)
    first = run.run(WS, entries, opts, jobs=1)
    assert first[0].status == "erratum"
    (f,) = list(tmp_path.glob("*.json"))
    d = json.loads(f.read_text())
    d["outcome"]["status"] = "verified"
    f.write_text(json.dumps(d))
    said = []
    again = run.run(WS, entries, opts, jobs=1, on_warning=said.append)
    assert again[0].status == "erratum"
    assert len(said) == 1 and "contradicts the errata registry" in said[0]
    # the recomputed verdict replaced the bad one
    assert json.loads(f.read_text())["outcome"]["status"] == "erratum"


@pytest.mark.parametrize("junk", ['{"foo": 1}', "[1, 2]", '{"id": "pendulum:55"}', "not json"])
def test_cache_of_the_wrong_shape_is_recomputed(tmp_path, monkeypatch, junk):
    monkeypatch.setenv("QUASICENTRAL_CACHE", str(tmp_path))
    entries = [shipped.entry("pendulum:55")]
    opts = Options(points=6, symbolic=False)
    assert run.run(WS, entries, opts, jobs=1)[0].status == "verified"
    (f,) = list(tmp_path.glob("*.json"))
    f.write_text(junk)
    said = []
    assert run.run(WS, entries, opts, jobs=1, on_warning=said.append)[0].status == "verified"
    assert len(said) == 1


def test_cli_prints_one_line_for_a_discarded_cache_entry(tmp_path, monkeypatch, capsys):
    from quasicentral.cli import main

    monkeypatch.setenv("QUASICENTRAL_CACHE", str(tmp_path))
    assert main(["verify", "--id", "pendulum:55", "--jobs", "1"]) == 0
    (f,) = list(tmp_path.glob("*.json"))
    f.write_text('{"id": 3}')
    capsys.readouterr()
    assert main(["verify", "--id", "pendulum:55", "--jobs", "1"]) == 0
    err = [ln for ln in capsys.readouterr().err.splitlines() if "warning" in ln]
    assert len(err) == 1 and "pendulum:55" in err[0]


# --- 7. the guards bite -------------------------------------------------------------------------
def _with_registry(monkeypatch, errs, cleared):
    """A deliberately wrong registry for the text of the entries tested (pendulum)."""
    text = shipped.text("pendulum")
    monkeypatch.setattr(text, "records", errata.Records(errs, cleared, text.causes))


FAST = Options(points=6, symbolic=False, certify=False)


def test_guard_registered_erratum_must_be_refuted(monkeypatch):
    """An erratum registered for an entry whose print is right does not stand."""
    e = shipped.entry("pendulum:55")
    fake = errata.Erratum(e.id, errata.Kind.SIGN, e.printed_text, e.latex, {"": "n"}, ("c",), symbols=e.symbols)
    _with_registry(monkeypatch, {e.id: fake}, {})
    o = run.verify_entry(WS, e, FAST)
    assert o.status == "unexpected" and "not refuted" in o.problem_texts[0]


def test_guard_the_correction_must_verify(monkeypatch):
    e = shipped.entry("pendulum:equation-of-motion")
    fake = errata.Erratum(e.id, errata.Kind.DERIVATIVE_ORDER, e.printed_text, e.latex, {"": "n"}, ("c",),
                          symbols=e.symbols)  # "corrects" to the print
    _with_registry(monkeypatch, {e.id: fake}, {})
    o = run.verify_entry(WS, e, FAST)
    assert o.status == "unexpected" and any("corrected form is refuted" in p for p in o.problem_texts)


def test_guard_a_cleared_suspect_must_verify(monkeypatch):
    e = shipped.entry("pendulum:equation-of-motion")
    _with_registry(monkeypatch, {}, {e.id: errata.Cleared(e.id, "s", {"": "n"})})
    o = run.verify_entry(WS, e, FAST)
    assert o.status == "unexpected" and "cleared suspect is refuted" in o.problem_texts[0]


def test_guard_an_unregistered_refutation_is_unexpected(monkeypatch):
    e = shipped.entry("pendulum:equation-of-motion")
    _with_registry(monkeypatch, {}, {})
    assert run.verify_entry(WS, e, FAST).status == "unexpected"


def test_the_true_registry_passes_the_same_entries():
    for eid, status in (("pendulum:55", "verified"), ("pendulum:equation-of-motion", "erratum")):
        assert run.verify_entry(WS, shipped.entry(eid), FAST).status == status


# --- the double-precision series (66), pinned term by term --------------------------------------
@pytest.mark.parametrize("n_terms", [1, 2, 3, 4, 5, 10, 44])
@pytest.mark.parametrize("m", ["0.0076", "0.5", "0.97"])
def test_series_66_matches_mpmath_at_each_number_of_terms(n_terms, m):
    """T/T0 ≈ Σ_{n<N} ((2n−1)!!/(2n)!!)² mⁿ computed independently in mpmath (binomial form
    ((1/2)_n/n!)², 40 digits): the double-precision sum with N terms agrees to 4 ulp, and the
    sum with N + 1 terms does not (so one term too many, or too few, fails)."""
    import numpy as np

    from quasicentral.models import period as P

    with mpmath.workdps(40):
        mm = mpmath.mpf(m)
        exact = [mpmath.fsum((mpmath.rf(0.5, n) / mpmath.factorial(n)) ** 2 * mm**n for n in range(N))
                 for N in (n_terms, n_terms + 1)]
    got = float(P.series_ratio(np.array([float(m)]), n_terms)[0][0])
    assert abs(got - float(exact[0])) <= 4 * np.spacing(float(exact[0]))
    if abs(float(exact[1]) - float(exact[0])) > 8 * np.spacing(float(exact[0])):
        assert abs(got - float(exact[1])) > 4 * np.spacing(float(exact[0]))
