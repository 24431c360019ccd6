#!/usr/bin/env python3
"""Write the identity texts ``quasicentral/texts/dlmf-19`` and ``quasicentral/texts/dlmf-22`` from the DLMF.

Every numbered formula of DLMF chapters 19 and 22 (the current text: the markdown mirror)
and every entry of Tables 22.4.1–22.5.4 becomes one catalog entry, its transcription read
from the DLMF's semantic LaTeX (LaCASt's data set) by :mod:`quasicentral.notation.semantic`.
What the reader cannot do from the LaTeX alone — a notation the prose defines, the limit of an
O-term, a formula added to the DLMF since 2021 — is stated per label in ``dlmf_overrides``,
with its reason; the output is never edited by hand.  The files are written sorted and
byte-identical on every run.

    PYTHONPATH=. python3 tools/dlmf_import.py            # writes quasicentral/texts/dlmf-19, dlmf-22
    PYTHONPATH=. python3 tools/dlmf_import.py --check    # exits 1 if the files would change
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path[:0] = [str(HERE), str(ROOT)]

from dlmf_overrides import (CHAPTER_WHERE, CHAPTERS, CONVENTIONS, INTEGER_NAMES, INTEGER_SYMBOL, MOVED, OVERRIDES,  # noqa: E402
                            SECTIONS, SYMBOL_DEFAULT, SYMBOL_LATEX, Override)
from dlmf_sources import Formula, align, markdown_sections, numbered, semantic_lines  # noqa: E402
from dlmf_tables import table_entries  # noqa: E402

from quasicentral.notation.semantic import Limit, Options, SemanticLatexError, read  # noqa: E402
from quasicentral.notation.semantic.constraints import read_constraint  # noqa: E402

KINDS = ("identity", "definition", "inequality", "series", "asymptotic", "notation")


@dataclass
class Entry:
    id: str
    number: str
    name: str
    latex: str
    printed: str
    url: str
    kind: str
    semantic: str = ""
    constraints: list[str] = field(default_factory=list)
    real: list[str] = field(default_factory=list)
    defines: list[str] = field(default_factory=list)
    note: str = ""
    symbols: set[str] = field(default_factory=set)
    overridden: str = ""   # why the reader's reading was replaced or steered ("" = read as is)
    read_fully: bool = True


# --- one numbered formula ----------------------------------------------------------------------
def options_for(number: str, section: str, ov: Override | None) -> Options:
    base = dict(SECTIONS.get(section, {}).get("options", {}))
    if ov and ov.options:
        for key, value in ov.options.items():
            if isinstance(value, dict):
                base[key] = {**base.get(key, {}), **value}
            elif isinstance(value, (set, frozenset)):
                base[key] = set(base.get(key, set())) | set(value)
            else:
                base[key] = value
    return Options(**base)


def read_lines(number: str, latexes: list[str], opts: Options, limits: list[Limit | None],
               bindings: tuple[dict, ...], sign: int | None = None) -> tuple[list[str], set[str], list[str]]:
    """The relations of a formula's semantic lines (once per binding of its generic letters)."""
    relations: list[str] = []
    symbols: set[str] = set()
    notes: list[str] = []
    for binding in bindings or ({},):
        o = Options(**{**opts.__dict__, "letters": {**opts.letters, **binding}})
        for latex, limit in zip(latexes, limits):
            if limit is not None and r"\bigO" in latex and o.order is None:
                o2 = Options(**{**o.__dict__, "order": (limit.var, limit.point)})
            else:
                o2 = o
            try:
                r = read(latex, o2, limit, sign)
            except SemanticLatexError as exc:
                raise SystemExit(f"{number}: {exc}\n   {latex}")
            relations += [x for x in r.relations if x not in relations]
            symbols |= r.symbols
            notes += r.notes
    return relations, symbols, notes


