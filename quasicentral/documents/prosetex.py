"""Prose for pdfLaTeX: text with Unicode mathematics (ρ, ψ̇, ², √, ∫, −, ·, ≤ …) turned into
LaTeX — one function, one table (:data:`MATH_CHARS`) — with TeX's specials escaped, and the
prose of derivations and errata cleaned for a reader (:func:`clean_prose`).

>>> text("ρ̈ − ρψ̇²")
'\\\\ensuremath{\\\\ddot{\\\\varrho}} \\\\ensuremath{-} \\\\ensuremath{\\\\varrho \\\\dot{\\\\psi}^{2}}'
"""

from __future__ import annotations

import re
import unicodedata
from types import MappingProxyType

# --- prose: Unicode mathematics to LaTeX -------------------------------------------------------

#: One table: a character of prose and its LaTeX in math mode (None: text-mode replacement below).
MATH_CHARS = MappingProxyType({
    "α": r"\alpha", "β": r"\beta", "γ": r"\gamma", "δ": r"\delta", "ε": r"\varepsilon", "ζ": r"\zeta",
    "η": r"\eta", "θ": r"\theta", "ϑ": r"\vartheta", "κ": r"\kappa", "λ": r"\lambda", "μ": r"\mu",
    "ν": r"\nu", "ξ": r"\xi", "π": r"\pi", "ρ": r"\varrho", "ϱ": r"\varrho", "σ": r"\sigma",
    "τ": r"\tau", "φ": r"\varphi", "ϕ": r"\phi", "χ": r"\chi", "ψ": r"\psi", "ω": r"\omega",
    "Γ": r"\Gamma", "Δ": r"\Delta", "Θ": r"\Theta", "Λ": r"\Lambda", "Ξ": r"\Xi", "Π": r"\Pi",
    "Σ": r"\Sigma", "Φ": r"\Phi", "Ψ": r"\Psi", "Ω": r"\Omega",
    "−": "-", "±": r"\pm", "∓": r"\mp", "·": r"\cdot", "×": r"\times", "÷": r"\div",
    "√": r"\surd", "∫": r"\int", "∂": r"\partial", "∑": r"\sum", "∏": r"\prod", "∞": r"\infty",
    "∅": r"\emptyset", "∈": r"\in", "∉": r"\notin", "≈": r"\approx", "≐": r"\doteq", "≠": r"\neq",
    "≤": r"\le", "≥": r"\ge", "≡": r"\equiv", "∼": r"\sim", "→": r"\rightarrow", "←": r"\leftarrow",
    "⇒": r"\Rightarrow", "↦": r"\mapsto", "⌊": r"\lfloor", "⌋": r"\rfloor", "⌈": r"\lceil",
    "⌉": r"\rceil", "⟨": r"\langle", "⟩": r"\rangle", "‖": r"\|", "½": r"\tfrac{1}{2}",
    "¼": r"\tfrac{1}{4}", "¾": r"\tfrac{3}{4}", "°": r"^{\circ}", "′": r"'", "ℓ": r"\ell",
    "ṙ": r"\dot{r}", "ẋ": r"\dot{x}", "ẍ": r"\ddot{x}", "ẏ": r"\dot{y}", "ÿ": r"\ddot{y}",
    "ż": r"\dot{z}",
})
SUPERSCRIPTS = MappingProxyType(dict(zip("⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻ⁿⁱ", "0123456789+-ni")))
SUBSCRIPTS = MappingProxyType(dict(zip("₀₁₂₃₄₅₆₇₈₉₊₋ₙₘₖ", "0123456789+-nmk")))
COMBINING = MappingProxyType({"\u0307": r"\dot", "\u0308": r"\ddot", "\u0302": r"\hat", "\u0304": r"\bar", "\u20d7": r"\vec"})
#: Text-mode replacements for characters that are special to TeX or absent from T1 fonts.
TEXT_CHARS = MappingProxyType({
    "\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&", "#": r"\#",
    "%": r"\%", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}", "_": r"\_",
    "<": r"\textless{}", ">": r"\textgreater{}", "|": r"\textbar{}", '"': r"\textquotedbl{}",
    "–": "--", "—": "---", "…": r"\dots{}", "„": r"\quotedblbase{}", "“": r"\textquotedblleft{}",
    "”": r"\textquotedblright{}", "‘": "`", "’": "'", "\u00a0": "~", "\t": " ",
})
_WORD = re.compile(r"[A-Za-z]")


