"""``mint check --diff`` says, after what it would fix, what it leaves to ``--unsafe-fixes``, as ruff's ``--diff``
does ('1 additional fix available with --unsafe-fixes'), and as the text report after ``--fix`` does: a file
whose only fixes are unsafe was 'Nothing to fix', with no word that a fix was there to review."""

from __future__ import annotations

from pathlib import Path

from tests.cli.invoking import mint_check, write

# Line 1: typographic quotes (W101, a safe fix). Line 2: IDL for IDLE (E3007, an unsafe respelling).
BOTH = "PRINT \u201cready\u201d\nPAUSE IDL.0\n"


def test_the_unsafe_fixes_left_are_counted_after_the_safe_ones_shown(tmp_path: Path) -> None:
    result = mint_check("--diff", write(tmp_path / "cell.mnt", BOTH))
    assert result.exit_code == 1  # a fix to make
    assert result.stderr.splitlines() == [
        "mint check: Would fix 1 finding in 1 file (1 W101).",
        "mint check: 1 finding fixable with --fix --unsafe-fixes.",
    ]


def test_a_file_with_only_unsafe_fixes_says_so(tmp_path: Path) -> None:
    result = mint_check("--diff", write(tmp_path / "cell.mnt", "PAUSE IDL.0\n"))
    assert (result.exit_code, result.stdout) == (0, "")
    assert result.stderr == "mint check: Nothing to fix.\nmint check: 1 finding fixable with --fix --unsafe-fixes.\n"


def test_with_unsafe_fixes_nothing_is_left_to_tell(tmp_path: Path) -> None:
    result = mint_check("--diff", "--unsafe-fixes", write(tmp_path / "cell.mnt", BOTH))
    assert result.stderr == "mint check: Would fix 2 findings in 1 file (1 E3007, 1 W101).\n"
