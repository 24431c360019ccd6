"""A record's note with its ``{witness…}`` placeholders filled from the witness of the run —
per language, its numbers formatted as the language writes them (the JSON documents: English).

>>> from quasicentral.engine.verdict import Witness
>>> w = Witness({"t": "3/2"}, "1.5", "2.25", 3, True, relative_difference="3.333e-01")
>>> render_note("at t = {witness.parameters.t}: {witness.printed}", w, "cs")
'at t = 1,5: 1,5'
"""

from __future__ import annotations

import re
from types import MappingProxyType

import mpmath
import sympy as sp

from quasicentral.engine.wording import Plain

_PLACEHOLDER = re.compile(r"\{witness(?:\.(printed|corrected|relative_difference|quantity|parameters\.[A-Za-z_0-9]+))?\}")
PARAMETER_DIGITS = 8  # significant digits of a witness's parameter in prose


def parameters_text(w, lang: str = "en", digits: int = PARAMETER_DIGITS) -> dict[str, str]:
    """The witness's exact parameters as short decimals for prose (integers as they are)."""
    style = Plain(lang)
    out = {}
    for k, v in w.parameters.items():
        val = sp.sympify(v, rational=True) if not isinstance(v, sp.Basic) else v
        # rounded once, from the exact value: sympy's N(x, 4) rounds a binary value of about four
        # digits again, and said U = 5.222 of 5476191/1048576 = 5.22250…
        with mpmath.workdps(digits + 30):
            exact = mpmath.mpf(int(val.p)) / int(val.q) if val.is_Rational else mpmath.mpf(sp.N(val, digits + 30))
            short = mpmath.nstr(exact, digits, strip_zeros=True) if exact != 0 else "0"
        if "." in short and "e" not in short:  # 1.5000000 → 1.5: the zeros say nothing
            short = short.rstrip("0").rstrip(".")
        out[k] = v if val.is_Rational and val.q == 1 else style.decimal(short)
    return out


_SUPERSCRIPT = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


def _power_of_ten(shown: str) -> str:
    """8.799e+12 → 8.799·10¹², as the verdict lines write it (a decimal without one as it is)."""
    mantissa, e, exponent = shown.partition("e")
    return f"{mantissa}·10{str(int(exponent)).translate(_SUPERSCRIPT)}" if e else shown


def short_value(value: str, digits: int | None) -> str:
    """A witness value (a decimal string of up to 20 digits) in ``digits`` significant digits
    with a real minus sign and a power of ten, for a reader; as it is where ``digits`` is None or
    it is no number.

    >>> short_value("8.79912e+12", 4), short_value("-1.5e-7", 3), short_value("inf", 4)
    ('8.799·10¹²', '−1.5·10⁻⁷', '∞')
    """
    if digits is None:
        return value
    try:
        with mpmath.workdps(max(digits, 20) + 5):
            x = mpmath.mpmathify(value)
            shown = mpmath.nstr(x, digits, strip_zeros=True) if x != 0 else "0"
    except (ValueError, TypeError):
        return value
    if mpmath.isinf(x):  # a limit without bound
        return "−∞" if x < 0 else "∞"
    return _power_of_ten(shown).replace("-", "−")


_SENTENCE = MappingProxyType({
    "en": ("at {at} the printed form gives {p}, the correct one {c} ({q}{r}; {cert})",
           "certified", "not certified",
           "no numeric witness (the printed relation is dimensionally inconsistent)",
           "the printed value is {p}, the correct one {c} ({q}{r}; {cert})", "; relative difference ",
           "at {at} the left side is {p}, the right side {c} ({r}{cert})",
           "the left side is {p}, the right side {c} ({r}{cert})",
           "at {at} {q} is {p} at the last step and {c} three steps before ({cert})",
           "at {at}, {q}: {p} and {c} ({cert})", "{q}: {p} and {c} ({cert})"),
    "cs": ("v bodě {at} dává vytištěný tvar {p}, správný {c} ({q}{r}; {cert})",
           "potvrzeno", "nepotvrzeno",  # the Czech documents' term for certified (their method section)
           "bez numerického svědka (vytištěný vztah je rozměrově nekonzistentní)",
           "vytištěná hodnota je {p}, správná {c} ({q}{r}; {cert})", "; relativní rozdíl ",
           "v bodě {at} je levá strana {p}, pravá {c} ({r}{cert})",
           "levá strana je {p}, pravá {c} ({r}{cert})",
           "v bodě {at} je {q} v posledním kroku {p} a o tři kroky dříve {c} ({cert})",
           "v bodě {at}: {q}: {p} a {c} ({cert})", "{q}: {p} a {c} ({cert})"),
})


