"""The fixed prose of the reports and handouts, in English and Czech, as LaTeX.

Everything a reader sees that is not taken from the registry lives here: titles, section
introductions, the sentences that connect one step to the next, and the labels of the report.
The Czech is written for a student reading the Czech originals; it keeps their notation
(ϱ, ψ, φ, κ, β, Ω) and their terms (moment rychlosti, průvodič, mez aperiodického pohybu).
Czech one-letter prepositions are tied to the next word with ``~`` as Czech typography asks.
"""

from __future__ import annotations

LANGS = ("en", "cs")

#: Per text: title, subtitle of the report and of the handout, and the handout's introduction.
TEXTS = {
    "brepta1953": {
        "en": {
            "title": r"R.~Brepta (1953): Motion of a point in a resisting medium --- quasicentral motion",
            "report": "Derivation and verification report",
            "handout": "A handout for students",
            "intro": (
                r"A point of mass $m$ is pulled towards a fixed centre by a central force $S$ and "
                r"slowed down by the drag $R$ of the medium.  Brepta first derives general laws for "
                r"this \emph{quasicentral} motion, then applies them to the spherical pendulum at small "
                r"swings: without drag, with the linear drag $R = 2\kappa m v$ and with the quadratic "
                r"drag $R = m\beta v^2$.  Every equation below was derived again with sympy and compared "
                r"with the print; where the print is wrong, the corrected form is shown and the printed "
                r"one is quoted next to it.  Exercises are collected at the end, followed by their solutions."
            ),
        },
        "cs": {
            "title": r"R.~Brepta (1953): Pohyb bodu v~odporujícím prostředí --- quasicentrální pohyb",
            "report": "Zpráva o~odvození a~ověření",
            "handout": "Studijní text",
            "intro": (
                r"Na hmotný bod o~hmotnosti $m$ působí centrální síla $S$, která jej přitahuje "
                r"k~pevnému středu, a~odpor prostředí $R$, který jej brzdí.  Brepta nejprve odvodí "
                r"obecné zákony takového \emph{quasicentrálního} pohybu a~potom je použije na sférické "
                r"kyvadlo při malých rozkyvech: bez odporu, s~lineárním odporem $R = 2\kappa m v$ "
                r"a~s~kvadratickým odporem $R = m\beta v^2$.  Každý vztah jsme znovu odvodili "
                r"v~programu sympy a~porovnali s~tiskem.  Kde je v~tisku chyba, uvádíme opravený tvar "
                r"a~vytištěnou podobu připojujeme.  Na konci najdete cvičení a~za nimi jejich řešení."
            ),
        },
    },
    "pendulum": {
        "en": {
            "title": r"The exact period of the simple pendulum, eqs.~(49)--(66)",
            "report": "Derivation and verification report",
            "handout": "A handout for students",
            "intro": (
                r"The period of a simple pendulum of length $l$ does not depend on the amplitude only "
                r"as long as the swings are small.  The text derives the period for any initial "
                r"deflection $\varphi_0$: from the conservation of energy, by separating the variables, "
                r"through the substitution $\sin\frac{\varphi}{2} = \sin\frac{\varphi_0}{2}\sin\psi$ "
                r"that leads to the complete elliptic integral of the first kind, and finally by a "
                r"series in $\sin^2\frac{\varphi_0}{2}$.  Every equation was derived again with sympy "
                r"and compared with the print; corrected forms are shown where the print is wrong."
            ),
        },
        "cs": {
            "title": r"Přesné řešení matematického kyvadla, rovnice (49)--(66)",
            "report": "Zpráva o~odvození a~ověření",
            "handout": "Studijní text",
            "intro": (
                r"Perioda matematického kyvadla délky $l$ nezávisí na výchylce jen pro malé kyvy.  "
                r"Text odvozuje periodu pro libovolnou počáteční výchylku $\varphi_0$: ze zákona "
                r"zachování mechanické energie, separací proměnných, substitucí "
                r"$\sin\frac{\varphi}{2} = \sin\frac{\varphi_0}{2}\sin\psi$, která vede na úplný "
                r"eliptický integrál prvního druhu, a~nakonec rozvojem v~řadu podle "
                r"$\sin^2\frac{\varphi_0}{2}$.  Každý vztah jsme znovu odvodili v~programu sympy "
                r"a~porovnali s~tiskem; kde je tisk chybný, uvádíme opravený tvar."
            ),
        },
    },
}