def _scan_braced(s: str, i: int) -> tuple[str, int]:
    """The content of the balanced {...} group starting at s[i] == '{', and the index after it."""
    depth, j = 0, i
    while j < len(s):
        if s[j] == "{":
            depth += 1
        elif s[j] == "}":
            depth -= 1
            if depth == 0:
                return s[i + 1:j], j + 1
        j += 1
    return s[i + 1:], len(s)


def _script(ch: str) -> tuple[str, str] | None:
    """('^', 't') for a superscript character such as ᵗ or ², ('_', '0') for ₀; else None."""
    if ch in SUPERSCRIPTS:
        return "^", SUPERSCRIPTS[ch]
    if ch in SUBSCRIPTS:
        return "_", SUBSCRIPTS[ch]
    d = unicodedata.decomposition(ch)
    if d.startswith(("<super> ", "<sub> ")):
        base = chr(int(d.split()[1], 16))
        tex = base if base.isascii() and base.isalnum() else MATH_CHARS.get(base)
        if tex:
            return ("^" if d.startswith("<super>") else "_"), tex
    return None


def _other(ch: str, math: bool) -> str:
    """Any other character: T1 has the Latin letters with diacritics (Czech among them);
    the rest is decomposed to ASCII where it can be, else named by its code point."""
    if ch.isascii():
        if math and (ch.isalnum() or ch in "+-=()[]/.,;:!?' *<>|"):
            return ch
        return TEXT_CHARS.get(ch, ch) if not math else (r"\text{" + TEXT_CHARS.get(ch, ch) + "}")
    if ch in TEXT_CHARS:
        return TEXT_CHARS[ch] if not math else r"\text{" + TEXT_CHARS[ch] + "}"
    if "\u00c0" <= ch <= "\u017f" and ch.isalpha() and ch not in "×÷":
        return ch if not math else r"\text{" + ch + "}"
    ascii_ = unicodedata.normalize("NFKD", ch).encode("ascii", "ignore").decode()
    if ascii_.strip():
        return _other(ascii_, math) if len(ascii_) == 1 else escape(ascii_)
    return r"\text{[U+%04X]}" % ord(ch) if math else "[U+%04X]" % ord(ch)


def _math(s: str) -> str:
    """A short run of prose mathematics (inside ^{...} or _{...}) in math mode."""
    out: list[str] = []
    for ch in s:
        sc = _script(ch)
        if ch in MATH_CHARS:
            out.append(MATH_CHARS[ch] + (" " if MATH_CHARS[ch][-1].isalpha() else ""))
        elif sc:
            out.append(f"{sc[0]}{{{sc[1]}}}")
        elif ch in COMBINING and out:
            out[-1] = f"{COMBINING[ch]}{{{out[-1].strip()}}}"
        elif ch in "{}":
            out.append("\\" + ch)
        else:
            out.append(_other(ch, math=True))
    return "".join(out).strip()


def _closing(s: str, i: int) -> int:
    """The index of the parenthesis that closes the one at s[i] (−1 where s[i] is none, or it
    is never closed)."""
    if i >= len(s) or s[i] != "(":
        return -1
    depth = 0
    for j in range(i, len(s)):
        depth += {"(": 1, ")": -1}.get(s[j], 0)
        if depth == 0:
            return j
    return -1


