"""MintMT as ``mint-run`` runs it: Mint v4's numbers, functions and messages with MintMT's keywords and constants.

The notes give MintMT no other arithmetic or error reporting than v4's
(mintlang/MINTMT.md, MT-1): what differs is how the program is written, which
the parser has already made v4's syntax, and its blocks (``program.py``).
"""

from __future__ import annotations

from dataclasses import replace

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Addressing
from mintlang.runtime.dialects.v4 import V4

_KEYWORDS = database().keywords_of(Dialect.MINTMT)

MINTMT = replace(
    V4,
    dialect=Dialect.MINTMT,
    constants={name.upper(): float(record.value) for name, record in database().constants_of(Dialect.MINTMT).items()},
    axis_keywords=frozenset(name for name, record in _KEYWORDS.items() if record.addressing is Addressing.AXIS),
    one_value_keywords=frozenset(name for name, record in _KEYWORDS.items() if record.one_value_a_write),
)
