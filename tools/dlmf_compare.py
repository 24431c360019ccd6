"""quasicentral's verdicts on DLMF chapters 19 and 22 beside LaCASt's, per DLMF label.

    quasicentral verify --text dlmf-19 --text dlmf-22 --no-cache --json > dlmf.json
    python3 tools/dlmf_compare.py dlmf.json

A label (a numbered formula, e.g. 19.2.4) is verified when every entry it was split into is
verified, refuted when one is refuted, else inconclusive; entries that only state notation do
not count against it.  LaCASt's figures are its own per-label verdicts
(``tools/lacast_baseline.json``, from ``gipplab/LaCASt`` ``misc/Results``: a label verified in
any of its four runs, Maple and Mathematica, symbolic and numeric).  Prints a Markdown table.

Only the standard library.
"""

from __future__ import annotations

import json
import re
import sys
from collections import Counter, defaultdict
from pathlib import Path

BASELINE = Path(__file__).resolve().parent / "lacast_baseline.json"


def label_of(eid: str) -> str | None:
    """'dlmf-19:19.2.4-a' → '19.2.4'; an unnumbered entry ('dlmf-19:19.2#Ex1') → None."""
    m = re.match(r"dlmf-\d+:(\d+\.\d+\.\d+)(?:-|$)", eid)
    return m.group(1) if m else None


def per_label(doc: dict) -> dict[str, str]:
    by = defaultdict(list)
    for e in doc["equations"]:
        label = label_of(e["id"])
        if label is not None and e["status"] != "notation":
            by[label].append(e["status"] if e["status"] != "unexpected" else e["verdict"])
    out = {}
    for label, states in by.items():
        if "refuted" in states:
            out[label] = "refuted"
        elif all(s in ("verified", "erratum", "cleared") for s in states):
            out[label] = "verified"
        else:
            out[label] = "inconclusive"
    return out


def main(path: str) -> None:
    doc = json.loads(Path(path).read_text(encoding="utf-8"))
    base = json.loads(BASELINE.read_text(encoding="utf-8"))["totals"]
    ours = per_label(doc)
    print("| chapter | DLMF labels | LaCASt: verified in any run | quasicentral: verified | inconclusive | refuted |")
    print("|---|---|---|---|---|---|")
    for chapter in ("19", "22"):
        counts = Counter(v for k, v in ours.items() if k.startswith(chapter + "."))
        total = sum(counts.values())
        if not total:
            continue
        print(f"| {chapter} | {base[f'{chapter}/formulas']} | {base[f'{chapter}/verified_in_any_run']} | "
              f"{counts['verified']} of {total} ({100 * counts['verified'] / total:.0f} %) | "
              f"{counts['inconclusive']} | {counts['refuted']} |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "dlmf.json")
