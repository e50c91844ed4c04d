"""A Mint v3 or misspelt keyword in a macro's text: error 3007 points at the macro's use, where the controller
meets it, but the replacement belongs in the macro's text. Writing the keyword in place of the macro's name
would drop the rest of the text (``.0``, ``= 5``): the controller puts the whole text where the name is
written (000:1456-1458)."""

from __future__ import annotations

import pytest

from tests.analysis.checking import apply, covered, only


@pytest.mark.parametrize(
    ("source", "use", "said"),
    [
        pytest.param("DIM a\nDEFINE q = HMSPEED.0\na = q\nPRINT a\n", "q", "replaced by HOMESPEED in v4", id="v3-read"),
        pytest.param("DEFINE s = HMSPEED.0 = 5\ns\n", "s", "replaced by HOMESPEED in v4", id="v3-statement"),
        pytest.param("DIM a\nDEFINE q = SPEEDD.0\na = q\nPRINT a\n", "q", "did you mean 'SPEED'?", id="misspelt-read"),
        pytest.param("DEFINE s = SPEEDD.0 = 5\ns\n", "s", "did you mean 'SPEED'?", id="misspelt-statement"),
        pytest.param("DEFINE g = GOO\ng\n", "g", "did you mean", id="misspelt-command"),
    ],
)
def test_a_keyword_from_a_macros_text_gets_no_replacement_at_the_use(source, use, said) -> None:
    diagnostic = only(source, "E3007")
    assert covered(source, diagnostic) == use
    assert said in diagnostic.message
    assert diagnostic.fixes == ()


@pytest.mark.parametrize(
    ("source", "fixed"),
    [
        pytest.param("DEFINE ax = 0\nHMSPEED.ax = 5\n", "DEFINE ax = 0\nHOMESPEED.ax = 5\n", id="v3"),  # HMSPEED entry
        pytest.param("DEFINE ax = 0\nSPEEDD.ax = 5\n", "DEFINE ax = 0\nSPEED.ax = 5\n", id="misspelt"),
    ],
)
def test_the_same_keyword_written_in_the_line_is_still_replaced(source, fixed) -> None:
    (fix,) = only(source, "E3007").fixes
    assert apply(source, fix.edits) == fixed
