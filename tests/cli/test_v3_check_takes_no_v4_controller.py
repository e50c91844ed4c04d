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


def test_a_controller_of_the_v3_guide_is_told_how_v3_is_checked(tmp_path: Path) -> None:
    # mint-run and mint test take --controller euroservo with --dialect v3; mint check said it is "not one of
    # 'nextmove-pci', …", and a v4 one is refused beside --dialect v3 (above): the user went round in a circle
    path = write(tmp_path / "cell.mnt", "SPEED.2 = 10\n")
    result = mint_check("--dialect", "v3", "--controller", "euroservo", path)
    assert result.exit_code == 2
    assert "euroservo is a controller of the Mint v3 guide: mint check --dialect v3 checks" in result.output
    assert "leave --controller out" in result.output
