"""What each code means, grouped by the kind of problem; one module a group."""

from __future__ import annotations

from mintlang.ruledocs.catalogue import (
    addressing,
    arithmetic,
    files,
    flow,
    keywords,
    limits,
    names,
    suppression,
    syntax,
)
from mintlang.ruledocs.model import Group

GROUPS: tuple[Group, ...] = (
    syntax.GROUP,
    keywords.GROUP,
    addressing.GROUP,
    names.GROUP,
    flow.GROUP,
    arithmetic.GROUP,
    limits.GROUP,
    suppression.GROUP,
    files.GROUP,
)
