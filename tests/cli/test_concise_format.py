"""``mint check --output-format concise`` (ruff's concise format): a line a finding, as a quickfix list reads it.

Each finding is ``path:line:column: CODE message``, the line and column counted from 1 as in the text
report's ``-->`` line; the closing count follows unless ``-q``, and the fix summary as after the text report.
"""

from __future__ import annotations

from pathlib import Path

from tests.cli.invoking import mint_check, write

# line 2: 'targt' is no variable (E3001); line 3: typographic quotes (W101, a safe fix)
PROGRAM = "DIM target\nPRINT targt\nPRINT “done”, target\n"
E3001 = "E3001 Variable undefined, use DIM: 'targt' is not declared; did you mean 'target'?"


def test_each_finding_is_one_line_then_the_count(tmp_path: Path) -> None:
    path = write(tmp_path / "cell.mnt", PROGRAM)
    result = mint_check("--output-format", "concise", path)
    assert result.exit_code == 1
    assert result.stdout.splitlines() == [
        f"{path}:2:7: {E3001}",
        f'{path}:3:7: W101 typographic quotes: the controller expects plain quotes (")',
        "1 file checked: 1 error, 1 warning, 0 infos",
        "1 finding fixable with --fix.",
    ]


def test_quiet_leaves_the_findings_alone(tmp_path: Path) -> None:
    path = write(tmp_path / "cell.mnt", PROGRAM)
    result = mint_check("--format", "concise", "-q", "--select", "E", path)
    assert result.stdout == f"{path}:2:7: {E3001}\n"


def test_statistics_are_counted_as_in_text(tmp_path: Path) -> None:
    path = write(tmp_path / "cell.mnt", PROGRAM)
    concise = mint_check("--format", "concise", "--statistics", path)
    assert concise.stdout == mint_check("--statistics", path).stdout
