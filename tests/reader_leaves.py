"""A tool run as ``tool | head -1`` runs it: its first line read, then the pipe closed before the rest.

A shell reports 141 (128 + SIGPIPE) for a writer whose reader went away; the tools exit with it,
quietly. The report a test asks for must be far larger than a pipe's buffer (64 KiB on Linux), so
that the reader is gone before the last of it is written.
"""

from __future__ import annotations

import subprocess
import sys

BROKEN_PIPE = 141


def first_line_then_hang_up(*arguments: str) -> tuple[str, int, str]:
    """``python -m mintlang <arguments>``: its first line, its exit status and its standard error."""
    process = subprocess.Popen(
        [sys.executable, "-m", "mintlang", *arguments],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        assert process.stdout is not None and process.stderr is not None
        first = process.stdout.readline()
        process.stdout.close()
        stderr = process.stderr.read()
        process.wait(timeout=120)
    finally:
        process.kill()
    return first, process.returncode, stderr
