"""Displays that fit the page: the width of a formula as typeset, long sums broken before a + or −
(:func:`broken_lines`, :func:`relation_lines`), and a catalog entry's verbatim printed LaTeX cut
into the balanced rows of one display (:func:`display_rows`, :func:`wrap_row`).

Hand-written because no library measures LaTeX without typesetting it: the estimate counts
glyphs (a fraction is as wide as its wider part, scripts are smaller), which is all a choice of
line break needs; the compiled documents are checked for overfull boxes.
"""

from __future__ import annotations

import re
from types import MappingProxyType

import sympy as sp

from quasicentral.documents.latex import PaperLatexPrinter, paper_latex

_BREAK = "\x00"


#: Commands typeset as words (their width is their length); others count as one glyph.
_WORDS_WIDE = frozenset({"sin", "cos", "tan", "cot", "ln", "log", "exp", "arccotg", "arcsin", "arccos", "arctan",
               "operatorname", "text", "lfloor", "rfloor"})
_SPACES = MappingProxyType({"quad": 2.0, "qquad": 4.0, ",": 0.3, ";": 0.5, ":": 0.4, "!": 0.0, " ": 0.4})


def visible_width(tex: str) -> float:
    """An estimate of the width of ``tex`` in display style, in glyphs: a fraction is as wide as
    its wider part, scripts are smaller, a binary operator or relation counts its spacing."""
    return _width(tex, 0, len(tex))[0]


def _group(tex: str, i: int, end: int) -> tuple[float, int]:
    """The width of the argument at tex[i] (a {...} group or a single token) and the index after."""
    while i < end and tex[i] == " ":
        i += 1
    if i < end and tex[i] == "{":
        depth, j = 0, i
        while j < end:
            if tex[j] == "\\":
                j += 2
                continue
            depth += tex[j] == "{"
            depth -= tex[j] == "}"
            if depth == 0:
                return _width(tex, i + 1, j)[0], j + 1
            j += 1
        return _width(tex, i + 1, end)[0], end
    if i < end and tex[i] == "\\":
        m = re.match(r"\\([A-Za-z]+|.)", tex[i:end])
        return 1.0, i + (len(m.group(0)) if m else 1)
    return (1.0, i + 1) if i < end else (0.0, i)


def _width(tex: str, i: int, end: int) -> tuple[float, int]:
    w = 0.0
    while i < end:
        ch = tex[i]
        if ch == "\\":
            m = re.match(r"\\([A-Za-z]+|.)", tex[i:end])
            name = m.group(1) if m else ""
            i += len(m.group(0)) if m else 1
            if name == "frac" or name == "dfrac" or name == "tfrac":
                a, i = _group(tex, i, end)
                b, i = _group(tex, i, end)
                w += max(a, b) * (0.7 if name == "tfrac" else 1.0) + 0.4
            elif name in ("left", "right", "big", "Big", "bigg", "Bigg", "displaystyle", "mid"):
                if name == "mid":
                    w += 1
                continue
            elif name == "sqrt":
                a, i = _group(tex, i, end)
                w += a + 1.2
            elif name in _SPACES:
                w += _SPACES[name]
            elif name in _WORDS_WIDE:
                w += len(name) * 0.9 if name not in ("operatorname", "text") else 0.0
            elif name in ("cdot", "pm", "mp", "times", "rightarrow", "mapsto", "le", "ge", "doteq", "approx"):
                w += 2.0
            else:
                w += 1.0
        elif ch in "^_":
            a, i = _group(tex, i + 1, end)
            w += 0.7 * a
        elif ch in "{}":
            i += 1
        elif ch in "+-=<>":
            w += 2.0
            i += 1
        elif ch in " &\n\t":
            i += 1
        else:
            w += 1.0
            i += 1
    return w, i


class _BreakingPrinter(PaperLatexPrinter):
    """Marks the places where a long sum may be broken: before the + and − of a top-level sum
    and of a sum that is a factor of a top-level product (printed as coefficient × (sum))."""

    def __init__(self, width: int, names: dict[str, str] | None = None, functions: dict[str, str] | None = None):
        super().__init__(names=names, function_names=functions)
        self._width = width

    def _long(self, expr) -> bool:
        return visible_width(self._print(expr)) > self._width

    def breakable(self, expr) -> str:
        if isinstance(expr, sp.Add) and self._long(expr):
            return self._add_broken(expr)
        if isinstance(expr, sp.Mul) and self._long(expr):
            return self._mul_broken(expr)
        return self._print(expr)

    def _add_broken(self, expr) -> str:
        tex = ""
        for i, term in enumerate(self._as_ordered_terms(expr)):
            if i > 0:
                if term.could_extract_minus_sign():
                    tex += _BREAK + " - "
                    term = -term
                else:
                    tex += _BREAK + " + "
            piece = self.breakable(term)
            if self._needs_add_brackets(term):
                piece = rf"\left({piece}\right)"
            tex += piece
        return tex

    def _mul_broken(self, expr) -> str:
        sums = [f for f in expr.args if isinstance(f, sp.Add)]
        if not sums:
            return self._print(expr)
        big = max(sums, key=lambda a: (visible_width(self._print(a)), sp.default_sort_key(a)))
        rest = sp.Mul(*[f for f in expr.args if f is not big])
        if rest == 1:
            head = ""
        elif rest == -1:
            head = "- "
        elif rest.could_extract_minus_sign():
            head = "- " + self._print(-rest) + " "
        else:
            head = self._print(rest) + " "
        return head + r"\left(" + self._add_broken(big) + r"\right)"


