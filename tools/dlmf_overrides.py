"""What the importer is told per label, with the reason: the hand fixes where the semantic
reader cannot read a formula from its LaTeX alone.

* ``options``: the reading's context (:class:`quasicentral.notation.semantic.Options`): a
  notation the prose defines (``Δ(θ)``), the limit of an O-term, generic letters;
* ``limit``: the passage a relation ``→`` or ``∼`` holds in;
* ``semantic``: semantic LaTeX written for this import from the current presentation LaTeX,
  where LaCASt's 2021 data has no line (a formula added or changed since);
* ``printed``: a transcription by hand, where the reader has no reading (operators, vectors);
* ``constraints`` (added), ``constraints_only`` (replacing), ``drop_constraints`` (LaCASt's
  constraint strings that are fragments or belong elsewhere), ``real``;
* ``kind``, ``name``, ``note``; ``split``: entries per sign where DLMF's upper and lower signs
  hold under different conditions ``{suffix: (relations, constraints)}``.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from quasicentral.notation.semantic import Limit


@dataclass(frozen=True)
class Override:
    reason: str
    options: dict = field(default_factory=dict)
    limit: Limit | None = None
    semantic: tuple[str, ...] | None = None
    printed: tuple[str, ...] | None = None
    constraints: tuple[str, ...] = ()
    constraints_only: tuple[str, ...] | None = None
    drop_constraints: tuple[str, ...] = ()
    real: tuple[str, ...] = ()
    defines: tuple[str, ...] = ()  # symbols the entry introduces (a hypothesis, an implicit definition)
    kind: str = ""
    name: str = ""
    note: str = ""
    split: dict | None = None      # {suffix: Part}
    expand: tuple[dict, ...] = ()  # bindings of generic letters, each read in turn
    whole: bool = False            # keep lines of differing constraints in one entry


@dataclass(frozen=True)
class Part:
    """One entry of a split formula: its semantic LaTeX (or transcription) and conditions."""

    semantic: tuple[str, ...] = ()
    printed: tuple[str, ...] = ()
    constraints: tuple[str, ...] = ()
    name: str = ""
    sign: int | None = None        # only the upper (+1) or lower (-1) signs of ± and ∓


RELEASE = "Release 1.2.4 of 2025-03-15"
CHAPTERS = {
    "19": {"id": "dlmf-19", "authors": ["B. C. Carlson"],
           "title": "NIST Digital Library of Mathematical Functions, Chapter 19: Elliptic Integrals",
           "citation": f"NIST Digital Library of Mathematical Functions, https://dlmf.nist.gov/19, {RELEASE} "
                       "(formulas only; read from the DLMF's semantic LaTeX)"},
    "22": {"id": "dlmf-22", "authors": ["W. P. Reinhardt", "P. L. Walker"],
           "title": "NIST Digital Library of Mathematical Functions, Chapter 22: Jacobian Elliptic Functions",
           "citation": f"NIST Digital Library of Mathematical Functions, https://dlmf.nist.gov/22, {RELEASE} "
                       "(formulas and Tables 22.4.1-22.5.4; read from the DLMF's semantic LaTeX)"},
}

#: LaCASt's labels of formulas the DLMF has renumbered since: old key → (new key, note).
MOVED = {
    "19.16.E3": ("19.23.E6_5", "was 19.16.3 in the DLMF LaCASt read"),
    "19.23.E7": ("19.16.E2_5", "was 19.23.7 in the DLMF LaCASt read"),
}

#: Per section: reading options, and "where" definitions its prose states, added to every
#: formula of the section that uses the symbol (an equation whose left side is a bare symbol
#: defines that symbol for the formula).
C_PHI = "Eq(c, csc(phi)**2)"
DELTA_PHI = "Eq(Delta, sqrt(1 - k**2*sin(phi)**2))"
AGM_SEQUENCES = {"sequences": {"a", "g", "c", "p", "Q", "varepsilon"}}
SECTIONS: dict[str, dict] = {
    "19.6": {"where": {"c": C_PHI, "Delta": DELTA_PHI}},
    "19.7": {"where": {"c": C_PHI}},
    "19.9": {"where": {"Delta": DELTA_PHI}},
    "19.11": {"options": {"defined": {"Delta": (("x",), r"\sqrt{1-k^{2}\sin^{2}@@{x}}")}}},
    "19.12": {"options": {"defined": {"d": (("x",), r"\digamma@{1+x}-\digamma@{\tfrac{1}{2}+x}")}}},
    "19.16": {"options": {"defined": {"s": (("u",), r"\sqrt{u+x}\sqrt{u+y}\sqrt{u+z}")}, "dimension": 3}},
    "19.18": {"options": {"dimension": 3, "operators": {"partial": "z"}}},
    "19.20": {"options": {"dimension": 3}},
    "19.23": {"options": {"dimension": 3}},
    "19.24": {"options": {"dimension": 3}},
    "19.25": {"where": {"c": C_PHI}},
    "19.30": {"where": {"c": C_PHI}},
}
#: Per chapter: the symbols DLMF's chapter fixes (K = K(k), q the nome …), added where used.
CHAPTER_WHERE = {
    "19": {},
    "22": {"K": "Eq(K, EllipticK(k))", "Kp": "Eq(Kp, EllipticKp(k))", "q": "Eq(q, EllipticNome(k))",
           "tau": "Eq(tau, I*EllipticKp(k)/EllipticK(k))"},
}


@dataclass(frozen=True)
class Convention:
    """What a chapter's notation section fixes for every formula (outside the sections it
    names): bounds on a symbol, symbols that are real."""

    reason: str
    bounds: dict = field(default_factory=dict)   # symbol -> constraints
    real: tuple[str, ...] = ()
    except_sections: tuple[str, ...] = ()


#: Per chapter: the domains its notation section (§19.1, §22.1) states once for all formulas.
CONVENTIONS: dict[str, Convention] = {
    "22": Convention(
        reason="§22.1: the modulus k is in [0, 1] except in §§22.3(iv), 22.17 and 22.19; x, y are real",
        bounds={"k": ("Gt(k, 0)", "Lt(k, 1)")}, real=("k", "x", "y"), except_sections=("22.17", "22.19")),
}
ZETA_Z = "Eq(zeta, pi*z/(2*K))"
LETTERS_SCDN = "scdn"
#: Neville's theta functions θ_s, θ_c, θ_d, θ_n of (z|τ) (DLMF §20.1), u = z/θ_3²(0|τ), in Jacobi's
#: θ_j(·, q); θ_1'(0, q) = θ_2 θ_3 θ_4 (0, q) (DLMF 20.4.6)
NEVILLE = {"s": "JacobiTheta3(0, q)**2*JacobiTheta1(u, q)/(JacobiTheta2(0, q)*JacobiTheta3(0, q)*JacobiTheta4(0, q))",
           "c": "JacobiTheta2(u, q)/JacobiTheta2(0, q)", "d": "JacobiTheta3(u, q)/JacobiTheta3(0, q)",
           "n": "JacobiTheta4(u, q)/JacobiTheta4(0, q)"}


def _perms(letters: str, names: str) -> tuple[dict, ...]:
    from itertools import permutations

    return tuple(dict(zip(names, p)) for p in permutations(letters, len(names)))


def O(var: str, point: str) -> dict:
    return {"order": (var, point)}


def upper_lower(upper: tuple[str, ...], lower: tuple[str, ...], semantic: tuple[str, ...] = (),
                printed_upper=(), printed_lower=()) -> dict:
    """Two entries where DLMF's upper signs hold under one condition and the lower under another."""
    return {"upper": Part(semantic=semantic, printed=printed_upper, constraints=upper, sign=1),
            "lower": Part(semantic=semantic, printed=printed_lower, constraints=lower, sign=-1)}


UNIT = "the reader has no reading of"
NEW = "not in LaCASt's data of 2021 (added to the DLMF since): semantic LaTeX written for this import from the presentation LaTeX"
CHANGED = "changed in the DLMF since LaCASt's data of 2021: semantic LaTeX written for this import from the current presentation LaTeX"

