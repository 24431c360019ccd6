"""Tokens of DLMF's semantic LaTeX.

A token is a command (``\\incellintFk``, ``\\,``, ``\\\\``), a brace, one of ``^ _ & ' @``
(a run of ``@`` is one token: DLMF writes ``@`` or ``@@`` before a macro's arguments, the
count only says how the function is printed), a number (digits with at most one decimal
point), a letter, or any other single character.  Whitespace separates tokens and is dropped;
a comment (``%`` to the end of the line) too.

>>> [t.text for t in tokenize(r"\\sin^{2}@@{\\theta}+1.5x")]
['\\\\sin', '^', '{', '2', '}', '@@', '{', '\\\\theta', '}', '+', '1.5', 'x', '']
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum


class Kind(Enum):
    COMMAND = "command"
    OPEN = "{"
    CLOSE = "}"
    NUMBER = "number"
    LETTER = "letter"
    AT = "@"
    CHAR = "char"  # any other single character: + - = ( ) [ ] | , ; . ! / < > ^ _ & ' * :
    END = "end"


@dataclass(frozen=True)
class Token:
    kind: Kind
    text: str
    pos: int  # offset in the source, for messages

    def is_(self, *texts: str) -> bool:
        return self.text in texts and self.kind is not Kind.END


class LexError(ValueError):
    """A character the tokenizer cannot place (reported with its offset)."""


def tokenize(source: str) -> list[Token]:
    """The tokens of ``source``, ending with one END token."""
    out: list[Token] = []
    i, n = 0, len(source)
    while i < n:
        c = source[i]
        if c.isspace():
            i += 1
        elif c == "%":
            while i < n and source[i] != "\n":
                i += 1
        elif c == "\\":
            j = i + 1
            if j < n and source[j].isalpha():
                while j < n and source[j].isalpha():
                    j += 1
                out.append(Token(Kind.COMMAND, source[i:j], i))
                i = j
            elif j < n:
                out.append(Token(Kind.COMMAND, source[i:j + 1], i))
                i = j + 1
            else:
                raise LexError(f"a lone backslash at offset {i}")
        elif c == "{":
            out.append(Token(Kind.OPEN, c, i))
            i += 1
        elif c == "}":
            out.append(Token(Kind.CLOSE, c, i))
            i += 1
        elif c == "@":
            j = i
            while j < n and source[j] == "@":
                j += 1
            out.append(Token(Kind.AT, source[i:j], i))
            i = j
        elif c.isdigit() or (c == "." and i + 1 < n and source[i + 1].isdigit()):
            j = i
            seen_point = False
            while j < n and (source[j].isdigit() or (source[j] == "." and not seen_point
                                                     and j + 1 < n and source[j + 1].isdigit())):
                seen_point = seen_point or source[j] == "."
                j += 1
            out.append(Token(Kind.NUMBER, source[i:j], i))
            i = j
        elif c.isalpha():
            out.append(Token(Kind.LETTER, c, i))
            i += 1
        else:
            out.append(Token(Kind.CHAR, c, i))
            i += 1
    out.append(Token(Kind.END, "", n))
    return out
