"""S-IN: with ``#INn`` handlers, a masked read of IN is a manual item as an unmasked one is.

v3 IN gave the present state of inputs 0..7 (001:8927-8947). S-INEDGE makes each handler's input
edge triggered, as v3 called ``#INn`` once per edge (001:2525); for such an input v4 IN gives the latched
edge, not the state, and reading IN clears the latch (000:11976-11978). ``IN & 15`` beside ``#IN3`` reads
bit 3 that way just as ``IN`` does: the mask keeps the other inputs out of the value, not the latch.
"""

from __future__ import annotations

import pytest

from tests.migrate.helpers import flagged

LATCH = "IN reads all inputs and clears edge latches of #INn inputs in v4: mask with & 255"


@pytest.mark.parametrize("read", ["b = IN & 15", "PAUSE IN AND 12", "IF IN & 8 THEN x = 1"])
def test_a_masked_read_is_flagged_beside_a_handler(read: str) -> None:
    assert flagged("S-IN", f"{read}\nEND\n#IN3\nRETURN\n") == [LATCH]


def test_without_handlers_a_masked_read_is_kept() -> None:
    assert flagged("S-IN", "b = IN & 15\n") == []