OVERRIDES: dict[str, Override] = {
    # --- 19.1: the notation
    "19.1.3": Override("the list of variables b_1, ..., b_n is read for n = 3", options={"dimension": 3},
                       note="n = 3"),
    # --- 19.2
    "19.2.8_1": Override(NEW, semantic=(
        r"\ccompellintKk@{k}=\int_{0}^{1}\frac{\diff{t}}{\sqrt{1-t^{2}}\sqrt{1-(1-k^{2})t^{2}}}",), note=NEW),
    "19.2.8_2": Override(NEW, semantic=(
        r"\ccompellintEk@{k}=\int_{0}^{1}\frac{\sqrt{1-(1-k^{2})t^{2}}}{\sqrt{1-t^{2}}}\diff{t}",), note=NEW),
    "19.2.9": Override(CHANGED + "; the cases are three entries", kind="identity", note=CHANGED, split={
        "principal": Part(semantic=(r"\ccompellintKk@{k}=\compellintKk@{k^{\prime}}",
                                    r"\ccompellintEk@{k}=\compellintEk@{k^{\prime}}"),
                          constraints=("Le(Abs(arg(k)), pi/2)",), name="K′ and E′ for |ph k| ≤ π/2"),
        "upper": Part(semantic=(r"\ccompellintKk@{k}=\compellintKk@{k^{\prime}}-2\iunit\compellintKk@{-k}",
                                r"\ccompellintEk@{k}=\compellintEk@{k^{\prime}}-2\iunit(\compellintKk@{-k}-\compellintEk@{-k})"),
                      constraints=("Lt(pi/2, arg(k))", "Lt(arg(k), pi)"), name="K′ and E′ for π/2 < ph k < π"),
        "lower": Part(semantic=(r"\ccompellintKk@{k}=\compellintKk@{k^{\prime}}+2\iunit\compellintKk@{-k}",
                                r"\ccompellintEk@{k}=\compellintEk@{k^{\prime}}+2\iunit(\compellintKk@{-k}-\compellintEk@{-k})"),
                      constraints=("Lt(pi/2, -arg(k))", "Lt(-arg(k), pi)"), name="K′ and E′ for −π < ph k < −π/2")}),
    "19.2.10": Override("m is an integer (the prose)", constraints=("Eq(m, floor(m))",), real=("m",)),
    "19.2.11_5": Override(NEW, semantic=(
        r"\Bulirschincellintel{1}@{x}{k_{c}}=\int_{0}^{\atan@@{x}}\frac{1}{\sqrt{\cos^{2}@@{\theta}+k_{c}^{2}\sin^{2}@@{\theta}}}\diff{\theta}",),
        note=NEW),
    # --- 19.5
    "19.5.4_1": Override(NEW, note=NEW, semantic=(
        r"\incellintFk@{\phi}{k}=\sum_{m=0}^{\infty}\frac{\Pochhammersym{\tfrac{1}{2}}{m}\sin^{2m+1}@@{\phi}}{(2m+1)m!}"
        r"\genhyperF{2}{1}@{m+\tfrac{1}{2},\tfrac{1}{2}}{m+\tfrac{3}{2}}{\sin^{2}@@{\phi}}k^{2m}"
        r"=\sin@@{\phi}\AppellF{1}@{\tfrac{1}{2}}{\tfrac{1}{2}}{\tfrac{1}{2}}{\tfrac{3}{2}}{\sin^{2}@@{\phi}}{k^{2}\sin^{2}@@{\phi}}",)),
    "19.5.4_2": Override(NEW, note=NEW, semantic=(
        r"\incellintEk@{\phi}{k}=\sum_{m=0}^{\infty}\frac{\Pochhammersym{-\tfrac{1}{2}}{m}\sin^{2m+1}@@{\phi}}{(2m+1)m!}"
        r"\genhyperF{2}{1}@{m+\tfrac{1}{2},\tfrac{1}{2}}{m+\tfrac{3}{2}}{\sin^{2}@@{\phi}}k^{2m}"
        r"=\sin@@{\phi}\AppellF{1}@{\tfrac{1}{2}}{\tfrac{1}{2}}{-\tfrac{1}{2}}{\tfrac{3}{2}}{\sin^{2}@@{\phi}}{k^{2}\sin^{2}@@{\phi}}",)),
    "19.5.4_3": Override(NEW, note=NEW, semantic=(
        r"\incellintPik@{\phi}{\alpha^{2}}{k}=\sum_{m=0}^{\infty}\frac{\Pochhammersym{\tfrac{1}{2}}{m}\sin^{2m+1}@@{\phi}}{(2m+1)m!}"
        r"\AppellF{1}@{m+\tfrac{1}{2}}{\tfrac{1}{2}}{1}{m+\tfrac{3}{2}}{\sin^{2}@@{\phi}}{\alpha^{2}\sin^{2}@@{\phi}}k^{2m}",)),
    "19.5.5": Override("q is the nome (19.5.5 itself, first member)", constraints=("Eq(r, k**2/16)",),
                       drop_constraints=(r"r=\frac{1}{16}k^{2}",)),
    "19.5.6": Override("q is the nome and λ is given by 19.5.7", constraints=(
        "Eq(lamda, (1 - sqrt(sqrt(1 - k**2)))/(2*(1 + sqrt(sqrt(1 - k**2)))))", "Eq(q, EllipticNome(k))")),
    "19.5.8": Override("q is the nome of k (19.5.5)", constraints=("Eq(q, EllipticNome(k))",)),
    "19.5.9": Override("q is the nome of k (19.5.5)", constraints=("Eq(q, EllipticNome(k))",)),
    "19.5.10": Override("k_m is a sequence (19.5.11, k_0 = k)", options={"sequences": {"k"}},
                        constraints=('Eq(Function("k")(0), k)',),
                        note="k_m read as the sequence Function(\"k\")(m) of 19.5.11 with k_0 = k"),
    "19.5.11": Override("k_m is a sequence", options={"sequences": {"k"}}, kind="definition",
                        note="k_m read as the sequence Function(\"k\")(m)"),
    # --- 19.6
    "19.6.1": Override("the values at k = 1, 0 are limits (K(1) = ∞)", whole=True),
    "19.6.4": Override("each line holds in its own passage", whole=False),
    "19.6.6": Override("each line holds in its own passage"),
    # --- 19.7
    "19.7.3": Override("upper signs for Im k² > 0, lower for Im k² < 0 (the prose), Re k > 0 (since DLMF 1.2.0)",
                       constraints=("Gt(re(k), 0)",), split=upper_lower(("Gt(im(k**2), 0)",), ("Lt(im(k**2), 0)",), semantic=(
                           r"\compellintKk@{1/k}=k(\compellintKk@{k}\mp\iunit\compellintKk@{k^{\prime}})",
                           r"\compellintKk@{1/k^{\prime}}=k^{\prime}(\compellintKk@{k^{\prime}}\pm\iunit\compellintKk@{k})",
                           r"\compellintEk@{1/k}=(1/k)\left(\compellintEk@{k}\pm\iunit\compellintEk@{k^{\prime}}-{k^{\prime}}^{2}\compellintKk@{k}\mp\iunit k^{2}\compellintKk@{k^{\prime}}\right)",
                           r"\compellintEk@{1/k^{\prime}}=(1/k^{\prime})\left(\compellintEk@{k^{\prime}}\mp\iunit\compellintEk@{k}-k^{2}\compellintKk@{k^{\prime}}\pm\iunit{k^{\prime}}^{2}\compellintKk@{k}\right)"))),
    "19.7.4": Override("k_1 = 1/k and sin β = k_1 sin φ ≤ 1 (19.7.4's constraints)", whole=True,
                       constraints=("Eq(k_1, 1/k)", "Eq(beta_, asin(k_1*sin(phi)))")),
    "19.7.5": Override("κ, θ, α_1 are given by 19.7.6", constraints=(
        "Eq(kappa, k/sqrt(1 + k**2))", "Eq(theta, asin(sqrt(1 + k**2)*sin(phi)/sqrt(1 + k**2*sin(phi)**2)))",
        "Eq(alpha_1, sqrt((alpha**2 + k**2)/(1 + k**2)))")),
    "19.7.7": Override("ψ is given by sinh φ = tan ψ (the prose)", constraints=("Eq(psi, atan(sinh(phi)))",)),
    "19.7.8": Override("c = csc²φ (19.7(iii))", whole=True),
    "19.7.9": Override("c = csc²φ (19.7(iii))", whole=True),
    "19.7.10": Override("c = csc²φ (19.7(iii))", whole=True),
    # --- 19.8 (the AGM and its sequences)
    **{f"19.8.{n}": Override("a_n, g_n, c_n, p_n, Q_n, ε_n are sequences (19.8.1–19.8.10)",
                             options=AGM_SEQUENCES, note="a_n, g_n, c_n, p_n, Q_n, epsilon_n read as sequences Function(\"a\")(n), ...")
       for n in (1, 2, 3, 6, 7, 8, 9, 10)},
    "19.8.4": Override("a_0, g_0 are numbers here", whole=True),
    "19.8.13": Override("k_1, φ_1 are given by 19.8.11", constraints=(
        "Eq(k_1, (1 - sqrt(1 - k**2))/(1 + sqrt(1 - k**2)))", "Eq(phi_1, phi + atan(sqrt(1 - k**2)*tan(phi)))")),
    "19.8.12": Override("k_1 is given by 19.8.11", constraints=("Eq(k_1, (1 - sqrt(1 - k**2))/(1 + sqrt(1 - k**2)))",)),
    "19.8.14": Override("k_1, φ_1 (19.8.11), ω², α_1², c_1 (19.8.15)", constraints=(
        "Eq(k_1, (1 - sqrt(1 - k**2))/(1 + sqrt(1 - k**2)))", "Eq(phi_1, phi + atan(sqrt(1 - k**2)*tan(phi)))",
        "Eq(omega, sqrt((k**2 - alpha**2)/(1 - alpha**2)))", "Eq(alpha_1, alpha*omega/(1 + sqrt(1 - k**2)))",
        "Eq(c_1, csc(phi_1)**2)")),
    "19.8.17": Override("k_2, φ_2 are given by 19.8.16", constraints=(
        "Eq(k_2, 2*sqrt(k)/(1 + k))", "Eq(phi_2, (phi + asin(k*sin(phi)))/2)")),
    "19.8.19": Override("k_1, ψ_1, Δ are given by 19.8.18", constraints=(
        "Eq(k_1, (1 - sqrt(1 - k**2))/(1 + sqrt(1 - k**2)))", "Eq(Delta, sqrt(1 - k**2*sin(phi)**2))",
        "Eq(psi_1, asin((1 + sqrt(1 - k**2))*sin(phi)/(1 + Delta)))")),
    "19.8.20": Override("k_1, ψ_1, Δ (19.8.18), ρ, α_1², c (19.8.21)", constraints=(
        "Eq(k_1, (1 - sqrt(1 - k**2))/(1 + sqrt(1 - k**2)))", "Eq(Delta, sqrt(1 - k**2*sin(phi)**2))",
        "Eq(psi_1, asin((1 + sqrt(1 - k**2))*sin(phi)/(1 + Delta)))", "Eq(rho, sqrt(1 - k**2/alpha**2))",
        "Eq(alpha_1, alpha*(1 + rho)/(1 + sqrt(1 - k**2)))", C_PHI)),
    # --- 19.9
    "19.9.9": Override("L(a, b) is the perimeter of an ellipse; k as 19.9.9's constraints", whole=True),
    "19.9.16": Override("θ is bounded, not given: the relation says F lies within the stated range", whole=True),
    "19.9.17": Override("L and U are given by 19.9.18", constraints=(
        "Eq(L, atanh(sigma*sin(phi))/sigma)", "Eq(U, atanh(sin(phi))/2 + atanh(k*sin(phi))/(2*k))",
        "Eq(sigma, sqrt((1 + k**2)/2))")),
    # --- 19.11: addition theorems
    "19.11.1": Override("ψ is given by 19.11.3 (its sine and cosine)", constraints=(
        "Eq(sin(psi), (sin(theta)*cos(phi)*sqrt(1 - k**2*sin(phi)**2) + sin(phi)*cos(theta)*sqrt(1 - k**2*sin(theta)**2))/(1 - k**2*sin(theta)**2*sin(phi)**2))",
        "Eq(cos(psi), (cos(theta)*cos(phi) - sin(theta)*sin(phi)*sqrt(1 - k**2*sin(theta)**2)*sqrt(1 - k**2*sin(phi)**2))/(1 - k**2*sin(theta)**2*sin(phi)**2))")),
    # --- 19.12 (asymptotics as k′ → 0)
    "19.12.1": Override("an expansion in k′", whole=True),
    "19.12.4": Override("the O-term is as k′ → 0, i.e. k → 1", options=O("k", "1")),
    "19.12.5": Override("the O-term is as k′ → 0, i.e. k → 1", options=O("k", "1")),
    # --- 19.14
    "19.14.4": Override("the prose orders α ≤ β ≤ γ among 0, a_1 b_2, a_2 b_1", whole=True),
    # --- 19.16
    "19.16.9": Override("read for n = 3", drop_constraints=(r"b_{1}+\cdots+b_{n}>a>0",),
                        constraints=("Gt(b_1 + b_2 + b_3, a)", "Gt(a, 0)"), note="n = 3"),
    "19.16.11": Override("read for n = 3", drop_constraints=(r"\boldsymbol{{1}}=(1,\dots,1)",), note="n = 3"),
    "19.16.8": Override("read for n = 3", note="n = 3"),
    "19.16.10": Override("read for n = 3", note="n = 3"),
    "19.16.19": Override("read for n = 3", note="n = 3"),
    "19.16.24": Override("read for n = 3", note="n = 3"),
    # --- 19.18
    "19.18.3": Override("read for n = 3, each j", expand=({"j": "1"}, {"j": "2"}, {"j": "3"}), note="n = 3, j = 1, 2, 3"),
    "19.18.4": Override("read for n = 3, each j; w_j = b_j/(b_1 + b_2 + b_3) (19.18.3)",
                        expand=({"j": "1"}, {"j": "2"}, {"j": "3"}),
                        constraints=tuple(f"Eq(w_{j}, b_{j}/(b_1 + b_2 + b_3))" for j in (1, 2, 3)), note="n = 3, j = 1, 2, 3"),
    "19.18.5": Override("read for n = 3, each j; w_j (19.18.3), a′ (19.16.10)",
                        expand=({"j": "1"}, {"j": "2"}, {"j": "3"}),
                        constraints=tuple(f"Eq(w_{j}, b_{j}/(b_1 + b_2 + b_3))" for j in (1, 2, 3)) + ("Eq(ap, -a + b_1 + b_2 + b_3)",),
                        note="n = 3, j = 1, 2, 3"),
    "19.18.8": Override("read for n = 3", note="n = 3"),
    "19.18.11": Override("v = R_{-a}(b; z) (the prose), n = 3",
                         options={"defined": {"v": ((), r"\Carlsonmultivarhyper{-a}@{\mathbf{b}}{\mathbf{z}}")}}, note="n = 3; v = R_{-a}(b; z)"),
    "19.18.12": Override("v = R_{-a}(b; z) (the prose), n = 3, each j ≠ l",
                         options={"defined": {"v": ((), r"\Carlsonmultivarhyper{-a}@{\mathbf{b}}{\mathbf{z}}")}},
                         expand=tuple({"j": a, "l": b} for a, b in (("1", "2"), ("1", "3"), ("2", "3"))),
                         note="n = 3; v = R_{-a}(b; z); (j, l) = (1, 2), (1, 3), (2, 3)"),
    "19.18.13": Override("v = R_{-a}(b; z) (the prose), n = 3, each j ≠ l",
                         options={"defined": {"v": ((), r"\Carlsonmultivarhyper{-a}@{\mathbf{b}}{\mathbf{z}}")}},
                         expand=tuple({"j": a, "l": b} for a, b in (("1", "2"), ("1", "3"), ("2", "3"))),
                         note="n = 3; v = R_{-a}(b; z); (j, l) = (1, 2), (1, 3), (2, 3)"),
    "19.18.14": Override("w = R_{-a}(1/2, 1/2; x + y, x - y) (the prose)", options={"defined": {"w": ((), r"\Carlsonmultivarhyper{-a}@{\tfrac{1}{2},\tfrac{1}{2}}{x+y,x-y}")}}),
    "19.18.15": Override("W = R_{-a}(1/2, 1/2; t + r, t - r), r = √(x² + y²) (the prose)", options={"defined": {"W": ((), r"\Carlsonmultivarhyper{-a}@{\tfrac{1}{2},\tfrac{1}{2}}{t+\sqrt{x^{2}+y^{2}},t-\sqrt{x^{2}+y^{2}}}")}}),
    "19.18.16": Override("u = R_{-a}(1/2, 1/2; x + iy, x - iy) (the prose)", options={"defined": {"u": ((), r"\Carlsonmultivarhyper{-a}@{\tfrac{1}{2},\tfrac{1}{2}}{x+\iunit y,x-\iunit y}")}}),
    "19.18.17": Override("U = R_{-a}(1/2, 1/2; z + iρ, z - iρ), ρ = √(x² + y²) (the prose)", options={"defined": {"U": ((), r"\Carlsonmultivarhyper{-a}@{\tfrac{1}{2},\tfrac{1}{2}}{z+\iunit\sqrt{x^{2}+y^{2}},z-\iunit\sqrt{x^{2}+y^{2}}}")}}),
}


