"""A numeric sanity check of the DLMF transcriptions with mpmath alone (no special-function
classes): the transcription is parsed with sympy, its functions are evaluated by name through
mpmath (modulus k → parameter m = k²), and each relation is tested at a few points that satisfy
the entry's constraints.  It is the importer's check of its own reading, not a verification:
an evaluation that is not defined here (Weierstrass, undefined functions) makes the entry
``Unevaluable``.

Evaluations are by independent routes where mpmath has one (ellipk, elliprf, ellipfun, jtheta);
functions mpmath lacks (am, ℰ, the inverse Jacobian functions, Bulirsch's integrals) are the
integrals that define them.
"""

from __future__ import annotations

import random
import time
import tomllib
from dataclasses import dataclass
from pathlib import Path

import mpmath as mp
import sympy as sp
from sympy.parsing.sympy_parser import auto_number, parse_expr

ROOT = Path(__file__).resolve().parent.parent
TEXTS = {"dlmf-19": ROOT / "quasicentral" / "texts" / "dlmf-19", "dlmf-22": ROOT / "quasicentral" / "texts" / "dlmf-22"}

#: Function names of the contract, with their arities where fixed (None: any).
CONTRACT = [
    "EllipticK", "EllipticE", "EllipticF", "EllipticD", "EllipticPi", "EllipticKp", "EllipticEp",
    "CarlsonRF", "CarlsonRD", "CarlsonRJ", "CarlsonRC", "CarlsonRG", "CarlsonR", "BulirschCel",
    "BulirschEl1", "BulirschEl2", "BulirschEl3", "AGM", "JacobiZeta", "HeumanLambda",
    *[f"Jacobi{p}" for p in ("SN", "CN", "DN", "NS", "NC", "ND", "SC", "SD", "CS", "CD", "DS", "DC")],
    "JacobiAM", "JacobiEpsilon", "JacobiZ",
    *[f"JacobiArc{p}" for p in ("SN", "CN", "DN", "NS", "NC", "ND", "SC", "SD", "CS", "CD", "DS", "DC")],
    "JacobiTheta1", "JacobiTheta2", "JacobiTheta3", "JacobiTheta4", "EllipticNome",
]
#: Names this import needed beyond the contract (sympy's own, and the Weierstrass functions).
EXTRA = ["WeierstrassP", "WeierstrassZeta", "WeierstrassSigma"]
SYMPY_NAMES = ["sqrt", "sin", "cos", "tan", "cot", "sec", "csc", "asin", "acos", "atan", "sinh", "cosh",
               "tanh", "coth", "sech", "csch", "asinh", "acosh", "atanh", "log", "exp", "pi", "I", "oo",
               "gamma", "beta", "digamma", "hyper", "appellf1", "rf", "binomial", "factorial", "Sum",
               "Product", "Integral", "Derivative", "Limit", "O", "Abs", "re", "im", "arg", "conjugate",
               "sign", "floor", "Eq", "Ne", "Lt", "Le", "Gt", "Ge", "And", "Or", "Rational", "Tuple",
               "Min", "Max", "Function", "Subs"]


class Unevaluable(Exception):
    """An entry this helper has no numbers for."""


@dataclass
class Text:
    id: str
    symbols: dict[str, sp.Symbol]
    entries: list[dict]


def load(text_id: str) -> Text:
    root = TEXTS[text_id]
    meta = tomllib.loads((root / "text.toml").read_text(encoding="utf-8"))
    symbols = {n: sp.Symbol(n, **{a: True for a in s.get("assumptions", [])}) for n, s in meta["symbols"].items()}
    entries = []
    for f in sorted((root / "catalog").glob("*.toml")):
        data = tomllib.loads(f.read_text(encoding="utf-8"))
        for e in data["equation"]:
            entries.append({**e, "section": data["section"], "file": f.name})
    return Text(text_id, symbols, entries)


