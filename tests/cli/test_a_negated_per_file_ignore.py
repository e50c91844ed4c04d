"""A ``per-file-ignores`` glob that starts with ``!`` applies to every file it does not match, as ruff's
does: ``"!legacy/*.mnt" = ["W103"]`` keeps unused variables reported in the legacy folder only. It matched
no file, so a ruff user's setting silenced nothing, without a word."""

from __future__ import annotations

from pathlib import Path

from tests.cli.invoking import mint_check, records, write

UNUSED = "DIM spare\nEND\n"  # W103: declared and never used


def test_the_codes_are_ignored_in_the_files_the_glob_does_not_match(tmp_path: Path) -> None:
    write(tmp_path / "mint.toml", '[per-file-ignores]\n"!legacy/*.mnt" = ["W103"]\n')
    write(tmp_path / "legacy" / "old.mnt", UNUSED)
    write(tmp_path / "src" / "cell.mnt", UNUSED)
    write(tmp_path / "top.mnt", UNUSED)
    found = records(tmp_path)
    assert [(Path(record["path"]).relative_to(tmp_path).as_posix(), record["code"]) for record in found] == [
        ("legacy/old.mnt", "W103")
    ]


def test_show_settings_lists_the_negated_glob_for_a_file_it_does_not_match(tmp_path: Path) -> None:
    write(tmp_path / "mint.toml", '[per-file-ignores]\n"!legacy/*.mnt" = ["W103"]\n')
    result = mint_check("--show-settings", write(tmp_path / "src" / "cell.mnt", UNUSED))
    assert "per-file-ignores    !legacy/*.mnt: W103" in result.stdout
