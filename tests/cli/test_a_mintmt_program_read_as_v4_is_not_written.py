"""A MintMT program checked without ``--dialect`` is read as Mint v4 and hinted at (``mint check``'s MintMT
hint); ``--fix`` and ``--add-ignore`` leave it as it is. Read as v4, its ``'`` comments (004:32) are code: a
suppression comment would go inside one, where it silences nothing once the program is read as MintMT, and a
fix would rewrite what is no code (here v4's W117 fix took the REM out of the comment, leaving ``Loop '``).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.cli.invoking import mint_check, write

MINTMT = "Loop ' REM mint: ignore[W103] kept from the v4 program\nEnd Loop\n"


@pytest.mark.parametrize("option", ["--add-ignore", "--fix", "--unsafe-fixes"])
def test_the_program_is_reported_as_v4_reads_it_and_left_as_it_is(option: str, tmp_path: Path) -> None:
    path = write(tmp_path / "buffer.mnt", MINTMT)
    arguments = ["--fix", option] if option == "--unsafe-fixes" else [option]
    result = mint_check(*arguments, path)
    assert path.read_text(encoding="utf-8") == MINTMT
    assert "looks like MintMT (a ' comment on line 1)" in result.stderr
    assert result.exit_code == 1  # its v4 findings are reported


def test_with_its_dialect_given_it_is_written(tmp_path: Path) -> None:
    path = write(tmp_path / "buffer.mnt", "Dim spare\n")
    assert mint_check("--dialect", "mintmt", "--add-ignore", path).exit_code == 0
    assert path.read_text(encoding="utf-8") == "Dim spare : REM mint: ignore[W103]\n"
