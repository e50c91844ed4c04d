"""A program already ported to Mint v4 by hand is left alone even where the rules would rewrite it.

A plant's folder often holds programs ported by hand beside v3 originals. Such a program may hold
what a v3 rule rewrites: ``SIN`` read as v4 reads it (v4 guide, SIN: the sine itself, where v3's
was 1000 times it) and ``ACCEL`` without ``DECEL``. Migrating it again would scale the sine by 1000
and add a ``DECEL`` nobody wrote. A form v3 could not have written (a scalar ``DIM``: the v3 guide's
DIM declares arrays only, with their size; a v4-only keyword with an axis, as a command or read)
with no error in Mint v4 makes it v4. A v4-only keyword only ever assigned is also what a v3 variable
of that name looks like, so it does not.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from mintlang.migrate import migrate
from mintlang.migrate.recognise import Evidence, may_show_v4_beyond_doubt, v4_evidence
from mintlang.semantic.units import Unit
from tests.migrate.helpers import every_word

HAND_PORTED = (
    "AXES[0,1]\n"
    "DIM i\n"
    "SCALE = 500,500\n"
    "SPEED = 30,30\n"
    "ACCEL = 500,500\n"
    "DRIVEENABLE[0,1] = 1\n"
    "FOR i = 1 TO 4\n"
    "  MOVER = 10,10 : GO\n"
    "  PAUSE IDLE[0,1]\n"
    '  PRINT "angle ", SIN(i * 10)\n'
    "NEXT\n"
)


@pytest.mark.parametrize(
    "program",
    [
        pytest.param(HAND_PORTED, id="scalar DIM, SIN and ACCEL as v4 reads them"),
        pytest.param("HOMESPEED.0 = 10\nACCEL = 500\n", id="v4-only keyword with an axis, ACCEL alone"),
        pytest.param("DIM a = 30\nPRINT SIN(a)\n", id="scalar DIM with a value"),
    ],
)
def test_a_valid_v4_program_with_a_form_v3_could_not_have_written_is_left_alone(program: str) -> None:
    result = migrate(program)
    assert result.already_v4
    assert result.text == program and not result.changes and not result.manual


def test_a_scalar_dim_beside_a_word_v4_rejects_is_migrated() -> None:
    """HMSPEED is v3's abbreviation of HOMESPEED; Mint v4 does not know it, so the file is not v4."""
    result = migrate("DIM a\nHMSPEED.0 = 10\n")
    assert not result.already_v4
    assert "HOMESPEED.0 = 10" in result.text


def test_a_v4_keyword_only_assigned_is_a_v3_variable_where_rules_rewrite() -> None:
    """``homespeed = 10`` alone is how a v3 user variable named homespeed looks: the SIN is v3's."""
    result = migrate("homespeed = 10\nPRINT SIN(30)\n")
    assert not result.already_v4
    assert "(SIN(30) * 1000)" in result.text


def test_a_spelling_both_versions_know_is_no_sign_of_v4() -> None:
    """``DE`` abbreviates v3's DECEL and v4's DRIVEENABLE (v4 guide, DRIVEENABLE): a v3 program's
    ``DE.0 = 1`` is a deceleration, and is migrated as one."""
    result = migrate("DIM x(2)\nDE.0 = 1\n")
    assert not result.already_v4
    assert "DECEL.0 = 1" in result.text


def _programs() -> list[str]:
    tests = Path(__file__).parent.parent
    files = sorted((tests / "corpus").rglob("*.mnt")) + sorted((tests / "conformance").rglob("*.mnt"))
    programs = [path.read_text(encoding="utf-8", errors="replace") for path in files]
    for word in every_word():
        programs += [f"{word}\n", f"{word}.0 = 1\n", f"DIM x\nx = {word}\n", f"{word} = 1\nPRINT {word}\n"]
    return programs


def test_the_quick_look_never_misses_a_form_beyond_doubt() -> None:
    """The look at the words that spares most v3 files a v4 reading is never false where that
    reading finds a form beyond doubt, on every corpus and conformance program and every keyword of
    both versions in four forms."""
    missed = [
        program[:60]
        for program in _programs()
        if v4_evidence({Unit.PROGRAM: program}, "nextmove-pci") is Evidence.BEYOND_DOUBT
        and not may_show_v4_beyond_doubt({Unit.PROGRAM: program}, "nextmove-pci")
    ]
    assert missed == []
