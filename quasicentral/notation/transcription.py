"""Reading a transcription: Python's expression syntax over a whitelist of names, never executed.

A transcription (``Eq(v**2, v0**2 + 2*a*(x - x0))``) is data from someone else's folder.  It
is parsed with :mod:`ast` and built node by node into sympy objects: only numbers, names the
namespace declares (the text's symbols and the functions and constants of the vocabulary),
calls of those names, arithmetic, comparisons, ``and``/``or``, tuples and lists.  No attribute
(``Eq.__globals__``), no subscript, no lambda, no comprehension, no string but a keyword's
value; numbers and powers are bounded (``10**10**10`` is refused, not computed).  A decimal
literal is the exact rational it writes (0.1 is 1/10).

>>> import sympy as sp
>>> x = sp.Symbol("x")
>>> parse("Eq(x**2, 0.25)", {"x": x, "Eq": sp.Eq})
Eq(x**2, 1/4)
>>> parse("x.__class__", {"x": x})
Traceback (most recent call last):
...
quasicentral.notation.transcription.TranscriptionError: line 1, column 0: attribute access (.__class__) is not allowed in a transcription
"""

from __future__ import annotations

from types import MappingProxyType
import ast
import re
from fractions import Fraction

import sympy as sp

MAX_LENGTH = 200_000  # characters of one transcription
MAX_DEPTH = 400  # nesting of the expression's tree
MAX_INTEGER_DIGITS = 2_000  # digits of an integer literal
MAX_POWER_BITS = 200_000  # bits of an exact integer power a ** b built from numbers
MAX_FACTORIAL = 100_000  # the largest integer a factorial-like function is applied to exactly
KEYWORDS = frozenset({"evaluate", "dir"})  # keyword arguments a call may take
#: the names that take a name as a string: Symbol('R_1'), Function('A')(t) (a symbol or a
#: function the text does not declare, as older transcriptions write them)
NAMING = frozenset({"Symbol", "Function"})
FACTORIAL_LIKE = frozenset({"factorial", "factorial2", "binomial", "subfactorial", "fibonacci", "catalan",
                            "bernoulli", "euler", "harmonic", "rf", "ff", "RisingFactorial", "FallingFactorial",
                            "prime", "bell", "lucas"})


class TranscriptionError(ValueError):
    """A transcription that cannot be read (the message starts with its line and column)."""

    def __init__(self, message: str, line: int = 1, column: int = 0):
        super().__init__(f"line {line}, column {column}: {message}")
        self.line, self.column, self.reason = line, column, message


def _fail(node, message: str):
    raise TranscriptionError(message, getattr(node, "lineno", 1), getattr(node, "col_offset", 0))


def _tree(text: str) -> ast.Expression:
    if len(text) > MAX_LENGTH:
        raise TranscriptionError(f"{len(text)} characters: a transcription is at most {MAX_LENGTH}")
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except SyntaxError as exc:
        raise TranscriptionError(f"syntax error: {exc.msg}", exc.lineno or 1, (exc.offset or 1) - 1) from None
    except (RecursionError, MemoryError, ValueError):
        raise TranscriptionError("nested too deeply to be read") from None
    return tree


_BINARY = MappingProxyType({ast.Add: lambda a, b: a + b, ast.Sub: lambda a, b: a - b, ast.Mult: lambda a, b: a * b,
           ast.Div: lambda a, b: a / b, ast.Mod: lambda a, b: sp.Mod(a, b)})
_COMPARE = MappingProxyType({ast.Lt: sp.StrictLessThan, ast.LtE: sp.LessThan, ast.Gt: sp.StrictGreaterThan,
            ast.GtE: sp.GreaterThan, ast.NotEq: sp.Ne})