def namespace(text: Text) -> dict:
    ns = {n: sp.Function(n) for n in CONTRACT + EXTRA}
    for n in SYMPY_NAMES:
        ns[n] = getattr(sp, n)
    ns["Eq"] = lambda a, b: sp.Eq(a, b, evaluate=False)
    for rel in ("Ne", "Lt", "Le", "Gt", "Ge"):
        ns[rel] = (lambda r: lambda a, b: r(a, b, evaluate=False))(getattr(sp, rel))
    ns.update(text.symbols)
    return ns


def parse(text: str, ns: dict):
    out = parse_expr(text, local_dict=ns, global_dict={"__builtins__": {}, "Integer": sp.Integer,
                                                         "Float": sp.Float, "Symbol": sp.Symbol},
                     transformations=(auto_number,))
    return list(out) if isinstance(out, (list, tuple)) else [out]


# --- evaluation -----------------------------------------------------------------------------
def _sn(u, k):
    return mp.ellipfun("sn", u, m=k ** 2)


def _jac(p: str):
    def part(c, u, k):
        if c == "n":
            return mp.mpf(1)
        return mp.ellipfun({"s": "sn", "c": "cn", "d": "dn"}[c], u, m=k ** 2)
    return lambda u, k: part(p[0], u, k) / part(p[1], u, k)


def _quad(f, a, b):
    return mp.quad(f, [a, b])


def _kp(k):
    return mp.sqrt(1 - k ** 2)


_ARC = {  # DLMF 22.15.12-23: (lower, upper, integrand) with x the argument
    "SN": lambda x, k: _quad(lambda t: 1 / mp.sqrt((1 - t ** 2) * (1 - k ** 2 * t ** 2)), 0, x),
    "CN": lambda x, k: _quad(lambda t: 1 / mp.sqrt((1 - t ** 2) * (_kp(k) ** 2 + k ** 2 * t ** 2)), x, 1),
    "DN": lambda x, k: _quad(lambda t: 1 / mp.sqrt((1 - t ** 2) * (t ** 2 - _kp(k) ** 2)), x, 1),
    "CD": lambda x, k: _quad(lambda t: 1 / mp.sqrt((1 - t ** 2) * (1 - k ** 2 * t ** 2)), x, 1),
    "SD": lambda x, k: _quad(lambda t: 1 / mp.sqrt((1 - _kp(k) ** 2 * t ** 2) * (1 + k ** 2 * t ** 2)), 0, x),
    "ND": lambda x, k: _quad(lambda t: 1 / mp.sqrt((t ** 2 - 1) * (1 - _kp(k) ** 2 * t ** 2)), 1, x),
    "DC": lambda x, k: _quad(lambda t: 1 / mp.sqrt((t ** 2 - 1) * (t ** 2 - k ** 2)), 1, x),
    "NC": lambda x, k: _quad(lambda t: 1 / mp.sqrt((t ** 2 - 1) * (k ** 2 + _kp(k) ** 2 * t ** 2)), 1, x),
    "SC": lambda x, k: _quad(lambda t: 1 / mp.sqrt((1 + t ** 2) * (1 + _kp(k) ** 2 * t ** 2)), 0, x),
    "NS": lambda x, k: _quad(lambda t: 1 / mp.sqrt((t ** 2 - 1) * (t ** 2 - k ** 2)), x, mp.inf),
    "DS": lambda x, k: _quad(lambda t: 1 / mp.sqrt((t ** 2 + k ** 2) * (t ** 2 - _kp(k) ** 2)), x, mp.inf),
    "CS": lambda x, k: _quad(lambda t: 1 / mp.sqrt((1 + t ** 2) * (t ** 2 + _kp(k) ** 2)), x, mp.inf),
}


def _kprime(k, f):
    """K′(k), E′(k): K(k′), E(k′) for |ph k| ≤ π/2, continued beyond by DLMF 19.2.9 (the
    complementary integrals are analytic in the plane cut along k ≤ 0)."""
    k = mp.mpc(k)
    base = f(1 - k ** 2)
    if abs(mp.arg(k)) <= mp.pi / 2:
        return base
    s = 1 if mp.arg(k) > 0 else -1
    if f is mp.ellipk:
        return base - s * 2j * mp.ellipk(k ** 2)
    return base - s * 2j * (mp.ellipk(k ** 2) - mp.ellipe(k ** 2))


