"""Printed against derived, for every catalog entry (ids are the equation labels)."""

import shipped
import mpmath
import pytest
import sympy as sp

from quasicentral.notation import bridge
from quasicentral.engine.checker import claims_for
from quasicentral.notation.domain import substitute_definitions
from quasicentral.engine.verdict import Method, Refuted, Verified
from shipped import derived

IDS = [e.id for t in shipped.workspace().papers() for e in t.entries.values()]
ERRATA, CLEARED = shipped.records()


@pytest.mark.parametrize("eid", IDS)
def test_verify(eid, outcomes):
    """Each entry is verified, a registered erratum (printed refuted, correction verified) or a
    cleared suspect."""
    o = outcomes[eid]
    assert o.ok, f"{o.status}: {o.verdict.name} ({o.verdict.method.value}): {o.verdict.detail}; {o.problems}"


@pytest.mark.parametrize("eid", sorted(ERRATA))
def test_erratum_both_ways(eid, outcomes):
    o = outcomes[eid]
    assert isinstance(o.verdict, Refuted)
    assert isinstance(o.corrected_verdict, Verified)
    assert o.verdict.method in (Method.NUMERIC, Method.CERTIFIED, Method.DIMENSIONAL)


@pytest.mark.parametrize("eid", sorted(ERRATA))
def test_witness_reproduces(eid, outcomes):
    """A numeric witness is reproducible: re-evaluating both sides at its exact parameters gives
    its values again, and they differ."""
    w = getattr(outcomes[eid].verdict, "witness", None)
    if w is None:
        assert outcomes[eid].verdict.method is Method.DIMENSIONAL
        return
    der = shipped.derivation(eid)
    defs = der.domain.definition_map(shipped.entry(eid).symbols)
    for claim in claims_for(shipped.entry(eid).relations(), der, derived(eid)):
        if claim.quantity != w.quantity:
            continue
        p = bridge.to_jets(substitute_definitions(claim.printed, defs))
        d = bridge.to_jets(substitute_definitions(claim.derived, defs))
        names = {str(s): s for s in p.free_symbols | d.free_symbols}
        if set(names) - set(w.parameters):
            continue
        pt = {s: sp.sympify(w.parameters[n]) for n, s in names.items()}
        dps = int(2.5 * w.working_digits) + 20  # above the working precision: the digits shown are exact
        pv, dv = bridge.mp_eval(p, pt, dps), bridge.mp_eval(d, pt, dps)
        tol = mpmath.mpf(10) ** (1 - w.digits)  # the values show w.digits guaranteed digits
        with mpmath.workdps(w.working_digits):
            wp, wd = mpmath.mpmathify(w.printed), mpmath.mpmathify(w.corrected)
            if abs(pv - wp) <= tol * (1e-30 + abs(pv)) and abs(dv - wd) <= tol * (1e-30 + abs(dv)):
                assert abs(pv - dv) > 1e-10 * (abs(pv) + abs(dv))
                return
    pytest.fail("the witness could not be reproduced")


@pytest.mark.parametrize("eid", sorted(CLEARED))
def test_cleared_suspect_verifies(eid, outcomes):
    """A cleared suspect verifies as printed; on an entry that is an erratum for another
    reason, the correction keeps the suspected detail and verifies."""
    o = outcomes[eid]
    assert isinstance(o.corrected_verdict if eid in ERRATA else o.verdict, Verified)
    assert CLEARED[eid].note and CLEARED[eid].suspicion
