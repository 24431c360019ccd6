"""Forked worker processes: ending with their parent, and keeping each family of work together.

:func:`map_grouped` runs a function over items that come in groups (the entries of one
derivation module): each worker works through its own groups first, in order, and only then
takes what is left of the others' from their far ends.  Entries of one family build on the
same derivations; a worker that keeps to its family derives them once (and keeps them,
:mod:`quasicentral.engine.store`), where workers taking entries in turn would each derive the
whole chain at the same time.
"""

from __future__ import annotations

import os
import pickle
import queue as queue_mod
import signal
import sys
import threading
from concurrent.futures import ProcessPoolExecutor
from multiprocessing import get_context
from typing import Callable, Sequence, TypeVar

T = TypeVar("T")
R = TypeVar("R")

PR_SET_PDEATHSIG = 1  # <linux/prctl.h>
POLL_SECONDS = 0.5  # how often the parent looks at its workers while it waits for a result
IDLE_SECONDS = 30.0  # how long results of workers that have all returned may take to arrive


def die_with_parent(parent: int) -> None:
    """Worker initializer: end this process when ``parent`` ends, even by ``kill -9``.

    On Linux the kernel sends SIGKILL when the parent dies (``prctl(PR_SET_PDEATHSIG)``); as a
    fallback (other systems, or no libc) a daemon thread checks every second whether the process
    has been re-parented."""
    if sys.platform.startswith("linux"):
        try:
            import ctypes

            libc = ctypes.CDLL(None, use_errno=True)
            libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
        except (OSError, AttributeError):
            pass
    if os.getppid() != parent:  # the parent died before the signal was armed
        os._exit(1)

    def watch() -> None:
        import time

        while True:
            time.sleep(1.0)
            if os.getppid() != parent:
                os._exit(1)

    threading.Thread(target=watch, name="quasicentral-parent-watch", daemon=True).start()


def worker_pool(jobs: int) -> ProcessPoolExecutor:
    """A pool of ``jobs`` forked workers that end with this process (see :func:`die_with_parent`)."""
    return ProcessPoolExecutor(max_workers=jobs, mp_context=get_context("fork"),
                               initializer=die_with_parent, initargs=(os.getpid(),))


def preference_orders(groups: Sequence[Sequence[int]], jobs: int) -> list[list[int]]:
    """For each of ``jobs`` workers, the order in which it takes the items (indices): its own
    groups first (the largest groups dealt out first, each to the worker with the fewest items
    so far), then every other worker's items from the end backwards, so that the one who
    steals and the owner meet in the middle."""
    own: list[list[int]] = [[] for _ in range(jobs)]
    for group in sorted(groups, key=len, reverse=True):
        min(own, key=len).extend(group)
    orders = []
    for w in range(jobs):
        order = list(own[w])
        for k in range(1, jobs):
            order.extend(reversed(own[(w + k) % jobs]))
        orders.append(order)
    return orders


_SHARED: dict = {}  # what the forked workers of map_grouped read (set before the fork)


def _take_and_run(w: int) -> int:
    func, items, orders, claimed, lock, results = (
        _SHARED[k] for k in ("func", "items", "orders", "claimed", "lock", "results"))
    # this process may end with results nobody reads (the parent gave up): never block on them
    results.cancel_join_thread()
    done = 0
    for i in orders[w]:
        with lock:
            if claimed[i]:
                continue
            claimed[i] = 1
        # pickled here, so that a result that cannot be sent fails in this call, not silently
        # in the queue's thread
        results.put((i, pickle.dumps(func(items[i]), protocol=pickle.HIGHEST_PROTOCOL)))
        done += 1
    return done


def map_grouped(func: Callable[[T], R], groups: Sequence[Sequence[T]], jobs: int,
                on_result: Callable[[T, R], None]) -> None:
    """``on_result(item, func(item))`` for every item of ``groups``, in this process as each
    result arrives, computed on ``jobs`` forked workers (see the module's docstring).  An
    exception in ``func`` or ``on_result`` (or an interrupt) is raised here once every worker
    has finished the item it was on; none starts another."""
    items = [x for g in groups for x in g]
    if not items:
        return
    index_groups, start = [], 0
    for g in groups:
        index_groups.append(list(range(start, start + len(g))))
        start += len(g)
    ctx = get_context("fork")
    results = ctx.Queue()
    claimed = ctx.RawArray("b", len(items))
    _SHARED.update(func=func, items=items, orders=preference_orders(index_groups, jobs),
                   claimed=claimed, lock=ctx.Lock(), results=results)
    try:
        with worker_pool(jobs) as pool:
            futures = [pool.submit(_take_and_run, w) for w in range(jobs)]
            try:
                _collect(futures, results, items, on_result)
            except BaseException:
                with _SHARED["lock"]:  # no worker starts another item
                    claimed[:] = b"\1" * len(items)
                raise
    finally:
        _SHARED.clear()
        results.close()


def _collect(futures, results, items, on_result) -> None:
    received, idle = 0, 0
    while received < len(items):
        try:
            i, payload = results.get(timeout=POLL_SECONDS)
        except queue_mod.Empty:
            failed = next((f.exception() for f in futures if f.done() and f.exception()), None)
            if failed is not None:
                raise failed
            if all(f.done() for f in futures):
                # every worker has returned: what they sent is still on its way, for a moment
                idle += 1
                if idle * POLL_SECONDS > IDLE_SECONDS or sum(f.result() for f in futures) < len(items):
                    raise RuntimeError(f"the workers ended with {len(items) - received} results not received")
            continue
        received += 1
        on_result(items[i], pickle.loads(payload))
