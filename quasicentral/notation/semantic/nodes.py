"""The expression tree a reading builds, and its printer in sympy syntax.

The tree is small on purpose: numbers, symbols, constants, sums, products, quotients,
powers, function calls, tuples and relations, plus two placeholders for DLMF's correlated
signs (``\\pm``, ``\\mp``) that :func:`resolve` replaces by +1 or −1 before printing.  The
constructors :func:`add`, :func:`mul`, :func:`div`, :func:`neg` and :func:`power` keep it
flat (no product inside a product, no double negation), so that the printer needs only
precedences to place parentheses.

>>> print(to_sympy(div(add(Sym("a"), neg(Sym("b"))), mul(Num("2"), Sym("c")))))
(a - b)/(2*c)
>>> print(to_sympy(power(neg(Num("1")), Sym("n"))))
(-1)**n
"""

from __future__ import annotations

from dataclasses import dataclass

ADD, NEG, MUL, POW, ATOM = 10, 15, 20, 30, 100


class Node:
    """A node of the tree (immutable, hashable)."""


@dataclass(frozen=True)
class Num(Node):
    text: str  # an unsigned decimal numeral, "2", "0.5", "6.65e-12"


@dataclass(frozen=True)
class Sym(Node):
    name: str


@dataclass(frozen=True)
class Const(Node):
    name: str  # "pi", "I", "oo", "E" (Euler's number, printed exp(1))


@dataclass(frozen=True)
class Str(Node):
    text: str  # a string argument: the side of a one-sided limit


@dataclass(frozen=True)
class Add(Node):
    terms: tuple[Node, ...]


@dataclass(frozen=True)
class Neg(Node):
    arg: Node


@dataclass(frozen=True)
class Mul(Node):
    factors: tuple[Node, ...]


@dataclass(frozen=True)
class Div(Node):
    num: Node
    den: Node


@dataclass(frozen=True)
class Pow(Node):
    base: Node
    exp: Node


@dataclass(frozen=True)
class Call(Node):
    func: str
    args: tuple[Node, ...]


@dataclass(frozen=True)
class Tup(Node):
    items: tuple[Node, ...]
    bare: bool = False  # (n, 0, oo) in Sum and Integral; else Tuple(...)


@dataclass(frozen=True)
class Rel(Node):
    op: str  # Eq Ne Lt Le Gt Ge, or "to" / "sim" / "in" (read by the caller)
    lhs: Node
    rhs: Node


@dataclass(frozen=True)
class PM(Node):
    sign: int  # +1: \pm (upper sign +), -1: \mp


@dataclass(frozen=True)
class PMSym(Node):
    base: str  # p_{\pm}: p_plus under the upper sign, p_minus under the lower
    sign: int


@dataclass(frozen=True)
class Op(Node):
    """A differential operator not yet applied: ∂^{n1+n2…}/∂x^{n1}∂y^{n2}…"""
    orders: tuple[tuple[Node, int], ...]


ONE, ZERO = Num("1"), Num("0")


# --- constructors that keep the tree flat ---------------------------------------------------
def neg(x: Node) -> Node:
    if isinstance(x, Neg):
        return x.arg
    if x == ZERO:
        return x
    return Neg(x)


def add(*terms: Node) -> Node:
    flat: list[Node] = []
    for t in terms:
        if isinstance(t, Add):
            flat.extend(t.terms)
        elif t != ZERO:
            flat.append(t)
    if not flat:
        return ZERO
    return flat[0] if len(flat) == 1 else Add(tuple(flat))


def mul(*factors: Node) -> Node:
    sign = 1
    flat: list[Node] = []
    for f in factors:
        while isinstance(f, Neg):
            sign, f = -sign, f.arg
        if isinstance(f, Mul):
            flat.extend(f.factors)
        elif f != ONE:
            flat.append(f)
    out = ONE if not flat else flat[0] if len(flat) == 1 else Mul(tuple(flat))
    return neg(out) if sign < 0 else out


def div(num: Node, den: Node) -> Node:
    if den == ONE:
        return num
    sign = 1
    while isinstance(num, Neg):
        sign, num = -sign, num.arg
    while isinstance(den, Neg):
        sign, den = -sign, den.arg
    out = Div(num, den)
    return neg(out) if sign < 0 else out


def power(base: Node, exp: Node) -> Node:
    if isinstance(base, Op) and isinstance(exp, Num) and exp.text.isdigit():
        return Op(tuple((v, n * int(exp.text)) for v, n in base.orders))
    return base if exp == ONE else Pow(base, exp)


def has_op(node: Node) -> bool:
    return any(isinstance(n, Op) for n in walk(node))


def apply_ops(operator: Node, operand: Node) -> Node:
    """An operator expression — a sum of coefficients times ∂'s, with multiplication terms —
    applied to ``operand``: (x ∂/∂x + b) f → x ∂f/∂x + b f."""
    if isinstance(operator, Op):
        return call("Derivative", operand, *(Tup((v, Num(str(n))), True) for v, n in operator.orders))
    if isinstance(operator, Add):
        return add(*(apply_ops(t, operand) for t in operator.terms))
    if isinstance(operator, Neg):
        return neg(apply_ops(operator.arg, operand))
    if isinstance(operator, Mul) and has_op(operator):
        ops = [f for f in operator.factors if has_op(f)]
        coef = [f for f in operator.factors if not has_op(f)]
        inner = operand
        for op in reversed(ops):
            inner = apply_ops(op, inner)
        return mul(*coef, inner)
    return mul(operator, operand)


def call(func: str, *args: Node) -> Node:
    return Call(func, tuple(args))


