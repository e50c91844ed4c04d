"""Headless Neovim with the README's snippet (``nvim/mint.lua``), driven by a Lua probe that writes JSON."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

NVIM = Path(__file__).parent / "nvim"
needs_neovim = pytest.mark.skipif(shutil.which("nvim") is None, reason="Neovim is not installed")


def run_probe(probe: str, file: Path, tmp_path: Path, **env: str) -> Any:
    """Open ``file`` in Neovim, run ``nvim/<probe>`` with ``env`` (``mint-lsp`` on PATH), and return the
    JSON it writes to ``$MINT_PROBE_OUT``."""
    out = tmp_path / "probe.json"
    environment = {
        **os.environ,
        "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}",
        "MINT_PROBE_OUT": str(out),
        "XDG_STATE_HOME": str(tmp_path),
        "XDG_DATA_HOME": str(tmp_path),
        **env,
    }
    command = ["nvim", "--headless", "-n", "-i", "NONE", "-u", str(NVIM / "mint.lua"), str(file)]
    subprocess.run([*command, "-c", f"luafile {NVIM / probe}"], env=environment, timeout=90, check=True)
    return json.loads(out.read_text(encoding="utf-8"))
