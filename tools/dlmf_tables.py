"""The tables of DLMF §22.4 and §22.5, entry by entry, read with the semantic reader.

Each cell is a fact about one Jacobian function f (modulus k suppressed, as the tables say):

* 22.4.1/22.4.2: f's two periods (``f(z + ω) = f(z)``) and one pole (``1/f → 0``) or zero;
* 22.4.3: f(z + shift) in terms of another function of z;
* 22.5.1: f's value and z-derivative at a point, or — at a pole — ``∞`` and the residue;
* 22.5.2: f's value at a point;
* 22.5.3/22.5.4: the limit of f(z, k) as k → 0 and as k → 1−.

Ids: ``dlmf-22:22.4.1-sn-periods``, ``-sn-pole``; ``22.4.2-sn-zero``; ``22.4.3-sn-K+iKp`` (the
shift); ``22.5.1-sn-2K``; ``22.5.2-cn-K-half`` (z = K/2), ``-K+iKp-3half`` (z = 3(K+iK′)/2);
``22.5.3-sn``.  The latex of an entry is composed of the cell and its row and column heads.
"""

from __future__ import annotations

import re

from quasicentral.notation.semantic import Options, read

PRES = Options(modulus="k")


def _math(cell: str) -> list[str]:
    """The formulas of a cell: ``$4K$ , $2iK^{\\prime}$`` → [``4K``, ``2iK^{\\prime}``]."""
    return [m.strip() for m in re.findall(r"\$([^$]*)\$", cell)]


def _slug(latex: str) -> str:
    return latex.replace(r"^{\prime}", "p").replace(" ", "").replace("\\", "")


def _fn(cell: str) -> str:
    return re.search(r"\\operatorname\{(\w\w)\}", cell).group(1)


def _r(latex: str) -> str:
    return read(latex, PRES).transcription


def _entry(eid, table, name, latex, printed, note=""):
    out = {"id": f"dlmf-22:{eid}", "number": f"Table {table}", "name": name, "latex": latex,
           "printed": printed, "url": f"https://dlmf.nist.gov/{table.rsplit('.', 1)[0]}.T{table.rsplit('.', 1)[1]}",
           "kind": "identity", "table": table}
    if note:
        out["note"] = note
    return out


def periods_and_points(table, t, what: str) -> list[dict]:
    """Tables 22.4.1 (poles) and 22.4.2 (zeros)."""
    out = []
    points = [_math(c)[0] for c in t.rows[1][:4]]
    for row in t.rows[2:]:
        periods = _math(row[0])
        for col, cell in enumerate(row[1:5]):
            f = _fn(cell)
            eqs = [rf"\operatorname{{{f}}}\left(z+{w}\right)=\operatorname{{{f}}}\left(z\right)" for w in periods]
            out.append(_entry(f"{table}-{f}-periods", table, f"{f} has the periods {', '.join(periods)}",
                              r",\quad ".join(eqs), "[" + ", ".join(_r(e) for e in eqs) + "]"))
            p = points[col]
            if what == "pole":
                printed = _r(rf"\lim_{{z\to {p}}}\frac{{1}}{{\operatorname{{{f}}}z}}=0")
                latex = rf"\operatorname{{{f}}}\left({p}\right)=\infty"
            else:
                printed = _r(rf"\operatorname{{{f}}}\left({p}\right)=0")
                latex = rf"\operatorname{{{f}}}\left({p}\right)=0"
            out.append(_entry(f"{table}-{f}-{what}", table, f"{f} has a {what} at z = {p}", latex, printed,
                              "a pole p read as 1/f(z) -> 0 as z -> p" if what == "pole" else ""))
    return out


