"""Typed records of the keyword database.

The JSON files beside this module are generated from the manuals by
``tools/keyworddb``; these frozen dataclasses are the only shape the rest of the
project sees, so the generator and the consumers agree on one contract.
"""

from __future__ import annotations

import re
from enum import StrEnum

from mintlang.records import record

_ADDRESSING = re.compile(r"\[[^\]]*\]|\{#<terminal>\}|\{?\.<[^>]*>\}?")  # [axes], {#<terminal>}, .<channel>


def _writes(layout: str, name: str) -> bool:
    """Whether a format gives ``name`` a value (``WAIT = <expression>``), rather than reading it (``v = WAIT``)."""
    return layout.strip().upper().startswith(name) and "=" in layout


class Controller(StrEnum):
    """Controllers the Mint v4 reference guide documents."""

    NEXTMOVE_PCI = "nextmove-pci"
    NEXTMOVE_PC = "nextmove-pc"
    NEXTMOVE_BX = "nextmove-bx"
    MINTDRIVE = "mintdrive"
    SERVONODE51 = "servonode51"


NEXTMOVES = frozenset({Controller.NEXTMOVE_PCI, Controller.NEXTMOVE_PC, Controller.NEXTMOVE_BX})
"""The NextMove cards, which share restrictions MintDrive and ServoNode 51 do not have."""


class Addressing(StrEnum):
    """What the dot parameter or bracket list of a keyword selects."""

    AXIS = "axis"
    CHANNEL = "channel"
    NONE = "none"


CIRCLES = frozenset({"CIRCLEA", "CIRCLER"})
"""The axis keywords given more values than axes: a centre on each of two axes and an angle (000:8152, 8215)."""

CIRCLE_AXES = 2
"""The axes a circle moves, ``CIRCLEA[axis0,axis1]`` (000:8152, 8215): one listed is too few, three too many."""

VECTORS = frozenset({"VECTORA", "VECTORR"})
"""The straight lines interpolated through two axes or more (000:16958, 17031: at least two must be given)."""


class Use(StrEnum):
    """How a keyword is used where it is written."""

    READ = "read"  # inside an expression
    WRITE = "write"  # KW = value
    COMMAND = "command"  # KW or KW args as a statement


class KeywordKind(StrEnum):
    """How a keyword takes part in the grammar."""

    PARAMETER = "parameter"  # read and/or written value, e.g. SPEED, POS, IN
    COMMAND = "command"  # does something, e.g. GO, STOP, LOCATE
    FUNCTION = "function"  # returns a value from bracketed arguments, e.g. SIN, POW
    OPERATOR = "operator"  # AND, OR, XOR, NOT, MOD
    STATEMENT = "statement"  # block and flow words: IF, FOR, GOSUB, DIM, PRINT, REM ...
    EVENT = "event"  # reserved labels: #ONERROR, #IN0 .. #INx ...
    COMMAND_LINE = "command_line"  # only valid at the command line: NEW, EDIT, LIST ...


@record
class ValueRange:
    """A keyword's accepted values as the attributes table prints them."""

    text: str
    minimum: float | None
    maximum: float | None
    fractional: bool  # the printed range has a decimal part, so fractions are accepted
    minimum_included: bool = True  # "0 < x" leaves the bound out
    maximum_included: bool = True  # "x < 4096" likewise
    allowed: tuple[float, ...] | None = None  # a mode's values where they are no range: "0 .. 4, 6"

    def holds(self, value: float) -> bool:
        """Whether ``value`` lies in the range (True when a bound is not known)."""
        if self.allowed is not None:
            return value in self.allowed
        above = self.minimum is None or value > self.minimum or (self.minimum_included and value == self.minimum)
        below = self.maximum is None or value < self.maximum or (self.maximum_included and value == self.maximum)
        return above and below


@record
class Attributes:
    """One row of a keyword's attributes table, for the controllers it names."""

    controllers: tuple[Controller, ...]
    read: bool
    write: bool
    command: bool
    multi_axis: bool
    scaled: bool
    default: str | None
    range: ValueRange | None