def broken_lines(expr, width: int = 70, names: dict[str, str] | None = None,
                 functions: dict[str, str] | None = None) -> list[str]:
    """``expr`` in the paper's notation, broken into lines of about ``width`` glyphs; each line
    has its ``\\left``/``\\right`` pairs closed so that it typesets on its own."""
    tex = _BreakingPrinter(width, names, functions).breakable(expr)
    return [balance(line) for line in fill_lines(tex.split(_BREAK), width)]


def fill_lines(pieces, width: int) -> list[str]:
    """Greedy line filling: the pieces in order, a new line where the next would pass ``width``
    (the one place it is done, for expressions and for printed rows)."""
    lines, cur = [], ""
    for piece in pieces:
        if cur and visible_width(cur) + visible_width(piece) > width:
            lines.append(cur)
            cur = piece
        else:
            cur += piece
    lines.append(cur)
    return lines


def relation_lines(rel, width: int = 70, names: dict[str, str] | None = None,
                   functions: dict[str, str] | None = None) -> list[str]:
    """A derived relation (``Eq``, expression, or a (symbol, value) pair of a model) as the rows
    of an ``aligned`` display: ``lhs &= …`` then ``&\\quad …``, broken where a long sum allows."""
    if isinstance(rel, tuple):
        lhs, rhs, rel_sym = rel[0], rel[1], r"\mapsto"
    elif isinstance(rel, sp.Eq):
        lhs, rhs, rel_sym = rel.lhs, rel.rhs, "="
    else:
        lhs, rhs, rel_sym = None, rel, ""
    left = paper_latex(lhs, names, functions) if lhs is not None else ""
    lines = broken_lines(rhs, width, names, functions)
    out = [f"{left} &{rel_sym} {lines[0]}".strip()]
    out += [rf"&\quad {line}" for line in lines[1:]]
    return out


# --- the catalog's printed LaTeX, ready for a display ------------------------------------------
_LEFT = re.compile(r"\\left(?![A-Za-z])")
_RIGHT = re.compile(r"\\right(?![A-Za-z])")
_ENV = re.compile(r"\\(begin|end)\{([A-Za-z*]+)\}")


def _split_top(s: str, seps: tuple[str, ...], newline: bool) -> list[str]:
    """Split ``s`` at ``seps`` (and newlines) that are outside braces and environments."""
    parts, cur, depth, env, i = [], [], 0, 0, 0
    while i < len(s):
        m = _ENV.match(s, i)
        if m:
            env += 1 if m.group(1) == "begin" else -1
            cur.append(m.group(0))
            i = m.end()
            continue
        ch = s[i]
        if ch == "\\" and i + 1 < len(s) and s[i + 1] in "{}\\&":
            if s[i + 1] == "\\" and depth == 0 and env == 0 and "\\\\" in seps:
                parts.append("".join(cur))
                cur = []
                i += 2
                continue
            cur.append(s[i:i + 2])
            i += 2
            continue
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        elif depth == 0 and env == 0 and ((ch == "\n" and newline) or ch in seps):
            parts.append("".join(cur))
            cur = []
            i += 1
            continue
        cur.append(ch)
        i += 1
    parts.append("".join(cur))
    return parts


def balance(row: str) -> str:
    """Close a ``\\left`` that the print closes on a later line (and open the ``\\right`` it
    opened on an earlier one) with invisible delimiters, so the row typesets on its own."""
    masked = _mask_nested(row)
    lefts, rights = len(_LEFT.findall(masked)), len(_RIGHT.findall(masked))
    # a \right before any \left at the same level needs an opening \left. in front
    opening = 0
    depth = 0
    for m in re.finditer(r"\\left(?![A-Za-z])|\\right(?![A-Za-z])", masked):
        if m.group(0) == r"\left":
            depth += 1
        else:
            depth -= 1
            if depth < 0:
                opening += 1
                depth = 0
    closing = lefts + opening - rights
    return (r"\left. " * opening) + row.strip() + (r" \right." * max(closing, 0))


