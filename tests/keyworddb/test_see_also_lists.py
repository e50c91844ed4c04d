"""An entry's See-also list names keywords, one item a name, as the guide prints it at the entry's end.

``000:N`` is line N of the Mint v4 guide.
"""

from __future__ import annotations

import re

import pytest

from mintlang.keyworddb import database

_NAME = re.compile(r"[#A-Z][A-Z0-9]*x?|~")  # ~, the bitwise NOT (000:5694)
_ITEM = re.compile(rf"(?:{_NAME.pattern})(?: ?\.\. ?(?:{_NAME.pattern}))?")  # ERL, #IN0 .. #INx, FOR..NEXT


def test_a_name_that_ends_a_printed_line_is_a_name_of_its_own() -> None:
    # 000:6731-6733: "... FASTAUXENCODER" ends one line, "MASTERSOURCE, POS" starts the next
    assert database().keywords["AUXENCODER"].see_also == (
        "AUXENCODERSCALE",
        "AUXENCODERVEL",
        "AUXENCODERWRAP",
        "FASTAUXENCODER",
        "MASTERSOURCE",
        "POS",
    )


def test_the_footnote_printed_below_a_list_is_not_in_it() -> None:
    # 000:5954-5959: #IN's list ends with RETURN; footnote 8 (NextMove PCI's expansion cards) follows the rule
    assert database().keywords["#IN"].see_also[-3:] == ("IN", "IN0..INx", "RETURN")


@pytest.mark.parametrize("name", sorted(database().keywords))
def test_every_item_is_a_keyword_name(name: str) -> None:
    for item in database().keywords[name].see_also:
        assert _ITEM.fullmatch(item), f"{name}: {item!r}"
