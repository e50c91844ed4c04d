"""A MintMT file given to the v3 -> v4 migration is recognised (``mintlang.detection``) and left as
it was, reported "already mintmt": read as Mint v3, every ``'`` comment would be flagged as not valid
v3 and the file would get v3's prologue notes. A folder run over a plant's programs, some already
MintMT, must not damage those."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.migrate import migrate
from mintlang.migrate.cli import migrate as command

LISTINGS = sorted((Path(__file__).parents[1] / "corpus" / "mintmt").glob("*.mnt"))


@pytest.mark.parametrize("path", LISTINGS, ids=[path.stem for path in LISTINGS])
def test_every_mintmt_listing_is_left_as_it_was(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    result = migrate(text)
    assert result.text == text
    assert result.already_mintmt
    assert not result.changes
    assert not result.manual


def test_a_mintmt_program_paired_with_a_configuration_file_leaves_both_as_they_were() -> None:
    program = "Loop\n  If x > 0 Then ' moving\n    x = 0\n  End If\nEnd Loop\n"
    configuration = "HMSPEED = 10\n"
    result = migrate(program, config=configuration)
    assert (result.text, result.configuration.text) == (program, configuration)
    assert result.already_mintmt and result.configuration.already_mintmt


def test_a_folder_run_writes_the_v3_file_and_reports_the_mintmt_one(tmp_path: Path) -> None:
    mintmt = "' restock\nLoop\n  MOVER(0) = 10 : GO(0)\nEnd Loop\n"
    (tmp_path / "mt.mnt").write_text(mintmt, encoding="utf-8")
    (tmp_path / "old.mnt").write_text("HMSPEED = 10\n", encoding="utf-8")
    outcome = CliRunner().invoke(command, [str(tmp_path), "--write", "--format", "json"])
    assert outcome.exit_code == 0, outcome.output
    statuses = {Path(row["path"]).name: row["status"] for row in json.loads(outcome.output)["files"]}
    assert statuses == {"mt.mnt": "already mintmt", "old.mnt": "changed"}
    assert (tmp_path / "mt.mnt").read_text(encoding="utf-8") == mintmt
    assert json.loads(outcome.output)["totals"]["already_mintmt"] == 1
