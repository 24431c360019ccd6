"""The DLMF chapters 19 and 22 as shipped identity texts, in the default run: a fixed sample of
each chapter verified, the misprints the checker found recorded as errata (each printed form
refuted, each correction verified), and the chapters' stated domains in the catalogs.  The
whole corpus runs under ``-m slow`` (``tests/test_semantic.py``) and in ``benchmarks/``."""

from __future__ import annotations

import tomllib

import pytest

import quasicentral as qc
from quasicentral.engine.texts import SHIPPED_ROOT

#: one or two entries of each family: Legendre, Carlson, Bulirsch, the AGM; Jacobi's functions,
#: their theta quotients (Neville's), zeros and poles at rounded K, K′ (Tables 22.4, 22.5), an
#: integral on the branch its principal value holds on, the pendulum's solution
SAMPLE = {
    "dlmf-19": ["dlmf-19:19.2.4", "dlmf-19:19.4.1", "dlmf-19:19.6.3", "dlmf-19:19.8.12", "dlmf-19:19.10.1",
                "dlmf-19:19.21.1", "dlmf-19:19.22.1", "dlmf-19:19.25.1", "dlmf-19:19.26.6", "dlmf-19:19.27.3"],
    "dlmf-22": ["dlmf-22:22.2.11", "dlmf-22:22.5.1-cn-K", "dlmf-22:22.4.1-sn-pole", "dlmf-22:22.6.1",
                "dlmf-22:22.14.2", "dlmf-22:22.19.2", "dlmf-22:22.19.3", "dlmf-22:22.16.1"],
}
#: the DLMF's misprints the checker found, each printed form refuted with a witness
MISPRINTS = ["dlmf-22:22.9.23", "dlmf-22:22.8.23", "dlmf-22:22.19.8", "dlmf-22:22.5.1-dc-K+iKp"]


@pytest.fixture(scope="module")
def chapter22():
    return qc.load_text("dlmf-22").verify(SAMPLE["dlmf-22"] + MISPRINTS + ["dlmf-22:22.19.1", "dlmf-22:22.8.19"],
                                          cache=False, jobs=1)


def test_a_sample_of_chapter_19_verifies():
    results = qc.load_text("dlmf-19").verify(SAMPLE["dlmf-19"], cache=False, jobs=1)
    assert {i: results[i].status.value for i in SAMPLE["dlmf-19"]} == {i: "verified" for i in SAMPLE["dlmf-19"]}


def test_a_sample_of_chapter_22_verifies(chapter22):
    assert {i: chapter22[i].status.value for i in SAMPLE["dlmf-22"]} == {i: "verified" for i in SAMPLE["dlmf-22"]}


def test_zeros_and_poles_at_rounded_periods_are_exact(chapter22):
    for i in ("dlmf-22:22.5.1-cn-K", "dlmf-22:22.4.1-sn-pole"):
        verdict = chapter22[i].outcome.verdict
        assert verdict.reason["zeros"] > 0, i


@pytest.mark.parametrize("eid", MISPRINTS)
def test_each_misprint_found_is_refuted_as_printed_and_verified_as_corrected(chapter22, eid):
    r = chapter22[eid]
    assert r.status.value == "erratum"
    assert r.outcome.verdict.name == "refuted" and r.outcome.verdict.witness is not None
    assert r.outcome.corrected_verdict.name == "verified"


def test_the_eom_a_section_solves_is_a_hypothesis_not_a_claim(chapter22):
    """22.19.1 states θ'' = −sin θ for the function θ(t) it introduces; 22.8.19 the condition
    z_1 + … + z_4 = 0 that introduces z_4: notation, not refuted (both were, before)."""
    assert chapter22["dlmf-22:22.19.1"].status.value == "notation"
    assert chapter22["dlmf-22:22.8.19"].status.value == "notation"


def test_chapter_22_keeps_its_modulus_in_the_unit_interval():
    """§22.1: 0 ≤ k ≤ 1 except in §§22.17 and 22.19 — every entry elsewhere that draws k draws it
    real in (0, 1) (drawn from the complex box, 22.4.3's shifts were "refuted" at k < 0)."""
    missing = []
    for path in sorted((SHIPPED_ROOT / "dlmf-22" / "catalog").glob("*.toml")):
        if path.stem in ("22.17", "22.19"):
            continue
        for e in tomllib.loads(path.read_text(encoding="utf-8"))["equation"]:
            cons = e.get("constraints", [])
            free_k = "k" in e.get("printed", "").replace("(", " ").replace(",", " ").replace(")", " ").split() \
                and not e.get("printed", "").startswith("Eq(Limit(") and "Eq(k," not in " ".join(cons)
            bounded = any(c.startswith(("Gt(k,", "Ge(k,", "Lt(0, k", "Le(0, k")) for c in cons)
            if free_k and not (bounded and "k" in e.get("real", [])):
                missing.append(e["id"])
    assert not missing
