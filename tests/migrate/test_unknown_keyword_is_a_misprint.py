"""X-V3 does not call a word "Mint v3 only" when no Mint v3 keyword has that name.

The v3 guide's HOME example starts ``HMPSEED.2 = 10`` (v3:8708): HMSPEED (v3:8618-8627)
misprinted. HMPSEED is a keyword of neither version, so telling the reader it is "Mint v3 only"
sends them looking for a v3 keyword that does not exist (the spec's X-COMMENTED row: report a
listing's misprint, do not "fix" it). The marker says the word is unknown and may be a misprint.
"""

from __future__ import annotations

from mintlang.migrate import migrate
from tests.migrate.helpers import flagged

_GUIDE = "HMPSEED.2 = 10\nBACKOFF.2 = 5\nHOME.2 = 1\n"  # v3:8708-8710
_UNKNOWN = "HMPSEED is no Mint v3 or v4 keyword the migrator knows (misprint?): no automatic rewrite"


def test_the_misprinted_keyword_is_not_called_a_v3_keyword() -> None:
    assert flagged("X-V3", "HMPSEED.2 = 10\n") == [_UNKNOWN]


def test_a_v3_keyword_written_the_same_way_still_is() -> None:
    # HMSPEED is the v3 keyword (v3:8618); alone, X-V3 flags it as v3 only (M-REN renames it otherwise)
    assert flagged("X-V3", "HMSPEED.2 = 10\n") == ["HMSPEED is Mint v3 only: no automatic rewrite"]


def test_the_guide_example_gets_one_item_on_the_misprint_and_its_renames_on_the_rest() -> None:
    result = migrate(_GUIDE)
    assert [(item.rule, item.original_line) for item in result.manual if not item.note] == [("X-V3", 1)]
    # BACKOFF -> HOMEBACKOFF (M-REN, v4:7312); the misprint stays as it was under its marker
    assert result.text.endswith(f"REM MIGRATE: X-V3: {_UNKNOWN}\nHMPSEED.2 = 10\nHOMEBACKOFF.2 = 5\nHOME.2 = 1\n")
