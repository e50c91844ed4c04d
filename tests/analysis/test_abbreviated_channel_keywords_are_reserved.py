"""A v4 abbreviation stands for its keyword in every spelling, the glued channel included.

OUT is abbreviated OT (000:14879) and takes its channel glued on, ``OUTx`` (000:14896); so ``OT2``
is output 2, a keyword, and a variable cannot be given its name (000:882-883); DIM of a keyword is
a syntax error (000:9189-9192). Mint v3 abbreviated the bit keywords OUT0..OUT7 as O0..O7
(001:10602), so there ``OT2`` stays a user's name.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.placed import placed_codes


@pytest.mark.parametrize("name", ["OT2", "ot2", "Ot11"])
def test_declaring_an_abbreviated_output_is_a_syntax_error(name: str) -> None:
    assert placed_codes(f"DIM {name}\n") == [("E2003", 1, 5)]


def test_an_abbreviated_output_is_written_and_read_as_the_output() -> None:
    assert placed_codes("OT2 = 1\nPRINT OT2\n") == []


def test_an_abbreviated_output_past_the_controllers_outputs_is_error_8() -> None:
    # NextMove BX has the digital outputs OUT0 .. OUT7 (000:14943)
    codes = [d.code for d in mintlang.check("OT7 = 1\nOT8 = 1\n", controller="nextmove-bx")]
    assert codes == ["E0008"]


def test_in_mint_v3_the_name_stays_a_users_variable() -> None:
    assert placed_codes("OT2 = 1\nPRINT OT2\n", dialect="v3") == []
