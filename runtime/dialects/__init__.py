"""The dialects ``mint-run`` runs: Mint v4 (the reference), Mint v3 (the older guide's language) and MintMT."""

from __future__ import annotations

from mintlang.dialect import Dialect
from mintlang.runtime.dialects.mintmt import MINTMT
from mintlang.runtime.dialects.v3.semantics import V3
from mintlang.runtime.dialects.v4 import V4
from mintlang.runtime.semantics import Semantics

_SEMANTICS = {Dialect.V4: V4, Dialect.V3: V3, Dialect.MINTMT: MINTMT}
SIMULATED = tuple(_SEMANTICS)


def semantics(dialect: Dialect | str) -> Semantics:
    """What ``dialect`` means by a program's numbers, names and messages (ValueError for one not simulated)."""
    found = _SEMANTICS.get(Dialect(dialect))
    if found is None:
        raise ValueError(f"{Dialect(dialect).value} programs are not simulated yet: mint-run runs v4 and v3")
    return found
