"""``RELEASE`` in a configuration file clears the user variables before the program runs (000:932-939).

Variables are compiled with the application and RELEASE clears them when it runs (001:11328):
each reads 0 again until set. Mint v4's RELEASE clears the arrays too (000:5541-5543), back to
what their DIM gives them; Mint v3's leaves the array values (001:11326).
"""

from __future__ import annotations

from mintlang.runtime.interpreter.vm import StopReason
from mintlang.runtime.run import run_source
from mintlang.runtime.simulation import Limits
from tests.runtime.running import simulate

LIMITS = Limits(until_ms=1_000, max_wall_s=30.0)


def test_release_then_enabling_the_drives_runs_the_program() -> None:
    result = simulate('PRINT "hi"\n', config="RELEASE\nDRIVEENABLE[0,1] = 1;\n")
    assert result.stop.reason is StopReason.END
    assert result.terminal == "hi\n"


def test_release_clears_the_variables_the_configuration_set() -> None:
    config = "DIM a = 5\nPRINT a\nRELEASE\nPRINT a\n"
    assert simulate("PRINT a\n", config=config).terminal == "5\n0\n0\n"


def test_the_program_sets_its_own_variables_after_a_release() -> None:
    assert simulate("DIM b = 7\nPRINT b\n", config="RELEASE\n").terminal == "7\n"


def test_in_mint_v4_release_puts_the_arrays_back_as_their_dim_gives_them() -> None:
    config = "DIM t(3) = 1, 2, 3\nt(1) = 9\nPRINT t(1)\nRELEASE\n"
    assert simulate("PRINT t(1)\nPRINT t(2)\n", config=config).terminal == "9\n1\n2\n"


def test_in_mint_v3_release_leaves_the_array_values() -> None:
    config = "a = 5\nDIM t(3) = 1, 2, 3\nt(1) = 9\nRELEASE\n"  # v3 declares a scalar by assigning it
    result = run_source("PRINT a\nPRINT t(1)\nPRINT t(2)\n", config=config, dialect="v3", limits=LIMITS)
    assert result.stop.reason is StopReason.END
    assert result.terminal == "0\n9\n2\n"


def test_release_in_a_program_is_still_refused_as_an_editor_command() -> None:
    result = simulate("DIM a\nRELEASE\n")
    assert (result.stop.reason, result.err, result.erl) == (StopReason.ERROR, 2006, 2)


def test_release_in_a_mint_v3_program_is_not_simulated() -> None:
    result = run_source("a = 1\nRELEASE\n", dialect="v3", limits=LIMITS)  # 001:11328: not within a program
    assert (result.stop.reason, result.stop.line) == (StopReason.ERROR, 2)
    assert "RELEASE (in a program) is not simulated" in result.stop.message
