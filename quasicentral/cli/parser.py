"""The command line's grammar: every command, option, default and example (argparse)."""

from __future__ import annotations

import argparse

from quasicentral.models.parameters import G_STANDARD

EXIT_OK, EXIT_UNEXPECTED, EXIT_USAGE = 0, 1, 2
MAX_DPS = 2000
VERIFY_MAX_DPS = 300  # the ladder doubles it, and every in-domain point is evaluated at both rungs
MAX_TIMEOUT = 86_400.0  # seconds: a day
MAX_POINTS = 10**6  # --n, and the number of --t values
MAX_POINTS_DPS = 10**4  # the same with --dps (mpmath evaluates point by point)


class UsageError(Exception):
    """Bad usage or input: reported as one line, exit 2."""


class Parser(argparse.ArgumentParser):
    def __init__(self, *args, **kwargs):
        kwargs.setdefault("formatter_class", argparse.RawDescriptionHelpFormatter)
        super().__init__(*args, **kwargs)

    def error(self, message):  # argparse would print usage and exit 2; we keep one line
        raise UsageError(message)


def _command(sub, name: str, summary: str, description: str, examples: str):
    """A subcommand with a one-line summary (in ``quasicentral --help``), a description and
    worked examples (in ``quasicentral NAME --help``)."""
    return sub.add_parser(name, help=summary, description=f"{summary[0].upper()}{summary[1:]}.\n\n{description}",
                          epilog="examples:\n" + "\n".join(f"  {line}" for line in examples.strip().splitlines()))


def version() -> str:
    from importlib import metadata

    try:
        return metadata.version("quasicentral")
    except metadata.PackageNotFoundError:
        return "unknown (not installed)"


def positive_int(name: str, upper: int):
    def parse(text: str) -> int:
        try:
            val = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{name} must be a whole number, not {text!r}") from None
        if val <= 0 or val > upper:
            raise argparse.ArgumentTypeError(f"{name} must be between 1 and {upper}, not {val}")
        return val

    return parse


def _timeout(text: str) -> float:
    try:
        val = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"--timeout must be a number of seconds, not {text!r}") from None
    if not 0 < val <= MAX_TIMEOUT:
        raise argparse.ArgumentTypeError(f"--timeout must be between 0 and {MAX_TIMEOUT:g} seconds, not {text}")
    return val


def _add_timeout(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--timeout", type=_timeout, default=None, metavar="SECONDS",
                        help="the most time one entry may take, wall-clock and CPU (default 120): past it the "
                             "entry is inconclusive, never a hang")


def _add_text_options(parser: argparse.ArgumentParser, source: bool = True) -> None:
    """--text DIR (repeatable) and --source ID: which texts a command works on."""
    parser.add_argument("--text", action="append", dest="texts", metavar="DIR",
                        help="a text's folder, or a shipped text's id (repeatable; default: the shipped texts). "
                             "A folder's .py modules are code and are run (as pytest runs conftest.py), bounded "
                             "by --timeout; its TOML files are data, read and never executed")
    if source:
        parser.add_argument("--source", metavar="ID",
                            help="only the entries of the text with this id, among those selected (default: all)")


def build_parser() -> argparse.ArgumentParser:
    p = Parser(prog="quasicentral", description="Re-derive every equation of a text with sympy, check it with mpmath and ball "
                "arithmetic, and record its errata (the shipped texts, or a text of your own: new-text).",
                epilog="exit codes: 0 success, 1 an unexpected result (see each command), 2 bad usage or input\n"
                       "(one line on stderr).  A reader that closes the pipe early (| head) ends the output quietly\n"
                       "and the exit code stays the command's own, so `set -o pipefail` fails only on a real failure.\n"
                       "Long commands draw progress on stderr when it is a terminal (not when CI is set, nor with --json).\n"
                       "\nexamples:\n  quasicentral verify\n  quasicentral verify --help")
    p.add_argument("--version", action="version", version=f"%(prog)s {version()}")
    sub = p.add_subparsers(dest="command", parser_class=Parser, metavar="COMMAND")

    _add_verify(sub)
    _add_errata(sub)
    _add_mutate(sub)
    _add_period(sub)
    _add_trajectory(sub)
    _add_figures(sub)
    _add_charts(sub)
    _add_report(sub)
    _add_new_text(sub)
    _add_scene(sub)
    _add_catalog(sub)
    return p


