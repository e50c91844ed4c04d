"""The distribution installs every package of the repository.

The tools' folders are mapped into the ``mintlang`` namespace (``migrate/`` is
``mintlang.migrate``), so setuptools cannot find their packages by itself:
``pyproject.toml`` lists them, and this test keeps the list complete.
"""

from __future__ import annotations

import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def _configuration() -> dict:
    return tomllib.loads((ROOT / "pyproject.toml").read_text("utf-8"))["tool"]["setuptools"]


def test_every_package_folder_is_listed() -> None:
    setuptools = _configuration()
    found = set()
    for package, folder in setuptools["package-dir"].items():
        for init in (ROOT / folder).rglob("__init__.py"):
            relative = init.parent.relative_to(ROOT / folder)
            found.add(".".join((package, *relative.parts)))
    assert found == set(setuptools["packages"])


def test_tool_folders_install_inside_the_mintlang_namespace() -> None:
    # Generic top-level names such as "migrate" or "lsp" would collide with other distributions.
    assert all(package == "mintlang" or package.startswith("mintlang.") for package in _configuration()["packages"])


@pytest.mark.parametrize("tool", ["mintlang", "mintlang.lsp", "mintlang.migrate", "mintlang.runtime"])
def test_every_tool_runs_with_python_dash_m(tool: str) -> None:
    """Editors started through a configured Python (mint.pythonPath) run the tools this way."""
    result = subprocess.run([sys.executable, "-m", tool, "--help"], capture_output=True, text=True, check=False)
    assert result.returncode == 0 and result.stdout.startswith("Usage:"), result.stderr
