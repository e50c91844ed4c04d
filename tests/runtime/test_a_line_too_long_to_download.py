"""A line longer than the controller takes: a v4 program would not download, a v3 one would not compile.

The v4 controller takes 255 characters a line, comments included, and a program with a longer line does not
download (000:254-256, 000:18454-18456); no error number is given. mint check warns (W111); mint-run runs
the line as written and notes it on stderr and in the JSON report, as it notes what it reads leniently.
A Mint v3 controller's compiler stops on a line past 127 characters with "Line too long" (001:12999-13001),
so a v3 run stops there as on any other compile error.
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


def test_a_mint_v3_line_past_127_characters_stops_compiling_as_the_v3_guide_says() -> None:
    # Mint v3 takes 127 characters and its compiler stops on a longer line with "Line too long" (001:12999-13001),
    # an error of chapter 11 as "Undefined Variables" is: nothing of the program runs, not the line before it
    result = run_source(f"PRINT 0\na = 1{' ' * 120}: PRINT a\n", dialect="v3")  # 5 + 120 + 9 = 134
    assert result.refused
    assert result.terminal == "ERROR: Program: Line too long at line 2\n"
    assert result.read_leniently == ()


def test_a_mint_v3_line_of_127_characters_runs() -> None:
    assert run_source(f"a = 1{' ' * 113}: PRINT a\n", dialect="v3").terminal == "1\n"  # 5 + 113 + 9 = 127


def test_a_mint_v3_configuration_line_past_127_characters_stops_compiling_it() -> None:
    # the configuration file is compiled first (001:12999-13001 names both files); the guide's word for it is Config
    result = run_source("PRINT 2\n", config=f"a = 1{' ' * 120}: PRINT a\n", dialect="v3")
    assert result.terminal == "ERROR: Config: Line too long at line 1\n"
