"""A check of Mint v4 builds only v4's keywords and constants from the keyword database; the rest
(v3's keywords, constants and renames, MintMT's own words, the errors) is built when first asked for,
once, and each lookup then answers with the records of its table."""

from __future__ import annotations

import json
import subprocess
import sys

from mintlang.keyworddb import database

_CHECK_AND_LIST_WHAT_WAS_BUILT = """
import json, mintlang
from mintlang.keyworddb import database
mintlang.check("SPEED = 10")
print(json.dumps(sorted(vars(database()))))
"""

BUILT_WHEN_ASKED = (
    "errors",
    "v3_keywords",
    "v3_constants",
    "renames",
    "mintmt_keywords",
    "mintmt_constants",
    "_v3_words",
    "_old_words",
)


def test_a_v4_check_builds_none_of_the_other_tables() -> None:
    command = [sys.executable, "-c", _CHECK_AND_LIST_WHAT_WAS_BUILT]
    built = json.loads(subprocess.run(command, capture_output=True, text=True, check=True).stdout)
    assert {"keywords", "constants"} <= set(built)
    assert [name for name in BUILT_WHEN_ASKED if name in built] == []


def test_a_table_built_when_asked_is_built_once_and_its_lookups_answer_from_it() -> None:
    db = database()
    assert db.v3_keywords is db.v3_keywords
    assert db.lookup_v3("hmspeed") is db.v3_keywords["HMSPEED"]  # v3:8618 "HMSPEED/HS"
    rename = db.rename_of(db.renames[0].old)
    assert rename is db.renames[0]