def _add_verify(sub) -> None:
    v = _command(sub, "verify", "verify every catalog entry (printed vs derived)",
                 "Checks each equation as printed against its re-derivation: symbolically, then numerically on a\n"
                 "precision ladder (dps, 2·dps), certified by ball arithmetic where it can.  Verdicts are cached\n"
                 "under a hash of the code, the catalog, the errata and the options ($QUASICENTRAL_CACHE, else\n"
                 "~/.cache/quasicentral); a run whose code, texts and options are unchanged is read back whole.\n"
                 "Exit 0 when every entry is verified, a registered erratum, a cleared suspect or notation\n"
                 "(a definition: nothing to check); 1 when anything is unexpected; 2 on bad usage (e.g. a\n"
                 "selection that selects nothing).",
                 "quasicentral verify\n"
                 "quasicentral verify --text mynotes --json\n"
                 "quasicentral verify --text mynotes --id mynotes:2 --no-cache --jobs 2\n"
                 "quasicentral verify --junit build/verify.xml")
    _add_text_options(v)
    v.add_argument("--id", action="append", dest="ids", metavar="ID",
                   help="only this entry, TEXT:LABEL (repeatable; see `quasicentral catalog`)")
    v.add_argument("--json", action="store_true", help="print a JSON document instead of the table (no progress bar)")
    v.add_argument("--dps", type=positive_int("--dps", VERIFY_MAX_DPS), default=30, metavar="N",
                   help=f"first rung of the precision ladder, decimal digits, at most {VERIFY_MAX_DPS} "
                        "(default 30; the ladder is dps, 2·dps)")
    v.add_argument("--no-cache", action="store_true", help="ignore cached verdicts (a cold run; default: use them)")
    v.add_argument("--junit", metavar="FILE", help="also write a JUnit XML report to FILE (default: none)")
    v.add_argument("--jobs", type=positive_int("--jobs", 64), default=None, metavar="N",
                   help="worker processes, 1 to 64 (default: one per core, at most one per entry)")
    _add_timeout(v)


def _add_errata(sub) -> None:
    e = _command(sub, "errata", "the errata found and the suspects cleared",
                 "Lists each registered erratum (the printed form refuted, the corrected one verified, with the\n"
                 "witness values) and each suspect that turned out right.  Exit 0 when every erratum still stands\n"
                 "and every suspect is cleared, 1 otherwise.",
                 "quasicentral errata\nquasicentral errata --text mynotes --json")
    _add_text_options(e)
    e.add_argument("--json", action="store_true", help="print a JSON document instead of the table")
    e.add_argument("--no-cache", action="store_true", help="ignore cached verdicts (default: use them)")
    _add_timeout(e)


def _add_mutate(sub) -> None:
    mu = _command(sub, "mutate", "seed typical typos into verified entries and measure the checker",
                  "Mutates every verified entry as a typesetter would (sign flip, exponent, factor 2, k <-> k^2,\n"
                  "dropped parentheses, swapped variables, a variable slipped for another of its dimension),\n"
                  "drops the mutants sympy shows equivalent, checks the rest with the fast checker, and lists\n"
                  "apart those equivalent on the declared domain (a proof under the domain's signs, or the full\n"
                  "checker verifies them).  Takes minutes: use --per-entry for a sample.\n\n"
                  "exit codes: 0 every mutant detected (recall 100 %) and no false alarm on the unmutated\n"
                  "entries; 1 a mutant went undetected or an unmutated entry was refuted; 2 bad usage.",
                  "quasicentral mutate --per-entry 3\nquasicentral mutate --text mynotes --json")
    mu.add_argument("--json", action="store_true", help="print a JSON document instead of the table")
    _add_text_options(mu)
    mu.add_argument("--per-entry", type=positive_int("--per-entry", 50), default=None, metavar="N",
                    help="at most this many mutants per entry, 1 to 50, spread over the operators (default: all)")
    mu.add_argument("--jobs", type=positive_int("--jobs", 64), default=None, metavar="N",
                    help="worker processes, 1 to 64 (default: one per core)")
    _add_timeout(mu)


