"""The fixed prose of the reports and handouts, in English and Czech, as LaTeX.

Everything a reader sees that is not taken from the registry lives here: titles, section
introductions, the sentences that connect one step to the next, and the labels of the report.
The Czech is written for a student reading the Czech originals; it keeps their notation
(ϱ, ψ, φ, κ, β, Ω) and their terms (moment rychlosti, průvodič, mez aperiodického pohybu).
Czech one-letter prepositions are tied to the next word with ``~`` as Czech typography asks.
"""

from __future__ import annotations

from types import MappingProxyType
import tomllib
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

LANGS = ("en", "cs")

#: Kinds of errata, in Czech.
KINDS_CS = MappingProxyType({
    "sign": "znaménko", "exponent": "exponent", "wrong variable": "záměna proměnné",
    "missing factor": "chybějící činitel", "limits of integration": "integrační meze",
    "range of validity": "obor platnosti", "OCR glyph": "chybně přepsaný znak",
    "derivative order": "řád derivace", "parenthesis": "závorky", "coefficient": "koeficient",
    "rounding": "zaokrouhlení",
})

#: Sentences and labels, per language.  ``{refs}`` is a list of equation references.
WORDS = MappingProxyType({
    "en": {
        "and": "and",
        "report": "Derivation and verification report",
        "handout": "A handout for students",
        "teacher": "A handout for students: teacher's edition with solutions",
        "start": "We start from",
        "states": ("The text continues with", "Next comes", "Further,"),
        "from_one": ("From {refs} we obtain", "From {refs} it follows that", "Then {refs} gives"),
        "from_many": ("Combining {refs} we obtain", "From {refs} together we get"),
        "erratum": r"The text prints this equation with an error ({kind}); the corrected form is shown above.  As printed:",
        "cleared": r"This step looks suspicious, but the check confirms it.",
        "cleared_doubt": r"A reader may doubt this step --- {doubt} --- but it is right: the check confirms it.",
        "same_step": r"The same argument gives this relation.",
        "derive_exercise": r"How it follows is exercise~{ref}.",
        "erratum_exercise": r"This display contains an error, as the text prints it: find it in exercise~{ref}.",
        "unverified": r"This step has not been verified yet.",
        "exercises": "Exercises",
        "solutions": "Solutions",
        "figures": "Figures",
        "studies_intro": (r"The charts compare ways of computing the closed forms (the time they take "
                          r"against the digits they get right) and show where the text's approximations "
                          r"hold; they are drawn from the measurements of \emph{quasicentral}."),
        "ex_derive": "Starting from {refs}, derive equation {ref}.",
        "ex_derive_one": "Starting from {refs}, derive equation {ref}.",
        "ex_derive_none": "Derive equation {ref}.",
        "ex_errata": "The text prints equation {ref} as follows.  Find the error and correct it.",
        "sol_derive": "From {refs} we obtain",
        "sol_derive_none": "We obtain",
        "sol_corrected": "The correct form is",
        "sol_answer": r"Answer: {answer} (from {ref}; computed and checked by \emph{{quasicentral}}).",
        "sol_kind": "The error is of the kind: {kind}.",
        "exercise": "Exercise",
        "verified_by": (r"All equations of this handout were checked by \emph{{quasicentral}}; the "
                        r"report {report} gives every verdict and its evidence."),
        "teacher_note": r"This edition has the solutions of the exercises at its end; the students' edition has not.",
        # the steps, when no words of the text's own say more
        "step_from": {"solve": "It follows from {refs}.", "expression": "The expression follows from {refs}.",
                      "condition": "The condition follows from {refs}.",
                      "substitute": "It is checked by putting the solution {refs} into it.",
                      "identity": "It is checked as printed, with the definitions of {refs}."},
        "step_none": {"solve": "Derived directly, from none of the text's other equations.",
                      "expression": "Derived directly, from none of the text's other equations.",
                      "condition": "A condition under which the derived quantity must vanish.",
                      "substitute": "It is checked by putting the derived solution into it.",
                      "identity": "It is checked as printed, on its stated constraints."},
        # report
        "summary": "Summary",
        "checked": (r"This report checks the {n} equations of the text one by one.  Each was derived "
                    r"again with the computer algebra system sympy from the equations it rests on, and "
                    r"compared with the print: symbolically where sympy proves the difference zero, "
                    r"otherwise numerically at points of the physical domain at 30 and 60 digits; every "
                    r"error found is backed by a witness, a point at which the printed and the corrected "
                    r"form differ, certified by ball arithmetic where it could be "
                    r"(section~\ref{{sec:method}})."),
        "checked_mixed": (r"This report checks the {n} equations of the text one by one.  Each was derived "
                          r"again with the computer algebra system sympy from the equations it rests on, or, "
                          r"where the text states it as it stands, checked as printed on its stated "
                          r"constraints; then compared symbolically where sympy proves the difference zero, "
                          r"otherwise numerically at points of the physical domain at 30 and 60 digits; every "
                          r"error found is backed by a witness, a point at which the two forms differ, "
                          r"certified by ball arithmetic where it could be (section~\ref{{sec:method}})."),
        "checked_identity": (r"This report checks the {n} equations of the text one by one, each as printed on "
                             r"its stated constraints: symbolically where sympy proves its two sides equal, "
                             r"otherwise numerically at points drawn from its domain at 30 and 60 digits; every "
                             r"error found is backed by a witness, a point at which the two sides differ, "
                             r"certified by ball arithmetic where it could be (section~\ref{{sec:method}})."),
        "count_checked": "Equations checked",
        "section": "section",
        "count_verified": "verified",
        "count_errata": "errata",
        "count_causes": "{n} causes",
        "count_cause": "1 cause",
        "count_cleared": "suspects cleared",
        "count_inconclusive": "inconclusive or unexpected",
        "count_notation": "notation (nothing to check)",
        "how_reached": "of which",
        "errata_table": "The errata, printed and corrected side by side",
        "errata_more": r"Section~\ref{{sec:errata}} explains each cause once.",
        "found_title": "What was found",
        "col_cause": "Cause", "col_kind": "Kind", "col_displays": "Equations",
        "witness_in": "in {ref}: {values}",
        "found_more": (r"Section~\ref{{sec:errata}} explains each cause; appendix~\ref{{sec:sidebyside}} sets "
                       r"every erratum's printed and corrected form side by side."),
        "numbering": (r"Numbers in parentheses, such as {numbered}, are the text's own; numbers in brackets, "
                      r"such as {unnumbered}, name the displays the text leaves unnumbered, counted through "
                      r"the text."),
        "source_generic": (r"``Printed'' means the text as its catalog transcribes it (the LaTeX of each "
                           r"display and its reading in sympy); a slip of the transcription would show here as "
                           r"an erratum."),
        "software_note": "Software note: speed and accuracy of the computations",
        "software_note_intro": (r"This appendix is about the toolkit, not about the text: it measures how fast "
                                r"and how accurately the closed forms above can be computed, and where the "
                                r"text's approximations hold.  Nothing in it changes a verdict."),
        "printed": "As printed",
        "derived": "Re-derived",
        "same_as_printed": "the same relation as printed (sympy proves their difference zero).",
        "as_it_stands": "nothing to substitute: the printed relation is checked as it stands.",
        "verdict": "Verdict",
        "step": "Step",
        "uses": "from",
        "nothing": "a starting point of the text",
        "corrected": "Corrected",
        "errata": "Errata and their causes",
        "cause_affects": "Affects",
        "cause_kind": "Kind",
        "cause_of": "Cause",
        "cleared_title": "Cleared suspects",
        "cleared_yet_erratum": (r"the suspicion is unfounded; {ref} is nevertheless an erratum, for the cause "
                                r"given with it."),
        "suspicion": "Suspicion",
        "witness": "Witness",
        "versions": "Software used",
        "notation_title": "Notation",
        "notation_text": (r"The symbols of the text as it writes them, with what each stands for, its dimension "
                          r"(in the base dimensions L, T, M, $\Theta$, or in the units the text gives) and the range "
                          r"the checker draws it from, or what defines it."),
        "notation_symbol": "Symbol", "notation_meaning": "Meaning", "notation_dimension": "Dimension",
        "notation_where": "Range or definition",
        "notation_elliptic": (r"Elliptic integrals are written with the modulus $k$ as the text writes them, "
                              r"$F(k, \zeta) = \int_0^\zeta \frac{dt}{\sqrt{(1 - t^2)(1 - k^2 t^2)}}$; the checker "
                              r"evaluates them in the parameter $m = k^2$ (sympy's and mpmath's convention)."),
        "method": "Method and evidence",
        "method_text": (
            r"\emph{Symbolically}: sympy simplifies the difference of the two sides of the printed "
            r"relation, on the re-derived solution where the relation is checked on one, to zero.  "
            r"Every symbolic proof is cross-checked numerically at the same points as below; where "
            r"the numbers disagree with a proof, the numbers win.  \emph{Numerically}: both sides "
            r"are evaluated at points drawn from the ranges the text declares for its symbols "
            r"at 30 and then at 60 significant "
            r"digits; a relation is verified when they agree to at least 18 digits at every point.  "
            r"\emph{By ball arithmetic}: at the witness of an error, the two values are computed as "
            r"intervals that are guaranteed to contain them; the error is \emph{certified} when the "
            r"intervals do not overlap.  \emph{Dimensions}: every relation is also checked for "
            r"dimensional consistency; a relation whose sides have different dimensions is refuted, "
            r"unless the numbers verify it at every point: then the dimension check itself is the "
            r"suspect, and the relation is left undecided.  The table lists how each verdict was "
            r"reached."),
        "evidence_table": "Evidence for each equation",
        "col_eq": "Eq.", "col_status": "Status", "col_method": "Method", "col_evidence": "Evidence",
        "no_derivation": "No derivation is registered for this entry yet.",
        "derivation_failed": "The derivation failed with an error.",
        "model": "checked on the solution",
        "condition": "the quantity that must vanish under the printed condition:",
        "status": {"verified": "verified", "erratum": "erratum", "cleared": "cleared suspect",
                   "notation": "notation (nothing to check)", "unexpected": "unexpected"},
        "verdicts": {"verified": "verified", "refuted": "refuted", "inconclusive": "inconclusive"},
        "methods": {"symbolic": "symbolically", "numeric": "numerically", "certified": "with ball arithmetic",
                    "dimensional": "by dimensions", "none": "by no method"},
        "see_cause": r"see~\ref{{{label}}}",
        "certified_yes": "certified",
        "certified_no": "not certified",
        "at": "at",
        "vs": "printed {p}, correct {c}",
        "vs_sides": "left side {p}, right side {c}",
        "vs_ratio": "|lhs − rhs|/|O-term| {p} at the last step, {c} three steps before",
        "corrected_form": "The corrected form is",
        "table_eq": "Eq.", "table_printed": "Printed", "table_corrected": "Corrected",
        "table_witness": "Witness", "table_cert": "Cert.",
        "none_found": "None.",
        "report_intro": (r"Each equation follows in the order of the text: as printed, as re-derived, the "
                         r"verdict and the step that produces it."),
        "report_intro_identity": (r"Each equation follows in the order of the text: as printed and its verdict, "
                                  r"with the corrected form where the print is wrong."),
        "equation": "Equation",
        "relation": "Relation",
        "dims_ok": "",
        "dims_bad": "The dimensions do not match",
        "dims_add": r"the term {term} has the dimension {a}, the rest of the sum {b}",
        "dims_exp": r"the exponent {arg} has the dimension {a} instead of none",
        "dims_limit": r"the limit {lim} of the integral has the dimension {a}, the variable of integration {b}",
    },
    "cs": {
        "and": "a",
        "report": "Zpráva o~odvození a~ověření",
        "handout": "Studijní text",
        "teacher": "Studijní text: vydání pro učitele s~řešením",
        "start": "Vyjdeme ze vztahu",
        "states": ("Dále platí", "Text pokračuje vztahem", "Dále máme"),
        "from_one": ("Z~rovnice {refs} dostaneme", "Z~rovnice {refs} plyne", "Odtud podle {refs} vychází"),
        "from_many": ("Z~rovnic {refs} dostaneme", "Spojením rovnic {refs} dostaneme"),
        "erratum": r"V~tisku je v~této rovnici chyba ({kind}); výše uvádíme opravený tvar.  Vytištěno bylo:",
        "cleared": r"Tento krok vypadá podezřele, ověření však potvrdilo, že je správný.",
        "cleared_doubt": r"Tento krok může vzbudit pochybnost --- {doubt} --- je však správný, jak potvrdilo ověření.",
        "same_step": r"Stejnou úvahou dostaneme i~tento vztah.",
        "derive_exercise": r"Jak z~toho plyne, je úlohou cvičení~{ref}.",
        "erratum_exercise": r"Tato rovnice je v~textu vytištěna s~chybou: najděte ji ve cvičení~{ref}.",
        "unverified": r"Tento krok zatím nebyl ověřen.",
        "exercises": "Cvičení",
        "solutions": "Řešení",
        "figures": "Obrázky",
        "studies_intro": (r"Grafy porovnávají způsoby výpočtu uzavřených tvarů (potřebný čas proti počtu "
                          r"správných číslic) a~ukazují, kde platí přiblížení textu; jsou sestrojeny "
                          r"z~měření programu \emph{quasicentral}."),
        "ex_derive": "Z~rovnic {refs} odvoďte vztah {ref}.",
        "ex_derive_one": "Z~rovnice {refs} odvoďte vztah {ref}.",
        "ex_derive_none": "Odvoďte vztah {ref}.",
        "ex_errata": "Rovnice {ref} je v~textu vytištěna takto.  Najděte chybu a~opravte ji.",
        "sol_derive": "Z~{refs} dostaneme",
        "sol_derive_none": "Dostaneme",
        "sol_corrected": "Správný tvar je",
        "sol_answer": r"Výsledek: {answer} (z~{ref}; spočteno a~ověřeno programem \emph{{quasicentral}}).",
        "sol_kind": "Druh chyby: {kind}.",
        "exercise": "Cvičení",
        "verified_by": (r"Všechny vztahy tohoto textu ověřil program \emph{{quasicentral}}; zpráva "
                        r"{report} uvádí každý verdikt i~jeho doklad."),
        "teacher_note": r"Toto vydání má na konci řešení cvičení; vydání pro studenty je nemá.",
        "step_from": {"solve": "Vztah plyne z~{refs}.", "expression": "Výraz dostaneme z~{refs}.",
                      "condition": "Podmínka plyne z~{refs}.",
                      "substitute": "Vztah ověříme dosazením řešení {refs}.",
                      "identity": "Vztah ověříme tak, jak je vytištěn, s~definicemi z~{refs}."},
        "step_none": {"solve": "Odvozeno přímo, bez dalších rovnic textu.",
                      "expression": "Odvozeno přímo, bez dalších rovnic textu.",
                      "condition": "Podmínka, za níž musí odvozená veličina vymizet.",
                      "substitute": "Vztah ověříme dosazením odvozeného řešení.",
                      "identity": "Vztah ověříme tak, jak je vytištěn, na oboru, který text udává."},
        "summary": "Přehled",
        "checked": (r"Tato zpráva ověřuje jednu po druhé všech {n} rovnic textu.  Každou jsme znovu "
                    r"odvodili v~systému počítačové algebry sympy z~rovnic, na kterých stojí, a~porovnali "
                    r"s~tiskem: symbolicky, kde sympy dokázal, že rozdíl je nulový, jinak numericky "
                    r"v~bodech fyzikálního oboru na 30 a~60 platných číslic.  Každou nalezenou chybu "
                    r"dokládá protipříklad, bod, ve kterém se vytištěný a~opravený tvar liší, a~kde to šlo, "
                    r"je rozdíl potvrzen intervalovou aritmetikou (oddíl~\ref{{sec:method}})."),
        "checked_mixed": (r"Tato zpráva ověřuje jednu po druhé všech {n} rovnic textu.  Každou jsme znovu "
                          r"odvodili v~systému počítačové algebry sympy z~rovnic, na kterých stojí, nebo, kde ji "
                          r"text uvádí tak, jak stojí, ověřili tak, jak je vytištěna, na jejím uvedeném oboru; "
                          r"porovnání je symbolické, kde sympy dokáže, že rozdíl je nulový, jinak numerické "
                          r"v~bodech fyzikálního oboru na 30 a~60 platných číslic.  Každou nalezenou chybu "
                          r"dokládá protipříklad, bod, ve kterém se oba tvary liší, a~kde to šlo, je rozdíl "
                          r"potvrzen intervalovou aritmetikou (oddíl~\ref{{sec:method}})."),
        "checked_identity": (r"Tato zpráva ověřuje jednu po druhé všech {n} rovnic textu, každou tak, jak je "
                             r"vytištěna, na jejím uvedeném oboru: symbolicky, kde sympy dokáže, že se obě strany "
                             r"rovnají, jinak numericky v~bodech jejího oboru na 30 a~60 platných číslic; každou "
                             r"nalezenou chybu dokládá protipříklad, bod, ve kterém se obě strany liší, a~kde to "
                             r"šlo, je rozdíl potvrzen intervalovou aritmetikou (oddíl~\ref{{sec:method}})."),
        "count_checked": "Kontrolovaných rovnic",
        "section": "oddíl",
        "count_verified": "správně",
        "count_errata": "tiskových chyb",
        "count_causes": "příčin: {n}",
        "count_cause": "jedna příčina",
        "count_cleared": "vyvrácených podezření",
        "count_inconclusive": "nerozhodnutých nebo neočekávaných",
        "count_notation": "označení (není co ověřit)",
        "how_reached": "z~toho",
        "errata_table": "Chyby: vytištěný a~opravený tvar vedle sebe",
        "errata_more": r"Oddíl~\ref{{sec:errata}} vysvětluje každou příčinu jednou.",
        "found_title": "Co jsme našli",
        "col_cause": "Příčina", "col_kind": "Druh", "col_displays": "Rovnice",
        "witness_in": "v~{ref}: {values}",
        "found_more": (r"Oddíl~\ref{{sec:errata}} vysvětluje každou příčinu; příloha~\ref{{sec:sidebyside}} "
                       r"staví vedle sebe vytištěný a~opravený tvar každé chyby."),
        "numbering": (r"Čísla v~kulatých závorkách, např. {numbered}, jsou čísla textu; čísla v~hranatých "
                      r"závorkách, např. {unnumbered}, označují nečíslované rovnice textu, počítané od "
                      r"začátku textu."),
        "source_generic": (r"„Vytištěno“ znamená text tak, jak jej přepisuje jeho katalog (LaTeX každé "
                           r"rovnice a~její čtení v~programu sympy); chyba přepisu by se zde ukázala jako "
                           r"tisková chyba."),
        "software_note": "Poznámka o~programu: rychlost a~přesnost výpočtů",
        "software_note_intro": (r"Tato příloha se týká programu, ne textu: měří, jak rychle a~jak přesně lze "
                                r"spočítat uzavřené tvary uvedené výše a~kde platí přiblížení textu.  Na žádném "
                                r"verdiktu nic nemění."),
        "printed": "Vytištěno",
        "derived": "Znovu odvozeno",
        "same_as_printed": "týž vztah jako v~tisku (sympy dokázal, že jejich rozdíl je nulový).",
        "as_it_stands": "není co dosadit: vytištěný vztah se ověřuje tak, jak stojí.",
        "verdict": "Verdikt",
        "step": "Krok",
        "uses": "podle",
        "nothing": "výchozí vztah textu",
        "corrected": "Opraveno",
        "errata": "Chyby a~jejich příčiny",
        "cause_affects": "Týká se rovnic",
        "cause_kind": "Druh",
        "cause_of": "Příčina",
        "cleared_title": "Vyvrácená podezření",
        "cleared_yet_erratum": (r"podezření se nepotvrdilo; rovnice {ref} je přesto chybná, z~příčiny uvedené u~ní."),
        "suspicion": "Podezření",
        "witness": "Protipříklad",
        "versions": "Použitý software",
        "notation_title": "Označení",
        "notation_text": (r"Symboly textu tak, jak je píše, s~tím, co znamenají, s~jejich rozměrem (v~základních "
                          r"rozměrech L, T, M, $\Theta$ nebo v~jednotkách, které text uvádí) a~s~oborem, ze kterého "
                          r"je program vybírá, nebo s~tím, co je definuje."),
        "notation_symbol": "Symbol", "notation_meaning": "Význam", "notation_dimension": "Rozměr",
        "notation_where": "Obor nebo definice",
        "notation_elliptic": (r"Eliptické integrály píšeme s~modulem $k$ jako text, "
                              r"$F(k, \zeta) = \int_0^\zeta \frac{dt}{\sqrt{(1 - t^2)(1 - k^2 t^2)}}$; program je "
                              r"počítá v~parametru $m = k^2$ (jak je zvykem v~sympy a~mpmath)."),
        "method": "Metoda a~doklady",
        "method_text": (
            r"\emph{Symbolicky}: sympy zjednoduší rozdíl obou stran vytištěného vztahu na nulu (kde se "
            r"vztah ověřuje na odvozeném řešení, po dosazení tohoto řešení).  Každý symbolický důkaz "
            r"je navíc zkontrolován numericky ve stejných bodech jako níže; kdyby čísla důkazu "
            r"odporovala, platí čísla.  \emph{Numericky}: obě strany vyčíslíme v~bodech z~rozsahů, "
            r"které text svým symbolům určuje, na 30 "
            r"a~potom na 60 platných číslic; vztah je ověřen, shodují-li se v~každém bodě alespoň na "
            r"18 číslic.  \emph{Intervalovou aritmetikou}: v~protipříkladu chyby spočteme obě hodnoty "
            r"jako intervaly, které je zaručeně obsahují; chyba je \emph{potvrzena}, když se intervaly "
            r"nepřekrývají.  \emph{Rozměry}: u~každého vztahu kontrolujeme i~rozměry; vztah, jehož "
            r"strany mají různé rozměry, je vyvrácen, ledaže jej čísla ověří v~každém bodě: tehdy je "
            r"podezřelá sama kontrola rozměrů a~vztah zůstává nerozhodnut.  Tabulka uvádí, jak byl "
            r"získán každý verdikt."),
        "evidence_table": "Doklady pro jednotlivé rovnice",
        "col_eq": "Rovnice", "col_status": "Stav", "col_method": "Metoda", "col_evidence": "Doklad",
        "no_derivation": "Pro tento vztah zatím není zapsáno odvození.",
        "derivation_failed": "Odvození skončilo chybou.",
        "model": "ověřeno na řešení",
        "condition": "veličina, která musí za vytištěné podmínky vymizet:",
        "status": {"verified": "ověřeno", "erratum": "tisková chyba", "cleared": "vyvrácené podezření",
                   "notation": "označení (není co ověřit)", "unexpected": "neočekávaný výsledek"},
        "verdicts": {"verified": "ověřeno", "refuted": "vyvráceno", "inconclusive": "nerozhodnuto"},
        "methods": {"symbolic": "symbolicky", "numeric": "numericky", "certified": "intervalovou aritmetikou",
                    "dimensional": "rozměrovou analýzou", "none": "žádnou metodou"},
        "see_cause": r"viz~\ref{{{label}}}",
        "certified_yes": "potvrzeno",  # the method section's term; the witness sentences say it too
        "certified_no": "nepotvrzeno",
        "at": "v~bodě",
        "vs": "vytištěno {p}, správně {c}",
        "vs_sides": "levá strana {p}, pravá strana {c}",
        "vs_ratio": "|levá − pravá|/|člen O| {p} v posledním kroku, {c} o tři kroky dříve",
        "corrected_form": "Opravený tvar:",
        "table_eq": "Rovnice", "table_printed": "Vytištěno", "table_corrected": "Opraveno",
        "table_witness": "Protipříklad", "table_cert": "Potvrz.",
        "none_found": "Žádné.",
        "report_intro": (r"Rovnice následují v~pořadí textu: jak jsou vytištěny, jak jsme je znovu "
                         r"odvodili, verdikt a~krok, který je dává."),
        "report_intro_identity": (r"Rovnice následují v~pořadí textu: jak jsou vytištěny a~jejich verdikt, "
                                  r"u~chybných s~opraveným tvarem."),
        "equation": "Rovnice",
        "relation": "Vztah",
        "dims_ok": "",
        "dims_bad": "Rozměry nesouhlasí",
        "dims_add": r"člen {term} má rozměr {a}, zbytek součtu {b}",
        "dims_exp": r"exponent {arg} má rozměr {a}, a~ne žádný",
        "dims_limit": r"mez {lim} integrálu má rozměr {a}, integrační proměnná {b}",
    },
})


