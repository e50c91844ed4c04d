"""Parse the garbled "Attributes" tables of chapter 10 and their value ranges.

A row is ``<controllers> <Read> <Write> <Command> <Multi-Axis> <Scaled>
<Default> <Range>``; the five flag cells are ticks or nothing, one space apart
(see ``checkmarks``).  Long controller labels, defaults and ranges wrap onto
lines of their own, which this module glues back to their row.  A label may
end in a footnote number ("NextMove PCI10"); where that footnote widens the
range for NextMove PCI with expansion cards (``footnotes``), the card gets a
row of its own with the widened range.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, replace

from mintlang.keyworddb.model import Attributes, Controller, ValueRange
from tools.keyworddb.checkmarks import TICK

_NUMBER = r"-?\d[\d,]*(?:\.\d+)*"
_DASH = "[-\u2013]"  # the guide prints ranges with hyphens and en dashes
_LABEL = re.compile(
    r"^(?P<label>(?:All|N(?:e|en)xt[Mm]ove|NM|MintDrive|ServoNode)"
    r"(?: ?(?:PCI|PC|BX|51|&|,))*)(?P<footnote>\d*),?(?=\s|$)"
)
_HEADER = re.compile(r"^(Controller Read|Axis$|Scaled Default Range)")
_STOP = re.compile(r"^(On |LOOPTIME|Figure |Keyword Reference|MN1262|[A-Z][a-z]+ [a-z]+ )")
_RANGE_START = re.compile(rf"^(?:{_NUMBER}\s*(?:[<≤]|{_DASH}|to\b|\.\.|,|or\b)|[Ss]ee\b|{_NUMBER}$)")
_WHOLE_INTERVAL = re.compile(rf"^{_NUMBER}\s*[<≤]")
"""A range cell that starts the text at once: the Default cell was empty."""
# A default per axis type wraps onto a second line, and the conversion loses the comma between the two that
# SPEED keeps ("20,000, 1000 (stepper)"): HOMESPEED "1000" / "500 (step)" (000:11607-11608) is 1000, 500 (step).
_TWO_DEFAULTS = re.compile(r"(\d) (?=\d)")
_INTERVAL = re.compile(rf"^(?P<min>{_NUMBER})\s*(?P<low>[<≤])\s*x\s*(?P<high>[<≤])\s*(?P<max>{_NUMBER})\s*(?:ms)?$")
_SPAN = re.compile(rf"^(?P<min>{_NUMBER})\s*(?:{_DASH}|to|\.\.)\s*(?P<max>{_NUMBER})$")
_CHOICES = re.compile(rf"^{_NUMBER}(?:\s*(?:,|,? or)\s*{_NUMBER})*$")
_FLAG_COUNT = 5
NAMED_CONSTANTS = re.compile(r"^(?P<span>.+?) and (?P<word>[a-z]+) constants?(?=;|$)")
"""DRIVEENABLEOUTPUT's "-1 ≤ x ≤ 11 and relay constant": a span and a family of constants (``constant_ranges``)."""


@dataclass
class _Row:
    label: str
    flags: list[bool]
    rest: list[str]
    line: int
    footnotes: tuple[int, ...]  # the footnote numbers printed after the label
    shifted: tuple[list[bool], str] | None = None  # the reading with one leading empty cell restored


def controllers_of_label(label: str, supported: tuple[Controller, ...]) -> tuple[Controller, ...]:
    """The controllers a row label names, limited to those supporting the keyword."""
    named: set[Controller] = set()
    if re.search(r"\bPCI\b", label):
        named.add(Controller.NEXTMOVE_PCI)
    if re.search(r"\bPC\b", label):
        named.add(Controller.NEXTMOVE_PC)
    if re.search(r"\bBX\b", label):
        named.add(Controller.NEXTMOVE_BX)
    if not named and re.search(r"(?i)next?move", label):
        named.update({Controller.NEXTMOVE_PCI, Controller.NEXTMOVE_PC, Controller.NEXTMOVE_BX})
    if "MintDrive" in label:
        named.add(Controller.MINTDRIVE)
    if "ServoNode" in label:
        named.add(Controller.SERVONODE51)
    if not named:  # "All", or no label at all
        named = set(Controller)
    return tuple(c for c in supported if c in named) or tuple(c for c in Controller if c in named)