# --- walking the tree -------------------------------------------------------------------------
def rebuild(node: Node, leaf) -> Node:
    """The tree with every leaf replaced by ``leaf(node)`` (which returns a node), rebuilt
    through the flattening constructors."""
    if isinstance(node, Add):
        return add(*(rebuild(t, leaf) for t in node.terms))
    if isinstance(node, Neg):
        return neg(rebuild(node.arg, leaf))
    if isinstance(node, Mul):
        return mul(*(rebuild(f, leaf) for f in node.factors))
    if isinstance(node, Div):
        return div(rebuild(node.num, leaf), rebuild(node.den, leaf))
    if isinstance(node, Pow):
        return power(rebuild(node.base, leaf), rebuild(node.exp, leaf))
    if isinstance(node, Call):
        return Call(node.func, tuple(rebuild(a, leaf) for a in node.args))
    if isinstance(node, Tup):
        return Tup(tuple(rebuild(a, leaf) for a in node.items), node.bare)
    if isinstance(node, Rel):
        return Rel(node.op, rebuild(node.lhs, leaf), rebuild(node.rhs, leaf))
    return leaf(node)


def walk(node: Node):
    """Every node of the tree, parents first."""
    yield node
    children: tuple = ()
    if isinstance(node, Add):
        children = node.terms
    elif isinstance(node, Neg):
        children = (node.arg,)
    elif isinstance(node, Mul):
        children = node.factors
    elif isinstance(node, Div):
        children = (node.num, node.den)
    elif isinstance(node, Pow):
        children = (node.base, node.exp)
    elif isinstance(node, Call):
        children = node.args
    elif isinstance(node, Tup):
        children = node.items
    elif isinstance(node, Rel):
        children = (node.lhs, node.rhs)
    for c in children:
        yield from walk(c)


def has_signs(node: Node) -> bool:
    """Whether the tree holds a ``\\pm`` or ``\\mp`` (and so reads as two relations)."""
    return any(isinstance(n, (PM, PMSym)) for n in walk(node))


def resolve(node: Node, choice: int) -> Node:
    """The tree under one choice of the correlated signs: ``choice`` +1 takes the upper sign
    of every ``\\pm`` and ``\\mp``, −1 the lower."""
    def leaf(n: Node) -> Node:
        if isinstance(n, PM):
            return ONE if n.sign * choice > 0 else neg(ONE)
        if isinstance(n, PMSym):
            return Sym(f"{n.base}_{'plus' if n.sign * choice > 0 else 'minus'}")
        return n
    return rebuild(node, leaf)


# --- printing -----------------------------------------------------------------------------------
def to_sympy(node: Node) -> str:
    """The tree in sympy syntax (signs must be resolved first)."""
    return _p(node)[0]


def _wrap(node: Node, least: int) -> str:
    text, prec = _p(node)
    return f"({text})" if prec < least else text


def _p(node: Node) -> tuple[str, int]:
    if isinstance(node, Num):
        return node.text, ATOM
    if isinstance(node, Sym):
        return node.name, ATOM
    if isinstance(node, Const):
        return ("exp(1)" if node.name == "E" else node.name), ATOM
    if isinstance(node, Str):
        return f'"{node.text}"', ATOM
    if isinstance(node, Call):
        return f"{node.func}({', '.join(to_sympy(a) for a in node.args)})", ATOM
    if isinstance(node, Tup):
        inner = ", ".join(to_sympy(a) for a in node.items)
        if node.bare:
            return f"({inner}{',' if len(node.items) == 1 else ''})", ATOM
        return f"Tuple({inner})", ATOM
    if isinstance(node, Rel):
        return f"{node.op}({to_sympy(node.lhs)}, {to_sympy(node.rhs)})", ATOM
    if isinstance(node, Add):
        parts = [_wrap(node.terms[0], ADD)]
        for t in node.terms[1:]:
            if isinstance(t, Neg):
                parts.append(" - " + _wrap(t.arg, MUL))
            else:
                parts.append(" + " + _wrap(t, NEG))
        return "".join(parts), ADD
    if isinstance(node, Neg):
        return "-" + _wrap(node.arg, MUL), NEG
    if isinstance(node, (Mul, Div)):
        num, den = _fraction(node)
        top = "*".join(_wrap(f, MUL) for f in num) if num else "1"
        if not den:
            return top, MUL
        if len(den) == 1:
            bottom = _wrap(den[0], POW)
        else:
            bottom = "(" + "*".join(_wrap(f, MUL) for f in den) + ")"
        return f"{top}/{bottom}", MUL
    if isinstance(node, Pow):
        return f"{_wrap(node.base, POW + 1)}**{_exponent(node.exp)}", POW
    if isinstance(node, (PM, PMSym)):
        raise ValueError("resolve the signs (\\pm, \\mp) before printing")
    if isinstance(node, Op):
        raise ValueError("a differential operator applied to nothing")
    raise TypeError(f"not a node: {node!r}")


def _exponent(node: Node) -> str:
    text, prec = _p(node)
    return text if prec == ATOM and not text.startswith("-") else f"({text})"


def _fraction(node: Node) -> tuple[list[Node], list[Node]]:
    """Numerator and denominator factors of a product of quotients, numerals first."""
    num: list[Node] = []
    den: list[Node] = []

    def take(n: Node, top: bool):
        if isinstance(n, Mul):
            for f in n.factors:
                take(f, top)
        elif isinstance(n, Div):
            take(n.num, top)
            take(n.den, not top)
        elif n != ONE:
            (num if top else den).append(n)

    take(node, True)
    numerals = [f for f in num if isinstance(f, Num)]
    return numerals + [f for f in num if not isinstance(f, Num)], den