def join_refs(refs: list[str], lang: str) -> str:
    """'(1)', '(1) and (2)', '(1), (2) and (3)' in the language."""
    word = WORDS[lang]["and"]
    if len(refs) <= 1:
        return "".join(refs)
    return ", ".join(refs[:-1]) + f" {word}~" + refs[-1]


# --- a text's own prose: <text folder>/report.toml ----------------------------------------------
@dataclass(frozen=True)
class FigureProse:
    """A figure a text's documents show: its caption per language, whether it is a figure of
    the text (``role = "text"``, also in the handouts) or a chart of the toolkit's measurements
    (``"study"``, reports only), and whether it needs a landscape page of its own."""

    name: str
    caption: dict[str, str]
    role: str = "text"
    landscape: bool = False


@dataclass(frozen=True)
class EntryProse:
    """Words for one catalog entry, per language (each optional): a name for its heading, the
    text of its step (replacing the derivation's docstring), a note for its erratum."""

    name: dict[str, str] = field(default_factory=dict)
    step: dict[str, str] = field(default_factory=dict)
    erratum: dict[str, str] = field(default_factory=dict)


@dataclass(frozen=True)
class TextProse:
    """Everything a text's documents say about that text in particular (all LaTeX).

    Read from ``<text folder>/report.toml`` by :func:`load_prose`; a text without that file
    gets :func:`generic_prose` (no sentence about lost figures, no section introductions)."""

    id: str
    title: dict[str, str]
    intro: dict[str, str]
    figures_intro: dict[str, str]
    sections: dict[str, tuple[dict[str, str], dict[str, str]]]  # section -> (title, intro)
    figures: tuple[FigureProse, ...] = ()
    entries: dict[str, EntryProse] = field(default_factory=dict)
    author: str = ""
    #: the text's notation for the printer: symbol name -> LaTeX, function class name -> LaTeX
    symbols: dict[str, str] = field(default_factory=dict)
    functions: dict[str, str] = field(default_factory=dict)
    #: page 1's story in words (what was found, the substantive findings first) and what
    #: "printed" means for this text (its source: a transcription, an OCR …), per language
    abstract: dict[str, str] = field(default_factory=dict)
    source: dict[str, str] = field(default_factory=dict)
    #: the language the text is written in (its catalog's names and section titles)
    language: str = "en"

    def section_title(self, section: str, lang: str) -> str | None:
        got = self.sections.get(section)
        return got[0].get(lang) if got else None

    def section_intro(self, section: str, lang: str) -> str:
        got = self.sections.get(section)
        return got[1].get(lang, "") if got else ""

    def figure(self, name: str) -> FigureProse | None:
        return next((f for f in self.figures if f.name == name), None)

    def entry(self, eid: str) -> EntryProse:
        return self.entries.get(eid) or EntryProse()