def _t_n(b: tuple[str, ...], z: tuple[str, ...], N: str = "N") -> str:
    """T_N(b; z) of 19.19.1 written out for two or three variables (a sum over m_1, m_2)."""
    if len(b) == 2:
        return (f"Sum(rf({b[0]}, m_1)*rf({b[1]}, {N} - m_1)*({z[0]})**m_1*({z[1]})**({N} - m_1)"
                f"/(factorial(m_1)*factorial({N} - m_1)), (m_1, 0, {N}))")
    m3 = f"{N} - m_1 - m_2"
    return (f"Sum(Sum(rf({b[0]}, m_1)*rf({b[1]}, m_2)*rf({b[2]}, {m3})*({z[0]})**m_1*({z[1]})**m_2*({z[2]})**({m3})"
            f"/(factorial(m_1)*factorial(m_2)*factorial({m3})), (m_2, 0, {N} - m_1)), (m_1, 0, {N}))")


B3, Z3 = ("b_1", "b_2", "b_3"), ("z_1", "z_2", "z_3")
T_NOTE = "n = 3: T_N (19.19.1) written out as the sum over m_1 + m_2 + m_3 = N"
I_NOTE = "I(m) of 19.29.11 and the unit vectors e_j are kept as undefined functions and symbols: not evaluable here"
WP = r"\Weierstrassplatt@@{z}{\mathbb{L}}"
ROOTS = [rf"\Weierstrasselatt{{{j}}}@@{{\mathbb{{L}}}}" for j in (1, 2, 3)]
SIGMA_J = {f"sigma_{j}": (("u",), rf"\exp@{{-\Weierstrasszetalatt@@{{\omega_{{{j}}}}}{{\mathbb{{L}}}}u}}"
                          rf"\Weierstrasssigmalatt@@{{u+\omega_{{{j}}}}}{{\mathbb{{L}}}}/\Weierstrasssigmalatt@@{{\omega_{{{j}}}}}{{\mathbb{{L}}}}")
           for j in (1, 3)}
SIGMA_J["sigma_2"] = (("u",), r"\exp@{-\Weierstrasszetalatt@@{-\omega_{1}-\omega_{3}}{\mathbb{L}}u}"
                              r"\Weierstrasssigmalatt@@{u-\omega_{1}-\omega_{3}}{\mathbb{L}}/\Weierstrasssigmalatt@@{-\omega_{1}-\omega_{3}}{\mathbb{L}}")
