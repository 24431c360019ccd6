"""The commands of a reading: letters, constants, fractions, roots, delimiters, the big
operators (integrals, sums, products, limits), derivatives, O-terms and the macros of
:data:`.macros.MACROS`.  Each reader takes the parser with its cursor on the command."""

from __future__ import annotations

from types import MappingProxyType
import re

from . import nodes as N
from .lexer import Kind, Token
from .macros import CONSTANTS, GREEK, JACOBI, MACROS

_DELIMS = MappingProxyType({"(": ")", "[": "]", "|": "|", ".": None, r"\{": r"\}", r"\|": r"\|", r"\lbrace": r"\rbrace"})
_OPERATORNAMES = MappingProxyType({"sech": "sech", "csch": "csch", "arctan": "atan", "arccos": "acos",
                  "arcsin": "asin", "arctanh": "atanh", "arcsinh": "asinh", "ph": "arg",
                  "sign": "sign", "gd": "gd"})


def atom_command(p, t: Token) -> N.Node:
    name = t.text
    if name[1:] in GREEK:
        p.next()
        return p.symbol(p.letters.get(name[1:], GREEK[name[1:]]))
    if name in CONSTANTS:
        p.next()
        return N.Const(CONSTANTS[name])
    if name in (r"\frac", r"\tfrac", r"\dfrac", r"\ifrac", r"\cfrac"):
        p.next()
        if p.toks[p.i + 1].is_(r"\pdiff"):
            return partial_fraction(p)
        num = p.group()
        return N.div(num, p.group())
    if name == r"\sqrt":
        return root(p)
    if name == r"\left":
        return delimited(p)
    if name == r"\int":
        return integral(p)
    if name in (r"\sum", r"\prod"):
        return bigop(p, "Sum" if name == r"\sum" else "Product")
    if name == r"\lim":
        return limit(p)
    if name in (r"\deriv", r"\pderiv"):
        return derivative(p)
    if name == r"\diff":
        p.next()
        var = p.group()
        if not p.diffs:
            raise p.error("a differential outside an integral", t)
        p.diffs[-1].append(var)
        return N.ONE
    if name == r"\bigO":
        return big_o(p)
    if name == r"\operatorname":
        return operatorname(p)
    if name in (r"\mathbf", r"\boldsymbol"):
        return vector(p, t)
    if name == r"\partial":
        return partial_index(p, t)
    if name == r"\mathrm":
        p.next()
        text = p.group_text()
        if re.fullmatch(r"[a-z](,[a-z])+", text):  # \mathrm{p,q}: letters
            return N.Tup(tuple(N.Sym(p.letters.get(c, c)) for c in text.split(",")), True)
        if text == "i":
            return N.Const("I")
        if text == "e":
            return N.Const("E")
        if len(text) == 1 and text.isalpha():
            return p.symbol(p.letters.get(text, text))
        raise p.error(f"\\mathrm{{{text}}}", t)
    if name == r"\begin":
        return environment(p)
    if name == r"\Sci":
        p.next()
        mantissa, exponent = p.group_text(), p.group_text()
        return N.Num(f"{mantissa}e{exponent}")
    if name == r"\lightspeed":
        p.next()
        return N.Sym("lightspeed")
    if name in MACROS:
        return macro(p, name)
    raise p.error(f"the macro {name} is not known to the reader", t)


def root(p) -> N.Node:
    p.next()
    degree = None
    if p.tok.is_("["):
        p.next()
        start = p.i
        while not p.tok.is_("]"):
            if p.tok.kind is Kind.END:
                raise p.error("an unclosed [ of a root's degree")
            p.next()
        degree = p.sub(start, p.i, p.expr)
        p.next()
    radicand = p.group()
    if degree is None:
        return N.call("sqrt", radicand)
    return N.power(radicand, N.div(N.ONE, degree))


def delimited(p) -> N.Node:
    p.next()
    opener = p.next().text
    if opener not in _DELIMS:
        raise p.error(f"the delimiter \\left{opener}")
    depth = p.abs_depth
    p.abs_depth = 0
    items = p.comma_list()
    p.abs_depth = depth
    p.skip_space()
    p.expect(r"\right")
    if not p.tok.is_("/"):  # \left. … \right/ : the slash is a division of what follows
        p.next()
    inner = items[0] if len(items) == 1 else N.Tup(tuple(items), True)
    return N.call("Abs", inner) if opener in ("|", r"\|") else inner


