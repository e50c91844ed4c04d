"""A blocked PAUSE is tried again only when what it reads can change, even while other work fills every tick.

Axis 1 runs on the torque plant, so the simulator processes every tick while it
moves; a ``PAUSE`` whose condition reads only inputs and variables is tried when
it is reached, then not before the world next changes an input (or an event
runs), not on each of those ticks. Stepping every tick, the reference, tries it
on every tick; both runs must show the same.
"""

from __future__ import annotations

from mintlang.runtime.controller import Controller
from mintlang.runtime.motion.plants import TORQUE_PLANT_GAINS
from mintlang.runtime.run import RunResult, run_source
from mintlang.runtime.scenario.stimulus import InputLevel, PlantChoice, Scenario
from mintlang.runtime.simulation import Limits

from .running import observable

GAINS = TORQUE_PLANT_GAINS
CONFIGURATION = (
    f"RESETALL\nKPROP.1 = {GAINS.kprop}\nKDERIV.1 = {GAINS.kderiv}\nKVELFF.1 = {GAINS.kvelff}\n"
    f"KACCEL.1 = {GAINS.kaccel}\n"
)
MOVING = "MOVER.1 = 100000\nGO.1\n"  # about 2 s at the default speed: every tick is processed meanwhile
INPUT_3_AT_500 = Scenario(plants=(PlantChoice(1, "torque"),), inputs=(InputLevel(500, 3, 1),))


def _attempts(source: str, *, every_tick: bool) -> tuple[RunResult, dict[int, int]]:
    """The run, and how often the statement on each program line was tried (line 0: ticks processed)."""
    tried: dict[int, int] = {}

    def ticked(controller: Controller, tick: int) -> None:
        tried[0] = tried.get(0, 0) + 1

    def counting(controller: Controller) -> None:
        vm = controller.vm

        def count(line: int, operation):
            def counted():
                tried[line] = tried.get(line, 0) + 1
                return operation()

            return counted

        vm.operations[:] = [
            count(site.line, operation) if site.unit == "program" else operation
            for operation, site in zip(vm.operations, vm.sites, strict=True)
        ]

    limits = Limits(until_ms=3000, every_tick=every_tick)
    result = run_source(
        source,
        config=CONFIGURATION,
        controller="nextmove-bx",
        scenario=INPUT_3_AT_500,
        limits=limits,
        on_start=counting,
        on_tick=ticked,
    )
    return result, tried


def test_a_pause_on_an_input_is_tried_when_reached_and_when_the_input_changes() -> None:
    source = MOVING + "PAUSE IN.3 = 1\nPRINT TIME\n"
    result, tried = _attempts(source, every_tick=False)
    assert result.terminal == "500\n"  # the input is active from 500 ms: the PAUSE passes on that tick
    assert tried[3] == 2  # at 0 ms, then at 500 ms
    reference, stepped = _attempts(source, every_tick=True)
    assert stepped[3] == 501  # stepping every tick tries it on each tick from 0 to 500
    assert observable(result) == observable(reference)


def test_an_event_handler_lets_a_sleeping_pause_on_a_variable_pass_at_once() -> None:
    source = MOVING + "DIM a\nPAUSE a = 1\nPRINT TIME\nEND\n#IN3\n  a = 1\nRETURN\n"
    result, tried = _attempts(source, every_tick=False)
    assert result.terminal == "500\n"  # #IN3 runs at 500 ms, sets a, and the PAUSE passes after its RETURN
    assert tried[4] == 2
    reference, _ = _attempts(source, every_tick=True)
    assert observable(result) == observable(reference)


def test_a_pause_on_what_does_not_report_every_change_is_tried_on_every_processed_tick() -> None:
    # COMMS locations may be written by the host at any tick: its reader names no tick of change
    source = MOVING + "PAUSE COMMS(1) = 1\n"
    _, tried = _attempts(source, every_tick=False)
    assert tried[3] == tried[0] > 1000
