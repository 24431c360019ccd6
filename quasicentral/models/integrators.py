"""The back ends of :func:`quasicentral.models.reference.solve`, one algorithm each over the
systems of :mod:`quasicentral.models.equations`: scipy's Fortran DOP853 (double precision),
heyoka.py's Taylor integrator (double, quadruple, MPFR; optional) and mpmath's ``odefun`` (any
precision).  A planar swing under quadratic drag has a kink where the speed vanishes: each back
end restarts at the turning points (an event on the velocity), so no step straddles it.

Each takes a :class:`reference.Problem` ``p`` and returns (rows of the state at the times, info).
"""

from __future__ import annotations

import functools
import math
import warnings

import mpmath
import numpy as np

from quasicentral.models.equations import System, rhs


def initial(p, extras: bool) -> list:
    """The paper's initial state x = R0, y = 0, ẋ = 0, ẏ = v0 (planar: x, ẋ), plus s = D = 0."""
    z = mpmath.mpf(0)
    st = [p.R0, z] if p.planar else [p.R0, z, z, p.v0]
    return st + ([z, z] if extras else [])


def by_stretches(times, reach, turn):
    """The restart at turning points, written once for every back end.  The requested times are
    visited in increasing order; ``reach(target)`` returns the state at ``target``, or None when
    a turning point (ẋ = 0 of a planar swing under quadratic drag) comes first — the back end
    has then stopped there, at rest; ``turn()`` restarts from that point with σ = sign ẋ
    flipped, so that every stretch is analytic and no step straddles the kink.  Returns (the
    states in the order of ``times``, the number of turning points)."""
    order = sorted(range(len(times)), key=lambda i: times[i])
    out = [None] * len(times)
    turns = 0
    for i in order:
        while (state := reach(times[i])) is None:
            turn()
            turns += 1
        out[i] = state
    return out, turns


class _BranchFailed(ArithmeticError):
    """A stretch's own analytic branch, continued past its turning point, blew up."""


# --- back end: scipy DOP853 (Fortran) -----------------------------------------------------------
def scale(p) -> float:
    """max(R0, v0/Ω) as a float: the size of the motion errors are measured against."""
    om = math.sqrt(float(p.omega2))
    return max(float(p.R0), float(p.v0) / om)


def solve_dop853(p, times: list[float], tol: float, extras: bool, branchwise: bool | None = None):
    from scipy.integrate import ode

    pars = tuple(float(a) for a in p.pars())
    planar, kind = p.planar, p.kind
    om = math.sqrt(float(p.omega2))
    # planar: the main integration runs on the physical law σ = sign ẋ (never the analytic
    # continuation of a stretch beyond its turning point, which can blow up within a long step);
    # the step that crosses a turning point is discarded and redone up to the zero of ẋ on the
    # stretch's own analytic branch (σ fixed), so no accepted step straddles the kink.
    # (at tight tolerances the steps are short and the stretch's own branch is used throughout:
    # the step across a turning point is then smooth and accepted at once, fewer evaluations)
    if branchwise is None:
        branchwise = planar and tol <= 1e-6
    cur = {"sig": -1.0, "f": rhs(kind, pars + ((-1.0 if branchwise else None,) if planar else ()), math, extras)}
    rtol = 0.1 * tol  # the global error of DOP853 grows to ~3–10× its local tolerance over 10 periods
    atol = rtol * scale(p) * 1e-2

    def fun(tt, y):
        return cur["f"](tt, y.tolist())

    r = ode(fun).set_integrator("dop853", rtol=rtol, atol=atol, nsteps=10**7)
    prev = {}

    def solout(tt, y):  # stop where σẋ turns negative (a turning point passed inside the step)
        if cur["sig"] * y[1] < 0:
            return -1
        prev["t"], prev["y"] = tt, y.copy()
        return 0

    if planar:
        r.set_solout(solout)
        finder = ode(lambda tt, y: cur["branch"](tt, y.tolist())).set_integrator("dop853", rtol=rtol, atol=atol,
                                                                                  nsteps=10**6)
    r.set_initial_value([float(a) for a in initial(p, extras)], 0.0)

    def reach(target):
        if target - r.t <= 1e-10 / om:  # too short for DOP853: one Euler step, error ≤ 1e-20
            return list(np.asarray(r.y) + (target - r.t) * np.asarray(cur["f"](r.t, list(r.y))))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # failures are checked below (successful())
            y = r.integrate(target)
        if not (planar and cur["sig"] * y[1] < 0):  # no turning point passed in the last step
            if not r.successful():
                if branchwise:  # a branch continued too far past a turning point: the safe law
                    raise _BranchFailed
                raise ArithmeticError(f"dop853 failed (code {r.get_return_code()})")
            return list(y)
        # a turning point in (last accepted step, r.t): Newton on ẋ(t) with the same stretch
        cur["branch"] = branch = rhs(kind, pars + (cur["sig"],), math, extras)
        tz, yz = _turning_point(finder, branch, prev["t"], prev["y"], r.t, y, 0.01 * tol / om)
        yz[1] = 0.0  # exactly at rest
        cur["at"] = (tz, yz)
        return None

    def turn():
        cur["sig"] = -cur["sig"]
        if branchwise:
            cur["f"] = rhs(kind, pars + (cur["sig"],), math, extras)
        prev.clear()
        tz, yz = cur.pop("at")
        r.set_initial_value(yz, tz)

    try:
        out, turns = by_stretches(times, reach, turn)
    except _BranchFailed:
        return solve_dop853(p, times, tol, extras, branchwise=False)
    return out, {"turning_points": turns}


