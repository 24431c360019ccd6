"""A recursive-descent parser of DLMF's semantic LaTeX into the tree of :mod:`.nodes`.

Precedence, loosest first: a list of formulas (``\\quad`` between them), a chain of relations
(``a = b = c``, ``0 < k < 1``, ``x \\to 0``), a sum (``+ - \\pm \\mp``), a product (juxtaposition,
``/``, ``\\times``, ``\\cdot``; a big operator — ``\\sum``, ``\\prod``, ``\\int``, ``\\lim`` —
takes the rest of its product), a power (``^``, subscripts, primes, ``!``), an atom.

Conventions of DLMF read here, not by the caller:

* ``\\sin^{2}@@{\\theta}`` and ``\\Jacobiellsnk^{2}@{z}{k}`` are powers of the value;
* a prime on a modulus (``k^{\\prime}``, ``k_{1}^{\\prime}``, ``\\kappa^{\\prime}``) is the
  complementary modulus √(1 − k²) (DLMF 19.1, 22.1); on any other letter it names a symbol
  (``a^{\\prime}`` → ``ap``);
* ``\\int … \\diff{t}``: the integral ends at its differential, which may sit in a numerator
  (``\\frac{\\diff{t}}{…}``); nested integrals take their differentials inside out;
* ``\\sum``/``\\prod`` over a few integers whose body indexes a subscript (``x_{j}``) are
  written out term by term;
* ``\\pm``/``\\mp`` are kept as correlated signs (two readings), ``p_{\\pm}`` too.
"""

from __future__ import annotations

from itertools import permutations

from . import nodes as N
from .lexer import Kind, Token
from .macros import GREEK, JACOBI, RELATIONS, RESERVED, SPACING, THETA_INDEX
from .options import Options, SemanticLatexError

_CLOSERS = frozenset({")", "]", "}"})