def _single_base(s: str, i: int) -> bool:
    """Is the character before s[i] a one-letter variable (x, ρ, C, a digit after one)?
    Then '_' or '^' at s[i] is a sub/superscript; after a longer word it is literal."""
    j = i
    while j > 0 and (s[j - 1] in COMBINING):
        j -= 1
    if j == 0:
        return False
    prev = s[j - 1]
    if prev in MATH_CHARS or _script(prev) is not None:  # ρ^…, and the upper limit of ∫₀^ζ
        return True
    if not (prev.isascii() and prev.isalnum()):
        return prev in ")]}"
    k = j - 1
    while k > 0 and s[k - 1].isascii() and s[k - 1].isalnum():
        k -= 1
    return j - k == 1


#: the one-letter words of each language: in Czech the prepositions and conjunctions k, s, v, z,
#: o, u, a, i, which Czech typography ties to the next word (``v~tisku``); any other lone letter
#: of prose is a variable
ONE_LETTER_WORDS = MappingProxyType({"en": frozenset("aI"), "cs": frozenset("ksvzouaiKSVZOUAI")})


#: a number in scientific form as the witness sentences write it: 8,799·10¹², −1.5·10⁻⁷
_SCIENTIFIC = re.compile(r"(?<![\w.,])([−-]?\d+(?:[.,]\d+)?)·10([⁻]?[⁰¹²³⁴⁵⁶⁷⁸⁹]+)")
_FROM_SUPERSCRIPT = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻", "0123456789-")


def _scientific(m: re.Match) -> str:
    mantissa = m.group(1).replace("−", "-").replace(",", "{,}")
    return f"\\ensuremath{{{mantissa}\\cdot 10^{{{m.group(2).translate(_FROM_SUPERSCRIPT)}}}}}"


def text(s: str, letters: bool = True, lang: str = "en") -> str:
    r"""Prose with Unicode mathematics as LaTeX for pdfLaTeX (T1 fonts, UTF-8 input).

    Greek letters, operators, super- and subscript characters and combining dots become math
    (``\\ensuremath``); ``a_b`` and ``a^{b}`` after a one-letter variable become sub- and
    superscripts (after a word such as ``test_x`` the underscore is literal); every character
    special to TeX is escaped.  Letters with diacritics that T1 has (Czech) pass through.
    With ``letters``, a lone letter such as the R of "R = 2κmv" is a variable and set in math
    italics too — not a one-letter word of ``lang`` (:data:`ONE_LETTER_WORDS`) before a word, nor
    the d of "d/dt"; in Czech such a word is tied to the next one.

    >>> print(text("v tisku je x − κy a k je modul", lang="cs"))
    v~tisku je \ensuremath{x} \ensuremath{-} \ensuremath{\kappa y} a~k~je modul
    >>> print(text("levá strana 1,065·10⁴, pravá −2·10⁻⁵", lang="cs"))
    levá strana \ensuremath{1{,}065\cdot 10^{4}}, pravá \ensuremath{-2\cdot 10^{-5}}
    """
    sci = _SCIENTIFIC.search(s)
    if sci:  # a number with its power of ten is one piece of mathematics, 1{,}065\cdot 10^{4}
        return text(s[:sci.start()], letters, lang) + _scientific(sci) + text(s[sci.end():], letters, lang)
    tokens: list[tuple[bool, str]] = []  # (is_math, latex)

    def push(is_math: bool, tex: str) -> None:
        tokens.append((is_math, tex))

    i, n = 0, len(s)
    while i < n:
        ch = s[i]
        sc = _script(ch)
        if ch in COMBINING:
            # a dot over the previous character: make it math and decorate it
            if tokens:
                was_math, prev = tokens.pop()
                base = prev if was_math else prev[-1:]
                rest = "" if was_math else prev[:-1]
                if rest:
                    push(False, rest)
                # decorate the last atom of a math run
                m = re.search(r"(\\[A-Za-z]+|\\[a-z]+\{[^{}]*\}|[A-Za-z0-9]) ?$", base)
                if m:
                    push(True, base[:m.start()] + f"{COMBINING[ch]}{{{m.group(1)}}}")
                else:
                    push(True, base)
            i += 1
        elif ch in MATH_CHARS:
            tex = MATH_CHARS[ch]
            push(True, tex + (" " if tex[-1].isalpha() and i + 1 < n and s[i + 1].isalnum() else ""))
            i += 1
        elif sc:
            j, parts = i, []
            while j < n and (_script(s[j]) or (None,))[0] == sc[0]:
                parts.append(_script(s[j])[1])
                j += 1
            push(True, sc[0] + "{" + "".join(parts) + "}")
            i = j
        elif (ch in "^_" and i + 1 < n
              and (_single_base(s, i) or (ch == "^" and i > 0 and (s[i + 1] == "{" or s[i + 1].isdigit())))
              and (s[i + 1] == "{" or s[i + 1].isalnum() or s[i + 1] in MATH_CHARS)):
            if s[i + 1] == "{":
                inner, j = _scan_braced(s, i + 1)
            else:
                j = i + 1
                while j < n and (s[j].isalnum() or s[j] in MATH_CHARS or s[j] in COMBINING) and not (
                        ch == "^" and s[j].isalpha() and s[j].isascii() and j > i + 1):
                    j += 1
                inner = s[i + 1:j]
            push(True, ch + "{" + _math(inner) + "}")
            i = j
        elif ch == "^" and 0 < i and _closing(s, i + 1) > 0:
            # a power of a parenthesis, (1 − X)^(−1/2): its exponent raised, without the brackets
            j = _closing(s, i + 1)
            push(True, "^{" + _math(s[i + 2:j]) + "}")
            i = j + 1
        elif ch == "\n":
            push(False, " ")
            i += 1
        else:
            push(False, _other(ch, math=False))
            i += 1
    return _join(tokens, letters, ONE_LETTER_WORDS.get(lang, ONE_LETTER_WORDS["en"]), lang == "cs")


