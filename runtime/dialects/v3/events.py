"""Mint v3 interrupts: the reserved labels, their priority, and inputs that interrupt on a falling edge.

The reserved labels are ``#ONERROR``, ``#STOP``, ``#FASTPOS`` and ``#IN0``..``#IN7``
(001:2469-2476); any other label is a subroutine, even one v4 reserves (``#TIMER``,
``#COMMS1``). The priority is #ONERROR, #FASTPOS, #STOP, then the inputs with
#IN7 highest (001:2574-2583); a higher routine finishes before a lower one is
called, except that an input's routine can be interrupted by another input's,
never by its own (001:2548-2549, 2583). An input interrupts on its falling edge,
active to inactive (001:2523-2538, 4328). #ONERROR is called when a motion error
occurs (001:5501-5511), once: returning with an error still latched does not call
it again, as v4's does.
"""

from __future__ import annotations

from collections.abc import Mapping

from mintlang.runtime.events import Dispatch, EventClass
from mintlang.runtime.io import DigitalIO

_E = EventClass
DISPATCH = Dispatch(
    order=(_E.ERROR, _E.FASTIN, _E.STOP, _E.INPUT, _E.CAN1, _E.CAN2, _E.TIMER, _E.COMMS),  # v3 raises the first 4
    preemptive=True,
    disable_keyword="",
    pending_keyword="",
    bits={kind: 1 << kind.value for kind in EventClass},
    timer_minimum_ms=0,
    highest_input_first=True,
    inputs_interrupt_inputs=True,
    onerror_repeats=False,
    unhandled_inputs_pend=False,
)
_RESERVED = {"ONERROR": "ONERROR", "STOP": "STOP", "FASTPOS": "FASTIN"} | {f"IN{n}": f"IN{n}" for n in range(8)}


def handlers(labels: Mapping[str, int]) -> dict[str, int]:
    """The interrupt routines among a file's labels, under the names the event system calls them by."""
    return {_RESERVED[label]: pc for label, pc in labels.items() if label in _RESERVED}


def falling_edges(io: DigitalIO) -> None:
    """Every input interrupts on its falling edge, and only then; ``IN`` reads the levels."""
    io.edge_mode = io.all_inputs
    io.negative_trigger = io.all_inputs
    io.positive_trigger = 0
    io.levels_only = True
