"""A v3 command written with a value (``SERVOC = 4000,4000``) is kept as written and flagged, not rewritten.

ZERO, SERVOC, SERVOFF, CONTON, DINT, PON and the other statement rules' keywords are commands in Mint v3:
their format takes no value (``ZERO[axes]``, 001:12838-12841; ``SERVOC[axes]``, 001:11637-11640), and
writing one is the v3 error "Read only or Command" (001:13082-13084). Such a line was broken on the v3
controller already; rewriting it as the command (``CANCEL : DRIVEENABLE = 1;``) dropped the value the
user wrote without a word, typically a misremembered abbreviation (``SC`` is SERVOC, not SCALE: SCALE's
is SF, 001:11578).
"""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate

WRITTEN = [
    ("M-ZERO", "ZERO = 5\n", "ZERO"),
    ("S-SERVOC", "SC = 4000, 4000\n", "SERVOC"),
    ("S-SERVOFF", "SERVOFF.1 = 3\n", "SERVOFF"),
    ("S-CONT", "CONTON = 2\n", "CONTON"),
    ("S-INT", "DINT = 1\n", "DINT"),
    ("S-LIMIT", "DISLIMIT = 1\n", "DISLIMIT"),
    ("S-ECHO", "PON = 1\n", "PON"),
    ("M-NOTAVAIL", "COMMSON = 1\n", "COMMSON"),
]


@pytest.mark.parametrize(("rule", "source", "word"), WRITTEN)
def test_the_line_is_kept_and_flagged(rule: str, source: str, word: str) -> None:
    result = migrate(source, only=[rule])
    assert result.text == f"REM MIGRATE: {rule}: not valid Mint v3 either: {word} is a command, no value\n{source}"
    assert [(item.rule, item.line) for item in result.manual] == [(rule, 2)]


def test_the_command_itself_is_still_rewritten() -> None:
    # ZERO[axes] becomes POS[axes] = 0; (M-ZERO, v4:17428); SERVOC.1 CANCEL.1 with the drive enabled (S-SERVOC)
    assert migrate("ZERO.1\nSC.1\n", only=["M-ZERO", "S-SERVOC"]).text == "POS.1 = 0\nCANCEL.1 : DRIVEENABLE.1 = 1\n"