def escape(s: str) -> str:
    r"""Plain text (identifiers, file names) with TeX's special characters escaped, no mathematics.

    >>> print(escape("derivations.text_s2 {50%}"))
    derivations.text\_s2 \{50\%\}
    """
    return "".join(TEXT_CHARS.get(ch, ch) if ch.isascii() else text(ch) for ch in s)


#: the control words a text's inline mathematics may use: its symbols, operators and layout —
#: nothing that reads, writes or redefines (a folder's words are printed, never obeyed)
SAFE_MATH = frozenset("""
alpha beta gamma delta epsilon varepsilon zeta eta theta vartheta iota kappa lambda mu nu xi omicron pi varpi
rho varrho sigma varsigma tau upsilon phi varphi chi psi omega Gamma Delta Theta Lambda Xi Pi Sigma Upsilon
Phi Psi Omega frac tfrac dfrac sqrt cdot times div pm mp le leq ge geq ne neq approx sim simeq equiv propto to
rightarrow leftarrow Rightarrow Leftarrow mapsto infty partial nabla int iint oint sum prod lim limsup liminf
sin cos tan cot sec csc arcsin arccos arctan arccotg cotg tg sinh cosh tanh coth ln log exp min max det
left right big Big bigg Bigg bigl bigr Bigl Bigr dot ddot dddot hat bar vec tilde widetilde widehat overline
underline mathrm mathbf mathit mathcal mathsf mathbb text textrm operatorname quad qquad ldots cdots dots vdots
ddots prime circ ell hbar emptyset varnothing lfloor rfloor lceil rceil langle rangle mid vert Vert forall
exists in notin subset subseteq supset cup cap wedge vee neg land lor displaystyle textstyle limits nolimits
substack over choose binom pmod bmod perp parallel angle degree star ast bullet oplus otimes ll gg
""".split())


def safe_math(tex: str) -> bool:
    """Whether ``tex`` (a text's inline mathematics) uses only :data:`SAFE_MATH` control words."""
    return all(word in SAFE_MATH for word in re.findall(r"\\([A-Za-z@]+)", tex))


