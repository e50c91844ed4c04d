"""Losslessness: every byte outside the edited spans survives (CRLF, tabs, cp1252, odd spacing
and case). Idempotence: migrating migrated text changes nothing."""

from __future__ import annotations

import re

import pytest
from hypothesis import given
from hypothesis import strategies as st

from mintlang.migrate import migrate
from mintlang.source import decode
from tests.migrate.golden import Case, cases

CASES = cases()


_INSERTED = re.compile(r"^\s*(REM MIGRATE:.*|DIM \w+|AXES\[0,1,2\]|INPUT(MODE|NEGTRIGGER) = .*)\r?\n?$")


def _without_inserted_lines(text: str) -> str:
    return "".join(line for line in text.splitlines(keepends=True) if not _INSERTED.match(line))


def test_crlf_tabs_and_odd_spacing_survive() -> None:
    source = "REM  Odd\tspacing\r\n\r\n\tGaIn  =  2;\t: rem  keep   me\r\n\tx=1 :REM x\r\n"
    result = migrate(source, controller="mintdrive")
    flag = "\tREM MIGRATE: X-UNITS: servo gains changed units and loop rate in v4: re-tune\r\n"  # indented as its line
    assert (
        result.text == f"REM  Odd\tspacing\r\nDIM x\r\n\r\n{flag}\tKPROP  =  2;\t: rem  keep   me\r\n\tx=1 :REM x\r\n"
    )
    assert "\n" not in result.text.replace("\r\n", "")


def test_cp1252_bytes_survive_a_rewrite() -> None:
    data = "REM Geschwindigkeit für Achse – “schnell”\r\nHMSPEED = 10 : REM größer\r\n".encode("cp1252")
    text, encoding = decode(data)
    assert encoding == "cp1252"
    migrated = migrate(text, controller="mintdrive").text.encode(encoding)
    assert migrated == data.replace(b"HMSPEED", b"HOMESPEED")


def test_breaking_the_auto_line_changes_only_its_separator() -> None:
    """A flag for a statement after AUTO breaks the line after AUTO (nothing may go above it,
    v4:6647-6649): without the marker, the text is the original with that `` : `` a line end."""
    config = "AUTO : ERRORIN = 1 : REM  keep\tme\r\n\tx=1 :REM x\r\n"
    result = migrate("", config=config, only=["S-ERRORIN"]).configuration
    assert result is not None
    assert _without_inserted_lines(result.text) == config.replace(" : ", "\r\n", 1)
    assert [(change.line, change.original) for change in result.changes] == [(1, " : ")]


def test_untouched_lines_are_byte_identical_in_the_corpus() -> None:
    for case in CASES:
        result = case.migrate()
        changed_lines = {change.line for change in result.changes}
        original = result.source.splitlines(keepends=True)
        kept = [line for number, line in enumerate(original, start=1) if number not in changed_lines]
        output = _without_inserted_lines(result.text).splitlines(keepends=True)
        assert all(line in output for line in kept), case.name


@pytest.mark.parametrize("case", CASES, ids=lambda case: case.name)
def test_migrating_twice_changes_nothing(case: Case) -> None:
    first = case.migrate()
    config = first.configuration.text if first.configuration is not None else None
    second = migrate(first.text, config=config)
    assert second.text == first.text
    assert second.changes == ()
    if first.configuration is not None:
        assert second.configuration is not None and second.configuration.text == config
    assert [(item.rule, item.line) for item in second.manual] == [(item.rule, item.line) for item in first.manual]


_WORDS = st.sampled_from(
    ["a", "Node", "GAIN", "ma", "SIN(30)", "~b", "ERROR.0", "_limit", "MOVEA", "1", "2.5", "'x'", '"s"']
)
_LINES = st.lists(
    st.builds(
        lambda target, op, value, pad, comment: f"{pad}{target}{op}{value}{comment}",
        st.sampled_from(["a", "x", "SPEED", "SCALE", "ACCEL", "HMSPEED", "OUT1", "IF a THEN b", "PAUSE"]),
        st.sampled_from([" = ", "=", "  =\t"]),
        _WORDS,
        st.sampled_from(["", " ", "\t", "   "]),
        st.sampled_from(["", " : REM c", "\tREM x"]),
    ),
    max_size=8,
)


@given(lines=_LINES, newline=st.sampled_from(["\n", "\r\n"]))
def test_random_programs_migrate_idempotently_and_keep_their_newlines(lines: list[str], newline: str) -> None:
    source = newline.join(lines) + newline
    first = migrate(source)
    assert migrate(first.text).text == first.text
    if newline == "\r\n":
        assert "\n" not in first.text.replace("\r\n", "")
