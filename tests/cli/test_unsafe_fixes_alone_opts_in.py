"""``--unsafe-fixes`` without ``--fix`` opts in to the unsafe fixes as ruff's does: the report's closing count
takes them as fixable, and tells the command that applies them, instead of telling the user to add the
option just given. It still writes nothing (README, Fixes)."""

from __future__ import annotations

from pathlib import Path

from tests.cli.invoking import mint_check, write

# Line 1: typographic quotes (W101, a safe fix). Line 2: IDL for IDLE (E3007, an unsafe respelling).
PROGRAM = "PRINT \u201cready\u201d\nPAUSE IDL.0\n"


def test_the_closing_count_takes_the_unsafe_fixes_as_fixable(tmp_path: Path) -> None:
    path = write(tmp_path / "cell.mnt", PROGRAM)
    result = mint_check("--unsafe-fixes", path)
    assert result.stdout.endswith(
        "1 file checked: 1 error, 1 warning, 0 infos\n2 findings fixable with --fix --unsafe-fixes.\n"
    )
    assert path.read_text(encoding="utf-8") == PROGRAM


def test_without_it_the_unsafe_ones_are_counted_apart(tmp_path: Path) -> None:
    result = mint_check(write(tmp_path / "cell.mnt", PROGRAM))
    assert result.stdout.endswith("1 finding fixable with --fix (1 more with --unsafe-fixes).\n")


def test_with_only_unsafe_fixes_to_make_the_count_is_the_same(tmp_path: Path) -> None:
    result = mint_check("--unsafe-fixes", write(tmp_path / "cell.mnt", "PAUSE IDL.0\n"))
    assert result.stdout.endswith("1 finding fixable with --fix --unsafe-fixes.\n")