def check(text: str, names) -> list[str]:
    """The names ``text`` uses that ``names`` does not hold (a syntax error, a construct that is
    not allowed or a number too large raises :class:`TranscriptionError`); nothing is built."""
    tree = _tree(text)
    unknown: list[str] = []
    stack = [(tree.body, 0)]
    while stack:
        node, depth = stack.pop()
        if depth > MAX_DEPTH:
            _fail(node, f"nested more than {MAX_DEPTH} deep")
        _allowed(node)
        if isinstance(node, ast.Name) and node.id not in names and node.id not in unknown:
            unknown.append(node.id)
        children = list(ast.iter_child_nodes(node))
        if isinstance(node, ast.Call):
            children = [c for c in children if not isinstance(c, ast.keyword)] + [k.value for k in node.keywords]
        stack.extend((c, depth + 1) for c in reversed(children) if not isinstance(c, (ast.operator, ast.cmpop,
                                                                                         ast.unaryop, ast.boolop,
                                                                                         ast.expr_context)))
    return unknown


def _allowed(node) -> None:
    if isinstance(node, (ast.BinOp, ast.UnaryOp, ast.Compare, ast.BoolOp, ast.Tuple, ast.List, ast.Name)):
        if isinstance(node, ast.BinOp) and type(node.op) not in (*_BINARY, ast.Pow):
            _fail(node, f"the operator {type(node.op).__name__} is not allowed in a transcription")
        if isinstance(node, ast.UnaryOp) and not isinstance(node.op, (ast.USub, ast.UAdd)):
            _fail(node, f"the operator {type(node.op).__name__} is not allowed in a transcription")
        if isinstance(node, ast.Compare) and not all(type(op) in _COMPARE for op in node.ops):
            _fail(node, "== compares structures in Python: write Eq(a, b) for an equation")
        if isinstance(node, ast.Name) and node.id.startswith("__"):
            _fail(node, f"the name {node.id} is not allowed in a transcription")
        return
    if isinstance(node, ast.Constant):
        value = node.value
        if isinstance(value, bool) or value is None or getattr(node, "_naming", False):
            return
        if isinstance(value, int) and len(str(abs(value))) > MAX_INTEGER_DIGITS:
            _fail(node, f"an integer of more than {MAX_INTEGER_DIGITS} digits")
        if isinstance(value, (int, float, complex)):
            return
        _fail(node, f"a {type(value).__name__} constant is not allowed here (only as a keyword's value)")
    if isinstance(node, ast.Call):
        if _naming_call(node):
            node.args[0]._naming = True  # its one string is a name (checked when it is built)
            return
        if _direction(node) is not None:
            node.args[3]._naming = True  # Limit(f, x, 0, "+"): the side, as sympy writes it
        if isinstance(node.func, ast.Attribute):
            _fail(node, f"attribute access (.{node.func.attr}) is not allowed in a transcription"
                  + (": write x(value) for a function x at a value, or Subs(expr, t, value)"
                     if node.func.attr == "subs" else ""))
        if not (isinstance(node.func, ast.Name) or _naming_call(node.func)):
            _fail(node, "only a name can be called (f(x), not (expression)(x))")
        for k in node.keywords:
            if k.arg not in KEYWORDS:
                _fail(node, f"the keyword {k.arg or '**'} is not allowed (only {', '.join(sorted(KEYWORDS))})")
            if not (isinstance(k.value, ast.Constant) and isinstance(k.value.value, (bool, str))):
                _fail(node, f"the keyword {k.arg} takes True, False or a short string")
        if any(isinstance(a, ast.Starred) for a in node.args):
            _fail(node, "*arguments are not allowed in a transcription")
        return
    if isinstance(node, ast.Attribute):
        _fail(node, f"attribute access (.{node.attr}) is not allowed in a transcription")
    if isinstance(node, ast.Subscript):
        _fail(node, "a subscript x[...] is not allowed: write x_0 as a declared symbol")
    _fail(node, f"{type(node).__name__} is not allowed in a transcription")


#: the sides a limit may be taken from, as sympy's Limit writes them
DIRECTIONS = frozenset({"+", "-", "+-"})


def _direction(node) -> str | None:
    """The side of ``Limit(f, x, x0, "+")`` written as its fourth argument (None: not so)."""
    if (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "Limit"
            and len(node.args) == 4 and isinstance(node.args[3], ast.Constant) and node.args[3].value in DIRECTIONS):
        return node.args[3].value
    return None


