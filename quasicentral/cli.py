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
VERIFY_MAX_DPS = 300  # the ladder doubles it, and every in-domain point is evaluated at both rungs


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
    from quasicentral.engine.catalog import SOURCES

    p = _Parser(prog="quasicentral", description="Re-derive and verify Brepta (1953) and the exact pendulum period.")
    sub = p.add_subparsers(dest="command", parser_class=_Parser)

    v = sub.add_parser("verify", help="verify every catalog entry (printed vs derived)")
    v.add_argument("--source", choices=sorted(SOURCES))
    v.add_argument("--id", action="append", dest="ids", metavar="ID", help="only this entry (repeatable)")
    v.add_argument("--json", action="store_true")
    v.add_argument("--dps", type=_positive_int("--dps", VERIFY_MAX_DPS), default=30,
                   help="first rung of the precision ladder, decimal digits (default 30; the ladder is dps, 2·dps)")
    v.add_argument("--no-cache", action="store_true", help="ignore cached verdicts (a cold run)")
    v.add_argument("--junit", metavar="FILE", help="also write a JUnit XML report")
    v.add_argument("--jobs", type=_positive_int("--jobs", 64), default=None, help="worker processes (default: cores)")

    e = sub.add_parser("errata", help="the errata found and the suspects cleared")
    e.add_argument("--source", choices=sorted(SOURCES))
    e.add_argument("--json", action="store_true")
    e.add_argument("--no-cache", action="store_true")

    mu = sub.add_parser("mutate", help="seed typical typos into verified entries and measure the checker",
                        description="Seed typical typos into verified entries and measure the checker's recall. "
                                    "Mutants equivalent on the declared domain (a proof under the domain's signs, "
                                    "or the full checker verifies them) are listed and not counted.",
                        epilog="exit codes: 0 recall 100 % and no false alarm; 1 an undetected mutant or a "
                               "false alarm (listed); 2 bad usage")
    mu.add_argument("--json", action="store_true")
    mu.add_argument("--source", choices=sorted(SOURCES))
    mu.add_argument("--per-entry", type=_positive_int("--per-entry", 50), default=None,
                    help="at most this many mutants per entry (default: all)")

    pe = sub.add_parser("period", help="the exact period of the simple pendulum, T and T/T0")
    amp = pe.add_mutually_exclusive_group()
    amp.add_argument("--amplitude-deg", metavar="A")
    amp.add_argument("--amplitude-rad", metavar="A")
    amp.add_argument("--complement-rad", metavar="D", help="δ = π − φ0 (full accuracy near π)")
    pe.add_argument("--l", metavar="L", default="1", help="length in m (default 1)")
    pe.add_argument("--g", metavar="G", default="9.81", help="gravity in m/s² (default 9.81)")
    pe.add_argument("--method", choices=("agm", "series", "ellipk", "quad", "ode"), default="ellipk")
    pe.add_argument("--terms", type=_positive_int("--terms", 10**6), default=4, help="terms of the series (66)")
    pe.add_argument("--dps", type=_positive_int("--dps", MAX_DPS), default=None,
                    help="decimal digits (inputs read exactly; agm and ellipk results correctly rounded)")
    pe.add_argument("--table", action="store_true", help="T/T0 from 5° to 179.99° at 20 digits, two methods")
    pe.add_argument("--json", action="store_true")

    tr = sub.add_parser("trajectory", help="the motion of a small-swing spherical pendulum x(t), y(t)")
    tr.add_argument("--model", required=True, metavar="MODEL")
    tr.add_argument("--R0", required=True, metavar="X", help="initial distance from the vertical, m")
    tr.add_argument("--v0", required=True, metavar="V", help="initial speed perpendicular to R0, m/s")
    tr.add_argument("--omega2", metavar="G_OVER_L", help="Ω² = g/l, 1/s²")
    tr.add_argument("--l", metavar="L")
    tr.add_argument("--g", metavar="G")
    drag = tr.add_mutually_exclusive_group()
    drag.add_argument("--kappa", metavar="K", help="linear drag, 1/s (R = 2κmv)")
    drag.add_argument("--beta", metavar="B", help="quadratic drag, 1/m (R = mβv²)")
    tr.add_argument("--t", metavar="T1,T2,...")
    tr.add_argument("--t0", metavar="A")
    tr.add_argument("--t1", metavar="B")
    tr.add_argument("--n", type=_positive_int("--n", 10**7), metavar="N")
    tr.add_argument("--dps", type=_positive_int("--dps", MAX_DPS), default=None)
    fmt = tr.add_mutually_exclusive_group()
    fmt.add_argument("--json", action="store_true")
    fmt.add_argument("--csv", action="store_true")

    fg = sub.add_parser("figures", help="reproduce the texts' missing figures (CSV data and PNG plots)")
    fg.add_argument("--out", default="figures", metavar="DIR")

    ch = sub.add_parser("charts", help="work–precision charts, stability maps, validity of the approximations")
    ch.add_argument("--out", default="charts", metavar="DIR", help="output directory (default charts)")
    ch.add_argument("--quick", action="store_true", help="a fast, coarse run (CI, tests)")
    ch.add_argument("--only", action="append", metavar="NAME", help="only this chart (repeatable)")
    ch.add_argument("--render-only", action="store_true", help="redraw the PNGs from the CSVs in DIR, measure nothing")

    rp = sub.add_parser("report", help="LaTeX reports (or handouts) regenerated from the verified derivations")
    rp.add_argument("--out", default="reports", metavar="DIR", help="output directory (default reports)")
    rp.add_argument("--pdf", action="store_true", help="also compile each document with latexmk")
    rp.add_argument("--lang", choices=("en", "cs"), default="en", help="language (default en)")
    rp.add_argument("--handout", action="store_true", help="a teaching handout instead of the report")
    rp.add_argument("--all", action="store_true",
                    help="every golden document: reports and handouts, English and Czech")

    sc = sub.add_parser("scene", help="a situation and the accuracy it needs: the cheapest model that meets it")
    sc.add_argument("file", metavar="FILE", help="a scene (TOML; examples in scenes/)")
    sc.add_argument("--json", action="store_true")
    sc.add_argument("--plot", metavar="OUT.png", help="also plot the answer and the evidence")

    c = sub.add_parser("catalog", help="list the catalog: ids, dimensions, LaTeX-parser coverage")
    c.add_argument("--source", choices=sorted(SOURCES))
    c.add_argument("--json", action="store_true")
    return p


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
        if args.command is None:
            raise UsageError(f"a command is required: {', '.join(sorted(_COMMANDS))} (see --help)")
        return _COMMANDS[args.command](args)
    except UsageError as exc:
        print(f"quasicentral: error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except KeyboardInterrupt:
        print("quasicentral: interrupted", file=sys.stderr)
        return 130
    except Exception as exc:  # noqa: BLE001 - the CLI never shows a traceback
        from quasicentral.engine.catalog import CatalogError

        if isinstance(exc, CatalogError):
            print(f"quasicentral: error: malformed data: {exc}", file=sys.stderr)
            return EXIT_USAGE
        print(f"quasicentral: internal error: {type(exc).__name__}: {exc}", file=sys.stderr)
        return EXIT_UNEXPECTED


def _selected(args):
    from quasicentral.engine import catalog

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
    from quasicentral.engine import formats as output
    from quasicentral.engine import run as verify
    from quasicentral.engine.checker import Options

    try:
        opts = Options(dps=args.dps)  # the ladder's floor is the checker's (Options.MIN_DPS)
    except ValueError as exc:
        raise UsageError(f"--dps: {exc}") from None
    entries = _selected(args)
    t0 = time.perf_counter()
    outcomes = verify.run(entries, opts, use_cache=not args.no_cache, jobs=args.jobs, on_warning=_warn_line)
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


def _warn_line(text: str) -> None:
    print(f"quasicentral: warning: {text}", file=sys.stderr)


def _errata(args) -> int:
    from quasicentral.engine import formats as output
    from quasicentral.engine import run as verify
    from quasicentral.engine.checker import Options

    entries = _selected(args)
    outcomes = verify.run(entries, Options(), use_cache=not args.no_cache, on_warning=_warn_line)
    doc = output.errata_document(entries, outcomes)
    if args.json:
        print(json.dumps(doc, indent=2, ensure_ascii=False))
    else:
        print(output.errata_table(doc))
    return EXIT_OK if all(o.ok for o in outcomes if o.erratum or o.status == "cleared") else EXIT_UNEXPECTED


def _mutate(args) -> int:
    from quasicentral.engine import mutate

    res = mutate.run(source=args.source, per_entry=args.per_entry)
    if args.json:
        print(json.dumps(res, indent=2, ensure_ascii=False))
    else:
        print(mutate.table(res))
    return EXIT_OK if res["recall"] == 1.0 and res["false_alarms"] == 0 else EXIT_UNEXPECTED


def _catalog(args) -> int:
    from quasicentral.engine import latexparse
    from quasicentral.engine import formats as output

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
    from quasicentral.files import write_text

    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        write_text(path, text)
    except OSError as exc:
        raise UsageError(f"cannot write {path}: {exc.strerror}") from None


def _period(args) -> int:
    from quasicentral.models import period as P

    if args.table:
        rows = P.table()
        if args.json:
            print(json.dumps({"table": rows}, indent=2))
        else:
            print("amplitude   T/T0 (AGM, correctly rounded)   quadrature agrees")
            for r in rows:
                print(f"{r['amplitude_deg']:>9}°  {r['T_over_T0']:<30}  {'yes' if r['agree'] else 'NO'}")
        return EXIT_OK if all(r["agree"] for r in rows) else EXIT_UNEXPECTED
    given = {"phi0": args.amplitude_rad, "amplitude_deg": args.amplitude_deg, "delta": args.complement_rad}
    if all(v is None for v in given.values()):
        raise UsageError("give --amplitude-deg, --amplitude-rad or --complement-rad")
    length, grav = finite_float(args.l, "--l"), finite_float(args.g, "--g")
    if length <= 0:
        raise UsageError(f"--l must be a positive length, not {args.l}")
    if grav <= 0:
        raise UsageError(f"--g must be positive, not {args.g}")
    try:
        out = {"method": args.method}
        if args.dps:
            import mpmath

            kw = {k: v for k, v in given.items() if v is not None}
            if args.method in ("agm", "ellipk"):
                ratio_text = P.period_ratio_rounded(digits=args.dps, method=args.method, **kw)
            else:
                ratio_text = mpmath.nstr(P.period_ratio_mp(dps=args.dps, method=args.method, terms=args.terms, **kw),
                                         args.dps, strip_zeros=False)
            with mpmath.workdps(args.dps + 10):
                t0 = 2 * mpmath.pi * mpmath.sqrt(mpmath.mpf(args.l) / mpmath.mpf(args.g))
                out["T"] = mpmath.nstr(t0 * mpmath.mpf(ratio_text), args.dps, strip_zeros=False)
            out["T_over_T0"] = ratio_text
            out["T0"] = mpmath.nstr(t0, args.dps, strip_zeros=False)
            out["digits"] = args.dps
        else:
            val = {k: finite_float(v, "--" + k.replace("phi0", "amplitude-rad").replace("_", "-")) for k, v in given.items() if v is not None}
            if "amplitude_deg" in val:
                val = {"phi0": math.radians(val.pop("amplitude_deg"))}
            ratio = float(P.period_ratio(val.get("phi0"), delta=val.get("delta"), method=args.method, terms=args.terms))
            t0 = 2 * math.pi * math.sqrt(length / grav)
            out.update({"T": t0 * ratio, "T_over_T0": ratio, "T0": t0})
        if args.method == "series":
            import numpy as np

            c = P._complement_sine(phi0=math.radians(float(args.amplitude_deg)) if args.amplitude_deg else
                                   (float(args.amplitude_rad) if args.amplitude_rad else None),
                                   delta=float(args.complement_rad) if args.complement_rad else None)
            _, tail = P.series_ratio(np.array([1 - float(c) ** 2]), args.terms)
            out["terms"] = args.terms
            out["error_estimate"] = float(tail[0])
    except P.DomainError as exc:
        raise UsageError(str(exc)) from None
    if not all(math.isfinite(float(v)) for k, v in out.items() if k in ("T", "T_over_T0", "error_estimate")):
        raise UsageError("the result is not finite for these inputs (e.g. a series truncation at an amplitude "
                         "where its error bound diverges)")
    if args.json:
        print(json.dumps(out, indent=2, allow_nan=False))
    else:
        for k, v in out.items():
            print(f"{k:15s} {v}")
    return EXIT_OK


def _trajectory(args) -> int:
    import mpmath

    from quasicentral.models import motion

    if args.model not in motion.MODELS:
        raise UsageError(f"unknown model {args.model!r}; choose from {', '.join(motion.MODELS)}")
    if args.dps:
        # numbers are read, and the times spaced, at the asked precision plus guard digits
        with mpmath.workdps(args.dps + 20):
            return _trajectory_run(args, motion, mpmath)
    return _trajectory_run(args, motion, mpmath)


def _trajectory_run(args, motion, mpmath) -> int:
    num = (lambda text, name: _exact_number(text, name)) if args.dps else (lambda text, name: finite_float(text, name))
    R0, v0 = num(args.R0, "--R0"), num(args.v0, "--v0")
    if args.omega2 is not None:
        if args.l is not None or args.g is not None:
            raise UsageError("give --omega2 or --l and --g, not both")
        omega2 = num(args.omega2, "--omega2")
    elif args.l is not None and args.g is not None:
        length, grav = num(args.l, "--l"), num(args.g, "--g")
        if length <= 0:
            raise UsageError(f"--l must be a positive length, not {args.l}")
        if grav <= 0:
            raise UsageError(f"--g must be positive, not {args.g}")
        omega2 = grav / length
    else:
        raise UsageError("give --omega2, or --l and --g")
    quadratic = args.model.startswith("quadratic")
    if args.beta is not None and not quadratic:
        raise UsageError(f"model {args.model} takes --kappa, not --beta")
    if args.kappa is not None and quadratic:
        raise UsageError(f"model {args.model} takes --beta, not --kappa")
    if quadratic and args.beta is None:
        raise UsageError(f"model {args.model} needs --beta (quadratic drag, 1/m)")
    kappa = num(args.kappa, "--kappa") if args.kappa is not None else 0
    beta = num(args.beta, "--beta") if args.beta is not None else 0
    if args.model == "ellipse" and args.kappa is not None and kappa != 0:
        raise UsageError("model ellipse has no drag: leave out --kappa")
    times = _times(args, num)
    try:
        x, y = motion.trajectory(args.model, times, R0, v0, omega2, kappa, beta, dps=args.dps)
    except (motion.ParameterError, ValueError) as exc:
        raise UsageError(str(exc)) from None
    if not all(mpmath.isfinite(v) for v in list(times) + list(x) + list(y)):
        raise UsageError("the result is not finite for these inputs (a time or a value overflows)")
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
    import mpmath

    try:
        val = mpmath.mpf(text.strip())
    except (ValueError, TypeError, AttributeError):
        raise UsageError(f"{name} must be a number, not {text!r}") from None
    if not mpmath.isfinite(val):
        raise UsageError(f"{name} must be finite, not {text!r}")
    return val


def _times(args, num):
    if args.t is not None:
        if any(v is not None for v in (args.t0, args.t1, args.n)):
            raise UsageError("give --t, or --t0 --t1 --n, not both")
        parts = [p for p in args.t.split(",") if p.strip()]
        if not parts:
            raise UsageError("--t is an empty list of times")
        times = [num(p, "--t") for p in parts]
    elif None not in (args.t0, args.t1, args.n):
        a, b = num(args.t0, "--t0"), num(args.t1, "--t1")
        if b < a:
            raise UsageError("--t1 must not be before --t0")
        n = args.n
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
        try:
            scenes.plot(decision, Path(args.plot))
        except OSError as exc:
            raise UsageError(f"cannot write {args.plot}: {exc.strerror or exc}") from None
    if args.json:
        print(json.dumps(scenes.document(decision), ensure_ascii=False))
    else:
        print(scenes.report(decision))
    return EXIT_OK if decision.meets else EXIT_UNEXPECTED


def _figures(args) -> int:
    from quasicentral.studies import figures

    try:
        paths = figures.write_all(Path(args.out))
    except OSError as exc:
        raise UsageError(f"cannot write figures to {args.out}: {exc.strerror}") from None
    for p in paths:
        print(p)
    return EXIT_OK


def _report(args) -> int:
    from quasicentral.documents import report

    if args.all and (args.handout or args.lang != "en"):
        raise UsageError("--all writes every document: leave out --handout and --lang")
    out = Path(args.out)
    try:
        report.check_writable(out)
    except OSError as exc:
        raise UsageError(f"cannot write to {args.out}: {exc.strerror or exc}") from None
    if args.all:
        jobs = list(report.GOLDEN)
    else:
        jobs = [(("handout",) if args.handout else ("report",), (args.lang,))]
    outcomes = report.outcomes_for_all()
    docs: dict[str, str] = {}
    for kinds, langs in jobs:
        docs.update(report.generate(kinds, langs, outcomes))
    try:
        paths = report.write(out, dict(sorted(docs.items())))
    except OSError as exc:
        raise UsageError(f"cannot write to {args.out}: {exc.strerror or exc}") from None
    for p in paths:
        print(p)
    if args.pdf:
        try:
            pdfs = report.compile_all(out, [n for n in sorted(docs) if n != report.VERSIONS_FILE])
        except report.LatexError as exc:
            print(f"quasicentral: error: {exc}", file=sys.stderr)
            return EXIT_UNEXPECTED
        for p in pdfs:
            print(p)
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
            paths = charts.build(out, quick=args.quick, only=args.only)
    except OSError as exc:
        raise UsageError(f"cannot write charts to {args.out}: {exc.strerror or exc}") from None
    except charts.ChartError as exc:
        raise UsageError(str(exc)) from None
    for p in paths:
        print(p)
    return EXIT_OK


_COMMANDS = {"charts": _charts, "scene": _scene, "report": _report, "figures": _figures, "trajectory": _trajectory, "verify": _verify, "errata": _errata, "mutate": _mutate, "catalog": _catalog, "period": _period}


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
