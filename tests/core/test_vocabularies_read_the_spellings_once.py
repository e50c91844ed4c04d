"""The lexer's vocabulary (any controller) and the parser's (the checked controller's) differ only in
which keyword a shared abbreviation names: a fresh check reads each keyword's spelling from the database
once for both, in a process that does nothing else."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

_CHECK_AND_COUNT_THE_READINGS = """
import json, mintlang
from mintlang.keyworddb.load import KeywordDatabase
read = []
original = KeywordDatabase.spellings_of
def counted(self, dialect):
    read.append(dialect.value)
    return original(self, dialect)
KeywordDatabase.spellings_of = counted
mintlang.check("SPEED = 10", dialect="{dialect}", controller="nextmove-bx")
print(json.dumps(read))
"""


@pytest.mark.parametrize("dialect", ["v4", "mintmt"])
def test_a_check_reads_the_spellings_once(dialect: str) -> None:
    command = [sys.executable, "-c", _CHECK_AND_COUNT_THE_READINGS.replace("{dialect}", dialect)]
    read = json.loads(subprocess.run(command, capture_output=True, text=True, check=True).stdout)
    assert read == [dialect]
