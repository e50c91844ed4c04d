"""A v3 program with an array named like a v4 keyword (``DIM adc(4)``) is migrated, not taken for MintMT.

``adc`` is no v3 keyword, so ``DIM adc(4) = 1,2,3,4`` declares an array (001:7303-7353) whose elements are read
as ``adc(2)`` (001:1539). Dialect detection took ``adc(`` for MintMT's round-bracket addressing of the ADC
channel, and mint-migrate left the whole application unmigrated as "already mintmt", exit 0, so ``--check``
passed on Mint v3. A name the text declares as an array is no keyword in any dialect; v4 reserves the name
(000:18940-18943), so M-IDENT renames it.
"""

from __future__ import annotations

from mintlang.detection import detect_dialect
from mintlang.dialect import Dialect
from mintlang.migrate import migrate

SOURCE = "DIM adc(4) = 1,2,3,4\nSP = 10\nMA = adc(2) : GO\n? adc(3)\n"


def test_the_program_reads_as_v4_not_mintmt() -> None:
    assert detect_dialect(SOURCE) is Dialect.V4


def test_the_program_is_migrated_and_its_array_renamed() -> None:
    result = migrate(SOURCE)
    assert not result.already_mintmt
    assert "DIM adc_u(4) = 1,2,3,4\n" in result.text
    assert "MOVEA = adc_u(2) : GO\n? adc_u(3)\n" in result.text