def _take_flags(text: str) -> tuple[list[bool], str] | None:
    """Consume the five flag cells from the start of ``text``; the rest follows."""
    flags = []
    for _ in range(_FLAG_COUNT):
        if text.startswith(TICK):
            flags.append(True)
            text = text[1:]
        elif text.startswith(" ") or not text:
            flags.append(False)
        else:
            return None
        text = text[1:] if text.startswith(" ") else text
    return flags, text


_Label = tuple[str, int | None]
"""A controller label without its footnote number, and that number."""


def _footnote(match: re.Match[str]) -> int | None:
    return int(match["footnote"]) if match["footnote"] else None


def _label_line(text: str, match: re.Match[str]) -> _Label:
    """A line holding only a (wrapped) label: all of it but the footnote number."""
    return text[: match.start("footnote")] + text[match.end("footnote") :], _footnote(match)


def _split_row(raw: str) -> tuple[_Label, str] | None:
    """Split a table line into its controller label and the cells after it."""
    text = raw.lstrip(" ")
    if text.startswith(TICK):
        return ("", None), text
    match = _LABEL.match(text)
    if not match or TICK not in text[match.end() :]:
        return None
    return (match["label"], _footnote(match)), text[match.end() + 1 :]


def _rows(lines: list[tuple[int, str]]) -> list[_Row]:
    rows: list[_Row] = []
    pending_label: list[_Label] = []
    for number, raw in lines:
        text = raw.strip()
        if not text or _HEADER.match(text):
            continue
        if _STOP.match(text):
            break
        split = _split_row(raw.rstrip("\n").removesuffix(" "))
        taken = _take_flags(split[1]) if split else None
        if split and taken:
            labels = [*pending_label, split[0]]
            label = " ".join(text for text, _ in labels if text)
            footnotes = tuple(footnote for _, footnote in labels if footnote is not None)
            shifted = _take_flags(" " + split[1]) if pending_label and not split[0][0] else None
            rows.append(_Row(label, taken[0], [taken[1]], number, footnotes, shifted))
            pending_label = []
        elif match := _LABEL.match(text):
            pending_label.append(_label_line(text, match))
        elif rows:
            rows[-1].rest.append(text)
    return [_realign(row, rows) for row in rows]


def _realign(row: _Row, rows: list[_Row]) -> _Row:
    """Undo a lost leading empty cell on a row whose label wrapped onto lines of its own.

    The conversion sometimes drops that cell (FLY, CAMTABLE on MintDrive); the
    shifted reading is taken only when it then agrees with another row of the
    same table and the literal reading agrees with none.
    """
    others = [other.flags for other in rows if other is not row]
    if row.shifted is None or row.flags in others or row.shifted[0] not in others:
        return row
    return _Row(row.label, row.shifted[0], [row.shifted[1], *row.rest[1:]], row.line, row.footnotes)


def _default_and_range(rest: list[str]) -> tuple[str | None, str | None]:
    """Split the text after the flags into the Default and Range cells."""
    first, *more = rest
    if first.startswith(" ") or not first.strip():
        text = " ".join([first.strip(), *more]).strip()
        return None, text or None
    words = " ".join([first, *more]).split()
    if _WHOLE_INTERVAL.match(" ".join(words)):
        return None, " ".join(words)
    for cut in range(1, len(words)):
        candidate = " ".join(words[cut:])
        if _RANGE_START.match(candidate):
            return _TWO_DEFAULTS.sub(r"\1, ", " ".join(words[:cut])), candidate
    return _TWO_DEFAULTS.sub(r"\1, ", " ".join(words)), None


def _number(text: str) -> float:
    """A printed number; "-83886.07.0" (ENCODERVEL) is a misplaced point, so drop all but the last."""
    whole, _, fraction = text.replace(",", "").rpartition(".")
    return float(f"{whole.replace('.', '')}.{fraction}" if whole else fraction)


_CHANNEL_RANGE = re.compile(r"(\d) (0 or 1)$")
_SPAN_AND_ONE = re.compile(r"^(?P<low>-?\d+)\s*(?:\.\.|≤\s*x\s*≤)\s*(?P<high>-?\d+)\s*,\s*(?P<one>-?\d+)$")
_NAMED_VALUE = rf"(-?\d+) {_DASH} [A-Za-z]+"  # MOTORDIRECTION "0 – Forward 1 – Reverse": a mode per value
_NAMED_VALUES = re.compile(rf"^{_NAMED_VALUE}(?: {_NAMED_VALUE})*$")


