"""The dialects ``mint-run`` runs: Mint v4 (the reference) and Mint v3 (the older guide's language)."""

from __future__ import annotations

from mintlang.dialect import Dialect
from mintlang.runtime.dialects.v3.semantics import V3
from mintlang.runtime.dialects.v4 import V4
from mintlang.runtime.semantics import Semantics

_SEMANTICS = {Dialect.V3: V3, Dialect.V4: V4}


def semantics(dialect: Dialect | str) -> Semantics:
    """What ``dialect`` means by a program's numbers, names and messages."""
    return _SEMANTICS[Dialect(dialect)]