LATTICE_NOTE = "holds for one sign and some period 2ω of the lattice (the sign changes across curves where ℘(z) − e_j < 0)"
DELTA_PQ = {"Delta": (("P", "Q"), r"\genJacobiellk{P}{s}^{2}@{u}{k}-\genJacobiellk{Q}{s}^{2}@{u}{k}")}
CDN3 = _perms("cdn", "pqr")

OVERRIDES.update({
    # --- 19.19 (n = 3)
    "19.19.1": Override("the sum over all multi-indices m with m_1 + ... + m_n = N has no limits to read", kind="definition",
                        printed=(f'Eq(Function("T")(N, Tuple(b_1, b_2, b_3), Tuple(z_1, z_2, z_3)), {_t_n(B3, Z3)})',), note=T_NOTE),
    "19.19.2": Override("T_N written out (n = 3); c = b_1 + b_2 + b_3", note=T_NOTE,
                        printed=(f"Eq(CarlsonR(a, Tuple(b_1, b_2, b_3), Tuple(z_1, z_2, z_3)), Sum(rf(a, N)/rf(c, N)*{_t_n(B3, ('1 - z_1', '1 - z_2', '1 - z_3'))}, (N, 0, oo)))",),
                        drop_constraints=(r"c=\sum_{j=1}^{n}b_{j}", r"|1-z_{j}|<1"),
                        constraints=("Eq(c, b_1 + b_2 + b_3)", "Lt(Abs(1 - z_1), 1)", "Lt(Abs(1 - z_2), 1)", "Lt(Abs(1 - z_3), 1)")),
    "19.19.3": Override("T_N written out (n = 3); c = b_1 + b_2 + b_3", note=T_NOTE,
                        printed=(f"Eq(CarlsonR(a, Tuple(b_1, b_2, b_3), Tuple(z_1, z_2, z_3)), z_3**(-a)*Sum(rf(a, N)/rf(c, N)*{_t_n(('b_1', 'b_2'), ('1 - z_1/z_3', '1 - z_2/z_3'))}, (N, 0, oo)))",),
                        drop_constraints=(r"c=\sum_{j=1}^{n}b_{j}", r"|1-(z_{j}/z_{n})|<1"),
                        constraints=("Eq(c, b_1 + b_2 + b_3)", "Lt(Abs(1 - z_1/z_3), 1)", "Lt(Abs(1 - z_2/z_3), 1)")),
    "19.19.4": Override("E_s(z), the elementary symmetric functions, are defined by this formula (n = 3)", kind="definition",
                        printed=('Eq((1 + t*z_1)*(1 + t*z_2)*(1 + t*z_3), Sum(t**s*Function("E")(s, z_1, z_2, z_3), (s, 0, 3)))',), note="n = 3"),
    "19.19.5": Override("the sum over all m with m_1 + 2m_2 + ... + n m_n = N has no limits to read", kind="notation",
                        printed=('Function("T")(N, Tuple(1/2, 1/2, 1/2), Tuple(z_1, z_2, z_3))',),
                        note="only the left side is transcribed: the sum runs over m with m_1 + 2 m_2 + ... + n m_n = N, M = m_1 + ... + m_n"),
    "19.19.7": Override("T_N written out (n = 3); A, Z_j of 19.19.8", note=T_NOTE,
                        printed=(f"Eq(CarlsonR(a, Tuple(1/2, 1/2, 1/2), Tuple(z_1, z_2, z_3)), A**(-a)*Sum(rf(a, N)/rf(3/2, N)*{_t_n(('1/2', '1/2', '1/2'), ('Z_1', 'Z_2', 'Z_3'))}, (N, 0, oo)))",),
                        constraints=("Eq(A, (z_1 + z_2 + z_3)/3)", "Eq(Z_1, 1 - z_1/A)", "Eq(Z_2, 1 - z_2/A)", "Eq(Z_3, 1 - z_3/A)")),
    "19.19.8": Override("read for n = 3", options={"dimension": 3}, kind="definition", note="n = 3"),
    # --- 19.20
    "19.20.7": Override("R_J → +∞ as p → 0+ and as p → 0− (LaCASt's constraint is cut in two)", kind="asymptotic",
                        printed=('Eq(Limit(CarlsonRJ(x, y, z, p), p, 0, "+"), oo)', 'Eq(Limit(CarlsonRJ(x, y, z, p), p, 0, "-"), oo)'),
                        constraints_only=("Gt(x, 0)", "Gt(y, 0)", "Gt(z, 0)"), real=("x", "y", "z")),
    "19.20.9": Override("the upper and lower signs are two cases of one formula", whole=True),
    "19.20.11": Override("p real and nonzero (LaCASt's constraint is cut in two)", drop_constraints=("p", r"\neq 0"),
                         constraints=("Ne(p, 0)",), real=("p",)),
    "19.20.26": Override("read for n = 3", drop_constraints=(r"\boldsymbol{{z^{-1}}}=(z_{1}^{-1},\dots,z_{n}^{-1})",), note="n = 3"),
    # --- 19.21
    "19.21.4": Override("upper signs for 0 < ph z < π, lower for −π < ph z < 0 (the prose)",
                        split=upper_lower(("Lt(0, arg(z))", "Lt(arg(z), pi)"), ("Lt(-pi, arg(z))", "Lt(arg(z), 0)"), semantic=(
                            r"\CarlsonsymellintRF@{0}{z-1}{z}=\CarlsonsymellintRF@{0}{1-z}{1}\mp\iunit\CarlsonsymellintRF@{0}{z}{1}",))),
    "19.21.5": Override("upper signs for 0 < ph z < π, lower for −π < ph z < 0 (the prose)",
                        split=upper_lower(("Lt(0, arg(z))", "Lt(arg(z), pi)"), ("Lt(-pi, arg(z))", "Lt(arg(z), 0)"), semantic=(
                            r"2\CarlsonsymellintRG@{0}{z-1}{z}=2\CarlsonsymellintRG@{0}{1-z}{1}\pm\iunit 2\CarlsonsymellintRG@{0}{z}{1}+(z-1)\CarlsonsymellintRF@{0}{1-z}{1}\mp\iunit z\CarlsonsymellintRF@{0}{z}{1}",))),
    "19.21.11": Override("the sums run over the three cyclic permutations of x, y, z (the prose): written out",
                         semantic=(r"6\CarlsonsymellintRG@{x}{y}{z}=3(x+y+z)\CarlsonsymellintRF@{x}{y}{z}-(x^{2}\CarlsonsymellintRD@{y}{z}{x}+y^{2}\CarlsonsymellintRD@{z}{x}{y}+z^{2}\CarlsonsymellintRD@{x}{y}{z})"
                                    r"=x(y+z)\CarlsonsymellintRD@{y}{z}{x}+y(z+x)\CarlsonsymellintRD@{z}{x}{y}+z(x+y)\CarlsonsymellintRD@{x}{y}{z}",),
                         note="the cyclic sums written out for this import"),
    # --- 19.22 (the AGM)
    **{f"19.22.{n}": Override("a_n, g_n, c_n, p_n, Q_n, ε_n are sequences (19.22(ii))", options=AGM_SEQUENCES,
                              note="a_n, g_n, c_n, p_n, Q_n, epsilon_n read as sequences Function(\"a\")(n), ...")
       for n in range(9, 16)},
    # --- 19.23
    "19.23.6_5": Override("moved from 19.16.3", note="was 19.16.3 in the DLMF LaCASt read"),
    # --- 19.25
    "19.25.28": Override("p, q any two of c, d, n (the prose); Δ(p, q) as defined here", kind="definition",
                         options={"defined": DELTA_PQ}, expand=_perms("cdn", "pq")),
    "19.25.29": Override("Δ(p, q) of 19.25.28", options={"defined": DELTA_PQ}),
    "19.25.31": Override("p, q, r any permutation of c, d, n (the prose)", expand=CDN3, constraints=("Le(0, k**2)", "Le(k**2, 1)")),
    "19.25.32": Override("p, q, r any permutation of c, d, n; Δ of 19.25.28", options={"defined": DELTA_PQ}, expand=CDN3,
                         note="the range of x each function needs (the prose) is not among the constraints"),
    "19.25.33": Override("p, q, r any permutation of c, d, n; Δ of 19.25.28", options={"defined": DELTA_PQ}, expand=CDN3,
                         note="the range of x each function needs (the prose) is not among the constraints"),
    "19.25.34": Override("p, q, r any permutation of c, d, n; Δ of 19.25.28; w = (1 - x²)/Δ(q, p) read as a notation",
                         options={"defined": {**DELTA_PQ, "w": ((), r"\ifrac{(1-x^{2})}{\Delta(\mathrm{q,p})}")}}, expand=CDN3,
                         drop_constraints=(r"w=\ifrac{(1-x^{2})}{\Delta(\mathrm{q,p})}",),
                         note="the range of x each function needs (the prose) is not among the constraints"),
    "19.25.35": Override(CHANGED, note=CHANGED + "; " + LATTICE_NOTE, semantic=(
        rf"z+2\omega=\pm\CarlsonsymellintRF@{{{WP}-{ROOTS[0]}}}{{{WP}-{ROOTS[1]}}}{{{WP}-{ROOTS[2]}}}",)),
    "19.25.36": Override("℘(z) − e_j ∉ (−∞, 0] for j = 1, 2, 3: a condition", kind="definition", expand=({"j": "1"}, {"j": "2"}, {"j": "3"}),
                         printed=tuple(f"Or(Ne(im(WeierstrassP(z, omega_1, omega_3) - WeierstrassP({w}, omega_1, omega_3)), 0), "
                                       f"Gt(re(WeierstrassP(z, omega_1, omega_3) - WeierstrassP({w}, omega_1, omega_3)), 0))"
                                       for w in ("omega_1", "-omega_1 - omega_3", "omega_3")),
                         note="the condition under which 19.25.35 holds, for j = 1, 2, 3"),
    "19.25.37": Override(CHANGED, note=CHANGED + "; " + LATTICE_NOTE, semantic=(
        rf"\Weierstrasszetalatt@@{{z+2\omega}}{{\mathbb{{L}}}}+(z+2\omega){WP}=\pm 2\CarlsonsymellintRG@{{{WP}-{ROOTS[0]}}}{{{WP}-{ROOTS[1]}}}{{{WP}-{ROOTS[2]}}}",)),
    "19.25.38": Override("j, k, ℓ any permutation of 1, 2, 3 (the prose)", expand=_perms("123", ["j", "k", "ell"]),
                         note="for some 2ω_j in the lattice with ℘(ω_j) = e_j (the prose)"),
    "19.25.39": Override("j, k, ℓ any permutation of 1, 2, 3 (the prose)", expand=_perms("123", ["j", "k", "ell"]),
                         note="η_j = ζ(ω_j) (19.25.41's prose), for some 2ω_j in the lattice with ℘(ω_j) = e_j"),
    "19.25.40": Override(CHANGED + "; σ_j(z) as 19.25.41 defines it", options={"defined": SIGMA_J}, note=CHANGED + "; " + LATTICE_NOTE,
                         semantic=(r"z+2\omega=\pm\Weierstrasssigmalatt@@{z}{\mathbb{L}}\CarlsonsymellintRF@{\sigma_{1}(z)^{2}}{\sigma_{2}(z)^{2}}{\sigma_{3}(z)^{2}}",)),
    "19.25.41": Override("j = 1, 2, 3; η_j = ζ(ω_j), ω_2 = −ω_1 − ω_3 (the prose)", kind="definition",
                         expand=({"j": "1"}, {"j": "3"}), note="read for j = 1 and 3 (ω_2 = −ω_1 − ω_3)",
                         constraints=("Eq(eta_1, WeierstrassZeta(omega_1, omega_1, omega_3))",
                                      "Eq(eta_3, WeierstrassZeta(omega_3, omega_1, omega_3))")),
    # --- 19.26, 19.27
    "19.26.27": Override("LaCASt's second constraint is a fragment", drop_constraints=("s^{2}",)),
    "19.27.13": Override("the O-term is read as a → 0 (with z, p fixed), one way to make max(x, y)/min(z, p) → 0",
                         drop_constraints=(r"\max(x,y)/\min(z,p)\to 0",), options=O("a", "0"), constraints=("Eq(a, (x + y)/2)",)),
    "19.27.14": Override("the O-term is read as x, p → 0 through x → 0, one way to make max(x, p)/min(y, z) → 0",
                         drop_constraints=(r"\max(x,p)/\min(y,z)\to 0",), options=O("x", "0")),
    # --- 19.29–19.36: applications
    "19.29.11": Override(UNIT + " a product over a symbolic number of factors a_α + b_α t", kind="definition",
                         printed=('Eq(Function("I")(m), Integral(Product((Function("a")(alpha) + Function("b")(alpha)*t)**(-1/2), (alpha, 1, h))'
                                  '*Product((Function("a")(j) + Function("b")(j)*t)**Function("m")(j), (j, 1, n)), (t, y, x)))',), note=I_NOTE),
    "19.29.12": Override(UNIT + " the multi-index m", kind="notation", printed=("m",), note="the multi-index m = (m_1, ..., m_n) = sum of m_j e_j"),
    "19.29.13": Override(UNIT + " I(0) out of context", kind="notation", printed=('Function("I")(0)',), note=I_NOTE),
    "19.29.14": Override(UNIT + " I(0) out of context", kind="notation", printed=('Function("I")(0)',), note=I_NOTE),
    "19.29.15": Override(UNIT + " I(m) with unit vectors", printed=('Eq(b_j*Function("I")(e_l - e_j), d_lj*Function("I")(-e_j) + b_l*Function("I")(0))',), note=I_NOTE),
    "19.29.16": Override(UNIT + " I(m) with unit vectors", options={"defined": {"s": (("u",), r"\prod_{\alpha=1}^{3}\sqrt{a_{\alpha}+b_{\alpha}u}")}},
                         printed=('Eq(b_beta*b_gamma*Function("I")(e_alpha), d_alphabeta*d_alphagamma*Function("I")(-e_alpha) + 2*b_alpha*(Function("s")(x)/(a_alpha + b_alpha*x) - Function("s")(y)/(a_alpha + b_alpha*y)))',), note=I_NOTE),
    "19.29.18": Override(UNIT + " I(m) with unit vectors", printed=('Eq(b_j**q*Function("I")(q*e_l), Sum(binomial(q, r)*b_l**r*d_lj**(q - r)*Function("I")(r*e_j), (r, 0, q)))',), note=I_NOTE),
    "19.30.6": Override("∂s/∂(1/k) is read as −k² ∂s/∂k", printed=(
        "Eq(-k**2*Derivative(s, (k, 1)), sqrt(a**2 - b**2)*EllipticF(phi, k))",
        "Eq(-k**2*Derivative(s, (k, 1)), sqrt(a**2 - b**2)*CarlsonRF(c - 1, c - k**2, c))"),
        note="∂/∂(1/k) read as −k² ∂/∂k; s = a E(φ, k) (19.30.3) at fixed a, φ"),
    "19.30.9": Override(UNIT + " I(e_1) (19.29.11)", printed=(
        'Eq(s, Function("I")(e_1)/2)',
        "Eq(s, -a**2*b**2*CarlsonRD(r, r + b**2 + a**2, r + b**2)/3 + y*sqrt((r + b**2 + a**2)/(r + b**2)))"), note=I_NOTE),
    "19.31.1": Override("the quadratic form is notation: its double sum read for n = 3", kind="notation", options={"dimension": 3},
                        semantic=(r"\sum_{r=1}^{n}\sum_{s=1}^{n}a_{r,s}x_{r}x_{s}",), note="n = 3; only the right side (the quadratic form written out)"),
    "19.31.2": Override(UNIT + " an integral over R^n of matrices", kind="notation", printed=(
        'pi**(n/2)*gamma(mu + n/2)*CarlsonR(-mu, Tuple(1/2, 1/2, 1/2), Tuple(lamda_1, lamda_2, lamda_3))/(sqrt(Function("det")(B))*gamma(n/2))',),
        note="only the right side, for n = 3: the integral over R^n of the quadratic forms is not transcribed"),
    "19.32.2": Override("dz = f dp is read as dz/dp = f, with z(p) of 19.32.1", printed=(
        "Eq(Derivative(CarlsonRF(p - x_1, p - x_2, p - x_3), (p, 1)), -(p - x_1)**(-1/2)*(p - x_2)**(-1/2)*(p - x_3)**(-1/2)/2)",)),
    "19.33.10": Override(UNIT + " an integral over R^6", kind="notation", printed=("U",),
                         note="only the left side: the integral over R^6 of the density is not transcribed"),
    "19.34.1": Override(UNIT + " I(e_5) (19.29.11)", printed=(
        "Eq(lightspeed**2*M/(2*pi), a*b*Integral((h**2 + a**2 + b**2 - 2*a*b*cos(theta))**(-1/2)*cos(theta), (theta, 0, 2*pi)))",
        "Eq(lightspeed**2*M/(2*pi), 2*a*b*Integral(t/sqrt((1 + t)*(1 - t)*(a_3 - 2*a*b*t)), (t, -1, 1)))",
        'Eq(lightspeed**2*M/(2*pi), 2*a*b*Function("I")(e_5))'), constraints=("Eq(a_3, h**2 + a**2 + b**2)",), note=I_NOTE),
    "19.34.3": Override(UNIT + " I(m) with unit vectors", printed=(
        'Eq(2*a*b*Function("I")(e_5), a_3*Function("I")(0) - Function("I")(e_3))',
        'Eq(2*a*b*Function("I")(e_5), a_3*Function("I")(0) - r_plus**2*r_minus**2*Function("I")(-e_3))',
        'Eq(2*a*b*Function("I")(e_5), 2*a*b*(Function("I")(0) - r_minus**2*Function("I")(e_1 - e_3)))'), note=I_NOTE),
    "19.36.4": Override(UNIT + " an aligned list of numbers", kind="definition", printed=(
        "Eq(z_1, 2.10985990988)", "Eq(z_3, 2.15673490988)", "Eq(Z_1, 0.00977772535)", "Eq(z_2, 2.12548490988)",
        "Eq(A, 2.13069324321)", "Eq(Z_2, 0.00244443134)", "Eq(Z_3, -Z_1 - Z_2)", "Eq(Z_3, -0.01222215669)",
        "Eq(E_2, -1.2548014e-4)", "Eq(E_3, -2.9212e-7)"), note="the numbers of the worked example (19.36.3), as printed"),
    "19.36.13": Override("a_m, c_m, t_m, h_m are sequences (19.36(i))", options={"sequences": {"a", "c", "t", "h"}},
                         note="a_m, c_m, t_m, h_m read as sequences Function(\"c\")(m), ..."),
    # --- 22
    "22.2.10": Override("p, q, r any three distinct letters of s, c, d, n (the prose)", expand=_perms(LETTERS_SCDN, "pqr")),
    "22.2.11": Override("the theta functions of the right side are Neville's (the prose, §20.1), which LaCASt's semantic "
                        "LaTeX reads as Jacobi's θ_1 … θ_4 of the same argument: written here from §20.1's definitions of "
                        "θ_s, θ_c, θ_d, θ_n (u = z/θ_3²(0|τ)); p, q any two distinct letters of s, c, d, n",
                        printed=tuple(f"Eq(Jacobi{a.upper()}{b.upper()}(z, k), ({NEVILLE[a]})/({NEVILLE[b]}))"
                                      for a, b in ((x["p"], x["q"]) for x in _perms(LETTERS_SCDN, "pq"))),
                        constraints=("Eq(tau, I*EllipticKp(k)/EllipticK(k))", "Eq(q, exp(I*pi*tau))",
                                     "Eq(u, z/JacobiTheta3(0, q)**2)")),
    "22.6.22": Override("p, q, r any permutation of c, d, n (the prose)", expand=CDN3),
    "22.10.7": Override("the O-term is as k′ → 0, i.e. k → 1", options=O("k", "1")),
    "22.10.8": Override("the O-term is as k′ → 0, i.e. k → 1", options=O("k", "1")),
    "22.10.9": Override("the O-term is as k′ → 0, i.e. k → 1", options=O("k", "1")),
    "22.16.8": Override("the O-term is as k′ → 0, i.e. k → 1", options=O("k", "1")),
    "22.17.1": Override("for all twelve functions (the prose)", expand=_perms(LETTERS_SCDN, "pq")),
    "22.20.2": Override(UNIT + r" \text{(const.)}", kind="inequality", printed=(
        'Le(Max(Abs(Function("a")(n) - M), Abs(Function("b")(n) - M), Abs(Function("c")(n))), C*2**(-2**n))',),
        note="(const.) read as a constant C; a_n, b_n, c_n the sequences of 22.20.1"),
})

