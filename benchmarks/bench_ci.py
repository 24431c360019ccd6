"""What CI waits for: a cold and a warm `verify` of the shipped texts (wall time, in a fresh
cache; warm both as the whole run read back and from the per-entry verdicts), the full
`mutate`, and the default test run — each as the command a user or CI types.

    python3 benchmarks/bench_ci.py            # verify cold and warm
    python3 benchmarks/bench_ci.py --all      # also the full mutate and the default test run

Targets (issue "No wrong answer, no crash, no silence", on a 2-core machine): cold verify ≤ 20 s,
warm ≤ 0.5 s, full mutate ≤ 3 minutes, default test run ≤ 3 minutes.  The numbers are printed,
never asserted: compare them with the previous runs' in benchmarks/RESULTS.md.
"""

import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from _timing import machine

ROOT = Path(__file__).resolve().parent.parent


def timed(argv: list[str], env: dict) -> tuple[float, int, str]:
    """Wall time, exit code and the last line the command printed (a library's warning
    excepted: pytest's summary is on stdout, its plugins' warnings on stderr)."""
    t0 = time.perf_counter()
    proc = subprocess.run(argv, cwd=ROOT, env=env, capture_output=True, text=True)
    lines = [line for line in (proc.stdout + "\n" + proc.stderr).splitlines()
             if line.strip() and "Warning" not in line and "warner(" not in line]
    return time.perf_counter() - t0, proc.returncode, lines[-1].strip() if lines else ""


def main() -> None:
    print(machine())
    with tempfile.TemporaryDirectory() as cache:
        env = {**os.environ, "QUASICENTRAL_CACHE": cache, "CI": "1"}
        qc = [sys.executable, "-m", "quasicentral.cli"]
        seconds, code, last = timed(qc + ["verify"], env)
        print(f"verify, cold (both texts, fresh cache): {seconds:6.1f} s wall  (exit {code}; {last})")
        best = min(timed(qc + ["verify"], env)[0] for _ in range(3))
        print(f"verify, warm (best of 3):               {best:6.2f} s wall  (the whole run read back)")
        for record in Path(cache).glob("runs/*.json"):  # the whole run forgotten, its verdicts kept
            record.unlink()
        seconds = timed(qc + ["verify"], env)[0]
        print(f"verify, per-entry verdicts read back:   {seconds:6.2f} s wall  (no whole-run record: loads sympy and the texts)")
        if "--all" in sys.argv:
            seconds, code, last = timed(qc + ["mutate"], env)
            print(f"mutate, every mutant:                    {seconds:6.1f} s wall  (exit {code}; {last})")
            seconds, code, last = timed([sys.executable, "-m", "pytest", "-q"], env)  # its own cold cache
            print(f"default test run (pytest -q):            {seconds:6.1f} s wall  (exit {code}; {last})")


if __name__ == "__main__":
    main()