def _add_figures(sub) -> None:
    fg = _command(sub, "figures", "reproduce the texts' missing figures (CSV data and PNG plots)",
                  "Writes each text's figures (those its folder's figures.py lists: for the shipped texts the\n"
                  "figures lost in print and the measured charts) as CSV data and PNG plots.  Each file is written through a temporary file and\n"
                  "a rename, only inside DIR; a symbolic link where a file would go is refused (exit 2).",
                  "quasicentral figures\nquasicentral figures --out build/figures")
    fg.add_argument("--out", default="figures", metavar="DIR", help="output directory, created if needed (default figures)")
    _add_text_options(fg)


def _add_report(sub) -> None:
    rp = _command(sub, "report", "LaTeX reports (or handouts) regenerated from the verified derivations",
                  "Per text, the derivation report (printed vs re-derived, verdicts, steps, errata, cleared\n"
                  "suspects, figures, software versions) or a teaching handout with exercises, written into DIR\n"
                  "with the figures they include (only inside DIR, never through a symbolic link).  --pdf compiles\n"
                  "each with latexmk and exits 1 naming the log on a LaTeX error or an undefined reference; a\n"
                  "failed run removes the job's auxiliary files, so a stale .aux never blocks the next one.",
                  "quasicentral report --out build/reports --pdf\n"
                  "quasicentral report --handout --lang cs\n"
                  "quasicentral report --all --out reports      # regenerate the golden files")
    rp.add_argument("--out", default="reports", metavar="DIR", help="output directory, created if needed (default reports)")
    rp.add_argument("--pdf", action="store_true", help="also compile each document with latexmk (default: LaTeX only)")
    rp.add_argument("--lang", choices=("en", "cs"), default=None, help="language: en or cs (default en)")
    rp.add_argument("--handout", action="store_true",
                    help="the teaching handouts instead of the report: the students' and the teacher's (with solutions)")
    rp.add_argument("--all", action="store_true",
                    help="every golden document: reports and handouts, English and Czech")
    _add_text_options(rp, source=False)
    _add_timeout(rp)


def _add_new_text(sub) -> None:
    nt = _command(sub, "new-text", "write the skeleton of a text of your own (a folder) that verifies at once",
                  "Writes DIR/text.toml (the text's id, title, language and symbol table), DIR/catalog/ (what is\n"
                  "printed, transcribed), DIR/errata/ (one recorded erratum as an example) and DIR/motion.py (the\n"
                  "derivations).  Edit them into your own text; README: \"Verify your own derivation\".",
                  "quasicentral new-text mynotes\nquasicentral verify --text mynotes")
    nt.add_argument("dir", metavar="DIR", help="the new text's folder (must not exist, or be empty)")
    nt.add_argument("--id", dest="text_id", metavar="ID", help="the text's id (default: the folder's name)")


def _add_catalog(sub) -> None:
    c = _command(sub, "catalog", "list the catalog: ids, dimensions, LaTeX-parser coverage",
                 "Lists every entry with its id (for verify --id), section and dimensions, and which of sympy's\n"
                 "LaTeX parsers read its printed form back correctly (each answer kept in the cache).",
                 "quasicentral catalog\nquasicentral catalog --text mynotes --json")
    _add_text_options(c)
    c.add_argument("--json", action="store_true", help="print a JSON document instead of the table")
    c.add_argument("--no-cache", action="store_true",
                   help="parse every entry's LaTeX anew (default: read the kept answers back)")
    _add_timeout(c)


