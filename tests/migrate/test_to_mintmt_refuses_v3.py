"""``--to mintmt`` reads Mint v4: a Mint v3 file is refused with what shows it is v3 ("migrate it to v4
first"), exit status 2, and left as it was. Rewritten, it kept its v3 keywords and failed
``mint check --dialect mintmt`` on each of them, with no marker.

What shows v3 is a word the v4 checker does not know that is a v3 keyword and not a v4 one
(HMSPEED, GEARN, CONTON, DINT, EINT: the v3 guide's keywords the v4 guide replaced), a v3
constant (_servo, v4's _cfSERVO) or a v3 event (#FASTPOS, v4's #FASTIN)."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.migrate.cli import migrate as command
from mintlang.migrate.mintmt import to_mintmt
from mintlang.migrate.mintmt.v3 import v3_uses
from mintlang.migrate.model import MigrationFailed
from tests.corpus_files import CORPUS

V3_PROGRAM = "HMSPEED = 10\nSP = 5\nMA = 100\nGEARN = 1\nCONTON\nDINT\nEINT\nEND\n#FASTPOS\nRETURN\n"


def test_the_v3_keywords_v4_does_not_know_are_named() -> None:
    # SP and MA are abbreviations v4 still reads (SPEED, MOVEA): they do not show v3.
    assert v3_uses(V3_PROGRAM).words == ("HMSPEED", "GEARN", "CONTON", "DINT", "EINT", "#FASTPOS")


def test_a_v3_constant_shows_v3() -> None:
    # the v3 guide's own configuration (001:828): v3's CONFIG constant _servo (001:1327) is v4's _cfSERVO (000:8438)
    assert v3_uses("AXES[0,1]\nCONFIG = _servo, _servo\n").words == ("_SERVO",)


@pytest.mark.parametrize(
    ("source", "words"),
    [
        # the ';' fill of every default axis (001:633 'ACCEL = 500;', 001:1109): v4 reads a name the v4
        # guide does not know as a variable, and a variable takes no fill, so the check stops at the ';'
        pytest.param("HMSPEED = 10;\n", ("HMSPEED",), id="fill"),
        pytest.param("x = 1 : GAIN = 2; : REM gains\n", ("GAIN",), id="fill-after-a-statement"),
        pytest.param("DIM hmspeed\nhmspeed = 10;\n", (), id="a-declared-v4-variable-is-v4-s-own-mistake"),
        pytest.param("DIM x\nx = 10;\n", (), id="a-v4-name"),
    ],
)
def test_a_v3_keyword_written_with_a_fill_shows_v3(source: str, words: tuple[str, ...]) -> None:
    assert v3_uses(source).words == words


def test_a_v4_variable_named_like_a_v3_keyword_does_not_show_v3() -> None:
    assert v3_uses("DIM conton\nconton = 1\nPRINT conton\n").words == ()


def test_an_abbreviation_of_a_v3_keyword_does_not_show_v3() -> None:
    # ax abbreviates v3's AUX: as a (here undeclared) v4 name it is the program's own mistake.
    assert v3_uses("SPEED.ax = 1\n").words == ()


@pytest.mark.parametrize(
    ("source", "words"),
    [
        # 001:8645-8651 as typed with v3's abbreviations: BA is BACKOFF's (001:6047), which the v4 guide
        # retires with it (000:7311); HS and HM are v4's HOMESPEED and HOME, so they show nothing
        pytest.param("BA.2 = 5\nHS.2 = 100\nHM.2 = 0\n", ("BA",), id="with-an-axis"),
        # 001:7459 DISLIMIT[0,1] abbreviated (DISLIMIT/DL, 001:7433; retired by 000:9238)
        pytest.param("dl[0,1]\n", ("DL",), id="a-command"),
    ],
)
def test_an_abbreviation_written_as_a_keyword_shows_v3(source: str, words: tuple[str, ...]) -> None:
    # Written with an axis or alone as a command, the word is a keyword, which v4 does not know: no v4
    # name is used so (an abbreviation used as a variable, above, is another matter).
    assert v3_uses(source).words == words


def test_to_mintmt_refuses_a_v3_program() -> None:
    with pytest.raises(MigrationFailed, match=r"this is Mint v3 \(HMSPEED, .*\): migrate it to v4 first"):
        to_mintmt(V3_PROGRAM)


def test_a_v3_configuration_file_refuses_its_application() -> None:
    with pytest.raises(MigrationFailed, match=r"Mint v3 \(CONTON\)"):
        to_mintmt("DIM x\nx = 1\n", config="CONTON\n")


def test_no_v4_program_of_the_corpus_reads_as_v3() -> None:
    shown = {path.name: v3_uses(path.read_text(encoding="utf-8")).words for path in (CORPUS / "v4").rglob("*.mnt")}
    assert {name: words for name, words in shown.items() if words} == {}


def test_the_command_leaves_the_v3_file_as_it_was_and_exits_2(tmp_path: Path) -> None:
    program = tmp_path / "old.mnt"
    program.write_text(V3_PROGRAM, encoding="utf-8")
    outcome = CliRunner().invoke(command, ["--to", "mintmt", "--write", str(program)])
    assert outcome.exit_code == 2
    assert "this is Mint v3 (HMSPEED, GEARN, CONTON, DINT, EINT, #FASTPOS): migrate it to v4 first" in outcome.output
    assert program.read_text(encoding="utf-8") == V3_PROGRAM


def test_the_command_refuses_a_v3_program_whose_only_v3_word_is_a_constant(tmp_path: Path) -> None:
    program = tmp_path / "template.mnt"
    program.write_text("CONFIG = _servo, _servo\nSPEED = 20\n", encoding="utf-8")
    outcome = CliRunner().invoke(command, ["--to", "mintmt", "--format", "json", str(program)])
    assert outcome.exit_code == 2
    assert "this is Mint v3 (_SERVO): migrate it to v4 first" in outcome.output
    assert program.read_text(encoding="utf-8") == "CONFIG = _servo, _servo\nSPEED = 20\n"


# What mint-migrate leaves of v3 for a person: CARD, which v4 reads as NODE, assigned (v3 could only read it)
FLAGGED = "REM MIGRATE: S-CARD: CARD can only be read (v4: NODE)\nCARD = 2\n"


def test_v3_left_on_lines_the_migration_flagged_asks_for_those_items_not_a_migration() -> None:
    """Migrating again would change nothing: what is left is the REM MIGRATE items to deal with."""
    with pytest.raises(MigrationFailed) as failed:
        to_mintmt(FLAGGED)
    assert str(failed.value) == (
        "failed: still Mint v3 (CARD) on lines mint-migrate flagged: deal with their REM MIGRATE items first"
    )


def test_v3_on_a_line_nobody_flagged_still_asks_for_the_migration() -> None:
    with pytest.raises(MigrationFailed, match=r"this is Mint v3 \(CARD, HMSPEED\): migrate it to v4 first"):
        to_mintmt(FLAGGED + "HMSPEED = 10\n")
