"""The move buffer note names the inter-vector angle ``CONTOURPARAMETER.axis.0`` (004:223), v4's dot form with
the index after the axis, as its listing writes ``CONTOURPARAMETER([0,1],0)`` (004:232). MintMT reads v4's dot
forms as the notes write them (MT-4): the dot form is the same write, checked and run alike."""

from __future__ import annotations

from mintlang.runtime.run import run_source
from tests.analysis.placed import placed_codes


def test_the_dot_form_is_clean() -> None:
    assert placed_codes("CONTOURPARAMETER.1.0 = 10\nMOVEOUT.0.0 = 7\nMOVEOUTX.0.1 = 0\n", "mintmt") == []


def test_it_writes_the_axis_angle_as_the_bracket_form_does() -> None:
    source = 'CONTOURPARAMETER.1.0 = 10\nCONTOURPARAMETER(0,0) = 20\nPrint CONTOURANGLE(0), " ", CONTOURANGLE(1)\n'
    assert run_source(source, dialect="mintmt").terminal == "20 10\n"


def test_its_value_is_held_to_the_angles_range() -> None:
    # index 0 is v4's CONTOURANGLE, 0 to 180 (MT-11)
    source = "CONTOURPARAMETER.1.0 = 200\n"
    assert placed_codes(source, "mintmt") == [("E0003", 1, 24)]
    assert run_source(source, dialect="mintmt").err == 3


def test_without_the_index_it_is_still_a_missing_parameter() -> None:
    assert placed_codes("CONTOURPARAMETER.1 = 10\n", "mintmt") == [("E2001", 1, 17)]
