"""The study commands: scenes and charts."""

from __future__ import annotations

import json
from pathlib import Path

from quasicentral.cli.parser import EXIT_OK, EXIT_UNEXPECTED, UsageError
from quasicentral.cli.terminal import ProgressBar


def scene(args) -> int:
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



def charts(args) -> int:
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


