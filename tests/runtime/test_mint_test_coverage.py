"""``mint test --coverage``: lines, branch outcomes and event handlers, worked out by hand on small programs."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.cli import main

# Lines with statements: 2-11, 13, 14 (the label line 12 holds none). The FOR runs its body three times;
# the IF .. THEN of line 5 is never true; the IF .. DO is, and its PAUSE passes at once; #ONERROR never runs.
PROGRAM = """REM @expect a = 3
DIM a
DIM i
FOR i = 1 TO 3
  IF i > 5 THEN a = 100
  a = a + 1
NEXT
IF a = 3 DO
  PAUSE a = 3
ENDIF
END
#ONERROR
  a = 0
RETURN
"""

EXPECTED = """TN:
SF:{path}
FN:13,#ONERROR
FNDA:0,#ONERROR
FNF:1
FNH:0
BRDA:4,0,0,1
BRDA:4,0,1,0
BRDA:5,1,0,0
BRDA:5,1,1,3
BRDA:8,2,0,1
BRDA:8,2,1,0
BRDA:9,3,0,1
BRDA:9,3,1,0
BRF:8
BRH:4
DA:2,1
DA:3,1
DA:4,1
DA:5,3
DA:6,3
DA:7,3
DA:8,1
DA:9,1
DA:10,1
DA:11,1
DA:13,0
DA:14,0
LF:12
LH:10
end_of_record
"""


def test_the_tracefile_counts_each_line_branch_outcome_and_handler(tmp_path: Path) -> None:
    program = tmp_path / "counted.mnt"
    program.write_text(PROGRAM, encoding="utf-8")
    tracefile = tmp_path / "lcov.info"
    result = CliRunner().invoke(main, ["test", str(program), "--coverage", "--lcov", str(tracefile), "-j", "1"])
    assert result.exit_code == 0, result.output
    assert tracefile.read_text(encoding="utf-8") == EXPECTED.format(path=program)
    assert "10/12 (83 %)" in result.output and "4/8 (50 %)" in result.output and "0/1 (0 %)" in result.output


def _records(tmp_path: Path, text: str, kinds: tuple[str, ...], *options: str) -> list[str]:
    """The tracefile's records of ``kinds`` (``"DA:"``, ``"BRDA"`` …) after ``mint test --coverage`` of one
    program, which must pass."""
    program = tmp_path / "covered.mnt"
    program.write_text(text, encoding="utf-8")
    tracefile = tmp_path / "lcov.info"
    arguments = ["test", str(program), *options, "--coverage", "--lcov", str(tracefile), "-j", "1"]
    result = CliRunner().invoke(main, arguments)
    assert result.exit_code == 0, result.output
    return [line for line in tracefile.read_text(encoding="utf-8").splitlines() if line.startswith(kinds)]


def test_a_pause_that_waits_and_a_loop_left_by_until_are_the_other_outcomes(tmp_path: Path) -> None:
    # REPEAT runs twice: UNTIL repeats once and is left once; the PAUSE waits for the timer.
    program = "REM @expect n = 2\nDIM n\nREPEAT\n  n = n + 1\nUNTIL n = 2\nPAUSE TIME > 10\n"
    branches = _records(tmp_path, program, ("BRDA",))
    assert branches == ["BRDA:5,0,0,1", "BRDA:5,0,1,1", "BRDA:6,1,0,0", "BRDA:6,1,1,1"]


def test_a_mintmt_event_line_is_a_declaration_not_a_line_to_run(tmp_path: Path) -> None:
    # The host writes comms 1 at 10 ms: the handler (lines 7-8) runs once while line 4 waits; line 6, the
    # Event line, is entered by the event and never run itself, so it is no line to cover.
    program = (
        "' @sim host write 1 \"7\" at 10\n' @expect n = 1\nDim n\nPause n = 1\nEnd\n"
        "Event Comms1\n  n = n + 1\nEnd Event\n"
    )
    lines = _records(tmp_path, program, ("DA:", "L"), "--dialect", "mintmt")
    assert lines == ["DA:3,1", "DA:4,1", "DA:5,1", "DA:7,1", "DA:8,1", "LF:5", "LH:5"]


def test_a_mintmt_startup_line_is_a_declaration_not_a_line_to_run(tmp_path: Path) -> None:
    # The Startup block (lines 6-7) runs first, at power-up (004:128-133), then the program from line 2 to its
    # End (line 4); the Startup line (5) is entered by the controller and never run, so it is no line to cover.
    program = "' @expect OUT = 2\nDim n\nn = 1\nEnd\nStartup\n  OUTX(1) = 1\nEnd Startup\n"
    lines = _records(tmp_path, program, ("DA:", "L"), "--dialect", "mintmt")
    assert lines == ["DA:2,1", "DA:3,1", "DA:4,1", "DA:6,1", "DA:7,1", "LF:5", "LH:5"]


def test_the_line_that_raises_the_error_ending_the_run_ran(tmp_path: Path) -> None:
    # Line 3 indexes outside a(3): the run stops there with R2016, so line 3 ran once and END (line 4) never.
    lines = _records(tmp_path, "REM @expect stopped error\nDIM a(3)\na(5) = 1\nEND\n", ("DA:", "L"))
    assert lines == ["DA:2,1", "DA:3,1", "DA:4,0", "LF:3", "LH:2"]


def test_a_line_failing_into_onerror_ran_once(tmp_path: Path) -> None:
    # Line 4 fails once into #ONERROR (lines 7-8) with a system error (axis 12 is invalid, 000:4616-4618),
    # whose RETURN resumes after it at END (line 5); the label line 6 holds no statement.
    program = "REM @expect n = 1\nDIM v\nDIM n\nv = POS.12\nEND\n#ONERROR\n  n = n + 1\nRETURN\n"
    lines = _records(tmp_path, program, ("DA:", "L"))
    assert lines == ["DA:2,1", "DA:3,1", "DA:4,1", "DA:5,1", "DA:7,1", "DA:8,1", "LF:6", "LH:6"]


def test_an_else_line_counts_its_branch_and_the_endif_counts_every_branch_that_ended(tmp_path: Path) -> None:
    # The first IF block runs its true branch for i = 1 and its ELSE branch for i = 2: the ELSE line (7) began
    # a branch once and the ENDIF (9) ended one twice. The second block's IF is true: its ELSE line (13) and
    # branch (14) never ran, its ENDIF (15) ended the true branch once.
    program = (
        "REM @expect a = 2\nDIM a\nDIM i\nFOR i = 1 TO 2\n  IF i = 1 DO\n    a = a + 1\n  ELSE\n    a = a + 1\n"
        "  ENDIF\nNEXT\nIF a = 2 DO\n  a = a\nELSE\n  a = 0\nENDIF\nEND\n"
    )
    lines = _records(tmp_path, program, ("DA:", "L"))
    assert lines == [
        *("DA:2,1", "DA:3,1", "DA:4,1", "DA:5,2", "DA:6,1", "DA:7,1", "DA:8,1", "DA:9,2", "DA:10,2"),
        *("DA:11,1", "DA:12,1", "DA:13,0", "DA:14,0", "DA:15,1", "DA:16,1", "LF:15", "LH:13"),
    ]


def test_lcov_without_coverage_is_a_usage_error_before_any_test_runs(tmp_path: Path) -> None:
    """--lcov only says where --coverage writes: alone, the run ended with no tracefile and no word of why."""
    program = tmp_path / "cell.mnt"
    program.write_text(PROGRAM, encoding="utf-8")
    tracefile = tmp_path / "cov.info"
    result = CliRunner().invoke(main, ["test", str(program), "--lcov", str(tracefile), "-j", "1"])
    assert result.exit_code == 2
    assert f"--lcov {tracefile} names the tracefile --coverage writes: add --coverage" in result.output
    assert "PASSED" not in result.output
    assert not tracefile.exists()


def test_coverage_without_lcov_writes_lcov_info_in_the_working_folder(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    program = tmp_path / "cell.mnt"
    program.write_text(PROGRAM, encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(main, ["test", str(program), "--coverage", "-j", "1"])
    assert result.exit_code == 0, result.output
    assert (tmp_path / "lcov.info").read_text(encoding="utf-8").startswith("TN:\nSF:")
