"""``mint-migrate --check`` as a CI gate: exit 0 when nothing is left to rewrite, whatever
manual items remain (they are reported); 1 when something would be rewritten, or when
manual items remain and ``--fail-on manual`` was given; 2 when something was not done.
``--help`` lists the statuses."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner, Result

from mintlang.migrate import migrate
from mintlang.migrate.cli import migrate as command

V3 = "LOAD 3\nHMSPEED = 10\n"  # a rename to make, and LOAD, which v4 lacks: a manual item


def run(*arguments: object) -> Result:
    return CliRunner().invoke(command, ["--controller", "mintdrive", *(str(argument) for argument in arguments)])


def migrated(tmp_path: Path) -> Path:
    """A program as ``--write`` leaves it: no rewrite left, one manual item."""
    path = tmp_path / "done.mnt"
    path.write_text(migrate(V3, controller="mintdrive").text)
    return path


def test_nothing_left_to_rewrite_passes_and_the_manual_items_are_reported(tmp_path: Path) -> None:
    result = run("--check", migrated(tmp_path))
    assert result.exit_code == 0
    assert "X-HOST LOAD" in result.output and "1 manual item" in result.output


def test_something_left_to_rewrite_fails(tmp_path: Path) -> None:
    path = tmp_path / "old.mnt"
    path.write_text(V3)
    assert run("--check", path).exit_code == 1
    assert path.read_text() == V3


def test_fail_on_manual_makes_manual_items_fail_the_gate(tmp_path: Path) -> None:
    assert run("--check", "--fail-on", "manual", migrated(tmp_path)).exit_code == 1
    clean = tmp_path / "clean.mnt"
    clean.write_text("DIM a\nPRINT a\n")
    assert run("--check", "--fail-on", "manual", clean).exit_code == 0


def test_something_not_done_outranks_a_failed_gate(tmp_path: Path) -> None:
    binary = tmp_path / "a.mnt"
    binary.write_bytes(b"PRINT\x00\n")
    assert run("--check", "--fail-on", "manual", binary).exit_code == 2


def test_help_documents_the_exit_statuses() -> None:
    text = " ".join(CliRunner().invoke(command, ["--help"]).output.split())
    assert "0 done: nothing left to rewrite (--check)" in text
    assert "1 the gate failed: --check found something to rewrite, --verify found a divergence, or manual items" in text
    assert "left and --fail-on manual was given" in text
    assert "2 something was not done:" in text and "a rule that failed on a file" in text
    assert "a --verify comparison that could not cover the run (incomplete)" in text