def witness_sentence(w, lang: str = "en", digits: int | None = None, name=None, unit=None) -> str:
    """The witness as one sentence, from its record only: its values in full (the JSON, the
    terminal), or in ``digits`` significant digits with real minus signs (a document's prose,
    its point then in as many); ``name`` writes a parameter's name as the reader's text does
    ($\\lambda$ for lam in a document; default: as the checker names it) and ``unit`` the units
    after its value (' K' where the text declared them; default: none)."""
    words = _SENTENCE.get(lang, _SENTENCE["en"])
    if w is None:
        return words[3]
    from quasicentral.engine.wording import render

    style = Plain(lang)
    params = parameters_text(w, lang, digits or PARAMETER_DIGITS)
    at = ", ".join(f"{name(k) if name else k} = {_power_of_ten(v).replace('-', '−') if digits else v}"
                   f"{unit(k) if unit else ''}" for k, v in params.items())
    p, c = short_value(w.printed, digits), short_value(w.corrected, digits)
    more = digits
    while more is not None and p == c and more < 20:  # as many digits as tell the two apart
        more += 1
        p, c = short_value(w.printed, more), short_value(w.corrected, more)
    # a value with no point (a printed rounding, a special value) is said without one
    r = words[5] + style.decimal(short_value(w.relative_difference, digits and 2)) if w.relative_difference else ""
    from quasicentral.engine.reasons import Code

    sides = getattr(w.quantity, "code", None) is Code.Q_SIDES  # an identity: its two sides, no "correct" one
    ratio = getattr(w.quantity, "code", None) is Code.Q_ORDER_RATIO  # one form's ratio at two steps
    # a bound: the two values compared, neither printed nor correct, no relative difference
    bound = getattr(w.quantity, "code", None) in (Code.Q_LESSER_GREATER, Code.Q_ROUNDING_WINDOW)
    template = words[8] if ratio else words[9 if at else 10] if bound else \
        words[6 if at else 7] if sides else words[0 if at else 4]
    if sides:
        r = r[2:] + "; " if r else ""  # "relative difference 1.9; certified"
    return template.format(at=at, q=render(w.quantity, lang), p=style.decimal(p),
                           c=style.decimal(c), r=r, cert=words[1] if w.certified else words[2])


def render_note(note: str, w, lang: str = "en", digits: int | None = None, name=None, unit=None) -> str:
    """``note`` with its ``{witness…}`` placeholders filled from the witness ``w`` ('—' where
    the witness has no such value); its numbers in ``digits`` significant digits where given
    and its parameters' names and units written by ``name`` and ``unit`` (:func:`witness_sentence`)."""
    style = Plain(lang)

    def fill(m: re.Match) -> str:
        field = m.group(1)
        if field is None:
            return witness_sentence(w, lang, digits, name, unit)
        if w is None:
            return "—"
        if field.startswith("parameters."):
            got = parameters_text(w, lang, digits or PARAMETER_DIGITS).get(field.split(".", 1)[1], "—")
            return _power_of_ten(got).replace("-", "−") if digits else got
        if field == "quantity":
            from quasicentral.engine.wording import render

            return render(w.quantity, lang)
        return style.decimal(short_value(str(getattr(w, field)), digits))

    return _PLACEHOLDER.sub(fill, note)