def line_constraints(number: str, line, ov: Override | None, opts: Options):
    rels, real, limits = [], set(), []
    for c in line.constraints:
        if ov and (c in ov.drop_constraints or ov.constraints_only is not None):
            continue
        # with vectors of a fixed length, a constraint on z_j holds for each j
        indices = range(1, opts.dimension + 1) if opts.dimension and re.search(r"_\{j\}", c) else [None]
        for j in indices:
            o = opts if j is None else Options(**{**opts.__dict__, "letters": {**opts.letters, "j": str(j)}})
            try:
                cr = read_constraint(c, o)
            except SemanticLatexError as exc:
                raise SystemExit(f"{number}: constraint {c!r}: {exc} (add it to drop_constraints)")
            rels += cr.relations
            real |= cr.real
            limits += cr.limits
    return rels, real, limits


def build(f: Formula, chapter: str) -> list[Entry]:
    ov = OVERRIDES.get(f.number)
    opts = options_for(f.number, f.section, ov)
    lines = f.lines
    semantic = [ln.formula for ln in lines]
    per_line = [line_constraints(f.number, ln, ov, opts) for ln in lines]
    # lines whose constraints differ are separate entries (-a, -b, ...)
    groups: list[list[int]] = []
    for i, (rels, _, _) in enumerate(per_line):
        if groups and per_line[groups[-1][0]][0] == rels:
            groups[-1].append(i)
        else:
            groups.append([i])
    if ov and (ov.semantic is not None or ov.printed is not None or ov.split):
        groups = [list(range(len(lines)))]
    if len(groups) > 1 and not (ov and ov.whole):
        parts = [(chr(ord("a") + g), [semantic[i] for i in grp], [per_line[i] for i in grp])
                 for g, grp in enumerate(groups)]
    else:
        parts = [("", semantic, per_line)]
    out = []
    for suffix, latexes, cons in parts:
        out += _entries(f, chapter, ov, opts, suffix, latexes, cons)
    for e in out:
        if f.number in MOVED_NOTES and MOVED_NOTES[f.number] not in e.note:
            e.note = "; ".join(x for x in (e.note, MOVED_NOTES[f.number]) if x)
    return out


def _entries(f, chapter, ov, opts, suffix, latexes, cons) -> list[Entry]:
    constraints = [c for rels, _, _ in cons for c in rels]
    real = {r for _, rs, _ in cons for r in rs}
    limits = [(ls[0] if ls else None) for _, _, ls in cons]
    if ov and ov.limit:
        limits = [ov.limit] * len(latexes)
    notes: list[str] = []
    read_fully = True
    semantic_out = "\n".join(latexes)
    if ov and ov.semantic is not None:
        latexes, limits, semantic_out = list(ov.semantic), [ov.limit] * len(ov.semantic), ""
        read_fully = False
    if ov and ov.printed is not None:
        relations = list(ov.printed)
        symbols = {w for t in relations for w in re.findall(r"\b[A-Za-z][A-Za-z0-9_]*\b", t)}
        read_fully = False
    elif ov and ov.split:
        relations, symbols = [], set()
    else:
        relations, symbols, notes = read_lines(f.number, latexes, opts, limits, ov.expand if ov else ())
    if ov:
        if ov.constraints_only is not None:
            constraints = list(ov.constraints_only)
        else:
            constraints += list(ov.constraints)
        real |= set(ov.real)
    where = {**CHAPTER_WHERE[chapter], **SECTIONS.get(f.section, {}).get("where", {})}
    add_where(constraints, relations, where)
    kind = ov.kind if ov and ov.kind else classify(relations, f) if relations else "identity"
    note = "; ".join(dict.fromkeys(notes + ([ov.note] if ov and ov.note else [])))
    number = f.number
    sec_num, eq = number.rsplit(".", 1)[0], number.split(".", 2)[2]
    base = Entry(
        id=f"{CHAPTERS[chapter]['id']}:{number}" + (f"-{suffix}" if suffix else ""), number=number,
        name=(ov.name if ov and ov.name else name_for(relations, kind) if relations else ""),
        latex=f.latex, printed=_join(relations) if relations else "", url=f"https://dlmf.nist.gov/{sec_num}.E{eq}",
        kind=kind, semantic=semantic_out, constraints=list(dict.fromkeys(constraints)), real=sorted(real),
        defines=list(ov.defines) if ov else [], note=note, symbols=symbols, overridden=(ov.reason if ov else ""), read_fully=read_fully)
    if not (ov and ov.split):
        _symbols_of_constraints(base)
        return [base]
    out = []
    for part_suffix, part in ov.split.items():
        if part.semantic:
            rels, syms, pnotes = read_lines(number, list(part.semantic), opts, [None] * len(part.semantic), (), part.sign)
        else:
            rels, syms, pnotes = list(part.printed), set(), []
        e = Entry(**{**base.__dict__, "id": f"{base.id}-{part_suffix}", "printed": _join(rels),
                     "constraints": base.constraints + list(part.constraints), "symbols": set(syms),
                     "name": part.name or base.name or name_for(rels, kind),
                     "kind": ov.kind or classify(rels, f)})
        e.note = "; ".join(x for x in (e.note, *pnotes) if x)
        _symbols_of_constraints(e)
        out.append(e)
    return out


