"""The AXES default before an AXES that sits in a subroutine is not known from the text alone.

v3 keeps the default axis list AXES sets until the next AXES runs (001:1029-1033, 001:1052-1109), and
the guide's program layout calls ``#init`` first to set up what the program uses (001:873-901). An
``AXES[0,1]`` in a subroutine therefore holds for whatever runs after the GOSUB to it, including
lines written above the subroutine: in ``GOSUB init : CURRLIMIT = 50;`` the CURRLIMIT sets axes 0 and
1, not the three of the power-up default. A rewrite that names the axes (one DACLIMITMAX per channel,
000:8712) cannot take them from the text above such a subroutine: it is left for a person. Below the
AXES, as in the guide's ``#init`` then ``#main`` layout, the default is the one it sets.
"""

from __future__ import annotations

from tests.migrate.helpers import flagged, rewritten

PROGRAM = "GOSUB init\nCURRLIMIT = 50;\nGOSUB main\nEND\n#init\n  AXES[0,1]\nRETURN\n#main\n  CURRLIMIT = 80;\nRETURN\n"


def test_a_write_above_the_subroutine_is_left_for_a_person() -> None:
    assert flagged("S-CURR", "GOSUB init\nCURRLIMIT = 50;\nEND\n#init\n  AXES[0,1]\nRETURN\n") == [
        "DACLIMITMAX takes one channel per write and the axes here are not constant"
    ]


def test_a_write_below_it_takes_the_axes_it_sets() -> None:
    text = rewritten("S-CURR", PROGRAM)
    assert "  DACLIMITMAX.0 = 80 : DACLIMITMAX.1 = 80\n" in text
    assert "\nCURRLIMIT = 50;\n" in text  # above the subroutine: flagged, left as written


def test_an_axes_before_any_label_still_sets_the_default_for_what_follows() -> None:
    assert rewritten("S-CURR", "AXES[0,1]\nCURRLIMIT = 50;\nGOSUB x\nEND\n#x\nRETURN\n") == (
        "AXES[0,1]\nDACLIMITMAX.0 = 50 : DACLIMITMAX.1 = 50\nGOSUB x\nEND\n#x\nRETURN\n"
    )