def _naming_call(node) -> bool:
    """Symbol('name') or Function('name'): one string constant, no keyword."""
    return (isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in NAMING
            and len(node.args) == 1 and not node.keywords and isinstance(node.args[0], ast.Constant)
            and isinstance(node.args[0].value, str) and len(node.args[0].value) <= 64)


def parse(text: str, namespace: dict, *, calls: dict | None = None) -> sp.Basic:
    """``text`` built into sympy objects over ``namespace`` (see the module); an unknown name
    raises :class:`TranscriptionError`.  ``calls`` maps a name to what calling it means where
    the namespace holds a value (a declared function ``x`` is ``x(t)``; ``x(0)`` is its head
    at 0)."""
    unknown = check(text, namespace)
    if unknown:
        raise TranscriptionError(f"unknown name{'s' if len(unknown) > 1 else ''} {', '.join(unknown)} "
                                 "(declare it in text.toml)")
    return _Builder(namespace, calls or {}, text.strip()).build(_tree(text).body)


class _Builder:
    def __init__(self, namespace: dict, calls: dict, source: str):
        self.ns, self.calls, self.source = namespace, calls, source

    def build(self, node):  # noqa: C901 - one dispatch over the allowed nodes
        if isinstance(node, ast.Constant):
            return self.constant(node)
        if isinstance(node, ast.Name):
            return self.ns[node.id]
        if isinstance(node, (ast.Tuple, ast.List)):
            items = [self.build(e) for e in node.elts]
            return sp.Tuple(*items) if isinstance(node, ast.Tuple) else items
        if isinstance(node, ast.UnaryOp):
            value = self.build(node.operand)
            return -value if isinstance(node.op, ast.USub) else value
        if isinstance(node, ast.BinOp):
            a, b = self.build(node.left), self.build(node.right)
            if isinstance(node.op, ast.Pow):
                return self.power(node, a, b)
            return _BINARY[type(node.op)](a, b)
        if isinstance(node, ast.Compare):
            parts, left = [], self.build(node.left)
            for op, right_node in zip(node.ops, node.comparators):
                right = self.build(right_node)
                parts.append(_COMPARE[type(op)](left, right))
                left = right
            return parts[0] if len(parts) == 1 else sp.And(*parts)
        if isinstance(node, ast.BoolOp):
            values = [self.build(v) for v in node.values]
            return sp.And(*values) if isinstance(node.op, ast.And) else sp.Or(*values)
        if isinstance(node, ast.Call):
            return self.call(node)
        _fail(node, f"{type(node).__name__} is not allowed in a transcription")

    def constant(self, node: ast.Constant):
        v = node.value
        if isinstance(v, bool):
            return sp.true if v else sp.false
        if isinstance(v, int):
            return sp.Integer(v)
        try:
            if isinstance(v, float):
                return decimal_literal(ast.get_source_segment(self.source, node) or repr(v))
            if isinstance(v, complex):
                imag = ast.get_source_segment(self.source, node) or repr(v.imag)
                return sp.I * decimal_literal(imag.rstrip("jJ") or "1")
        except ValueError as exc:
            _fail(node, str(exc))
        _fail(node, f"a {type(v).__name__} constant is not allowed here")

    def power(self, node, a, b):
        if a.is_Number and b.is_Integer and abs(int(b)) > 1:
            base = abs(a.p) if a.is_Rational else None
            if base is not None and base > 1 and abs(int(b)) * base.bit_length() > MAX_POWER_BITS:
                _fail(node, f"a number too large to be exact (its power has more than {MAX_POWER_BITS} bits)")
        if a.is_Number and b.is_Rational and not b.is_Integer and a.is_Rational:
            big = max(abs(a.p), abs(a.q))
            if big.bit_length() * max(abs(b.p), 1) > MAX_POWER_BITS:
                _fail(node, f"a number too large to be exact (its power has more than {MAX_POWER_BITS} bits)")
        return a ** b

    def call(self, node: ast.Call):
        if _naming_call(node):
            try:
                return self.ns[node.func.id](node.args[0].value)
            except ValueError as exc:
                _fail(node, str(exc))
        if not isinstance(node.func, ast.Name):  # Function('A')(t)
            head = self.call(node.func)
            return head(*[self.build(a) for a in node.args])
        name = node.func.id
        side = _direction(node)
        args = [self.build(a) for a in node.args[:3]] + [side] if side else [self.build(a) for a in node.args]
        kwargs = {k.arg: (sp.true if k.value.value is True else sp.false if k.value.value is False else k.value.value)
                  if k.arg != "dir" else k.value.value for k in node.keywords}
        if "evaluate" in kwargs:
            kwargs["evaluate"] = bool(kwargs["evaluate"])
        if name in FACTORIAL_LIKE:
            for a in args:
                if isinstance(a, sp.Integer) and abs(int(a)) > MAX_FACTORIAL:
                    _fail(node, f"{name} of an integer above {MAX_FACTORIAL} is too large to be exact")
        target = self.calls.get(name, self.ns[name])
        places_of = getattr(target, "places_of", None)  # a printed rounding: its places are counted here
        if places_of is not None and len(node.args) > places_of:
            value = node.args[places_of]
            if isinstance(value, ast.Constant):
                kwargs["places"] = decimal_places(ast.get_source_segment(self.source, value) or "")
            else:  # 1.22*lam/D: each printed decimal with its places
                found = sorted(decimal_literals(ast.get_source_segment(self.source, value) or "").items(),
                               key=lambda kv: (kv[0], kv[1]))
                if not found:
                    _fail(node, f"{name}(x, value): value prints no decimal digits (a printed decimal "
                                "such as 4.965114, or a formula with one such as 1.22*lam/D)")
                kwargs["places"] = sp.Tuple(*(sp.Tuple(v, p) for v, p in found))
        if not callable(target) or isinstance(target, sp.Basic) and not isinstance(target, sp.FunctionClass):
            _fail(node, f"{name} is not a function: it cannot be called")
        try:
            return target(*args, **kwargs)
        except TranscriptionError:
            raise
        except (TypeError, ValueError, AttributeError, NotImplementedError, ArithmeticError, RecursionError) as exc:
            _fail(node, f"{name}(…): {type(exc).__name__}: {exc}"[:300])


