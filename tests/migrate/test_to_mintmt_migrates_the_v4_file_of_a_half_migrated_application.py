"""A file already in MintMT is left as it is, and only that file: its v4 partner is still migrated.

A program migrated alone (``--no-config``, or edited by hand into MintMT) leaves its configuration file
in Mint v4. The whole application used to come back "already mintmt": the configuration file kept its
``REM`` and ``SPEED.0``, the report called it MintMT, and ``--check`` passed. The README and MT-17 leave
as it is a file, a text, that shows a MintMT form; the other is rewritten as any v4 file is: ``REM``
becomes ``'`` and ``KW.0`` ``KW(0)`` (004:32, MT-18, MT-19).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.migrate.cli import migrate
from mintlang.migrate.mintmt import to_mintmt

V4_CONFIG = "REM set-up\nDEFINE clamp = OUT.2\nSPEED.0 = 100\n"
MINTMT_CONFIG = "' set-up\nDEFINE clamp = OUTX(2)\nSPEED(0) = 100\n"
V4_PROGRAM = "LOOP\n  clamp = _ON\n  MOVER.0 = 10 : GO.0\nENDL\n"
MINTMT_PROGRAM = "LOOP\n  clamp = _ON\n  MOVER(0) = 10 : GO(0)\nEND LOOP\n"


@pytest.mark.parametrize(
    ("program", "config"),
    [
        pytest.param(MINTMT_PROGRAM, V4_CONFIG, id="program-done"),
        pytest.param(V4_PROGRAM, MINTMT_CONFIG, id="configuration-done"),
    ],
)
def test_the_v4_file_is_migrated_and_the_mintmt_one_kept(program: str, config: str) -> None:
    result = to_mintmt(program, config=config)
    assert result.configuration is not None
    assert (result.text, result.configuration.text) == (MINTMT_PROGRAM, MINTMT_CONFIG)
    assert result.already_mintmt is (program == MINTMT_PROGRAM)
    assert result.configuration.already_mintmt is (config == MINTMT_CONFIG)


def test_both_files_in_mintmt_are_both_left_as_they_are() -> None:
    result = to_mintmt(MINTMT_PROGRAM, config=MINTMT_CONFIG)
    assert result.configuration is not None
    assert result.already_mintmt and result.configuration.already_mintmt
    assert (result.text, result.configuration.text) == (MINTMT_PROGRAM, MINTMT_CONFIG)


def test_check_fails_on_the_configuration_file_left_in_v4(tmp_path: Path) -> None:
    (tmp_path / "app.mnt").write_text(MINTMT_PROGRAM)
    (tmp_path / "app.cfg").write_text(V4_CONFIG)
    run = CliRunner().invoke(migrate, ["--to", "mintmt", "--check", "--color", "never", str(tmp_path)])
    assert run.exit_code == 1
    assert "1 changed, 0 unchanged, 1 already mintmt" in run.output