def apply_convention(e: Entry, chapter: str, section: str) -> None:
    """The chapter's notation section's domains (:data:`CONVENTIONS`) on an entry that uses the
    symbol and does not bound it itself."""
    conv = CONVENTIONS.get(chapter)
    if conv is None or section in conv.except_sections:
        return
    used = _free_names([e.printed] + e.constraints)
    for sym, bounds in conv.bounds.items():
        own = any(re.match(rf"(?:Lt|Le|Gt|Ge)\((?:{sym}, |[^,]*, {sym}\))", c) for c in e.constraints)
        if sym in used and not own:
            e.constraints += [b for b in bounds if b not in e.constraints]
    e.real = sorted(set(e.real) | {s for s in conv.real if s in used})


#: The domains DLMF's prose states for ranges of formulas ("In (19.25.9)–(19.25.11) x, y, z
#: are positive"), read section by section and written as constraints: ``dlmf_domains.json``
#: (its ``kind``: ``prose`` stated, ``implied`` a parenthetical or inferred domain, ``note`` a
#: remark — a Cauchy principal value's region is a note and not a domain to sample; ``default``
#: the chapter's notation section, which :data:`CONVENTIONS` applies).
DOMAINS = json.loads((HERE / "dlmf_domains.json").read_text(encoding="utf-8"))
#: the reading's names for what the domains write in sympy's own
_DOMAIN_NAMES = [(r"elliptic_k\(1 - k\*\*2\)", "EllipticKp(k)"), (r"elliptic_k\(k\*\*2\)", "EllipticK(k)"),
                 (r"Symbol\('beta'\)", "beta_"), (r"Symbol\('gamma'\)", "gamma_"), (r"Symbol\('(\w+)'\)", r"\1"),
                 (r"\bkp\b", "sqrt(1 - k**2)"), (r"\bcs\(", "JacobiCS(")]
_ORDER = re.compile(r"(?:Lt|Le|Gt|Ge)\(")


def _domain_constraints(c: str) -> list[str]:
    """One domain constraint in the catalog's transcription ([] for one it has no reading of)."""
    for pat, rep in _DOMAIN_NAMES:
        c = re.sub(pat, rep, c)
    m = re.fullmatch(r"Contains\((\w+), S\.(Integers|Naturals0)\)", c)
    if m:
        return [f"Eq({m.group(1)}, floor({m.group(1)}))"] + ([f"Ge({m.group(1)}, 0)"] if m.group(2) == "Naturals0" else [])
    return [] if re.search(r"\bwp\(|Contains|\bS\.", c) else [c]


def apply_prose_domains(e: Entry, number: str) -> None:
    """The domains DLMF's prose states for this formula (:data:`DOMAINS`); a symbol an order
    relation bounds (outside re, im, Abs) is real."""
    used, before = _free_names([e.printed] + e.constraints), _free_names(e.constraints)
    for d in DOMAINS:
        if number not in d["formulas"] or d["kind"] == "default" or (
                d["kind"] == "note" and "principal value" in d["note"]):
            continue
        for c in (x for raw in d["constraints"] for x in _domain_constraints(raw)):
            names = _free_names([c])
            defined = _DEFINED_LHS.match(c)
            if not names or not (defined.group(1) in used if defined else names <= used):
                continue
            if defined and defined.group(1) in before:
                continue  # the entry says already how that symbol is obtained (defines or bounds it)
            if c not in e.constraints:
                e.constraints.append(c)
            if _ORDER.match(c) and not re.search(r"\b(?:re|im|Abs|arg)\(", c):
                e.real = sorted(set(e.real) | names)
        e.real = sorted(set(e.real) | {r.split("*")[0] for r in d["real"]} & used)