def shifts(t) -> list[dict]:
    """Table 22.4.3: f(z + shift) = cell."""
    out = []
    heads = [_math(c)[0] for c in t.rows[1][1:]]
    for row in t.rows[2:]:
        f = _fn(row[0])
        for head, cell in zip(heads, row[1:]):
            rhs = _math(cell)[0]
            latex = rf"\operatorname{{{f}}}\left({head}\right)={rhs}"
            shift = head.removeprefix("z+")
            out.append(_entry(f"22.4.3-{f}-{_slug(shift)}", "22.4.3", f"{f}(z + {shift}) in terms of z", latex, _r(latex)))
    return out


def values(t) -> list[dict]:
    """Table 22.5.1: value and derivative, or pole and residue, at z = mK + niK′."""
    out = []
    points = [_math(c)[0] for c in t.rows[1][1:]]
    for row in t.rows[2:]:
        f = _fn(row[0])
        for p, cell in zip(points, row[1:]):
            parts = _math(cell)
            parts = parts[0].split(",") if len(parts) == 1 else parts
            a, b = (x.strip() for x in parts)
            fz = rf"\operatorname{{{f}}}z"
            if a == r"\infty":
                rels = [_r(rf"\lim_{{z\to {p}}}\frac{{1}}{{{fz}}}=0"),
                        _r(rf"\lim_{{z\to {p}}}(z-({p})){fz}={b}")]
                name, note = f"{f} at z = {p}: a pole and its residue", "a pole p read as 1/f(z) -> 0; the residue as the limit of (z - p) f(z)"
            else:
                rels = [_r(rf"\operatorname{{{f}}}\left({p}\right)={a}"),
                        _r(rf"\lim_{{z\to {p}}}\deriv{{}}{{z}}{fz}={b}")]
                name, note = f"{f} at z = {p}: value and derivative", "the derivative at p read as the limit of f'(z) as z -> p"
            out.append(_entry(f"22.5.1-{f}-{_slug(p) or '0'}", "22.5.1", name,
                              rf"z={p}:\ {fz},\ \frac{{d}}{{dz}}{fz}={cell.replace('$', '')}",
                              "[" + ", ".join(rels) + "]", note))
    return out


def other_values(t) -> list[dict]:
    """Table 22.5.2: sn, cn, dn at halves and three-halves of K, K + iK′, iK′."""
    out = []
    block = None
    for row in t.rows[1:]:
        if row[0] == "":
            if any("frac" in c for c in row):
                block = [_math(c)[0] if "$" in c else c for c in row[1:]]
            continue
        f = _fn(row[0])
        for p, cell in zip(block, row[1:]):
            latex = rf"\operatorname{{{f}}}\left({p}\right)={cell.strip('$')}"
            m = re.fullmatch(r"\\frac\{(\d)\}\{2\}\(?(.*?)\)?", p)
            where = (_slug(m.group(2)) + ("-half" if m.group(1) == "1" else "-3half"))
            out.append(_entry(f"22.5.2-{f}-{where}", "22.5.2", f"{f} at z = {p}", latex, _r(latex)))
    return out


def limits(t, table: str, point: str, side: str) -> list[dict]:
    """Tables 22.5.3 (k → 0) and 22.5.4 (k → 1−)."""
    out = []
    for row in t.rows:
        for j in range(0, len(row), 2):
            f = _fn(row[j])
            g = _math(row[j + 1])[0]
            lim = rf"\lim_{{k\to {point}{side}}}\operatorname{{{f}}}z={g}"
            printed = read(lim, PRES).transcription
            out.append(_entry(f"{table}-{f}", table, f"{f}(z, k) as k -> {point}{side}",
                              rf"\operatorname{{{f}}}\left(z,k\right)\;\to\;{g}", printed))
    return out


def table_entries(section_22_4, section_22_5) -> list[dict]:
    t41, t42, t43 = section_22_4.tables
    t51, t52, t53, t54 = section_22_5.tables
    return (periods_and_points("22.4.1", t41, "pole") + periods_and_points("22.4.2", t42, "zero")
            + shifts(t43) + values(t51) + other_values(t52)
            + limits(t53, "22.5.3", "0", "") + limits(t54, "22.5.4", "1", "-"))
