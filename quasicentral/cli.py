"""The ``quasicentral`` command.

Exit codes: 0 success (every entry verified, a registered erratum or a cleared suspect);
1 something unexpected (a new mismatch, an erratum that no longer stands, an inconclusive
entry); 2 bad usage or bad input (one line on stderr naming the option, never a traceback).

A reader that stops early (``quasicentral verify | head -2``) is not an error: the output
stops quietly and the exit code is still the command's own verdict (0 when everything
verified), not 141 or 1.  A pipeline under ``set -o pipefail`` therefore fails only when the
verification does, as it does with ``grep -q`` style readers.

Progress of long work (verify, errata, catalog, mutate, charts, report, figures) is drawn on
stderr with tqdm only when stderr is a terminal, the environment variable ``CI`` is not set
and ``--json`` is not given; library functions only report :class:`quasicentral.progress.Progress`
records to a callback.
"""

from __future__ import annotations

import argparse
from contextlib import contextmanager
import io
import json
import math
import os
import sys
import time
import warnings
from pathlib import Path

from quasicentral.models.parameters import G_STANDARD

EXIT_OK, EXIT_UNEXPECTED, EXIT_USAGE = 0, 1, 2
MAX_DPS = 2000
VERIFY_MAX_DPS = 300  # the ladder doubles it, and every in-domain point is evaluated at both rungs


class UsageError(Exception):
    """Bad usage or input: reported as one line, exit 2."""


class _Parser(argparse.ArgumentParser):
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


def _positive_int(name: str, upper: int):
    def parse(text: str) -> int:
        try:
            val = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{name} must be a whole number, not {text!r}") from None
        if val <= 0 or val > upper:
            raise argparse.ArgumentTypeError(f"{name} must be between 1 and {upper}, not {val}")
        return val

    return parse


def _add_text_options(parser: argparse.ArgumentParser, source: bool = True) -> None:
    """--text DIR (repeatable) and --source ID: which texts a command works on."""
    parser.add_argument("--text", action="append", dest="texts", metavar="DIR",
                        help="a text's folder, or a shipped text's id (repeatable; default: the shipped texts)")
    if source:
        parser.add_argument("--source", metavar="ID",
                            help="only the entries of the text with this id, among those selected (default: all)")


