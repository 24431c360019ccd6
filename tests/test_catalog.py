"""The catalog of printed equations: complete, well-formed, dimensionally checked."""

import shipped
import pytest
import sympy as sp

from quasicentral.engine.catalog import CatalogError, load_file
from quasicentral.engine.checker import decided
from quasicentral.engine.dimensions import check_relation

WS = shipped.workspace()
ENTRIES = [e for t in WS.papers() for e in t.entries.values()]
IDS = [e.id for e in ENTRIES]


def test_every_numbered_equation_is_catalogued():
    numbers = {(e.source, e.number) for e in ENTRIES if e.number}
    expected = {("brepta1953", str(n)) for n in range(1, 34)} | {("brepta1953", "8a")}
    expected |= {("pendulum", str(n)) for n in range(49, 67)}
    assert expected <= numbers


def test_ids_are_unique_and_labelled():
    assert len(IDS) == len(set(IDS))
    for e in ENTRIES:
        assert e.id.startswith(e.source + ":")
        if e.number:
            assert e.id == f"{e.source}:{e.number}"


@pytest.mark.parametrize("eid", IDS)
def test_transcription_parses(eid):
    e = shipped.entry(eid)
    for rel in e.relations():
        assert isinstance(rel, sp.Basic)
        assert decided(rel) not in (sp.true, sp.false), "a transcription must not be decided True/False"
    assert e.latex and e.name and e.section


@pytest.mark.parametrize("eid", IDS)
def test_dimensions(eid):
    """Every entry is dimensionally consistent, unless it is a registered erratum (a printed
    equation that mixes units is an error in print, and must be recorded as one)."""
    e = shipped.entry(eid)
    checks = [check_relation(r, e.dims) for r in e.relations()]
    problems = [c for c in checks if c.inconsistent or c.undetermined]
    assert not any(c.undetermined for c in checks), f"a dimension is not declared: {problems}"
    errs, _ = shipped.records()
    if problems:
        assert eid in errs, f"dimensionally inconsistent and not a registered erratum: {problems}"
    if eid in errs:
        rec = errs[eid]
        for rel in rec.relations():
            assert check_relation(rel, e.dims).status.value == "consistent", "a correction must be dimensionally consistent"


def test_every_entry_has_a_derivation():
    missing = [i for i in IDS if WS.derivation(i) is None]
    assert not missing
    ours = {t.id for t in WS.papers()}
    stray = [i for i in WS.derivations.by_id if i.split(":")[0] in ours and i not in set(IDS)]
    assert not stray, "derivations for ids the catalog does not have"


def test_malformed_file_is_refused(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text('source = "brepta1953"\nsection = "2"\n[[equation]]\nid = "brepta1953:x"\nname = "x"\n'
                   "latex = 'x'\nprinted = 'Eq(x, nosuchname)'\n")
    table = shipped.text("brepta1953").symbols
    with pytest.raises(CatalogError, match=r"bad.toml:7: brepta1953:x: unknown name nosuchname"):
        load_file(bad, "brepta1953", table)
    bad.write_text('source = "brepta1953"\nsection = "2"\n[[equation]]\nid = "brepta1953:x"\nname = "x"\n')
    with pytest.raises(CatalogError, match="lacks"):
        load_file(bad, "brepta1953", table)
    bad.write_text("source = [")
    with pytest.raises(CatalogError):
        load_file(bad, "brepta1953", table)


@pytest.mark.parametrize("eid", IDS)
def test_uses_are_what_the_derivation_uses(eid):
    """A derivation's declared ``uses`` are exactly the ids it asks ``derived()`` for."""
    assert WS.used(eid) == set(shipped.derivation(eid).declared_uses)


def test_an_integral_over_a_bound_variable_has_the_dimension_of_its_integrand_times_the_variable():
    """∫₀^∞ v f(v) dv (f a density in s/m) has no free symbol, and sympy calls it a number:
    it was dimensionless, so a correct ⟨v⟩ = ∫ v f dv was "inconsistent" and a wrong
    ∫ v f dv = 1 "consistent" (a newcomer's Maxwell distribution)."""
    from quasicentral.notation.units import parse_dim

    v, w = sp.symbols("v w", nonnegative=True)
    f = sp.Function("f")(v)
    speed = parse_dim("m/s")
    dims = {v: speed, w: speed, f: 1 / speed}
    mean = sp.Integral(v * f, (v, 0, sp.oo))
    assert check_relation(sp.Eq(mean, w), dims).status.value == "consistent"
    assert check_relation(sp.Eq(mean, 1), dims).status.value == "inconsistent"
    assert check_relation(sp.Eq(sp.Integral(f, (v, 0, sp.oo)), 1), dims).status.value == "consistent"