def scripts(p) -> tuple[tuple[int, int] | None, tuple[int, int] | None]:
    """The token ranges of a big operator's lower and upper limits (either order)."""
    lower = upper = None
    for _ in range(2):
        p.skip_space()
        if p.tok.is_("_") and lower is None:
            p.next()
            lower = p.script_tokens()
        elif p.tok.is_("^") and upper is None:
            p.next()
            upper = p.script_tokens()
    return lower, upper


def integral(p) -> N.Node:
    t = p.next()
    lower, upper = scripts(p)
    if (lower is None) != (upper is None):
        raise p.error("an integral over a domain, not between two limits", t)
    lo = p.sub(*lower, p.expr) if lower else None
    hi = p.sub(*upper, p.expr) if upper else None
    p.diffs.append([])
    body = p.term(integral=p.diffs[-1])
    found = p.diffs.pop()
    if not found:
        raise p.error("an integral without its differential \\diff", t)
    var, rest = found[0], found[1:]
    if rest:
        if not p.diffs:
            raise p.error("more differentials than integrals", t)
        p.diffs[-1].extend(rest)
    if not isinstance(var, N.Sym):
        raise p.error("a differential of an expression", t)
    limits = N.Tup((var, lo, hi), True) if lo is not None else var
    return N.call("Integral", body, limits)


def bigop(p, head: str) -> N.Node:
    t = p.next()
    lower, upper = scripts(p)
    if lower is None or upper is None:
        raise p.error(f"a {'sum' if head == 'Sum' else 'product'} without its limits", t)
    first = p.toks[lower[0]]
    index = first.text[1:] if first.kind is Kind.COMMAND else first.text
    outer = p.letters.pop(index, None)  # inside the sum the letter is its index
    try:
        rel = p.sub(*lower, p.chain)
        if len(rel) != 1 or not isinstance(rel[0], N.Rel) or rel[0].op != "Eq" or not isinstance(rel[0].lhs, N.Sym):
            raise p.error("a lower limit that is not index=value", t)
        var, lo = rel[0].lhs, rel[0].rhs
        hi = p.sub(*upper, p.expr)
        return _bigop_body(p, head, t, var, lo, hi)
    finally:
        if outer is not None:
            p.letters[index] = outer


def _bigop_body(p, head, t, var, lo, hi) -> N.Node:
    """The body of a sum or product: the factors that follow, up to the last one that depends
    on the index (∏ z_j^{-b_j} R(…) is (∏ z_j^{-b_j}) R(…)); a subscript indexed by the index
    over a few integers is written out term by term."""
    diffs = p.diffs[-1] if p.diffs else None  # the differential of an enclosing integral ends the body
    n0 = len(diffs) if diffs is not None else 0
    start, outer = p.i, p.sub_letters
    p.sub_letters = set()
    ends, depends = [], []
    while True:
        before = set(p.sub_letters)
        divide = p.tok.is_("/")
        if divide:
            p.next()
        f = p.factor()
        uses = var.name in (p.sub_letters - before) or any(isinstance(x, N.Sym) and x.name == var.name for x in N.walk(f))
        ends.append(p.i)
        depends.append(uses)
        if (diffs is not None and len(diffs) > n0) or p.at_term_end() or p.tok.is_(r"\times", r"\cdot"):
            break
    last = max((j for j, d in enumerate(depends) if d), default=len(ends) - 1)
    if diffs is not None and len(diffs) > n0:
        last = len(ends) - 1  # an integrand ends at its differential
    end = ends[last]
    used, p.sub_letters = p.sub_letters, outer | p.sub_letters
    if var.name not in used:
        p.i = start
        body = _factors(p, end)
        return N.call(head, body, N.Tup((var, lo, hi), True))
    ints = [int(x.text) if isinstance(x, N.Num) and x.text.isdigit() else None for x in (lo, hi)]
    if None in ints or not 0 <= ints[1] - ints[0] <= 12:
        raise p.error(f"a {head.lower()} whose terms index a subscript by {var.name} "
                      "(only a few integers are written out)", t)
    parts = []
    for value in range(ints[0], ints[1] + 1):
        p.i = start
        if diffs is not None:
            del diffs[n0:]
        p.letters[var.name] = str(value)
        p.values[var.name] = N.Num(str(value))
        parts.append(_factors(p, end))
    p.values.pop(var.name, None)
    p.letters.pop(var.name, None)
    return N.add(*parts) if head == "Sum" else N.mul(*parts)