#: Per (text, section): the section's title and a short introduction for the handout.  The
#: Czech titles are the printed ones.
SECTIONS = {
    ("brepta1953", "2"): {
        "en": ("General relations", (
            r"We write Newton's law in the polar coordinates $\varrho$, $\psi$.  The equation across "
            r"the radius vector does not contain the central force $S$; it gives a law for the "
            r"angular momentum $\varrho^2\dot\psi$ that holds whatever the law of the central force.  "
            r"For the linear drag the angular momentum decays exponentially in time, for the "
            r"quadratic drag exponentially in the arc length.")),
        "cs": ("Obecné závislosti", (
            r"Pohybové rovnice napíšeme v~polárních souřadnicích $\varrho$, $\psi$.  Rovnice ve směru "
            r"kolmém k~průvodiči neobsahuje centrální sílu $S$; plyne z~ní zákon pro moment "
            r"rychlosti $\varrho^2\dot\psi$, který platí pro libovolný zákon centrální síly.  Při "
            r"lineárním odporu moment rychlosti klesá exponenciálně s~časem, při kvadratickém "
            r"odporu exponenciálně s~dráhou.")),
    },
    ("brepta1953", "3"): {
        "en": ("The spherical pendulum at small swings without drag", (
            r"The pendulum of length $l$ is described by the angle $\varphi$ between the thread and "
            r"the vertical and by the angle $\psi$ of the pendulum's plane.  For small swings we put "
            r"$\sin\varphi \doteq \varphi$ and $\cos\varphi \doteq 1$.  Projected onto the tangent "
            r"plane, the motion is a plane motion under a central force proportional to the "
            r"distance: an ellipse, run through in the period $T = 2\pi\sqrt{l/g}$.")),
        "cs": ("Sférické kyvadlo při malých rozkyvech v~neodporujícím prostředí", (
            r"Kyvadlo délky $l$ popíšeme úhlem $\varphi$ mezi vláknem a~svislicí a~úhlem $\psi$, "
            r"který udává polohu roviny kyvadla.  Pro malé výchylky klademe "
            r"$\sin\varphi \doteq \varphi$ a~$\cos\varphi \doteq 1$.  Průmět pohybu do tečné roviny "
            r"je pak rovinný pohyb pod centrální silou úměrnou vzdálenosti, tedy pohyb po elipse "
            r"s~periodou $T = 2\pi\sqrt{l/g}$.")),
    },
    ("brepta1953", "4"): {
        "en": (r"The spherical pendulum in a medium resisting with $R = 2\kappa m v$", (
            r"With the linear drag it pays to use Cartesian coordinates: the two equations of motion "
            r"separate into two damped oscillations with the same characteristic equation.  The "
            r"constants of integration follow from the initial position and from an initial velocity "
            r"perpendicular to the radius vector.  The limit of aperiodic motion, $\kappa = \Omega$, "
            r"is solved separately.")),
        "cs": (r"Sférické kyvadlo v~prostředí, které odporuje silou $R = 2\kappa m v$", (
            r"Při lineárním odporu je výhodné použít pravoúhlé souřadnice: obě pohybové rovnice se "
            r"rozpadnou na dvě rovnice tlumeného kmitání se stejnou charakteristickou rovnicí.  "
            r"Integrační konstanty určíme z~počáteční polohy a~z~počáteční rychlosti kolmé "
            r"k~průvodiči.  Zvlášť vyřešíme mez aperiodického pohybu, kdy $\kappa = \Omega$.")),
    },
    ("brepta1953", "5"): {
        "en": (r"The spherical pendulum in a medium resisting with $R = m\beta v^2$", (
            r"With the quadratic drag no second integral in closed form exists.  For a small "
            r"$\beta$ the velocities of the motion without drag (the ellipse) are put into the drag "
            r"force, and the resulting linear equations are solved by the variation of constants.  "
            r"The integrals that appear are reduced to the elliptic integrals $F(k, \zeta)$ and "
            r"$E(k, \zeta)$.  The conical pendulum, $R_0\Omega = v_0$, is a special case.")),
        "cs": (r"Sférické kyvadlo v~prostředí, které odporuje silou $R = m\beta v^2$", (
            r"Při kvadratickém odporu druhý integrál v~uzavřeném tvaru nenajdeme.  Pro malé $\beta$ "
            r"dosadíme do odporové síly rychlosti pohybu v~ideálním prostředí (po elipse) a~vzniklé "
            r"lineární rovnice řešíme metodou variace konstant.  Integrály, které přitom dostaneme, "
            r"převedeme na eliptické integrály $F(k, \zeta)$ a~$E(k, \zeta)$.  Zvláštním případem je "
            r"konické kyvadlo, kdy $R_0\Omega = v_0$.")),
    },
    ("pendulum", "exact-period"): {
        "en": ("The exact solution of the simple pendulum", (
            r"Energy conservation gives the angular velocity $\dot\varphi$ as a function of the angle.  "
            r"Separating the variables and integrating from $0$ to $\varphi_0$ gives a quarter of "
            r"the period.  The substitution (57) turns the integral into the complete elliptic "
            r"integral $K$, whose series gives the corrections to the period of small swings.")),
        "cs": ("Přesné řešení matematického kyvadla", (
            r"Ze zákona zachování energie vyjádříme úhlovou rychlost $\dot\varphi$ jako funkci úhlu.  "
            r"Separací proměnných a~integrací od $0$ do $\varphi_0$ dostaneme čtvrtinu periody.  "
            r"Substituce (57) převede integrál na úplný eliptický integrál $K$; jeho rozvoj v~řadu "
            r"dává opravy k~periodě malých kyvů.")),
    },
}