def with_math(s: str, letters: bool = True, lang: str = "en") -> str:
    r"""Prose that may hold inline mathematics between ``$`` signs (catalog notes and titles):
    the mathematics is kept as written, the rest goes through :func:`text`.  An odd number of
    ``$`` means they are not delimiters, and mathematics with a control word outside
    :data:`SAFE_MATH` (``\input``, ``\write``, ``\def`` …) is no mathematics of a text's:
    everything is prose then, escaped.

    >>> print(with_math(r"silou $R = 2\kappa mv$ a κ"))
    silou $R = 2\kappa mv$ a \ensuremath{\kappa}
    >>> print(with_math(r"$\input{/etc/passwd}$"))
    \$\textbackslash{}input\{/etc/passwd\}\$
    """
    parts = s.split("$")
    if len(parts) % 2 == 0 or any(not p.strip() for p in parts[1::2]) or not all(safe_math(p) for p in parts[1::2]):
        return text(s, letters, lang)
    return "".join(text(p, letters, lang) if i % 2 == 0 else f"${p}$" for i, p in enumerate(parts))


_NEIGHBOURS = frozenset(set(" =+-,;:()[]/*<>0123456789"))
#: words after which an opening "A" is a variable, not the article: "A and B are constants"
_NOT_AFTER_ARTICLE = frozenset({"and", "or", "is", "are", "was", "equals", "sin", "cos", "tan", "exp", "ln", "log",
                                "sinh", "cosh", "tanh", "e", "cot", "of", "in", "at"})


def _word_at(tokens: list[tuple[bool, str]], i: int) -> str:
    """The word of prose that starts at token i ('' where none does)."""
    out = []
    while i < len(tokens) and not tokens[i][0] and tokens[i][1].isalpha():
        out.append(tokens[i][1])
        i += 1
    return "".join(out)


def _lone_variable(tokens: list[tuple[bool, str]], k: int, words: frozenset = frozenset("aI")) -> bool:
    """Is text token k a letter standing alone between spaces, operators or brackets (and not a
    one-letter word of the language before a word)?"""
    tex = tokens[k][1]
    prev = tokens[k - 1] if k > 0 else (False, " ")
    nxt = tokens[k + 1] if k + 1 < len(tokens) else (False, " ")
    after = tokens[k + 2] if k + 2 < len(tokens) else (False, " ")
    then = tokens[k + 3] if k + 3 < len(tokens) else (False, "")
    # a one-letter word before a word or a number ("v 20 bodech", "6 z 6 bodů")
    if tex == "d" or (tex in words and (tex in "aI" or (nxt[1] == " " and not after[0] and after[1][:1].isalnum()))):
        return False
    opening = k == 0 or (prev[1] == " " and k > 1 and tokens[k - 2][1] in ".:" and not tokens[k - 2][0])
    if tex == "A" and opening and nxt[1] == " " and _word_at(tokens, k + 2) not in _NOT_AFTER_ARTICLE \
            and _word_at(tokens, k + 2)[:1].islower():
        return False  # the article opening a sentence, "A definition: …"
    prev_ok = prev[0] or prev[1] in _NEIGHBOURS
    # before a full stop only at the end of a sentence ("law of S."), not in "t. j." or "e.g."
    end_of_sentence = nxt[1] in ".?!" and (k + 2 >= len(tokens) or (
        after[1] in (" ", "\n") and (then[0] or not then[1][:1].isalpha() or then[1][:1].isupper())))
    next_ok = nxt[0] or nxt[1] in _NEIGHBOURS or end_of_sentence
    return prev_ok and next_ok


