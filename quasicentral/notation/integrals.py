"""Definite integrals made ready for numbers, in sympy alone: ends smoothed, parameters lifted
out, a period found.  Both the ball integrator (:mod:`quasicentral.notation.balls`) and
mpmath's quadrature (:mod:`quasicentral.notation.mpeval`) take their integrals from here.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import sympy as sp
from sympy.simplify.fu import TR9

def _singular(value: sp.Basic) -> bool:
    return value.has(sp.zoo, sp.oo, -sp.oo, sp.nan)


@dataclass(frozen=True)
class Prepared:
    """A definite integral made ready for quadrature (:func:`prepare`): ``pieces`` are
    integrals in the ``params`` only, each parameter standing for an expression in the outer
    symbols, computed once per value instead of at every node; ``singular`` says which pieces
    keep a singular end (mpmath integrates those at doubled precision)."""

    params: tuple[tuple[sp.Dummy, sp.Expr], ...]
    pieces: tuple[sp.Integral, ...]
    singular: tuple[bool, ...]


@lru_cache(maxsize=512)
def prepare(integral: sp.Integral) -> Prepared:
    """``integral`` with its ends smoothed, then its parameters lifted out (:func:`_lift`).

    At an end e where the integrand is unbounded like |x − e|^(−1/2) (1/√(1 − ζ²) at ζ = 1),
    x = e ± (b − a)·u² (u from 0 to 1) makes it analytic: every radicand is factored, its
    factor u² leaves the root as u (u > 0, so √(u²·W) = u·√W on the principal branch: the
    value is unchanged) and cancels the Jacobian's u.  The distance to the end is then u²,
    computed without cancellation, so both flint's Gauss–Legendre and tanh–sinh keep every
    working digit there.  A radicand in sines and cosines, cos(φ₀ − c·u²) − cos φ₀, shows its
    factor u² once written as products of sines (:func:`_small_sines`).  A path singular at
    both ends is cut at its midpoint.  Where the substitution does not leave an integrand sympy
    sees bounded (a log, a higher order) the path stays as it is, marked singular."""
    x, a, b = integral.limits[0]
    f = integral.function
    if any(e in (sp.oo, -sp.oo) for e in (a, b)):  # a half-line: mpmath's tanh–sinh maps it itself
        ends = [False, False]
    else:
        ends = [_singular(f.xreplace({x: e})) for e in (a, b)]
    pieces = [(integral, any(ends))]
    if any(ends):
        u = sp.Dummy("u", positive=True)
        spans = [(a, (a + b) / 2, True), ((a + b) / 2, b, False)] if all(ends) else [(a, b, ends[0])]
        smoothed = []
        for lo, hi, at_lower in spans:
            # ∫_lo^hi f dx = ∫_0^1 f(x(u))·2(hi − lo)·u du, x = lo + (hi − lo)u² or hi − (hi − lo)u²
            xs = lo + (hi - lo) * u**2 if at_lower else hi - (hi - lo) * u**2
            substituted = f.xreplace({x: xs}) * 2 * (hi - lo) * u
            bounded = False
            rewrites = [lambda r: r]
            if substituted.has(sp.sin, sp.cos):  # the product form is tried only where it can differ
                rewrites.append(lambda r: _small_sines(TR9(r), u))
            for radicand in rewrites:
                try:
                    g = substituted.replace(
                        lambda e: isinstance(e, sp.Pow) and not e.exp.is_Integer and e.base.has(u),
                        lambda e: sp.factor(radicand(e.base)) ** e.exp)
                    bounded = not _singular(g.xreplace({u: 0}))
                except (sp.PolynomialError, ValueError, TypeError, NotImplementedError):
                    bounded = False  # sympy cannot factor it: the path stays as it is
                if bounded:
                    break
            smoothed.append((sp.Integral(g, (u, 0, 1)), False))
            if not bounded:
                break
        else:
            pieces = smoothed
    table: dict[sp.Expr, sp.Dummy] = {}
    lifted = []
    for piece, _ in pieces:
        var, lo, hi = piece.limits[0]
        try:
            if piece.function.has(sp.Integral, sp.Sum, sp.Derivative, sp.Piecewise):
                raise TypeError("bound variables or conditions inside")
            body = _lift(piece.function, var, table)
        except (TypeError, ValueError, AttributeError):
            # kept whole (bound variables inside, or a node that cannot be rebuilt from its
            # arguments): only its outer symbols become parameters
            body = piece.function.xreplace({sym: _param(sym, table) for sym in piece.function.free_symbols - {var}})
        lo, hi = (end if end.is_number else _param(end, table) for end in (lo, hi))
        lifted.append(sp.Integral(body, (var, lo, hi)))
    return Prepared(tuple((d, e) for e, d in table.items()), tuple(lifted), tuple(s for _, s in pieces))


def _small_sines(e: sp.Expr, u: sp.Symbol) -> sp.Expr:
    """A radicand that vanishes at u = 0 without u² as a factor, cos(φ₀ − c·u²) − cos φ₀: after
    sympy's sum-to-product rules (``TR9``: −2·sin(φ₀ − c·u²/2)·sin(−c·u²/2)), each sine of an
    argument w that vanishes at u = 0 is written w·sinc(w) (sinc 1 at 0).  Identities for all
    complex values; the radicand's factor u² then shows, and its small factor is computed
    without the cancellation of cos(φ₀ − c·u²) − cos φ₀."""
    return e.replace(lambda s: isinstance(s, sp.sin) and s.args[0].has(u) and s.args[0].xreplace({u: 0}) == 0,
                     lambda s: s.args[0] * sp.sinc(s.args[0]))


def _param(e: sp.Expr, table: dict) -> sp.Dummy:
    if e not in table:
        table[e] = sp.Dummy(f"p{len(table)}")
    return table[e]


def _lift(e: sp.Expr, x: sp.Symbol, table: dict) -> sp.Expr:
    """``e`` with each largest sub-expression free of ``x`` (other than a number) replaced by a
    parameter: cos(√(g/l)·t)·(1 − k²x²) → p0·(1 − p1·x²).  The tree is only rebuilt, so its
    value is unchanged; an integrand is then a small expression in x and the parameters."""
    if not e.has(x):
        return e if e.is_number else _param(e, table)
    if e.is_Atom:
        return e
    if isinstance(e, sp.Add):
        e = sp.collect(e, x)  # a polynomial in x keeps one coefficient per power
    if isinstance(e, (sp.Add, sp.Mul)):
        free, bound = e.as_independent(x, as_Add=isinstance(e, sp.Add))
        rest = bound.args if bound.func is e.func else (bound,)
        return e.func(_lift(free, x, table), *[_lift(r, x, table) for r in rest])
    return e.func(*[_lift(arg, x, table) for arg in e.args])



def period(body: sp.Expr, var: sp.Symbol) -> sp.Expr | None:
    """A period P of ``body`` in ``var``, body(var + P) ≡ body(var) for every complex var, where
    var enters only through sines, cosines and tangents of c·var + d with one rate c for all:
    π/c if the shift by it leaves ``body`` unchanged (sympy's own rules, sin(x + π) = −sin x,
    then expansion), else 2π/c if that does; None otherwise (also where a period exists but
    is not found this way)."""
    trig = [f for f in body.atoms(sp.sin, sp.cos, sp.tan) if f.has(var)]
    if not trig or body.xreplace({f: sp.Dummy() for f in trig}).has(var):
        return None
    rates = set()
    for f in trig:
        arg = sp.expand(f.args[0])
        c = arg.coeff(var)
        if c == 0 or c.has(var) or (arg - c * var).has(var):
            return None
        rates.add(c)
    if len(rates) != 1:
        return None
    (c,) = rates
    for candidate in (sp.pi / c, 2 * sp.pi / c):
        shifted = body.xreplace({f: f.func(sp.expand(f.args[0].xreplace({var: var + candidate}))) for f in trig})
        if sp.expand(shifted - body) == 0:
            return candidate
    return None


#: a path of at least this many periods is integrated over one period and what is left over
PERIODS_WORTH_FOLDING = 2


def infinite_end(integral: sp.Integral) -> bool:
    """Whether a one-variable integral runs to ±∞ at an end."""
    return any(e in (sp.oo, -sp.oo) for e in integral.limits[0][1:])
