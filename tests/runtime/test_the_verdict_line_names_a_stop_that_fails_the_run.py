"""``mint-run --expect``: when every expectation held but the run stopped short, the closing line says the run
fails and why, as its exit status does (runtime/scenario/README.md: a run that stops on an error, a deadlock or
the wall-clock limit fails unless a ``stopped`` expectation asks for it)."""

from __future__ import annotations

from pathlib import Path

from tests.runtime.invoking import mint_run, write


def _closing_line(stderr: str) -> str:
    return stderr.rstrip().splitlines()[-1]


def test_expectations_held_in_a_run_an_error_stopped_are_not_a_pass(tmp_path: Path) -> None:
    # 1 / 0 on line 2 is an error the program has no handler for: the run stops there.
    program = write(tmp_path, "crash.mnt", "DIM x = 0\nPRINT 1 / x\n")
    held = write(tmp_path, "held.toml", '[[expect]]\nwhat = "x"\nequals = 0\n')
    result = mint_run(program, "--expect", held)
    assert result.exit_code == 1
    assert _closing_line(result.stderr) == "The expectation held, but the run fails: it stopped on error."


def test_a_main_loop_that_runs_into_the_wall_clock_limit_is_not_a_pass(tmp_path: Path) -> None:
    # The expectation is at the end of the run, which a LOOP .. ENDL never reaches: the wall-clock limit stops it.
    program = write(tmp_path, "forever.mnt", "REM @expect n >= 0\nREM @expect n >= 0\nDIM n\nLOOP\n  n = 1\nENDL\n")
    result = mint_run(program, "--expect", write(tmp_path, "none.toml", ""), "--max-wall-s", "0.2")
    assert result.exit_code == 1
    assert _closing_line(result.stderr) == "All 2 expectations held, but the run fails: it stopped on wall-limit."


def test_a_stop_a_stopped_expectation_asks_for_leaves_the_line_as_it_was(tmp_path: Path) -> None:
    program = write(tmp_path, "crash.mnt", "DIM x = 0\nPRINT 1 / x\n")
    crash = write(tmp_path, "crash.toml", '[[expect]]\nstopped = "error"\n')
    result = mint_run(program, "--expect", crash)
    assert result.exit_code == 0
    assert _closing_line(result.stderr) == "The expectation held."