def _factors(p, end: int) -> N.Node:
    """The product of the factors from the cursor to ``end`` (re-read, so that bindings apply)."""
    value = N.ONE
    while p.i < end:
        divide = p.tok.is_("/")
        if divide:
            p.next()
        f = p.factor()
        value = N.div(value, f) if divide else (N.apply_ops(value, f) if N.has_op(value) else N.mul(value, f))
    return value


def limit(p) -> N.Node:
    t = p.next()
    p.skip_space()
    if not p.tok.is_("_"):
        raise p.error("a limit without its subscript", t)
    p.next()
    start, end = p.script_tokens()

    def point():
        var = p.atom()
        p.skip_space()
        if not p.tok.is_(r"\to", r"\rightarrow"):
            raise p.error("a limit's subscript is var \\to point")
        p.next()
        p.trailing_sign = None
        at = p.expr()
        return var, at, p.trailing_sign

    var, at, side = p.sub(start, end, point)
    body = p.term()
    args = [body, var, at]
    if side is not None:
        args.append(N.Str("-" if isinstance(side, N.Neg) else "+"))
    return N.Call("Limit", tuple(args))


def derivative(p) -> N.Node:
    t = p.next()
    order: N.Node = N.ONE
    if p.tok.is_("["):
        p.next()
        start = p.i
        while not p.tok.is_("]"):
            p.next()
        order = p.sub(start, p.i, p.expr)
        p.next()
    f_start, f_end = p.group_tokens()
    var = p.group()
    if not isinstance(var, N.Sym):
        raise p.error("a derivative with respect to an expression", t)
    if f_end > f_start:
        f = p.sub(f_start, f_end, p.expr)
    elif p.at_term_end() or p.tok.is_(r"\pderiv", r"\deriv"):
        if not (isinstance(order, N.Num) and order.text.isdigit()):
            raise p.error("an operator of a symbolic order", t)
        return N.Op(((var, int(order.text)),))  # an operator: its operand follows the parenthesis
    else:
        f = p.factor()
    return N.call("Derivative", f, N.Tup((var, order), True))


def partial_fraction(p) -> N.Node:
    """``\\frac{\\pdiff[2]{}}{\\pdiff{x}\\pdiff{y}}``: the operator ∂²/∂x∂y."""
    num_start, num_end = p.group_tokens()
    den_start, den_end = p.group_tokens()
    variables = []
    j = den_start
    while j < den_end:
        if not p.toks[j].is_(r"\pdiff"):
            raise p.error("a denominator of differentials \\pdiff{x}", p.toks[j])
        save = p.i
        p.i = j + 1
        variables.append(p.group())
        j, p.i = p.i, save
    counts: dict = {}
    for v in variables:
        counts[v] = counts.get(v, 0) + 1
    return N.Op(tuple(counts.items()))


def partial_index(p, t) -> N.Node:
    """``\\partial_{j}``: ∂/∂x_j, with x the letter ``Options.operators["partial"]`` names."""
    p.next()
    stem = p.opt.operators.get("partial")
    if stem is None or not p.tok.is_("_"):
        raise p.error("\\partial_{j} (give Options.operators['partial'], the variables' letter)", t)
    p.next()
    start, end = p.script_tokens()
    idx = "".join(p.letters.get(tok.text, tok.text) for tok in p.toks[start:end])
    return N.Op(((N.Sym(f"{stem}_{idx}"), 1),))


