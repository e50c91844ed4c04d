"""``mint-run`` given awkward programs, files and options: a clear message and exit status, never a traceback."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner, Result

from mintlang.cli import main


def mint_run(*arguments: str | Path) -> Result:
    return CliRunner().invoke(main, ["run", *(str(argument) for argument in arguments)])


def write(directory: Path, name: str, text: str) -> Path:
    path = directory / name
    path.write_text(text, encoding="utf-8")
    return path


def test_program_text_that_looks_like_markup_is_shown_as_written(tmp_path: Path) -> None:
    result = mint_run(write(tmp_path, "markup.mnt", 'DIM x\nx = 0\nPRINT "[/red][bold]", 1/x\n'))
    assert result.exit_code == 1
    assert result.exception is None or isinstance(result.exception, SystemExit)
    assert 'PRINT "[/red][bold]", 1/x' in result.stderr
    assert "R2021" in result.stderr and "[line 3]" in result.stderr


def test_a_compile_error_quoting_markup_keeps_its_line(tmp_path: Path) -> None:
    result = mint_run(write(tmp_path, "markup.mnt", 'DIM x\nPRINT x "[/b]"\n'))
    assert result.exit_code == 1
    assert '"[/b]"' in result.stderr and "[line 2]" in result.stderr
