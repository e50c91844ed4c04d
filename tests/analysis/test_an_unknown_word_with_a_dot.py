"""A word that is no keyword, written with a dot (``x = ANALOGIN.3``), is error 3007 told of channels, not arrays.

A dot after a keyword names its axis or channel: ``v = ADC.1`` reads analog input channel 1 (000:701-705).
``ANALOGIN.3`` is that form for channel 3 of a keyword that does not exist, so the message says the dot
addresses nothing and shows the keyword form; an array's round brackets are no part of what was meant.
Square brackets (``arr[2]``) keep the array hint: test_an_array_indexed_in_square_brackets.
"""

from __future__ import annotations

import pytest

import mintlang


@pytest.mark.parametrize(
    ("source", "word"),
    [
        pytest.param("DIM x\nx = ANALOGIN.3\n", "ANALOGIN", id="channel-3"),
        pytest.param("DIM x\nx = ANALOGIN.(1 + 2)\n", "ANALOGIN", id="channel-as-an-expression"),
        pytest.param("DIM arr(5)\nPRINT arr.2\n", "arr", id="an-array-written-with-a-dot"),
    ],
)
def test_the_message_names_the_dot_form_and_no_array(source: str, word: str) -> None:
    (error,) = [d for d in mintlang.check(source) if d.code == "E3007"]
    assert f"'{word}' is not a keyword, so its dot addresses no channel or axis" in error.message
    assert "ADC.1" in error.message
    assert "array" not in error.message and "round brackets" not in error.message
    assert error.fixes == ()


def test_a_misspelt_keyword_with_a_dot_is_still_offered_the_keyword() -> None:
    (error,) = [d for d in mintlang.check("DIM x\nx = ADCC.3\n") if d.code == "E3007"]
    assert error.message.endswith("'ADCC' is not a keyword (did you mean 'ADC'?)")
