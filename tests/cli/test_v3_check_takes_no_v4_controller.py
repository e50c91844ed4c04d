"""``mint check --dialect v3 --controller nextmove-bx`` is refused, as ``mint-run --dialect v3`` refuses it.

The v4 controllers are not v3's: a v3 program is checked against the v3 guide's own limits, at most three
axes (001:972) and inputs and outputs 0 to 7 (001:8965, 10592), whatever a v4 controller has. Given both on
the command line, the check used to go ahead with the v4 controller silently ignored.
"""

from __future__ import annotations

from pathlib import Path

from tests.cli.invoking import mint_check, write


def test_a_v4_controller_with_v3_is_a_usage_error(tmp_path: Path) -> None:
    path = write(tmp_path / "cell.mnt", "SPEED.2 = 10\n")
    result = mint_check("--dialect", "v3", "--controller", "nextmove-bx", path)
    assert result.exit_code == 2
    assert "--controller nextmove-bx is a Mint v4 controller" in result.output


def test_v3_alone_and_a_controller_alone_are_checked(tmp_path: Path) -> None:
    path = write(tmp_path / "cell.mnt", "SPEED.2 = 10\n")
    assert mint_check("--dialect", "v3", path).exit_code == 0
    assert mint_check("--controller", "nextmove-bx", path).exit_code == 0