def _carlson_r(a, b, z):
    b, z = list(b), list(z)
    if len(b) == 2:  # 19.25.43
        return z[1] ** (-a) * mp.hyp2f1(a, b[0], b[0] + b[1], 1 - z[0] / z[1])
    ap = sum(b) - a
    if mp.re(a) <= 0 or mp.re(ap) <= 0:
        raise Unevaluable("R_-a with a or a' not positive")
    f = lambda t: t ** (ap - 1) * mp.fprod((t + zj) ** (-bj) for bj, zj in zip(b, z))  # noqa: E731
    return mp.quad(f, [0, 1, mp.inf]) / mp.beta(a, ap)


FUNCS = {
    "EllipticK": lambda k: mp.ellipk(k ** 2),
    "EllipticE": lambda *a: mp.ellipe(a[0] ** 2) if len(a) == 1 else mp.ellipe(a[0], a[1] ** 2),
    "EllipticF": lambda phi, k: mp.ellipf(phi, k ** 2),
    "EllipticD": lambda *a: ((mp.ellipk(a[0] ** 2) - mp.ellipe(a[0] ** 2)) / a[0] ** 2 if len(a) == 1
                             else (mp.ellipf(a[0], a[1] ** 2) - mp.ellipe(a[0], a[1] ** 2)) / a[1] ** 2),
    "EllipticPi": lambda *a: mp.ellippi(a[0], a[1] ** 2) if len(a) == 2 else mp.ellippi(a[1], a[0], a[2] ** 2),
    "EllipticKp": lambda k: _kprime(k, mp.ellipk),
    "EllipticEp": lambda k: _kprime(k, mp.ellipe),
    "CarlsonRF": mp.elliprf, "CarlsonRD": mp.elliprd, "CarlsonRJ": mp.elliprj, "CarlsonRC": mp.elliprc,
    "CarlsonRG": mp.elliprg, "AGM": mp.agm, "EllipticNome": lambda k: mp.qfrom(k=k),
    "BulirschCel": lambda kc, p, a, b: _quad(lambda t: (a * mp.cos(t) ** 2 + b * mp.sin(t) ** 2) / (mp.cos(t) ** 2 + p * mp.sin(t) ** 2)
                                             / mp.sqrt(mp.cos(t) ** 2 + kc ** 2 * mp.sin(t) ** 2), 0, mp.pi / 2),
    "BulirschEl1": lambda x, kc: _quad(lambda t: 1 / mp.sqrt(mp.cos(t) ** 2 + kc ** 2 * mp.sin(t) ** 2), 0, mp.atan(x)),
    "BulirschEl2": lambda x, kc, a, b: _quad(lambda t: (a + b * mp.tan(t) ** 2) / mp.sqrt((1 + mp.tan(t) ** 2) * (1 + kc ** 2 * mp.tan(t) ** 2)), 0, mp.atan(x)),
    "BulirschEl3": lambda x, kc, p: _quad(lambda t: 1 / ((mp.cos(t) ** 2 + p * mp.sin(t) ** 2) * mp.sqrt(mp.cos(t) ** 2 + kc ** 2 * mp.sin(t) ** 2)), 0, mp.atan(x)),
    "JacobiAM": lambda x, k: _quad(lambda t: mp.ellipfun("dn", t, m=k ** 2), 0, x),
    "JacobiEpsilon": lambda x, k: _quad(lambda t: mp.ellipfun("dn", t, m=k ** 2) ** 2, 0, x),
    "JacobiZ": lambda x, k: (_quad(lambda t: mp.ellipfun("dn", t, m=k ** 2) ** 2, 0, x)
                             - mp.ellipe(k ** 2) / mp.ellipk(k ** 2) * x),
    **{f"Jacobi{p.upper()}": _jac(p) for p in ("sn", "cn", "dn", "ns", "nc", "nd", "sc", "sd", "cs", "cd", "ds", "dc")},
    **{f"JacobiArc{p}": f for p, f in _ARC.items()},
    **{f"JacobiTheta{j}": (lambda j: lambda z, q: mp.jtheta(j, z, q))(j) for j in (1, 2, 3, 4)},
    "CarlsonR": _carlson_r,
}
#: Our own routes (above) are the reference; with the special functions merged
#: (quasicentral.notation.special) their ``mp`` methods evaluate the contract's names instead,
#: unless DLMF_NUMERIC=helper asks for this file's routes.
HELPER = dict(FUNCS)


