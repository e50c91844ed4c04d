"""``mint-dap`` and ``mint dap`` are the same adapter."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from tests.debugger.client import adapter_command


def test_mint_dap_says_what_it_is() -> None:
    shown = subprocess.run([*adapter_command(), "--help"], capture_output=True, text=True, check=True)
    assert "debug adapter" in shown.stdout


def test_mint_dap_is_also_a_mint_subcommand() -> None:
    mint = Path(sys.executable).with_name("mint")
    shown = subprocess.run([str(mint), "dap", "--help"], capture_output=True, text=True, check=True)
    assert "Usage: mint dap" in shown.stdout
