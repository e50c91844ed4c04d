"""An axis or channel number on a keyword whose formats take none is error 2003 "Syntax error".

TIME's formats are ``TIME = <expression>`` and ``v = TIME`` (000:16737-16738), with no dot and no
brackets; ERR's is ``v = ERR`` and BEEP's the bare word. The guide gives no error for ``TIME.5``: the dot
names an axis of an axis keyword or a channel of a channel keyword (000:677-680, 702-705), and its
chapter 12 list names no error for a keyword that takes neither. Error 2 is for an axis number the
controller does not have (000:18514-18517) and 2017 for more axes than the controller has
(000:19047-19052): both are about the controller, and axis 5 exists on a NextMove PCI. The closest is
2003 "Syntax error", a statement not written as its keyword's format allows (000:18920-18922): it is
what the tools already make of an addressing the format does not show for a channel keyword written
with brackets, ``v = ADC[1]``, which the guide calls invalid without a number (000:702-708). A syntax
error is the compiler's, so mint-run does not start the program either
(tests/runtime/test_an_axis_number_on_a_keyword_that_takes_none.py).
"""

from __future__ import annotations

import pytest

from tests.analysis.placed import placed


@pytest.mark.parametrize(
    ("line", "addressed"),
    [
        pytest.param("a = TIME.2", ".2", id="read-by-dot"),
        pytest.param("TIME.0 = 5", ".0", id="write-by-dot"),
        pytest.param("TIME[0] = 5", "[0]", id="write-by-brackets"),
        pytest.param("a = TIME.(a + 1)", ".(a + 1)", id="dot-expression"),
        pytest.param("a = ERR.1", ".1", id="read-only-keyword"),
        pytest.param("BEEP.1", ".1", id="command"),
        # a bit pattern is written whole, one bit per input (000:12389-12390, 12414-12416): no bit by dot
        pytest.param("INPUTNEGTRIGGER.1 = 1", ".1", id="bit-pattern"),
    ],
)
def test_the_number_is_a_syntax_error_where_it_is_written(line: str, addressed: str) -> None:
    assert placed(f"DIM a\n{line}\nPRINT a\n", "code", "line", "text", codes="E") == [("E2003", 2, addressed)]


def test_a_parameter_alone_with_a_number_is_also_given_no_value() -> None:
    # TIME.5 as a statement: the number is 2003, and a parameter alone is 2005 "No expression" (000:18930-18934)
    assert sorted(placed("TIME.5\n", "code", "line", "text", codes="E")) == [("E2003", 1, ".5"), ("E2005", 1, "TIME")]


@pytest.mark.parametrize("line", ["a = TIME", "TIME = 0", "a = INKEY.1", "a = POS.1", "a = ADC.1"])
def test_a_keyword_that_takes_its_number_or_none_is_not_flagged(line: str) -> None:
    # INKEY takes a terminal channel by dot (000:2044-2047), POS an axis, ADC a channel (000:705)
    assert placed(f"DIM a\n{line}\nPRINT a\n", "code", "line", "text", codes="E") == []
