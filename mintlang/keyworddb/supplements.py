"""What the tools take of keywords the v4 guide prints no attributes table for.

Chapter 10 gives no table to a keyword whose entry defers to the Advanced guide, which has no seed
here ("This is an advanced Mint feature"), nor to a few commands, so the keyword database knows
neither its access nor its range. Where the guide says more elsewhere (the quick reference's purpose,
a chapter's text, the entry's purpose), or the runtime specification chose a range, the row below
holds it, so ``mint check`` and ``mint-run`` judge the same line the same way: a write to one read
only is error 2000 in both, a value outside the range error 3.
"""

from __future__ import annotations

from collections.abc import Mapping
from functools import cache
from types import MappingProxyType

from mintlang.controllers import io_banks, profile
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Attributes, Controller, Keyword, ValueRange

_ALL = tuple(Controller)  # each row applies wherever the keyword itself exists (its own controllers)
_ERROR_MODES = ValueRange("0 ≤ x ≤ 3, 5", None, None, False, allowed=(0.0, 1.0, 2.0, 3.0, 5.0))


def _unranged(*, write: bool) -> Attributes:
    """A parameter the guide gives no range: read only, or a setting it only ever assigns (read back as the run
    remembers it)."""
    return Attributes(
        _ALL, read=True, write=write, command=False, multi_axis=False, scaled=False, default=None, range=None
    )


def _setting(limits: ValueRange, *, scaled: bool = False) -> Attributes:
    return Attributes(
        _ALL, read=True, write=True, command=False, multi_axis=True, scaled=scaled, default=None, range=limits
    )


SUPPLEMENTS: Mapping[str, Attributes] = MappingProxyType(
    {
        # Read only: the quick reference's purpose reads them, and nothing in the guide writes them.
        "EVENTACTIVE": _unranged(write=False),  # "read which events are active" (000:18061; 4392, 4470)
        "HOMEPOS": _unranged(write=False),  # "can be read" (000:3438, 11401-11402; 17640)
        "MOVEBUFFERFREE": _unranged(write=False),  # "read free space in move buffer" (000:17689; 2978)
        # Settings: the guide's examples assign them and its quick reference's purpose sets them; so no command,
        # and one named alone is #2005, as SPEED is (000:18930-18933).
        "DACMODE": _unranged(write=True),  # DACMODE.1 = 1 (000:4188); "configures DAC output" (000:17836)
        "GEARING": _unranged(write=True),  # GEARING.0 = 100.0 (000:3746); "gearing compensation %" (000:17625)
        "GEARINGMODE": _unranged(write=True),  # GEARINGMODE.0 = 1 (000:3747); "gearing compensation mode" (000:17627)
        "KEYPADNODE": _unranged(write=True),  # KEYPADNODE._tmLCD1 = 14 (000:2077); "sets the node id" (000:18266)
        # A command that also gives a value: "To return the last known error condition" (000:13270-13282)
        "LASTERR": Attributes(_ALL, True, False, True, multi_axis=False, scaled=False, default=None, range=None),
        # Ranges of the runtime specification (the runtime's BEHAVIOUR.md, "Parameter ranges").
        "SRAMP": _setting(ValueRange("0 ≤ x ≤ 100", 0.0, 100.0, True)),  # MP-9: percent of each ramp
        # The modes of LIMITMODE's table (000:13479-13493); mode 4, _emSMART_MODE, anticipates a software
        # limit (000:16057-16068) and means nothing for a following error or an error input.
        "FOLERRORMODE": _setting(_ERROR_MODES),  # AX-10 RC
        "ERRORINPUTMODE": _setting(_ERROR_MODES),  # AX-16 RC
        "KINTMODE": _setting(ValueRange("0, 1, 2, 3", None, None, False, allowed=(0.0, 1.0, 2.0, 3.0))),  # SL-5 RC
        "KACCEL": _setting(ValueRange("0 ≤ x ≤ 10000", 0.0, 10000.0, True)),  # SL-2 RC: as KVELFF
        "IDLEPOS": _setting(ValueRange("0 ≤ x ≤ 8388607", 0.0, 8388607.0, True), scaled=True),
        "IDLEVEL": _setting(ValueRange("0 ≤ x ≤ 8388607", 0.0, 8388607.0, True), scaled=True),
        "MOVEBUFFERSIZE": _setting(ValueRange("2 ≤ x ≤ 100", 2.0, 100.0, False)),  # MP-25: 000:11053-11054
    }
)


