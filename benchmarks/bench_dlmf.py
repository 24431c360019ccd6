"""The DLMF corpus at the scale of a real formula collection: `quasicentral verify --text dlmf-19
--text dlmf-22` cold (a fresh cache) and warm, each as the command a user types, in a subprocess,
with the counts per chapter (DLMF labels verified, or an erratum recorded, against LaCASt's
baseline on the same labels: ``tools/dlmf_compare.py``).

    python3 benchmarks/bench_dlmf.py [--timeout S] [--jobs N] [--save FILE]

``--save`` keeps the cold run's ``verify --json`` (for ``python3 tools/dlmf_compare.py FILE``).

Target (issue 27, 2 cores): cold ≤ 90 s wall, warm ≤ 0.5 s.  The numbers are printed, never
asserted; compare them with benchmarks/RESULTS.md.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

from _timing import machine

ROOT = Path(__file__).resolve().parent.parent


def verify(env: dict, timeout: float, jobs: int) -> tuple[float, dict]:
    argv = [sys.executable, "-m", "quasicentral.cli", "verify", "--text", "dlmf-19", "--text", "dlmf-22", "--json",
            "--timeout", str(timeout), "--jobs", str(jobs)]
    t = time.perf_counter()
    out = subprocess.run(argv, env=env, capture_output=True, text=True)
    seconds = time.perf_counter() - t
    if out.returncode not in (0, 1):
        raise SystemExit(f"verify exited {out.returncode}: {out.stderr.strip()[-500:]}")
    return seconds, json.loads(out.stdout)


def per_chapter(report: dict) -> dict:
    """Per chapter: labels (notation left out), labels whose every entry is verified or a recorded
    erratum, and the entries' statuses."""
    labels: dict[str, dict[str, list[bool]]] = {}
    statuses: dict[str, Counter] = {}
    for e in report["equations"]:
        statuses.setdefault(e["text"], Counter())[e["status"]] += 1
        if e["status"] != "notation":
            labels.setdefault(e["text"], {}).setdefault(e["number"], []).append(e["status"] in ("verified", "erratum"))
    return {t: (len(ls), sum(all(v) for v in ls.values()), dict(statuses[t])) for t, ls in sorted(labels.items())}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--timeout", type=float, default=10.0)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--save", default="", help="write the cold run's JSON here")
    args = ap.parse_args()
    print(machine())
    with tempfile.TemporaryDirectory() as tmp:
        env = {**os.environ, "QUASICENTRAL_CACHE": str(Path(tmp) / "cache")}
        cold, report = verify(env, args.timeout, args.jobs)
        warm, _ = verify(env, args.timeout, args.jobs)
    if args.save:
        Path(args.save).write_text(json.dumps(report, indent=1, ensure_ascii=False), encoding="utf-8")
    print(f"cold: {cold:7.1f} s wall ({len(report['equations'])} entries, --timeout {args.timeout:g}, --jobs {args.jobs})")
    print(f"warm: {warm:7.2f} s wall")
    for text, (n, settled, statuses) in per_chapter(report).items():
        print(f"{text}: {settled} of {n} labels verified or a recorded erratum ({100 * settled / n:.0f} %); entries {statuses}")


if __name__ == "__main__":
    main()
