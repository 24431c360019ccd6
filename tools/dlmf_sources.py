"""The DLMF's chapters 19 and 22 as the importer reads them: LaCASt's semantic LaTeX per
formula (``artifact/dlmf/dlmf-formulae.txt``) and the current text in markdown (numbering,
presentation LaTeX, tables), both from bare git mirrors; and the alignment of the two (the
semantic lines are labelled by the DLMF of 2021, whose unnumbered ``#ExN`` anchors moved
where displays were added since).

Only the standard library; run ``tools/dlmf_import.py``.
"""

from __future__ import annotations

import difflib
import re
import subprocess
from dataclasses import dataclass, field
from pathlib import Path

MIRRORS = Path("/work/.mirror")
ARTIFACT = MIRRORS / "gipplab+LaCASt-Artifact" / "repo"
MARKDOWN = MIRRORS / "Novum-Mathematicum+DLMF-markdown" / "repo"
LACAST = MIRRORS / "gipplab+LaCASt" / "repo"


def git_show(repo: Path, path: str) -> str:
    return subprocess.run(["git", "-C", str(repo), "show", f"HEAD:{path}"], check=True,
                          capture_output=True, text=True).stdout


def git_ls(repo: Path, under: str) -> list[str]:
    out = subprocess.run(["git", "-C", str(repo), "ls-tree", "-r", "--name-only", "HEAD", under],
                         check=True, capture_output=True, text=True).stdout
    return out.split()


# --- LaCASt's semantic lines ------------------------------------------------------------------
@dataclass
class SemanticLine:
    lineno: int
    key: str          # "19.2.E4" or "19.2#Ex1", as LaCASt's url names it
    formula: str      # the semantic LaTeX, as written
    constraints: list[str]
    comments: list[str]

    @property
    def section(self) -> str:
        return re.match(r"(\d+\.\d+)", self.key).group(1)

    @property
    def number(self) -> str | None:
        m = re.fullmatch(r"(\d+\.\d+)\.E(\w+)", self.key)
        return f"{m.group(1)}.{m.group(2)}" if m else None


def braced(text: str, start: int) -> tuple[str, int]:
    """The contents of the brace group opening at ``text[start]`` and the index after it."""
    depth = 0
    for j in range(start, len(text)):
        if text[j] == "{" and (j == 0 or text[j - 1] != "\\"):
            depth += 1
        elif text[j] == "}" and text[j - 1] != "\\":
            depth -= 1
            if depth == 0:
                return text[start + 1:j], j + 1
    raise ValueError(f"unbalanced braces from {start}: {text[start:start + 40]!r}")


def semantic_lines(chapters: tuple[str, ...]) -> list[SemanticLine]:
    out = []
    for n, line in enumerate(git_show(ARTIFACT, "artifact/dlmf/dlmf-formulae.txt").splitlines(), 1):
        m = re.search(r"\\url\{https?://dlmf\.nist\.gov/([^}]*)\}", line)
        if not m or m.group(1).split(".")[0] not in chapters:
            continue
        formula = line[:line.index(r"\url{")].strip()
        tail = line[m.end():]
        cons = [braced(tail, c.end() - 1)[0] for c in re.finditer(r"\\constraint\{", tail)]
        cons += [braced(formula, c.end() - 1)[0] for c in re.finditer(r"\\constraint\{", formula)]
        comments = [braced(tail, c.end() - 1)[0] for c in re.finditer(r"\\comments\{", tail)]
        out.append(SemanticLine(n, m.group(1), formula, cons, comments))
    return out


# --- the markdown text ------------------------------------------------------------------------------
@dataclass
class Display:
    anchors: list[str]
    latex: str                 # presentation LaTeX, \tag and \displaystyle removed
    tag: str | None            # "19.2.4", "19.2.8_1"
    cluster: int               # displays with nothing but anchors between them share a cluster
    notes: list[str] = field(default_factory=list)


@dataclass
class Table:
    anchor: str
    rows: list[list[str]]      # cells, bold markers removed
    caption: str
    notes: list[str] = field(default_factory=list)


@dataclass
class Section:
    number: str
    title: str
    displays: list[Display]
    tables: list[Table]


def _clean_display(latex: str) -> tuple[str, str | None]:
    tag = re.search(r"\\tag\{([^}]*)\}", latex)
    latex = re.sub(r"\s*\\tag\{[^}]*\}", "", latex)
    latex = re.sub(r"\\displaystyle\s*", "", latex)
    return latex.strip(), tag.group(1) if tag else None


def markdown_sections(chapter: str) -> list[Section]:
    files = [f for f in git_ls(MARKDOWN, f"markdown/{chapter}") if re.search(rf"/{chapter}\.\d+\.md$", f)]
    files.sort(key=lambda f: int(re.search(r"\.(\d+)\.md$", f).group(1)))
    return [_section(git_show(MARKDOWN, f)) for f in files]


