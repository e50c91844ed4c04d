"""The README's nvim-dap configuration, in headless Neovim: stop at the entry, at a breakpoint, then step back.

nvim-dap is not in any registry this project installs from, so the test runs
only where ``$NVIM_DAP`` names a copy of it (``git clone
https://github.com/mfussenegger/nvim-dap``; 0.6.0 supports Neovim 0.7.2).
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from tests.debugger.test_stepping_back import LOOP

NVIM = Path(__file__).parent / "nvim"
NVIM_DAP = os.environ.get("NVIM_DAP", "")

pytestmark = [
    pytest.mark.skipif(shutil.which("nvim") is None, reason="Neovim is not installed"),
    pytest.mark.skipif(not (Path(NVIM_DAP) / "lua" / "dap").is_dir(), reason="$NVIM_DAP names no copy of nvim-dap"),
]


def test_the_readme_configuration_debugs_forwards_and_back(tmp_path: Path) -> None:
    readme = (Path(__file__).parents[2] / "README.md").read_text(encoding="utf-8")
    configuration = (NVIM / "dap.lua").read_text(encoding="utf-8")
    assert configuration.split("\n", 1)[1].strip() in readme, "dap.lua is the README's snippet"
    program = tmp_path / "loop.mnt"
    program.write_text(LOOP, encoding="utf-8")
    out = tmp_path / "probe.json"
    environment = {
        **os.environ,
        "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}",
        "MINT_DAP_CONFIG": str(NVIM / "dap.lua"),
        "MINT_BREAK_LINE": "6",
        "MINT_PROBE_OUT": str(out),
        "XDG_STATE_HOME": str(tmp_path),
        "XDG_CACHE_HOME": str(tmp_path),
    }
    command = ["nvim", "--headless", "-n", "-i", "NONE", "-u", "NONE", str(program)]
    subprocess.run([*command, "-c", f"luafile {NVIM / 'probe.lua'}"], env=environment, timeout=90, check=True)
    # the entry (line 1), the breakpoint (PRINT b, line 6), one statement back (NEXT, line 5)
    assert json.loads(out.read_text(encoding="utf-8")) == {"lines": [1, 6, 5]}