def _ode(x: str, rhs: str, at_rest: bool = True) -> tuple[str, ...]:
    """A solution x(t) of x'' = rhs(x): the equation of motion with x substituted, and, for a
    start at rest at t = 0, x'(0) = 0."""
    out = (f"Eq(Derivative({x}, (t, 2)), {rhs.replace('X', f'({x})')})",)
    return out + ((f"Eq(Subs(Derivative({x}, t), t, 0), 0)",) if at_rest else ())


def _solutions_22_19() -> dict:
    """§22.19's equations of motion (22.19.1, 22.19.4, 22.19.5) state the problem; each
    solution the section prints (22.19.2, 22.19.3, 22.19.6-22.19.9) is checked by putting it
    into its equation of motion, with the modulus and the initial conditions the prose gives."""
    hypothesis = "the equation of motion whose solutions the next formulas are: a hypothesis, checked through them"
    theta = "2*asin(sin(alpha/2)*JacobiSN(t + K, sin(alpha/2)))"
    sala = "2*JacobiAM(t*sqrt(E/2), sqrt(2/E))"
    # each case's range of η = βa²/2 (the prose's range of a): a drawn, or computed from an η drawn in
    # its range (η ≥ 1 as 1/s, 0 < s ≤ 1)
    drawn = ("Eq(eta, beta_*a**2/2)", "Gt(a, 0)")
    from_eta = ("Eq(a, sqrt(2*eta/beta_))",)
    quartic = {"22.19.6": ("a*JacobiCN(t*sqrt(1 + 2*eta), k)", "-X - beta_*X**3", "Eq(k, 1/sqrt(2 + 1/eta))", drawn, True),
               "22.19.7": ("a*JacobiSN(t*sqrt(1 - eta), k)", "-X + beta_*X**3", "Eq(k, 1/sqrt(1/eta - 1))",
                           drawn + ("Le(a, sqrt(1/beta_))",), False),
               "22.19.8": ("a*JacobiDN(t*sqrt(eta), k)", "X - beta_*X**3", "Eq(k, 1/sqrt(2 - 1/eta))",
                           ("Ge(eta, 1/2)", "Lt(eta, 1)") + from_eta, True),
               "22.19.9": ("a*JacobiCN(t*sqrt(2*eta - 1), k)", "X - beta_*X**3", "Eq(k, 1/sqrt(2 - 1/eta))",
                           ("Gt(s, 0)", "Le(s, 1)", "Eq(eta, 1/s)") + from_eta, True)}
    names = {"22.19.1": "the pendulum's equation of motion", "22.19.4": "Newton's equation in one dimension",
             "22.19.5": "the quartic potentials"}
    motion = {"22.19.1": (("Eq(Derivative(Function('theta')(t), (t, 2)), -sin(Function('theta')(t)))",), "theta"),
              "22.19.4": (("Eq(Derivative(Function('x')(t), (t, 2)), -Subs(Derivative(Function('V')(X), X), X, "
                           "Function('x')(t)))",), "V"),
              "22.19.5": (tuple(f"Eq(Function('V')(x), {a}x**2/2 {b} beta_*x**4/4)" for a in ("", "-") for b in "+-"), "V")}
    out = {n: Override(hypothesis, printed=motion[n][0], defines=(motion[n][1],), name=name) for n, name in names.items()}
    out["22.19.2"] = Override(
        "the pendulum's bounded solution put into (22.19.1), released at rest from θ = α (the prose); K = K(sin(α/2))",
        printed=_ode(theta, "-sin(X)") + (f"Eq(Subs({theta}, t, 0), alpha)",),
        constraints=("Eq(K, EllipticK(sin(alpha/2)))", "Gt(alpha, 0)", "Lt(alpha, pi)"), real=("alpha", "t"))
    out["22.19.3"] = Override(
        "Sala's solution put into (22.19.1), θ(0) = 0 and θ'(0) = √(2E) (the prose), for energies E > 0 on either "
        "side of the separatrix E = 2",
        printed=_ode(sala, "-sin(X)", at_rest=False) + (f"Eq(Subs({sala}, t, 0), 0)",
                                                          f"Eq(Subs(Derivative({sala}, t), t, 0), sqrt(2*E))"),
        constraints=("Gt(E, 0)", "Ne(E, 2)"), real=("E", "t"))
    for n, (x, rhs, modulus, bounds, at_rest) in quartic.items():
        out[n] = Override(
            "the quartic oscillator's solution put into (22.19.4) with its potential (22.19.5) and the modulus the prose "
            "gives for the case; η = βa²/2, β > 0" + (", released at rest from x = a" if at_rest else ""),
            printed=_ode(x, rhs, at_rest) + ((f"Eq(Subs({x}, t, 0), a)",) if at_rest else ()),
            constraints=("Gt(beta_, 0)",) + bounds + (modulus,), real=("a", "beta_", "eta", "s", "t"))
    return out