def _mask_nested(s: str) -> str:
    """``s`` with everything inside braces and environments blanked out."""
    out, depth, env, i = [], 0, 0, 0
    while i < len(s):
        m = _ENV.match(s, i)
        if m:
            env += 1 if m.group(1) == "begin" else -1
            out.append(" " * len(m.group(0)))
            i = m.end()
            continue
        ch = s[i]
        if ch == "\\" and i + 1 < len(s) and s[i + 1] in "{}":
            out.append(s[i:i + 2] if depth == 0 and env == 0 else "  ")
            i += 2
            continue
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        out.append(ch if depth == 0 and env == 0 and ch not in "{}" else " ")
        i += 1
    return "".join(out)


def display_rows(latex: str) -> list[str]:
    """The rows of one display for a catalog entry's printed LaTeX.

    The print separates displays by newlines and lines of one display by ``\\\\``; both become
    rows.  Newlines and ``\\\\`` inside an environment (``aligned``) stay where they are.  Each
    row's ``\\left``/``\\right`` pairs are balanced (see :func:`balance`); a row ending in a
    bare operator after a ``\\\\`` keeps it.

    >>> display_rows(r"a = \\left\\{ b + \\right. \\\\ \\left. + c \\right\\}")
    ['a = \\\\left\\\\{ b + \\\\right.', '\\\\left. + c \\\\right\\\\}']
    >>> display_rows("x = 1\\ny = 2")
    ['x = 1', 'y = 2']
    """
    rows = []
    for line in _split_top(latex, ("\\\\",), newline=True):
        if line.strip():
            rows.append(balance(_balance_environments(line.strip())))
    return rows or [""]


def _balance_environments(s: str) -> str:
    """Balance \\left/\\right inside each cell of each environment in ``s`` (recursively)."""
    out, i = [], 0
    while True:
        m = re.search(r"\\begin\{([A-Za-z*]+)\}", s[i:])
        if not m:
            out.append(s[i:])
            return "".join(out)
        start = i + m.start()
        name = m.group(1)
        # find the matching \end
        depth, j = 0, start
        for e in _ENV.finditer(s, start):
            if e.group(2) == name:
                depth += 1 if e.group(1) == "begin" else -1
                if depth == 0:
                    j = e.start()
                    end = e.end()
                    break
        else:
            out.append(s[i:])
            return "".join(out)
        body_start = start + len(m.group(0))
        body = s[body_start:j]
        rows = _split_top(body, ("\\\\",), newline=False)
        new_rows = []
        for row in rows:
            cells = _split_top(row, ("&",), newline=False)
            new_rows.append(" &".join(balance(_balance_environments(c)) if c.strip() else c.strip() for c in cells))
        out.append(s[i:body_start] + " " + " \\\\\n".join(r for r in new_rows) + " " + s[j:end])
        i = end


def _break_points(row: str) -> list[int]:
    """Indices in ``row`` before which a line may break: a binary + or − or a ``\\quad`` at
    brace depth 0, outside environments."""
    out, depth, env, i = [], 0, 0, 0
    while i < len(row):
        m = _ENV.match(row, i)
        if m:
            env += 1 if m.group(1) == "begin" else -1
            i = m.end()
            continue
        ch = row[i]
        if ch == "\\":
            if row.startswith(r"\quad", i) and depth == 0 and env == 0 and i > 0:
                out.append(i)
            j = i + 1
            while j < len(row) and row[j].isalpha():
                j += 1
            i = max(j, i + 2) if j == i + 1 else j
            continue
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
        elif ch in "+-" and depth == 0 and env == 0:
            before = row[:i].rstrip()
            binary = bool(before) and (before[-1].isalnum() or before[-1] in "})]|!'") \
                and not re.search(r"\\left\s*\S?$|\\(cdot|quad|qquad|,|;)$", before)
            if binary or (before.endswith(r"\right.")):
                out.append(i)
        i += 1
    return out


def wrap_row(row: str, width: int = 74) -> str:
    """A printed row wider than ``width`` glyphs, broken before top-level + and − into an
    ``aligned`` block (continuation lines indented); each line keeps its \\left/\\right pairs
    closed.  Rows that fit, or that hold an environment, are returned as they are."""
    if visible_width(row) <= width or r"\begin" in row:
        return row
    cuts = [0] + _break_points(row) + [len(row)]
    pieces = [row[a:b] for a, b in zip(cuts, cuts[1:]) if row[a:b].strip()]
    lines = fill_lines(pieces, width)
    if len(lines) == 1:
        return row
    lines = [balance(line) for line in lines]
    return ("\\begin{aligned}\n&" + lines[0] + "".join(" \\\\\n&\\qquad " + line for line in lines[1:])
            + "\n\\end{aligned}")
