"""Every keyword of both dialects, bare, assigned and read, migrates without a crash, and the
result is stable: migrating it again changes nothing.

The words come from the keyword database the migrator itself reads
(``mintlang.keyworddb``: the v3 guide's keywords, ``keywords_v3.json`` with its extras,
and the v4 guide's chapter 10), names and abbreviations alike, since the v3
abbreviations that name other v4 keywords are where the dialects collide (spec §9). Each
form is migrated for a four-axis NextMove PCI and a one-axis MintDrive, the two ends of
what the rules ask of the target (about 5,000 migrations, a few seconds).
"""

from __future__ import annotations

import pytest

from mintlang.keyworddb import database
from mintlang.migrate import migrate
from tests.migrate.helpers import every_word

CONTROLLERS = ("nextmove-pci", "mintdrive")


WORDS = every_word()


def test_the_sweep_covers_both_dialects() -> None:
    db = database()
    assert {"HMSPEED", "CONTON", "ZERO", "DE", "MA"} <= set(WORDS)  # v3 only, v3 abbreviations
    assert {"HOMESPEED", "DECELTIME", "MASTERCHANNEL", "DCL"} <= set(WORDS)  # v4 only, a v4 abbreviation
    assert len(WORDS) >= len(db.v3_keywords) + len(db.keywords) - len(set(db.v3_keywords) & set(db.keywords))


@pytest.mark.parametrize("word", WORDS)
def test_bare_assigned_and_read_forms_migrate_to_a_fixed_point(word: str) -> None:
    for controller in CONTROLLERS:
        for form in (word, f"{word} = 1", f"x = {word}"):
            first = migrate(f"{form}\n", controller=controller)
            again = migrate(first.text, controller=controller)
            assert again.text == first.text, f"{form!r} on {controller}: a second run changed the result"