def _turning_point(finder, f, t_a, y_a, t_b, y_b, dt_tol):
    """The zero of ẋ between two step points: a secant start, then Newton steps (ẍ from the
    right-hand side), each integrated afresh from the last accepted point.  A time error δ
    costs ~|ẍ|δ in the restart velocity, so δ ≤ ``dt_tol`` is enough."""
    u_a, u_b = y_a[1], y_b[1]
    span = t_b - t_a
    h = span * u_a / (u_a - u_b)

    def state_at(h):
        """The branch's state at t_a + h, or None where its continuation has blown up."""
        if h <= 1e-9 * span:  # too short for a step of its own: one Taylor term is exact enough
            return np.array(y_a) + h * np.array(f(t_a, list(y_a)))
        finder.set_initial_value(y_a, t_a)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # "step size becomes too small": handled below
            y = finder.integrate(t_a + h)
        return y if finder.successful() and np.all(np.isfinite(y)) else None

    yz = None
    for _ in range(60):
        yz = state_at(h)
        if yz is None:  # overshot into the branch's blow-up beyond the turning point
            h *= 0.5
            continue
        dh = -yz[1] / f(t_a + h, yz.tolist())[1]
        if abs(dh) <= dt_tol:
            break
        h = min(max(h + dh, 0.0), span)
    if yz is None:
        raise ArithmeticError("no turning point found")
    return t_a + h, np.array(yz)


# --- back end: heyoka ---------------------------------------------------------------------------
@functools.lru_cache(maxsize=1)
def heyoka_available() -> bool:
    """True when heyoka.py imports (the optional extra ``quasicentral[fast]``)."""
    try:
        import heyoka  # noqa: F401
    except Exception:  # noqa: BLE001 - any import failure means: use the fallback
        return False
    return True


def _heyoka_fp(tol: float):
    """(fp_type, precision in bits, converter from mpmath) for a tolerance."""
    import heyoka as hy

    if tol >= 1e-15:
        return float, 0, lambda a: float(a)
    if tol >= 1e-32:
        return hy.real128, 0, lambda a: hy.real128(mpmath.nstr(a, 40, min_fixed=1, max_fixed=0))
    prec = int(-math.log2(tol)) + 24
    return hy.real, prec, lambda a: hy.real(mpmath.nstr(a, int(prec * 0.302) + 6, min_fixed=1, max_fixed=0), prec)


@functools.lru_cache(maxsize=64)
def _heyoka_integrator(kind: str, extras: bool, tol: float):
    """A compiled Taylor integrator for ``kind`` (parameters at run time), cached per process."""
    import heyoka as hy

    fp, prec, conv = _heyoka_fp(tol)
    n = System(kind).dimension(extras)
    names = ["x", "y", "u", "w"] if not System(kind).planar else ["x", "u"]
    names += ["s", "D"] if extras else []
    vs = hy.make_vars(*names)
    npar = System(kind).n_parameters
    pars = [hy.par[i] for i in range(npar)]
    exprs = rhs(kind, pars, hy, extras)(None, vs)
    sysl = list(zip(vs, exprs))
    kw = {"fp_type": fp, "tol": conv(mpmath.mpf(tol) / 10)}
    if prec:
        kw.update(prec=prec, compact_mode=True)
    events = []
    if System(kind).planar:  # σẋ falls through zero at a turning point
        events = [hy.t_event(pars[-1] * vs[1], direction=hy.event_direction.negative, fp_type=fp)]
    zero = conv(mpmath.mpf(0))
    ta = hy.taylor_adaptive(sysl, [zero] * n, pars=[zero] * npar, t_events=events, **kw)
    return ta, conv


