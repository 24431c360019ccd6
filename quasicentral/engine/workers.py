"""Forked worker processes under supervision: keeping each family of work together, ending
with their parent, and never outliving an item's time.

:func:`map_grouped` runs a function over items that come in groups (the entries of one
derivation module): each worker works through its own groups first, in order, and only then
takes what is left of the others' from their far ends.  Entries of one family build on the
same derivations; a worker that keeps to its family derives them once (and keeps them,
:mod:`quasicentral.engine.store`), where workers taking entries in turn would each derive the
whole chain at the same time.

The parent watches every worker: an item that runs past ``timeout`` seconds of wall-clock time
(the worker's own budget failed: a C loop, a blocked call) gets its worker killed and is
answered by ``on_lost(item, why)``; so is the item of a worker that ends on its own (a
``sys.exit`` or ``os._exit`` in a text's code, a crash).  A new worker takes over the rest.
SIGINT and SIGTERM end the parent and every worker at once.  A worker's standard output goes
to standard error: what a text's code prints never mixes into a command's output.
"""

from __future__ import annotations

import os
import pickle
import signal
import sys
import threading
import time
from dataclasses import dataclass
from multiprocessing import get_context
from typing import Callable, Sequence, TypeVar

T = TypeVar("T")
R = TypeVar("R")

PR_SET_PDEATHSIG = 1  # <linux/prctl.h>
POLL_SECONDS = 0.2  # how often the parent looks at its workers while it waits for a result
#: the parent kills a worker whose item has run this much longer than its timeout (the
#: worker's own budget ends it sooner; this is for a worker stuck where signals do not reach)
GRACE_SECONDS = 5.0


class Lost(Exception):
    """An item whose worker was killed or ended without an answer (``why``)."""


