"""What a new user waits for: `quasicentral verify --text DIR` of a ten-entry text of their own,
cold (a fresh cache) and warm, and the import of the command alone — each as the command a user
types, in a subprocess.

    python3 benchmarks/bench_user.py

The text is written here, from the README tutorial's skeleton (`quasicentral new-text`, two
entries with a derivation module) and eight identity entries of the kinds lecture notes print
(an integral to ∞, a limit, a series, a printed rounding, special functions, an inequality),
so that it is the same on every run.  Target (issue 25, on a 2-core machine): cold ≤ 2 s wall.
The numbers are printed, never asserted; compare them with benchmarks/RESULTS.md.
"""

import os
import subprocess
import sys
import tempfile
from pathlib import Path

from _timing import machine

ROOT = Path(__file__).resolve().parent.parent

EXTRA = [  # (name, printed, approx): eight entries of a second, identity, text
    ("Planck's integral", "Eq(Integral(x**3/(exp(x) - 1), (x, 0, oo)), pi**4/15)", ""),
    ("no drag", "Eq(Limit((1 - exp(-k*x))/k, k, 0), x)", ""),
    ("Basel", "Eq(Sum(1/n**2, (n, 1, oo)), pi**2/6)", ""),
    ("Wien's constant", "5 + LambertW(-5*exp(-5))", "4.965114"),
    ("Gamma and zeta", "Eq(gamma(4)*zeta(4), pi**4/15)", ""),
    ("error function", "Eq(erf(x) + erfc(x), 1)", ""),
    ("a bound", "log(1 + x) <= x", ""),
    ("a Bessel function", "Eq(besselj(1, x), x*(besselj(0, x) + besselj(2, x))/2)", ""),
]


def write_text(folder: Path) -> list[Path]:
    """The skeleton (two entries) and an identity text of the eight entries above."""
    skeleton = folder / "notes"
    subprocess.run([sys.executable, "-m", "quasicentral.cli", "new-text", str(skeleton)], check=True,
                   capture_output=True)
    identity = folder / "formulas"
    (identity / "catalog").mkdir(parents=True)
    (identity / "text.toml").write_text(
        'id = "formulas"\ntitle = "Formulas"\nauthors = ["A. User"]\nlanguage = "en"\ncheck = "identity"\n\n'
        '[symbols.x]\nlatex = "x"\nassumptions = ["positive"]\nrange = ["1/10", "10"]\n\n'
        '[symbols.k]\nlatex = "k"\nassumptions = ["positive"]\nrange = ["1/10", "2"]\n\n'
        '[symbols.n]\nlatex = "n"\nassumptions = ["positive", "integer"]\nrange = ["1", "10"]\n', encoding="utf-8")
    rows = ['section = "1"\ntitle = "Formulas"\n']
    for i, (name, printed, approx) in enumerate(EXTRA, 1):
        rows.append(f'[[equation]]\nid = "formulas:{i}"\nnumber = "{i}"\nname = "{name}"\nlatex = \'\'\'{printed}\'\'\'\n'
                    f"printed = '''{printed}'''\n" + (f'approx = "{approx}"\n' if approx else ""))
    (identity / "catalog" / "a.toml").write_text("\n".join(rows), encoding="utf-8")
    return [skeleton, identity]


def run(argv: list[str], env: dict) -> tuple[float, int]:
    """Wall time (measured by the child's own clock, the process start included) and exit code."""
    code = ("import subprocess, sys, time; t = time.perf_counter(); "
            "r = subprocess.run(sys.argv[1:], capture_output=True); "
            "print(time.perf_counter() - t, r.returncode)")
    out = subprocess.run([sys.executable, "-c", code, *argv], env=env, capture_output=True, text=True, check=True)
    seconds, rc = out.stdout.split()
    return float(seconds), int(rc)


def main() -> None:
    print(machine())
    with tempfile.TemporaryDirectory() as tmp:
        texts = write_text(Path(tmp))
        args = [a for t in texts for a in ("--text", str(t))]
        qc = [sys.executable, "-m", "quasicentral.cli"]
        env = {**os.environ, "QUASICENTRAL_CACHE": str(Path(tmp) / "cache")}
        imports = min(run(qc + ["--version"], env)[0] for _ in range(3))
        print(f"import and --version:                  {imports:5.2f} s wall (best of 3)")
        colds = []
        for i in range(3):
            env_i = {**env, "QUASICENTRAL_CACHE": str(Path(tmp) / f"cold{i}")}
            seconds, code = run(qc + ["verify", *args], env_i)
            colds.append(seconds)
        print(f"verify, ten entries, cold:             {min(colds):5.2f} s wall (best of 3; {max(colds):.2f} worst; "
              f"exit {code})")
        warm = min(run(qc + ["verify", *args], {**env, "QUASICENTRAL_CACHE": str(Path(tmp) / "cold0")})[0]
                   for _ in range(3))
        print(f"verify, ten entries, warm:             {warm:5.2f} s wall (best of 3)")


if __name__ == "__main__":
    main()
