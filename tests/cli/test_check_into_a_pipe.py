"""``mint check | head -1``: a reader that stops reading ends ``mint check`` quietly, with 141, in every format.

A shell reports 141 (128 + SIGPIPE) for a writer whose reader went away, as ``mint-run`` and
``mint test`` exit. ``mint check`` must too, whatever the format: not 0 as if the whole report had
been read (one large write into the pipe used to lose the rest of a JSON report without a word),
nor 1, which says errors were found, nor a traceback. The files here have warnings only (an unused
variable), so a report read to its end exits 0, and the report is far larger than a pipe's buffer.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from tests.reader_leaves import BROKEN_PIPE, first_line_then_hang_up


@pytest.fixture(scope="module")
def warnings_only(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("warnings")
    for number in range(10):
        (folder / f"f{number}.mnt").write_text("".join(f"DIM x{i}\n" for i in range(200)), encoding="utf-8")
    return folder


@pytest.mark.parametrize("output_format", ["text", "json", "sarif", "github"])
def test_a_report_cut_short_by_its_reader_ends_with_the_broken_pipe_status(
    warnings_only: Path, output_format: str
) -> None:
    arguments = ("check", "-j", "1", "--format", output_format, "--color", "never", str(warnings_only))
    first, status, stderr = first_line_then_hang_up(*arguments)
    assert first
    assert status == BROKEN_PIPE
    assert "Traceback" not in stderr and "Exception ignored" not in stderr


def test_the_same_report_read_whole_exits_0(warnings_only: Path) -> None:
    done = subprocess.run(
        [sys.executable, "-m", "mintlang", "check", "-j", "1", "--format", "json", warnings_only],
        capture_output=True,
        check=False,
    )
    assert done.returncode == 0 and done.stdout.rstrip().endswith(b"]")