@record
class Keyword:
    """A Mint v4 keyword from chapter 10 of the reference guide."""

    name: str
    abbreviations: tuple[str, ...]
    kind: KeywordKind
    addressing: Addressing
    channel_suffix: bool  # also written with the channel glued on: IN3, OUT1, ADC0
    parameters: tuple[str, ...]  # bracketed arguments, e.g. POW -> ("x", "y")
    attributes: tuple[Attributes, ...]
    controllers: tuple[Controller, ...]
    formats: tuple[str, ...]
    constants: tuple[str, ...]
    see_also: tuple[str, ...]
    summary: str  # our own words, for hover
    documented: bool  # False for keywords only listed (advanced and CAN stubs)
    line: int  # line of the entry in ``manual``
    notes: tuple[str, ...]  # conflicts the manual itself contains about this keyword
    indices: tuple[str, ...] = ()  # MintMT: what follows the axes in its brackets, CONTOURPARAMETER(axes, index)
    manual: str = "000"  # the seed manual the entry comes from: 000 the v4 guide, 004/002 the MintMT notes

    @property
    def takes_operands(self) -> bool:
        """Whether a documented format has operands after the axes (``LOCATE 1,2`` yes, ``STOP[axes]`` no);
        a keyword without a documented format is given the benefit of the doubt."""
        if not self.formats:
            return True
        for layout in self.formats:
            text = layout.strip()
            if not text.upper().startswith(self.name):
                return True
            if _ADDRESSING.sub("", text[len(self.name) :]).strip():
                return True
        return False

    @property
    def one_value_a_write(self) -> bool:
        """Whether a write gives the keyword one value: a channel keyword addresses one channel a call
        (000:547-548), and its format writes one ``<expression>`` (``OUT.x = <expression>``); so does a parameter
        that addresses nothing (``TIMEREVENT = <expr>``, 000:16777). DAC, whose format shows more and whose
        table ticks Multi-Axis, and DACLIMITMAX, whose table ticks it too, are left alone."""
        if any(row.multi_axis for row in self.attributes) or any("{," in f.replace(" ", "") for f in self.formats):
            return False
        if self.addressing is Addressing.NONE:
            return self.kind is KeywordKind.PARAMETER and any(_writes(layout, self.name) for layout in self.formats)
        return self.addressing is Addressing.CHANNEL

    def available_on(self, controller: Controller) -> bool:
        """Whether ``controller`` has the keyword: its "Controllers Supported" list names it, or lists none."""
        return not self.controllers or controller in self.controllers

    def attributes_for(self, controller: Controller) -> Attributes | None:
        """The attributes row that applies to ``controller``, if the manual gives one."""
        for row in self.attributes:
            if controller in row.controllers:
                return row
        return None


@record
class Spelling:
    """How a keyword is written and what the lexer makes of it, read from its entry without building its
    ``Keyword``: the lexer's vocabulary reads every keyword's spellings, a one-line check few records."""

    name: str
    abbreviations: tuple[str, ...]
    kind: KeywordKind
    takes_arguments: bool  # has bracketed parameters
    channel_suffix: bool
    indices: int  # how many items of its brackets follow the axes (MintMT)


@record
class Constant:
    """A predefined constant (``_TRUE``, ``_hmPOSITIVE_SWITCH`` ...)."""

    name: str
    value: float
    keyword: str | None  # the keyword whose entry defines it; None for general constants
    line: int


class ErrorKind(StrEnum):
    MML = "mml"  # motion library errors 0 .. 108
    MINT = "mint"  # language errors 500 .. 502, 2000 .. 2021, 3000 .. 3007


@record
class ErrorCode:
    code: int
    kind: ErrorKind
    title: str  # the short title as the controller reports it
    constant: str | None  # e.g. _erINVALID_AXIS
    line: int


class MigrationClass(StrEnum):
    NONE = "none"  # unchanged in v4
    MECHANICAL = "mechanical"
    SEMI = "semi"
    MANUAL = "manual"


@record
class V3Keyword:
    """A keyword of the Mint v3 programming guide and what became of it in v4."""

    name: str
    abbreviations: tuple[str, ...]
    read: bool
    write: bool
    command: bool
    addressing: Addressing
    function: bool  # called with its argument in brackets, as PEEK(10) (v3:10732)
    v4_names: tuple[str, ...]  # the v4 keyword(s) it maps to; empty when removed
    status: str  # "same", "renamed", "replaced", "removed", "changed"
    migration: MigrationClass
    line: int  # line of the entry in the v3 guide
    formats: tuple[str, ...] = ()  # as its entry's Format section prints them (v3 and v4 differ: AUXDAC)

    @property
    def ticked(self) -> bool:
        """Whether the attributes table ticks any of read, write and command: an entry that ticks none says
        nothing of how the keyword may be used."""
        return self.read or self.write or self.command


@record
class Rename:
    """One of the old keywords the v4 guide marks as replaced or removed."""

    old: str
    old_abbreviation: str | None
    new: tuple[str, ...]  # empty when removed without replacement
    status: str  # "replaced" or "removed"
    line: int  # line in the v4 guide


@record
class V3Constant:
    """A predefined constant of Mint v3 and its v4 counterpart, if any."""

    name: str
    value: float
    v4_name: str | None
    line: int  # line in the v3 guide
