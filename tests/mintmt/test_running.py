"""``mint-run --dialect mintmt``: what runs, and what says plainly that it does not (mintlang/MINTMT.md)."""

from __future__ import annotations

from pathlib import Path

from tests.runtime.invoking import mint_run

CORPUS = Path(__file__).parents[1] / "corpus" / "mintmt"


def _run(*arguments: str) -> tuple[int, str]:
    result = mint_run("--dialect", "mintmt", "--drives", "enabled", *arguments)
    return result.exit_code, result.output


def test_a_listing_of_the_move_buffer_note_runs_to_its_end() -> None:
    status, output = _run(str(CORPUS / "an00117_l0080_buffer_large_enough.mnt"))
    assert status == 0
    assert "end after 0 ms at program line 7: GO(0)" in output


def test_a_keyword_not_simulated_stops_the_run_at_its_line_saying_so(tmp_path: Path) -> None:
    # the note names the jerks without their units or the profile they shape (mintlang/MINTMT.md)
    program = tmp_path / "jerk.mnt"
    program.write_text("SPEED(0) = 10\nACCELJERK(0) = 1000\n", encoding="utf-8")
    status, output = _run(str(program))
    assert status != 0
    assert "at program line 2: ACCELJERK(0) = 1000 — ACCELJERK (write) is not simulated by mint-run" in output


def test_the_output_moves_listing_runs_to_its_end() -> None:
    status, output = _run(str(CORPUS / "an00117_l0293_output_moves.mnt"))
    assert status == 0, output


def test_an_output_move_on_mintdrive_is_error_17_as_the_note_gives_them_to_nextmove_only() -> None:
    # "Output Moves (NextMove only)" (004:286); error 17, keyword not supported (000:18570-18575)
    status, output = _run("--controller", "mintdrive", str(CORPUS / "an00117_l0293_output_moves.mnt"))
    assert status != 0
    assert "at program line 5: MOVEOUT(0,0) = 7" in output
    assert "R0017: PROGRAM Keyword not supported on this platform" in output
