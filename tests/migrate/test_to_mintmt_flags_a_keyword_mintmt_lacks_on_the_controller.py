"""``--to mintmt`` flags a keyword Mint v4 has on the controller and MintMT does not, rather than write a line the
MintMT compiler refuses with error 17.

SUSPEND is on all five controllers in v4 (000:17775); the move buffer note names it in its "NextMove only" section
on contouring (004:176, 248), and MintMT gives that section's keywords to the NextMoves alone (MT-2). On a
MintDrive or a ServoNode 51 the migrated SUSPEND is error 17 in ``mint check --dialect mintmt``: the line is kept as
written, with a manual item above it. On a NextMove, where both dialects have it, nothing is flagged.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.migrate.mintmt import to_mintmt

PROGRAM = "MOVER.0 = 10 : GO.0\nSUSPEND.0 = 1\nPAUSE IDLE.0\n"
MIGRATED = "MOVER(0) = 10 : GO(0)\nSUSPEND(0) = 1\nPAUSE IDLE(0)\n"
HAVING = "only on NextMove PCI, NextMove PC and NextMove BX"


@pytest.mark.parametrize(("controller", "title"), [("mintdrive", "MintDrive"), ("servonode51", "ServoNode 51")])
def test_suspend_is_flagged_where_mintmt_lacks_it(controller: str, title: str) -> None:
    reason = f"in MintMT, SUSPEND is not available on {title}, {HAVING} (error 17)"
    result = to_mintmt(PROGRAM, controller=controller)
    assert [(item.rule, item.original_line, item.reason) for item in result.manual] == [("MT-PLATFORM", 2, reason)]
    assert result.text.splitlines()[1:3] == [f"REM MIGRATE: MT-PLATFORM: {reason}", "SUSPEND(0) = 1"]
    checked = mintlang.check(result.text, dialect="mintmt", controller=controller)
    assert [d.code for d in checked if d.code.startswith("E")] == ["E0017"]


@pytest.mark.parametrize("controller", ["nextmove-pci", "nextmove-pc", "nextmove-bx"])
def test_nothing_is_flagged_on_a_nextmove(controller: str) -> None:
    result = to_mintmt(PROGRAM, controller=controller)
    assert (result.text, result.manual) == (MIGRATED, ())


def test_a_second_migration_of_the_flagged_file_changes_nothing() -> None:
    first = to_mintmt(PROGRAM, controller="mintdrive")
    assert to_mintmt(first.text, controller="mintdrive").text == first.text