def vector(p, t) -> N.Node:
    """DLMF's vectors, written out for ``Options.dimension`` = n: ``\\mathbf{z}`` is
    (z_1, …, z_n), ``\\boldsymbol{{c}}`` the constant vector (c, …, c)."""
    p.next()
    text = p.group_text()
    n = p.opt.dimension
    if n is None:
        raise p.error(f"the vector {t.text}{{{text}}} (give Options.dimension)", t)
    if text == "e" and p.tok.is_("_"):  # the unit vector e_j
        p.next()
        start, end = p.script_tokens()
        j = p.sub(start, end, p.expr)
        if not (isinstance(j, N.Num) and j.text.isdigit()):
            raise p.error("a unit vector e_j of an unbound index (bind j)", t)
        return N.Tup(tuple(N.ONE if m == int(j.text) else N.ZERO for m in range(1, n + 1)), True)
    if re.fullmatch(r"[a-zA-Z]", text):
        return N.Tup(tuple(N.Sym(f"{text}_{j}") for j in range(1, n + 1)), True)
    inner = text[1:-1] if text.startswith("{") and text.endswith("}") else text
    power = re.fullmatch(r"([a-zA-Z])\^\{(-?\d+)\}", inner)
    if power:  # \boldsymbol{{z^{-1}}}: (z_1^{-1}, …, z_n^{-1})
        e = N.Num(power.group(2).lstrip("-"))
        e = N.neg(e) if power.group(2).startswith("-") else e
        return N.Tup(tuple(N.power(N.Sym(f"{power.group(1)}_{j}"), e) for j in range(1, n + 1)), True)
    from .lexer import tokenize
    from .parser import Parser

    sub = Parser(tokenize(inner), p.opt, inner)
    sub.letters, sub.values = p.letters, p.values
    c = sub.expr()
    if any(isinstance(x, N.Sym) for x in N.walk(c)):
        raise p.error(f"the vector {t.text}{{{text}}}", t)
    return N.Tup((c,) * n, True)


def flat_list(items) -> tuple:
    """A list of Carlson's R with its vectors written out: λ𝐳 → (λz_1, …, λz_n)."""
    out = []
    for item in items:
        if isinstance(item, N.Add) and any(isinstance(t, N.Tup) for t in item.terms):
            vecs = [t.items if isinstance(t, N.Tup) else None for t in item.terms]
            if None in vecs or len({len(v) for v in vecs}) != 1:
                raise ValueError("a sum of a vector and a scalar")
            out.extend(N.add(*parts) for parts in zip(*vecs))
            continue
        if isinstance(item, N.Tup):
            out.extend(item.items)
        elif isinstance(item, N.Mul) and any(isinstance(f, N.Tup) for f in item.factors):
            vec = [f for f in item.factors if isinstance(f, N.Tup)]
            scalar = [f for f in item.factors if not isinstance(f, N.Tup)]
            if len(vec) != 1:
                raise ValueError("a product of two vectors")
            out.extend(N.mul(*scalar, x) for x in vec[0].items)
        else:
            out.append(item)
    return tuple(out)


def big_o(p) -> N.Node:
    t = p.next()
    p.after_name()
    arg = p.group() if p.tok.kind is Kind.OPEN else p.factor()
    if p.opt.order is not None:
        var, at = N.Sym(p.opt.order[0]), p.opt.order[1]
        point = N.Const("oo") if at == "oo" else N.Num(at) if at.isdigit() else N.Sym(at)
    else:
        syms = {n for n in N.walk(arg) if isinstance(n, N.Sym)}
        plain = all(isinstance(n, (N.Sym, N.Num, N.Pow, N.Mul, N.Div)) for n in N.walk(arg))
        if len(syms) != 1 or not plain:
            raise p.error("an O-term whose limit the formula does not state (give Options.order)", t)
        var, point = syms.pop(), N.ZERO
    return N.call("O", arg, N.Tup((var, point), True))


def operatorname(p) -> N.Node:
    t = p.next()
    text = p.group_text()
    if text in JACOBI:
        return N.call(JACOBI[text], p.factor(), N.Sym(p.opt.modulus))
    if text in _OPERATORNAMES:
        return N.call(_OPERATORNAMES[text], p.factor())
    raise p.error(f"\\operatorname{{{text}}}", t)


def environment(p) -> N.Node:
    from .parser import determinant

    t = p.next()
    env = p.group_text()
    if env != "vmatrix":
        raise p.error(f"the environment {env}", t)
    rows: list[list[N.Node]] = [[]]
    p.matrix += 1
    while True:
        p.skip_space()
        if p.tok.is_(r"\end"):
            p.next()
            p.group_text()
            break
        rows[-1].append(p.expr())
        p.skip_space()
        if p.tok.is_("&"):
            p.next()
        elif p.tok.is_(r"\\"):
            p.next()
            rows.append([])
    p.matrix -= 1
    if any(len(r) != len(rows) for r in rows):
        raise p.error("a determinant that is not square", t)
    return determinant(rows)


