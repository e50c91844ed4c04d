"""The word after GOSUB or GOTO names a label and is kept as written, even when it spells an abbreviation.

A v3 label is ``#`` and up to ten alphanumeric characters, called by its name without the hash
(001:2426-2446); ``#ma`` and ``GOSUB ma`` are one label although MA abbreviates MOVEA (001:10121). M-ABBR
expands abbreviations word by word, and turned ``GOSUB ma`` into ``GOSUB movea``: a jump to a label the
file does not have, which X-COMMENTED then reported as the user's mistake. The label line itself was never
touched, so the jump must not be either.
"""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate


@pytest.mark.parametrize("word", ["ma", "SP", "de", "GN"])
def test_gosub_and_goto_keep_the_label_name(word: str) -> None:
    # the GOTO repeats the subroutine from inside it: one from the main program would reach its RETURN with
    # no GOSUB (error 2010, 000:18965-18967), which X-COMMENTED rightly reports
    source = f"GOSUB {word}\nEND\n#{word}\nIF IN1 THEN GOTO {word}\nRETURN\n"
    result = migrate(source, only=["M-ABBR", "X-COMMENTED"])
    assert (result.text, result.manual) == (source, ())


def test_the_rest_of_the_line_is_still_expanded() -> None:
    # MA = 5 after the jump's line, and SP before GOSUB on the same line, are keywords (MOVEA, SPEED)
    source = "SP = 2 : GOSUB ma\nMA = 5 : GO\nEND\n#ma\nRETURN\n"
    expected = "SPEED = 2 : GOSUB ma\nMOVEA = 5 : GO\nEND\n#ma\nRETURN\n"
    assert migrate(source, only=["M-ABBR"]).text == expected
