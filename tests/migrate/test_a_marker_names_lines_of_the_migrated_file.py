"""X-CHECK: a checker message that names another line names it as the migrated file numbers it.

The AXES list a write is counted against is named by its line (E2017, 000:19047). The message is worked
out on the text before X-CHECK's own markers go in, so each marker above that line moved it down one:
below, the second AXES[0,1] is line 4 of the migrated file, and the marker said line 3.
"""

from __future__ import annotations

from mintlang.migrate import migrate


def test_the_axes_line_a_marker_names_is_the_migrated_files() -> None:
    result = migrate("AXES[0,1]\nSCALE = 1,2,3\nAXES[0,1]\nSCALE = 4,5,6\n")
    lines = result.text.splitlines()
    named = [item.reason.rsplit("(the AXES list of line ", 1)[1].rstrip(")") for item in result.manual]
    assert named == ["1", "4"]
    assert [lines[int(number) - 1] for number in named] == ["AXES[0,1]", "AXES[0,1]"]
