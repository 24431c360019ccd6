"""The words of the engine's reasons, per language: one table, every code in every language.

:func:`render` turns a :class:`~quasicentral.engine.reasons.Reason` into a sentence.  How its
fields look is the *style*'s business: :class:`Plain` (the command line, the JSON documents:
expressions in sympy syntax, numbers with the language's decimal separator) or a style of the
documents (expressions typeset as mathematics in the text's notation, text escaped for LaTeX).
The English plain rendering of each code is the wording the JSON documents have always had.

>>> from quasicentral.engine.reasons import Code, Reason
>>> r = Reason.of(Code.DISAGREES, count=3, points=6, relative=0.25)
>>> render(r, "en")
'3 of 6 points disagree (largest relative difference 0.25)'
>>> render(r, "cs")
'3 z 6 bodů nesouhlasí (největší relativní rozdíl 0,25)'
"""

from __future__ import annotations

from types import MappingProxyType
from typing import Callable

from quasicentral.engine.reasons import Code, Reason

LANGUAGES = ("en", "cs")


class Plain:
    """Fields as plain text: expressions and dimensions as written, numbers per language."""

    def __init__(self, lang: str):
        self.lang = lang

    def text(self, s: str) -> str:
        return s

    def expr(self, s: str) -> str:
        return s

    def dim(self, s: str) -> str:
        return f"[{s}]"

    def num(self, x, spec: str = "") -> str:
        s = format(x, spec) if spec else str(x)
        return s.replace(".", ",") if self.lang == "cs" else s

    def decimal(self, s: str) -> str:
        """A number already written as a decimal string."""
        return s.replace(".", ",") if self.lang == "cs" else s


class _Fields:
    """A reason's fields for a template: ``f.n`` is the field, ``f.sub("why")`` a nested
    reason rendered in the same language and style."""

    def __init__(self, reason: Reason, lang: str, style):
        self._reason, self._lang, self._style = reason, lang, style

    def __getattr__(self, name: str):
        return self._reason[name]

    def sub(self, name: str) -> str:
        return render(self._reason[name], self._lang, self._style)


def _points(f, s, lang) -> str:
    """'20' or '18 of 20' points (en), '20' or '18 z 20' (cs)."""
    if f.n < f.of:
        return f"{f.n} of {f.of}" if lang == "en" else f"{f.n} z {f.of}"
    return f"{f.n}"


def _agrees_en(f, s) -> str:
    also = f"also at {f.top} digits" if f.confirmed == f.n == 1 else f"{f.confirmed} of them also at {f.top} digits"
    zeros = (f"; at {'all' if f.zeros == f.n else f.zeros} of them the difference falls with every digit added: "
             f"an exact zero, rounded" if f.zeros else "")
    return (f"agrees at {_points(f, s, 'en')} point{'' if f.n == 1 else 's'} to {f.digits}+ digits ({also}{zeros})"
            + (" (both sides vanish at every point)" if f.vacuous else ""))


def _agrees_cs(f, s) -> str:
    also = f"také na {f.top} číslic" if f.confirmed == f.n == 1 else f"{f.confirmed} z nich také na {f.top} číslic"
    zeros = (f"; v {'každém z nich' if f.zeros == f.n else f'{f.zeros} z nich'} rozdíl klesá s každou přidanou "
             f"číslicí: přesná nula, zaokrouhlená" if f.zeros else "")
    return (f"souhlasí v {_points(f, s, 'cs')} {'bodě' if f.n == 1 else 'bodech'} na {f.digits} a více platných číslic "
            f"({also}{zeros})" + (" (obě strany ve všech bodech vymizí)" if f.vacuous else ""))


def _numbers_en(f, s) -> str:
    n = f.numbers
    if n is None:
        return ""
    return f" ({n} numerically)" if isinstance(n, str) else f" ({f.sub('numbers')})"