def build_parser() -> argparse.ArgumentParser:

    p = _Parser(prog="quasicentral", description="Re-derive every equation of a text with sympy, check it with mpmath and ball "
                "arithmetic, and record its errata (the shipped texts, or a text of your own: new-text).",
                epilog="exit codes: 0 success, 1 an unexpected result (see each command), 2 bad usage or input\n"
                       "(one line on stderr).  A reader that closes the pipe early (| head) ends the output quietly\n"
                       "and the exit code stays the command's own, so `set -o pipefail` fails only on a real failure.\n"
                       "Long commands draw progress on stderr when it is a terminal (not when CI is set, nor with --json).\n"
                       "\nexamples:\n  quasicentral verify\n  quasicentral verify --help")
    p.add_argument("--version", action="version", version=f"%(prog)s {version()}")
    sub = p.add_subparsers(dest="command", parser_class=_Parser, metavar="COMMAND")

    v = _command(sub, "verify", "verify every catalog entry (printed vs derived)",
                 "Checks each equation as printed against its re-derivation: symbolically, then numerically on a\n"
                 "precision ladder (dps, 2·dps), certified by ball arithmetic where it can.  Verdicts are cached\n"
                 "under a hash of the code, the catalog, the errata and the options ($QUASICENTRAL_CACHE, else\n"
                 "~/.cache/quasicentral); a run whose code, texts and options are unchanged is read back whole.\n"
                 "Exit 0 when every entry is verified, a registered erratum or a cleared\n"
                 "suspect; 1 when anything is unexpected; 2 on bad usage (e.g. a selection that selects nothing).",
                 "quasicentral verify\n"
                 "quasicentral verify --text mynotes --json\n"
                 "quasicentral verify --text mynotes --id mynotes:2 --no-cache --jobs 2\n"
                 "quasicentral verify --junit build/verify.xml")
    _add_text_options(v)
    v.add_argument("--id", action="append", dest="ids", metavar="ID",
                   help="only this entry, TEXT:LABEL (repeatable; see `quasicentral catalog`)")
    v.add_argument("--json", action="store_true", help="print a JSON document instead of the table (no progress bar)")
    v.add_argument("--dps", type=_positive_int("--dps", VERIFY_MAX_DPS), default=30, metavar="N",
                   help=f"first rung of the precision ladder, decimal digits, at most {VERIFY_MAX_DPS} "
                        "(default 30; the ladder is dps, 2·dps)")
    v.add_argument("--no-cache", action="store_true", help="ignore cached verdicts (a cold run; default: use them)")
    v.add_argument("--junit", metavar="FILE", help="also write a JUnit XML report to FILE (default: none)")
    v.add_argument("--jobs", type=_positive_int("--jobs", 64), default=None, metavar="N",
                   help="worker processes, 1 to 64 (default: one per core, at most one per entry)")

    e = _command(sub, "errata", "the errata found and the suspects cleared",
                 "Lists each registered erratum (the printed form refuted, the corrected one verified, with the\n"
                 "witness values) and each suspect that turned out right.  Exit 0 when every erratum still stands\n"
                 "and every suspect is cleared, 1 otherwise.",
                 "quasicentral errata\nquasicentral errata --text mynotes --json")
    _add_text_options(e)
    e.add_argument("--json", action="store_true", help="print a JSON document instead of the table")
    e.add_argument("--no-cache", action="store_true", help="ignore cached verdicts (default: use them)")

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
    mu.add_argument("--per-entry", type=_positive_int("--per-entry", 50), default=None, metavar="N",
                    help="at most this many mutants per entry, 1 to 50, spread over the operators (default: all)")
    mu.add_argument("--jobs", type=_positive_int("--jobs", 64), default=None, metavar="N",
                    help="worker processes, 1 to 64 (default: one per core)")

    _add_period(sub)
    _add_trajectory(sub)

    fg = _command(sub, "figures", "reproduce the texts' missing figures (CSV data and PNG plots)",
                  "Writes each text's figures (those its folder's figures.py lists: for the shipped texts the\n"
                  "figures lost in print and the measured charts) as CSV data and PNG plots.  Each file is written through a temporary file and\n"
                  "a rename, only inside DIR; a symbolic link where a file would go is refused (exit 2).",
                  "quasicentral figures\nquasicentral figures --out build/figures")
    fg.add_argument("--out", default="figures", metavar="DIR", help="output directory, created if needed (default figures)")
    _add_text_options(fg)

    _add_charts(sub)

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

    nt = _command(sub, "new-text", "write the skeleton of a text of your own (a folder) that verifies at once",
                  "Writes DIR/text.toml (the text's id, title, language and symbol table), DIR/catalog/ (what is\n"
                  "printed, transcribed), DIR/errata/ (one recorded erratum as an example) and DIR/motion.py (the\n"
                  "derivations).  Edit them into your own text; README: \"Verify your own derivation\".",
                  "quasicentral new-text mynotes\nquasicentral verify --text mynotes")
    nt.add_argument("dir", metavar="DIR", help="the new text's folder (must not exist, or be empty)")
    nt.add_argument("--id", dest="text_id", metavar="ID", help="the text's id (default: the folder's name)")

    _add_scene(sub)

    c = _command(sub, "catalog", "list the catalog: ids, dimensions, LaTeX-parser coverage",
                 "Lists every entry with its id (for verify --id), section and dimensions, and which of sympy's\n"
                 "LaTeX parsers read its printed form back correctly (each answer kept in the cache).",
                 "quasicentral catalog\nquasicentral catalog --text mynotes --json")
    _add_text_options(c)
    c.add_argument("--json", action="store_true", help="print a JSON document instead of the table")
    c.add_argument("--no-cache", action="store_true",
                   help="parse every entry's LaTeX anew (default: read the kept answers back)")
    return p