def _use_special() -> None:
    import os

    if os.environ.get("DLMF_NUMERIC") == "helper":
        return
    try:
        from quasicentral.notation.special import FUNCTIONS as SPECIAL
    except ImportError:
        return
    for name, cls in SPECIAL.items():
        FUNCS[name] = (lambda c: lambda *a: c.mp(*[tuple(x) if isinstance(x, list) else x for x in a]))(cls)


_use_special()

ELEMENTARY = {
    sp.sin: mp.sin, sp.cos: mp.cos, sp.tan: mp.tan, sp.cot: mp.cot, sp.sec: mp.sec, sp.csc: mp.csc,
    sp.asin: mp.asin, sp.acos: mp.acos, sp.atan: mp.atan, sp.sinh: mp.sinh, sp.cosh: mp.cosh,
    sp.tanh: mp.tanh, sp.coth: mp.coth, sp.sech: mp.sech, sp.csch: mp.csch, sp.asinh: mp.asinh,
    sp.acosh: mp.acosh, sp.atanh: mp.atanh, sp.log: mp.log, sp.exp: mp.exp, sp.gamma: mp.gamma,
    sp.beta: mp.beta, sp.digamma: mp.digamma, sp.factorial: mp.factorial, sp.rf: mp.rf,
    sp.binomial: mp.binomial, sp.Abs: abs, sp.re: mp.re, sp.im: mp.im, sp.arg: mp.arg,
    sp.sign: lambda x: mp.sign(x), sp.floor: mp.floor, sp.conjugate: mp.conj,
    sp.Min: lambda *a: min(a, key=mp.re), sp.Max: lambda *a: max(a, key=mp.re),
}


_DEADLINE = [float("inf")]


def ev(e, env: dict):
    """The value of a sympy expression at ``env`` (symbol → mpmath number)."""
    if time.monotonic() > _DEADLINE[0]:
        raise Unevaluable("too slow to evaluate here")
    if isinstance(e, sp.Symbol):
        if e not in env:
            raise Unevaluable(f"no value for {e}")
        return env[e]
    if e.is_Number:
        return mp.mpf(e.p) / e.q if e.is_Rational else mp.mpf(str(e)) if e.is_Float else (
            mp.inf if e == sp.oo else -mp.inf if e == -sp.oo else mp.mpf(float(e)))
    if e is sp.pi:
        return +mp.pi
    if e is sp.I:
        return mp.mpc(0, 1)
    if e is sp.E:
        return mp.e
    if e is sp.oo:
        return mp.inf
    if isinstance(e, sp.Add):
        return mp.fsum(ev(a, env) for a in e.args)
    if isinstance(e, sp.Mul):
        return mp.fprod(ev(a, env) for a in e.args)
    if isinstance(e, sp.Pow):
        b, x = ev(e.base, env), ev(e.exp, env)
        if e.exp == sp.Rational(1, 2):
            return mp.sqrt(b)
        return mp.power(b, x)
    if isinstance(e, sp.Integral):
        return _integral(e, env)
    if isinstance(e, (sp.Sum, sp.Product)):
        return _sum(e, env)
    if isinstance(e, sp.Derivative):
        (var, n), = e.variable_count
        x0 = ev(var, env)
        return mp.diff(lambda t: ev(e.expr, {**env, var: t}), x0, int(n))
    if isinstance(e, sp.Limit):
        return _limit(e, env)
    if isinstance(e, sp.hyper):
        a = [ev(x, env) for x in e.ap]
        b = [ev(x, env) for x in e.bq]
        return mp.hyper(a, b, ev(e.argument, env))
    if isinstance(e, sp.appellf1):
        return mp.appellf1(*(ev(a, env) for a in e.args))
    if isinstance(e, sp.Order):
        raise Unevaluable("an O-term inside a function")
    if isinstance(e, sp.Tuple):
        return [ev(a, env) for a in e.args]
    f = type(e)
    if f in ELEMENTARY:
        return ELEMENTARY[f](*(ev(a, env) for a in e.args))
    name = getattr(f, "__name__", "")
    if name in FUNCS:
        args = [ev(a, env) for a in e.args]
        return FUNCS[name](*args)
    raise Unevaluable(f"no evaluation of {name or f}")


