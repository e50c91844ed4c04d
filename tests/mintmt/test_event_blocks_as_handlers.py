"""An ``Event`` block is its event's handler (MT-7, MT-13): the checks of v4's ``#`` handlers apply to it."""

from __future__ import annotations

from pathlib import Path

import mintlang
from tests.runtime.invoking import mint_run


def _findings(source: str, controller: str = "nextmove-pci") -> list[tuple[str, str, int]]:
    analysis = mintlang.check_application(source, dialect="mintmt", controller=controller)
    return [(d.code, d.message, d.span.start) for d in analysis.program]


def test_an_event_block_for_a_fast_input_the_controller_lacks_is_never_called() -> None:
    """MintDrive latches on inputs 0 and 2 only: it has no #FASTIN1 (000:5878-5888)."""
    source = "Dim n\nEvent FASTIN1\n  n = 1\nEnd Event\n"
    assert _findings(source, "mintdrive") == [
        ("W109", "Event FASTIN1: MintDrive calls #FASTINx for x = 0, 2 only", 12),  # the name after "Event "
    ]
    assert _findings(source.replace("FASTIN1", "FASTIN2"), "mintdrive") == []


def test_a_generic_and_a_numbered_fast_input_event_block_conflict() -> None:
    """Error 3006: #FASTIN and #FASTINx cannot both be defined (000:19108-19110), reported at the later one."""
    source = "Dim n\nEvent FASTIN\n  n = 1\nEnd Event\nEvent FASTIN0\n  n = 2\nEnd Event\n"
    assert _findings(source) == [
        ("E3006", "#FASTIN conflicts with #FASTINx: #FASTIN and #FASTINx handlers cannot both be defined", 43),
    ]


def test_a_fast_input_label_and_a_fast_input_event_block_conflict() -> None:
    source = "Dim n\nEnd\n#FASTIN0\n  n = 1\nReturn\nEvent FASTIN\n  n = 2\nEnd Event\n"
    ((code, _, start),) = _findings(source)
    assert (code, start) == ("E3006", 40)


def test_the_move_buffer_event_is_nextmove_only() -> None:
    """The note's section "Automatically Restocking the Move Buffer" is marked NextMove only (004:109)."""
    source = "Dim n\nEvent MOVEBUFFERLOW\n  n = 1\nEnd Event\n"
    assert _findings(source) == []
    assert _findings(source, "mintdrive") == [
        ("W109", "Event MOVEBUFFERLOW: MintDrive has no MOVEBUFFERLOW event: the note gives it to NextMove only", 12),
    ]


def test_the_run_stops_before_it_starts_on_conflicting_fast_input_blocks(tmp_path: Path) -> None:
    program = tmp_path / "fast.mnt"
    program.write_text("Dim n\nPrint 1\nEvent FASTIN\n  n = 1\nEnd Event\nEvent FASTIN3\n  n = 2\nEnd Event\n")
    result = mint_run("--dialect", "mintmt", str(program))
    assert result.exit_code != 0
    assert result.output.startswith("C3006: PROGRAM #FASTIN conflicts with #FASTINx [line 6]")