#: What a text without report.toml is called and told with.
GENERIC = MappingProxyType({
    "intro": {
        "en": (r"Every equation of the text was checked against the print (derived again with sympy "
               r"where the text derives it); where the print is wrong, the corrected form is shown and "
               r"the printed one is quoted next to it."),
        "cs": (r"Každý vztah textu jsme ověřili proti tisku (a~kde jej text odvozuje, znovu odvodili "
               r"v~programu sympy); kde je v~tisku chyba, uvádíme opravený tvar a~vytištěnou podobu "
               r"připojujeme."),
    },
    "figures_intro": {
        "en": r"The figures are drawn from the derived closed forms and from the toolkit's measurements.",
        "cs": r"Obrázky jsou sestrojeny z~odvozených vztahů a~z~měření, která provedl program.",
    },
})


def _lang_table(raw, where: str) -> dict[str, str]:
    if raw is None:
        return {}
    if isinstance(raw, str):
        return {lang: raw for lang in LANGS}
    if not isinstance(raw, dict) or not all(isinstance(v, str) for v in raw.values()):
        raise ValueError(f"{where}: expected a table of strings per language (en, cs)")
    return {k: " ".join(v.split()) if "\n" not in v.strip() else v.strip() for k, v in raw.items()}


def generic_prose(text_id: str, title: str | None = None, language: str = "en", title_en: str = "") -> TextProse:
    """The prose of a text that brings no report.toml: its title (or its id) — plain text from
    text.toml, escaped and typeset in the text's language (Czech v, z are words), the English
    report's from ``title_en`` where the text gives one — and generic words."""
    from quasicentral.documents.prosetex import text

    name = text(title or text_id, lang=language)
    english = text(title_en, lang="en") if title_en else name
    return TextProse(text_id, {lang: english if lang == "en" else name for lang in LANGS}, dict(GENERIC["intro"]),
                     dict(GENERIC["figures_intro"]), {}, language=language)


