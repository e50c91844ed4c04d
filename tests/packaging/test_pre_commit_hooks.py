"""The pre-commit hooks of ``.pre-commit-hooks.yaml``, tried on sample repositories as a user's pre-commit runs them.

``pre-commit try-repo`` installs this repository's committed HEAD into a virtual
environment of its own with pip (``language: python``), exactly as it installs a
hook from a user's configuration: the test needs the package index that the test
extra itself was installed from, no more. It takes about a minute, mostly pip.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PRE_COMMIT = Path(sys.executable).parent / "pre-commit"
CLEAN = "DIM homeRate = 10\nAXES[0]\nHOMESPEED.0 = homeRate\nPRINT homeRate\n"  # Mint v4, nothing to report
UNDECLARED = "AXES[0]\nPRINT target\n"  # an error: 'target' is not declared (E3001)
UNFORMATTED = "loop\nprint 1\nendl\n"  # mint format writes LOOP, an indented PRINT and ENDL
V3 = "HMSPEED.0 = 10\n"  # Mint v3: HMSPEED became HOMESPEED

pytestmark = pytest.mark.skipif(
    not (ROOT / ".git").exists() or not PRE_COMMIT.exists(), reason="needs a git checkout and pre-commit"
)


def git(repository: Path, *arguments: str) -> str:
    identity = ["-c", "user.name=test", "-c", "user.email=test@example.invalid", "-c", "commit.gpgsign=false"]
    result = subprocess.run(["git", *identity, *arguments], cwd=repository, capture_output=True, text=True, check=True)
    return result.stdout


def sample(directory: Path, files: dict[str, str]) -> Path:
    directory.mkdir()
    git(directory, "init", "-q")
    for name, text in files.items():
        (directory / name).write_text(text, encoding="utf-8")
    git(directory, "add", ".")
    return directory


def try_repo(repository: Path, home: Path) -> subprocess.CompletedProcess[str]:
    """Every hook of this repository's HEAD on every file of ``repository``."""
    environment = {key: value for key, value in os.environ.items() if not key.startswith(("GIT_", "PRE_COMMIT"))}
    return subprocess.run(
        [PRE_COMMIT, "try-repo", ROOT, "--ref", git(ROOT, "rev-parse", "HEAD").strip(), "--all-files"],
        cwd=repository,
        capture_output=True,
        text=True,
        timeout=600,
        env=environment | {"PRE_COMMIT_HOME": str(home), "NO_COLOR": "1"},
        check=False,
    )


def hook_lines(output: str) -> dict[str, str]:
    """``mint check....Passed`` lines: each hook's name and verdict."""
    return {line.split(".")[0]: line.rsplit(".", 1)[1] for line in output.splitlines() if "....." in line}


def test_the_hooks_pass_a_clean_repository_and_fail_one_with_findings(tmp_path: Path) -> None:
    if shutil.which("git") is None:
        pytest.skip("needs git")
    home = tmp_path / "pre-commit-home"  # the hook's environment is installed once, for both runs
    clean = try_repo(sample(tmp_path / "clean", {"cell.mnt": CLEAN, "notes.txt": "PRINT nothing\n"}), home)
    assert clean.returncode == 0, clean.stdout + clean.stderr
    hooks = ("mint check", "mint format", "mint-migrate --check")
    assert hook_lines(clean.stdout) == dict.fromkeys(hooks, "Passed")

    files = {"cell.mnt": UNDECLARED, "OLD.MNT": V3, "loop.mnt": UNFORMATTED}
    findings = try_repo(sample(tmp_path / "findings", files), home)
    assert findings.returncode == 1
    assert hook_lines(findings.stdout) == dict.fromkeys(hooks, "Failed")
    assert (tmp_path / "findings" / "loop.mnt").read_text(encoding="utf-8") == "LOOP\n  PRINT 1\nENDL\n"
    assert "cell.mnt:2:7" in findings.stdout  # mint check's report
    assert "OLD.MNT" in findings.stdout  # the v3 file, found whatever the case of its suffix
