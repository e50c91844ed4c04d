"""A write of a keyword M-REN renames to a v4 name longer than ten characters still counts for the notes.

The notes read the text the renames made, where the v3 reader takes ``FOLERRORFATAL = 200`` (from
``MFOLERR = 200``) for a variable, known by its first ten characters only (001:1342). The program sets
the parameter itself, so no note may say it relies on the v3 default; and a program that sets its stop
input's mode uses that input, so it needs the input assigned.
"""

from __future__ import annotations

from mintlang.migrate import migrate


def _notes(source: str, rule: str) -> list[str]:
    return [item.reason for item in migrate(source).manual if item.rule == rule]


def test_a_following_error_limit_written_without_brackets_is_not_reported_as_a_default() -> None:
    # MFOLERR = 200 sets the first default axis (001:1035-1057), the one axis MOVER moves: the v3
    # default 16000 (001:9989) is relied on nowhere
    notes = _notes("MFOLERR = 200\nMOVER = 10 : GO\n", "S-DEFAULTS")
    assert not any(note.startswith("FOLERRORFATAL") for note in notes)


def test_a_stop_mode_written_asks_for_the_stop_input() -> None:
    # STOPMODE configures what the stop input does (001:11894-11933): the program relies on that input,
    # which v4 assigns to no axis by default (000:4058-4061)
    assert "STOPINPUT[0] = <input>; : REM v3 had a stop input" in _notes(
        "STOPMODE = 2\nMOVER = 10 : GO\n", "S-PROLOGUE"
    )


def test_a_drive_enable_written_is_no_drive_enable_output_assigned() -> None:
    # S-CONFIG writes DRIVEENABLE around a CONFIG after RESET (000:8481-8482, 000:15625); that names no output,
    # which v4 leaves unassigned (000:4058-4061), though both names start with the same ten characters
    notes = _notes("RESET\nCONFIG = _servo\nMOVER = 10 : GO\n", "S-PROLOGUE")
    assert "DRIVEENABLEOUTPUT[0] = <output>; : REM v3 amplifier enable was dedicated; -1 if none is wired" in notes