def _join(tokens: list[tuple[bool, str]], letters: bool = True, words: frozenset = frozenset("aI"),
          tie: bool = False) -> str:
    """Merge runs of math tokens (and single letters glued to them) into one \\ensuremath;
    with ``tie``, a one-letter word of ``words`` is tied to the next word by ``~``."""
    # a lone ASCII letter touching math (ρψ̇, a_ρ, e^{...}) reads as a variable: make it math
    merged: list[tuple[bool, str]] = []
    for k, (is_math, tex) in enumerate(tokens):
        if not is_math and len(tex) == 1 and _WORD.match(tex):
            prev_math = k > 0 and tokens[k - 1][0]
            next_math = k + 1 < len(tokens) and tokens[k + 1][0]
            prev_letter = k > 0 and not tokens[k - 1][0] and tokens[k - 1][1][-1:].isalpha()
            next_letter = k + 1 < len(tokens) and not tokens[k + 1][0] and tokens[k + 1][1][:1].isalpha()
            if (prev_math or next_math) and not prev_letter and not next_letter:
                is_math = True
            elif letters and _lone_variable(tokens, k, words):
                is_math = True
        if merged and merged[-1][0] == is_math:
            a = merged[-1][1]
            sep = " " if is_math and re.search(r"\\[A-Za-z]+$", a) and tex[:1].isalpha() else ""
            merged[-1] = (is_math, a + sep + tex)
        else:
            merged.append((is_math, tex))
    out = []
    for is_math, tex in merged:
        if is_math:
            out.append(r"\ensuremath{" + tex.strip() + "}" + (" " if tex.endswith(" ") else ""))
        else:
            out.append(_tied(tex, words) if tie else tex)
    return "".join(out)


def _tied(prose: str, words: frozenset) -> str:
    """``prose`` with each one-letter word of ``words`` tied to what follows (Czech typography:
    no preposition at the end of a line)."""
    out = list(prose)
    for i in range(len(out) - 1):
        if out[i] in words and out[i + 1] == " " and (i == 0 or not (out[i - 1].isalnum() or out[i - 1] == "\\")):
            out[i + 1] = "~"
    return "".join(out)


# --- prose of the derivations and errata, cleaned for a reader ------------------------------------
_GREEK_WORDS = MappingProxyType({"alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "zeta": "ζ", "kappa": "κ",
                "lambda": "λ", "lam": "λ", "eta": "η", "nu": "ν", "sigma": "σ", "rho": "ϱ", "psi": "ψ", "phi": "φ", "vphi": "φ", "Omega": "Ω",
                "omega": "ω", "pi": "π", "theta": "θ", "tau": "τ"})
#: Names of the machinery a reader does not need: what they stand for in the text's notation.
CODE_NAMES = MappingProxyType({"elliptic_k": "K", "elliptic_f": "F", "elliptic_e": "E", "Fj": "F", "Ej": "E", "Kc": "K",
              "Ec": "E", "asin": "arcsin", "atan2": "arctg", "atan": "arctg", "sqrt": "√"})
_SUBSCRIPT_DIGITS = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
#: the checker's name for the n-th time derivative of a function at a point (phi_t1 for φ̇), and
#: the dots it is written with
_JET_NAME = re.compile(r"\b([A-Za-z]+)_t([0-4])\b")
_JET_DOTS = ("", "\u0307", "\u0308", "\u20db", "\u20dc")
_TEST_REFERENCE = re.compile(
    r"\s*\((?:[^()]|\([^()]*\))*?(?:\btests?\b/|\btest_\w+|\w+\.py\b|\btests\)|\(tests\b)(?:[^()]|\([^()]*\))*\)"
    r"|\s*\(tests?\)")
#: a code name in parentheses after a space, ``(legendre_antiderivative)`` — not the argument
#: of a function, ``y(t_v)``, which follows its name directly
_IDENT_IN_PARENS = re.compile(r"(?:(?<=\s)|^)\(\s*[A-Za-z]+_[A-Za-z0-9_]+\s*\)|\s+\(\s*[A-Za-z]+_[A-Za-z0-9_]+\s*\)")


