"""The text report says which fixes ``--fix`` applies unasked and which need ``--unsafe-fixes``."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from mintlang.cli import main


def test_a_safe_fix_is_a_fix_and_a_guess_an_unsafe_fix(tmp_path: Path) -> None:
    # typographic quotes become plain ones whatever the author meant (W101, safe); an undeclared name
    # declared with DIM is a guess at what the author meant (E3001, unsafe)
    path = tmp_path / "quotes.mnt"
    path.write_text("PRINT \u201chello\u201d\nPRINT targt\n", encoding="utf-8")
    result = CliRunner().invoke(main, ["check", "--color", "never", str(path)])
    fixes = [line.strip() for line in result.stdout.splitlines() if line.strip().startswith("=")]
    assert fixes == ["= fix: Replace with plain quotes", "= unsafe fix: Declare 'targt' with DIM"]
