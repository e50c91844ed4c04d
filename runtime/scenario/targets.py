"""What an expectation looks at: a keyword, a variable or an array element, spelt one way.

Users write ``pos.0``, ``PS.0`` or ``OUT3``; the simulator should answer one
spelling only, so every target is made canonical here: upper case, the
keyword's full name, an axis or channel as ``.n`` and indexes as ``(i,j)``.
A Mint v3 program's targets are its own keywords (``MODE.0``, ``GN.1``, ``IN3``). An axis may also be given
in square brackets, as programs give it (``IDLE[0]`` is ``IDLE.0``: 000:196-210, 556-557; 001:649-667);
a channel takes only the dot (000:560) and an array's index round brackets (000:1063-1066).
"""

from __future__ import annotations

import re

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Addressing, Keyword, KeywordKind, V3Keyword
from mintlang.records import record
from mintlang.runtime.scenario.problems import Invalid

_TARGET = re.compile(
    r"(?P<name>[A-Za-z_][A-Za-z0-9_]*)"
    r"(?:\.(?P<dot>[0-9]+)(?:\.(?P<index>[0-9]+))?|\((?P<indexes>\s*-?[0-9]+\s*(?:,\s*-?[0-9]+\s*)*)\)"
    r"|\[(?P<axes>\s*[0-9]+\s*(?:,\s*[0-9]+\s*)*)\])?"
)
_GLUED_CHANNEL = re.compile(r"[0-9]+$")
_NOT_A_TARGET = "{written!r} is not a keyword, variable or array element (e.g. POS.0, count, table(3))"


@record
class Target:
    """A canonical target; ``every_axis`` when an axis keyword was written without its axis. ``shown`` is how
    reports name it: a variable as the program spells it (``myCount``), a keyword by its full name."""

    text: str
    every_axis: bool
    shown: str = ""

    @property
    def name(self) -> str:
        return self.shown or self.text

    def on_axis(self, axis: int) -> str:
        return f"{self.text}.{axis}"


def target(written: str, dialect: Dialect = Dialect.V4) -> Target:
    """The canonical form of ``written`` in a program of ``dialect``, or ``Invalid`` saying why it names
    nothing readable."""
    found = _TARGET.fullmatch(written.strip())
    if found is None:
        raise Invalid(_NOT_A_TARGET.format(written=written))
    name, indexes = found["name"].upper(), found["indexes"]
    suffix = "" if indexes is None else "(" + ",".join(str(int(i)) for i in indexes.split(",")) + ")"
    if dialect is Dialect.V3:
        v3_keyword = database().lookup_v3(name)
        return _v3_target(found["name"], name, _dot(found, v3_keyword), suffix)
    db = database()
    keyword = (db.mintmt_keywords.get(name) if dialect is Dialect.MINTMT else None) or db.lookup(name)
    if keyword is not None and keyword.indices:
        return _indexed(keyword, found)
    if found["index"] is not None:  # a second dot is a MintMT keyword's index (CONTOURPARAMETER.0.0) only
        raise Invalid(_NOT_A_TARGET.format(written=written))
    dot = _dot(found, keyword)
    if keyword is None:
        return _variable(found["name"], name, dot, suffix)
    if keyword.kind is not KeywordKind.PARAMETER:
        raise Invalid(f"{keyword.name} is a {keyword.kind.value}, not a value to expect")
    _on_this_node(keyword, indexes)
    if suffix and dialect is Dialect.V4 and not keyword.parameters:
        raise Invalid(_round_brackets_refused(keyword, suffix))
    spellings = {keyword.name.upper(), *(abbreviation.upper() for abbreviation in keyword.abbreviations)}
    glued = _GLUED_CHANNEL.search(name) if name not in spellings else None
    if glued is not None:
        dot = glued[0]
    if dot is not None and keyword.addressing is Addressing.NONE:
        raise Invalid(f"{keyword.name} has no axis or channel, so it takes no .{dot}")
    if dot is not None:
        return Target(f"{keyword.name}.{int(dot)}{suffix}", every_axis=False)
    every_axis = keyword.addressing is Addressing.AXIS and not suffix
    return Target(keyword.name + suffix, every_axis)


def _indexed(keyword: Keyword, found: re.Match[str]) -> Target:
    """A MintMT keyword whose brackets give its axis and then its indices, read as the program reads it: one axis
    and every index, ``CONTOURPARAMETER(0,0)`` or the note's ``CONTOURPARAMETER.0.0`` (004:223; MT-11)."""
    form = f"{keyword.name}(axis, {', '.join(keyword.indices)})"
    if not any(row.read for row in keyword.attributes):
        raise Invalid(f"{keyword.name} is only written, so it is not a value to expect")
    if found["dot"] is not None:
        values = [found["dot"]] if found["index"] is None else [found["dot"], found["index"]]
    else:
        values = found["indexes"].split(",") if found["indexes"] is not None else []
    if len(values) != 1 + len(keyword.indices):
        raise Invalid(f"{keyword.name} reads one axis and its {', '.join(keyword.indices)}: write {form}")
    axis, *indices = (int(value) for value in values)
    listed = ",".join(map(str, indices))
    return Target(f"{keyword.name}.{axis}({listed})", every_axis=False, shown=f"{keyword.name}({axis},{listed})")


