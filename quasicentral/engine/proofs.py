"""Symbolic proofs that a difference is zero: cheapest means first, within a CPU-time bound.

:func:`prove_zero` tries expansion and cancellation (nine in ten of the catalog's identities),
then, for identities in sines and cosines, their exponential form expanded and cancelled, then
sympy's ``simplify`` — not tried where a few numbers show the difference clearly non-zero at
points its symbols' assumptions allow (:func:`clearly_nonzero`: no sound simplification could
then return 0); for an integral with a variable upper limit, the fundamental theorem.  A
last attempt combines radicals as if their radicands were positive (:func:`forced_zero`): a
proof on the physical domain, which the numeric stage then checks at every point.  A failure
of sympy proves nothing: the answer is then False.
"""

from __future__ import annotations

from functools import lru_cache
from random import Random

import sympy as sp

from quasicentral.notation.domain import seed_for
from quasicentral.notation.timelimit import TimeLimitExceeded, time_limit


def prove_zero(diff: sp.Expr, seconds: float, force: bool = True) -> bool:
    """True when sympy proves ``diff`` identically zero within ``seconds``.  With ``force``, a
    last attempt combines radicals as if their radicands were positive (see
    :func:`forced_zero`).  The answer is remembered for the same expression (a display the text
    repeats, an erratum's claims that share their difference): each is sought once."""
    return _prove_zero(diff, seconds, force)


@lru_cache(maxsize=10_000)
def _prove_zero(diff: sp.Expr, seconds: float, force: bool) -> bool:
    try:
        with time_limit(seconds):
            if diff == 0:
                return True
            if diff.has(sp.Integral):  # simplify cannot see through an integral: differentiate it
                return by_fundamental_theorem(diff, force)
            return zero_by_rewriting(diff, force)
    except TimeLimitExceeded:
        return False
    except Exception:  # noqa: BLE001 - a CAS failure proves nothing
        return False


_TRIGONOMETRIC = (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc)


def zero_by_rewriting(e: sp.Expr, force: bool) -> bool:
    """The proof, cheapest means first.  Expansion and cancellation prove nine in ten of the
    catalog's identities at a fifth of simplify's cost.  Of the rest, those in sines and cosines
    fall to their exponential form (sin x = (e^(ix) − e^(−ix))/2i, every step an identity for
    all complex values) expanded and cancelled, at a tenth of simplify's cost, which spends half
    its time in trigsimp; simplify (trigonometric, radicals) takes what is left — unless a few
    numbers show that it cannot succeed (:func:`clearly_nonzero`)."""
    expanded = sp.expand(e)
    if expanded == 0 or rational_zero(expanded):
        return True
    if e.has(*_TRIGONOMETRIC):
        exponential = sp.expand(sp.powsimp(sp.expand(e.rewrite(sp.exp))))
        if exponential == 0 or rational_zero(exponential):
            return True
    if e.has(sp.hyper, sp.meijerg):  # a hypergeometric function in closed form: milliseconds, where
        # simplify takes a third of a second (₂F₁(1, 1; 2; −x) = ln(1 + x)/x)
        closed = sp.expand(sp.hyperexpand(e))
        if closed == 0 or rational_zero(closed):
            return True
    if not clearly_nonzero(e) and sp.simplify(e, doit=False) == 0:
        return True
    return force and forced_zero(e)


#: points at which :func:`clearly_nonzero` evaluates an expression, and the digits it uses
NONZERO_POINTS = 3
NONZERO_DPS = 30
#: |e| above this fraction of the sum of its terms' magnitudes is not a rounding error at
#: NONZERO_DPS digits (a true identity leaves about 10^-29 of it)
NONZERO_MARGIN = sp.Float("1e-15")
#: the reach of a sampled value: |x| < NONZERO_REACH (wide, so that a sign or a branch that an
#: identity depends on shows: sin(φ0/2) changes sign at φ0 = 2π)
NONZERO_REACH = 16
#: facts a sampled value is not made to obey: an expression whose symbols carry one is not sampled
_UNSAMPLED_FACTS = ("even", "odd", "prime", "composite", "zero", "imaginary", "noninteger", "irrational",
                    "transcendental", "polar", "infinite")
#: what would let sympy see into a function defined outside sympy
_SEEING_HOOKS = ("eval", "_eval_")


def clearly_nonzero(e: sp.Expr) -> bool:
    """True when ``e`` is clearly not 0 at one of a few points that sympy's assumptions allow:
    then no sound simplification returns 0, and simplify (the costliest means, most of the
    time of a proof that fails) is not tried.  Each free symbol takes a value from the set its
    assumptions name (positive, real, integer, …; complex where none is said); so does each
    application of a function sympy cannot see into (an undefined x(t), its derivatives, a
    function class without evaluation rules of its own, such as one computed by ``_imp_``):
    for simplify it is a bare value.  Seeded by the expression, the points are the same in
    every run.  Where anything is in doubt (an integral or a sum, a value that cannot be
    computed, a function met at two different arguments) the answer is False: simplify
    decides as before.  A proof this test prevents is one that sympy could only have given
    in error."""
    if not _samplable(e):
        return False
    opaque: dict = {}
    for f in sorted(e.atoms(sp.Derivative, sp.Function), key=sp.default_sort_key):
        if isinstance(f, sp.Derivative) or _opaque(f):
            opaque[f] = sp.Dummy(**{fact: True for fact in ("integer", "positive", "nonnegative", "negative",
                                                            "nonpositive", "real")
                                    if getattr(f, "is_" + fact)})
    heads = [f.func if not isinstance(f, sp.Derivative) else (f.expr.func, f.variable_count) for f in opaque]
    if len(heads) != len(set(heads)):
        return False  # f(a) and f(b): simplify might show a = b, independent values would not
    if any(getattr(f, "is_" + fact) for f in opaque for fact in _UNSAMPLED_FACTS):
        return False
    # derivatives first (they contain the function), then the functions
    sampled = e.xreplace({f: d for f, d in opaque.items() if isinstance(f, sp.Derivative)})
    sampled = sampled.xreplace({f: d for f, d in opaque.items() if not isinstance(f, sp.Derivative)})
    symbols = sorted(sampled.free_symbols, key=sp.default_sort_key)
    if any(getattr(s, "is_" + fact) for s in symbols for fact in _UNSAMPLED_FACTS):
        return False
    terms = sampled.args if isinstance(sampled, sp.Add) else (sampled,)
    rng = Random(seed_for(sp.srepr(e)))
    for _ in range(NONZERO_POINTS):
        point = {s: _assumed_value(s, rng) for s in symbols}
        try:
            values = [t.evalf(NONZERO_DPS, subs=point) for t in terms]
        except (TypeError, ValueError, ZeroDivisionError, ArithmeticError):
            continue
        if not all(v.is_number and v.is_finite for v in values):
            continue
        total = sp.Add(*values)
        if total.is_finite and abs(total) > NONZERO_MARGIN * sum(abs(v) for v in values):
            return True
    return False


