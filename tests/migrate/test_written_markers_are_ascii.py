"""What a migration writes into a file is ASCII, so a file keeps its encoding: a marker
with an ellipsis (U+2026) would put the bytes E2 80 A6 into an ASCII file, or 0x85 into a cp1252 one.

Every v4 program of the corpus is migrated: its result has no non-ASCII character its source does not have."""

from __future__ import annotations

from collections import Counter

from mintlang.migrate import migrate
from mintlang.migrate.mintmt import to_mintmt
from tests.corpus_files import CORPUS

# One of each form the notes show no MintMT form of, so that every flag's reason is written.
FLAGGED = """\
DIM x
WHILE x < 3
  x = x + 1
ENDW
REPEAT
  x = x - 1
UNTIL x = 0
GOSUB sub
IF x > 0 DO : x = 1
AXES[0,1]
END
#sub
RETURN
#IN0
RETURN
"""


def _non_ascii(text: str) -> Counter[str]:
    return Counter(character for character in text if not character.isascii())


def test_every_flag_the_migration_to_mintmt_writes_is_ascii() -> None:
    result = to_mintmt(FLAGGED)
    assert len(result.manual) >= 5
    assert all(item.reason.isascii() for item in result.manual)


def test_the_migration_adds_no_character_outside_ascii_to_any_v4_program_of_the_corpus() -> None:
    """Comments' text is copied as it was; a character constant in typographic quotes (``‘Y’``, as the
    guide prints it) becomes its code, so the result may have fewer non-ASCII characters, never more."""
    for path in sorted((CORPUS / "v4").rglob("*.mnt")):
        source = path.read_text(encoding="utf-8")
        assert not _non_ascii(to_mintmt(source).text) - _non_ascii(source), path


def test_the_migration_to_v4_adds_no_character_outside_ascii_to_any_v3_program_of_the_corpus() -> None:
    """Citations in markers and in the lines the migrator writes say 'section 10.3', not '§10.3'
    (COMMSON's removal note put U+00A7 into ASCII listings)."""
    for path in sorted((CORPUS / "v3").rglob("*.mnt")):
        source = path.read_text(encoding="utf-8")
        configuration = path.with_suffix(".cfg")
        config = configuration.read_text(encoding="utf-8") if configuration.exists() else None
        result = migrate(source, config=config)
        assert not _non_ascii(result.text) - _non_ascii(source), path
