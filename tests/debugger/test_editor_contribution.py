"""The VS Code extension's launch attributes offer exactly the controllers and dialects mint-dap accepts,
with the defaults it applies when an attribute is left out."""

from __future__ import annotations

import json
from pathlib import Path

from mintlang.keyworddb.model import Controller
from mintlang.runtime.debugger.launch import AUTO, prepare
from mintlang.runtime.dialects import SIMULATED
from mintlang.runtime.dialects.v3.controllers import PROFILES

MANIFEST = Path(__file__).parents[2] / "vscode-ext" / "package.json"


def _launch_properties() -> dict[str, dict]:
    (contributed,) = json.loads(MANIFEST.read_text(encoding="utf-8"))["contributes"]["debuggers"]
    return contributed["configurationAttributes"]["launch"]["properties"]


def test_the_controllers_offered_are_the_v4_guides_and_the_v3_guides() -> None:
    offered = _launch_properties()["controller"]["enum"]
    assert sorted(offered) == sorted([controller.value for controller in Controller] + list(PROFILES))


def test_the_dialects_offered_are_those_simulated_and_auto() -> None:
    assert _launch_properties()["dialect"]["enum"] == [*(dialect.value for dialect in SIMULATED), AUTO]


def test_a_launch_without_stop_on_entry_does_what_the_schema_says(tmp_path: Path) -> None:
    program = tmp_path / "p.mnt"
    program.write_text("PRINT 1\n", encoding="utf-8")
    assert prepare({"program": str(program)}).stop_on_entry is _launch_properties()["stopOnEntry"]["default"]
