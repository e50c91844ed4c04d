"""S-CARD: reading CARD becomes NODE, except while a user variable is called NODE."""

from __future__ import annotations

from mintlang.migrate import migrate
from tests.migrate.helpers import flagged, rewritten


def test_card_reads_become_node() -> None:
    assert rewritten("S-CARD", "v = CARD\nIF cd = 3 THEN PRINT card\n", controller="mintdrive") == (
        "v = NODE\nIF node = 3 THEN PRINT node\n"
    )


def test_a_user_variable_named_node_is_renamed_first_and_card_then_becomes_node() -> None:
    result = migrate("node = 2\nv = CARD + node\n", only=["M-IDENT", "S-CARD"])
    assert result.text == "node_u = 2\nv = NODE + node_u\n"
    assert migrate(result.text, only=["M-IDENT", "S-CARD"]).text == result.text


def test_card_is_refused_while_the_user_variable_node_is_still_there() -> None:
    assert flagged("S-CARD", "node = 2\nv = CARD\n") == [
        "CARD is NODE in v4, which this program uses as a variable name"
    ]


def test_node_written_by_the_rule_is_not_a_user_name_on_a_second_run() -> None:
    first = migrate("v = CARD\n")
    second = migrate(first.text)
    assert "v = NODE" in first.text and second.text == first.text and second.changes == ()


def test_untouched_bytes_survive() -> None:
    source = "REM\tcard   test\r\n  v=CARD :rem  keep\r\n"
    assert rewritten("S-CARD", source) == "REM\tcard   test\r\n  v=NODE :rem  keep\r\n"
