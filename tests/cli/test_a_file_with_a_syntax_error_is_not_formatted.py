"""``mint format`` leaves a file with a syntax error as it is and names the error's place, as ``ruff format``
does with a file it cannot parse (exit 2, with ``--check`` and ``--diff`` too): what the compiler cannot read
may be words the author meant as text, which the house style would write in upper case. A C comment
(``//``: Mint's comments begin with REM, 000:15506-15510) kept its slashes but had its FOR and NEXT
upper-cased, and text after a DOS end-of-file mark (a stray character before the end, 2003) was rewritten."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from mintlang.cli import main
from tests.cli.invoking import write

C_COMMENT = "DIM a\n// for the next part, loop on\nloop\nprint a\nendl\n"


def mint_format(*arguments: str | Path, given: str | None = None) -> Result:
    return CliRunner().invoke(main, ["format", *(str(argument) for argument in arguments)], input=given)


@pytest.mark.parametrize(
    ("text", "place"),
    [
        pytest.param(C_COMMENT, "2:1", id="a-c-comment"),
        pytest.param("loop\nprint 1\nendl\n\x1athis is the end of it\n", "4:1", id="text-after-the-end-of-file-mark"),
        pytest.param("loop\nprint (1\nendl\n\x1athe end\n", "2:9", id="the-first-of-two-errors"),
    ],
)
@pytest.mark.parametrize("options", [(), ("--check",), ("--diff",)], ids=["write", "check", "diff"])
def test_the_file_is_named_with_the_place_of_its_error_and_left_as_it_is(
    tmp_path: Path, text: str, place: str, options: tuple[str, ...]
) -> None:
    path = write(tmp_path / "cell.mnt", text)
    result = mint_format(*options, path)
    assert result.exit_code == 2
    assert f"mint format: {path}:{place}: E2003 " in result.stderr
    assert result.stderr.rstrip().endswith(": not formatted")
    assert path.read_text(encoding="utf-8") == text


def test_the_other_files_are_formatted(tmp_path: Path) -> None:
    broken, good = write(tmp_path / "broken.mnt", C_COMMENT), write(tmp_path / "good.mnt", "loop\nprint 1\nendl\n")
    result = mint_format(tmp_path)
    assert result.exit_code == 2
    assert broken.read_text(encoding="utf-8") == C_COMMENT
    assert good.read_text(encoding="utf-8") == "LOOP\n  PRINT 1\nENDL\n"
    assert result.stdout == "1 file reformatted, 0 files left unchanged\n"


def test_standard_input_is_not_written_back_changed(tmp_path: Path) -> None:
    result = mint_format("--stdin-filename", str(tmp_path / "cell.mnt"), "-", given=C_COMMENT)
    assert (result.exit_code, result.stdout) == (2, "")
    assert f"{tmp_path / 'cell.mnt'}:2:1: E2003 " in result.stderr


def test_a_macro_of_the_configuration_file_is_read_as_the_program_sees_it(tmp_path: Path) -> None:
    # the configuration file's macros are the program's too (000:1540-1541): 'twice' completes the expression
    write(tmp_path / "cell.cfg", "DEFINE twice = * 2\nDIM g = 1\n")
    program = write(tmp_path / "cell.mnt", "loop\nprint g twice\nendl\n")
    result = mint_format(program)
    assert (result.exit_code, program.read_text(encoding="utf-8")) == (0, "LOOP\n  PRINT g twice\nENDL\n")
    named = write(tmp_path / "other.mnt", "print g twice\n")
    assert mint_format("--diff", named).exit_code == 2  # no configuration file beside it: an error
    write(tmp_path / "mint.toml", 'config = "cell.cfg"\n')  # one for every program
    assert mint_format(named).exit_code == 0