def _samplable(e: sp.Expr) -> bool:
    """No integral, sum, product or limit; each derivative one of an undefined function's."""
    return (not e.has(sp.Integral, sp.Sum, sp.Product, sp.Limit)
            and all(isinstance(d.expr, sp.core.function.AppliedUndef) for d in e.atoms(sp.Derivative)))


def _opaque(f: sp.Basic) -> bool:
    """An application sympy's simplification sees only as a value: an undefined function, or a
    class defined outside sympy with no evaluation rule or rewrite of its own (``eval``,
    ``_eval_*``)."""
    if isinstance(f, sp.core.function.AppliedUndef):
        return True
    own = [c for c in type(f).__mro__ if not (c.__module__ or "").startswith("sympy") and c is not object]
    return bool(own) and not any(name.startswith(_SEEING_HOOKS) for c in own for name in vars(c))


def _assumed_value(s: sp.Symbol, rng: Random) -> sp.Expr:
    """A value in the set ``s``'s assumptions name: an integer 1…9 (or −9…9 without 0), a
    rational in (0, NONZERO_REACH) or (−NONZERO_REACH, NONZERO_REACH), or a complex one."""
    def rational() -> sp.Rational:
        return sp.Rational(rng.randrange(1, NONZERO_REACH * 2**16), 2**16)

    if s.is_integer:
        if s.is_positive or s.is_nonnegative:
            return sp.Integer(rng.randint(1, 9))
        if s.is_negative or s.is_nonpositive:
            return sp.Integer(-rng.randint(1, 9))
        return sp.Integer(rng.choice([-1, 1]) * rng.randint(1, 9))
    if s.is_positive or s.is_nonnegative:
        return rational()
    if s.is_negative or s.is_nonpositive:
        return -rational()
    if s.is_real:
        return rng.choice([-1, 1]) * rational()
    return rng.choice([-1, 1]) * rational() + sp.I * rng.choice([-1, 1]) * rational()


def rational_zero(e: sp.Expr) -> bool:
    """``e`` is 0 as a rational function of its generators: the numerator of its form over a
    common denominator expands to 0 (``together`` is an identity).  Where the answer is yes,
    ``cancel`` would say 0 too, but it first computes the numerator's gcd with the denominator,
    which a zero test does not need (a seventh of the symbolic stage's time)."""
    return sp.expand(sp.fraction(sp.together(e))[0]) == 0


def forced_zero(e: sp.Expr) -> bool:
    """√a·√b = √(ab) as if every radicand were positive — true inside the physical domains
    (|ζ| ≤ 1, k² < 1, …) though not for all complex values; the numeric cross-check that
    follows every proof guards against a domain where it fails.  Where forcing changes nothing,
    simplify has already failed on this very expression (:func:`zero_by_rewriting`): not tried again."""
    forced = sp.powsimp(sp.powdenest(e, force=True), force=True)
    return forced != e and (forced == 0 or not clearly_nonzero(forced) and sp.simplify(forced, doit=False) == 0)


def by_fundamental_theorem(diff: sp.Expr, force: bool = True) -> bool:
    """Integrals with a variable upper limit X: d/dX diff ≡ 0 and diff(lower limit) = 0."""
    for integral in diff.atoms(sp.Integral):
        for lim in integral.limits:
            if len(lim) == 3 and isinstance(lim[2], sp.Symbol):
                X, lower = lim[2], lim[1]
                dd = sp.diff(diff, X)
                if dd == 0 or zero_by_rewriting(dd, force):
                    # integrals over [a, a] vanish and those over [b, a] are −∫_a^b before sympy
                    # tries to integrate them (for an elliptic integrand it would search for an
                    # antiderivative until the bound): equal integrals then cancel as terms
                    at_lower = diff.subs(X, lower).replace(lambda e: isinstance(e, sp.Integral), _oriented)
                    if at_lower == 0:
                        return True
                    at_lower = at_lower.doit()
                    if at_lower == 0 or zero_by_rewriting(at_lower, False):
                        return True
    return False


def _oriented(integral: sp.Integral) -> sp.Expr:
    """A one-variable definite integral with numeric limits in increasing order (0 over an empty
    path); any other integral as it is."""
    if len(integral.limits) == 1 and len(integral.limits[0]) == 3:
        var, lo, hi = integral.limits[0]
        if lo == hi:
            return sp.S.Zero
        if lo.is_comparable and hi.is_comparable and (lo > hi) is sp.true:
            return -sp.Integral(integral.function, (var, hi, lo))
    return integral

