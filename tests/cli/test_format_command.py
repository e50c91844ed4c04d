"""``mint format``: the house style written into the files, as ``ruff format`` writes Python's.

The style is the formatter's (``mintlang/formatting.py``): keywords in upper case, a level of indentation per
enclosing block with ELSE beside its IF, a label at the margin with its subroutine's body under it, no blanks at
a line's end; nothing else changes, line ends included. ``--check`` and ``--diff`` write nothing and exit 1 when
a file would change.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from mintlang.cli import main
from mintlang.formatting import project_indent_unit
from tests.cli.invoking import write

MESSY = "dim a\nif a > 1 do\nprint a   \n  else\n      a = 2\nendif\nEND\n  #sub\n    return\n"
FORMATTED = "DIM a\nIF a > 1 DO\n  PRINT a\nELSE\n  a = 2\nENDIF\nEND\n#sub\nRETURN\n"


def mint_format(*arguments: str | Path) -> Result:
    return CliRunner().invoke(main, ["format", *(str(argument) for argument in arguments)])


def test_a_program_is_written_in_the_house_style(tmp_path: Path) -> None:
    path = write(tmp_path / "cell.mnt", MESSY)
    result = mint_format(tmp_path)
    assert (result.exit_code, path.read_text(encoding="utf-8")) == (0, FORMATTED)
    assert result.stdout == "1 file reformatted, 0 files left unchanged\n"
    assert mint_format(tmp_path).stdout == "0 files reformatted, 1 file left unchanged\n"


def test_check_names_what_would_change_and_writes_nothing(tmp_path: Path) -> None:
    messy, tidy = write(tmp_path / "a.mnt", MESSY), write(tmp_path / "b.mnt", FORMATTED)
    result = mint_format("--check", tmp_path)
    assert result.exit_code == 1
    assert result.stdout == f"Would reformat: {messy}\n1 file would be reformatted, 1 file already formatted\n"
    assert messy.read_text(encoding="utf-8") == MESSY
    assert mint_format("--check", tidy).exit_code == 0


def test_diff_shows_the_change_and_writes_nothing(tmp_path: Path) -> None:
    path = write(tmp_path / "cell.mnt", "if 1 do\nprint 2\nendif\n")
    result = mint_format("--diff", path)
    assert result.exit_code == 1
    hunk = "@@ -1,3 +1,3 @@\n-if 1 do\n-print 2\n-endif\n+IF 1 DO\n+  PRINT 2\n+ENDIF\n"
    assert result.stdout == f"--- {path}\n+++ {path}\n{hunk}"
    assert path.read_text(encoding="utf-8") == "if 1 do\nprint 2\nendif\n"


def test_the_indentation_is_a_tab_or_so_many_spaces(tmp_path: Path) -> None:
    path = write(tmp_path / "cell.mnt", "LOOP\nPRINT 1\nENDL\n")
    mint_format("--indent-style", "tab", path)
    assert path.read_text(encoding="utf-8") == "LOOP\n\tPRINT 1\nENDL\n"
    mint_format("--indent-width", "4", path)
    assert path.read_text(encoding="utf-8") == "LOOP\n    PRINT 1\nENDL\n"


def test_configuration_files_are_formatted_too_and_line_ends_kept(tmp_path: Path) -> None:
    path = tmp_path / "cell.cfg"
    path.write_bytes(b"scale = 1000\r\nspeed = 10  \r\n")
    assert mint_format(tmp_path).exit_code == 0
    assert path.read_bytes() == b"SCALE = 1000\r\nSPEED = 10\r\n"


def test_mintmt_keeps_its_words_case(tmp_path: Path) -> None:
    path = write(tmp_path / "cell.mnt", "Loop\nPrint 1\nEnd Loop\n")
    mint_format("--dialect", "mintmt", path)
    assert path.read_text(encoding="utf-8") == "Loop\n  Print 1\nEnd Loop\n"


def test_a_file_that_is_not_text_is_named_and_the_others_are_formatted(tmp_path: Path) -> None:
    (tmp_path / "bad.mnt").write_bytes(b"PRINT 1\x00\n")
    good = write(tmp_path / "good.mnt", "print 1\n")
    result = mint_format(tmp_path)
    assert result.exit_code == 2 and "not formatted" in result.stderr
    assert good.read_text(encoding="utf-8") == "PRINT 1\n"


def test_standard_input_is_formatted_to_standard_output(tmp_path: Path) -> None:
    result = CliRunner().invoke(main, ["format", "-"], input="loop\nprint 1\nendl\n")
    assert (result.exit_code, result.stdout) == (0, "LOOP\n  PRINT 1\nENDL\n")
    check = CliRunner().invoke(main, ["format", "--check", "--stdin-filename", "cell.mnt", "-"], input="print 1\n")
    assert (check.exit_code, check.stdout) == (1, "Would reformat: cell.mnt\n")
    alone = CliRunner().invoke(main, ["format", "-", str(tmp_path)], input="")
    assert alone.exit_code == 2


NEAR_THE_LIMIT = 'PRINT "' + "x" * 244 + '"'  # 252 characters: two levels of 2 spaces would make it 256
NEAR_THE_V3_LIMIT = 'PRINT "' + "x" * 118 + '"'  # 126 characters: a level would make it 128


@pytest.mark.parametrize(
    ("dialect", "messy", "formatted"),
    [
        pytest.param(
            "v3",
            "protect abc : print 2\nend\n",
            "protect abc : PRINT 2\nEND\n",
            id="v3-ignores-a-protect-not-in-upper-case-so-its-case-stays",  # 001:11089; upper case: all a password
        ),
        pytest.param(
            "v4",
            f"loop\nloop\n{NEAR_THE_LIMIT}\nendl\nendl\n",
            f"LOOP\n  LOOP\n{NEAR_THE_LIMIT}\n  ENDL\nENDL\n",
            id="a-line-indentation-would-take-past-255-characters-keeps-its-own",  # 000:255
        ),
        pytest.param(
            "v3",
            f"loop\n{NEAR_THE_V3_LIMIT}\nendl\n",
            f"LOOP\n{NEAR_THE_V3_LIMIT}\nENDL\n",
            id="in-v3-past-127-characters",  # 001:5144
        ),
    ],
)
def test_formatting_changes_nothing_the_controller_reads(tmp_path: Path, dialect: str, messy: str, formatted: str):
    path = write(tmp_path / "cell.mnt", messy)
    mint_format("--dialect", dialect, path)
    assert path.read_text(encoding="utf-8") == formatted


MINTMT = "MOVER(0) = 10      ' Load a relative move of 10 units\nGO(0)\n"  # 004:32, a ' comment: MintMT's


def test_a_mintmt_program_read_as_v4_by_default_is_left_as_it_is(tmp_path: Path) -> None:
    # read as v4, the ' comment would be code: its "of" written OF
    path = write(tmp_path / "buffer.mnt", MINTMT)
    result = mint_format(path)
    assert (result.exit_code, path.read_text(encoding="utf-8")) == (2, MINTMT)
    assert f"{path}: looks like MintMT (a ' comment on line 1)" in result.stderr
    piped = CliRunner().invoke(main, ["format", "-"], input=MINTMT)
    assert (piped.exit_code, piped.stdout) == (2, "")
    chosen = mint_format("--dialect", "v4", path)  # the user's word: read as v4, the ' opens a character constant
    assert (chosen.exit_code, path.read_text(encoding="utf-8")) == (2, MINTMT)  # never closed: a syntax error
    assert f"{path}:1:20: E2003 " in chosen.stderr


def test_the_settings_files_format_table_gives_the_defaults(tmp_path: Path) -> None:
    write(tmp_path / "mint.toml", '[format]\nindent-style = "tab"\n')
    path = write(tmp_path / "cell.mnt", "LOOP\nPRINT 1\nENDL\n")
    assert mint_format(path).exit_code == 0
    assert path.read_text(encoding="utf-8") == "LOOP\n\tPRINT 1\nENDL\n"
    mint_format("--indent-style", "space", "--indent-width", "3", path)  # the command line wins
    assert path.read_text(encoding="utf-8") == "LOOP\n   PRINT 1\nENDL\n"
    write(tmp_path / "mint.toml", "[format]\nindent = 4\n")
    result = mint_format(path)
    assert result.exit_code == 2 and "unknown key" in result.stderr


def test_a_format_table_gives_the_indentation_the_editor_uses_too() -> None:
    assert project_indent_unit({}) is None  # the editor's own tab or spaces
    assert project_indent_unit({"indent-width": 4}) == "    "
    assert project_indent_unit({"indent-style": "tab"}) == "\t"
    assert project_indent_unit({"indent-style": "space"}) == "  "  # mint format's default width
    assert project_indent_unit({"indent-width": "wide"}) is None  # mint format refuses it: the editor's