def _free_names(transcriptions: list[str]) -> set[str]:
    """The symbols a point must give values to (a limit's or a sum's variable is bound)."""
    import sympy as sp

    out: set[str] = set()
    for t in transcriptions:
        if not t:
            continue
        names = names_in(t)
        local = {n: sp.Function(n) for n in names[1]} | {n: sp.Symbol(n) for n in names[0]}
        local |= {n: getattr(sp, n) for n in ("Limit", "Sum", "Product", "Integral", "Derivative", "Eq", "Lt", "Le",
                                              "Gt", "Ge", "Ne", "Abs", "sqrt", "oo", "I", "pi")}
        try:
            read = sp.sympify(t, locals=local)
            out |= {str(x) for r in (read if isinstance(read, (list, tuple)) else [read]) for x in r.free_symbols}
        except (sp.SympifyError, TypeError, SyntaxError, AttributeError):
            out |= set(names[0])
    return out


def add_where(constraints: list[str], relations: list[str], where: dict[str, str]) -> None:
    """Add the definitions ``where`` of the symbols the relations use, unless the entry
    defines the symbol itself (repeatedly: a definition may use another defined symbol)."""
    changed = True
    while changed:
        changed = False
        used = set(names_in(" ".join(relations + constraints))[0])
        for sym, c in where.items():
            defined = any(x.startswith(f"Eq({sym}, ") for x in constraints)
            if sym in used and not defined:
                constraints.append(c)
                changed = True


def names_in(text: str) -> tuple[list[str], list[str]]:
    """The symbols and the function names of a transcription (sympy syntax)."""
    import io
    import tokenize

    symbols, functions = [], []
    toks = [t for t in tokenize.generate_tokens(io.StringIO(text).readline)
            if t.type not in (tokenize.NEWLINE, tokenize.NL, tokenize.ENDMARKER)]
    for i, t in enumerate(toks):
        if t.type != tokenize.NAME:
            continue
        if i > 0 and toks[i - 1].string == ".":
            continue
        nxt = toks[i + 1].string if i + 1 < len(toks) else ""
        (functions if nxt == "(" else symbols).append(t.string)
    return ([s for s in dict.fromkeys(symbols) if s not in _CONSTANTS],
            list(dict.fromkeys(functions)))


_CONSTANTS = {"pi", "I", "oo", "True", "False"}


def _symbols_of_constraints(e: Entry) -> None:
    e.symbols = set(names_in(" ".join(e.constraints + [e.printed]))[0]) | set(e.defines)


_HEADS = {"Eq", "Ne", "Lt", "Le", "Gt", "Ge", "And", "Or", "Abs", "re", "im", "arg", "floor",
          "sqrt", "sin", "cos", "tan", "csc", "sec", "cot", "log", "exp", "pi", "I", "oo", "Max", "Min",
          "EllipticNome", "EllipticK", "EllipticKp", "sign"}


def _join(relations: list[str]) -> str:
    return relations[0] if len(relations) == 1 else "[" + ", ".join(relations) + "]"


_DEFINED_LHS = re.compile(r"Eq\((?:\d+\*)?(?:(?:sin|cos|tan)\()?([A-Za-z][A-Za-z0-9_]*)\)?(?:\*\*2)?, ")


def classify(relations: list[str], f: Formula) -> str:
    """identity, unless no relation is printed (notation), one is an order (inequality), the
    DLMF marks the formula as defining a symbol or every relation gives one symbol (sin ψ = …,
    2φ_2 = …) in terms of others (definition), an O-term or a limit at infinity (asymptotic),
    or an infinite sum or product (series)."""
    text = " ".join(relations)
    if not any(re.match(r"(Eq|Ne|Lt|Le|Gt|Ge)\(", r) for r in relations):
        return "notation"
    if any(re.match(r"(Lt|Le|Gt|Ge)\(", r) for r in relations):
        return "inequality"

    def gives_symbol(r: str) -> bool:
        m = _DEFINED_LHS.match(r)
        return bool(m) and not re.search(rf"\b{m.group(1)}\b", _sides(r)[1])
    if any("**Defines:**" in n for n in f.notes) or all(gives_symbol(r) for r in relations):
        return "definition"
    if "O(" in text or "Limit(" in text and ", oo" in text:
        return "asymptotic"
    if "Sum(" in text or "Product(" in text:
        return "series"
    return "identity"