#: Kinds of errata, in Czech.
KINDS_CS = {
    "sign": "znaménko", "exponent": "exponent", "wrong variable": "záměna proměnné",
    "missing factor": "chybějící činitel", "limits of integration": "integrační meze",
    "range of validity": "obor platnosti", "OCR glyph": "chybně přepsaný znak",
    "derivative order": "řád derivace", "parenthesis": "závorky", "coefficient": "koeficient",
}

#: Captions of the figures that the texts lost, per language (any other figure that
#: quasicentral.figures offers is captioned by its own title).
FIGURE_CAPTIONS = {
    "en": {
        "fig7a": r"Fig.~7a: the trajectory under linear drag, $\kappa = 0.4$~1/s, $\Omega = \sqrt{10}$~1/s, $R_0 = 0.1$~m, $v_0 = 0.1$~m/s.",
        "fig7b": r"Fig.~7b: the same motion as the two damped oscillations $x(t)$ and $y(t)$.",
        "fig8": r"Fig.~8: the limit of aperiodic motion, $\kappa = \Omega = \sqrt{10}$~1/s, $R_0 = 0.1$~m, $v_0 = 0.1$~m/s.",
        "overdamped": r"The overdamped motion $\kappa = 2\Omega$ (not in the text).",
        "fig32": r"Fig.~32: the ratio $T/T_0$ against the amplitude $\varphi_0$, with partial sums of the series (66).",
    },
    "cs": {
        "fig7a": r"Obr.~7a: dráha při lineárním odporu, $\kappa = 0{,}4$~1/s, $\Omega = \sqrt{10}$~1/s, $R_0 = 0{,}1$~m, $v_0 = 0{,}1$~m/s.",
        "fig7b": r"Obr.~7b: týž pohyb jako dvě tlumené kmitavé složky $x(t)$ a~$y(t)$.",
        "fig8": r"Obr.~8: mez aperiodického pohybu, $\kappa = \Omega = \sqrt{10}$~1/s, $R_0 = 0{,}1$~m, $v_0 = 0{,}1$~m/s.",
        "overdamped": r"Přetlumený pohyb, $\kappa = 2\Omega$ (v~článku není).",
        "fig32": r"Obr.~32: poměr $T/T_0$ v~závislosti na výchylce $\varphi_0$ a~částečné součty řady (66).",
    },
}

