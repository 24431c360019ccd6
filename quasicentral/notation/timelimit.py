"""Bounds on CPU time: the one time-limit mechanism of the package.

CPU time, not wall time: the same check reaches the same verdict on a busy machine as on an
idle one, so verdicts and the reports built from them do not depend on the load.

* :func:`time_limit` interrupts a block (SIGVTALRM; main thread only, elsewhere unbounded) by
  raising :class:`TimeLimitExceeded`, a ``BaseException`` so that sympy's ``except Exception``
  cannot swallow it — and again until the block has ended, where Python itself swallowed it;

Where a bound decides what a user keeps (a witness's certified digits in a report), a CPU-time
bound would make the document depend on the machine: that work is bounded by counting it
instead (:class:`quasicentral.notation.bridge.Work`).
"""

from __future__ import annotations

import signal
import threading
from contextlib import contextmanager


class TimeLimitExceeded(BaseException):
    """A block ran past its CPU-time bound."""


#: once the bound is past, the interruption is raised again every this many seconds of CPU time
#: until the block has ended: an exception raised where Python ignores exceptions (a garbage
#: collector's callback, a finalizer such as the one lambdify registers) would lose the bound
RETRY_SECONDS = 0.05


@contextmanager
def time_limit(seconds: float):
    """Bound the block's CPU time to ``seconds`` (≤ 0: unbounded)."""
    if seconds <= 0 or threading.current_thread() is not threading.main_thread():
        yield
        return
    active = [True]

    def handler(signum, frame):
        if active[0]:
            raise TimeLimitExceeded()

    old = signal.signal(signal.SIGVTALRM, handler)
    try:
        # armed inside the try: an interruption before the block starts still disarms the timer
        signal.setitimer(signal.ITIMER_VIRTUAL, seconds, RETRY_SECONDS)
        yield
    finally:
        signal.setitimer(signal.ITIMER_VIRTUAL, 0)
        active[0] = False
        signal.signal(signal.SIGVTALRM, old)