SECTIONS.update({
    "22.2": {"where": {"zeta": ZETA_Z}},
    "22.11": {"where": {"zeta": ZETA_Z}},
})
OVERRIDES.update({
    "22.16.9": Override("ζ = πx/(2K) here (the prose)", constraints=("Eq(zeta, pi*x/(2*K))",)),
    **_solutions_22_19(),
    "22.18.1": Override("the ellipse whose arc length (22.18.2)-(22.18.3) give: a definition of the curve", defines=("y",)),
    "22.18.3": Override("l(u), the arc length as a function of u, which this formula introduces",
                        printed=("Eq(Function('l')(u), a*JacobiEpsilon(u, k))",), defines=("l",)),
    "22.18.4": Override("l(r), the lemniscate's arc length as a function of r, which this formula introduces",
                        printed=("Eq(Function('l')(r), JacobiArcCN(r, 1/sqrt(2))/sqrt(2))",), defines=("l",)),
    "22.18.5": Override("the inverse of (22.18.4): r as a function of the arc length l = l(r), 0 < r < 1",
                        constraints_only=("Gt(r, 0)", "Lt(r, 1)", "Eq(l, JacobiArcCN(r, 1/sqrt(2))/sqrt(2))"),
                        real=("r",), kind="identity"),
    "22.18.7": Override("the family of curves the addition theorem of (22.18.8) parametrizes: a definition", defines=("y",)),
})

#: How text.toml declares a symbol: complex by default, sampled in a box; indices are integers.
SYMBOL_DEFAULT = {"assumptions": [], "range": ["-1-I", "1+I"]}
INTEGER_SYMBOL = {"assumptions": ["integer"], "range": ["0", "6"]}
INTEGER_NAMES = frozenset({"m", "n", "N", "j", "l", "M"})
#: LaTeX of names the naming convention does not spell back.
SYMBOL_LATEX: dict[str, str] = {"Kp": r"K^{\prime}", "lightspeed": r"c", "lamda": r"\lambda", "C": r"\text{const.}"}

# --- "where" definitions of neighbouring formulas and of the prose ---------------------------------
KP = "sqrt(1 - k**2)"
P_PM = {"p_plus": "Eq(p_plus, (sqrt((p + x)*(p + y)) + sqrt((p - x)*(p - y)))/2)",
        "p_minus": "Eq(p_minus, (sqrt((p + x)*(p + y)) - sqrt((p - x)*(p - y)))/2)"}
Z_PM = {"z_plus": "Eq(z_plus, (sqrt((z + x)*(z + y)) + sqrt((z - x)*(z - y)))/2)",
        "z_minus": "Eq(z_minus, (sqrt((z + x)*(z + y)) - sqrt((z - x)*(z - y)))/2)"}
