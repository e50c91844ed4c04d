"""ACTIVERS485NODE takes any node number: one outside 0 - 15 disables the transmitter, no error 3.

Its attributes table prints the range 0 - 15 (000:6300-6304), but the entry says what other
numbers do: any node number but the controller's own disables the RS485 transmitter, and 0
or a value above 15 does so too (000:6314-6320). Error 3 is a value outside the accepted range
(000:18518-18521); these are accepted. The keyword exists on MintDrive (000:6293-6296, 18229).
"""

from __future__ import annotations

import pytest

import mintlang


@pytest.mark.parametrize("node", ["0", "1", "15", "16", "99"])
def test_any_node_number_is_accepted(node: str) -> None:
    assert mintlang.check(f"ACTIVERS485NODE = {node}\n", controller="mintdrive") == []


def test_it_is_still_write_only() -> None:
    # the table ticks Write alone (000:6303-6304): reading it is error 2002 (000:18914-18917)
    source = "DIM station\nstation = ACTIVERS485NODE\n"
    [finding] = mintlang.check(source, controller="mintdrive")
    assert finding.code == "E2002"
