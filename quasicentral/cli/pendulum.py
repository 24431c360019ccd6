"""The pendulum commands: the exact period and the small-swing trajectory."""

from __future__ import annotations

import json
import math
import warnings

from quasicentral.cli.parser import EXIT_OK, EXIT_UNEXPECTED, MAX_DPS, MAX_POINTS, MAX_POINTS_DPS, UsageError
from quasicentral.models.parameters import G_STANDARD
from quasicentral.cli.terminal import warn


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


def period(args) -> int:
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
        warn(out["warning"])
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




def trajectory(args) -> int:
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
        warn(warning)
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




def finite_float(text: str, name: str) -> float:
    """A finite double from a decimal string (:mod:`quasicentral.notation.numbers`); bad input
    is a UsageError naming the option."""
    from quasicentral.notation import numbers

    try:
        return numbers.to_float(text, name)
    except numbers.NumberError as exc:
        raise UsageError(str(exc)) from None