def load_prose(root: Path, text_id: str | None = None, title: str | None = None, language: str = "en",
               title_en: str = "") -> TextProse:
    """The prose of the text whose folder is ``root``: ``root / "report.toml"`` when it exists,
    else :func:`generic_prose`.  ``text_id`` defaults to the folder's name."""
    text_id = text_id or Path(root).name
    path = Path(root) / REPORT_FILE
    if not path.is_file():
        return generic_prose(text_id, title, language, title_en)
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    where = f"{text_id}/{REPORT_FILE}"
    base = generic_prose(text_id, title, language, title_en)
    sections = {str(k): (_lang_table(v.get("title"), f"{where}: sections.{k}.title"),
                         _lang_table(v.get("intro"), f"{where}: sections.{k}.intro"))
                for k, v in data.get("sections", {}).items()}
    figures = tuple(FigureProse(str(k), _lang_table(v.get("caption"), f"{where}: figures.{k}"),
                                str(v.get("role", "text")), bool(v.get("landscape", False)))
                    for k, v in data.get("figures", {}).items())
    bad = [f.name for f in figures if f.role not in ("text", "study")]
    if bad:
        raise ValueError(f"{where}: figures {', '.join(bad)}: role is 'text' or 'study'")
    entries = {str(k): EntryProse(_lang_table(v.get("name"), f"{where}: entries.{k}.name"),
                                  _lang_table(v.get("step"), f"{where}: entries.{k}.step"),
                                  _lang_table(v.get("erratum"), f"{where}: entries.{k}.erratum"))
               for k, v in data.get("entries", {}).items()}
    return TextProse(
        text_id,
        _lang_table(data.get("title"), f"{where}: title") or base.title,
        _lang_table(data.get("intro"), f"{where}: intro") or base.intro,
        _lang_table(data.get("figures_intro"), f"{where}: figures_intro") or base.figures_intro,
        sections, figures, entries, str(data.get("meta", {}).get("author", "")),
        dict(data.get("notation", {}).get("symbols", {})), dict(data.get("notation", {}).get("functions", {})),
        _lang_table(data.get("abstract"), f"{where}: abstract"), _lang_table(data.get("source"), f"{where}: source"),
        language)


REPORT_FILE = "report.toml"


@lru_cache(maxsize=None)
def _prose_cached(root: str, text_id: str, title: str | None, language: str = "en", title_en: str = "") -> TextProse:
    return load_prose(Path(root), text_id, title, language, title_en)


def prose_of(text) -> TextProse:
    """The prose of ``text``: a Text-like object (``.root``, ``.id``, optionally ``.title``),
    or a folder."""
    if isinstance(text, Path):
        return _prose_cached(str(text), text.name, None)
    return _prose_cached(str(text.root), text.id, getattr(text, "title", None), getattr(text, "language", "en"),
                         getattr(text, "title_en", ""))