def _integral(e, env):
    body = e.function
    limits = list(e.limits)

    def inner(level, env2):
        if level < 0:
            return ev(body, env2)
        lim = limits[level]
        if len(lim) != 3:
            raise Unevaluable("an indefinite integral")
        var, a, b = lim
        lo, hi = ev(a, env2), ev(b, env2)
        return mp.quad(lambda t: inner(level - 1, {**env2, var: t}), [lo, hi])
    return inner(len(limits) - 1, env)


def _sum(e, env):
    if any(lim[1] == -sp.oo and lim[2] == sp.oo for lim in e.limits) and e.function.has(sp.Sum, sp.Limit):
        raise Unevaluable("a double series over all integers")
    if len(e.limits) > 1:
        inner = type(e)(e.function, *e.limits[:-1])
        return _sum(type(e)(inner, e.limits[-1]), env)
    (var, a, b), = e.limits
    lo, hi = ev(a, env), ev(b, env)
    f = lambda n: ev(e.function, {**env, var: mp.mpf(n)})  # noqa: E731
    if isinstance(e, sp.Product):
        if mp.isinf(hi):
            return mp.nprod(f, [lo, hi])
        return mp.fprod(f(n) for n in range(int(lo), int(hi) + 1))
    if mp.isinf(lo) or mp.isinf(hi):
        return mp.nsum(f, [lo, hi])
    return mp.fsum(f(n) for n in range(int(lo), int(hi) + 1))


def _asymptotic(difference, orders, env) -> bool:
    """lhs − rhs = O(g) as v → p: |lhs − rhs|/|g| does not grow as v approaches p."""
    var, point = orders[0].variables[0], orders[0].point[0]
    ratios = []
    for step in (1, 2, 3):
        h = mp.mpf(10) ** -step
        if point == sp.oo:
            x = 1 / h
        elif point == -sp.oo:
            x = -1 / h
        else:
            x = ev(point, {}) + h * env.get("__side__", 1)
        e2 = {**env, var: x}
        g = sum(abs(ev(o.expr, e2)) for o in orders)
        ratios.append(abs(ev(difference, e2)) / g if g else mp.inf)
    return bool(ratios[-1] <= 10 * ratios[0] + 1e-6)


def _limit_infinite(rel, env) -> bool:
    """f → ±∞: |f| grows as the point is approached, with the sign of the right side."""
    body, var, point, side = rel.lhs.args
    p = ev(point, env)
    rhs_sign = ev(rel.rhs.subs(sp.oo, 1), env)
    vals = []
    for h in (mp.mpf(10) ** -4, mp.mpf(10) ** -8):
        x = (1 / h if p > 0 else -1 / h) if mp.isinf(p) else p + (-h if str(side) == "-" else h)
        vals.append(ev(body, {**env, var: x}))
    grows = abs(vals[1]) > abs(vals[0]) * 1.2 and abs(vals[1]) > 5
    return bool(grows and mp.re(vals[1]) * mp.re(rhs_sign) > 0)


