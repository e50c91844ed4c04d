"""The text report's table names each file whole, however long its path: in a CI log (80 columns, no
terminal) a path cut short with an ellipsis would name no file, so a long one is folded over lines."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner

from mintlang.migrate.cli import migrate as command

V3 = "HMSPEED.0 = 20\nSPEED.0 = 2000\n"  # Mint v3: HMSPEED becomes HOMESPEED


def test_a_long_path_is_folded_not_cut(tmp_path: Path) -> None:
    folder = tmp_path / "a_rather_long_folder_name_for_one_plant" / "line_3_palletiser_station"
    folder.mkdir(parents=True)
    path = folder / "palletiser_station_written_for_mint_v3.mnt"
    path.write_text(V3, encoding="utf-8")
    result = CliRunner().invoke(command, [str(path)])
    table = result.stdout[result.stdout.index("mint-migrate (") :].split("\n")[3:]
    cells = "".join(line.split("│")[0].strip() for line in table if "│" in line)
    assert str(path) in cells and "…" not in result.stdout
