"""The partner file is read from disk once per change, not once per request."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from mintlang.lsp import disk


def _touch(path: Path, text: str, mtime_ns: int) -> None:
    path.write_text(text, encoding="utf-8")
    os.utime(path, ns=(mtime_ns, mtime_ns))


def test_a_file_is_read_again_when_it_changes(tmp_path: Path) -> None:
    config = tmp_path / "app.cfg"
    _touch(config, "AXES[0]\n", 1_000_000_000)
    assert disk.read_text(config, 1000) == "AXES[0]\n"
    _touch(config, "AXES[1]\n", 2_000_000_000)  # same size, later
    assert disk.read_text(config, 1000) == "AXES[1]\n"


def test_an_unchanged_file_is_not_read_again(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    config = tmp_path / "app.cfg"
    _touch(config, "AXES[0]\n", 1_000_000_000)
    disk.read_text(config, 1000)
    monkeypatch.setattr(Path, "read_bytes", lambda self: pytest.fail(f"{self} read again"))
    assert disk.read_text(config, 1000) == "AXES[0]\n"


def test_what_is_no_readable_file_gives_no_text(tmp_path: Path) -> None:
    large = tmp_path / "large.cfg"
    large.write_text("REM x\n" * 100, encoding="utf-8")
    assert disk.read_text(tmp_path, 1000) is None  # a folder
    assert disk.read_text(tmp_path / "missing.cfg", 1000) is None
    assert disk.read_text(large, 100) is None
