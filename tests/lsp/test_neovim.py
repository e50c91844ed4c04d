"""A new user's first minutes: Neovim with the README's snippet, a program with an error, a hover."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.lsp.conftest import corpus

NVIM = Path(__file__).parent / "nvim"


@pytest.mark.skipif(shutil.which("nvim") is None, reason="Neovim is not installed")
def test_neovim_shows_diagnostic_and_hover(tmp_path):
    program = tmp_path / "xy.mnt"
    program.write_text(corpus("ch01_l0144_xy_example.mnt").replace("DIM a\n", ""), encoding="utf-8")
    out = tmp_path / "probe.json"
    env = {
        **os.environ,
        "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}",
        "MINT_PROBE_OUT": str(out),
        "MINT_HOVER_LINE": "26",  # MOVEA[0,1] = xpos(a),ypos(a) : GO[0,1]
        "MINT_HOVER_CHARACTER": "2",
        "XDG_STATE_HOME": str(tmp_path),
        "XDG_DATA_HOME": str(tmp_path),
    }
    command = ["nvim", "--headless", "-n", "-i", "NONE", "-u", str(NVIM / "mint.lua"), str(program)]
    subprocess.run([*command, "-c", f"luafile {NVIM / 'probe.lua'}"], env=env, timeout=60, check=True)
    result = json.loads(out.read_text(encoding="utf-8"))
    undeclared = [d for d in result["diagnostics"] if d["code"] == "E3001"]
    assert undeclared and undeclared[0]["message"].startswith("Variable undefined, use DIM")
    assert "**MOVEA**" in result["hover"]
