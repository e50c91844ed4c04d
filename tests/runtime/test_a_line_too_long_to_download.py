"""A line longer than the controller takes: the program would not download, the simulator runs it and says so.

The controller takes 255 characters a line, comments included, and a program with a longer line does not
download (000:254-256, 000:18454-18456); no error number is given. mint check warns (W111); mint-run runs
the line as written and notes it on stderr and in the JSON report, as it notes what it reads leniently.
"""

from __future__ import annotations

from mintlang.runtime.run import run_source
from tests.runtime.running import simulate

# "a = 1" (5 characters), 250 blanks and ": PRINT a" (9): 264 characters
LONG = f"DIM a\na = 1{' ' * 250}: PRINT a\nPRINT 2\n"


def test_the_line_runs_and_is_noted_with_its_length() -> None:
    result = simulate(LONG)
    assert result.terminal == "1\n2\n"
    assert result.read_leniently == (
        "program line 2: line has 264 characters; the controller accepts 255, and would not download the program"
        " (000:18454-18456); run here as written",
    )


def test_a_line_of_255_characters_is_not_noted() -> None:
    assert simulate(f"DIM a\na = 1{' ' * 241}: PRINT a\n").read_leniently == ()  # 5 + 241 + 9 = 255


def test_a_mint_v3_line_past_127_characters_is_noted_as_the_v3_guide_says() -> None:
    # Mint v3 takes 127 characters and stops compiling a longer line with "Line too long" (001:12999-13001):
    # the v4 guide's download of 255 characters is not what a v3 controller does
    result = run_source(f"a = 1{' ' * 120}: PRINT a\n", dialect="v3")  # 5 + 120 + 9 = 134
    assert result.terminal == "1\n"
    assert result.read_leniently == (
        "program line 1: line has 134 characters; the controller accepts 127, and would stop compiling with"
        ' "Line too long" (001:12999-13001); run here as written',
    )