NARROWED: Mapping[str, ValueRange] = MappingProxyType(
    {
        # "Bit 1 cannot be set without bit 0" beside the table's 0 ≤ x ≤ 3 (000:8653-8654)
        "CONTOURMODE": ValueRange("0, 1 or 3: bit 1 needs bit 0", None, None, False, allowed=(0.0, 1.0, 3.0)),
    }
)
"""Ranges an entry's text narrows below what its table prints, which both tools take instead of the table's."""


def _motor_types(*values: float) -> ValueRange:
    return ValueRange(", ".join(f"{value:g}" for value in values), None, None, False, allowed=values)


NARROWED_ON: Mapping[tuple[str, Controller], ValueRange] = MappingProxyType(
    {
        # CONFIG's motor types ticked for each NextMove (000:8431-8443), within the row's "0 - 5" for all three
        # (000:8420): stepper on PCI and PC, PWM on PC alone (its PWMONTIME, 000:17742), virtual on all three,
        # 4 "Reserved" on none. NextMove BX has no stepper outputs (000:4050-4052).
        ("CONFIG", Controller.NEXTMOVE_PCI): _motor_types(0.0, 1.0, 2.0, 5.0),
        ("CONFIG", Controller.NEXTMOVE_PC): _motor_types(0.0, 1.0, 2.0, 3.0, 5.0),
        ("CONFIG", Controller.NEXTMOVE_BX): _motor_types(0.0, 1.0, 5.0),
    }
)
"""Ranges an entry's text narrows for one controller below the row its table prints for several."""


def narrowed(keyword: str, printed: ValueRange | None, controller: Controller) -> ValueRange | None:
    """The range ``mint check`` and ``mint-run`` hold ``keyword``'s values to on ``controller`` where its table
    prints ``printed``."""
    if printed is None:
        return None
    return NARROWED_ON.get((keyword, controller), NARROWED.get(keyword, printed))


def held_range(keyword: str, row: Attributes | None, controller: Controller, dialect: Dialect) -> ValueRange | None:
    """The range ``mint check``, ``mint-run`` and hover hold ``keyword``'s values to on ``controller``, whose row
    is ``row``: the row's as ``narrowed`` gives it, or, where the row prints none (ServoNode 51's), the bank of
    inputs or outputs a pattern keyword covers (``pattern_range``)."""
    found = narrowed(keyword, row.range if row is not None else None, controller)
    if found is None and row is not None and dialect.modern:
        return pattern_range(keyword, controller)
    return found


_WHOLE_WITHOUT_CONSTANTS = frozenset({"BANK", "CAMSTART", "CAMEND", "MASTERCHANNEL", "FOLLOWDENOM", "MOVEBUFFERSIZE"})
"""Keywords whose values no fraction can mean though the guide names none with a constant: BANK's are the
cards, in its table of values (000:7345-7348); CAMSTART's and CAMEND's a cam segment (000:7807-7810),
MASTERCHANNEL's the master's channel (000:13779); FOLLOWDENOM is the denominator that keeps a follow ratio
free of fractions (000:10802-10804); MOVEBUFFERSIZE counts the moves the buffer stores (000:11053-11054),
as MintMT's row holds it. None of their ranges prints a decimal part."""


@cache
def whole_only(keyword: str, dialect: Dialect = Dialect.V4) -> bool:
    """Whether ``mint check`` and ``mint-run`` hold ``keyword``'s values to whole numbers (error 3 for a fraction).

    A keyword "will accept fractional values" where its range "specifies a decimal part (.0)"
    (000:5647-5650). The guide does not keep to that for gains (its range 0 ≤ x ≤ 10000, KDERIV = 1.5 in
    its example: 000:12755), so it is held only where the values are modes, which a fraction cannot
    select: those the entry names with predefined constants (CONFIG's motor types, FOLLOWMODE's modes,
    CAM's bits: 000:8431, 000:10846, 000:7595) and whose range prints no decimal part, and the numbers of
    ``_WHOLE_WITHOUT_CONSTANTS`` (BANK's cards, a cam segment, a master channel, a follow denominator).
    MintMT's own keywords have rows written by hand from the decisions of ``mintlang/MINTMT.md`` (the notes
    print no tables), and there a range without a decimal part means what it says: a count of buffer places,
    of milliseconds, a mode (MT-10, MT-14, MT-16, MT-22).
    """
    db = database()
    if dialect is Dialect.MINTMT and keyword in db.mintmt_keywords:
        rows = db.mintmt_keywords[keyword].attributes
        return any(row.range is not None and not row.range.fractional for row in rows)
    if keyword in _WHOLE_WITHOUT_CONSTANTS:
        return True
    record = db.keywords.get(keyword)
    if record is None or not record.constants:
        return False
    return not any(row.range is not None and row.range.fractional for row in record.attributes)


