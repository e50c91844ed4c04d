"""An incomplete verification's headline says why the comparison stopped, and nothing of a difference: the
differences before it were all explained (M-TRIG), so each is listed as one, not as the headline's."""

from __future__ import annotations

import io

from rich.console import Console

from mintlang.migrate.verification import Divergence, Place, Stopped, Verdict, Verification
from mintlang.migrate.verification.report import Verified, render_text, report

STOP = Stopped("error", 0, Place("program", 4), "DAC (write) is not simulated by mint-run")
EXPLAINED = Divergence(  # SIN(45) * 1000 as v3's table and v4's function give it, before the run stopped
    0,
    "terminal",
    "'707'",
    "'707.1068'",
    Place("program", 2),
    Place("program", 3),
    "v3 character 86 / v4 character 86",
    explained_by="M-TRIG",
)
SHORT = "DAC (write) is not simulated by mint-run"
INCOMPLETE = Verification(
    Verdict.INCOMPLETE, 0, EXPLAINED, (EXPLAINED,), "euroservo", "nextmove-pci", STOP, STOP, (), (), SHORT
)


def test_the_headline_of_an_incomplete_run_names_no_difference_and_the_explained_one_is_listed() -> None:
    console = Console(file=io.StringIO(), width=200, color_system=None)
    render_text(report([Verified("p5.mnt", None, INCOMPLETE)]), console)
    lines = console.file.getvalue().splitlines()  # type: ignore[attr-defined]
    assert lines[0] == f"p5.mnt: incomplete: {SHORT}"
    assert lines[1] == "  also differs: terminal at 0 ms (v3 '707', v4 '707.1068', explained by M-TRIG)"
    assert lines[2].startswith("  explained: M-TRIG ")
