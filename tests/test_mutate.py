"""Mutation testing of the checker: seeded typos in verified entries must all be caught, and
the unmutated catalog must raise no alarm."""

import pytest
import sympy as sp

from quasicentral.engine import texts

from quasicentral.engine import mutate
from quasicentral.engine.texts import symbols_of, SHIPPED_ROOT

S_ = symbols_of(SHIPPED_ROOT / "brepta1953" / "text.toml")
k, t, x = S_("k t x")


def test_operators_produce_the_typical_typos():
    rel = sp.Eq(x, k**2 * (sp.cos(t) + 2 * sp.sin(t)) + (1 + sp.sin(t)) ** sp.Rational(3, 2))
    ops = {op for op, _, _ in mutate.mutations(rel)}
    assert {"sign flip", "factor 2", "exponent x2", "exponent /2", "exponent +1", "dropped parentheses",
            "k <-> k^2", "t <-> s"} <= ops


def test_recall_and_false_alarms_on_the_catalog():
    """At most 3 mutants per verified entry (spread over the operators), for every entry whose
    printed form has no integral (each mutant of an integral costs seconds of quadrature); every
    mutant of every entry runs as `quasicentral mutate` and in the slow test below."""
    ids = [i for i in mutate.verified_entries() if not texts.entry(i).printed.has(sp.Integral)]
    res = mutate.run(per_entry=3, ids=ids)
    assert res["entries"] > 120 and res["mutants"] > 300
    assert res["false_alarms"] == 0, res["false_alarm_entries"]
    assert res["recall"] == 1.0, res["undetected"]


@pytest.mark.slow
def test_recall_on_every_mutant():
    res = mutate.run()
    assert res["false_alarms"] == 0 and res["recall"] == 1.0, res["undetected"]