def _add_period(sub) -> None:
    from quasicentral.models.registry import PERIOD_METHODS, SERIES_MAX_TERMS

    pe = sub.add_parser("period", help="the exact period of the simple pendulum, T and T/T0")
    amp = pe.add_mutually_exclusive_group()
    amp.add_argument("--amplitude-deg", metavar="A", help="amplitude φ0 in degrees, 0 < A < 180 (read exactly)")
    amp.add_argument("--amplitude-rad", metavar="A", help="amplitude φ0 in radians, 0 < A < π (read exactly)")
    amp.add_argument("--complement-rad", metavar="D", help="δ = π − φ0 (full accuracy near π)")
    pe.add_argument("--l", metavar="L", default=None, help="length in m (default 1)")
    pe.add_argument("--g", metavar="G", default=None, help=f"gravity in m/s² (default {G_STANDARD})")
    pe.add_argument("--method", choices=PERIOD_METHODS, default=None,
                    help=f"route to T/T0: {', '.join(PERIOD_METHODS)} (default ellipk)")
    pe.add_argument("--terms", type=positive_int("--terms", SERIES_MAX_TERMS), default=None,
                    help="terms of the series (66), with --method series (default 4)")
    pe.add_argument("--dps", type=positive_int("--dps", MAX_DPS), default=None,
                    help="decimal digits (inputs read exactly; agm and ellipk results correctly rounded)")
    pe.add_argument("--table", action="store_true", help="T/T0 from 5° to 179.99° at 20 digits, two methods")
    pe.add_argument("--json", action="store_true", help="print JSON (with 'digits' and 'warning' when they apply)")


def _add_trajectory(sub) -> None:
    from quasicentral.models.registry import TRAJECTORY, names

    tr = sub.add_parser("trajectory", help="the motion of a small-swing spherical pendulum x(t), y(t)")
    tr.add_argument("--model", required=True, metavar="MODEL", choices=[m.value for m in TRAJECTORY],
                    help=f"one of {names(TRAJECTORY)}")
    tr.add_argument("--R0", required=True, metavar="X", help="initial distance from the vertical, m")
    tr.add_argument("--v0", required=True, metavar="V", help="initial speed perpendicular to R0, m/s")
    tr.add_argument("--omega2", metavar="G_OVER_L", help="Ω² = g/l, 1/s²")
    tr.add_argument("--l", metavar="L", help="length, m (with --g; then R0 must be below it)")
    tr.add_argument("--g", metavar="G", help="gravity, m/s² (with --l)")
    drag = tr.add_mutually_exclusive_group()
    drag.add_argument("--kappa", metavar="K", help="linear drag, 1/s (R = 2κmv)")
    drag.add_argument("--beta", metavar="B", help="quadratic drag, 1/m (R = mβv²)")
    tr.add_argument("--t", metavar="T1,T2,...", help="times, s (comma-separated, ≥ 0)")
    tr.add_argument("--t0", metavar="A", help="first time, s (with --t1 and --n)")
    tr.add_argument("--t1", metavar="B", help="last time, s")
    tr.add_argument("--n", type=positive_int("--n", MAX_POINTS), metavar="N", help="number of times from --t0 to --t1")
    tr.add_argument("--dps", type=positive_int("--dps", MAX_DPS), default=None,
                    help="decimal digits (mpmath; inputs read exactly); default double precision")
    fmt = tr.add_mutually_exclusive_group()
    fmt.add_argument("--json", action="store_true", help="print JSON (with 'warning' when it applies)")
    fmt.add_argument("--csv", action="store_true", help="print CSV t,x,y")


def _add_scene(sub) -> None:
    sc = sub.add_parser("scene", help="a situation and the accuracy it needs: the cheapest model that meets it")
    sc.add_argument("file", metavar="FILE", help="a scene (TOML; examples in scenes/)")
    sc.add_argument("--json", action="store_true", help="print the decision as JSON")
    sc.add_argument("--plot", metavar="OUT.png", help="also plot the answer and the evidence")


def _add_charts(sub) -> None:
    ch = sub.add_parser("charts", help="work–precision charts, stability maps, validity of the approximations")
    ch.add_argument("--out", default="charts", metavar="DIR", help="output directory (default charts)")
    ch.add_argument("--quick", action="store_true", help="a fast, coarse run (CI, tests)")
    ch.add_argument("--only", action="append", metavar="NAME", help="only this chart (repeatable)")
    ch.add_argument("--render-only", action="store_true", help="redraw the PNGs from the CSVs in DIR, measure nothing")