def solve_heyoka(p, times, tol: float, extras: bool):
    import heyoka as hy

    ta, conv = _heyoka_integrator(p.kind, extras, float(tol))
    order = sorted(range(len(times)), key=lambda i: times[i])
    pars = list(p.pars()) + ([mpmath.mpf(-1)] if p.planar else [])
    ta.time = conv(mpmath.mpf(0))
    ta.state[:] = np.array([conv(a) for a in initial(p, extras)], dtype=ta.state.dtype)
    ta.pars[:] = np.array([conv(a) for a in pars], dtype=ta.pars.dtype)
    if p.planar:
        ta.reset_cooldowns()
    to_mp = (lambda a: mpmath.mpf(float(a))) if ta.state.dtype == float else (lambda a: mpmath.mpf(str(a)))  # noqa: E731
    if not p.planar:
        # the grid must start at the current time: prepend t = 0 and drop its row
        grid = np.array([conv(mpmath.mpf(0))] + [conv(times[i]) for i in order], dtype=ta.state.dtype)
        res = ta.propagate_grid(grid)
        if res[0] != hy.taylor_outcome.time_limit:
            raise ArithmeticError(f"heyoka stopped: {res[0]}")
        out = [None] * len(times)
        for j, i in enumerate(order):
            out[i] = [to_mp(a) for a in res[-1][j + 1]]
        return out, {"steps": None}

    def reach(target):
        res = ta.propagate_until(conv(target))
        if res[0] == hy.taylor_outcome.time_limit:
            return [to_mp(a) for a in ta.state]
        if res[0] != hy.taylor_outcome(-1):
            raise ArithmeticError(f"heyoka stopped: {res[0]}")
        return None  # stopped at the event: a turning point

    def turn():
        ta.state[1] = conv(mpmath.mpf(0))  # exactly at rest
        ta.pars[-1] = -ta.pars[-1]

    out, turns = by_stretches(times, reach, turn)
    return out, {"turning_points": turns}


# --- back end: mpmath odefun -------------------------------------------------------------------
def solve_mpmath(p, times, tol: float, extras: bool):
    dps = int(-math.log10(tol)) + 8
    with mpmath.workdps(dps):
        order = sorted(range(len(times)), key=lambda i: times[i])
        pars = tuple(mpmath.mpf(a) for a in p.pars())
        y0 = [mpmath.mpf(a) for a in initial(p, extras)]
        out = [None] * len(times)
        if not p.planar:
            sol = mpmath.odefun(rhs(p.kind, pars, mpmath, extras), 0, y0)
            for i in order:
                out[i] = list(sol(times[i]))
            return out, {}
        h = 2 * mpmath.pi / mpmath.sqrt(p.omega2) / 16
        st = {"sig": -1, "t0": mpmath.mpf(0), "y0": y0}

        def start():
            """The stretch from rest at t0 with σ fixed, and its turning point tz."""
            sol = mpmath.odefun(rhs(p.kind, pars + (mpmath.mpf(st["sig"]),), mpmath, extras), st["t0"], st["y0"])
            a = st["t0"]
            while True:  # bracket the next zero of σẋ, then a root
                b = a + h
                if st["sig"] * sol(b)[1] <= 0:
                    break
                a = b
            st["sol"], st["tz"] = sol, mpmath.findroot(lambda tt: sol(tt)[1], (a, b), solver="anderson")

        def reach(target):
            return list(st["sol"](target)) if target <= st["tz"] else None

        def turn():
            y = list(st["sol"](st["tz"]))
            y[1] = mpmath.mpf(0)
            st.update(t0=st["tz"], y0=y, sig=-st["sig"])
            start()

        start()
        out, turns = by_stretches(times, reach, turn)
        return out, {"turning_points": turns}