SECTIONS.update({
    "19.16": {**SECTIONS["19.16"], "where": {"ap": "Eq(ap, -a + b_1 + b_2 + b_3)", "c": C_PHI}},
    "19.20": {**SECTIONS["19.20"], "where": {"ap": "Eq(ap, -a + b_1 + b_2 + b_3)", "c": "Eq(c, b_1 + b_2 + b_3)"}},
    "19.22": {"where": {"a": "Eq(a, (x + y)/2)", **P_PM, **Z_PM, "v_plus": "Eq(v_plus, (p**2 + x*y)/(2*p))",
                        "v_minus": "Eq(v_minus, (p**2 - x*y)/(2*p))"}},
    "19.23": {**SECTIONS["19.23"], "where": {"ap": "Eq(ap, -a + b_1 + b_2 + b_3)"}},
    "19.27": {"where": {"a": "Eq(a, (x + y)/2)", "b": "Eq(b, (y + z)/2)", "c": "Eq(c, (x + y + z)/3)",
                        "f": "Eq(f, (x*y*z)**(1/3))", "g": "Eq(g, sqrt(x*y))", "h": "Eq(h, sqrt(y*z))"}},
    "22.7": {"where": {"k_1": f"Eq(k_1, (1 - {KP})/(1 + {KP}))", "k_2": "Eq(k_2, 2*sqrt(k)/(1 + k))"}},
    "22.9": {"where": {"kappa": "Eq(kappa, JacobiDN(2*K/3, k))",
                       **{f"{f}_{m}_{p}__{j}": f"Eq({f}_{m}_{p}__{j}, Jacobi{F}(z + {j}*({m} - 1)*K/{p}, k))"
                          for f, F in (("s", "SN"), ("c", "CN"), ("d", "DN"))
                          for m in range(1, 5) for p in (2, 3, 4) for j in (2, 4)}}},
    "22.17": {"where": {"k_1": "Eq(k_1, k/sqrt(1 + k**2))"}},
})
LAMBDA_MU = "Eq(mu, ((sqrt((x + lamda)*y*z) + sqrt(x*(y + lamda)*(z + lamda)))/lamda)**2 - x)"
LAMBDA_DUP = "Eq(lamda, sqrt(x)*sqrt(y) + sqrt(y)*sqrt(z) + sqrt(z)*sqrt(x))"
POSITIVE_XYZ = ("Gt(x, 0)", "Gt(y, 0)", "Gt(z, 0)")
PHI_K_ALPHA = ("Eq(phi, acos(sqrt(x/z)))", "Eq(k, sqrt((z - y)/(z - x)))", "Eq(alpha, sqrt((z - p)/(z - x)))")
OVERRIDES.update({
    "19.2.14": Override("k_c, p are given by 19.2.13", constraints=(f"Eq(k_c, {KP})", "Eq(p, 1 - alpha**2)")),
    "19.2.15": Override("k_c, x are given by 19.2.13", constraints=(f"Eq(k_c, {KP})", "Eq(x, tan(phi))")),
    "19.2.16": Override("k_c = k′ (19.2.13) for the last member", constraints=(f"Eq(k_c, {KP})",)),
    "19.2.3": Override("ρ(t) and s(t) are functions of t (19.2(i))", options={"applied": {"rho", "s"}}),
    "19.4.8": Override("D_k = ∂/∂k (the prose)", options={"operators": {"D_k": "k"}}),
    "19.4.9": Override("D_k = ∂/∂k (the prose)", options={"operators": {"D_k": "k"}}),
    "19.6.5": Override("the Cauchy principal value, for 1 < α² < ∞ (the prose)", constraints=("Lt(1, alpha**2)",), real=("alpha",)),
    "19.6.6": Override("1 < α² < ∞ as in 19.6.5 (the prose)", constraints=("Lt(1, alpha**2)",), real=("alpha",)),
    "19.11.2": Override("ψ is given by 19.11.3", constraints=OVERRIDES["19.11.1"].constraints),
    "19.11.5": Override("ψ (19.11.3), γ, δ (19.11.6)", constraints=OVERRIDES["19.11.1"].constraints + (
        "Eq(gamma_, (csc(theta)**2 - alpha**2)*(csc(phi)**2 - alpha**2)*(csc(psi)**2 - alpha**2))",
        "Eq(delta, alpha**2*(1 - alpha**2)*(alpha**2 - k**2))")),
    "19.11.6_5": Override("ψ (19.11.3), γ, δ (19.11.6)", constraints=OVERRIDES["19.11.1"].constraints + (
        "Eq(gamma_, (csc(theta)**2 - alpha**2)*(csc(phi)**2 - alpha**2)*(csc(psi)**2 - alpha**2))",
        "Eq(delta, alpha**2*(1 - alpha**2)*(alpha**2 - k**2))")),
    "19.11.7": Override("θ is given by 19.11.9", constraints=(f"Eq(theta, atan(1/({KP}*tan(phi))))",)),
    "19.11.8": Override("θ is given by 19.11.9", constraints=(f"Eq(theta, atan(1/({KP}*tan(phi))))",)),
    "19.11.10": Override("θ (19.11.9), γ, δ (19.11.11)", constraints=(
        f"Eq(theta, atan(1/({KP}*tan(phi))))", "Eq(gamma_, (1 - alpha**2)*(csc(theta)**2 - alpha**2)*(csc(phi)**2 - alpha**2))",
        "Eq(delta, alpha**2*(1 - alpha**2)*(alpha**2 - k**2))")),
    "19.11.12": Override("ψ is given by 19.11.14", constraints=(
        "Eq(psi, 2*atan(tan(theta)*sqrt(1 - k**2*sin(theta)**2)))",)),
    "19.11.13": Override("ψ is given by 19.11.14", constraints=(
        "Eq(psi, 2*atan(tan(theta)*sqrt(1 - k**2*sin(theta)**2)))",)),
    "19.11.16": Override("ψ (19.11.14), γ, δ (19.11.17)", constraints=(
        "Eq(psi, 2*atan(tan(theta)*sqrt(1 - k**2*sin(theta)**2)))",
        "Eq(gamma_, (csc(theta)**2 - alpha**2)**2*(csc(psi)**2 - alpha**2))", "Eq(delta, alpha**2*(1 - alpha**2)*(alpha**2 - k**2))")),
    "19.10.1": Override("the principal branches: 0 < x < y (the prose of 19.10(i) restricts the real cases)", constraints=("Lt(0, x)", "Lt(x, y)"), real=("x", "y"), whole=True),
    "19.20.14": Override("q > 0 and p as 19.20.15 gives it", constraints=("Gt(q, 0)", "Eq(p, (z*(x + y + q) - x*y)/(z + q))") + POSITIVE_XYZ),
    "19.20.17": Override("q > 0 and p as 19.20.18 gives it (x = 0)", constraints=("Gt(q, 0)", "Eq(p, z*(y + q)/(z + q))", "Gt(y, 0)", "Gt(z, 0)"),
                         drop_constraints=(r"p=z(y+q)/(z+q)", r"w=z/(z+q)")),
    "19.21.12": Override("q, ξ, η are given by 19.21.13 and x, y, z > 0 (the prose)", constraints=(
        "Eq(q, x + (y - x)*(z - x)/(p - x))", "Eq(xi, y*z/x)", "Eq(eta, p*q/x)") + POSITIVE_XYZ),
    "19.21.14": Override("q, ξ, η as 19.21.13", constraints=("Eq(q, x + (y - x)*(z - x)/(p - x))", "Eq(xi, y*z/x)", "Eq(eta, p*q/x)")),
    "19.25.17": Override("x, y, z as 19.25.18", constraints=("Eq(x, c - 1)", "Eq(y, c - k**2)", "Eq(z, c)", C_PHI)),
    "19.25.18": Override("x, y, z are defined here", kind="definition"),
    "19.25.20": Override("r = 1/x² (the prose)", constraints=("Eq(r, 1/x**2)",)),
    "19.25.21": Override("r = 1/x² (the prose)", constraints=("Eq(r, 1/x**2)",)),
    "19.25.22": Override("r = 1/x² (the prose)", constraints=("Eq(r, 1/x**2)",)),
    **{f"19.25.{n}": Override("φ, k, α² as 19.25.23 gives them", constraints=PHI_K_ALPHA) for n in (24, 25, 26, 27)},
    **{f"19.26.{n}": Override("μ as 19.26.2 gives it; λ, x, y, z > 0 (19.26(i))", constraints=(LAMBDA_MU, "Gt(lamda, 0)") + POSITIVE_XYZ)
       for n in (1, 7, 8)},
    "19.26.9": Override("μ (19.26.2), γ, δ (19.26.10); λ, x, y, z > 0", constraints=(
        LAMBDA_MU, "Gt(lamda, 0)", "Eq(gamma_, p*(p + lamda)*(p + mu))", "Eq(delta, (p - x)*(p - y)*(p - z))") + POSITIVE_XYZ),
    "19.26.11": Override("μ as 19.26.12 gives it; λ, x, y > 0", constraints=(
        "Eq(mu, ((sqrt(x + lamda)*y + sqrt(x)*(y + lamda))/lamda)**2 - x)", "Gt(lamda, 0)", "Gt(x, 0)", "Gt(y, 0)")),
    **{f"19.26.{n}": Override("λ as 19.26.19 gives it", constraints=(LAMBDA_DUP,) + POSITIVE_XYZ) for n in (18, 20, 21)},
    "19.26.22": Override("λ (19.26.19), α, β (19.26.23)", constraints=(
        LAMBDA_DUP, "Eq(alpha, p*(sqrt(x) + sqrt(y) + sqrt(z)) + sqrt(x)*sqrt(y)*sqrt(z))", "Eq(beta_, sqrt(p)*(p + lamda))", "Gt(p, 0)") + POSITIVE_XYZ),
    "19.36.3": Override("z_1, z_2, z_3 as 19.36.4 prints them", constraints=(
        "Eq(z_1, 2.10985990988)", "Eq(z_2, 2.12548490988)", "Eq(z_3, 2.15673490988)")),
    "19.2.8_1": Override(NEW + "; the integral is K′ for |ph k| ≤ π/2 (K′ is continued beyond, 19.2.9)", note=NEW,
                         semantic=OVERRIDES["19.2.8_1"].semantic, constraints=("Le(Abs(arg(k)), pi/2)",)),
    "19.2.8_2": Override(NEW + "; the integral is E′ for |ph k| ≤ π/2 (E′ is continued beyond, 19.2.9)", note=NEW,
                         semantic=OVERRIDES["19.2.8_2"].semantic, constraints=("Le(Abs(arg(k)), pi/2)",)),
    # --- 22
    "22.8.20": Override("z_1 + z_2 + z_3 + z_4 = 0 (22.8.19)", constraints=("Eq(z_4, -z_1 - z_2 - z_3)",)),
    "22.8.21": Override("z_1 + z_2 + z_3 + z_4 = 0 (22.8.19)", constraints=("Eq(z_4, -z_1 - z_2 - z_3)",)),
    "22.8.23": Override("z_1 + z_2 + z_3 + z_4 = 2K (22.8.22)", constraints=("Eq(z_4, 2*K - z_1 - z_2 - z_3)",)),
    "22.8.25": Override("the expression takes one value for z_1 − z_2 = z_2 − z_3 = 2K/3 (22.8.24)", kind="notation"),
    "22.8.27": Override("z_1 − z_2 = z_2 − z_3 = z_3 − z_4 = K/2 (22.8.26)",
                        constraints=("Eq(z_2, z_1 - K/2)", "Eq(z_3, z_1 - K)", "Eq(z_4, z_1 - 3*K/2)")),
    **{f"22.8.{n}": Override("a condition on z_1, ..., z_4 for the next formula: a hypothesis that introduces the "
                             "later z_j, nothing to check", defines=zs)
       for n, zs in ((19, ("z_4",)), (22, ("z_4",)), (24, ("z_2", "z_3")), (26, ("z_2", "z_3", "z_4")))},
    "22.15.5": Override("the principal value for -1 ≤ x ≤ 1 (22.15(ii))", constraints=("Le(-1, x)", "Le(x, 1)"), real=("x", "k")),
    "22.15.6": Override("the principal value for -1 ≤ x ≤ 1 (22.15(ii))", constraints=("Le(-1, x)", "Le(x, 1)"), real=("x", "k")),
    "22.15.7": Override("the principal value for k′ ≤ x ≤ 1 (22.15(ii))", constraints=(f"Le({KP}, x)", "Le(x, 1)"), real=("x", "k")),
    **{f"22.15.{n}": Override("the general solution: m an integer", kind="definition", constraints=("Eq(m, floor(m))",)) for n in (8, 9, 10)},
    **{f"22.14.{n}": Override("Arccos is many-valued (22.14(i)); its principal branch, which the transcription's acos is, "
                              "is the continuous one where sn(x, k) > 0: 0 < x < 2K", constraints=("Gt(x, 0)", "Lt(x, 2*K)"))
       for n in (2, 6)},
    "22.16.30": Override("ξ = x/θ_3²(0, q) (the prose)", constraints=("Eq(xi, x/JacobiTheta3(0, q)**2)",)),
})