class _QuietPipe:
    """``sys.stdout`` while a command runs: once the reader has closed the pipe, the rest of the
    output goes to /dev/null and the command finishes with its own exit code."""

    def __init__(self, stream):
        self._stream = stream
        self.broken = False

    def _break(self) -> None:
        self.broken = True
        try:  # the interpreter flushes the real stdout at exit: point its descriptor at /dev/null
            fd = self._stream.fileno()
            null = os.open(os.devnull, os.O_WRONLY)
            os.dup2(null, fd)
            os.close(null)
        except (OSError, ValueError, AttributeError, io.UnsupportedOperation):
            pass

    def write(self, text: str) -> int:
        if not self.broken:
            try:
                return self._stream.write(text)
            except BrokenPipeError:
                self._break()
        return len(text)

    def flush(self) -> None:
        if not self.broken:
            try:
                self._stream.flush()
            except BrokenPipeError:
                self._break()

    def __getattr__(self, name):
        return getattr(self._stream, name)


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
    pe.add_argument("--terms", type=_positive_int("--terms", SERIES_MAX_TERMS), default=None,
                    help="terms of the series (66), with --method series (default 4)")
    pe.add_argument("--dps", type=_positive_int("--dps", MAX_DPS), default=None,
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
    tr.add_argument("--n", type=_positive_int("--n", MAX_POINTS), metavar="N", help="number of times from --t0 to --t1")
    tr.add_argument("--dps", type=_positive_int("--dps", MAX_DPS), default=None,
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


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    out = sys.stdout
    quiet = sys.stdout = _QuietPipe(out)
    try:
        args = parser.parse_args(argv)
        if args.command is None:
            raise UsageError(f"a command is required: {', '.join(sorted(_COMMANDS))} (see --help)")
        code = _COMMANDS[args.command](args)
        sys.stdout.flush()
        return code
    except UsageError as exc:
        print(f"quasicentral: error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except KeyboardInterrupt:
        print("quasicentral: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # a write that bypassed sys.stdout: the command's own code is lost
        quiet._break()
        return EXIT_OK
    except Exception as exc:  # noqa: BLE001 - the CLI never shows a traceback
        from quasicentral.engine.catalog import CatalogError

        if isinstance(exc, CatalogError):
            print(f"quasicentral: error: malformed data: {exc}", file=sys.stderr)
            return EXIT_USAGE
        print(f"quasicentral: internal error: {type(exc).__name__}: {exc}", file=sys.stderr)
        return EXIT_UNEXPECTED
    finally:
        if sys.stdout is quiet:
            sys.stdout = out


# --- progress on stderr ----------------------------------------------------------------------
def show_progress(args=None, stream=None, environ=None) -> bool:
    """Whether to draw a progress bar: stderr is a terminal, ``CI`` is not set (to anything but
    "", "0" or "false") and ``--json`` was not asked for."""
    stream = sys.stderr if stream is None else stream
    environ = os.environ if environ is None else environ
    if args is not None and getattr(args, "json", False):
        return False
    if environ.get("CI", "").strip().lower() not in ("", "0", "false", "no"):
        return False
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError, OSError):
        return False


class ProgressBar:
    """The callback the CLI hands to library functions: draws a tqdm bar on stderr when
    :func:`show_progress` says so, and always keeps the last record (for the timing line)."""

    mininterval = 0.2  # seconds between redraws

    def __init__(self, args, label: str, stream=None, enabled: bool | None = None):
        self.stream = sys.stderr if stream is None else stream
        self.enabled = show_progress(args, self.stream) if enabled is None else enabled
        self.label = label
        self.last = None
        self._bar = None
        self._phase = None

    def __call__(self, rec) -> None:
        self.last = rec
        if not self.enabled:
            return
        from tqdm import tqdm

        if self._bar is None or rec.phase != self._phase:
            self.close()
            self._phase = rec.phase
            size = self._size()
            self._bar = tqdm(total=rec.total, initial=rec.done, desc=self.label, unit=f" {rec.phase or 'items'}",
                             file=self.stream, dynamic_ncols=size is None, ncols=size and size[0],
                             nrows=size and size[1], leave=False, mininterval=self.mininterval,
                             bar_format="{desc}: {n_fmt}/{total_fmt}{unit} {bar} [{elapsed}<{remaining}{postfix}]")
        self._bar.total = rec.total
        if rec.current:
            done = "read from the cache" if rec.current == "cache" else f"last done: {rec.current}"
            self._bar.set_postfix_str(done, refresh=False)
        if rec.done > self._bar.n:
            self._bar.update(rec.done - self._bar.n)
        else:
            self._bar.refresh()

    def _size(self) -> tuple[int, int] | None:
        """None to follow the terminal's size; 80 × 24 when it reports none (a pty without a size)."""
        try:
            size = os.get_terminal_size(self.stream.fileno())
        except (OSError, ValueError, AttributeError, io.UnsupportedOperation):
            return 80, 24
        return None if size.columns > 0 and size.lines > 0 else (80, 24)

    def close(self) -> None:
        if self._bar is not None:
            self._bar.close()
            self._bar = None

    def __enter__(self):
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def _entries(n: int) -> str:
    return f"{n} entr{'y' if n == 1 else 'ies'}"


def _timing(args, text: str) -> None:
    """The line that says what was timed (stderr; not with --json)."""
    if not getattr(args, "json", False):
        print(text, file=sys.stderr)


# --- the verification commands ---------------------------------------------------------------
def _texts(args, source_filter: bool = True) -> list:
    """The texts a command works on: --text folders or ids (default the shipped ones), loaded;
    narrowed to --source unless ``source_filter`` is false."""
    from quasicentral.engine import texts

    selected = texts.resolve(getattr(args, "texts", None))
    source = getattr(args, "source", None)
    if source is not None and source_filter:
        chosen = [t for t in selected if t.id == source]
        if not chosen:
            raise UsageError(f"--source {source}: no such text among {', '.join(t.id for t in selected)}")
        selected = chosen
    return texts.activate(selected, exclusive=True)  # a command works on exactly these texts


def _selected(args):
    from quasicentral.engine import texts

    everything = texts.entries(_texts(args, source_filter=False))
    source = getattr(args, "source", None)
    entries = [e for e in everything if source is None or e.text == source]
    if source is not None and not entries:
        raise UsageError(f"--source {source}: no such text among {', '.join(sorted({e.text for e in everything}))}")
    ids = getattr(args, "ids", None)
    if ids:
        known = {e.id for e in everything}
        for i in ids:
            if i not in known:
                raise UsageError(f"--id: unknown equation id {i!r} (see `quasicentral catalog`)")
        in_source = {e.id for e in entries}
        outside = [i for i in ids if i not in in_source]
        if outside:
            raise UsageError(f"--id {outside[0]} is not in --source {source}: the selection would leave it out")
        entries = [e for e in entries if e.id in set(ids)]
    if not entries:
        raise UsageError("nothing selected: check --text, --source and --id")
    return entries


def _replay_key(args) -> str | None:
    """The key of a whole cached ``verify`` run with these options (None: none can apply)."""
    from quasicentral.engine import fingerprint, replay

    folders = fingerprint.text_folders(args.texts)
    if folders is None:
        return None  # the full reader says what is wrong with the names
    options = {"source": args.source, "ids": args.ids, "dps": args.dps, "json": args.json,
               "junit": args.junit is not None}
    return replay.key("verify", options, folders)


def _verify(args) -> int:
    from quasicentral.engine import replay

    if args.junit is not None and not args.junit.strip():
        raise UsageError("--junit needs a file name")
    t0 = time.perf_counter()
    key = None if args.no_cache else _replay_key(args)
    if key is not None:
        try:
            rec = replay.load(key)
        except replay.ReplayError as exc:
            _warn(f"cache: {exc}; discarded, recomputed")
            rec = None
        if rec is not None:  # nothing the run depends on has changed since
            if args.junit:
                _write_atomic(Path(args.junit), rec.junit or "", "--junit")
            sys.stdout.write(rec.stdout)
            _timing(args, f"verify: {_entries(rec.entries)} read back in {time.perf_counter() - t0:.1f} s "
                          "(a cached run: nothing it depends on has changed)")
            return rec.exit
    return _verify_run(args, key, t0)


def _verify_run(args, key: str | None, t0: float) -> int:
    from quasicentral.engine import formats as output
    from quasicentral.engine import replay
    from quasicentral.engine import run as verify
    from quasicentral.engine.checker import Options

    try:
        opts = Options(dps=args.dps)  # the ladder's floor is the checker's (Options.MIN_DPS)
    except ValueError as exc:
        raise UsageError(f"--dps: {exc}") from None
    entries = _selected(args)
    with ProgressBar(args, "verify") as bar:
        outcomes = verify.run(entries, opts, use_cache=not args.no_cache, jobs=args.jobs, progress=bar,
                              on_warning=_warn)
    seconds = time.perf_counter() - t0
    doc = output.verify_document(entries, outcomes)
    junit = output.junit_xml(entries, outcomes) if args.junit else None
    if args.junit:
        _write_atomic(Path(args.junit), junit, "--junit")
    shown = (json.dumps(doc, indent=2, sort_keys=False, ensure_ascii=False) if args.json
             else output.verify_table(doc)) + "\n"
    sys.stdout.write(shown)
    cached = bar.last.cached if bar.last else 0
    _timing(args, f"verify: checked {_entries(len(entries))} in {seconds:.1f} s "
                  f"(computed: {len(entries) - cached}, read from the cache: {cached})")
    code = EXIT_OK if doc["summary"]["ok"] else EXIT_UNEXPECTED
    if key is not None:
        keys = verify.cache_keys(entries, opts)
        digests = {verify.cache_file(keys[e.id]).name: replay.digest(verify.cache_file(keys[e.id])) for e in entries}
        if all(digests.values()):  # every verdict is in the cache: the run can be read back
            replay.store(key, replay.Record(stdout=shown, exit=code, entries=len(entries), junit=junit,
                                            verdicts=digests))
    return code


def _errata(args) -> int:
    from quasicentral.engine import formats as output
    from quasicentral.engine import run as verify
    from quasicentral.engine.checker import Options

    entries = _selected(args)
    with ProgressBar(args, "errata") as bar:
        outcomes = verify.run(entries, Options(), use_cache=not args.no_cache, progress=bar, on_warning=_warn)
    doc = output.errata_document(entries, outcomes)
    if args.json:
        print(json.dumps(doc, indent=2, ensure_ascii=False))
    else:
        print(output.errata_table(doc))
    return EXIT_OK if all(o.ok for o in outcomes if o.erratum or o.status == "cleared") else EXIT_UNEXPECTED


def _mutate(args) -> int:
    from quasicentral.engine import mutate

    t0 = time.perf_counter()
    with ProgressBar(args, "mutate") as bar:
        res = mutate.run(_texts(args), per_entry=args.per_entry, jobs=args.jobs, progress=bar)
    seconds = time.perf_counter() - t0
    if args.json:
        print(json.dumps(res, indent=2, ensure_ascii=False))
    else:
        print(mutate.table(res))
    _timing(args, f"mutate: {res['mutants']} mutants of {_entries(res['entries'])} checked in {seconds:.1f} s")
    return EXIT_OK if res["recall"] == 1.0 and res["false_alarms"] == 0 else EXIT_UNEXPECTED


def _catalog(args) -> int:
    from quasicentral.engine import latexparse
    from quasicentral.engine import formats as output

    entries = _selected(args)
    t0 = time.perf_counter()
    with ProgressBar(args, "catalog") as bar:
        cov = latexparse.coverage(entries, progress=bar, use_cache=not args.no_cache)
    seconds = time.perf_counter() - t0
    doc = output.catalog_document(entries, cov)
    if args.json:
        print(json.dumps(doc, indent=2, ensure_ascii=False))
    else:
        print(output.catalog_table(doc))
    _timing(args, f"catalog: parsed the LaTeX of {_entries(len(entries))} in {seconds:.1f} s "
                  f"(parsed: {len(entries) - cov['cached']}, read from the cache: {cov['cached']})")
    return EXIT_OK


@contextmanager
def _writing(option: str, target):
    """Turn a refused or failed write into one line naming ``option`` (exit 2)."""
    from quasicentral.files import UnsafePath

    name = f"{option}: " if option else ""
    try:
        yield
    except UnsafePath as exc:
        raise UsageError(f"{name}{exc}") from None
    except OSError as exc:
        raise UsageError(f"{name}cannot write to {target}: {exc.strerror or exc}") from None


def _write_atomic(path: Path, text: str, option: str = "") -> None:
    """Write via a temporary file and rename, so a failure never leaves a half-written file;
    a symbolic link at ``path`` is refused."""
    from quasicentral.files import write_text

    with _writing(option, path):
        path.parent.mkdir(parents=True, exist_ok=True)
        write_text(path, text)


def _out_dir(args) -> Path:
    if not args.out.strip():
        raise UsageError("--out needs a directory name")
    return Path(args.out)


def _warn(message: str) -> None:
    print(f"quasicentral: warning: {message}", file=sys.stderr)


def _period_refuse_ignored(args) -> None:
    """Options that would be silently ignored are refused, naming the option."""
    if args.table:
        for flag, value in (("--amplitude-deg", args.amplitude_deg), ("--amplitude-rad", args.amplitude_rad),
                            ("--complement-rad", args.complement_rad), ("--dps", args.dps),
                            ("--method", args.method), ("--terms", args.terms), ("--l", args.l), ("--g", args.g)):
            if value is not None:
                raise UsageError(f"{flag} has no effect with --table (T/T0 from 5° to 179.99° at 20 digits)")
    elif args.terms is not None and args.method != "series":
        raise UsageError(f"--terms applies to --method series only, not {args.method or 'ellipk'}")


def _period_table(args) -> int:
    from quasicentral.models import period as P

    rows = P.table()
    if args.json:
        print(json.dumps({"table": rows}, indent=2))
    else:
        print("amplitude   T/T0 (AGM, correctly rounded)   quadrature agrees")
        for r in rows:
            print(f"{r['amplitude_deg']:>9}°  {r['T_over_T0']:<30}  {'yes' if r['agree'] else 'NO'}")
    return EXIT_OK if all(r["agree"] for r in rows) else EXIT_UNEXPECTED


def _period_input(args) -> dict:
    """The amplitude or its complement as an exact decimal string, keyed as period.* takes it."""
    from quasicentral.notation import numbers

    given = {"phi0": ("--amplitude-rad", args.amplitude_rad), "amplitude_deg": ("--amplitude-deg", args.amplitude_deg),
             "delta": ("--complement-rad", args.complement_rad)}
    given = {k: (flag, v) for k, (flag, v) in given.items() if v is not None}
    if not given:
        raise UsageError("give --amplitude-deg, --amplitude-rad or --complement-rad")
    (key, (flag, text)), = given.items()
    try:
        return {key: str(numbers.decimal(text, flag))}, flag
    except numbers.NumberError as exc:
        raise UsageError(str(exc)) from None


def _period(args) -> int:
    from quasicentral.models import period as P
    from quasicentral.notation import numbers

    _period_refuse_ignored(args)
    if args.table:
        return _period_table(args)
    kw, flag = _period_input(args)
    method = args.method or "ellipk"
    terms = args.terms or 4
    l_text, g_text = args.l or "1", args.g or str(G_STANDARD)
    length, grav = finite_float(l_text, "--l"), finite_float(g_text, "--g")
    if length <= 0:
        raise UsageError(f"--l must be a positive length, not {l_text}")
    if grav <= 0:
        raise UsageError(f"--g must be positive, not {g_text}")
    try:
        out = {"method": method}
        if args.dps:
            out.update(_period_digits(P, kw, method, terms, args.dps, l_text, g_text))
        else:
            ratio = float(P.period_ratio(**kw, method=method, terms=terms))
            t0 = 2 * math.pi * math.sqrt(length / grav)
            out.update({"T": t0 * ratio, "T_over_T0": ratio, "T0": t0})
        if method == "series":
            _series_warning(P, kw, terms, out, args.dps or 16)
    except P.DomainError as exc:
        raise UsageError(f"{flag}: {exc}") from None
    except numbers.NumberError as exc:
        raise UsageError(str(exc)) from None
    if not all(math.isfinite(float(v)) for k, v in out.items() if k in ("T", "T_over_T0")):
        raise UsageError(f"the result is not finite for {flag} {next(iter(kw.values()))}")
    if "warning" in out:
        _warn(out["warning"])
    if args.json:
        print(json.dumps(out, indent=2, allow_nan=False))
    else:
        for k, v in out.items():
            print(f"{k:15s} {v}")
    return EXIT_OK


#: the most digits the slow routes are allowed (seconds at these limits); the ODE at any
#: precision also integrates at most ODE_MAX_QUARTER time units 1/Ω (a quarter period K(m))
PERIOD_MAX_DPS = {"ode": 40, "quad": 300}
ODE_MAX_QUARTER = 25.0


def _period_digits(P, kw, method, terms, dps, l_text, g_text) -> dict:
    import mpmath

    if dps > PERIOD_MAX_DPS.get(method, MAX_DPS):
        raise UsageError(f"--dps: --method {method} takes at most {PERIOD_MAX_DPS[method]} digits (it would run for "
                         "minutes); agm and ellipk take up to " + str(MAX_DPS))
    if method == "ode":
        quarter = float(P.period_ratio(**kw)) * math.pi / 2
        if quarter > ODE_MAX_QUARTER:
            raise UsageError(f"--method ode with --dps integrates a quarter period of {quarter:.3g} time units 1/Ω "
                             f"here (more than {ODE_MAX_QUARTER:g}: minutes); use --method agm or ellipk")

    if method in ("agm", "ellipk"):
        ratio_text = P.period_ratio_rounded(digits=dps, method=method, **kw)
    else:
        ratio_text = mpmath.nstr(P.period_ratio_mp(dps=dps, method=method, terms=terms, **kw), dps, strip_zeros=False)
    with mpmath.workdps(dps + 10):
        t0 = 2 * mpmath.pi * mpmath.sqrt(mpmath.mpf(l_text) / mpmath.mpf(g_text))
        return {"T": mpmath.nstr(t0 * mpmath.mpf(ratio_text), dps, strip_zeros=False), "T_over_T0": ratio_text,
                "T0": mpmath.nstr(t0, dps, strip_zeros=False), "digits": dps}


def _series_warning(P, kw, terms, out, printed_digits) -> None:
    """The series' error estimate, and how many digits hold when fewer than are printed."""
    value, tail = (float(a) for a in P.series_error(**kw, terms=terms))
    out["terms"] = terms
    out["error_estimate"] = tail if math.isfinite(tail) else None
    rel = tail / value if math.isfinite(tail) else math.inf
    if rel >= 0.1:
        bound = f"{tail:.2g}" if math.isfinite(tail) else "unbounded"
        raise UsageError(f"--terms: the series (66) truncated after {terms} terms holds no digit here (error "
                         f"estimate {bound} for T/T0 ≈ {value:.3g}); use more terms or --method ellipk")
    held = max(0, int(math.floor(-math.log10(rel)))) if rel > 0 else printed_digits
    if held < printed_digits:
        out["digits"] = held
        bound = f"{tail:.2g}" if math.isfinite(tail) else "unbounded"
        out["warning"] = (f"the series (66) truncated after {terms} terms holds about {held} significant digits "
                          f"here (error estimate {bound}); use more --terms or --method ellipk")


MAX_POINTS = 10**6  # --n, and the number of --t values
MAX_POINTS_DPS = 10**4  # the same with --dps (mpmath evaluates point by point)


def _trajectory(args) -> int:
    import mpmath

    from quasicentral.models import motion

    if args.dps:
        # numbers are read, and the times spaced, at the asked precision plus guard digits
        with mpmath.workdps(args.dps + 20):
            return _trajectory_run(args, motion, mpmath)
    return _trajectory_run(args, motion, mpmath)


def _trajectory_drag(args, num):
    """(kappa, beta) for the model: --kappa is required by the linear model, --beta by the
    quadratic ones; the other one is refused."""
    quadratic = args.model.startswith("quadratic")
    if args.beta is not None and not quadratic:
        raise UsageError(f"--beta: model {args.model} takes --kappa, not --beta")
    if args.kappa is not None and quadratic:
        raise UsageError(f"--kappa: model {args.model} takes --beta, not --kappa")
    if quadratic and args.beta is None:
        raise UsageError(f"--beta is required by model {args.model} (quadratic drag, 1/m)")
    if args.model == "linear" and args.kappa is None:
        raise UsageError("--kappa is required by model linear (linear drag, 1/s; --kappa 0 for none)")
    kappa = num(args.kappa, "--kappa") if args.kappa is not None else 0
    beta = num(args.beta, "--beta") if args.beta is not None else 0
    if args.model == "ellipse" and args.kappa is not None and kappa != 0:
        raise UsageError("--kappa: model ellipse has no drag; leave out --kappa")
    return kappa, beta


def _trajectory_pendulum(args, num):
    """(Ω², l, g): from --omega2, or from --l and --g (then R0 must stay below l)."""
    if args.omega2 is not None:
        if args.l is not None or args.g is not None:
            raise UsageError("--omega2: give --omega2 or --l and --g, not both")
        return num(args.omega2, "--omega2"), None, None
    if args.l is None or args.g is None:
        raise UsageError("give --omega2, or --l and --g")
    length, grav = num(args.l, "--l"), num(args.g, "--g")
    if length <= 0:
        raise UsageError(f"--l must be a positive length, not {args.l}")
    if grav <= 0:
        raise UsageError(f"--g must be positive, not {args.g}")
    return grav / length, length, grav


def _trajectory_run(args, motion, mpmath) -> int:
    num = (lambda text, name: _exact_number(text, name)) if args.dps else (lambda text, name: finite_float(text, name))
    R0, v0 = num(args.R0, "--R0"), num(args.v0, "--v0")
    omega2, length, grav = _trajectory_pendulum(args, num)
    kappa, beta = _trajectory_drag(args, num)
    times = _times(args, num)
    import numpy as np

    try:
        with np.errstate(all="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore")  # a failure is reported below, in one line
            x, y = motion.trajectory(args.model, times, R0, v0, omega2, kappa, beta, dps=args.dps, length=length,
                                     g=grav)
    except motion.ParameterError as exc:
        raise UsageError(_name_option(str(exc), exc.name)) from None
    except (ValueError, ArithmeticError) as exc:
        raise UsageError(str(exc)) from None
    if not all(mpmath.isfinite(v) for v in list(times) + list(x) + list(y)):
        raise UsageError("the result is not finite for these inputs (a time or a value overflows)")
    warning = None
    if args.model == "quadratic-first-order":
        warning = motion.first_order_warning(motion.Swing(R0, v0, omega2, 0, beta), float(max(times)))
    return _trajectory_print(args, times, x, y, warning, mpmath)


def _name_option(message: str, name: str | None) -> str:
    """'R0 must be …' → '--R0 must be …'; other messages get the option as a prefix."""
    if name not in ("R0", "v0", "omega2", "kappa", "beta", "t", "l", "g"):
        return message
    return "--" + message if message.startswith(name + " ") else f"--{name}: {message}"


def _trajectory_print(args, times, x, y, warning, mpmath) -> int:
    if args.dps:
        fmt = lambda a: mpmath.nstr(a, args.dps, strip_zeros=False)  # noqa: E731
    else:
        fmt = float
    params = {"R0": args.R0, "v0": args.v0, "omega2": args.omega2, "l": args.l, "g": args.g, "kappa": args.kappa,
              "beta": args.beta}
    doc = {"model": args.model, "parameters": {k: v for k, v in params.items() if v is not None},
           "t": [fmt(a) for a in times], "x": [fmt(a) for a in x], "y": [fmt(a) for a in y]}
    if args.dps:
        doc["digits"] = args.dps
    if warning:
        doc["warning"] = warning
        _warn(warning)
    if args.csv:
        print("t,x,y")
        for a, b, c in zip(doc["t"], doc["x"], doc["y"]):
            print(f"{a!r},{b!r},{c!r}" if not args.dps else f"{a},{b},{c}")
    elif args.json:
        print(json.dumps(doc, allow_nan=False))
    else:
        print(f"model {args.model}: {len(times)} points")
        for a, b, c in zip(doc["t"], doc["x"], doc["y"]):
            print(f"{a}\t{b}\t{c}")
    return EXIT_OK


def _exact_number(text: str, name: str):
    """An mpmath number from a decimal string, at the working precision."""
    from quasicentral.notation import numbers

    try:
        return numbers.to_mpf(text, name)
    except numbers.NumberError as exc:
        raise UsageError(str(exc)) from None


def _times(args, num):
    if args.t is not None:
        if any(v is not None for v in (args.t0, args.t1, args.n)):
            raise UsageError("give --t, or --t0 --t1 --n, not both")
        parts = [p for p in args.t.split(",") if p.strip()]
        if not parts:
            raise UsageError("--t is an empty list of times")
        limit = MAX_POINTS_DPS if args.dps else MAX_POINTS
        if len(parts) > limit:
            raise UsageError(f"--t has {len(parts)} times; at most {limit}{' with --dps' if args.dps else ''}")
        times = [num(p, "--t") for p in parts]
    elif None not in (args.t0, args.t1, args.n):
        a, b = num(args.t0, "--t0"), num(args.t1, "--t1")
        if b < a:
            raise UsageError("--t1 must not be before --t0")
        n = args.n
        if args.dps and n > MAX_POINTS_DPS:
            raise UsageError(f"--n must be at most {MAX_POINTS_DPS} with --dps (each point is evaluated in mpmath)")
        times = [a + (b - a) * i / (n - 1) for i in range(n)] if n > 1 else [a]
    else:
        raise UsageError("give the times: --t T1,T2,... or --t0 A --t1 B --n N")
    if any(tt < 0 for tt in times):
        raise UsageError("times must be ≥ 0 (the motion starts at t = 0)")
    return times


def _scene(args) -> int:
    """Exit 0 when a model meets the scene's tolerance, 1 when none does, 2 on a bad scene."""
    from quasicentral.studies import scenes

    try:
        decision = scenes.decide(scenes.load(args.file))
    except scenes.SceneError as exc:
        raise UsageError(str(exc)) from None
    if args.plot:
        from quasicentral import files

        try:  # through a temporary file and a rename, never through a symbolic link
            files.write_atomic(Path(args.plot), lambda tmp: scenes.plot(decision, tmp))
        except OSError as exc:
            raise UsageError(f"--plot: cannot write {args.plot}: {exc.strerror or exc}") from None
    if args.json:
        print(json.dumps(scenes.document(decision), ensure_ascii=False))
    else:
        print(scenes.report(decision))
    return EXIT_OK if decision.meets else EXIT_UNEXPECTED


def _figures(args) -> int:
    from quasicentral.studies import figures

    out = _out_dir(args)
    with _writing("--out", args.out), ProgressBar(args, "figures") as bar:
        paths = figures.write_all(out, _texts(args), progress=bar)
    for p in paths:
        print(p)
    return EXIT_OK


def _report(args) -> int:
    from quasicentral.documents import report

    if args.all and (args.handout or args.lang is not None):
        raise UsageError("--all writes every document: leave out --handout and --lang")
    out = _out_dir(args)
    with _writing("--out", args.out):
        report.check_writable(out)
    _texts(args)  # the texts named by --text (default: the shipped ones) are the ones built
    if args.all:
        jobs = list(report.GOLDEN)
    else:
        jobs = [(report.HANDOUT_KINDS if args.handout else ("report",), (args.lang or "en",))]
    t0 = time.perf_counter()
    with ProgressBar(args, "report") as bar:
        outcomes = report.outcomes_for_all(progress=bar)
        docs: dict[str, str] = {}
        for kinds, langs in jobs:
            docs.update(report.generate(kinds, langs, outcomes))
        with _writing("--out", args.out):
            paths = report.write(out, dict(sorted(docs.items())), progress=bar)
    for p in paths:
        print(p)
    if args.pdf:
        try:
            with _writing("--out", args.out), ProgressBar(args, "report") as bar:
                pdfs = report.compile_all(out, [n for n in sorted(docs) if n != report.VERSIONS_FILE], progress=bar)
        except report.LatexError as exc:
            print(f"quasicentral: error: {exc}", file=sys.stderr)
            return EXIT_UNEXPECTED
        for p in pdfs:
            print(p)
    _timing(args, f"report: wrote {len(paths)} files{' and compiled them' if args.pdf else ''} "
                  f"in {time.perf_counter() - t0:.1f} s")
    return EXIT_OK


def _charts(args) -> int:
    from quasicentral.studies import charts

    out = Path(args.out)
    if args.only:
        for name in args.only:
            if name not in charts.CHARTS:
                raise UsageError(f"unknown chart {name!r}; choose from {', '.join(charts.CHARTS)}")
    try:
        if args.render_only:
            if args.quick or args.only:
                raise UsageError("--render-only redraws every CSV in DIR: leave out --quick and --only")
            if not out.is_dir() or not any(out.glob("*.csv")):
                raise UsageError(f"no chart data (CSV) in {args.out}")
            paths = charts.render_all(out)
        else:
            with ProgressBar(args, "charts") as bar:
                paths = charts.build(out, quick=args.quick, only=args.only, progress=bar)
    except OSError as exc:
        raise UsageError(f"cannot write charts to {args.out} ({exc.filename or args.out}): {exc.strerror or exc}") from None
    except charts.ChartError as exc:
        raise UsageError(str(exc)) from None
    for p in paths:
        print(p)
    return EXIT_OK


def _new_text(args) -> int:
    from quasicentral.engine import skeleton

    try:
        paths = skeleton.write(Path(args.dir), args.text_id)
    except skeleton.SkeletonError as exc:
        raise UsageError(str(exc)) from None
    for p in paths:
        print(p)
    print(f"next: quasicentral verify --text {args.dir}", file=sys.stderr)
    return EXIT_OK


_COMMANDS = {"new-text": _new_text, "charts": _charts, "scene": _scene, "report": _report, "figures": _figures, "trajectory": _trajectory, "verify": _verify, "errata": _errata, "mutate": _mutate, "catalog": _catalog, "period": _period}


def finite_float(text: str, name: str) -> float:
    """A finite double from a decimal string (:mod:`quasicentral.notation.numbers`); bad input
    is a UsageError naming the option."""
    from quasicentral.notation import numbers

    try:
        return numbers.to_float(text, name)
    except numbers.NumberError as exc:
        raise UsageError(str(exc)) from None


if __name__ == "__main__":
    sys.exit(main())
