"""A v3 statement v4 does not have (COMMSON, BEEPON, a GEARD FOLLOW takes in) becomes a REM when it
is the last statement of its line, even after other code: a REM after a ``:`` comments out the rest
of the line only (v3:11344-11350, v4:15510-15515), so ``RESET : COMMSON`` keeps its RESET as
``RESET : REM COMMSON ...``. Only a statement with more code after it is left for a person.

The configuration file must begin with AUTO (v4:6647); ``AUTO : COMMSON`` was split so that the
marker could go under AUTO, the second pass then found COMMSON alone and removed it, and the
manual item "delete it" was left above a line that was already a comment."""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate

REMOVED = "REM {word}: not available in Mint v4 (v4 guide section 10.3 {word}), removed by mint-migrate"


@pytest.mark.parametrize(
    ("config", "migrated"),
    [
        pytest.param("AUTO : COMMSON\n", f"AUTO : {REMOVED.format(word='COMMSON')}\n", id="after-auto"),
        pytest.param("RESET : BEEPON\n", f"RESET : {REMOVED.format(word='BEEPON')}\n", id="after-a-command"),
        pytest.param(
            "RESET : COMMSOFF : REM host off\n",
            f"RESET : {REMOVED.format(word='COMMSOFF')} : REM host off\n",
            id="before-a-comment",
        ),
    ],
)
def test_the_last_statement_of_a_line_becomes_a_comment(config: str, migrated: str) -> None:
    result = migrate("END\n", config=config, controller="mintdrive", only=["M-NOTAVAIL"])
    assert result.configuration is not None
    assert result.configuration.text == migrated
    assert result.configuration.manual == ()


@pytest.mark.parametrize(
    "config",
    [
        pytest.param("COMMSON : RESET\n", id="code-after-it"),
        pytest.param("IF IN1 THEN BEEPON\n", id="the-body-of-then"),
    ],
)
def test_a_statement_that_cannot_become_a_comment_is_left_for_a_person(config: str) -> None:
    result = migrate("END\n", config=config, controller="mintdrive", only=["M-NOTAVAIL"])
    assert result.configuration is not None
    assert [item.rule for item in result.configuration.manual] == ["M-NOTAVAIL"]
