"""``MOVEOUT(axis, bank)`` gives a whole bank its pattern (004:288-297): on a NextMove PCI the main
card is bank 0 and its two expansion cards banks 1 and 2, whose outputs are numbered on from 12 and
24 (000:4125-4127, 7340-7348). A bank the controller lacks is out of range (error 3)."""

from __future__ import annotations

import pytest

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import Limits, run_source
from mintlang.runtime.scenario import DrivesEnabled, Scenario

_ENABLED = Scenario(drives=(DrivesEnabled(),))


def _run(source: str):
    limits = Limits(until_ms=1000, max_wall_s=60.0)
    return run_source(source, dialect="mintmt", controller="nextmove-pci", scenario=_ENABLED, limits=limits)


@pytest.mark.parametrize(("bank", "outputs"), [(0, 5), (1, 5 << 12), (2, 5 << 24)])
def test_an_output_move_sets_the_outputs_of_its_bank(bank: int, outputs: int) -> None:
    result = _run(f"MOVEBUFFERSIZE(0) = 4\nMOVER(0) = 10\nMOVEOUT(0,{bank}) = 5\nGO(0)\nWAIT = 100\n")
    assert result.stop.reason is StopReason.END
    assert result.outputs == outputs


def test_an_output_move_to_a_bank_the_controller_lacks_is_out_of_range() -> None:
    result = _run("MOVEBUFFERSIZE(0) = 4\nMOVEOUT(0,3) = 5\n")
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 3, 2)