def _numbers_cs(f, s) -> str:
    n = f.numbers
    if n is None:
        return ""
    word = {"verified": "ověřeno", "inconclusive": "nerozhodnuto", "refuted": "vyvráceno"}
    return f" (numericky {word.get(n, n)})" if isinstance(n, str) else f" ({f.sub('numbers')})"


_POWER = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")


def _places_en(n) -> str:
    """The places a printed decimal is rounded to: 1 decimal place, 3 decimal places, to a whole
    number, to a multiple of 10⁴ (3.155e7 printed: −4 places)."""
    n = int(n)
    return (f"{n} decimal place" + ("s" if n > 1 else "") if n > 0 else "to a whole number" if n == 0
            else f"to a multiple of 10{str(-n).translate(_POWER)}")


def _places_cs(n) -> str:
    """n decimal places in Czech: 1 desetinné místo, 2–4 desetinná místa, 5 and more desetinných
    míst; na celé číslo; na násobek 10⁴."""
    n = int(n)
    if n <= 0:
        return "na celé číslo" if n == 0 else f"na násobek 10{str(-n).translate(_POWER)}"
    return f"{n} desetinné místo" if n == 1 else f"{n} desetinná místa" if 2 <= n <= 4 else f"{n} desetinných míst"


_VERDICT_CS = MappingProxyType({"verified": "ověřen", "refuted": "vyvrácen", "inconclusive": "nerozhodnut"})

Template = Callable[[_Fields, object], str]

