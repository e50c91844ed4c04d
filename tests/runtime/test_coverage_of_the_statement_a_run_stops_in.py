"""``mint test --coverage``: a statement the program was waiting in when the run stopped ran, and waited.

A machine's test often ends while its program waits for the next part (the run ends at its last timed
expectation), or in a PAUSE an event handler ENDs the program from: the program reached the line, so the
line ran and its PAUSE took the "waited" way, however the run stopped.
"""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from mintlang.cli import main


def _records(tmp_path: Path, text: str) -> list[str]:
    """The tracefile's line and branch records after ``mint test --coverage`` of one program, which passes."""
    program = tmp_path / "cell.mnt"
    program.write_text(text, encoding="utf-8")
    tracefile = tmp_path / "lcov.info"
    result = CliRunner().invoke(main, ["test", str(program), "--coverage", "--lcov", str(tracefile), "-j", "1"])
    assert result.exit_code == 0, result.output
    return [line for line in tracefile.read_text(encoding="utf-8").splitlines() if line.startswith(("DA:", "BRDA"))]


def test_a_pause_waiting_when_the_last_check_ends_the_run_ran_and_waited(tmp_path: Path) -> None:
    # Every expectation gives a time, so the run ends at 100 ms with the program on line 3: input 0 is never
    # set, and PAUSE IN.0 waits for it (000:15023-15035); END on line 4 never runs.
    program = "REM @expect OUT.1 = 1 at 100\nOUT.1 = 1\nPAUSE IN.0\nEND\n"
    assert _records(tmp_path, program) == ["BRDA:3,0,0,0", "BRDA:3,0,1,1", "DA:2,1", "DA:3,1", "DA:4,0"]


def test_a_pause_an_error_handler_ends_the_program_in_ran_and_waited(tmp_path: Path) -> None:
    # The forward limit (input 5, high from 300 counts) trips during the move; the default limit mode crash
    # stops the axis and calls #ONERROR (000:13470-13495), which ENDs the program while line 6 waits for
    # IDLE.0: line 6 ran and waited, line 7 never ran, the handler's lines 9 and 10 ran and its RETURN did not.
    program = (
        "REM @sim drives enabled\nREM @sim input 5 when enc 0 >= 300\nREM @expect stopped end\n"
        'LIMITFORWARDINPUT.0 = 5\nMOVEA.0 = 1000 : GO.0\nPAUSE IDLE.0\nPRINT "past the limit"\nEND\n'
        "#ONERROR\n  PRINT ERR\n  END\nRETURN\n"
    )
    assert _records(tmp_path, program) == [
        *("BRDA:6,0,0,0", "BRDA:6,0,1,1"),
        *("DA:4,1", "DA:5,1", "DA:6,1", "DA:7,0", "DA:8,0", "DA:10,1", "DA:11,1", "DA:12,0"),
    ]
