"""Machine-readable documents (JSON, JUnit XML) and readable tables for the CLI.

Everything here is deterministic: entries in catalog order, keys in a fixed order, no
timestamps, so the same verdicts give byte-identical output.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

from quasicentral.engine.catalog import Entry
from quasicentral.engine.notes import render_note
from quasicentral.engine.reasons import Code
from quasicentral.engine.verdict import Outcome, Status


def _entry_head(e: Entry) -> dict:
    return {"id": e.id, "text": e.source, "source": e.source, "number": e.number, "name": e.name, "section": e.section}


def verify_document(entries: list[Entry], outcomes: list[Outcome]) -> dict:
    from quasicentral.engine.run import summary

    rows = []
    for e, o in zip(entries, outcomes):
        v = o.verdict
        row = {**_entry_head(e), "verdict": v.name, "method": v.method.value, "printed_latex": e.latex,
               "erratum": o.erratum, "status": o.status.value, "detail": v.detail, "dimensions": v.dimensions_text,
               "points": v.points, "digits": list(v.digits)}
        w = getattr(v, "witness", None)
        row["witness"] = w.to_json() if w else None
        if o.corrected_verdict is not None:
            row["corrected_verdict"] = o.corrected_verdict.name
            row["corrected_method"] = o.corrected_verdict.method.value
        row["problems"] = o.problem_texts
        rows.append(row)
    return {"equations": rows, "summary": summary(outcomes)}


def errata_document(entries: list[Entry], outcomes: list[Outcome]) -> dict:
    """Errata (each with its ``cause`` ids and its note rendered from its witness), the root
    ``causes`` (id, title, kind, the displays they affect, one witness) and cleared suspects —
    from the outcomes alone (each carries its records)."""
    out_e, out_c = [], []
    witness_of: dict[str, dict] = {}
    causes: dict[tuple[str, str], object] = {}
    for e, o in zip(entries, outcomes):
        rec = o.records.erratum if o.records is not None else None
        clr = o.records.cleared if o.records is not None else None
        if rec is not None:
            w = getattr(o.verdict, "witness", None)
            wj = w.to_json() if w else _dimensional_witness(o)
            witness_of[e.id] = wj
            out_e.append({**_entry_head(e), "kind": rec.kind.value, "cause": list(rec.causes),
                          "printed_latex": e.latex, "corrected_latex": rec.corrected_latex,
                          "witness": wj, "note": render_note(rec.note, w), "status": o.status.value,
                          "evidence": o.verdict.detail, "method": o.verdict.method.value})
            for c in o.causes:
                causes.setdefault((c.source, c.id), c)
        if clr is not None:
            # on an erratum the suspected detail is kept in the correction: its verdict is the evidence
            v = o.corrected_verdict if rec is not None else o.verdict
            out_c.append({**_entry_head(e), "kind": "cleared", "suspicion": clr.suspicion,
                          "branch": clr.branch or None,
                          "printed_latex": e.latex,
                          "corrected_latex": rec.corrected_latex if rec is not None else e.latex,
                          "witness": None, "note": clr.note, "status": o.status.value,
                          "evidence": (("the correction keeps it and is " if rec is not None else "")
                                       + f"{v.name} ({v.method.value}): {v.detail}"),
                          "method": v.method.value})
    rank = {tid: i for i, tid in enumerate(dict.fromkeys(e.source for e in entries))}
    out_causes = []
    for c in sorted(causes.values(), key=lambda c: (rank[c.source], c.order)):
        displays = [r["id"] for r in out_e if r["text"] == c.source and c.id in r["cause"]]
        # one witness: the first certified one among its displays, else the first
        ws = [(i, witness_of[i]) for i in displays]
        wid, wit = next(((i, w) for i, w in ws if w.get("certified")), ws[0])
        out_causes.append({"id": c.id, "text": c.source, "source": c.source, "title": c.title,
                           "title_cs": c.title_cs, "kind": c.kind.value, "note": c.note, "note_cs": c.note_cs,
                           "displays": displays, "witness": {"display": wid, **wit}})
    return {"causes": out_causes, "errata": out_e, "cleared": out_c}


def _dimensional_witness(o: Outcome) -> dict:
    """A dimensional refutation has no numeric point; its witness is the dimension mismatch."""
    return {"parameters": {}, "printed": o.verdict.dimensions, "corrected": "consistent",
            "digits": 0, "certified": True, "printed_certified": True, "corrected_certified": True,
            "working_digits": 0, "quantity": "dimensions", "relative_difference": "",
            "quantity_code": Code.Q_DIMENSIONS.value}


def catalog_document(entries: list[Entry], coverage: dict) -> dict:
    from quasicentral.engine.dimensions import check_relation
    from quasicentral.engine.wording import render

    rows = []
    for e in entries:
        problems = [c for c in (check_relation(r, e.dims) for r in e.relations()) if c.inconsistent or c.undetermined]
        rows.append({**_entry_head(e), "printed_latex": e.latex, "transcription": e.printed_text,
                     "dimensions": "consistent" if not problems else "; ".join(
                         f"{c.status.value}: {render(c.problem)}" for c in problems),
                     "latex_parser": coverage["entries"].get(e.id)})
    return {"equations": rows, "latex_parser": coverage["summary"]}


def junit_xml(entries: list[Entry], outcomes: list[Outcome]) -> str:
    suites = ET.Element("testsuites", name="quasicentral verify")
    by_source: dict[str, list] = {}
    for e, o in zip(entries, outcomes):
        by_source.setdefault(e.source, []).append((e, o))
    for source, pairs in by_source.items():
        fails = sum(1 for _, o in pairs if not o.ok)
        suite = ET.SubElement(suites, "testsuite", name=source, tests=str(len(pairs)), failures=str(fails),
                              errors="0", skipped="0")
        for e, o in pairs:
            case = ET.SubElement(suite, "testcase", classname=f"{source}.section{e.section}", name=e.id)
            props = ET.SubElement(case, "properties")
            for k, val in (("status", o.status.value), ("verdict", o.verdict.name), ("method", o.verdict.method.value),
                           ("erratum", str(o.erratum).lower())):
                ET.SubElement(props, "property", name=k, value=val)
            if not o.ok:
                f = ET.SubElement(case, "failure", message=f"{o.status.value}: {o.verdict.name}", type=o.verdict.name)
                f.text = "; ".join(o.problem_texts) or o.verdict.detail
            elif o.status in (Status.ERRATUM, Status.CLEARED):
                out = ET.SubElement(case, "system-out")
                out.text = f"{o.status.value}: printed form {o.verdict.name} ({o.verdict.method.value}); {o.verdict.detail}"
    ET.indent(suites)
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(suites, encoding="unicode") + "\n"


def _table(headers: list[str], rows: list[list[str]]) -> str:
    widths = [max(len(h), *(len(r[i]) for r in rows)) if rows else len(h) for i, h in enumerate(headers)]
    line = lambda cells: "  ".join(c.ljust(w) for c, w in zip(cells, widths)).rstrip()  # noqa: E731
    return "\n".join([line(headers), line(["-" * w for w in widths])] + [line(r) for r in rows])


DETAIL_WIDTH = 70  # characters of the table's detail column


def _shortened(text: str, width: int = DETAIL_WIDTH) -> str:
    """``text`` cut at a word boundary to ``width`` characters, an ellipsis saying so — before
    a parenthesis the cut would leave open (a remark is left out whole, not halved).

    >>> _shortened("agrees at 20 points to 18+ digits (4 of them also at 60 digits)", 50)
    'agrees at 20 points to 18+ digits…'
    """
    if len(text) <= width:
        return text
    cut = text[:width - 1].rsplit(" ", 1)[0]
    depth, opened = 0, None
    for i, c in enumerate(cut):
        if c == "(":
            depth, opened = depth + 1, i if depth == 0 else opened
        elif c == ")" and depth:
            depth -= 1
    if depth and opened and opened > width // 3:
        cut = cut[:opened]
    return cut.rstrip(" ,;:(") + "…"


def _table_detail(r: dict) -> str:
    """What the table says of an entry: its verdict's reason, or — where the records expected
    something else (an erratum whose correction fails) — the first problem."""
    if r["status"] == "unexpected" and r.get("problems"):
        return r["problems"][0]
    return r["detail"] or ""


def verify_table(doc: dict) -> str:
    rows = [[r["id"], r["status"], r["verdict"], r["method"], _shortened(_table_detail(r))] for r in doc["equations"]]
    s = doc["summary"]
    tail = (f"\n{s['entries']} entr{'ies' if s['entries'] != 1 else 'y'}: " + ", ".join(f"{v} {k}" for k, v in s["status"].items())
            + (f" ({s['causes']} root cause{'s' if s['causes'] != 1 else ''})" if s.get("causes") else "")
            + ("" if s["ok"] else f"\nunexpected: {', '.join(s['unexpected'])}"))
    return _table(["id", "status", "verdict", "method", "detail"], rows) + tail


def _short_number(s: str, digits: int = 10) -> str:
    """A witness value in ``digits`` significant digits, its exponent and its imaginary part
    kept (cutting the string would drop them: 1.84e-16 must not read 1.84).

    >>> _short_number("1.8409926290586405123e-16"), _short_number("-0.75012152623546089 + 1.79811868757946419i")
    ('1.840992629e-16', '-0.7501215262 + 1.798118688i')
    >>> _short_number("inf"), _short_number("-inf")
    ('∞', '-∞')
    """
    from decimal import Decimal, InvalidOperation

    if not isinstance(s, str):  # not a number (an erratum whose witness could not be computed)
        return str(s)[:18]

    def one(x: str) -> str:
        try:
            d = Decimal(x)
        except InvalidOperation:
            return x
        return format(d, f".{digits}g") if d.is_finite() else "-∞" if d < 0 else "∞"  # a limit without bound
    for sep in (" + ", " - "):
        head, found, tail = s.rpartition(sep)
        if found and tail.endswith("i"):
            return f"{one(head)}{sep}{one(tail[:-1])}i"
    return one(s)


def errata_table(doc: dict) -> str:
    crows = [[c["id"], c["kind"], str(len(c["displays"])), c["title"][:60]] for c in doc["causes"]]
    out = f"Root causes ({len(doc['causes'])} over {len(doc['errata'])} errata)\n" + _table(
        ["cause", "kind", "displays", "title"], crows)
    for c in doc["causes"]:
        out += f"\n  {c['id']}: " + ", ".join(c["displays"])
    rows = []
    for r in doc["errata"]:
        w = r["witness"]
        ratio = bool(w) and w.get("quantity_code") == Code.Q_ORDER_RATIO.value
        bound = bool(w) and w.get("quantity_code") in (Code.Q_LESSER_GREATER.value, Code.Q_ROUNDING_WINDOW.value)
        sides = bool(w) and w.get("quantity_code") == Code.Q_SIDES.value  # an identity: no "printed" side
        wit = "" if not w else (
            (f"|lhs − rhs|/|O-term| {_short_number(w['printed'])} at the last step, {_short_number(w['corrected'])} "
             "three before" if ratio else f"{_short_number(w['printed'])} > {_short_number(w['corrected'])}" if bound
             else f"left {_short_number(w['printed'])} vs right {_short_number(w['corrected'])}" if sides
             else f"printed {_short_number(w['printed'])} vs {_short_number(w['corrected'])}")
            + (" (certified)" if w["certified"] else ""))
        rows.append([r["id"], ",".join(r["cause"]), r["status"], wit])
    out += "\n\nErrata\n" + _table(["id", "cause", "status", "witness"], rows)
    crow = [[r["id"], r["suspicion"][:50], r["status"]] for r in doc["cleared"]]
    return out + "\n\nCleared suspects\n" + _table(["id", "suspicion", "status"], crow)


def catalog_table(doc: dict) -> str:
    rows = [[r["id"], r["number"] or "", r["name"][:45], "ok" if r["dimensions"] == "consistent" else "INCONSISTENT",
             ",".join(k for k, ok in (r["latex_parser"] or {}).items() if ok is True) or "-"] for r in doc["equations"]]
    s = doc["latex_parser"]
    return (_table(["id", "no.", "name", "dimensions", "parsed by"], rows)
            + f"\n\nLaTeX parser: {s['any']} of {s['entries']} entries read and agreeing "
              f"(antlr {s['antlr']}, lark {s['lark']})")
