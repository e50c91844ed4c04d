"""NODE takes the node numbers its table gives on every controller, 0 to 127 (000:14665).

The guide's CANopen paragraph speaks of node numbers above one as slaves (000:14684-14686),
and a node past 15 is one no host packet addresses, not a refused write: NODE = 127 reads back
127; 128 and -1 are error 3 (000:18518), as mint check says.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.interpreter.vm import StopReason
from tests.runtime.running import simulate


@pytest.mark.parametrize("node", ["16", "127"])
def test_a_node_past_15_is_taken(node: str) -> None:
    result = simulate(f"NODE = {node}\nPRINT NODE\n", controller="nextmove-pci")
    assert (result.stop.reason, result.terminal) == (StopReason.END, f"{node}\n")
    assert mintlang.check(f"NODE = {node}\n") == []


@pytest.mark.parametrize("node", ["128", "-1"])
def test_a_node_outside_0_to_127_is_error_3(node: str) -> None:
    result = simulate(f"NODE = {node}\n", controller="nextmove-pci")
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 3, 1)
    assert [d.code for d in mintlang.check(f"NODE = {node}\n")] == ["E0003"]