def parse_range(text: str) -> ValueRange:
    """Numbers where the manual prints an interval or a list of numbers; else text only."""
    fractional = re.search(r"\d\.\d", text) is not None
    compact = re.sub(r"\s+", " ", text.strip())
    if match := NAMED_CONSTANTS.match(compact):  # the span's bounds; ``constant_ranges`` adds the constants
        return replace(parse_range(match["span"]), text=compact)
    # IN, OUT: the range of the whole word, then on its own line that of one channel ("0 or 1").
    compact = _CHANNEL_RANGE.sub(r"\1; one channel: \2", compact)
    if match := _INTERVAL.match(compact):  # "0 ≤ x < 4096": a "<" leaves the bound out
        low, high = _number(match["min"]), _number(match["max"])
        return ValueRange(compact, low, high, fractional, match["low"] == "≤", match["high"] == "≤")
    if match := _SPAN_AND_ONE.match(compact):  # HOME "0 .. 4, 6": the whole numbers of a span, and one more
        low, high, one = (int(match[part]) for part in ("low", "high", "one"))
        allowed = tuple(float(value) for value in sorted({*range(low, high + 1), one}))
        return ValueRange(compact, None, None, fractional, allowed=allowed)
    if _NAMED_VALUES.match(compact):  # one mode a printed line: kept apart once the lines are joined
        modes = list(re.finditer(_NAMED_VALUE, compact))
        allowed = tuple(sorted(float(mode[1]) for mode in modes))
        return ValueRange("; ".join(mode[0] for mode in modes), None, None, fractional, allowed=allowed)
    bounds: tuple[float, float] | None = None
    if match := _SPAN.match(compact):
        bounds = _number(match["min"]), _number(match["max"])
    elif _CHOICES.match(compact):
        values = sorted({_number(v) for v in re.findall(_NUMBER, compact)})
        if _has_gap(values):  # ENCODERPRESCALE "1, 2, 4, 8, ...": only the values listed
            return ValueRange(compact, None, None, fractional, allowed=tuple(values))
        bounds = values[0], values[-1]
    if bounds is None:
        return ValueRange(compact, None, None, fractional)
    return ValueRange(compact, bounds[0], bounds[1], fractional)


def _has_gap(values: list[float]) -> bool:
    """Whether sorted whole ``values`` leave out a whole number between their ends.

    A list without a gap ("0 or 1", "2, 3") reads as its span, as an interval does, so a fraction in
    it is not rejected: whole-number ranges are not enforced (KDERIV's example writes 1.5).
    """
    return all(v == int(v) for v in values) and len(values) < values[-1] - values[0] + 1


def _widened_for_expansion(row: Attributes, maximum: float) -> tuple[Attributes, ...]:
    """NextMove PCI on a row of its own with the two-card ``maximum``; the row's other controllers as printed."""
    if Controller.NEXTMOVE_PCI not in row.controllers or row.range is None or row.range.maximum is None:
        return (row,)
    text = f"{row.range.text}; up to {maximum:g} with two expansion cards"
    widened = replace(row.range, text=text, maximum=maximum, maximum_included=True)
    others = tuple(c for c in row.controllers if c is not Controller.NEXTMOVE_PCI)
    pci = replace(row, controllers=(Controller.NEXTMOVE_PCI,), range=widened)
    return (pci, replace(row, controllers=others)) if others else (pci,)


def parse_attributes(
    lines: list[tuple[int, str]], supported: tuple[Controller, ...], expansion_maxima: Mapping[int, float]
) -> tuple[Attributes, ...]:
    """One ``Attributes`` per table row (two where a footnote widens NextMove PCI's range).

    ``lines`` are the raw lines of the section; ``expansion_maxima`` maps a footnote number to
    the range's maximum with two expansion cards fitted (``footnotes``).
    """
    result: list[Attributes] = []
    for row in _rows(lines):
        default, range_text = _default_and_range(row.rest)
        read, write, command, multi_axis, scaled = row.flags
        printed = Attributes(
            controllers=controllers_of_label(row.label, supported),
            read=read,
            write=write,
            command=command,
            multi_axis=multi_axis,
            scaled=scaled,
            default=default,
            range=parse_range(range_text) if range_text else None,
        )
        maxima = [expansion_maxima[number] for number in row.footnotes if number in expansion_maxima]
        result += _widened_for_expansion(printed, max(maxima)) if maxima else (printed,)
    return tuple(result)
