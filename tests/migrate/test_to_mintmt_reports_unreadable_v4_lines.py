"""``--to mintmt`` reports the lines of the Mint v4 input that Mint v4 cannot read, as the v3 → v4
migration reports the v3 lines it cannot read: the MintMT rewrites read tokens, so a broken line
would otherwise pass through unremarked, and the report said "0 unreadable lines"."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from mintlang.migrate.cli import migrate
from mintlang.migrate.mintmt.api import to_mintmt


def test_a_line_mint_v4_cannot_read_is_an_error_of_the_migration() -> None:
    # a missing ")" is a syntax error, 2003 (000:18920-18924)
    result = to_mintmt("DIM a\na = (1\nPRINT a\n")
    assert result.errors == ("line 2: E2003 Syntax error: a ')' is missing",)


def test_a_program_reading_as_v4_has_none() -> None:
    assert to_mintmt("DIM a\na = (1 + 2) * 3\nPRINT a\n").errors == ()


def test_a_macro_of_the_configuration_file_is_read_as_the_program_reads_it() -> None:
    # a macro's text takes its place where its name is found (000:1451-1458): "a = 10 half" is "a = 10 / 2",
    # and unreadable only to a reader that does not know the configuration file's macro
    result = to_mintmt("DIM a\na = 10 half\n", config="DEFINE half = / 2\n")
    assert (result.errors, result.configuration.errors if result.configuration else None) == ((), ())
    assert to_mintmt("DIM a\na = 10 half\n").errors == ("line 2: E2003 Syntax error: unexpected 'half'",)


def test_the_report_names_the_v4_reader(tmp_path: Path) -> None:
    path = tmp_path / "broken.mnt"
    path.write_text("DIM a\na = (1\n")
    result = CliRunner().invoke(migrate, ["--to", "mintmt", str(path)])
    assert f"{path}: unreadable v4 line 2: E2003 Syntax error: a ')' is missing" in result.output
    assert result.output.rstrip().endswith("0 changes, 0 manual items, 1 unreadable line")
