"""The ``quasicentral`` command.

Exit codes: 0 success (every entry verified, a registered erratum or a cleared suspect);
1 something unexpected (a new mismatch, an erratum that no longer stands, an inconclusive
entry); 2 bad usage or bad input (one line on stderr naming the option, file or entry, never a
traceback).  SIGINT ends a run with 130, SIGTERM with 143, and every worker with it.

A reader that stops early (``quasicentral verify | head -2``) is not an error: the output
stops quietly and the exit code is still the command's own verdict (0 when everything
verified), not 141 or 1.  A pipeline under ``set -o pipefail`` therefore fails only when the
verification does, as it does with ``grep -q`` style readers.

Progress of long work (verify, errata, catalog, mutate, charts, report, figures) is drawn on
stderr with tqdm only when stderr is a terminal, the environment variable ``CI`` is not set
and ``--json`` is not given; library functions only report :class:`quasicentral.progress.Progress`
records to a callback.

The package: :mod:`~quasicentral.cli.parser` (the grammar), :mod:`~quasicentral.cli.terminal`
(standard output and error, progress), and the commands: :mod:`~quasicentral.cli.verification`,
:mod:`~quasicentral.cli.pendulum`, :mod:`~quasicentral.cli.studies`.
"""

from __future__ import annotations

import signal
import sys

from quasicentral.cli import pendulum, studies, verification
from quasicentral.cli.parser import EXIT_OK, EXIT_UNEXPECTED, EXIT_USAGE, UsageError, build_parser  # noqa: F401
from quasicentral.cli.pendulum import finite_float  # noqa: F401 - part of the command's module surface
from quasicentral.cli.terminal import ProgressBar, QuietPipe, error, show_progress  # noqa: F401

COMMANDS = {"new-text": verification.new_text, "charts": studies.charts, "scene": studies.scene,
            "report": verification.report, "figures": verification.figures, "trajectory": pendulum.trajectory,
            "verify": verification.verify, "errata": verification.errata, "mutate": verification.mutate,
            "catalog": verification.catalog, "period": pendulum.period}


def _terminated(signum, frame):
    raise SystemExit(128 + signum)


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    out = sys.stdout
    quiet = sys.stdout = QuietPipe(out)
    previous = signal.signal(signal.SIGTERM, _terminated)
    try:
        args = parser.parse_args(argv)
        if args.command is None:
            raise UsageError(f"a command is required: {', '.join(sorted(COMMANDS))} (see --help)")
        code = COMMANDS[args.command](args)
        sys.stdout.flush()
        return code
    except UsageError as exc:
        error(str(exc))
        return EXIT_USAGE
    except KeyboardInterrupt:
        print("quasicentral: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # a write that bypassed sys.stdout: the command's own code is lost
        quiet.close_quietly()
        return EXIT_OK
    except Exception as exc:  # noqa: BLE001 - the CLI never shows a traceback
        from quasicentral.engine.catalog import CatalogError

        if isinstance(exc, CatalogError):
            error(f"malformed data: {exc}")
            return EXIT_USAGE
        print(f"quasicentral: internal error: {type(exc).__name__}: {exc}", file=sys.stderr)
        return EXIT_UNEXPECTED
    finally:
        signal.signal(signal.SIGTERM, previous)
        if sys.stdout is quiet:
            sys.stdout = out


if __name__ == "__main__":
    sys.exit(main())