class Parser:
    def __init__(self, tokens: list[Token], options: Options, source: str):
        self.toks = tokens
        self.i = 0
        self.opt = options
        self.source = source
        self.letters: dict[str, str] = dict(options.letters)   # generic letters, unrolled indices
        self.values: dict[str, N.Node] = {}                    # parameters of defined notations
        self.diffs: list[list[N.Node]] = []                   # differentials of open integrals
        self.abs_depth = 0
        self.sub_letters: set[str] = set()                     # letters seen in subscripts
        self.notes: list[str] = []
        self.trailing_sign: N.Node | None = None               # the side of 0+, 1-
        self.matrix = 0                                        # depth of matrix environments

    # --- tokens ------------------------------------------------------------------------------
    @property
    def tok(self) -> Token:
        return self.toks[self.i]

    def peek(self, k: int = 1) -> Token:
        return self.toks[min(self.i + k, len(self.toks) - 1)]

    def next(self) -> Token:
        t = self.toks[self.i]
        self.i = min(self.i + 1, len(self.toks) - 1)
        return t

    def error(self, what: str, tok: Token | None = None) -> SemanticLatexError:
        tok = tok or self.tok
        return SemanticLatexError(f"{what} (at offset {tok.pos}: {self.source[tok.pos:tok.pos + 30]!r})",
                                  token=tok.text or "end of formula")

    def expect(self, text: str) -> Token:
        if not self.tok.is_(text):
            raise self.error(f"expected {text!r}")
        return self.next()

    def skip_space(self):
        """Pass spacing commands, and a line break ``\\\\`` outside a matrix."""
        while self.tok.kind is Kind.COMMAND and (self.tok.text in SPACING or
                                                 (self.tok.text == "\\\\" and not self.matrix)):
            self.next()

    def group_tokens(self) -> tuple[int, int]:
        """The token range of the brace group at the cursor (the cursor moves past it)."""
        self.skip_space()
        if self.tok.kind is not Kind.OPEN:
            raise self.error("expected a brace group")
        start, depth = self.i + 1, 0
        while True:
            t = self.next()
            if t.kind is Kind.OPEN:
                depth += 1
            elif t.kind is Kind.CLOSE:
                depth -= 1
                if depth == 0:
                    return start, self.i - 1
            elif t.kind is Kind.END:
                raise self.error("an unclosed brace", t)

    def sub(self, start: int, end: int, rule):
        """Run ``rule`` on the tokens [start, end) as if they were the whole input."""
        saved_toks, saved_i = self.toks, self.i
        self.toks = self.toks[start:end] + [Token(Kind.END, "", self.toks[end].pos)]
        self.i = 0
        try:
            out = rule()
            self.skip_space()
            if self.tok.is_(",", ";", "."):  # DLMF leaves punctuation inside groups
                self.next()
            if self.tok.kind is not Kind.END:
                raise self.error("unexpected token")
            return out
        finally:
            self.toks, self.i = saved_toks, saved_i

    def group(self, rule=None):
        start, end = self.group_tokens()
        return self.sub(start, end, rule or self.expr)

    def group_text(self) -> str:
        start, end = self.group_tokens()
        return "".join(t.text for t in self.toks[start:end])

    # --- formulas and relations ----------------------------------------------------------------
    def formulas(self) -> list[N.Node]:
        self.skip_space()
        if self.tok.kind is Kind.OPEN:  # {a = b}, the whole formula braced
            start, end = self.group_tokens()
            rest = [t for t in self.toks[self.i:] if t.kind is not Kind.END and not t.is_(",", ";", ".")]
            if not rest:
                return self.sub(start, end, self.formulas)
            self.i = start - 1
        out = self.chain()
        while True:
            self.skip_space()
            if self.tok.is_(",", ";", ".") and self.peek().is_(r"\quad", r"\qquad"):
                self.next()
            if self.tok.is_(r"\quad", r"\qquad"):
                self.next()
                self.skip_space()
                if self.tok.is_(r"\text"):  # a remark in words after the formula
                    self.next()
                    self.notes.append(f"the remark \\text{{{self.group_text()}}} is not read")
                    continue
                out += self.chain()
                continue
            if self.tok.is_(",", ";", ".", r"\dots", r"\ldots") and self.peek().kind is Kind.END:
                self.next()
            break
        if self.tok.kind is not Kind.END:
            raise self.error("unexpected token")
        return out

    def chain(self) -> list[N.Node]:
        subjects = [self.expr()]
        while self.tok.is_(",") and not self.peek().is_(r"\quad", r"\qquad") and self.peek().kind is not Kind.END \
                and self.relation_ahead():
            self.next()
            subjects.append(self.expr())
        if len(subjects) > 1:  # a, b > 0: the relation for each
            tail_start = self.i
            out = []
            for subj in subjects:
                self.i = tail_start
                out += self.chain_from(subj)
            return out
        return self.chain_from(subjects[0])

    def relation_ahead(self) -> bool:
        depth = 0
        for t in self.toks[self.i + 1:]:
            if t.kind is Kind.OPEN or t.is_("(", "["):
                depth += 1
            elif t.kind is Kind.CLOSE or t.is_(")", "]"):
                depth -= 1
                if depth < 0:
                    return False
            elif depth == 0 and t.text in RELATIONS and t.kind is not Kind.LETTER:
                return True
            elif depth == 0 and t.is_(";", r"\quad"):
                return False
        return False

    def chain_from(self, first: N.Node) -> list[N.Node]:
        members = [first]
        ops: list[str] = []
        while True:
            self.skip_space()
            op = RELATIONS.get(self.tok.text) if self.tok.kind in (Kind.CHAR, Kind.COMMAND) else None
            if op is None:
                break
            self.next()
            ops.append(op)
            members.append(self.expr())
        if not ops:
            return members
        out: list[N.Node] = []
        for j, op in enumerate(ops):
            head = members[0] if op == "Eq" and all(o == "Eq" for o in ops[:j]) else members[j]
            rhs = members[j + 1]
            if (op == "Eq" and isinstance(head, N.Tup) and isinstance(rhs, N.Tup)
                    and len(head.items) == len(rhs.items)):  # (x, y, z) = (a, b, c): one per member
                out += [N.Rel(op, a, b) for a, b in zip(head.items, rhs.items)]
            else:
                out.append(N.Rel(op, head, rhs))
        return out

    # --- sums --------------------------------------------------------------------------------
    def expr(self) -> N.Node:
        terms: list[N.Node] = []
        sign: N.Node | None = self.sign()
        while True:
            self.skip_space()
            if self.tok.is_(r"\cdots", r"\dots", r"\ldots") and terms:
                dots = self.next()
                self.skip_space()
                if self.tok.is_("+", "-"):
                    raise self.error("an elided sum a_1 + \\cdots + a_n", dots)
                terms.append(self.series_tail(terms))
            else:
                t = self.term()
                terms.append(t if sign is None else N.mul(sign, t))
            self.skip_space()
            sign = self.sign()
            if sign is None:
                break
            if self.tok.kind in (Kind.CLOSE, Kind.END):  # a one-sided point: 0+, 1-
                self.trailing_sign = sign
                break
        return N.add(*terms)

    def sign(self) -> N.Node | None:
        self.skip_space()
        t = self.tok
        if t.is_("+"):
            self.next()
            return N.ONE
        if t.is_("-"):
            self.next()
            return N.neg(N.ONE)
        if t.is_(r"\pm", r"\mp"):
            self.next()
            return N.PM(1 if t.text == r"\pm" else -1)
        return None

    def series_tail(self, terms: list[N.Node]) -> N.Node:
        """``a + b r^{2} + c r^{3} + \\cdots``: the terms left off, as O(r^{n+s}) at r → 0,
        with n the last power and s the step of the powers shown."""
        powers = []
        for t in terms:
            t = t.arg if isinstance(t, N.Neg) else t
            factors = t.factors if isinstance(t, N.Mul) else (t,)
            for f in factors:
                if isinstance(f, N.Pow) and isinstance(f.base, N.Sym) and isinstance(f.exp, N.Num):
                    powers.append((f.base, int(f.exp.text)))
                elif isinstance(f, N.Sym):
                    powers.append((f, 1))
        if not powers or len({b for b, _ in powers}) != 1:
            raise self.error("a series tail \\cdots whose variable cannot be read")
        var, exps = powers[0][0], [e for _, e in powers]
        steps = {b - a for a, b in zip(exps, exps[1:])}
        step = steps.pop() if len(steps) == 1 else 1
        self.notes.append(f"the terms left off (\\cdots) read as O({var.name}**{exps[-1] + step}) "
                          f"as {var.name} -> 0")
        return N.call("O", N.power(var, N.Num(str(exps[-1] + step))), N.Tup((var, N.ZERO), True))

    # --- products ----------------------------------------------------------------------------
    def at_term_end(self) -> bool:
        self.skip_space()
        t = self.tok
        if t.kind in (Kind.END, Kind.CLOSE):
            return True
        if t.kind is Kind.CHAR and (t.text in "+-=<>,;&" or t.text in _CLOSERS or t.text == "."):
            return True
        if t.is_("|") and self.abs_depth:
            return True
        if t.kind is Kind.COMMAND and (t.text in RELATIONS or t.text in (
                r"\pm", r"\mp", r"\right", r"\\", r"\quad", r"\qquad", r"\cdots", r"\dots",
                r"\ldots", r"\end", r"\middle")):
            return True
        return False

    def term(self, integral: list | None = None) -> N.Node:
        value = self.factor()
        while not (integral is not None and integral) and not self.at_term_end():
            t = self.tok
            if t.is_("/") or t.is_(r"\bigg", r"\biggm", r"\big", r"\Big", r"\Bigg"):
                self.next()
                if t.text != "/":  # \bigg{/}: a big slash
                    if self.tok.kind is Kind.OPEN:
                        slash = self.group_text()
                    else:
                        slash = self.next().text
                    if slash != "/":
                        raise self.error(f"{t.text}{{{slash}}} in a product", t)
                value = N.div(value, self.factor())
            elif t.is_(r"\times", r"\cdot"):
                self.next()
            else:
                f = self.factor()
                value = N.apply_ops(value, f) if N.has_op(value) and not N.has_op(f) else N.mul(value, f)
        return value

    # --- powers, subscripts, primes ------------------------------------------------------------
    def factor(self) -> N.Node:
        value = self.atom()
        while True:
            self.skip_space()
            t = self.tok
            if t.is_("^"):
                self.next()
                value = self.superscript(value)
            elif t.is_("_") and isinstance(value, N.Sym):
                self.next()
                value = self.subscripted(value)
            elif t.is_("_") and isinstance(value, N.Pow) and isinstance(value.base, N.Sym):
                self.next()  # v^{2}_{+}: the subscript belongs to the letter
                value = N.power(self.subscripted(value.base), value.exp)
            elif t.is_("!"):
                self.next()
                value = N.call("factorial", value)
            elif t.is_("'"):
                self.next()
                value = self.primed(value)
            elif t.is_("(") and isinstance(value, N.Sym) and self.applies(value.name):
                value = self.application(value.name)
            else:
                return value

    def script_tokens(self) -> tuple[int, int]:
        """The tokens of a super- or subscript: a brace group or one token."""
        self.skip_space()
        if self.tok.kind is Kind.OPEN:
            return self.group_tokens()
        start = self.i
        self.next()
        return start, self.i

    def superscript(self, base: N.Node) -> N.Node:
        start, end = self.script_tokens()
        texts = [t.text for t in self.toks[start:end]]
        if texts and all(x == r"\prime" for x in texts):
            for _ in texts:
                base = self.primed(base)
            return base
        if (isinstance(base, N.Sym) and len(texts) == 3 and texts[0] == "(" and texts[2] == ")"
                and (texts[1].isdigit() or texts[1].isalpha())):
            return N.Sym(f"{base.name}__{texts[1]}")  # s^{(2)}: a label, not a power
        return N.power(base, self.sub(start, end, self.expr))

    def primed(self, base: N.Node) -> N.Node:
        if isinstance(base, N.Sym) and base.name.split("_")[0] in self.opt.complementary:
            return N.call("sqrt", N.add(N.ONE, N.neg(N.power(base, N.Num("2")))))
        if isinstance(base, N.Sym):
            return N.Sym(base.name + "p")
        raise self.error("a prime on an expression")

    def subscripted(self, base: N.Sym) -> N.Node:
        start, end = self.script_tokens()
        toks = self.toks[start:end]
        if base.name in self.opt.sequences:  # c_{n+1}: a term of a sequence
            return N.Call(f'Function("{base.name}")', (self.sub(start, end, self.expr),))
        if len(toks) == 1 and toks[0].is_(r"\pm", r"\mp", "+", "-"):
            if toks[0].text in ("+", "-"):
                return N.Sym(f"{base.name}_{'plus' if toks[0].text == '+' else 'minus'}")
            return N.PMSym(base.name, 1 if toks[0].text == r"\pm" else -1)
        parts: list[str] = []
        for t in toks:
            if t.kind is Kind.LETTER or t.kind is Kind.NUMBER:
                if t.kind is Kind.LETTER:
                    self.sub_letters.add(t.text)
                parts.append(self.letters.get(t.text, t.text))
            elif t.kind is Kind.COMMAND and t.text[1:] in GREEK:
                self.sub_letters.add(t.text[1:])
                parts.append(self.letters.get(t.text[1:], GREEK[t.text[1:]]))
            elif t.is_(","):
                parts.append("_")
            elif t.is_("+"):
                parts.append("p")
            elif t.is_("-"):
                parts.append("m")
            elif t.kind is Kind.COMMAND and t.text in SPACING:
                continue
            elif t.kind is Kind.COMMAND and t.text == r"\mathrm":
                continue
            elif t.kind in (Kind.OPEN, Kind.CLOSE):
                continue
            else:
                raise self.error("a subscript that is not an index", t)
        stem = base.name[:-1] if base.name.endswith("_") and base.name[:-1] in RESERVED else base.name
        return self.symbol(f"{stem}_{''.join(parts)}")

    def symbol(self, name: str) -> N.Node:
        if name in self.values:
            return self.values[name]
        if name in self.opt.defined and not self.opt.defined[name][0] and not self.tok.is_("("):
            return self.expand(self.opt.defined[name][1], {})  # a notation without arguments
        if name in self.opt.operators:
            return N.Op(((N.Sym(self.opt.operators[name]), 1),))
        return N.Sym(name + "_" if name in RESERVED else name)

    def applies(self, name: str) -> bool:
        """Whether ``name(`` is an application: a notation the options define or call a
        function, or parentheses holding a top-level comma (a list is no factor)."""
        if name in self.opt.defined or name in self.opt.applied:
            return True
        if self.peek().is_(r"\mathbf", r"\boldsymbol"):  # E_1(\mathbf{z}): a function of a vector
            return True
        depth = 0
        for t in self.toks[self.i:]:
            if t.text in ("(", "[", "{") or t.text == r"\left":
                depth += 1
            elif t.text in (")", "]", "}") or t.text == r"\right":
                depth -= 1
                if depth <= 0:
                    return False
            elif t.text == "," and depth == 1:
                return True
            elif t.kind is Kind.END:
                return False
        return False

    def application(self, name: str) -> N.Node:
        self.expect("(")
        args = self.comma_list(")")
        self.expect(")")
        if len(args) == 1 and isinstance(args[0], N.Tup):
            args = list(args[0].items)  # Δ(\mathrm{p,q})
        if name in self.opt.defined:
            params, body = self.opt.defined[name]
            if len(params) != len(args):
                raise self.error(f"{name} takes {len(params)} argument(s)")
            return self.expand(body, dict(zip(params, args)))
        return N.Call(f'Function("{name}")', tuple(args))

    def expand(self, body: str, values: dict[str, N.Node]) -> N.Node:
        from .lexer import tokenize

        saved, saved_letters = dict(self.values), dict(self.letters)
        self.values.update(values)
        for name, node in values.items():  # a letter argument (Δ(p, q)) binds a letter too
            if isinstance(node, N.Sym) and len(node.name) == 1:
                self.letters[name] = node.name
        try:
            toks = tokenize(body)
            inner = Parser(toks, self.opt, body)
            inner.values, inner.letters = self.values, self.letters
            return inner.expr()
        finally:
            self.values = saved
            self.letters.clear()
            self.letters.update(saved_letters)

    def comma_list(self, closer: str | None = None) -> list[N.Node]:
        """Expressions separated by commas; ``x_{1},\\dots,x_{4}`` written out."""
        items: list[N.Node] = [self.expr()]
        while self.tok.is_(","):
            self.next()
            self.skip_space()
            if self.tok.is_(r"\dots", r"\ldots", r"\cdots"):
                self.next()
                if self.tok.is_(","):
                    self.next()
                last = self.expr()
                items += self.fill(items[-1], last)
                continue
            items.append(self.expr())
        return items

    def fill(self, before: N.Node, last: N.Node) -> list[N.Node]:
        """The members a ``\\dots`` stands for between two members that differ in one index
        (``x_{2},\\dots,x_{5}``; ``t+z_{2},\\dots,t+z_{n}`` with n bound)."""
        def index(n: N.Node):
            if isinstance(n, N.Sym) and "_" in n.name:
                stem, _, idx = n.name.rpartition("_")
                if idx.isdigit():
                    return stem, int(idx)
            if isinstance(n, N.Num) and n.text.isdigit():
                return "", int(n.text)
            return None
        a, b = list(N.walk(before)), list(N.walk(last))
        diffs = [(x, y) for x, y in zip(a, b) if x != y and index(x) and index(y)]
        if len(a) != len(b) or not diffs:
            if before == last:
                return []
            raise self.error("a list with \\dots whose members cannot be written out")
        (x, y) = diffs[0]
        (stem, i), (stem2, j) = index(x), index(y)
        if stem != stem2 or not i < j <= i + 12 or any(index(u) != (stem, i) or index(v) != (stem, j) for u, v in diffs):
            raise self.error("a list with \\dots whose members cannot be written out")

        def at(m: int) -> N.Node:
            return N.rebuild(before, lambda leaf: (N.Sym(f"{stem}_{m}") if stem else N.Num(str(m)))
                             if leaf == x else leaf)
        return [at(m) for m in range(i + 1, j + 1)]

    # --- atoms ---------------------------------------------------------------------------------
    def atom(self) -> N.Node:
        from .forms import atom_command

        self.skip_space()
        t = self.tok
        if t.kind is Kind.NUMBER:
            return self.number()
        if t.kind is Kind.LETTER:
            self.next()
            name = self.letters.get(t.text, t.text)
            if name == "i" and self.opt.imaginary_i and "i" not in self.letters:
                return N.Const("I")
            if name.isdigit():  # a letter bound to a number (n = 3, an unrolled index)
                return N.Num(name)
            return self.symbol(name)
        if t.kind is Kind.OPEN:
            start, end = self.group_tokens()
            return self.sub(start, end, self.expr)
        if t.is_("(", "["):
            self.next()
            items = self.comma_list()
            closer = self.next()
            if closer.text not in (")", "]"):
                raise self.error("an unclosed parenthesis", closer)
            return items[0] if len(items) == 1 else N.Tup(tuple(items), True)
        if t.is_("|"):
            self.next()
            self.abs_depth += 1
            inner = self.expr()
            self.abs_depth -= 1
            self.expect("|")
            return N.call("Abs", inner)
        if t.kind is Kind.COMMAND:
            return atom_command(self, t)
        raise self.error("a token that starts no expression")

    def number(self) -> N.Node:
        text = self.next().text
        while "." in text and self.tok.is_(r"\;", r"\,", r"\ ") and self.peek().kind is Kind.NUMBER:
            self.next()
            text += self.next().text
        if "." in text and (self.tok.is_(r"\dots", r"\ldots") or
                            (self.tok.is_(r"\;", r"\,") and self.peek().is_(r"\dots", r"\ldots"))):
            self.skip_space()
            self.next()
            self.notes.append(f"{text}… is a decimal cut off after its last digit printed")
        return N.Num(text)

    # --- used by the forms ------------------------------------------------------------------
    def jacobi_name(self, p: str, q: str, arc: bool) -> str:
        p, q = self.letters.get(p, p), self.letters.get(q, q)
        if p + q not in JACOBI:
            raise self.error(f"the Jacobian function {p}{q} (bind the generic letters p, q, r)")
        return ("JacobiArc" + (p + q).upper()) if arc else JACOBI[p + q]

    def theta_index(self, text: str) -> str:
        text = self.letters.get(text, text)
        return THETA_INDEX.get(text, text)

    def macro_args(self, count: int) -> list[N.Node]:
        return [self.group() for _ in range(count)]

    def after_name(self) -> tuple[N.Node | None, bool]:
        """An exponent written between a macro's name and its arguments (``\\sin^{2}@@{x}``),
        then the ``@``s: (exponent, whether an ``@`` was written)."""
        exponent = None
        self.skip_space()
        if self.tok.is_("^"):
            self.next()
            start, end = self.script_tokens()
            exponent = self.sub(start, end, self.expr)
        self.skip_space()
        at = self.tok.kind is Kind.AT
        if at:
            self.next()
        return exponent, at


def determinant(rows: list[list[N.Node]]) -> N.Node:
    """The determinant of a square matrix by Leibniz's formula (for the vmatrix of DLMF)."""
    n = len(rows)
    terms = []
    for perm in permutations(range(n)):
        inversions = sum(1 for a in range(n) for b in range(a + 1, n) if perm[a] > perm[b])
        term = N.mul(*(rows[r][perm[r]] for r in range(n)))
        terms.append(N.neg(term) if inversions % 2 else term)
    return N.add(*terms)
