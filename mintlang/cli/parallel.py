"""Work on many files on all cores, in the order given, with a progress bar on a terminal.

The results come back in the order of the inputs whatever the number of
workers, so a report never depends on ``-j`` or on which process was quicker.
One file, or one worker, is done in this process: starting workers costs more
than it saves.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator, Sequence
from typing import TYPE_CHECKING, TypeVar

if TYPE_CHECKING:
    from rich.console import Console

In = TypeVar("In")
Out = TypeVar("Out")

_CHUNKS_PER_WORKER = 8  # small enough to keep every core busy to the end, large enough to send few messages


def all_cores() -> int:
    """The cores this process may run on (a container or ``taskset`` may allow fewer than the machine has)."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def _ignore_interrupts() -> None:
    """A worker leaves Ctrl-C to the command, which stops them all; each would print a traceback."""
    import signal  # noqa: PLC0415 - in the workers only, which one file does without

    signal.signal(signal.SIGINT, signal.SIG_IGN)


def _results(function: Callable[[In], Out], items: Sequence[In], workers: int) -> Iterator[Out]:
    if workers <= 1 or len(items) <= 1:
        yield from map(function, items)
        return
    from concurrent.futures import ProcessPoolExecutor  # noqa: PLC0415 - multiprocessing, for more than one file

    workers = min(workers, len(items))
    chunk = max(1, len(items) // (workers * _CHUNKS_PER_WORKER))
    with ProcessPoolExecutor(workers, initializer=_ignore_interrupts) as pool:
        try:
            yield from pool.map(function, items, chunksize=chunk)
        except BaseException:
            pool.shutdown(wait=False, cancel_futures=True)
            raise


def map_in_order(
    function: Callable[[In], Out],
    items: Sequence[In],
    *,
    workers: int,
    progress: Console | None = None,
    description: str = "checking",
) -> list[Out]:
    """``function`` of each item, in order, on up to ``workers`` processes (a top-level function: it is pickled).

    With a ``progress`` console that writes to a terminal, a transient bar counts the items done; one only
    coloured as a terminal (``--color always``, ``FORCE_COLOR``) writing to a pipe or a log gets no bar.
    """
    if progress is None or not progress.file.isatty():
        return list(_results(function, items, workers))
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn  # noqa: PLC0415

    bar = Progress(
        TextColumn(description),
        BarColumn(),
        MofNCompleteColumn(),
        TimeElapsedColumn(),
        console=progress,
        transient=True,
    )
    results: list[Out] = []
    with bar:
        task = bar.add_task(description, total=len(items))
        for result in _results(function, items, workers):
            results.append(result)
            bar.advance(task)
    return results
