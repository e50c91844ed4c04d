"""A keyword the guide gives ServoNode 51 has a ServoNode 51 row, though its table prints none.

WAIT ticks all five controllers (000:17319-17321) and its table prints a NextMove and a MintDrive
row, both write only (000:17332-17333), so WAIT is write only on ServoNode 51 too; its ranges
differ (2 ≤ x ≤ 16777215 and 0 ≤ x ≤ 65535), so ServoNode 51's is not known. SCALE's defaults,
1.0 and 1, are one number (000:15783-15784); TIMEREVENT's, 0 and 10000, are not (000:16786-16787),
but its text gives MintDrive and ServoNode 51 the minimum of 40 ms (000:16807) and both rows the
maximum of 8,000,000. IMASK's range follows the inputs, 18 on MintDrive and 6 on ServoNode 51
(000:11900, 11931-11932). AUXDAC's one row, MintDrive's, gives a value in ±10 V where 100 is +10 V
(000:6680, 6686), the same on the two MME controllers.
"""

from __future__ import annotations

from dataclasses import replace

import pytest

from mintlang.keyworddb import database
from mintlang.keyworddb.model import Attributes, Controller
from tools.keyworddb.servonode import with_servonode_rows

_SN51 = Controller.SERVONODE51


def _row(name: str) -> Attributes:
    row = database().keywords[name].attributes_for(_SN51)
    assert row is not None
    return row


def test_every_keyword_servonode_has_and_a_table_describes_has_its_row_but_one_read_two_ways() -> None:
    # AUXENCODERWRAP's rows tick Scaled on MintDrive only (000:6847-6848): which ServoNode 51 follows is unknown
    missing = [
        name
        for name, keyword in database().keywords.items()
        if keyword.attributes and _SN51 in keyword.controllers and keyword.attributes_for(_SN51) is None
    ]
    assert missing == ["AUXENCODERWRAP"]


def test_wait_is_write_only_with_no_known_range() -> None:
    row = _row("WAIT")
    assert (row.read, row.write, row.command, row.default, row.range) == (False, True, False, None, None)


def test_a_default_printed_as_1_0_and_1_is_taken() -> None:
    row = _row("SCALE")
    assert (row.read, row.write, row.default, row.range) == (True, True, "1", None)


def test_timerevent_takes_the_minimum_its_text_gives_servonode_but_no_default() -> None:
    row = _row("TIMEREVENT")
    assert row.range is not None and (row.range.minimum, row.range.maximum) == (40.0, 8_000_000.0)
    assert row.default is None


def test_a_range_that_follows_the_inputs_stays_unknown() -> None:
    row = _row("IMASK")
    assert (row.read, row.write, row.default, row.range) == (True, True, None, None)


@pytest.mark.parametrize(("name", "default"), [("ERRORINPUT", "-1"), ("STOPINPUT", "-1"), ("FOLERRORFATAL", "1000")])
def test_a_default_every_row_prints_is_servonodes_too(name: str, default: str) -> None:
    # 000:10041-10045, 16431-16435, 10667-10668
    assert _row(name).default == default


def test_a_mintdrive_only_table_in_percent_is_shared_with_servonode() -> None:
    row = _row("AUXDAC")
    assert row.controllers == (Controller.MINTDRIVE, _SN51)
    assert row.range is not None and (row.range.minimum, row.range.maximum, row.default) == (-100.0, 100.0, "0")


def test_rows_that_disagree_on_access_give_no_servonode_row() -> None:
    wait = database().keywords["WAIT"]
    printed = tuple(row for row in wait.attributes if _SN51 not in row.controllers)
    readable = tuple(replace(row, read=True) if Controller.MINTDRIVE in row.controllers else row for row in printed)
    derived = with_servonode_rows({"WAIT": replace(wait, attributes=readable)})["WAIT"]
    assert derived.attributes_for(_SN51) is None
