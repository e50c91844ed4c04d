"""An expectation on a digital input the controller does not have names nothing in the run: it fails as
missing, as one on an axis or output it lacks does, instead of reading 0 and passing."""

from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner

from mintlang.cli import main

# The NextMove BX has 16 digital inputs, IN0 to IN15 (000:5949); reading one beyond them is error 7, "Digital
# input specified out of range" (000:18532), as reading one beyond its 8 outputs, OUT0 to OUT7 (000:14944), is
# error 8 (000:18536).
PROGRAM = """\
REM @expect IN.15 = 0
REM @expect IN.16 = 0
REM @expect IN = 0
REM @expect OUT.7 = 0
REM @expect OUT.8 = 0
PRINT 1
"""


def test_an_input_beyond_the_controllers_fails_as_missing(tmp_path: Path) -> None:
    program = tmp_path / "inputs.mnt"
    program.write_text(PROGRAM, encoding="utf-8")
    arguments = ["test", str(program), "-j", "1", "--controller", "nextmove-bx", "--format", "json"]
    result = CliRunner().invoke(main, arguments)
    assert result.exit_code == 1, result.output
    checks = {check["what"]: check for check in json.loads(result.output)["tests"][0]["checks"]}
    assert {what: (check["held"], check["actual"]) for what, check in checks.items()} == {
        "IN.15": (True, "0"),
        "IN.16": (False, "missing"),
        "IN": (True, "0"),
        "OUT.7": (True, "0"),
        "OUT.8": (False, "missing"),
    }
