"""Neovim with the README's snippet: completion after a keyword's dot offers the controller's axes."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

NVIM = Path(__file__).parent / "nvim"


@pytest.mark.skipif(shutil.which("nvim") is None, reason="Neovim is not installed")
def test_neovim_completes_the_axes_after_a_dot(tmp_path):
    program = tmp_path / "axes.mnt"
    program.write_text("DEFINE xAxis = 0\nDIM a\n", encoding="utf-8")
    out = tmp_path / "probe.json"
    env = {
        **os.environ,
        "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}",
        "MINT_PROBE_OUT": str(out),
        "XDG_STATE_HOME": str(tmp_path),
        "XDG_DATA_HOME": str(tmp_path),
    }
    command = ["nvim", "--headless", "-n", "-i", "NONE", "-u", str(NVIM / "mint.lua"), str(program)]
    subprocess.run([*command, "-c", f"luafile {NVIM / 'complete.lua'}"], env=env, timeout=60, check=True)
    result = json.loads(out.read_text(encoding="utf-8"))
    assert "." in result["triggers"]
    assert result["labels"] == [*(str(axis) for axis in range(12)), "xAxis"]  # NextMove PCI: axes 0 to 11
