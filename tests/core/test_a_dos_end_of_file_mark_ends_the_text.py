"""A run of Ctrl-Z (0x1A) ending a file is the end-of-file mark DOS editors wrote (the v3 guide has array
files end with one, 001:1799), not characters of the program: every tool reads the text before it, as
the migrator keeps it (tests/migrate/test_a_dos_end_of_file_mark_is_kept.py). A Ctrl-Z anywhere else is
a stray character, error 2003 as before."""

from __future__ import annotations

import pytest

import mintlang
from mintlang.runtime.run import run_source

DIALECTS = ["v4", "v3", "mintmt"]


def _codes(source: str, dialect: str) -> list[str]:
    return [diagnostic.code for diagnostic in mintlang.check(source, dialect=dialect)]


@pytest.mark.parametrize("dialect", DIALECTS)
@pytest.mark.parametrize("source", ["PRINT 1\r\n\x1a", "PRINT 1\n\x1a\x1a", "PRINT 1\x1a"])
def test_a_mark_ending_the_file_is_not_an_error(source: str, dialect: str) -> None:
    assert _codes(source, dialect) == []


@pytest.mark.parametrize("dialect", DIALECTS)
@pytest.mark.parametrize("source", ["PRINT 1\x1a\r\nPRINT 2\r\n", "\x1a\nPRINT 1\n", "PRINT \x1a 1"])
def test_a_ctrl_z_before_the_end_is_a_stray_character(source: str, dialect: str) -> None:
    assert _codes(source, dialect) == ["E2003"]


def test_the_mark_stays_in_the_tokens() -> None:
    """Read past, not dropped: the tokens still join back to the text, so a fix keeps the mark."""
    source = "PRINT 1\r\n\x1a"
    assert "".join(token.text for token in mintlang.parse(source).tokens) == source


def test_a_program_ending_with_the_mark_runs_to_its_end() -> None:
    result = run_source("PRINT 1\r\nPRINT 2\r\n\x1a")
    assert result.terminal == "1\n2\n"
    assert not result.refused
