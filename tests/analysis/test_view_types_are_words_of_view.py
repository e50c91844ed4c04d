"""VIEW's operand names what to display, not a variable or a keyword.

The VIEW entry writes the command ``VIEW <type>`` (000:17184) and lists its types: ARRAY, CANBUSSTATE
with a bus as its dot parameter, CONFIG, HARDWARE, MACROS, PLATFORM, VAR ... (000:17190-17305); the
guide's own uses are ``VIEW VAR`` (000:950), ``VIEW ARRAY`` (000:1133) and ``VIEW CANBUSSTATE.2``
(000:17201). None of those words is a variable to declare (3001) or a misspelt keyword (3007), wherever
VIEW itself may stand.
"""

from __future__ import annotations

import pytest

import mintlang


@pytest.mark.parametrize("kind", ["VAR", "ARRAY", "MACROS", "HARDWARE", "PLATFORM", "CONFIG", "CANBUSSTATE.2"])
def test_the_type_after_view_is_not_a_name(kind: str) -> None:
    start = len("VIEW ")
    on_the_type = [d.code for d in mintlang.check(f"VIEW {kind}\nEND\n") if d.span.end > start]
    assert on_the_type == []