#: Sentences and labels, per language.  ``{refs}`` is a list of equation references.
WORDS = {
    "en": {
        "and": "and",
        "start": "We start from",
        "states": ("The text continues with", "Next comes", "Further,"),
        "from_one": ("From {refs} we obtain", "From {refs} it follows that", "Then {refs} gives"),
        "from_many": ("Combining {refs} we obtain", "From {refs} together we get"),
        "erratum": (r"The text prints this equation with an error ({kind}); the corrected form is "
                    r"shown above.  As printed:"),
        "cleared": r"This step looks suspicious, but the check confirms it.",
        "unverified": r"This step has not been verified yet.",
        "exercises": "Exercises",
        "solutions": "Solutions",
        "figures": "Figures",
        "ex_derive": "Starting from {refs}, derive equation {ref}:",
        "ex_derive_one": "Starting from {refs}, derive equation {ref}:",
        "ex_derive_none": "Derive equation {ref}:",
        "ex_errata": "The text prints equation {ref} as follows.  Find the error and correct it.",
        "sol_step": "The step, as the derivation states it:",
        "sol_result": "The result sympy obtains:",
        "sol_corrected": "The correct form is",
        "sol_kind": "Kind of error: {kind}.",
        "sol_note": "Explanation:",
        "exercise": "Exercise",
        "figures_intro": (r"The figures of the text were lost in print; these are reproduced from the "
                          r"closed forms with the parameters its captions give."),
        "verified_by": (r"All equations of this handout were checked by \texttt{{quasicentral}}; the "
                        r"report \texttt{{{report}.tex}} gives every verdict and its evidence."),
        # report labels
        "summary": "Summary",
        "how_reached": "Verdicts reached",
        "entries": "entries",
        "printed": "As printed",
        "derived": "As re-derived",
        "verdict": "Verdict",
        "step": "Step",
        "uses": "Built on",
        "nothing": "nothing (a starting point)",
        "code": "Code",
        "note": "Note",
        "corrected": "Corrected",
        "errata": "Errata",
        "cleared_title": "Cleared suspects",
        "suspicion": "Suspicion",
        "evidence": "Evidence",
        "witness": "Witness",
        "versions": "Software used",
        "no_derivation": "No derivation is registered for this entry yet.",
        "derivation_failed": "The derivation failed:",
        "identity": r"the printed relation is checked as an identity (no model is needed)",
        "model": "The printed relation is checked on the derived model",
        "condition": "The quantity that must vanish under the printed condition",
        "status": {"verified": "verified", "erratum": "erratum", "cleared": "cleared suspect",
                   "unexpected": "unexpected"},
        "verdicts": {"verified": "verified", "refuted": "refuted", "inconclusive": "inconclusive"},
        "methods": {"symbolic": "symbolically", "numeric": "numerically", "certified": "with ball arithmetic",
                    "dimensional": "by dimensions", "none": "no method settled it"},
        "points": "{n} in-domain points at {digits} digits",
        "dimensions": "Dimensions: {d}.",
        "certified_yes": "certified by ball arithmetic",
        "certified_no": "not certified",
        "printed_value": "printed",
        "derived_value": "derived",
        "at": "at",
        "quantity": "quantity",
        "problems": "Problems",
        "corrected_form": "corrected form",
        "table_eq": "Eq.", "table_kind": "Kind", "table_printed": "Printed form",
        "table_corrected": "Corrected form", "table_witness": "Witness", "table_status": "Status",
        "none_found": "None.",
        "python": "Python",
        "report_intro": (r"Each equation of the text is listed in the order of the paper: as printed "
                         r"(the catalog's verbatim \LaTeX), as re-derived (sympy's result in the paper's "
                         r"notation), the verdict and how it was reached, and the step that produces it."),
        "figure_source": "Data",
    },
    "cs": {
        "and": "a",
        "start": "Vyjdeme ze vztahu",
        "states": ("Dále platí", "Text pokračuje vztahem", "Dále máme"),
        "from_one": ("Z~rovnice {refs} dostaneme", "Z~rovnice {refs} plyne", "Odtud podle {refs} vychází"),
        "from_many": ("Z~rovnic {refs} dostaneme", "Spojením rovnic {refs} dostaneme"),
        "erratum": (r"V~tisku je v~této rovnici chyba ({kind}); výše uvádíme opravený tvar.  "
                    r"Vytištěno bylo:"),
        "cleared": r"Tento krok vypadá podezřele, ověření však potvrdilo, že je správný.",
        "unverified": r"Tento krok zatím nebyl ověřen.",
        "exercises": "Cvičení",
        "solutions": "Řešení",
        "figures": "Obrázky",
        "ex_derive": "Z~rovnic {refs} odvoďte vztah {ref}:",
        "ex_derive_one": "Z~rovnice {refs} odvoďte vztah {ref}:",
        "ex_derive_none": "Odvoďte vztah {ref}:",
        "ex_errata": "Rovnice {ref} je v~textu vytištěna takto.  Najděte chybu a~opravte ji.",
        "sol_step": "Postup, jak jej popisuje odvození v~programu (anglicky):",
        "sol_result": "Výsledek, který dává sympy:",
        "sol_corrected": "Správný tvar je",
        "sol_kind": "Druh chyby: {kind}.",
        "sol_note": "Vysvětlení (anglicky):",
        "exercise": "Cvičení",
        "figures_intro": (r"Obrázky se v~tisku nedochovaly; zde jsou znovu sestrojeny z~odvozených "
                          r"vztahů s~parametry, které uvádějí jejich popisky."),
        "verified_by": (r"Všechny vztahy tohoto textu ověřil program \texttt{{quasicentral}}; zpráva "
                        r"\texttt{{{report}.tex}} uvádí každý verdikt i~jeho doklad."),
        "summary": "Přehled",
        "how_reached": "Způsob ověření",
        "entries": "vztahů",
        "printed": "Jak je vytištěno",
        "derived": "Znovu odvozeno",
        "verdict": "Verdikt",
        "step": "Krok",
        "uses": "Vychází z~rovnic",
        "nothing": "ničeho (výchozí vztah)",
        "code": "Kód",
        "note": "Poznámka",
        "corrected": "Opraveno",
        "errata": "Tiskové chyby",
        "cleared_title": "Vyvrácená podezření",
        "suspicion": "Podezření",
        "evidence": "Doklad",
        "witness": "Protipříklad",
        "versions": "Použitý software",
        "no_derivation": "Pro tento vztah zatím není zapsáno odvození.",
        "derivation_failed": "Odvození selhalo:",
        "identity": r"vytištěný vztah se ověřuje jako identita (bez modelu)",
        "model": "Vytištěný vztah se ověřuje na odvozeném modelu",
        "condition": "Veličina, která musí za vytištěné podmínky vymizet",
        "status": {"verified": "ověřeno", "erratum": "tisková chyba", "cleared": "vyvrácené podezření",
                   "unexpected": "neočekávaný výsledek"},
        "verdicts": {"verified": "ověřeno", "refuted": "vyvráceno", "inconclusive": "nerozhodnuto"},
        "methods": {"symbolic": "symbolicky", "numeric": "numericky", "certified": "intervalovou aritmetikou",
                    "dimensional": "rozměrovou analýzou", "none": "žádnou metodou"},
        "points": "v~{n} bodech oboru na {digits} platných číslic",
        "dimensions": "Rozměry: {d}.",
        "certified_yes": "potvrzeno intervalovou aritmetikou",
        "certified_no": "nepotvrzeno intervalovou aritmetikou",
        "printed_value": "vytištěno",
        "derived_value": "odvozeno",
        "at": "v~bodě",
        "quantity": "veličina",
        "problems": "Problémy",
        "corrected_form": "opravený tvar",
        "table_eq": "Rovnice", "table_kind": "Druh", "table_printed": "Vytištěno",
        "table_corrected": "Opraveno", "table_witness": "Protipříklad", "table_status": "Stav",
        "none_found": "Žádné.",
        "python": "Python",
        "report_intro": (r"Každý vztah textu uvádíme v~pořadí článku: jak je vytištěn (doslovný "
                         r"\LaTeX{} z~katalogu), jak jej znovu odvodil sympy (v~označení článku), "
                         r"verdikt a~způsob, jakým byl získán, a~krok odvození, který jej dává."),
        "figure_source": "Data",
    },
}


def join_refs(refs: list[str], lang: str) -> str:
    """'(1)', '(1) and (2)', '(1), (2) and (3)' in the language."""
    word = WORDS[lang]["and"]
    if len(refs) <= 1:
        return "".join(refs)
    return ", ".join(refs[:-1]) + f" {word}~" + refs[-1]
