"""A line of a guide's text extraction, as the section a reader of the printed guide looks up.

Read in the guides: v4:3027 is the heading "6.7 AXISMODE and IDLE" and "6.8 Controlled
Motion" follows at v4:3051; "10.3 Mint Keywords" holds ACCEL's entry from v4:6143; the v3
guide's keyword chapter is "10. MINT Keywords" (v3:5368) with ACCEL's entry at v3:5635.
"""

from __future__ import annotations

from mintlang.manual.places import Place, place


def test_a_line_is_in_the_section_whose_heading_comes_last_before_it() -> None:
    assert place("v4", 3046) == Place("v4", "6.7", "AXISMODE and IDLE", "")
    assert place("v4", 3051).number == "6.8"


def test_a_line_of_a_keyword_chapter_names_the_entry_too() -> None:
    accel = place("v4", 6178)
    assert accel == Place("v4", "10.3", "Mint Keywords", "ACCEL")
    assert accel.full == "Mint v4 guide §10.3 Mint Keywords, ACCEL"
    assert accel.short == "§10.3 ACCEL"
    assert place("v3", 5662).full == "Mint v3 guide §10 MINT Keywords, ACCEL"


def test_a_line_before_chapter_1_is_the_guide_alone() -> None:
    before = place("v4", 10)
    assert (before.short, before.full) == ("", "Mint v4 guide")
