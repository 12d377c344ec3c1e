"""Worker processes for the benchmarks' ``--jobs N``: work spread over processes that always ends.

``multiprocessing.Pool`` (which ``bench tasks``, ``bench maps``' suite and ``bench tasks --suite context`` used)
waits forever for the result of a worker that died: a worker killed by a signal (the kernel's out-of-memory
killer, a ``kill -9``) leaves its task unanswered, and ``imap_unordered`` blocks for good; its ``terminate``
can block too, on the queue lock a killed worker held; an initializer that raises makes it start workers for
ever. Here the work runs on ``concurrent.futures.ProcessPoolExecutor``, which notices a worker that has gone, and
every way out of a run ends it:

- a worker killed by a signal: :class:`~seal_cli.errors.SealError` ``a worker process ended abruptly (killed by
  a signal, or out of memory?)`` (exit code 1);
- a worker whose initializer or task raised: the same exception in the parent (a SealError is the user's
  message, as with ``--jobs 1``; the initializer's is raised by the first task, not logged by the worker as a
  traceback);
- a result that cannot be pickled: the pickling error in the parent (a bug of the caller, never a hang);
- the parent interrupted (SIGINT, SIGTERM as an exception) or the caller stopping early: every pending task is
  cancelled, every worker terminated (killed if it has not gone within :data:`GRACE` seconds) and reaped before
  the exception goes on.

Two things make that hold under load. The workers are started (forked, at the first task) while SIGINT, SIGTERM
and SIGHUP wait: an interrupt that landed between a fork and the pool's record of the process it made left a worker
no one knew of, waiting for a task for ever and holding the command's standard output and error open (a judge
reading them saw a command that outlived its SIGINT). A worker ignores SIGINT (the parent, which a terminal's Ctrl-C
reaches too, ends its workers) and dies of SIGTERM and SIGHUP at once, even inside a long call of C code, where a
Python handler inherited from the parent would wait for the call to return.
"""

from __future__ import annotations

import contextlib
import multiprocessing
import signal
import time
from collections.abc import Callable, Iterable, Iterator, Sequence
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from typing import Any, TypeVar

from seal_cli.errors import SealError
from seal_cli.fileio import signals_wait

__all__ = ["GRACE", "ordered", "unordered"]

T = TypeVar("T")
R = TypeVar("R")

GRACE = 2.0
"""Seconds a terminated worker has to end before it is killed."""

_STOPPING = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)
"""The signals that end a run: they wait while workers are started."""

_STARTED: dict[str, BaseException | None] = {"failed": None}
"""In a worker: what its initializer raised, if anything (raised again by each of its tasks)."""


def _start(initializer: Callable[..., object] | None, initargs: Sequence[Any]) -> None:
    """A worker's start: its own signal handling, then ``initializer``, keeping what it raised for the first task."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent's to act on: it ends its workers
    for number in _STOPPING[1:]:
        signal.signal(number, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, _STOPPING)  # blocked by the parent while it forked: now acted on
    _STARTED["failed"] = None
    if initializer is None:
        return
    try:
        initializer(*initargs)
    except BaseException as error:  # noqa: BLE001 - sent to the parent by the task, not printed here
        _STARTED["failed"] = error


def _call(function: Callable[[T], R], item: T) -> R:
    failed = _STARTED["failed"]
    if failed is not None:
        raise failed
    return function(item)


def _context(method: str | None) -> multiprocessing.context.BaseContext:
    if method is None:
        method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
    return multiprocessing.get_context(method)


@contextlib.contextmanager
def _starting() -> Iterator[None]:
    """While the pool starts its workers (within the first ``submit``, or each for ``spawn``): SIGINT, SIGTERM and
    SIGHUP wait, both as Python sees them (noted by :func:`~seal_cli.fileio.signals_wait`, acted on at the end, so
    every process forked is recorded by then) and as the system does (blocked in this thread, so each new worker
    holds them until :func:`_start` has set its own handlers)."""
    with signals_wait():
        mask = signal.pthread_sigmask(signal.SIG_BLOCK, _STOPPING)
        try:
            yield
        finally:
            signal.pthread_sigmask(signal.SIG_SETMASK, mask)


def unordered(function: Callable[[T], R], items: Iterable[T], jobs: int, *,
              initializer: Callable[..., object] | None = None, initargs: Sequence[Any] = (),
              method: str | None = None) -> Iterator[R]:
    """``function(item)`` of every item, in ``jobs`` worker processes (started by ``method``: ``fork`` where the
    system has it, else ``spawn``; each runs ``initializer(*initargs)`` first), yielded as they finish."""
    executor = ProcessPoolExecutor(max(1, jobs), mp_context=_context(method), initializer=_start,
                                   initargs=(initializer, tuple(initargs)))
    finished = False
    try:
        with _starting():
            pending = _submitted(executor, function, items)
        while pending:
            done, pending = wait(pending, return_when=FIRST_COMPLETED)
            for future in done:
                yield _result(future)
        finished = True
    finally:  # any other way out (an interrupt even while the tasks were being submitted): end the workers
        _stop(executor, early=not finished)


def ordered(function: Callable[[T], R], items: Iterable[T], jobs: int, **options: Any) -> Iterator[R]:
    """:func:`unordered`'s results in the order of ``items``, each as soon as every earlier one has come."""
    done: dict[int, R] = {}
    following = 0
    for index, result in unordered(_indexed, [(function, i, item) for i, item in enumerate(items)], jobs,
                                   **options):
        done[index] = result
        while following in done:
            yield done.pop(following)
            following += 1


def _indexed(task: tuple[Callable[[T], R], int, T]) -> tuple[int, R]:
    function, index, item = task
    return index, function(item)


_BROKEN = ("a worker process ended abruptly (killed by a signal, or out of memory?): the run stopped; run it again, "
           "with fewer --jobs if memory is short")


def _submitted(executor: ProcessPoolExecutor, function: Callable[[T], R], items: Iterable[T]) -> set[Future[R]]:
    """Every item handed to the pool. The items may be built as they are handed over (a suite's episodes, slow under
    load), so a worker can die before the last: the pool then refuses the next, said as :func:`_result` says it."""
    try:
        return {executor.submit(_call, function, item) for item in items}
    except BrokenProcessPool:
        raise SealError(_BROKEN) from None


def _result(future: Future[R]) -> R:
    try:
        return future.result()
    except BrokenProcessPool:
        raise SealError(_BROKEN) from None


def _stop(executor: ProcessPoolExecutor, *, early: bool) -> None:
    """End every worker and reap it, and shut the pool down, its tasks not yet run cancelled. ``early``: the run did
    not finish (an error, an interrupt, the caller stopping), so the workers are ended first — terminated, killed
    after :data:`GRACE` seconds, reaped — and only then is the pool shut down (its manager thread then sees them
    gone, and waits for nothing); a finished run's workers are ended by the pool itself, then reaped here. The
    pool's own thread cancels the tasks (cancelled here too, its failing of the tasks of a broken pool met a
    cancelled one: an ``InvalidStateError`` traceback from that thread)."""
    processes = list((getattr(executor, "_processes", None) or {}).values())
    if early:
        _end(processes)
    executor.shutdown(wait=True, cancel_futures=True)
    _end(processes)


def _end(processes: list[multiprocessing.process.BaseProcess]) -> None:
    """Terminate each process, kill those still running after :data:`GRACE` seconds, and reap them all."""
    for process in processes:
        if process.is_alive():
            process.terminate()
    deadline = time.monotonic() + GRACE
    for process in processes:
        process.join(max(0.0, deadline - time.monotonic()))
        if process.is_alive():
            process.kill()
            process.join()
