#!/usr/bin/env python3
"""LaCASt's published verdicts on DLMF chapters 19 and 22, per DLMF label, in its four runs.

Reads ``misc/Results`` of the LaCASt mirror (Mathematica and Maple, symbolic and numeric:
``19-EL-*``, ``22-JA-*``); its result lines name the line of ``dlmf-formulae.txt`` they test,
which the importer's alignment (``tools/dlmf_import.py``) maps to the current DLMF number.  A
label's verdict in one run combines its lines (a chain's members, a formula's sub-lines) by
LaCASt's rule: error beats failure beats success, skipped is neutral; a label no line of a
numeric run names was not run there (numeric tests ran where the symbolic ones did not
succeed).  Writes ``tools/lacast_baseline.json`` (sorted, byte-identical on rerun).

    PYTHONPATH=. python3 tools/lacast_baseline.py
"""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path[:0] = [str(HERE), str(HERE.parent)]

from dlmf_import import formulas  # noqa: E402
from dlmf_sources import LACAST, git_show  # noqa: E402

RUNS = {
    "mathematica_symbolic": ("MathematicaSymbolic", "symbolic"),
    "mathematica_numeric": ("MathematicaNumeric", "numeric"),
    "maple_symbolic": ("MapleSymbolic", "symbolic"),
    "maple_numeric": ("MapleNumeric", "numeric"),
}
FILES = {"19": "19-EL", "22": "22-JA"}
#: LaCASt's words → the closed set of verdicts.
VERDICT = {
    "Successful": "verified", "Failure": "failed", "Failed": "failed",
    "Skipped": "skipped", "Skip": "skipped", "Manual Skip": "skipped", "Definition": "skipped",
    "All Aborted": "skipped", "Missing Macro Error": "error", "Translation Error": "error",
    "Error": "error", "All Errors": "error",
}
RANK = {"error": 3, "failed": 2, "verified": 1, "skipped": 0}
LINE = re.compile(r"^(\d+)(?:-[a-z]+)? \[[^\]]*\]: (.*)$")


def status_of(rest: str) -> str:
    for word in sorted(VERDICT, key=len, reverse=True):
        if rest.startswith(word):
            return word
    return "Error" if rest.strip() == "" or rest.startswith("Was expecting") else rest.split(" ")[0]


def baseline() -> dict:
    by_line: dict[int, str] = {}
    labels: list[str] = []
    for chapter in FILES:
        fs, _, _ = formulas(chapter)
        for f in fs:
            labels.append(f.number)
            for ln in f.lines:
                by_line[ln.lineno] = f.number
    out: dict = {"source": "gipplab/LaCASt misc/Results (Mathematica 12.1.1, Maple 2020.2)",
                 "rule": "per DLMF label: error > failed > verified; skipped is neutral; "
                         "a numeric run's label without a line was not run (skipped, status 'not run')",
                 "runs": list(RUNS), "formulas": {}, "totals": {}, "lacast_overall": {}}
    per: dict[str, dict[str, dict]] = {lab: {} for lab in labels}
    for chapter, stem in FILES.items():
        for run, (folder, kind) in RUNS.items():
            text = git_show(LACAST, f"misc/Results/{folder}/{stem}-{kind}.txt")
            lines = text.splitlines()
            out["lacast_overall"][f"{chapter}/{run}"] = lines[0].split("for test expression")[0].strip()
            for line in lines[1:]:
                m = LINE.match(line.strip())
                if not m or int(m.group(1)) not in by_line:
                    continue
                label = by_line[int(m.group(1))]
                status = status_of(m.group(2))
                verdict = VERDICT.get(status, "error")
                cur = per[label].get(run)
                if cur is None or RANK[verdict] > RANK[cur["verdict"]]:
                    per[label][run] = {"verdict": verdict, "status": status}
    for label in labels:
        chapter = label.split(".")[0]
        rec = {}
        for run in RUNS:
            rec[run] = per[label].get(run, {"verdict": "skipped", "status": "not run"})
        out["formulas"][label] = rec
    for chapter in FILES:
        for run in RUNS:
            counts = {v: 0 for v in RANK}
            for label, rec in out["formulas"].items():
                if label.split(".")[0] == chapter:
                    counts[rec[run]["verdict"]] += 1
            out["totals"][f"{chapter}/{run}"] = counts
        any_verified = sum(1 for label, rec in out["formulas"].items() if label.split(".")[0] == chapter
                           and any(r["verdict"] == "verified" for r in rec.values()))
        out["totals"][f"{chapter}/verified_in_any_run"] = any_verified
        out["totals"][f"{chapter}/formulas"] = sum(1 for label in out["formulas"] if label.split(".")[0] == chapter)
    return out


def main() -> int:
    data = baseline()
    path = HERE / "lacast_baseline.json"
    text = json.dumps(data, indent=1, sort_keys=True, ensure_ascii=False) + "\n"
    if not path.exists() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")
    for key, counts in sorted(data["totals"].items()):
        print(key, counts)
    return 0


if __name__ == "__main__":
    sys.exit(main())