def macro(p, name: str) -> N.Node:
    m = MACROS[name]
    t = p.next()
    params = [p.group_tokens() for _ in range(m.params)]
    ptext = ["".join(tok.text for tok in p.toks[a:b]) for a, b in params]
    if m.form == "noat":
        return N.Call(m.func, tuple(p.macro_args(m.args)))
    if m.form == "sqrt":
        p.i -= 1
        return root(p)
    exponent, at = p.after_name()
    bare = p.tok.kind is not Kind.OPEN
    if m.form == "list":
        p.skip_space()
        if p.tok.is_(r"\left"):
            inner = delimited(p)
        else:
            p.expect("(")
            items = p.comma_list()
            p.expect(")")
            inner = items[0] if len(items) == 1 else N.Tup(tuple(items), True)
        items = inner.items if isinstance(inner, N.Tup) else (inner,)
        node: N.Node = N.Call(m.func, tuple(items))
    elif m.form == "carlson":
        a = p.sub(*params[0], p.expr)
        b = flat_list(p.group(p.comma_list))
        z = flat_list(p.group(p.comma_list))
        node = N.call("CarlsonR", N.neg(a), N.Tup(b), N.Tup(z))
    elif m.form == "hyper":
        a = p.group(p.comma_list)
        b = p.group(p.comma_list)
        if [len(a), len(b)] != [int(x) for x in ptext]:
            raise p.error(f"{name}{{{ptext[0]}}}{{{ptext[1]}}} with {len(a)} and {len(b)} parameters", t)
        node = N.call("hyper", N.Tup(tuple(a), True), N.Tup(tuple(b), True), p.group())
    elif m.form == "appell":
        if ptext != ["1"]:
            raise p.error(f"the Appell function F{ptext[0]}", t)
        node = N.Call("appellf1", tuple(p.macro_args(6)))
    elif m.form == "bulirsch":
        counts = {"1": 2, "2": 4, "3": 3}
        if ptext[0] not in counts:
            raise p.error(f"Bulirsch's el{ptext[0]}", t)
        node = N.Call(f"BulirschEl{ptext[0]}", tuple(p.macro_args(counts[ptext[0]])))
    elif m.form == "jacobi":
        node = N.Call(p.jacobi_name(ptext[0], ptext[1], m.func == "JacobiArc"), tuple(p.macro_args(2)))
    elif m.form in ("theta", "theta_tau"):
        j = p.theta_index(ptext[0])
        if j not in ("1", "2", "3", "4"):
            raise p.error(f"the theta function θ_{ptext[0]} (bind its letter)", t)
        z, second = p.macro_args(2)
        if m.form == "theta_tau":
            second = N.call("exp", N.mul(N.Const("I"), N.Const("pi"), second))
        node = N.call(f"JacobiTheta{j}", z, second)
    elif m.form in ("lattice", "lattice_root"):
        node = lattice(p, m, ptext, t)
    elif bare and m.implied:
        node = N.Call(m.func, tuple(N.Sym(a) for a in m.implied))
    elif bare and m.args == 1 and not at:
        node = N.call(m.func, p.factor())  # presentation style: \sin z
    else:
        node = N.Call(m.func, tuple(p.macro_args(m.args)))
    if m.form == "general_value":
        p.notes.append(f"{name[1:]} (the general value) read as the principal {m.func}")
    if m.form == "gudermannian":
        x = node.args[0]
        node = (N.call("atan", N.call("sinh", x)) if m.func == "gd"
                else N.call("asinh", N.call("tan", x)))
    return N.power(node, exponent) if exponent is not None else node


def lattice(p, m, ptext, t) -> N.Node:
    """Weierstrass functions of the lattice 𝕃 = 2ω₁ℤ + 2ω₃ℤ, read as ``f(z, omega_1, omega_3)``;
    e_j = ℘(ω_j) with ω₂ = −ω₁ − ω₃ (DLMF 23.2.2)."""
    w1, w3 = N.Sym("omega_1"), N.Sym("omega_3")
    z = p.group() if m.form == "lattice" else None
    if p.group_text() != r"\mathbb{L}":
        raise p.error("a Weierstrass function of another lattice than \\mathbb{L}", t)
    if m.form == "lattice":
        return N.call(m.func, z, w1, w3)
    j = p.letters.get(ptext[0].lstrip("\\"), ptext[0])
    half = {"1": w1, "3": w3, "2": N.add(N.neg(w1), N.neg(w3))}.get(j)
    if half is None:
        raise p.error(f"the root e_{ptext[0]} (bind its index)", t)
    return N.call("WeierstrassP", half, w1, w3)
