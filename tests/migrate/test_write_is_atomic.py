"""What ``--write`` guarantees about the files it replaces (README, "mint-migrate"):

* every name of a file holds its old bytes or its new bytes at every moment: the new bytes
  go to a temporary file of the same folder, renamed over each name;
* hard links in the file's folder are kept (each name is renamed onto the new file), and a
  file with a link elsewhere is refused before anything is written, as is a file whose
  owner a new copy could not keep;
* a temporary file left by a killed run is removed by the next ``--write`` in that folder
  and named by the modes that write nothing; one a running ``mint-migrate`` holds is left.

``test_write_survives_kills`` kills real runs.
"""

from __future__ import annotations

import fcntl
import os
import stat
from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from mintlang import atomic
from mintlang.migrate.cli import migrate as command

V3 = "DIM a(2)\nPRINT a(1)\nSTOP\n"
V4 = "AXES[0,1,2]\nDIM a(2)\nPRINT a(1)\nSTOP\n"
LEFTOVER = ".a.mnt.k2x9_q1z.mint.tmp"


def run(*arguments: object) -> Result:
    return CliRunner().invoke(command, [str(argument) for argument in arguments])


def program(folder: Path, name: str = "a.mnt") -> Path:
    path = folder / name
    path.write_text(V3)
    return path


def test_every_hard_link_in_the_folder_gets_the_new_text_and_stays_a_link(tmp_path: Path) -> None:
    path = program(tmp_path)
    path.chmod(0o640)
    others = [tmp_path / "b.mnt", tmp_path / "old.txt"]
    for other in others:
        os.link(path, other)
    result = run("--write", path)
    assert result.exit_code == 0, result.output
    inodes = {name.stat().st_ino for name in (path, *others)}
    assert len(inodes) == 1 and path.stat().st_nlink == 3
    assert [name.read_text() for name in (path, *others)] == [V4, V4, V4]
    assert stat.S_IMODE(path.stat().st_mode) == 0o640
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.mnt", "b.mnt", "old.txt"]


def test_a_hard_link_outside_the_folder_is_refused_before_anything_is_written(tmp_path: Path) -> None:
    first = program(tmp_path, "first.mnt")
    path = program(tmp_path, "linked.mnt")
    elsewhere = tmp_path / "backup"
    elsewhere.mkdir()
    os.link(path, elsewhere / "linked.mnt")
    result = run("--write", first, path)
    assert result.exit_code == 2
    assert result.stderr.strip() == (
        f"mint-migrate: cannot write {path}: it has hard links outside its folder, which would keep the old text; "
        "nothing was written"
    )
    assert first.read_text() == V3 and path.read_text() == V3


def test_a_file_whose_owner_a_copy_could_not_keep_is_refused(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    path = program(tmp_path)
    monkeypatch.setattr(os, "geteuid", lambda: path.stat().st_uid + 1)  # someone else, not root
    with pytest.raises(atomic.Unwritable, match="belongs to another user or group, which a new copy could not keep"):
        atomic.target(path)


def test_a_leftover_is_named_by_a_dry_run_and_removed_by_write(tmp_path: Path) -> None:
    path = program(tmp_path)
    leftover = tmp_path / LEFTOVER
    leftover.write_text(V3[:5])  # what a killed run leaves: a partial copy
    dry = run(path)
    assert f"mint-migrate: {leftover} was left by an interrupted --write, which removes it" in dry.stderr
    assert leftover.exists()
    written = run("--write", path)
    assert written.exit_code == 0
    assert f"mint-migrate: removed {leftover}, left by an interrupted --write" in written.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.mnt"]


def test_a_temporary_file_in_use_by_another_run_is_left_alone(tmp_path: Path) -> None:
    path = program(tmp_path)
    busy = tmp_path / LEFTOVER
    busy.write_text("")
    with busy.open("rb") as held:
        fcntl.flock(held, fcntl.LOCK_EX)  # as the other run's atomic.write holds it
        result = run("--write", path)
    assert result.exit_code == 0
    assert busy.exists() and LEFTOVER not in result.stderr


def test_only_files_named_as_mint_migrate_temporaries_are_touched(tmp_path: Path) -> None:
    path = program(tmp_path)
    kept = [tmp_path / ".a.mnt.swp", tmp_path / "notes.tmp", tmp_path / ".x.mint.tmp.bak"]
    for other in kept:
        other.write_text("mine")
    assert run("--write", path).exit_code == 0
    assert all(other.read_text() == "mine" for other in kept)


def test_a_hard_linked_file_in_a_folder_that_cannot_be_listed_is_refused(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = program(tmp_path)
    os.link(path, tmp_path / "b.mnt")
    scandir = os.scandir

    def denied(folder: str | Path = ".") -> object:
        if Path(folder) == tmp_path:  # what a folder with write and search but no read permission does
            raise PermissionError(13, "Permission denied", str(folder))
        return scandir(folder)

    monkeypatch.setattr(os, "scandir", denied)
    result = run("--write", path)
    assert result.exit_code == 2 and "Traceback" not in result.output
    assert "its folder cannot be searched for its other names (Permission denied); nothing was written" in result.stderr
    assert path.read_text() == V3