READABLE = {
    "EllipticK": "K", "EllipticE": "E", "EllipticF": "F", "EllipticD": "D", "EllipticPi": "Π",
    "EllipticKp": "K′", "EllipticEp": "E′", "CarlsonRF": "R_F", "CarlsonRD": "R_D", "CarlsonRJ": "R_J",
    "CarlsonRC": "R_C", "CarlsonRG": "R_G", "CarlsonR": "R_−a", "BulirschCel": "cel", "BulirschEl1": "el1",
    "BulirschEl2": "el2", "BulirschEl3": "el3", "AGM": "AGM", "JacobiAM": "am", "JacobiEpsilon": "ℰ",
    "JacobiZ": "Z", "EllipticNome": "the nome", "hyper": "₂F₁", "appellf1": "F₁",
    "WeierstrassP": "℘", "WeierstrassZeta": "ζ", "WeierstrassSigma": "σ",
    **{f"JacobiTheta{j}": f"θ{j}" for j in "1234"},
    **{f"Jacobi{p.upper()}": p for p in ("sn", "cn", "dn", "ns", "nc", "nd", "sc", "sd", "cs", "cd", "ds", "dc")},
    **{f"JacobiArc{p.upper()}": f"arc{p}" for p in ("sn", "cn", "dn", "ns", "nc", "nd", "sc", "sd", "cs", "cd", "ds", "dc")},
}
_FUNC = re.compile(r"\b(" + "|".join(sorted(READABLE, key=len, reverse=True)) + r")\(")


def _sides(rel: str) -> tuple[str, str]:
    inner = rel[rel.index("(") + 1:-1]
    depth = 0
    for i, c in enumerate(inner):
        if c in "([":
            depth += 1
        elif c in ")]":
            depth -= 1
        elif c == "," and depth == 0:
            return inner[:i], inner[i + 1:]
    return inner, ""