#: code → language → template(fields, style).  A test checks that every code has every language.
WORDING: "MappingProxyType[Code, MappingProxyType[str, Template]]" = MappingProxyType({code: MappingProxyType(w) for code, w in {
    Code.AGREES: {"en": _agrees_en, "cs": _agrees_cs},
    Code.PROVED: {
        "en": lambda f, s: "sympy proves the difference zero; " + f.sub("numbers"),
        "cs": lambda f, s: "sympy dokazuje, že rozdíl je nulový; " + f.sub("numbers")},
    Code.DECIDED_TRUE: {
        "en": lambda f, s: "sympy decides the printed relation true from the symbols' assumptions",
        "cs": lambda f, s: "sympy rozhodne z předpokladů o symbolech, že vytištěný vztah platí"},
    Code.ROUNDS_TO: {
        "en": lambda f, s: (f"the exact value {s.decimal(f.value)} rounds to the printed {s.decimal(f.printed)} "
                            f"({_places_en(f.places)})"),
        "cs": lambda f, s: (f"přesná hodnota {s.decimal(f.value)} se zaokrouhlí na vytištěné {s.decimal(f.printed)} "
                            f"({_places_cs(f.places)})")},
    Code.HOLDS: {
        "en": lambda f, s: f"holds at {_points(f, s, 'en')} points ({f.top} digits)",
        "cs": lambda f, s: f"platí v {_points(f, s, 'cs')} bodech ({f.top} číslic)"},
    Code.LIMIT_FOUND: {
        "en": lambda f, s: ("sympy finds the limit " if f.how == "sympy" else "the sequence converges to ")
        + s.expr(f.value),
        "cs": lambda f, s: ("sympy nachází limitu " if f.how == "sympy" else "posloupnost konverguje k ")
        + s.expr(f.value)},
    Code.DISAGREES: {
        "en": lambda f, s: (f"{f.count} of {f.points} points disagree (largest relative difference "
                            if f.points != 1 else "disagrees at its one point (relative difference ")
                           + f"{s.num(f.relative, '.3g')})",
        "cs": lambda f, s: (f"{f.count} z {f.points} bodů nesouhlasí (největší relativní rozdíl "
                            if f.points != 1 else "nesouhlasí ve svém jediném bodě (relativní rozdíl ")
                           + f"{s.num(f.relative, '.3g')})"},
    Code.FAILS_AT: {
        "en": lambda f, s: f"fails at {f.count} of {f.points} points",
        "cs": lambda f, s: f"neplatí v {f.count} z {f.points} bodů"},
    Code.DIVERGES: {
        "en": lambda f, s: "the printed form diverges: " + f.sub("why"),
        "cs": lambda f, s: "vytištěný tvar diverguje: " + f.sub("why")},
    Code.INTEGRAND_GROWS: {
        "en": lambda f, s: (f"the integrand grows like |{s.expr(f.variable)} − {s.decimal(f.end)}|^(−"
                            f"{s.decimal(f.order)}) at an end of the path (not integrable)"),
        "cs": lambda f, s: (f"integrand roste jako |{s.expr(f.variable)} − {s.decimal(f.end)}|^(−"
                            f"{s.decimal(f.order)}) u konce integrační cesty (není integrovatelný)")},
    Code.TERMS_GROW: {
        "en": lambda f, s: (f"the terms of the series in {s.expr(f.variable)} grow (|a(n+1)/a(n)| = "
                            f"{s.decimal(f.ratio100)} at n = 100, {s.decimal(f.ratio200)} at n = 200): it does not converge"),
        "cs": lambda f, s: (f"členy řady v {s.expr(f.variable)} rostou (|a(n+1)/a(n)| = {s.decimal(f.ratio100)} "
                            f"pro n = 100, {s.decimal(f.ratio200)} pro n = 200): řada nekonverguje")},
    Code.NO_LIMIT: {
        "en": lambda f, s: (f"the printed limit does not exist: as {s.expr(f.variable)} → {s.expr(f.point)} from the "
                            f"left it tends to {s.decimal(f.left)}, from the right to {s.decimal(f.right)}"),
        "cs": lambda f, s: (f"vytištěná limita neexistuje: pro {s.expr(f.variable)} → {s.expr(f.point)} zleva se "
                            f"blíží {s.decimal(f.left)}, zprava {s.decimal(f.right)}")},
    Code.UNDEFINED_TERM: {
        "en": lambda f, s: (f"the printed sum or product is undefined: its term at {s.expr(f.variable)} = "
                            f"{s.expr(f.index)} divides by zero"),
        "cs": lambda f, s: (f"vytištěný součet nebo součin není definován: jeho člen pro {s.expr(f.variable)} = "
                            f"{s.expr(f.index)} dělí nulou")},
    Code.DIMENSIONAL: {
        "en": lambda f, s: "dimensionally inconsistent" + _numbers_en(f, s),
        "cs": lambda f, s: "rozměrově nekonzistentní" + _numbers_cs(f, s)},
    Code.ROUNDS_OTHERWISE: {
        "en": lambda f, s: (f"the exact value {s.decimal(f.exact)} does not round to the printed "
                            f"{s.decimal(f.printed)} ({_places_en(f.places)})"),
        "cs": lambda f, s: (f"přesná hodnota {s.decimal(f.exact)} se nezaokrouhlí na vytištěné "
                            f"{s.decimal(f.printed)} ({_places_cs(f.places)})")},
    Code.ROUNDING_FREE: {
        "en": lambda f, s: (f"a printed rounding of a value that depends on {', '.join(map(s.expr, f.symbols))}: "
                            "only a number rounds"),
        "cs": lambda f, s: (f"vytištěné zaokrouhlení hodnoty, která závisí na {', '.join(map(s.expr, f.symbols))}: "
                            "zaokrouhlit lze jen číslo")},
    Code.ROUNDING_TIE: {
        "en": lambda f, s: (f"the exact value lies on the half of the last printed place of {s.decimal(f.printed)}: "
                            "either rounding is right"),
        "cs": lambda f, s: (f"přesná hodnota leží na polovině posledního vytištěného místa čísla {s.decimal(f.printed)}: "
                            "správné je obojí zaokrouhlení")},
    Code.ROUNDING_NO_VALUE: {
        "en": lambda f, s: f"the value printed as {s.decimal(f.printed)} could not be computed: " + s.text(f.error),
        "cs": lambda f, s: f"hodnotu vytištěnou jako {s.decimal(f.printed)} nelze spočítat: " + s.text(f.error)},
    Code.ROUNDING_UNDECIDED: {
        "en": lambda f, s: (f"no precision tried decides whether the value rounds to {s.decimal(f.printed)} "
                            f"({_places_en(f.places)})"),
        "cs": lambda f, s: (f"žádná vyzkoušená přesnost nerozhodne, zda se hodnota zaokrouhlí na {s.decimal(f.printed)} "
                            f"({_places_cs(f.places)})")},
    Code.NOTHING_TO_CHECK: {"en": lambda f, s: "nothing to check", "cs": lambda f, s: "není co ověřit"},
    Code.NO_DERIVATION: {
        "en": lambda f, s: "no derivation registered for this entry yet",
        "cs": lambda f, s: "pro tento vztah zatím není zapsáno odvození"},
    Code.DERIVATION_FAILED: {
        "en": lambda f, s: "derivation failed: " + s.text(f.error),
        "cs": lambda f, s: "odvození selhalo: " + s.text(f.error)},
    Code.CONDITION_NOT_EQUATION: {
        "en": lambda f, s: "a condition is an equation",
        "cs": lambda f, s: "podmínka musí být rovnice"},
    Code.EVALUATES_TO: {
        "en": lambda f, s: f"printed relation evaluates to {f.value}",
        "cs": lambda f, s: "vytištěný vztah se vyhodnotí jako " + ("pravdivý" if f.value == "True" else "nepravdivý")},
    Code.RELATION_COUNT: {
        "en": lambda f, s: f"printed has {f.printed} relation(s), derivation gives {f.derived}",
        "cs": lambda f, s: f"vytištěných vztahů je {f.printed}, odvození jich dává {f.derived}"},
    Code.CANNOT_SOLVE: {
        "en": lambda f, s: f"cannot solve the derived relation for {s.expr(f.unknown)}",
        "cs": lambda f, s: f"odvozený vztah nelze vyřešit vzhledem k {s.expr(f.unknown)}"},
    Code.NOT_EQUATION_FOR: {
        "en": lambda f, s: f"the printed entry is not an equation for {s.expr(f.unknown)}",
        "cs": lambda f, s: f"vytištěný vztah není rovnicí pro {s.expr(f.unknown)}"},
    Code.SOLVE_TIMEOUT: {
        "en": lambda f, s: (f"cannot set up the comparison: sympy did not solve the relation within "
                            f"{s.num(f.seconds)} s"),
        "cs": lambda f, s: f"srovnání nelze sestavit: sympy vztah nevyřešil do {s.num(f.seconds)} s"},
    Code.SETUP_FAILED: {
        "en": lambda f, s: ("cannot set up the comparison: " + s.text(f.error))[:300],
        "cs": lambda f, s: "srovnání nelze sestavit: " + s.text(f.error)},
    Code.NO_RANGE: {
        "en": lambda f, s: f"no range declared for symbol {s.expr(f.symbol)}",
        "cs": lambda f, s: f"symbol {s.expr(f.symbol)} nemá deklarovaný obor"},
    Code.TOO_FEW_POINTS: {
        "en": lambda f, s: "the domain's constraints leave too few points",
        "cs": lambda f, s: "podmínky oboru ponechávají příliš málo bodů"},
    Code.TOO_FEW_EVALUATED: {
        "en": lambda f, s: f"only {f.n} of {f.of} points could be evaluated"
        + (f" ({s.text(f.error)})" if f.error else ""),
        "cs": lambda f, s: f"vyčíslit šlo jen {f.n} z {f.of} bodů" + (f" ({s.text(f.error)})" if f.error else "")},
    Code.UNSTABLE: {
        "en": lambda f, s: f"{f.n} of {f.of} points unstable under the precision ladder",
        "cs": lambda f, s: f"{f.n} z {f.of} bodů není stálých při zvyšování přesnosti"},
    Code.PROOF_CONTRADICTED: {
        "en": lambda f, s: f"sympy proves zero but numerics say {f.verdict}: " + f.sub("numbers"),
        "cs": lambda f, s: f"sympy dokazuje nulu, numerika však říká {_VERDICT_CS.get(f.verdict, f.verdict)}: "
                           + f.sub("numbers")},
    Code.DIMENSIONS_DISAGREE: {
        "en": lambda f, s: ("the numbers verify (" + f.sub("numbers") + ") but the dimension check says "
                            + f.sub("finding") + ": the check is the suspect, the entry is left undecided"),
        "cs": lambda f, s: ("čísla vztah potvrzují (" + f.sub("numbers") + "), rozměrová kontrola však hlásí "
                            + f.sub("finding") + ": podezřelá je kontrola, vztah zůstává nerozhodnut")},
    Code.STAGE_FAILED: {
        "en": lambda f, s: f"the {f.stage} failed: " + s.text(f.error),
        "cs": lambda f, s: f"selhal krok „{_STAGE_CS.get(f.stage, f.stage)}“: " + s.text(f.error)},
    Code.OUT_OF_TIME: {
        "en": lambda f, s: (f"the {f.stage} ran out of its {s.num(f.seconds, 'g')} s of "
                            + ("CPU time" if f.clock == "cpu" else "time") + " (raise --timeout to allow more)"),
        "cs": lambda f, s: (f"krok „{_STAGE_CS.get(f.stage, f.stage)}“ vyčerpal svých {s.num(f.seconds, 'g')} s "
                            + ("procesorového času" if f.clock == "cpu" else "času") + " (více dovolí --timeout)")},
    Code.NONSMOOTH_QUADRATURE: {
        "en": lambda f, s: (f"{f.count} of {f.points} points differ, but the integrand holds {s.text(f.function)} (a jump "
                            "or a kink the quadrature is good to a few digits across) and no ball certifies it"),
        "cs": lambda f, s: (f"{f.count} z {f.points} bodů se liší, integrand však obsahuje {s.text(f.function)} (skok "
                            "nebo zlom, přes který je kvadratura přesná jen na několik číslic) a intervalová "
                            "aritmetika rozdíl nepotvrdila")},
    Code.NO_NUMERIC_FORM: {
        "en": lambda f, s: f"no numeric evaluation of {s.text(f.function)}",
        "cs": lambda f, s: f"funkci {s.text(f.function)} nelze numericky vyčíslit"},
    Code.ONE_POINT_DOMAIN: {
        "en": lambda f, s: f"the range of {s.expr(f.symbol)} is a single point: agreement there proves nothing",
        "cs": lambda f, s: f"obor symbolu {s.expr(f.symbol)} je jediný bod: shoda v něm nic nedokazuje"},
    Code.CONDITION_UNSOLVED: {
        "en": lambda f, s: (f"the condition could be solved for {s.expr(f.unknown)} at only {f.count} points: "
                            "too few where it holds"),
        "cs": lambda f, s: (f"podmínku šlo vyřešit vzhledem k {s.expr(f.unknown)} jen v {f.count} bodech: "
                            "příliš málo bodů, kde platí")},
    Code.CONDITION_UNKNOWN: {
        "en": lambda f, s: "an implicit condition in no symbol: nothing to solve it for",
        "cs": lambda f, s: "implicitní podmínka bez symbolu: není podle čeho ji řešit"},
    Code.CONDITIONS_NOT_ELIMINATING: {
        "en": lambda f, s: (f"several conditions that, put in, leave {', '.join(map(s.expr, f.symbols))}: "
                            "write each as a symbol's value (x = …) or state one condition"),
        "cs": lambda f, s: (f"několik podmínek, po jejichž dosazení zůstává {', '.join(map(s.expr, f.symbols))}: "
                            "zapište každou jako hodnotu symbolu (x = …), nebo uveďte jedinou podmínku")},
    Code.ASYMPTOTIC_WITHOUT_LIMIT: {
        "en": lambda f, s: "an asymptotic form (an O-term) without a stated limit: nothing to evaluate",
        "cs": lambda f, s: "asymptotický tvar (člen O) bez udané limity: není co vyčíslit"},
    Code.NOTATION_ONLY: {
        "en": lambda f, s: "notation only: the entry states no relation",
        "cs": lambda f, s: "pouze označení: záznam neuvádí žádný vztah"},
    Code.LIMIT_UNDECIDED: {
        "en": lambda f, s: (f"neither sympy nor a sequence on the precision ladder decides the limit "
                            f"{s.expr(f.variable)} → {s.expr(f.point)}"),
        "cs": lambda f, s: (f"limitu {s.expr(f.variable)} → {s.expr(f.point)} nerozhodne sympy ani posloupnost "
                            "při zvyšování přesnosti")},
    Code.DIM_ADDS: {
        "en": lambda f, s: f"adds {s.dim(f.first)} to {s.dim(f.other)} in {s.expr(f.sum)}: term {s.expr(f.term)}",
        "cs": lambda f, s: f"sčítá {s.dim(f.first)} s {s.dim(f.other)} v {s.expr(f.sum)}: člen {s.expr(f.term)}"},
    Code.DIM_EXPONENT: {
        "en": lambda f, s: f"exponent with dimension in {s.expr(f.power)}",
        "cs": lambda f, s: f"exponent s rozměrem v {s.expr(f.power)}"},
    Code.DIM_SYMBOLIC_POWER: {
        "en": lambda f, s: f"symbolic power of a dimensional quantity in {s.expr(f.power)}",
        "cs": lambda f, s: f"obecná mocnina rozměrové veličiny v {s.expr(f.power)}"},
    Code.DIM_ARGUMENT: {
        "en": lambda f, s: f"{f.function} of {s.dim(f.dimension)} argument {s.expr(f.argument)}",
        "cs": lambda f, s: f"{f.function} argumentu {s.expr(f.argument)} s rozměrem {s.dim(f.dimension)}"},
    Code.DIM_LIMIT: {
        "en": lambda f, s: (f"limit {s.expr(f.limit)} {s.dim(f.dimension)} of d{f.variable} "
                            f"{s.dim(f.variable_dimension)}"),
        "cs": lambda f, s: (f"mez {s.expr(f.limit)} {s.dim(f.dimension)} integrálu podle {f.variable} "
                            f"{s.dim(f.variable_dimension)}")},
    Code.DIM_SIDES: {
        "en": lambda f, s: f"left side {s.dim(f.left)}, right side {s.dim(f.right)}",
        "cs": lambda f, s: f"levá strana {s.dim(f.left)}, pravá strana {s.dim(f.right)}"},
    Code.DIM_RELATION_INSIDE: {
        "en": lambda f, s: "relation inside an expression",
        "cs": lambda f, s: "vztah uvnitř výrazu"},
    Code.DIM_UNDECLARED_SYMBOL: {
        "en": lambda f, s: f"no dimension declared for symbol {s.expr(f.symbol)}",
        "cs": lambda f, s: f"symbol {s.expr(f.symbol)} nemá deklarovaný rozměr"},
    Code.DIM_UNDECLARED: {
        "en": lambda f, s: f"no dimension declared for {s.expr(f.expression)}",
        "cs": lambda f, s: f"{s.expr(f.expression)} nemá deklarovaný rozměr"},
    Code.DIM_CANNOT: {
        "en": lambda f, s: f"cannot take the dimension of {s.expr(f.expression)}",
        "cs": lambda f, s: f"rozměr výrazu {s.expr(f.expression)} nelze určit"},
    Code.ERRATUM_NOT_REFUTED: {
        "en": lambda f, s: f"the printed form is {f.verdict}, not refuted: the registered erratum does not stand",
        "cs": lambda f, s: (f"vytištěný tvar je {_VERDICT_CS.get(f.verdict, f.verdict)}, nikoli vyvrácen: "
                            "zapsaná tisková chyba neplatí")},
    Code.CORRECTION_NOT_VERIFIED: {
        "en": lambda f, s: f"the corrected form is {f.verdict}: " + f.sub("reason"),
        "cs": lambda f, s: f"opravený tvar je {_VERDICT_CS.get(f.verdict, f.verdict)}: " + f.sub("reason")},
    Code.CLEARED_NOT_VERIFIED: {
        "en": lambda f, s: f"cleared suspect is {f.verdict}",
        "cs": lambda f, s: f"očištěné podezření je {_VERDICT_CS.get(f.verdict, f.verdict)}"},
    Code.UNEXPECTED_VERDICT: {
        "en": lambda f, s: f"{f.verdict}: " + f.sub("reason"),
        "cs": lambda f, s: f"{_VERDICT_CS.get(f.verdict, f.verdict)}: " + f.sub("reason")},
    Code.NO_DERIVATION_PROBLEM: {"en": lambda f, s: "no derivation", "cs": lambda f, s: "chybí odvození"},
    Code.USES_MISMATCH: {
        "en": lambda f, s: (f"the derivation declares uses=({', '.join(f.declared)}) but used "
                            f"({', '.join(f.used) or 'nothing'}): the report cites what it used"),
        "cs": lambda f, s: (f"odvození uvádí uses=({', '.join(f.declared)}), ale použilo "
                            f"({', '.join(f.used) or 'nic'}): zpráva cituje, co použilo")},
    Code.Q_VALUE: {"en": lambda f, s: "value", "cs": lambda f, s: "hodnota"},
    Code.Q_RESIDUAL: {"en": lambda f, s: "lhs - rhs on the derived solution",
                      "cs": lambda f, s: "rozdíl stran na odvozeném řešení"},
    Code.Q_EXPRESSION: {"en": lambda f, s: "expression on the derived solution",
                        "cs": lambda f, s: "výraz na odvozeném řešení"},
    Code.Q_ROUNDING: {"en": lambda f, s: "the printed decimal and the exact value",
                      "cs": lambda f, s: "vytištěné desetinné číslo a přesná hodnota"},
    Code.Q_ANTIDERIVATIVE: {
        "en": lambda f, s: f"the derivative in {s.expr(f.variable)} of the printed antiderivative, and the integrand",
        "cs": lambda f, s: f"derivace vytištěné primitivní funkce podle {s.expr(f.variable)} a integrand"},
    Code.Q_UNDER_CONDITION: {"en": lambda f, s: f"{s.expr(f.quantity)} under the condition",
                             "cs": lambda f, s: f"{s.expr(f.quantity)} při dané podmínce"},
    Code.Q_PRINTED_RESIDUAL: {
        "en": lambda f, s: f"printed lhs - rhs where {s.expr(f.unknown)} is derived",
        "cs": lambda f, s: f"rozdíl stran vytištěného vztahu, kde {s.expr(f.unknown)} je odvozeno"},
    Code.Q_ROUNDING_WINDOW: {
        "en": lambda f, s: "the distance from the printed formula and the most its rounded decimals allow",
        "cs": lambda f, s: "odchylka od vytištěného vzorce a nejvíc, co dovolí jeho zaokrouhlená čísla"},
    Code.Q_DERIVED_RESIDUAL: {
        "en": lambda f, s: f"derived lhs - rhs where {s.expr(f.unknown)} is printed",
        "cs": lambda f, s: f"rozdíl stran odvozeného vztahu, kde {s.expr(f.unknown)} je vytištěno"},
    Code.Q_UNKNOWN: {"en": lambda f, s: s.expr(f.unknown), "cs": lambda f, s: s.expr(f.unknown)},
    Code.Q_DIMENSIONS: {"en": lambda f, s: "dimensions", "cs": lambda f, s: "rozměry"},
    Code.ORDER_HOLDS: {
        "en": lambda f, s: (f"|lhs − rhs| / |O-term| stays bounded as {s.expr(f.variable)} → {s.expr(f.point)} "
                            f"({f.steps} steps, at {f.n} points)"),
        "cs": lambda f, s: (f"|levá − pravá| / |člen O| zůstává omezený pro {s.expr(f.variable)} → {s.expr(f.point)} "
                            f"({f.steps} kroků, v {f.n} bodech)")},
    Code.ORDER_GROWS: {
        "en": lambda f, s: (f"|lhs − rhs| / |O-term| grows as {s.expr(f.variable)} → {s.expr(f.point)} "
                            f"(at least like the power {s.num(f.rate, '.3g')} of the inverse distance)"),
        "cs": lambda f, s: (f"|levá − pravá| / |člen O| roste pro {s.expr(f.variable)} → {s.expr(f.point)} "
                            f"(nejméně jako mocnina {s.num(f.rate, '.3g')} převrácené vzdálenosti)")},
    Code.BLOWS_UP: {
        "en": lambda f, s: f"grows without bound as {s.expr(f.variable)} → {s.expr(f.point)} (at {f.n} points)",
        "cs": lambda f, s: f"roste nade všechny meze pro {s.expr(f.variable)} → {s.expr(f.point)} (v {f.n} bodech)"},
    Code.STAYS_BOUNDED: {
        "en": lambda f, s: f"stays bounded as {s.expr(f.variable)} → {s.expr(f.point)}, printed infinite",
        "cs": lambda f, s: f"zůstává omezená pro {s.expr(f.variable)} → {s.expr(f.point)}, vytištěno nekonečno"},
    Code.Q_ORDER_RATIO: {
        "en": lambda f, s: f"|lhs − rhs| / |O-term| as {s.expr(f.variable)} → {s.expr(f.point)}",
        "cs": lambda f, s: f"|levá − pravá| / |člen O| pro {s.expr(f.variable)} → {s.expr(f.point)}"},
    Code.Q_SIDES: {"en": lambda f, s: "the left and the right side", "cs": lambda f, s: "levá a pravá strana"},
    Code.Q_LESSER_GREATER: {"en": lambda f, s: "the side printed lesser and the side printed greater",
                            "cs": lambda f, s: "strana vytištěná jako menší a strana vytištěná jako větší"},
    Code.DEFINES: {
        "en": lambda f, s: (f"defines {', '.join(s.expr(x) for x in f.symbols)}: notation, nothing to check "
                            "(the entries that use it check it)"),
        "cs": lambda f, s: (f"definuje {', '.join(s.expr(x) for x in f.symbols)}: označení, není co ověřovat "
                            "(ověřují je záznamy, které je používají)")},
    Code.NOT_EQUAL_ONLY: {
        "en": lambda f, s: "a printed inequation a ≠ b: true almost everywhere, nothing to check",
        "cs": lambda f, s: "vytištěná nerovnost a ≠ b: platí skoro všude, není co ověřovat"},
}.items()})

_STAGE_CS = MappingProxyType({"derivation": "odvození", "comparison": "srovnání", "compilation": "překlad",
                              "evaluation": "vyčíslení", "certification": "certifikace", "proof": "důkaz",
                              "dimension check": "rozměrová kontrola", "check": "ověření",
                              "condition": "podmínka"})


def render(reason: Reason | None, lang: str = "en", style=None) -> str:
    """``reason`` as a sentence in ``lang`` ('' for None), its fields shown by ``style``
    (default :class:`Plain`)."""
    if reason is None:
        return ""
    style = style if style is not None else Plain(lang)
    words = WORDING[reason.code]
    template = words.get(lang) or words["en"]
    return template(_Fields(reason, lang, style), style)
