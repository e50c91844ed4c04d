"""The verification report of ``--to mintmt`` names its two runs ``v4`` (the original) and ``mintmt`` (the
migration) where the v3 → v4 report says ``v3`` and ``v4``."""

from __future__ import annotations

import io

from rich.console import Console

from mintlang.migrate.verification import Divergence, Place, Stopped, Verdict, Verification
from mintlang.migrate.verification.report import V3_TO_V4, V4_TO_MINTMT, Verified, render_text, report

STOP = Stopped("end", 30, None, "")
FOUND = Divergence(12, "terminal", '"1"', '"2"', Place("program", 3), Place("program", 4))
VERIFIED = Verified(
    "cell.mnt",
    None,
    Verification(Verdict.DIVERGES, 30, FOUND, (FOUND,), "nextmove-pci", "nextmove-pci", STOP, STOP, (), ()),
)


def _text(sides: tuple[str, str]) -> list[str]:
    console = Console(file=io.StringIO(), width=200, color_system=None)
    render_text(report([VERIFIED], sides), console, sides=sides)
    return console.file.getvalue().splitlines()  # type: ignore[attr-defined]


def test_json_names_the_runs_v4_and_mintmt() -> None:
    application = report([VERIFIED], V4_TO_MINTMT)["applications"][0]
    assert (application["v4_controller"], application["mintmt_controller"]) == ("nextmove-pci", "nextmove-pci")
    assert set(application["stopped"]) == {"v4", "mintmt"}
    assert application["divergence"]["v4"]["line"] == 3 and application["divergence"]["mintmt"]["line"] == 4


def test_text_names_the_runs_and_places_the_migrations_line_in_the_migrated_file() -> None:
    lines = _text(V4_TO_MINTMT)
    assert lines[0] == "cell.mnt: diverges at 12 ms: terminal"
    assert lines[1:3] == ['  v4: "1"  at cell.mnt:3', '  mintmt: "2"  at migrated cell.mnt:4']


def test_the_v3_to_v4_report_is_as_it_was() -> None:
    assert _text(V3_TO_V4)[1:3] == ['  v3: "1"  at cell.mnt:3', '  v4: "2"  at migrated cell.mnt:4']
    assert "v3_controller" in report([VERIFIED])["applications"][0]