def name_for(relations: list[str], kind: str) -> str:
    """A short name made from the transcription (never from DLMF's prose)."""
    first = relations[0]
    heads = lambda s: list(dict.fromkeys(READABLE[m] for m in _FUNC.findall(s)))  # noqa: E731
    syms = lambda s: [n for n in names_in(s)[0] if not n.startswith("_")][:3]  # noqa: E731
    if kind == "notation":
        h = heads(first)
        return f"notation: {', '.join(h)}" if h else f"an expression in {', '.join(syms(first))}"
    lhs, rhs = _sides(first)
    rhs_all = " ".join(_sides(r)[1] for r in relations)
    lh = heads(lhs)
    subject = lh[0] if lh else (lhs.strip() if re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", lhs.strip()) else "")
    if kind == "inequality":
        inner = heads(" ".join(relations))
        return f"bounds for {', '.join(inner[:2])}" if inner else f"an inequality in {', '.join(syms(first))}"
    if kind == "definition" and subject and not lh:
        return f"{subject} defined"
    if not subject:
        h = heads(first)
        return (f"a relation of {', '.join(h[:3])}" if h else f"a relation of {', '.join(syms(lhs) or syms(first))}")
    if "Integral(" in rhs_all:
        return f"{subject} as an integral"
    if "Sum(" in rhs_all or "Product(" in rhs_all:
        return f"{subject} as a series" if "Sum(" in rhs_all else f"{subject} as a product"
    if "O(" in rhs_all:
        return f"{subject}: leading terms"
    if "Limit(" in first:
        return f"a limit of {subject}"
    if lh and re.fullmatch(r"[A-Za-z]+\(([-0-9./*I pi]+,?\s*)+(k|[a-z]\w*)?\)", lhs.strip()):
        return f"{subject} at a special argument"
    others = [h for h in heads(rhs_all) if h != subject]
    if others:
        return f"{subject} in terms of {', '.join(others[:3])}"
    if subject in heads(rhs_all):
        return f"a transformation of {subject}"
    return f"{subject} in elementary terms"


# --- the chapters --------------------------------------------------------------------------
def formulas(chapter: str) -> tuple[list, dict]:
    sections = markdown_sections(chapter)
    lines = semantic_lines((chapter,))
    by_section: dict[str, list] = {}
    moved = {}
    for ln in lines:
        target = MOVED.get(ln.key)
        if target:  # renumbered since LaCASt's data: attached by its new number
            ln.key = target[0]
            moved[ln.number] = ln
            continue
        by_section.setdefault(ln.section, []).append(ln)
    out = []
    titles = {}
    for s in sections:
        titles[s.number] = s.title
        fs, _ = numbered(s)
        pairs = align(s, by_section.get(s.number, []))
        owner = {id(d): f for f in fs for d in f.displays}
        for ln, d, score in pairs:
            if d is not None and id(d) in owner and not (ln.number is None and score < 0.5):
                owner[id(d)].lines.append(ln)
        for f in fs:
            if f.number in moved:
                f.lines.append(moved[f.number])
        out += fs
    return out, titles, {s.number: s for s in sections}


MOVED_NOTES = {new.replace(".E", "."): note for new, note in MOVED.values()}


def build_chapter(chapter: str):
    fs, titles, sections = formulas(chapter)
    entries: list[tuple[str, Entry]] = []
    missing = []
    for f in fs:
        ov = OVERRIDES.get(f.number)
        if not f.lines and not (ov and (ov.semantic is not None or ov.printed is not None or ov.split)):
            missing.append(f.number)
            continue
        for e in build(f, chapter):
            apply_convention(e, chapter, f.section)
            apply_prose_domains(e, f.number)
            entries.append((f.section, e))
    if missing:
        raise SystemExit(f"formulas without semantic LaTeX and without an override: {missing}")
    if chapter == "22":
        for t in table_entries(sections["22.4"], sections["22.5"]):
            sec = t.pop("table").rsplit(".", 1)[0]
            ov = OVERRIDES.get(t["id"].split(":", 1)[1])
            e = Entry(id=t["id"], number=t["number"], name=t["name"], latex=t["latex"], printed=t["printed"],
                      url=t["url"], kind=t["kind"], note=t.get("note", ""))
            if ov:
                if ov.printed is not None:
                    e.printed, e.read_fully = _join(list(ov.printed)), False
                e.constraints += list(ov.constraints)
                e.note = "; ".join(x for x in (e.note, ov.note) if x)
                e.overridden = ov.reason
            add_where(e.constraints, [e.printed], CHAPTER_WHERE[chapter])
            _symbols_of_constraints(e)
            apply_convention(e, chapter, sec)
            entries.append((sec, e))
    return entries, titles, fs


# --- writing ---------------------------------------------------------------------------------
def toml_str(s: str) -> str:
    if "\n" in s or "\\" in s or '"' in s:
        if "'''" not in s and not s.endswith("'"):
            return f"'''{s}'''"
    return json.dumps(s, ensure_ascii=False)


def toml_list(items: list[str]) -> str:
    return "[" + ", ".join(json.dumps(i, ensure_ascii=False) for i in items) + "]"


def write_catalog(section: str, title: str, entries: list[Entry]) -> str:
    out = [f"section = {toml_str(section)}", f"title = {toml_str(title)}", ""]
    for e in entries:
        out.append("[[equation]]")
        out.append(f"id = {toml_str(e.id)}")
        out.append(f"number = {toml_str(e.number)}")
        out.append(f"name = {toml_str(e.name)}")
        out.append(f"latex = {toml_str(e.latex)}")
        if e.semantic:
            out.append(f"semantic = {toml_str(e.semantic)}")
        out.append(f"printed = {toml_str(e.printed)}")
        if e.constraints:
            out.append(f"constraints = {toml_list(e.constraints)}")
        if e.real:
            out.append(f"real = {toml_list(e.real)}")
        if e.defines:
            out.append(f"defines = {toml_list(e.defines)}")
        out.append(f"url = {toml_str(e.url)}")
        out.append(f"kind = {toml_str(e.kind)}")
        if e.note:
            out.append(f"note = {toml_str(e.note)}")
        out.append("")
    return "\n".join(out)


def write_text(chapter: str, symbols: dict[str, dict]) -> str:
    meta = CHAPTERS[chapter]
    out = [f"id = {toml_str(meta['id'])}", f"title = {toml_str(meta['title'])}",
           f"authors = {toml_list(meta['authors'])}", 'language = "en"',
           f"citation = {toml_str(meta['citation'])}", 'check = "identity"', ""]
    for name in sorted(symbols, key=lambda n: (n.lower(), n)):
        s = symbols[name]
        out.append(f"[symbols.{name}]")
        out.append(f"latex = {toml_str(s['latex'])}")
        out.append(f"assumptions = {toml_list(s['assumptions'])}")
        if "definition" in s:
            out.append(f"definition = {toml_str(s['definition'])}")
        else:
            out.append(f"range = {toml_list(s['range'])}")
        out.append("")
    return "\n".join(out)


def symbol_latex(name: str) -> str:
    """The LaTeX of a symbol, spelled back from the reader's naming: ``k_c`` → ``k_{c}``,
    ``s_1_3__4`` → ``s_{1,3}^{(4)}``, ``ap`` → ``a^{\\prime}``, ``alpha_1`` → ``\\alpha_{1}``."""
    from quasicentral.notation.semantic.macros import GREEK

    if name in SYMBOL_LATEX:
        return SYMBOL_LATEX[name]
    rev = {v: k for k, v in GREEK.items()}
    base, _, label = name.partition("__")
    head, *subs = base.split("_")

    def tex(p: str) -> str:
        if p in rev:
            return "\\" + rev[p]
        for g in sorted(rev, key=len, reverse=True):  # U_alphabeta: \alpha\beta
            if len(g) > 1 and p.startswith(g):
                return "\\" + rev[g] + (" " + tex(p[len(g):]) if p[len(g):] else "")
        return p

    if head not in rev and head.endswith("p") and len(head) > 1:
        head_tex = "{" + tex(head[:-1]) + r"^{\prime}}"
    else:
        head_tex = tex(head)
    subs = [{"plus": "+", "minus": "-"}.get(x, tex(x)) for x in subs if x]
    out = head_tex + (("_{" + ",".join(subs) + "}") if subs else "")
    return out + (f"^{{({label})}}" if label else "")


def symbol_table(entries: list[Entry]) -> dict[str, dict]:
    names: set[str] = set()
    for e in entries:
        names |= e.symbols
    out = {}
    for n in sorted(names):
        spec = dict(INTEGER_SYMBOL if n in INTEGER_NAMES else SYMBOL_DEFAULT)
        out[n] = {"latex": symbol_latex(n), **spec}
    return out


def render(chapter: str, out: Path) -> tuple[list[Entry], dict[Path, str]]:
    """The entries of a chapter and the text of each file of its folder under ``out``."""
    entries, titles, _ = build_chapter(chapter)
    folder = out / CHAPTERS[chapter]["id"]
    files: dict[Path, str] = {}
    by_section: dict[str, list[Entry]] = {}
    for sec, e in entries:
        by_section.setdefault(sec, []).append(e)
    for sec, es in by_section.items():
        files[folder / "catalog" / f"{sec}.toml"] = write_catalog(sec, titles[sec], es)
    files[folder / "text.toml"] = write_text(chapter, symbol_table([e for _, e in entries]))
    return [e for _, e in entries], files


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true", help="exit 1 if a file would change")
    ap.add_argument("--out", default=str(ROOT / "quasicentral" / "texts"))
    args = ap.parse_args(argv)
    changed = []
    for chapter in ("19", "22"):
        _, files = render(chapter, Path(args.out))
        folder = Path(args.out) / CHAPTERS[chapter]["id"]
        for path, text in sorted(files.items()):
            old = path.read_text(encoding="utf-8") if path.exists() else None
            if old != text:
                changed.append(path)
                if not args.check:
                    path.parent.mkdir(parents=True, exist_ok=True)
                    path.write_text(text, encoding="utf-8")
        for stale in sorted((folder / "catalog").glob("*.toml")) if folder.exists() else []:
            if stale not in files:
                changed.append(stale)
                if not args.check:
                    stale.unlink()
    if args.check and changed:
        print("would change:", *map(str, changed), sep="\n  ")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
