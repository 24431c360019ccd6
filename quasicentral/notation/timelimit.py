"""Bounds on CPU time: the one time-limit mechanism of the package.

CPU time, not wall time: the same check reaches the same verdict on a busy machine as on an
idle one, so verdicts and the reports built from them do not depend on the load.

* :func:`time_limit` interrupts a block (SIGVTALRM; main thread only, elsewhere unbounded) by
  raising :class:`TimeLimitExceeded`, a ``BaseException`` so that sympy's ``except Exception``
  cannot swallow it;
* :class:`Deadline` is the cooperative form, for code that cannot be interrupted by a signal
  (python-flint's integrator calls back into Python: the callback asks ``expired()``).
"""

from __future__ import annotations

import signal
import threading
import time
from contextlib import contextmanager
from dataclasses import dataclass


class TimeLimitExceeded(BaseException):
    """A block ran past its CPU-time bound."""


@contextmanager
def time_limit(seconds: float):
    """Bound the block's CPU time to ``seconds`` (≤ 0: unbounded)."""
    if seconds <= 0 or threading.current_thread() is not threading.main_thread():
        yield
        return

    def handler(signum, frame):
        raise TimeLimitExceeded()

    old = signal.signal(signal.SIGVTALRM, handler)
    signal.setitimer(signal.ITIMER_VIRTUAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_VIRTUAL, 0)
        signal.signal(signal.SIGVTALRM, old)


@dataclass(frozen=True)
class Deadline:
    """A point in CPU time (``None``: never)."""

    at: float | None

    @staticmethod
    def after(seconds: float | None) -> "Deadline":
        return Deadline(time.process_time() + seconds if seconds else None)

    def expired(self) -> bool:
        return self.at is not None and time.process_time() > self.at
