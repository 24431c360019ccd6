"""Progress of long work, as data: library code reports, the command line draws.

A long-running library function takes an optional ``progress`` callback and calls it with a
:class:`Progress` record each time one item of its work is done (and once at the start, with
``done`` = the items that needed no work, e.g. read from the cache).  It never prints: the
command line turns the records into a bar on a terminal (tqdm), or ignores them in CI.

>>> seen = []
>>> notify(seen.append, done=1, total=3, current="brepta1953:4")
>>> seen[0].done, seen[0].total, seen[0].current
(1, 3, 'brepta1953:4')
>>> notify(None, done=2, total=3)  # no callback: nothing happens
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Optional


@dataclass(frozen=True)
class Progress:
    """``done`` of ``total`` items finished; ``current`` names the item just finished (or the
    phase, e.g. ``"cache"``); ``cached`` counts the items that were read back, not computed;
    ``phase`` says what is counted (``"entries"``, ``"mutated entries"``, ``"charts"``, …)."""

    done: int
    total: int
    current: str = ""
    cached: int = 0
    phase: str = ""


Callback = Callable[[Progress], None]
OptionalCallback = Optional[Callback]


def notify(progress: OptionalCallback, done: int, total: int, current: str = "", cached: int = 0,
           phase: str = "") -> None:
    """Call ``progress`` with a :class:`Progress` record, if there is a callback."""
    if progress is not None:
        progress(Progress(done, total, current, cached, phase))