def die_with_parent(parent: int) -> None:
    """In a worker: end this process when ``parent`` ends, even by ``kill -9``.

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
        while True:
            time.sleep(1.0)
            if os.getppid() != parent:
                os._exit(1)

    threading.Thread(target=watch, name="quasicentral-parent-watch", daemon=True).start()


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


@dataclass
class _Worker:
    process: object
    conn: object  # the parent's end of the worker's own pipe
    order: list[int]
    item: int | None = None  # the item it is on
    since: float = 0.0  # when it started it (monotonic)


class _Pool:
    """The shared state of one :func:`map_grouped` call (inherited by the forked workers).
    Each worker has a pipe of its own: a worker killed while it writes breaks only its pipe."""

    def __init__(self, func, items, orders, timeout):
        ctx = get_context("fork")
        self.ctx, self.func, self.items, self.timeout = ctx, func, items, timeout
        self.orders = orders
        self.claimed = ctx.RawArray("b", len(items))
        self.lock = ctx.Lock()
        self.parent = os.getpid()

    def start(self, order: list[int]) -> _Worker:
        mine, theirs = self.ctx.Pipe(duplex=False)
        p = self.ctx.Process(target=self._work, args=(order, theirs), daemon=True)
        p.start()
        theirs.close()
        return _Worker(p, mine, order)

    def _work(self, order: list[int], conn) -> None:
        die_with_parent(self.parent)
        signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent ends us; no traceback of our own
        signal.signal(signal.SIGTERM, signal.SIG_DFL)
        try:
            os.dup2(2, 1)  # a text's prints go to stderr, never into the command's output
            sys.stdout = sys.stderr
        except OSError:
            pass
        for i in order:
            with self.lock:
                if self.claimed[i]:
                    continue
                self.claimed[i] = 1
            conn.send(("start", i, None))
            try:
                payload = ("done", pickle.dumps(self.func(self.items[i]), protocol=pickle.HIGHEST_PROTOCOL))
            except BaseException as exc:  # noqa: BLE001 - reported to the parent, which raises it
                payload = ("error", _portable(exc))
            conn.send((payload[0], i, payload[1]))
        conn.send(("idle", None, None))
        conn.close()
        os._exit(0)


def _portable(exc: BaseException) -> bytes:
    """An exception as bytes the parent can raise again (its type kept where it pickles)."""
    try:
        return pickle.dumps(exc, protocol=pickle.HIGHEST_PROTOCOL)
    except Exception:  # noqa: BLE001 - an exception that does not pickle is sent as its words
        return pickle.dumps(RuntimeError(f"{type(exc).__name__}: {exc}"[:500]))


def map_grouped(func: Callable[[T], R], groups: Sequence[Sequence[T]], jobs: int,
                on_result: Callable[[T, R], None], timeout: float | None = None,
                on_lost: Callable[[T, str], R] | None = None) -> None:
    """``on_result(item, func(item))`` for every item of ``groups``, in this process as each
    result arrives, computed on ``jobs`` forked workers (see the module's docstring).  An item
    whose worker is lost (killed past ``timeout`` + :data:`GRACE_SECONDS`, or ended on its
    own) gets ``on_result(item, on_lost(item, why))`` (without ``on_lost``: :class:`Lost` is
    raised); an exception in ``func`` is raised here.  On any exception (an interrupt
    included) every worker is killed at once."""
    items = [x for g in groups for x in g]
    if not items:
        return
    index_groups, start = [], 0
    for g in groups:
        index_groups.append(list(range(start, start + len(g))))
        start += len(g)
    pool = _Pool(func, items, preference_orders(index_groups, min(jobs, len(items))), timeout)
    workers: list[_Worker] = []
    answered: set[int] = set()
    main = threading.current_thread() is threading.main_thread()
    previous = signal.signal(signal.SIGTERM, _terminate) if main else None
    try:
        workers += [pool.start(order) for order in pool.orders]
        while len(answered) < len(items):
            _receive(pool, workers, answered, on_result)
            _watch(pool, workers, answered, on_result, on_lost)
    finally:
        for w in workers:
            _kill(w.process)
            w.conn.close()
        if previous is not None:
            signal.signal(signal.SIGTERM, previous)


def _terminate(signum, frame):
    raise SystemExit(128 + signum)


def _kill(process) -> None:
    try:
        if process.is_alive():
            process.kill()
        process.join(timeout=1.0)
    except (OSError, ValueError, AssertionError):
        pass


def _receive(pool: _Pool, workers: list, answered: set, on_result) -> None:
    """What the workers have sent, waiting at most :data:`POLL_SECONDS`."""
    from multiprocessing.connection import wait

    ready = wait([w.conn for w in workers], timeout=POLL_SECONDS)
    for w in workers:
        if w.conn in ready:
            _drain(pool, w, answered, on_result)


def _drain(pool: _Pool, w: _Worker, answered: set, on_result) -> None:
    """Every message a worker has sent so far."""
    while True:
        try:
            if not w.conn.poll():
                return
            kind, i, payload = w.conn.recv()
        except (EOFError, OSError):
            return  # its pipe is closed: _watch answers for its item
        if kind == "start":
            w.item, w.since = i, time.monotonic()
        elif kind == "done":
            w.item = None
            if i not in answered:
                answered.add(i)
                on_result(pool.items[i], pickle.loads(payload))
        elif kind == "error":
            raise pickle.loads(payload)
        elif kind == "idle":
            w.item = None


def _watch(pool: _Pool, workers: list, answered: set, on_result, on_lost) -> None:
    """Kill a worker past its item's time; answer the item of a worker that is gone; start a
    worker in the place of each one lost while items are left."""
    now = time.monotonic()
    for w in list(workers):
        why = None
        if w.item is not None and pool.timeout is not None and now - w.since > pool.timeout + GRACE_SECONDS:
            why = f"killed after {now - w.since:.0f} s (its budget of {pool.timeout:g} s did not stop it)"
            _kill(w.process)
        elif w.process.is_alive():
            continue
        else:
            _drain(pool, w, answered, on_result)  # what it sent before it ended
            w.process.join(timeout=0)
            code = w.process.exitcode
            if w.item is not None:
                why = f"its worker process ended (exit code {code}) while it was on this entry"
        workers.remove(w)
        w.conn.close()
        if w.item is not None and w.item not in answered:
            answered.add(w.item)
            if on_lost is None:
                raise Lost(why)
            on_result(pool.items[w.item], on_lost(pool.items[w.item], why))
        if any(not pool.claimed[j] for j in range(len(pool.items))):
            workers.append(pool.start(w.order))
    if not workers and len(answered) < len(pool.items):
        # items claimed by workers that vanished before they said which: answered as lost
        for j in [j for j in range(len(pool.items)) if j not in answered]:
            if pool.claimed[j]:
                answered.add(j)
                if on_lost is None:
                    raise Lost("its worker vanished")
                on_result(pool.items[j], on_lost(pool.items[j], "its worker vanished"))
        if len(answered) < len(pool.items):
            workers.append(pool.start([j for j in range(len(pool.items)) if j not in answered]))


def in_child(func: Callable[[], R], timeout: float) -> R:
    """``func()`` computed in a forked child process (its standard output to standard error),
    its result sent back; an exception it raises is raised here.  A child that runs past
    ``timeout`` seconds is killed, and one that ends without an answer (``os._exit``, a crash)
    is reported: both as :class:`Lost`, with why."""
    ctx = get_context("fork")
    mine, theirs = ctx.Pipe(duplex=False)
    parent = os.getpid()

    def child() -> None:
        die_with_parent(parent)
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        try:
            os.dup2(2, 1)
            sys.stdout = sys.stderr
        except OSError:
            pass
        try:
            payload = ("done", pickle.dumps(func(), protocol=pickle.HIGHEST_PROTOCOL))
        except BaseException as exc:  # noqa: BLE001 - reported to the parent, which raises it
            payload = ("error", _portable(exc))
        theirs.send(payload)
        theirs.close()
        os._exit(0)

    p = ctx.Process(target=child, daemon=True)
    p.start()
    theirs.close()
    try:
        if not mine.poll(timeout):
            raise Lost(f"did not finish within {timeout:g} s")
        try:
            kind, payload = mine.recv()
        except (EOFError, OSError):
            p.join(timeout=1.0)
            raise Lost(f"the process ended without an answer (exit code {p.exitcode})") from None
        return pickle.loads(payload) if kind == "done" else _raise(pickle.loads(payload))
    finally:
        _kill(p)
        mine.close()


def _raise(exc: BaseException):
    raise exc
