"""A rule that fails never becomes a traceback: the application it failed on is reported with
its path and the rule, left as it was, and every other application is migrated and written.
Exit status 2 says something was not done."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path

import pytest
from click.testing import CliRunner, Result

import mintlang
from mintlang.caching import Shelf
from mintlang.diagnostics import Span
from mintlang.migrate import MigrationFailed, migrate
from mintlang.migrate.cli import migrate as command
from mintlang.migrate.context import Context, LineTags
from mintlang.migrate.rules import RULES, Replace, Rule
from mintlang.semantic.units import Unit
from mintlang.syntax.parser import Document

V3 = "DIM a(2)\nPRINT a(1)\nSTOP\n"
V4 = "AXES[0,1,2]\nDIM a(2)\nPRINT a(1)\nSTOP\n"
TRIGGER = "REM boom\n"  # the text the broken rule below chokes on


def _rule(rule_id: str) -> Rule:
    return next(rule for rule in RULES if rule.id == rule_id)


@pytest.fixture
def broken_rule(monkeypatch: pytest.MonkeyPatch) -> None:
    """S-ACCEL raises on any program holding TRIGGER, as a bug would."""
    apply = _rule("S-ACCEL").apply

    def raising(context: Context) -> Iterator[object]:
        if TRIGGER in context.files[Unit.PROGRAM].text:
            raise KeyError("no such axis")
        return apply(context)

    monkeypatch.setattr(_rule("S-ACCEL"), "apply", raising)


def run(*arguments: object) -> Result:
    return CliRunner().invoke(command, [str(argument) for argument in arguments])


@pytest.mark.usefixtures("broken_rule")
def test_the_library_raises_migration_failed_naming_the_rule() -> None:
    with pytest.raises(MigrationFailed) as failed:
        migrate(TRIGGER + V3)
    assert failed.value.rule == "S-ACCEL"
    assert str(failed.value) == "rule S-ACCEL failed: KeyError: 'no such axis'"


def test_a_rule_that_keeps_rewriting_its_own_output_is_named(monkeypatch: pytest.MonkeyPatch) -> None:
    def growing(context: Context) -> Iterator[Replace]:
        end = len(context.files[Unit.PROGRAM].text)
        yield Replace(Unit.PROGRAM, Span(end, end), " ")  # one more space on every pass

    monkeypatch.setattr(_rule("M-PREC"), "apply", growing)  # a phase that confirms its fixed point
    with pytest.raises(MigrationFailed, match=r"^rule M-PREC failed: it kept rewriting its own output"):
        migrate(V3)


@pytest.mark.usefixtures("broken_rule")
def test_the_other_files_are_migrated_and_written(tmp_path: Path) -> None:
    first, broken, last = (tmp_path / name for name in ("a.mnt", "b.mnt", "c.mnt"))
    first.write_text(V3)
    broken.write_text(TRIGGER + V3)
    last.write_text(V3)
    result = run("--write", tmp_path)
    assert result.exit_code == 2
    assert "Traceback" not in result.output
    assert result.stderr.splitlines() == [
        f"mint-migrate: {broken}: rule S-ACCEL failed: KeyError: 'no such axis'; left as it was"
    ]
    assert (first.read_text(), broken.read_text(), last.read_text()) == (V4, TRIGGER + V3, V4)


@pytest.mark.usefixtures("broken_rule")
def test_the_json_report_lists_the_failed_file_with_its_rule(tmp_path: Path) -> None:
    (tmp_path / "a.mnt").write_text(V3)
    (tmp_path / "b.mnt").write_text(TRIGGER + V3)
    result = run("--format", "json", tmp_path)
    data = json.loads(result.stdout)
    assert result.exit_code == 2
    assert [(row["status"], row.get("failure")) for row in data["files"]] == [
        ("changed", None),
        ("failed", {"rule": "S-ACCEL", "reason": "KeyError: 'no such axis'"}),
    ]
    assert data["totals"]["failed"] == 1


@pytest.mark.usefixtures("broken_rule")
def test_a_failure_leaves_the_configuration_file_of_its_application_as_well(tmp_path: Path) -> None:
    config, program = tmp_path / "app.cfg", tmp_path / "app.mnt"
    config.write_text("AUTO\nspeed1 = 5\n")
    program.write_text(TRIGGER + V3)
    result = run("--write", "--config", config, program)
    assert result.exit_code == 2
    assert result.stderr.count("rule S-ACCEL failed") == 2  # each file of the application is named
    assert (config.read_text(), program.read_text()) == ("AUTO\nspeed1 = 5\n", TRIGGER + V3)


def test_a_bug_outside_the_rules_is_isolated_too(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    build = Context.build

    def failing(
        texts: dict[Unit, str], controller: str, tags: LineTags | None = None, v4_shelf: Shelf | None = None
    ) -> Context:
        if TRIGGER in texts[Unit.PROGRAM]:
            raise RecursionError("maximum recursion depth exceeded")
        return build(texts, controller, tags, v4_shelf)

    monkeypatch.setattr(Context, "build", failing)
    (tmp_path / "a.mnt").write_text(TRIGGER + V3)
    (tmp_path / "b.mnt").write_text(V3)
    result = run("--write", tmp_path)
    assert result.exit_code == 2
    assert "a.mnt: failed: reading it as Mint v3 raised RecursionError" in result.stderr
    assert (tmp_path / "b.mnt").read_text() == V4


def test_a_model_that_cannot_be_built_is_a_reading_failure_not_the_rule_that_asked(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The semantic model is built when a rule first asks for it; a failure there is the reader's."""
    build_model = mintlang.build_model

    def failing(program: Document, *rest: object) -> object:
        if TRIGGER in program.source:
            raise RecursionError("maximum recursion depth exceeded")
        return build_model(program, *rest)

    monkeypatch.setattr(mintlang, "build_model", failing)
    (tmp_path / "a.mnt").write_text(TRIGGER + "DIM b\n" + V3)  # a program whose migration needs the model
    (tmp_path / "b.mnt").write_text(V3)
    result = run("--write", tmp_path)
    assert result.exit_code == 2
    assert "a.mnt: failed: reading it as Mint v3 raised RecursionError" in result.stderr
    assert "rule " not in result.stderr
    assert (tmp_path / "b.mnt").read_text() == V4