def decimal_literals(text: str) -> dict:
    """The decimal literals a transcription prints, each as its exact rational and the decimal
    places printed (``Eq(x, 0.6850858166)`` → {0.6850858166: 10}); its syntax is read, nothing
    is evaluated (an unreadable text has none)."""
    try:
        tree = _tree(text)
    except TranscriptionError:
        return {}
    source, out = text.strip(), {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Constant) and isinstance(node.value, float):
            literal = ast.get_source_segment(source, node) or repr(node.value)
            out.setdefault(decimal_literal(literal), decimal_places(literal))
    return out


#: the largest power of ten a decimal literal may write (1e999999999 would be a billion digits)
MAX_DECIMAL_EXPONENT = 1000


def decimal_literal(text: str) -> sp.Rational:
    """The exact rational a decimal literal writes: '0.1' → 1/10, '1e-3' → 1/1000; a ValueError
    for anything else, or for a power of ten beyond :data:`MAX_DECIMAL_EXPONENT`."""
    text = text.strip().replace("_", "")
    mantissa, _, exponent = text.lower().partition("e")
    if not re.fullmatch(r"[+-]?(\d+\.?\d*|\.\d+)", mantissa) or (exponent and not re.fullmatch(r"[+-]?\d{1,6}", exponent)):
        raise ValueError(f"{text!r} is not a decimal number such as 4.965114 or 1.2e-3")
    if exponent and abs(int(exponent)) > MAX_DECIMAL_EXPONENT or len(mantissa) > MAX_DECIMAL_EXPONENT:
        raise ValueError(f"{text!r}: a decimal number's power of ten is at most {MAX_DECIMAL_EXPONENT} here")
    f = Fraction(text)
    return sp.Rational(f.numerator, f.denominator)


def decimal_places(text: str) -> int:
    """The decimal places a printed number shows ('4.965114' → 6, '1.2e-3' → 4)."""
    mantissa, _, exponent = text.lower().replace("_", "").partition("e")
    places = len(mantissa.split(".", 1)[1]) if "." in mantissa else 0
    return places - (int(exponent) if exponent else 0)
