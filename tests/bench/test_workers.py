"""``bench/workers.py``: every way a ``--jobs N`` run ends (a worker killed, a worker raising, a result that does
not pickle, the parent interrupted or stopping early) ends it, with a clear error and no worker left; a
``multiprocessing.Pool`` waited for ever on a killed worker."""

from __future__ import annotations

import multiprocessing
import os
import signal
import time

import pytest

from seal_cli.bench.workers import ordered, unordered
from seal_cli.errors import SealError


def _square(n: int) -> int:
    return n * n


def _killed_at_one(n: int) -> int:
    if n == 1:
        os.kill(os.getpid(), signal.SIGKILL)
    return n


def _refused_at_two(n: int) -> int:
    if n == 2:
        raise SealError("episode 2: no such room")
    return n


def _unpicklable(n: int) -> object:
    return lambda: n


def _slow_but_zero(n: int) -> int:
    if n:
        time.sleep(60)
    return n


_SEEN: dict[str, int] = {}


def _remember(value: int) -> None:
    _SEEN["value"] = value


def _seen(n: int) -> int:
    return _SEEN["value"] + n


def _refuse_to_start() -> None:
    raise SealError("cannot read the suite")


def _no_workers_left() -> bool:
    return not [p for p in multiprocessing.active_children() if p.name.startswith("SpawnProcess")
                or p.name.startswith("ForkProcess")]


def test_results_come_in_order_or_as_they_finish() -> None:
    assert list(ordered(_square, range(6), 2)) == [0, 1, 4, 9, 16, 25]
    assert sorted(unordered(_square, range(6), 3)) == [0, 1, 4, 9, 16, 25]
    assert list(ordered(_square, [], 2)) == []


def test_each_worker_runs_its_initializer_first() -> None:
    assert list(ordered(_seen, range(3), 2, initializer=_remember, initargs=(10,))) == [10, 11, 12]


def test_a_worker_killed_by_a_signal_ends_the_run_with_a_message() -> None:
    started = time.monotonic()
    with pytest.raises(SealError, match=r"a worker process ended abruptly \(killed by a signal, or out of memory"):
        list(ordered(_killed_at_one, range(4), 2))
    assert time.monotonic() - started < 30
    assert _no_workers_left()


def _made_slowly(count: int) -> object:
    """Items built one by one, slower than a worker dies: the pool breaks while they are still being handed over."""
    for n in range(count):
        yield n
        time.sleep(1.0)


def test_a_worker_killed_while_the_items_are_still_handed_over_ends_the_run_with_the_message() -> None:
    """Under load a suite's episodes are built slower than a worker is killed: the pool broke during ``submit``
    and its ``BrokenProcessPool`` escaped as a traceback (words31's whole-suite run, hostile23's SIGKILL case)."""
    with pytest.raises(SealError, match=r"a worker process ended abruptly \(killed by a signal, or out of memory"):
        list(unordered(_killed_at_one, _made_slowly(4), 2))  # type: ignore[arg-type]
    assert _no_workers_left()


def test_a_workers_error_is_the_runs_error() -> None:
    with pytest.raises(SealError, match="episode 2: no such room"):
        list(ordered(_refused_at_two, range(4), 2))
    assert _no_workers_left()


def test_an_initializer_that_raises_is_raised_once_not_restarted_for_ever() -> None:
    started = time.monotonic()
    with pytest.raises(SealError, match="cannot read the suite"):
        list(unordered(_square, range(4), 2, initializer=_refuse_to_start))
    assert time.monotonic() - started < 30
    assert _no_workers_left()


def test_a_result_that_does_not_pickle_is_an_error_not_a_hang() -> None:
    with pytest.raises(Exception, match="pickle"):
        list(ordered(_unpicklable, range(3), 2))
    assert _no_workers_left()


@pytest.mark.parametrize("stop", ["interrupt", "early"])
def test_an_interrupted_or_abandoned_run_ends_its_workers_at_once(stop: str) -> None:
    started = time.monotonic()
    results = unordered(_slow_but_zero, range(3), 2)
    assert next(results) == 0
    if stop == "interrupt":
        with pytest.raises(KeyboardInterrupt):
            results.throw(KeyboardInterrupt)
    else:
        results.close()
    assert time.monotonic() - started < 30   # the two tasks of a minute were not waited for
    assert _no_workers_left()


def test_an_interrupt_while_a_worker_is_forked_leaves_no_worker_behind(monkeypatch: pytest.MonkeyPatch) -> None:
    """SIGINT landing between a fork and the pool's record of its process (under load the fork of a large process
    is slow): that worker was known to no one, waited for a task for ever and kept the command's output open."""
    forked: list[int] = []
    fork = os.fork

    def interrupted_fork() -> int:
        pid = fork()
        if pid:
            forked.append(pid)
            if len(forked) == 1:
                os.kill(os.getpid(), signal.SIGINT)   # acted on by Python right here, just after the fork
        return pid

    monkeypatch.setattr(os, "fork", interrupted_fork)
    with pytest.raises(KeyboardInterrupt):
        list(unordered(_square, range(4), 2, method="fork"))
    assert forked
    for pid in forked:   # ended and reaped: not even a zombie
        with pytest.raises(ProcessLookupError):
            os.kill(pid, 0)


def _busy_in_c(n: int) -> int:
    if n:
        return sum(range(10**11))   # one call of C code for minutes: no Python signal handler runs meanwhile
    return os.getpid()


def test_a_worker_in_a_long_c_call_is_ended_at_once_though_the_parent_handles_sigterm() -> None:
    """seal's command line handles SIGTERM in Python (to remove its temporaries); a worker inheriting that handler
    ran it only when its C call returned, and the pool's shutdown waited for it."""
    previous = signal.signal(signal.SIGTERM, lambda number, frame: None)
    try:
        started = time.monotonic()
        results = unordered(_busy_in_c, range(3), 2)
        next(results)
        time.sleep(0.2)
        results.close()
    finally:
        signal.signal(signal.SIGTERM, previous)
    assert time.monotonic() - started < 30
    assert _no_workers_left()


def _pid_or_nap(n: int) -> int:
    if n == 0:
        return os.getpid()
    time.sleep(0.5)
    return n


def test_a_ctrl_c_reaching_a_worker_is_left_to_the_parent() -> None:
    """A terminal's Ctrl-C goes to every process of the foreground group: a worker does not act on it (it ended a
    task with a KeyboardInterrupt, or a waiting worker with a traceback); the parent, which got it too, does."""
    results = unordered(_pid_or_nap, range(4), 1)
    worker = next(results)
    os.kill(worker, signal.SIGINT)
    assert sorted(results) == [1, 2, 3]
    assert _no_workers_left()
