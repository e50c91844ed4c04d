"""``mint check --watch``: check again whenever a file the check reads changes, as ruff's ``--watch`` does.

The files are polled, not watched through the operating system: a folder of Mint programs is small, a look at
every file twice a second costs next to nothing, and no dependency is needed for it. What is looked at is each
folder the check searched or found a program in: its Mint files (programs, configuration files) and settings
files, and the settings files of the folders above it, which a check reads as well. A file added, removed or
saved with new content changes what is seen, and the check runs again.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable, Iterable
from pathlib import Path

import click

from mintlang.cli.files import find
from mintlang.settings import Overrides

POLL_SECONDS = 0.5
_READ = frozenset({".mnt", ".cfg"})  # what a check reads besides its settings files (any case)
_SETTINGS = ("mint.toml", "pyproject.toml")

Seen = frozenset[tuple[str, int, int]]  # each file looked at: its path, modification time and size


def seen(paths: Iterable[Path], overrides: Overrides) -> Seen:
    """The state of every file a check of ``paths`` reads, or may read once it appears."""
    named = list(paths)
    found = find(named, overrides=overrides)
    folders = {path for path in named if path.is_dir()} | {file.parent for file in [*found.files, *named]}
    return frozenset(entry for folder in folders for entry in _folder(folder))


def _folder(folder: Path) -> Iterable[tuple[str, int, int]]:
    try:
        with os.scandir(folder) as entries:
            files = [Path(entry.path) for entry in entries if Path(entry.name).suffix.lower() in _READ]
    except OSError:  # gone, or not to be listed: the check says so
        files = []
    above = [parent / name for parent in folder.resolve().parents for name in _SETTINGS]
    for file in [*files, *(folder / name for name in _SETTINGS), *above]:
        try:
            status = file.stat()
        except OSError:
            continue
        yield str(file), status.st_mtime_ns, status.st_size


def watch(check: Callable[[], int | None], state: Callable[[], Seen], *, clear: bool) -> None:
    """Run ``check``, then again each time ``state`` changes, until Ctrl-C; ``clear``: the terminal first."""
    try:
        while True:
            if clear:
                click.clear()
            code = check()
            before = state()  # after the check: what --fix wrote is no change to check again
            # as the exit status says it: a warning left passes, and --exit-zero passes with errors
            outcome = "passed" if not code else "failed" if code == 1 else "could not check everything"
            click.echo(f"[{time.strftime('%H:%M:%S')}] {outcome}; watching for changes (Ctrl-C to stop)", err=True)
            while state() == before:
                time.sleep(POLL_SECONDS)
    except KeyboardInterrupt:  # the way a watch ends: no traceback, and no failure
        click.echo("", err=True)