INDEXED_AS: Mapping[tuple[str, int], str] = MappingProxyType({("CONTOURPARAMETER", 0): "CONTOURANGLE"})
"""The v4 keyword a MintMT keyword writes at an index, whose row then ranges the value: the note names
CONTOURPARAMETER's index 0 alone, the inter-vector angle v4 calls CONTOURANGLE (004:223, 232; MT-11)."""


WRITTEN_AS: Mapping[str, str] = MappingProxyType({"OUTX": "OUT"})
"""The v4 keyword a MintMT keyword writes, whose row then ranges the value: ``OUTX(channel)`` is v4's
``OUT.channel`` (004:148; MINTMT.md), so ``OUTX(1) = -1`` is out of range as ``OUT.1 = -1`` is."""


INPUT_PATTERNS = frozenset({"INPUTMODE", "INPUTACTIVELEVEL", "INPUTPOSTRIGGER", "INPUTNEGTRIGGER"})
"""Bitmaps of the digital inputs, one bit an input (000:12315-12316, 12293): each row of their tables prints the
pattern of all the controller's inputs (NextMove PCI's 20 are 0 ≤ x ≤ 1048575: 000:11928, 12336)."""

OUTPUT_PATTERNS = frozenset({"OUT"})
"""Bitmaps of the digital outputs, one bit an output (OUT = 266 sets outputs 1, 3 and 8, 000:14922-14924): each row
of OUT's table prints the pattern of all the controller's outputs (NextMove BX's 8 are 0 ≤ x < 256, 000:14911)."""


def pattern_range(keyword: str, controller: Controller) -> ValueRange | None:
    """The range of an ``INPUT_PATTERNS`` or ``OUTPUT_PATTERNS`` keyword on a controller whose row prints none
    (ServoNode 51): the pattern of a bank of its inputs or outputs, as the printed rows are, from the banks
    ``mint-run`` holds the writes to (``controllers.io_banks``: 6 inputs, 0 to 63, and 3 outputs, 0 to 7,
    000:4048)."""
    banks = io_banks(profile(controller))
    if keyword in INPUT_PATTERNS:
        bits = banks.inputs
    elif keyword in OUTPUT_PATTERNS:
        bits = banks.outputs
    else:
        return None
    top = (1 << bits) - 1
    return ValueRange(f"0 ≤ x ≤ {top}", 0.0, float(top), fractional=False)


POSITIVE_ONLY = frozenset({"SCALE", "ENCODERSCALE"})
"""Scale factors the guide's text takes only positive where a table prints 0 ≤ x: SCALE (000:532-537), and
ENCODERSCALE, which divides the counts into ENCODER's units as SCALE does into POS's (000:9731-9735): a
factor of 0 leaves no unit to divide by."""


ANY_VALUE = frozenset({"ACTIVERS485NODE"})
"""Keywords whose entry says what a value outside the printed range does, so it is no error 3: ACTIVERS485NODE's
table prints 0 - 15, the node numbers whose transmitter it can enable, and its restrictions say that 0 or a value
above 15 disables the transmitter (000:6314-6320)."""


def attributes_for(keyword: Keyword, controller: Controller, dialect: Dialect) -> Attributes | None:
    """``keyword``'s attributes on ``controller``: its table's row, or, for a Mint v4 or MintMT keyword whose
    entry prints no table, the row the tools take here."""
    if keyword.attributes or not dialect.modern:
        return keyword.attributes_for(controller)
    return SUPPLEMENTS.get(keyword.name)
