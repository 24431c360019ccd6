"""Bounds on time: the one time-limit mechanism of the package, nested, on two clocks.

* ``time_limit(seconds)`` bounds a block's **CPU time** (``ITIMER_VIRTUAL``): the same check
  reaches the same verdict on a busy machine as on an idle one;
* ``time_limit(seconds, clock=WALL)`` bounds its **wall-clock time** (``ITIMER_REAL``): what
  uses no CPU (a sleep, a blocked read) ends too.

Limits nest (a symbolic proof's bound inside an entry's budget): each clock's timer is armed
for the nearest deadline of the limits active now, and expiry raises
:class:`TimeLimitExceeded` carrying the limit that ran out — the outermost one that has — a
``BaseException``, so that sympy's ``except Exception`` cannot swallow it; where something
swallows it anyway (a ``try``/``except BaseException``, a finalizer), it is raised again every
:data:`RETRY_SECONDS` until that limit's block has ended.  A block catching its own limit's
expiry tests :meth:`Limit.owns`, so an outer budget is never mistaken for an inner bound.
Signals reach the main thread only: elsewhere a block runs unbounded.

Where a bound decides what a user keeps (a witness's certified digits in a report), a
time bound would make the document depend on the machine: that work is bounded by counting it
instead (:class:`quasicentral.notation.bridge.Work`).
"""

from __future__ import annotations

from types import MappingProxyType
import contextvars
import signal
import threading
import time
from contextlib import contextmanager
from enum import Enum


class Clock(Enum):
    CPU = "cpu"
    WALL = "wall"


CPU, WALL = Clock.CPU, Clock.WALL
#: once a bound is past, the interruption is raised again every this many seconds until its
#: block has ended: an exception raised where Python ignores exceptions (a garbage collector's
#: callback, a finalizer such as the one lambdify registers) would lose the bound
RETRY_SECONDS = 0.05
_TIMER = MappingProxyType({CPU: (signal.ITIMER_VIRTUAL, signal.SIGVTALRM), WALL: (signal.ITIMER_REAL, signal.SIGALRM)})


def now(clock: Clock) -> float:
    """The clock's reading: the process's CPU time (at least the user time ``ITIMER_VIRTUAL``
    counts, so a limit has expired whenever its timer fires), or monotonic wall time."""
    return time.process_time() if clock is CPU else time.monotonic()


class Limit:
    """One active bound: its clock, its length and its deadline on that clock."""

    def __init__(self, seconds: float, clock: Clock):
        self.seconds, self.clock = seconds, clock
        self.deadline = now(clock) + seconds

    def owns(self, exc: BaseException) -> bool:
        """Whether ``exc`` is this limit running out (not an outer one)."""
        return isinstance(exc, TimeLimitExceeded) and exc.limit is self

    @property
    def expired(self) -> bool:
        return now(self.clock) >= self.deadline


class TimeLimitExceeded(BaseException):
    """A block ran past its bound (``limit``: which one)."""

    def __init__(self, limit: Limit | None = None):
        super().__init__(f"{limit.seconds:g} s of {limit.clock.value} time" if limit is not None else "time limit")
        self.limit = limit


#: the limits active in this context, outermost first (an immutable tuple, replaced on entry
#: and exit: the context's state, not the module's)
_ACTIVE: contextvars.ContextVar[tuple] = contextvars.ContextVar("quasicentral_time_limits", default=())


def _handler(signum, frame):
    for limit in _ACTIVE.get():  # the outermost expired limit wins: its whole block must stop
        if limit.expired:
            raise TimeLimitExceeded(limit)
    # woken before any deadline (another clock's timer): the repeating timers fire again


def _arm() -> None:
    active = _ACTIVE.get()
    for clock, (which, _) in _TIMER.items():
        deadlines = [lim.deadline for lim in active if lim.clock is clock]
        if not deadlines:
            signal.setitimer(which, 0)
            continue
        left = min(deadlines) - now(clock)
        signal.setitimer(which, max(left, 1e-4), RETRY_SECONDS)


@contextmanager
def time_limit(seconds: float, clock: Clock = CPU):
    """Bound the block's time on ``clock`` to ``seconds`` (≤ 0 or off the main thread:
    unbounded); yields the :class:`Limit`."""
    if seconds <= 0 or threading.current_thread() is not threading.main_thread():
        yield None
        return
    limit = Limit(seconds, clock)
    before = _ACTIVE.get()
    olds = {}
    if not before:  # the first limit installs the handlers; the last restores what was there
        olds = {sig: signal.signal(sig, _handler) for _, sig in _TIMER.values()}
    token = _ACTIVE.set(before + (limit,))
    try:
        _arm()  # armed inside the try: an interruption before the block starts still disarms
        yield limit
    finally:
        _ACTIVE.reset(token)
        _arm()
        for sig, old in olds.items():
            signal.signal(sig, old)