def _section(text: str) -> Section:
    lines = text.splitlines()
    head = re.match(r"# §(\d+\.\d+) (.*)", lines[0])
    displays: list[Display] = []
    tables: list[Table] = []
    anchors: list[str] = []
    cluster, gap = 0, True
    last = None  # the display or table a note block describes
    i = 0
    while i < len(lines):
        line = lines[i].strip()
        a = re.fullmatch(r'<a id="([^"]+)"></a>', line)
        if a:
            anchors.append(a.group(1))
        elif line == "$$":
            j = i + 1
            while lines[j].strip() != "$$":
                j += 1
            latex, tag = _clean_display("\n".join(lines[i + 1:j]))
            if gap:
                cluster += 1
            displays.append(Display(anchors, latex, tag, cluster))
            last = displays[-1]
            anchors, gap, i = [], False, j
        elif line.startswith(":::{note}"):
            j = i + 1
            while lines[j].strip() != ":::":
                j += 1
            note = "\n".join(lines[i + 1:j])
            if last is not None:
                last.notes.append(note)
            gap, i = True, j
        elif line.startswith("|"):
            j = i
            rows = []
            while j < len(lines) and lines[j].strip().startswith("|"):
                cells = [c.strip() for c in lines[j].strip().strip("|").split("|")]
                if not all(set(c) <= {"-", ":"} for c in cells):
                    rows.append([re.sub(r"^\*\*(.*)\*\*$", r"\1", c) for c in cells])
                j += 1
            caption = ""
            while j < len(lines) and not lines[j].strip():
                j += 1
            if j < len(lines) and lines[j].startswith(": "):
                caption = lines[j][2:].strip()
                while j + 1 < len(lines) and lines[j + 1].strip() and not lines[j + 1].startswith(":::"):
                    j += 1
                    caption += " " + lines[j].strip()
            tables.append(Table(anchors[-1] if anchors else "", rows, caption))
            last = tables[-1]
            anchors, gap, i = [], True, j
        elif line:
            gap = True
        i += 1
    return Section(head.group(1), head.group(2).strip(), displays, tables)


# --- numbered formulas ---------------------------------------------------------------------------------
@dataclass
class Formula:
    number: str                # "19.2.8"
    section: str
    displays: list[Display]
    lines: list[SemanticLine] = field(default_factory=list)

    @property
    def latex(self) -> str:
        return "\n".join(d.latex for d in self.displays)

    @property
    def notes(self) -> list[str]:
        return [n for d in self.displays for n in d.notes]


def numbered(section: Section) -> tuple[list[Formula], list[tuple[Display, Formula | None]]]:
    """The section's numbered formulas, and every display with the formula it belongs to
    (None: an unnumbered display of the prose)."""
    formulas: list[Formula] = []
    owner: list[tuple[Display, Formula | None]] = []
    current: Formula | None = None
    last_cluster = None
    for d in section.displays:
        if d.cluster != last_cluster:
            current = None
        last_cluster = d.cluster
        if d.tag:
            current = Formula(d.tag, section.number, [d])
            formulas.append(current)
        elif current is not None:
            current.displays.append(d)
        owner.append((d, current))
    return formulas, owner


_GREEK = re.compile(r"\\(alpha|beta|gamma|delta|epsilon|varepsilon|zeta|eta|theta|kappa|lambda|mu|nu|"
                    r"xi|pi|rho|sigma|tau|phi|chi|psi|omega|Delta|Gamma|ell|iunit|infty|cpi|prime)\b")


def skeleton(latex: str) -> list[str]:
    """Letters, digits, Greek names and = of a formula, for matching the two prints of it."""
    latex = re.sub(r"\\(operatorname|mathrm|text|url|mbox)\{[^}]*\}", " ", latex)
    out = []
    for m in re.finditer(r"\\[A-Za-z]+|[a-z0-9=]", latex):
        tok = m.group(0)
        if tok.startswith("\\"):
            g = _GREEK.fullmatch(tok)
            if g:
                out.append({"iunit": "i", "cpi": "pi"}.get(g.group(1), g.group(1)))
        else:
            out.append(tok)
    return out


def similarity(a: list[str], b: list[str]) -> float:
    return difflib.SequenceMatcher(None, a, b, autojunk=False).ratio()


def align(section: Section, lines: list[SemanticLine]) -> list[tuple[SemanticLine, Display | None, float]]:
    """Each semantic line of the section with the display it prints (in order; a line
    numbered E-n goes to formula n's displays only)."""
    _, owner = numbered(section)
    disp = [d for d, _ in owner]
    num = [f.number if f else None for _, f in owner]
    sk_d = [skeleton(d.latex) for d in disp]
    sk_l = [skeleton(ln.formula) for ln in lines]
    memo: dict[tuple[int, int], float] = {}
    n, m = len(lines), len(disp)
    NEG = -1e9

    def score(i, j):
        if (i, j) not in memo:
            ln = lines[i]
            if ln.number is not None and ln.number != num[j]:
                memo[i, j] = NEG
            else:
                memo[i, j] = similarity(sk_l[i], sk_d[j]) + (1.0 if ln.number is not None else 0.0)
        return memo[i, j]

    best = [[0.0] * (m + 1) for _ in range(n + 1)]
    move = [[""] * (m + 1) for _ in range(n + 1)]
    for i in range(n + 1):
        for j in range(m + 1):
            if i == 0 and j == 0:
                continue
            cands = []
            if j > 0:
                cands.append((best[i][j - 1], "skipd"))
            if i > 0:
                cands.append((best[i - 1][j] - 0.2 - (5 if lines[i - 1].number else 0), "skipl"))
            if i > 0 and j > 0:
                s = score(i - 1, j - 1)
                if s > NEG / 2 and s > 0.3:
                    cands.append((best[i - 1][j - 1] + s, "match"))
            best[i][j], move[i][j] = max(cands)
    out = []
    i, j = n, m
    while i > 0 or j > 0:
        mv = move[i][j]
        if mv == "match":
            out.append((lines[i - 1], disp[j - 1], score(i - 1, j - 1)))
            i, j = i - 1, j - 1
        elif mv == "skipl":
            out.append((lines[i - 1], None, 0.0))
            i -= 1
        else:
            j -= 1
    return out[::-1]
