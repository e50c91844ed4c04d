"""MintMT's Comms array: the note's 99 general elements (002:19, 41) over v4's extended map (MT-1)."""

from __future__ import annotations

from pathlib import Path

import mintlang
from tests.runtime.invoking import mint_run


def test_writing_a_general_element_is_fine() -> None:
    assert mintlang.check_application("comms (99) = 3\n", dialect="mintmt").program == ()


def test_writing_a_mapped_read_only_element_is_error_45_in_the_check_and_the_run(tmp_path: Path) -> None:
    """Element 100 is axis 0's POS, read only (000:2567-2594); writing one is error 45 (000:18676-18678)."""
    source = "Print 1\ncomms(100) = 1\n"
    (diagnostic,) = mintlang.check_application(source, dialect="mintmt").program
    assert (diagnostic.code, diagnostic.span.start) == ("E0045", 14)  # the 100 of line 2
    assert diagnostic.message.endswith(": COMMS element 100 is POS of axis 0, which can only be read")
    program = tmp_path / "write.mnt"
    program.write_text(source, encoding="utf-8")
    result = mint_run("--dialect", "mintmt", str(program))
    assert result.exit_code != 0
    assert result.output.startswith("1\nR0045: PROGRAM COMMS element is read only [line 2]")