def _limit(e, env):
    body, var, point, side = e.args
    p = ev(point, env)
    if mp.isinf(p):
        return ev(body, {**env, var: mp.mpf(10) ** 12 * (1 if p > 0 else -1)})
    h = mp.mpf(10) ** -(mp.mp.dps // 2)
    sides = {"+": [h], "-": [-h]}.get(str(side), [h])
    return ev(body, {**env, var: p + sides[0]})


# --- relations and points ------------------------------------------------------------------------
def split_order(expr):
    """(expr without its O-terms, their arguments)."""
    orders = list(expr.atoms(sp.Order))
    rest = expr.subs({o: 0 for o in orders}) if orders else expr
    return rest, orders


QUADRATURE = ("Integral", "Sum", "Product", "CarlsonR(", "JacobiAM", "JacobiEpsilon", "JacobiZ", "JacobiArc", "Bulirsch")


def holds(rel, env, tol=mp.mpf(10) ** -7, strict: bool = False) -> bool | None:
    """Whether a relation holds at ``env`` (None: not tested, e.g. Ne); ``strict`` (for the
    constraints a point must satisfy) keeps off the boundaries, else the slack is lenient."""
    if isinstance(rel, sp.Equality) and isinstance(rel.lhs, sp.Limit) and rel.rhs.has(sp.oo):
        return _limit_infinite(rel, env)
    if isinstance(rel, sp.Equality):
        lhs, rhs = rel.lhs, rel.rhs
        lhs, lo = split_order(lhs)
        rhs, ro = split_order(rhs)
        a, b = ev(lhs, env), ev(rhs, env)
        if mp.isinf(a) or mp.isinf(b):  # a limit approached numerically: large is infinite
            return bool(min(abs(a), abs(b)) > 1e3 and (mp.re(a) * mp.re(b) >= 0))
        diff = abs(a - b)
        if lo or ro:
            return _asymptotic(lhs - rhs, lo + ro, env)
        if any(q in str(rel) for q in QUADRATURE):
            tol = max(tol, mp.mpf(10) ** -5)  # a quadrature or a series summed numerically
        if "Limit" in str(rel):
            tol = max(tol, mp.mpf(10) ** -6)  # a limit taken at a nearby point
        return diff <= tol * (1 + abs(a) + abs(b))
    if isinstance(rel, sp.Ne):
        return None
    if isinstance(rel, (sp.StrictLessThan, sp.LessThan, sp.StrictGreaterThan, sp.GreaterThan)):
        a, b = ev(rel.lhs, env), ev(rel.rhs, env)
        if abs(mp.im(a)) > 1e-9 * (1 + abs(a)) or abs(mp.im(b)) > 1e-9 * (1 + abs(b)):
            return False
        a, b = mp.re(a), mp.re(b)
        slack = tol * (1 + abs(a) + abs(b)) * (-1 if strict else 1)
        return {sp.StrictLessThan: a < b + slack, sp.LessThan: a <= b + abs(slack),
                sp.StrictGreaterThan: a > b - slack, sp.GreaterThan: a >= b - abs(slack)}[type(rel)]
    if isinstance(rel, sp.Or):
        return any(holds(r, env, tol, strict) for r in rel.args)
    if isinstance(rel, sp.And):
        return all(holds(r, env, tol, strict) for r in rel.args)
    if isinstance(rel, sp.Basic) and not isinstance(rel, sp.Rel):
        raise Unevaluable("a bare expression")
    raise Unevaluable(f"the relation {type(rel).__name__}")


@dataclass
class Outcome:
    ok: bool
    tested: int
    point: dict | None = None
    values: tuple | None = None
    reason: str = ""


def check(entry: dict, text: Text, points: int = 3, seed: int = 1, dps: int = 30, budget: float = 20) -> Outcome:
    _DEADLINE[0] = time.monotonic() + budget
    try:
        return _check(entry, text, points, seed, dps)
    except RecursionError:
        raise Unevaluable("too deep to evaluate here") from None
    finally:
        _DEADLINE[0] = float("inf")


def _check(entry: dict, text: Text, points: int, seed: int, dps: int) -> Outcome:
    ns = namespace(text)
    rels = parse(entry["printed"], ns)
    cons = [parse(c, ns)[0] for c in entry.get("constraints", [])]
    if not all(isinstance(r, sp.Rel) for r in rels):
        raise Unevaluable("a bare expression")
    defs, conds = {}, []
    # a relation whose left side is a bare symbol no constraint fixes defines that symbol
    tested_rels = []
    for r in rels:
        if (isinstance(r, sp.Equality) and isinstance(r.lhs, sp.Symbol) and r.lhs not in defs
                and not any(isinstance(c, sp.Equality) and c.lhs == r.lhs for c in cons)
                and r.lhs not in r.rhs.free_symbols):
            defs[r.lhs] = r.rhs
        else:
            tested_rels.append(r)
    if not tested_rels:
        raise Unevaluable("a definition only")
    rels = tested_rels
    for c in cons:
        if isinstance(c, sp.Equality) and isinstance(c.lhs, sp.Symbol) and c.lhs not in defs:
            defs[c.lhs] = c.rhs
        elif isinstance(c, sp.Equality) and c.rhs == sp.floor(c.lhs):
            conds.append(("integer", c.lhs))
        else:
            conds.append(("rel", c))
    bound = set()
    for r in rels + cons:
        for node in sp.preorder_traversal(r):
            if isinstance(node, (sp.Integral, sp.Sum, sp.Product)):
                bound |= {lim[0] for lim in node.limits}
            if isinstance(node, sp.Lambda):
                bound |= set(node.variables)
    free = set()
    for r in rels + cons:
        free |= r.free_symbols
    free -= bound
    free -= set(defs)
    for v in defs.values():
        free |= v.free_symbols - set(defs) - bound
    real = set(entry.get("real", []))
    integers = {s for kind, s in conds if kind == "integer"} | {s for s in free if s.is_integer}
    order_points = {}
    for r in rels:
        for o in r.atoms(sp.Order):
            for v, p in zip(o.variables, o.point):
                order_points[v] = p
    if any(v in defs for v in order_points):
        raise Unevaluable("an O-term in a symbol another defines")
    rng = random.Random(seed + hash(entry["id"]) % 1000)
    tested = 0
    with mp.workdps(dps):
        for scale in ("unit", "wide", "complex"):
            for _ in range(60):
                env = {}
                for s in sorted(free, key=str):
                    if s in integers:
                        env[s] = mp.mpf(rng.randint(0, 4))
                    elif s in order_points:
                        p = order_points[s]
                        side = rng.choice((1, -1))
                        env["__side__"] = side
                        env[s] = mp.mpf(10) ** 4 if p == sp.oo else ev(p, {}) + side * mp.mpf(10) ** -3
                    elif scale == "unit" or s.name in real:
                        env[s] = mp.mpf(rng.uniform(0.1, 0.9)) if scale == "unit" else mp.mpf(rng.uniform(-2, 2))
                    elif scale == "wide":
                        env[s] = mp.mpf(rng.uniform(-2, 2))
                    else:
                        env[s] = mp.mpc(rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5))
                try:
                    for _ in range(len(defs) + 1):
                        for s, v in defs.items():
                            try:
                                env[s] = ev(v, env)
                            except Unevaluable:
                                pass
                    if any(s not in env for s in defs):
                        continue
                    if not all(holds(c, env, strict=True) is not False for kind, c in conds if kind == "rel"):
                        continue
                    values = []
                    for r in rels:
                        ok = holds(r, env)
                        values.append(ok)
                        if ok is False:
                            return Outcome(False, tested, {str(k): v for k, v in env.items()},
                                           (_side(r.lhs, env), _side(r.rhs, env)), f"{r}")
                except (ZeroDivisionError, ValueError, OverflowError, mp.libmp.NoConvergence):
                    continue
                tested += 1
                if tested >= points:
                    return Outcome(True, tested)
    if tested == 0:
        raise Unevaluable("no point satisfies the constraints")
    return Outcome(True, tested)


def _side(e, env):
    try:
        return ev(split_order(e)[0], env)
    except Exception:  # noqa: BLE001 - for the report only
        return None