PSI_SUM = ("Eq(psi, 2*atan((sin(theta)*sqrt(1 - k**2*sin(phi)**2) + sin(phi)*sqrt(1 - k**2*sin(theta)**2))"
           "/(cos(theta) + cos(phi))))")
PSI_DOUBLE = "Eq(psi, 2*atan(tan(theta)*sqrt(1 - k**2*sin(theta)**2)))"
GAMMA_DELTA = ("Eq(gamma_, (csc(theta)**2 - alpha**2)*(csc(phi)**2 - alpha**2)*(csc(psi)**2 - alpha**2))",
               "Eq(delta, alpha**2*(1 - alpha**2)*(alpha**2 - k**2))")
SECTIONS["19.24"] = {}
OVERRIDES.update({
    "19.11.1": Override("ψ is given by 19.11.3–19.11.4 (read through tan(ψ/2), |ψ| < π)", constraints=(PSI_SUM,)),
    "19.11.2": Override("ψ is given by 19.11.3–19.11.4 (read through tan(ψ/2), |ψ| < π)", constraints=(PSI_SUM,)),
    "19.11.3": Override("ψ is defined by 19.11.3–19.11.4", kind="definition", constraints=(PSI_SUM,)),
    "19.11.4": Override("ψ is defined by 19.11.3–19.11.4", kind="definition", constraints=(PSI_SUM,)),
    "19.11.5": Override("ψ (19.11.3–19.11.4), γ, δ (19.11.6)", constraints=(PSI_SUM,) + GAMMA_DELTA),
    "19.11.6_5": Override("ψ (19.11.3–19.11.4), γ, δ (19.11.6)", constraints=(PSI_SUM,) + GAMMA_DELTA),
    "19.11.14": Override("ψ is defined by 19.11.14–19.11.15", kind="definition", constraints=(PSI_DOUBLE,)),
    "19.11.15": Override("ψ is defined by 19.11.14–19.11.15", kind="definition", constraints=(PSI_DOUBLE,)),
    "19.14.5": Override("φ is defined by this formula and U by 19.14.6", kind="definition"),
    "19.14.6": Override("U is defined by this formula", kind="definition"),
    "19.21.13": Override("q is defined by this formula; ξ, η too", kind="definition"),
    "19.23.8": Override("two variables (b_1, b_2 > 0)", options={"dimension": 2}, note="n = 2"),
    "19.23.9": Override("three variables; l_j as the prose gives them", constraints=(
        "Eq(l_1, sin(theta)*cos(phi))", "Eq(l_2, sin(theta)*sin(phi))", "Eq(l_3, cos(theta))"), note="n = 3"),
    "19.23.10": Override("read for n = 3", note="n = 3"),
    "19.24.5": Override("a_n, g_n are the AGM sequences of 19.8.1", options={"sequences": {"a", "g"}}, whole=True,
                        note="a_n, g_n read as sequences Function(\"a\")(n), Function(\"g\")(n)"),
    "19.24.6": Override("a_n, g_n are the AGM sequences", options={"sequences": {"a", "g"}}, kind="definition"),
    "19.24.9": Override("a_n, g_n are the AGM sequences", options={"sequences": {"a", "g"}},
                        note="a_n, g_n read as sequences Function(\"a\")(n), Function(\"g\")(n)"),
    "19.24.13": Override("read for n = 3", options={"dimension": 3}, note="n = 3"),
    "19.24.14": Override("read for n = 3", options={"dimension": 3}, note="n = 3"),
    "19.32.1": Override("z(p) is a function of p", options={"applied": {"z"}}, kind="definition"),
    "19.32.4": Override("z(p) is a function of p (19.32.1)", options={"applied": {"z"}}),
    "19.36.11": Override("T², M² as 19.36.10 prints them", constraints=("Eq(T, sqrt(1.46971531731))", "Eq(M, sqrt(2.46209302060))")),
    "19.36.9": Override("T, M are the limits of the sequences (the prose)", note="T and M are the common limits of the sequences of 19.36.6"),
})

OVERRIDES.update({
    **{f"22.16.{n}": Override("x = F(φ, k) (22.16.10)", constraints=("Eq(x, EllipticF(phi, k))",)) for n in (11, 12, 13)},
    "22.16.10": Override("x = F(φ, k) defines φ = am(x, k) for 22.16.11-13", kind="definition"),
    **{f"22.15.{n}": Override("ξ, η, ζ are defined by this formula (22.15(i)): it introduces them, nothing to check",
                             kind="definition", defines=(v,)) for n, v in ((1, "xi"), (2, "eta"), (3, "zeta"))},
    **{f"19.26.{n}": Override("μ (or ξ, η, ζ) is defined by this formula", kind="definition") for n in (2, 3, 5, 12)},
    "19.26.14": Override("p, q, ξ, η as 19.26.15 gives them", constraints=(
        "Eq(q, x + (y - x)**2/(p - x))", "Eq(xi, y**2/x)", "Eq(eta, p*q/x)", "Gt(x, 0)", "Gt(y, 0)")),
    "19.26.15": Override("q, ξ, η are defined by this formula", kind="definition"),
})

OVERRIDES.update({
    "19.26.6": Override("μ as 19.26.2 gives it; λ, x, y, z > 0", constraints=(LAMBDA_MU, "Gt(lamda, 0)") + POSITIVE_XYZ),
    "19.26.23": Override("α, β are defined here, λ by 19.26.19", constraints=(LAMBDA_DUP,) + POSITIVE_XYZ + ("Gt(p, 0)",)),
    "19.26.4": Override("ξ, η, ζ and their primes are defined here", kind="definition"),
})
