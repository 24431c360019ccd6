"""The ``quasicentral`` command.

Exit codes: 0 success (every entry verified, a registered erratum or a cleared suspect);
1 something unexpected (a new mismatch, an erratum that no longer stands, an inconclusive
entry); 2 bad usage or bad input (one line on stderr, never a traceback).
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

EXIT_OK, EXIT_UNEXPECTED, EXIT_USAGE = 0, 1, 2
MAX_DPS = 2000


class UsageError(Exception):
    """Bad usage or input: reported as one line, exit 2."""


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # argparse would print usage and exit 2; we keep one line
        raise UsageError(message)


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


def build_parser() -> argparse.ArgumentParser:
    from .catalog import SOURCES

    p = _Parser(prog="quasicentral", description="Re-derive and verify Brepta (1953) and the exact pendulum period.")
    sub = p.add_subparsers(dest="command", parser_class=_Parser)

    v = sub.add_parser("verify", help="verify every catalog entry (printed vs derived)")
    v.add_argument("--source", choices=sorted(SOURCES))
    v.add_argument("--id", action="append", dest="ids", metavar="ID", help="only this entry (repeatable)")
    v.add_argument("--json", action="store_true")
    v.add_argument("--dps", type=_positive_int("--dps", MAX_DPS), default=30,
                   help="first rung of the precision ladder, decimal digits (default 30; the ladder is dps, 2·dps)")
    v.add_argument("--no-cache", action="store_true", help="ignore cached verdicts (a cold run)")
    v.add_argument("--junit", metavar="FILE", help="also write a JUnit XML report")
    v.add_argument("--jobs", type=_positive_int("--jobs", 64), default=None, help="worker processes (default: cores)")

    e = sub.add_parser("errata", help="the errata found and the suspects cleared")
    e.add_argument("--source", choices=sorted(SOURCES))
    e.add_argument("--json", action="store_true")
    e.add_argument("--no-cache", action="store_true")

    mu = sub.add_parser("mutate", help="seed typical typos into verified entries and measure the checker")
    mu.add_argument("--json", action="store_true")
    mu.add_argument("--source", choices=sorted(SOURCES))
    mu.add_argument("--per-entry", type=_positive_int("--per-entry", 50), default=None,
                    help="at most this many mutants per entry (default: all)")

    c = sub.add_parser("catalog", help="list the catalog: ids, dimensions, LaTeX-parser coverage")
    c.add_argument("--source", choices=sorted(SOURCES))
    c.add_argument("--json", action="store_true")
    return p


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
        if args.command is None:
            raise UsageError("a command is required: verify, errata, mutate or catalog (see --help)")
        return _COMMANDS[args.command](args)
    except UsageError as exc:
        print(f"quasicentral: error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except KeyboardInterrupt:
        print("quasicentral: interrupted", file=sys.stderr)
        return 130
    except Exception as exc:  # noqa: BLE001 - the CLI never shows a traceback
        from .catalog import CatalogError

        if isinstance(exc, CatalogError):
            print(f"quasicentral: error: malformed data: {exc}", file=sys.stderr)
            return EXIT_USAGE
        print(f"quasicentral: internal error: {type(exc).__name__}: {exc}", file=sys.stderr)
        return EXIT_UNEXPECTED


def _selected(args):
    from . import catalog

    entries = catalog.entries(getattr(args, "source", None))
    ids = getattr(args, "ids", None)
    if ids:
        known = catalog.load()
        for i in ids:
            if i not in known:
                raise UsageError(f"unknown equation id {i!r}")
        entries = [e for e in entries if e.id in set(ids)]
    return entries


def _verify(args) -> int:
    from . import output, verify
    from .check import Options

    entries = _selected(args)
    t0 = time.perf_counter()
    outcomes = verify.run(entries, Options(dps=args.dps), use_cache=not args.no_cache, jobs=args.jobs)
    seconds = time.perf_counter() - t0
    doc = output.verify_document(entries, outcomes)
    if args.junit:
        _write_atomic(Path(args.junit), output.junit_xml(entries, outcomes))
    if args.json:
        print(json.dumps(doc, indent=2, sort_keys=False, ensure_ascii=False))
    else:
        print(output.verify_table(doc))
        print(f"({seconds:.1f} s)", file=sys.stderr)
    return EXIT_OK if doc["summary"]["ok"] else EXIT_UNEXPECTED


def _errata(args) -> int:
    from . import output, verify
    from .check import Options

    entries = _selected(args)
    outcomes = verify.run(entries, Options(), use_cache=not args.no_cache)
    doc = output.errata_document(entries, outcomes)
    if args.json:
        print(json.dumps(doc, indent=2, ensure_ascii=False))
    else:
        print(output.errata_table(doc))
    return EXIT_OK if all(o.ok for o in outcomes if o.erratum or o.status == "cleared") else EXIT_UNEXPECTED


def _mutate(args) -> int:
    from . import mutate

    res = mutate.run(source=args.source, per_entry=args.per_entry)
    if args.json:
        print(json.dumps(res, indent=2, ensure_ascii=False))
    else:
        print(mutate.table(res))
    return EXIT_OK


def _catalog(args) -> int:
    from . import latexparse, output

    entries = _selected(args)
    cov = latexparse.coverage(entries)
    doc = output.catalog_document(entries, cov)
    if args.json:
        print(json.dumps(doc, indent=2, ensure_ascii=False))
    else:
        print(output.catalog_table(doc))
    return EXIT_OK


def _write_atomic(path: Path, text: str) -> None:
    """Write via a temporary file and rename, so a failure never leaves a half-written file."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        tmp = path.with_name(path.name + ".tmp")
        tmp.write_text(text, encoding="utf-8")
        tmp.replace(path)
    except OSError as exc:
        raise UsageError(f"cannot write {path}: {exc.strerror}") from None


_COMMANDS = {"verify": _verify, "errata": _errata, "mutate": _mutate, "catalog": _catalog}


def finite_float(text: str, name: str) -> float:
    """Parse a finite float for the CLI (NaN and infinities are bad input)."""
    try:
        val = float(text)
    except ValueError:
        raise UsageError(f"{name} must be a number, not {text!r}") from None
    if not math.isfinite(val):
        raise UsageError(f"{name} must be finite, not {text!r}")
    return val


if __name__ == "__main__":
    sys.exit(main())