def clean_prose(s: str) -> str:
    """Prose written for programmers, made fit for a reader: references to tests and code
    (``(tests/test_x.py)``, ``(legendre_antiderivative)``) dropped, the names of sympy's
    functions replaced by the text's (``elliptic_k`` → K), Greek letters written out in ASCII
    set as letters (``Omega t`` → Ωt), and the digit after a one-letter symbol made a
    subscript (``R0`` → R₀, ``C1`` → C₁).

    >>> clean_prose("R0 = v0 at Omega t = 2 pi (tests/test_a.py)")
    'R₀ = v₀ at Ω t = 2 π'
    >>> clean_prose("elliptic_k(m) (legendre_antiderivative) and phi0")
    'K(m) and φ₀'
    >>> print(clean_prose("h = y(t_v), x'' = a with x'(0) = v0, the 'free' fall"))
    h = y(t_v), x′′ = a with x′(0) = v₀, the ‘free’ fall
    >>> print(clean_prose(r"int_0^oo of lam at $\\lambda = 2$ as x -> oo"))
    ∫_0^∞ of λ at $\\lambda = 2$ as x -> ∞
    """
    parts = s.split("$")
    if len(parts) > 1 and len(parts) % 2 == 1:  # inline mathematics (a witness's $\\lambda$) is kept as written
        return "$".join(p if i % 2 else clean_prose(p) for i, p in enumerate(parts))
    s = _TEST_REFERENCE.sub("", s)
    s = re.sub(r'"([^"]+)"', "\u201c\\1\u201d", s)  # straight quotes become typographic ones
    # single quotes around words, never the primes of a derivative (x'' = a, x'(0) = v0)
    s = re.sub(r"(?<![A-Za-z0-9'])'(?=[^\s'])([^'\n]+?)(?<=\S)'(?![A-Za-z0-9'(])", "\u2018\\1\u2019", s)
    # the primes of a one-letter symbol (x'' = a, x'(0)), never an apostrophe (Newton's)
    s = re.sub(r"(?<![A-Za-zα-ωΑ-Ω])([A-Za-zα-ωΑ-Ω])('+)(?![A-Za-z])", lambda m: m.group(1) + "′" * len(m.group(2)), s)
    s = _IDENT_IN_PARENS.sub("", s)
    s = re.sub(r"\btests?/[\w/]+\.py\b", "the tests", s)
    s = re.sub(r"\btest_\w+", "a test", s)
    s = re.sub(r"\b(" + "|".join(sorted(CODE_NAMES, key=len, reverse=True)) + r")(?=\()",
               lambda m: CODE_NAMES[m.group(1)], s)
    # a point's coordinate of a motion, phi_t1 (the checker's jet: φ̇ at the point), as the paper writes it
    s = _JET_NAME.sub(lambda m: _GREEK_WORDS.get(m.group(1), m.group(1)) + _JET_DOTS[int(m.group(2))], s)
    # a Greek letter's name as its letter — not in the name of a function or a constant ("the gamma function", "the omega constant")
    s = re.sub(r"\b(" + "|".join(sorted(_GREEK_WORDS, key=len, reverse=True)) + r")(\d?)\b(?!\s+(?:functions?|constants?)\b)",
               lambda m: _GREEK_WORDS[m.group(1)] + m.group(2).translate(_SUBSCRIPT_DIGITS), s)
    s = re.sub(r"\bint_(\w)\^(\w+|\{[^{}]*\})", r"∫_\1^\2", s)
    s = re.sub(r"(?<=[\^_])oo\b|(?<=[\s(=,])oo\b|(?<=→ )oo\b", "∞", s)  # sympy's oo
    s = re.sub(r"\b(elliptic_[kfe]|Fj|Ej|Kc|Ec)\b", lambda m: CODE_NAMES[m.group(1)], s)
    s = re.sub(r"\bdsolve of\b", "the solution of", s)
    s = re.sub(r"\bdsolve\b", "solving", s)
    s = re.sub(r"(?<![A-Za-z0-9_.])([A-Za-zα-ωϱφ])0(?=[A-Za-zα-ωΑ-Ω(√])", lambda m: m.group(1) + "₀", s)
    s = re.sub(r"(?<![A-Za-z0-9_.])([A-Za-zΑ-Ωα-ωϱφ])(\d)(?![A-Za-z0-9_(])",
               lambda m: m.group(1) + m.group(2).translate(_SUBSCRIPT_DIGITS), s)
    return s
