"""A launch naming a controller there is none of is refused with the controllers the dialect knows.

``controller`` in a launch is as ``mint-run``'s option (README.md, "Debugging"), whose error names
the controllers to choose from; the launch answered with Python's own enum message instead,
"'nextmove-xyz' is not a valid Controller", which names none of them. The v4 guide's controllers
are the NextMove PCI, PC and BX, the MintDrive and the ServoNode 51 (000's keyword tables).
"""

from __future__ import annotations

from pathlib import Path

from tests.debugger.client import DapClient


def test_an_unknown_controller_is_refused_naming_the_v4_controllers(tmp_path: Path) -> None:
    program = tmp_path / "p.mnt"
    program.write_text("DIM x\n", encoding="utf-8")
    client = DapClient()
    client.body("initialize", {"adapterID": "mint"})
    response = client.request("launch", {"program": str(program), "controller": "nextmove-xyz"})
    assert not response["success"]
    assert response["message"] == (
        "nextmove-xyz is not a controller of the Mint v4 guide: use one of"
        " nextmove-pci, nextmove-pc, nextmove-bx, mintdrive, servonode51"
    )
    assert "Traceback" not in client.close()
