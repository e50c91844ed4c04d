"""``mint test | head -1``: a reader that stops reading ends ``mint test`` as it ends ``mint-run``.

A shell reports 141 (128 + SIGPIPE) for a writer whose reader went away; ``mint-run`` exits with it,
and so must ``mint test``, without a traceback, an "Exception ignored" note or the status 1 that
would say a test failed. The report here is a line per failed expectation, written as it goes and
far larger than a pipe's buffer (64 KiB on Linux), so the reader is gone before the last of it is written.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.reader_leaves import BROKEN_PIPE, first_line_then_hang_up


@pytest.mark.parametrize("verbosity", ["-q", "-v"])
def test_a_report_cut_short_by_its_reader_ends_with_the_broken_pipe_status(tmp_path: Path, verbosity: str) -> None:
    expectations = "".join(f"REM @expect a = {value}\n" for value in range(1, 5001))
    (tmp_path / "many.mnt").write_text(f"{expectations}DIM a\n", encoding="utf-8")
    first, status, stderr = first_line_then_hang_up("test", "-j", "1", "--color", "never", verbosity, str(tmp_path))
    assert first == f"FAILED {tmp_path / 'many.mnt'}  5000 of 5000 expectations failed\n"
    assert status == BROKEN_PIPE
    assert "Traceback" not in stderr and "Exception ignored" not in stderr


def test_a_json_report_cut_short_by_its_reader_ends_with_the_broken_pipe_status(tmp_path: Path) -> None:
    # every test passes, so a report read to its end exits 0; one cut short must not look like that
    for number in range(200):
        (tmp_path / f"t{number}.mnt").write_text('REM @expect terminal contains "x"\nPRINT "x"\n', encoding="utf-8")
    first, status, stderr = first_line_then_hang_up("test", "-j", "1", "--format", "json", str(tmp_path))
    assert first == "{\n"
    assert status == BROKEN_PIPE
    assert "Traceback" not in stderr and "Exception ignored" not in stderr