def _on_this_node(keyword: Keyword, indexes: str | None) -> None:
    """Refuse a network node before the index, ``COMMS(4,130)`` (000:2553-2559, 2670-2672): a run simulates one
    controller, whose own element is written without one."""
    values = [int(index) for index in indexes.split(",")] if indexes is not None else []
    if keyword.parameters[:1] == ("node?",) and len(values) == len(keyword.parameters):
        node, local = values[0], ",".join(map(str, values[1:]))
        remote = f"{keyword.name}({node},{local}) reads node {node} over the network"
        raise Invalid(f"{remote}, and a run simulates one controller: expect {keyword.name}({local})")


def _round_brackets_refused(keyword: Keyword, suffix: str) -> str:
    """What a v4 keyword that takes no index is told of ``IDLE(0)``: round brackets give an array's index
    (000:1063-1066), so the value read would not be the axis or channel meant (``IN(3)`` read the whole bank)."""
    first = suffix[1:-1].split(",", maxsplit=1)[0]
    if keyword.addressing is Addressing.AXIS:
        instead = f"its axis goes after a dot or in square brackets, {keyword.name}.{first} or {keyword.name}[{first}]"
    elif keyword.addressing is Addressing.CHANNEL:
        instead = f"its channel goes after a dot, {keyword.name}.{first}"
    else:
        return f"{keyword.name} has no axis, channel or index, so it takes no {suffix}"
    return f"{keyword.name}{suffix}: {instead}; round brackets give an array's index"


def _dot(found: re.Match[str], keyword: Keyword | V3Keyword | None) -> str | None:
    """The axis or channel written after a dot, or the one axis in square brackets (``IDLE[0]``); why not, for
    brackets that give no one axis of an axis keyword."""
    if found["axes"] is None:
        return found["dot"]
    written, axes = found["name"], [int(axis) for axis in found["axes"].split(",")]
    listed = ",".join(map(str, axes))
    if keyword is None:
        raise Invalid(f"{written}[{listed}]: an array's element is written {written}({listed}), in round brackets")
    if keyword.addressing is Addressing.CHANNEL or (isinstance(keyword, V3Keyword) and _has_bits(keyword)):
        raise Invalid(f"{keyword.name} takes its channel after a dot, {keyword.name}.{axes[0]}, not in brackets")
    if keyword.addressing is Addressing.NONE:
        indexed = isinstance(keyword, Keyword) and keyword.parameters  # COMMS(5): an element, in round brackets
        instead = f": write {keyword.name}({listed})" if indexed else ""
        raise Invalid(f"{keyword.name} has no axis or channel, so it takes no [{listed}]{instead}")
    if len(axes) > 1:
        each = ", ".join(f"{keyword.name}.{axis}" for axis in axes)
        raise Invalid(
            f"{keyword.name}[{listed}] reads its axes as one value: expect each axis on its own ({each}), "
            f"or {keyword.name} alone for every axis"
        )
    return str(axes[0])


def _variable(written: str, name: str, dot: str | None, suffix: str) -> Target:
    if dot is not None:
        raise Invalid(f"{written} is not a keyword, so it takes no .{dot}")
    return Target(name + suffix, every_axis=False, shown=written + suffix)


def _v3_target(written: str, name: str, dot: str | None, suffix: str) -> Target:
    """A v3 keyword by its v3 name; ``IN`` and ``OUT``, which have bit keywords (``IN3``), take a bit as ``.n``."""
    keyword = database().lookup_v3(name)
    if keyword is None:
        return _variable(written, name, dot, suffix)
    if not keyword.read:
        raise Invalid(f"{keyword.name} cannot be read in Mint v3, so it is not a value to expect")
    if dot is not None and keyword.addressing is Addressing.NONE and not _has_bits(keyword):
        raise Invalid(f"{keyword.name} has no axis or channel, so it takes no .{dot}")
    if dot is not None:
        return Target(f"{keyword.name}.{int(dot)}{suffix}", every_axis=False)
    return Target(keyword.name + suffix, keyword.addressing is Addressing.AXIS and not suffix)


def _has_bits(keyword: V3Keyword) -> bool:
    return database().lookup_v3(keyword.name + "0") is not None
