"""A marker stays directly above the line it flags when the same pass inserts lines at that line.

M-DIM flags an array that is never dimensioned and, in the same pass, inserts ``DIM name`` for the
implicit variables at the top of the file: when the flagged line is the first line of code, both go
at one place. The inserted lines belong above the marker, which belongs to the line below it
(spec §5 puts declarations at the top; a ``REM MIGRATE:`` line annotates the next line); with the
marker above the ``DIM``, the next pass found the line unmarked and flagged it again.
"""

from __future__ import annotations

from mintlang.migrate import MigrationResult, migrate

_ARRAY = "REM MIGRATE: M-DIM: array '{}' is used but never dimensioned"


def _items(result: MigrationResult) -> list[tuple[str, int, int | None]]:
    return [(item.rule, item.line, item.original_line) for item in result.manual]


def test_an_undimensioned_array_on_the_first_line_gets_one_marker_below_the_inserted_dim() -> None:
    result = migrate("PRINT foo(1)\nPRINT b\n", only=["M-DIM"])
    assert result.text == f"DIM b\n{_ARRAY.format('foo')}\nPRINT foo(1)\nPRINT b\n"
    assert _items(result) == [("M-DIM", 3, 1)]


def test_after_a_header_comment_the_dim_and_the_marker_go_below_it_in_that_order() -> None:
    source = "REM header\r\nPRINT foo(1)\r\nPRINT b\r\n"
    result = migrate(source, only=["M-DIM"])
    assert result.text == f"REM header\r\nDIM b\r\n{_ARRAY.format('foo')}\r\nPRINT foo(1)\r\nPRINT b\r\n"


def test_a_v4_keyword_used_as_a_v3_array_is_flagged_once_under_its_new_name() -> None:
    # SQRT is no v3 keyword, so SQRT(...) is an array there; M-IDENT renames it, as SQRT is a v4 keyword
    source = "PRINT SQRT(4.4)\nPRINT SQRT(INT(a))\n"
    result = migrate(source, only=["M-IDENT", "M-DIM"])
    expected = f"DIM a\n{_ARRAY.format('SQRT_u')}\nPRINT SQRT_u(4.4)\nPRINT SQRT_u(INT(a))\n"
    assert result.text == expected
    # every rule: the two X-NUM markers join the lines they flag; M-DIM's is still there once
    assert _items(migrate(source)) == [("M-DIM", 4, 1), ("X-NUM", 4, 1), ("X-NUM", 6, 2)]


def test_migrating_the_result_again_changes_nothing() -> None:
    for source in ("PRINT SQRT(4.4)\nPRINT SQRT(INT(a))\n", "REM header\nPRINT foo(1)\nPRINT b\n"):
        once = migrate(source).text
        assert migrate(once).text == once
