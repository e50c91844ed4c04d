"""Optional rules (S-IDLEAXES, M-BIT, M-REMCOLON, S-DEFAULTS-V3) and how they are asked for."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.migrate import UnknownRule, migrate, rules, select
from mintlang.migrate.cli import migrate as migrate_command
from tests.migrate.helpers import rewritten

OPTIONAL = {"S-IDLEAXES", "M-BIT", "M-REMCOLON", "S-DEFAULTS-V3"}


def test_the_optional_rules_are_marked_and_not_selected_by_default() -> None:
    assert {info.id for info in rules() if info.optional} == OPTIONAL
    assert not OPTIONAL & {rule.id for rule in select()}


def test_opt_in_adds_a_rule_and_only_names_it_explicitly() -> None:
    assert "M-BIT" in {rule.id for rule in select(opt_in=["m-bit"])}
    assert [rule.id for rule in select(only=["M-BIT"])] == ["M-BIT"]
    assert "M-BIT" not in {rule.id for rule in select(opt_in=["M-BIT"], skip=["M-BIT"])}
    with pytest.raises(UnknownRule, match="M-NOPE"):
        select(opt_in=["M-NOPE"])


def test_default_migration_leaves_the_optional_forms_alone() -> None:
    assert migrate("OUT0 = 1 REM on\n", controller="mintdrive").text == "OUT0 = 1 REM on\n"
    chosen = migrate("OUT0 = 1 REM on\n", controller="mintdrive", opt_in=["M-BIT", "M-REMCOLON"])
    assert chosen.text == "OUT.0 = 1 : REM on\n"


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("AXES[0,1]\nHOME = 0,0 : REM both\n", "AXES[0,1]\nHOME[0,1] = 0,0 : REM both\n"),
        ("AXES[0,1]\nMOVEA = x,y : GO\n", "AXES[0,1]\nMOVEA[0,1] = x,y : GO[0,1]\n"),
        ("MOVEA = 10 : GO\n", "MOVEA[0] = 10 : GO[0]\n"),
        ("MOVEA = 10\nGO\n", "MOVEA[0] = 10\nGO[0,1,2]\n"),
        ("IF a THEN OFFSET = 10 : GO\n", "IF a THEN OFFSET[0] = 10 : GO[0]\n"),
        ("SPEED = ,10\nACCEL = 5;\n", "SPEED[0,1] = ,10\nACCEL[0,1,2] = 5;\n"),
        ("MOVEA.1 = 5 : GO[1]\n", "MOVEA.1 = 5 : GO[1]\n"),
    ],
)
def test_explicit_axes(source: str, expected: str) -> None:
    assert rewritten("S-IDLEAXES", source) == expected


def test_explicit_axes_refuses_an_unknown_default() -> None:
    source = "AXES[a]\nMOVEA = 1 : GO\n"
    assert rewritten("S-IDLEAXES", source) == source
    assert rewritten("S-IDLEAXES", "AXES[0]\nMOVEA = 1,2\n") == "AXES[0]\nMOVEA = 1,2\n"  # too many values


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("OUT0 = 1\nIF IN7 THEN OUT3 = 0\n", "OUT.0 = 1\nIF IN.7 THEN OUT.3 = 0\n"),
        ("x = in2 + IN.3\n", "x = IN.2 + IN.3\n"),
        ("OUT = 5 : x = IN\n", "OUT = 5 : x = IN\n"),
    ],
)
def test_dot_bits(source: str, expected: str) -> None:
    assert rewritten("M-BIT", source) == expected


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("PRINT REM blank\r\nx = 1 REM one\r\n", "PRINT : REM blank\r\nx = 1 : REM one\r\n"),
        ("x = 1 : REM kept\nREM alone\n  REM indented\n", "x = 1 : REM kept\nREM alone\n  REM indented\n"),
        ("#lbl REM label\nIF a THEN REM then\n", "#lbl REM label\nIF a THEN REM then\n"),
    ],
)
def test_rem_colon(source: str, expected: str) -> None:
    assert rewritten("M-REMCOLON", source) == expected


@pytest.mark.parametrize("rule", sorted(OPTIONAL - {"S-DEFAULTS-V3"}))
def test_optional_rules_are_idempotent(rule: str) -> None:
    source = "AXES[0,1]\nHOME = 0,0 REM home\nOUT0 = 1 REM out\nMOVEA = 1,2 : GO\n"
    once = rewritten(rule, source)
    assert once != source
    assert rewritten(rule, once) == once


def test_cli_with_and_list_rules(tmp_path: Path) -> None:
    runner = CliRunner()
    listed = runner.invoke(migrate_command, ["--list-rules"]).output
    assert all(rule in listed for rule in OPTIONAL)
    assert "mechanical (optional)" in listed and "semi (optional)" in listed
    program = tmp_path / "a.mnt"
    program.write_text("x = IN0 REM in\n")
    common = ["--controller", "mintdrive", "--stdout"]
    plain = runner.invoke(migrate_command, [*common, str(program)])
    assert plain.stdout_bytes == b"DIM x\nx = IN0 REM in\n"
    chosen = runner.invoke(migrate_command, [*common, "--with", "M-BIT", "--with", "M-REMCOLON", str(program)])
    assert chosen.stdout_bytes == b"DIM x\nx = IN.0 : REM in\n"
    unknown = runner.invoke(migrate_command, ["--with", "M-NOPE", str(program)])
    assert unknown.exit_code == 2 and "unknown rule: M-NOPE" in unknown.output
