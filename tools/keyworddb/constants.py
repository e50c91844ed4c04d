"""Collect the predefined v4 constants and their numeric values.

Keyword entries print them in tables whose first column is either a value or a
bit number (the header says which: "Value ..." / "Mode ..." or "Bit ...");
a bit's constant is the mask ``2**bit``.  Section 3.2.4 lists the general
constants, and chapter 12 names each MML error code with an ``_er`` constant.
"""

from __future__ import annotations

import re
from collections.abc import Iterable

from mintlang.keyworddb.model import Constant, ErrorCode
from tools.keyworddb.conflicts import Conflict, conflict
from tools.keyworddb.entries import Entry
from tools.keyworddb.seeds import Seed

_NAME = r"_[a-z]{0,3}[A-Z][A-Z0-9_]*"
"""``_hmPOSITIVE_SWITCH``, ``_RELAY0``: optional lower-case family prefix, then capitals."""
_ROW = re.compile(rf"^(?P<value>0x[0-9A-Fa-f]+|-?\d+)\s+(?P<name>{_NAME})(?P<rest>.*)$")
_NAME_FIRST = re.compile(rf"^(?P<name>{_NAME})\s+\S.*?\s(?P<value>0x[0-9A-Fa-f]+|-?\d+)$")
"""SERIALBAUD's table prints the constant first and its value last: "_tmRS232 RS232 serial port 1" (000:15851)."""
_BARE = re.compile(rf"^{_NAME}$")
_TABLE_HEADER = re.compile(r"^(?P<word>Bit|Value|Mode|Phase)\b")
_IMPLIED_ZERO = re.compile(rf"\bzero \(i\.e\.\s*(?P<name>{_NAME})\)")
_COMBINATION = re.compile(r"(?P<name>_\w+) which combines (?P<first>_\w+) and (?P<second>_\w+)")
_GENERAL_ROW = re.compile(r"^(?P<name>_[A-Z]+)\s+(?P<value>-?\d+)$")


def _value(text: str) -> int:
    return int(text, 16) if text.lower().startswith("0x") else int(text)


def in_bit_table(seed: Seed, heading: int, number: int) -> bool:
    """Whether the nearest table header above line ``number``, below the entry's ``heading``, counts bits."""
    for above in range(number - 1, heading, -1):
        if match := _TABLE_HEADER.match(seed.stripped(above)):
            return match["word"] == "Bit"
    return False


def _table_rows(entry: Entry, seed: Seed) -> Iterable[tuple[str, int, int]]:
    """(name, value, line) for every table row in the entry.

    A bit row followed by a second, bare constant names the bit's two states
    (``0 _ctmCONTOUR_OFF`` / ``_ctmCONTOUR_ON``): cleared is 0, set is the mask.
    """
    for number in range(entry.line, entry.end + 1):
        if named := _NAME_FIRST.match(seed.stripped(number)):
            yield named["name"], _value(named["value"]), number
            continue
        match = _ROW.match(seed.stripped(number))
        if not match or match["rest"].strip().startswith("+"):  # "3 _acDIFFERENTIAL + _acBIPOLAR"
            continue
        value = _value(match["value"])
        if not in_bit_table(seed, entry.line, number):
            yield match["name"], value, number
            continue
        following = seed.next_nonblank(number)
        if not match["rest"].strip() and _BARE.match(seed.stripped(following)):
            yield match["name"], 0, number
            yield seed.stripped(following), 1 << value, following
        else:
            yield match["name"], 1 << value, number


def _combinations(entry: Entry, seed: Seed, known: dict[str, Constant]) -> Iterable[tuple[Constant, Conflict | None]]:
    """Constants printed as the union of two others (``_erHARD_LIMIT``).

    The guide pairs each with the other one's components (SOFT with the HARD
    bits); the name wins, so the pair is matched by suffix and the swap noted.
    """
    printed = []
    for number in range(entry.line, entry.end + 1):
        if match := _COMBINATION.search(seed.stripped(number)):
            printed.append((match["name"], (match["first"], match["second"]), number))
    pairs = [parts for _, parts, _ in printed]
    for name, parts, number in printed:
        suffix = re.sub(r"^_[a-z]+", "", name)  # "_erHARD_LIMIT" -> "HARD_LIMIT"
        matching = next((p for p in pairs if all(part.endswith(suffix) for part in p)), parts)
        keyword = known[matching[0]].keyword
        found = None
        if matching != parts:
            detail = (
                f"the guide says {name} combines {' and '.join(parts)}; by its name it combines "
                f"{' and '.join(matching)}, which is what is recorded"
            )
            found = conflict("constant_value", name, detail, (number,), keywords=[keyword])
        yield Constant(name, sum(known[part].value for part in matching), keyword, number), found


def keyword_constants(
    entries: Iterable[Entry], keyword_of: dict[int, str], seed: Seed
) -> tuple[dict[str, Constant], list[Conflict], dict[str, list[str]]]:
    """Constants defined in entry tables, the value conflicts, and each keyword's constant names.

    ``keyword_of`` maps an entry's heading line to its canonical keyword name.
    """
    constants: dict[str, Constant] = {}
    conflicts: list[Conflict] = []
    owned: dict[str, list[str]] = {}
    for entry in entries:
        keyword = keyword_of[entry.line]
        found = [Constant(name, float(value), keyword, line) for name, value, line in _table_rows(entry, seed)]
        for number in range(entry.line, entry.end + 1):
            if match := _IMPLIED_ZERO.search(seed.stripped(number)):
                found.append(Constant(match["name"], 0.0, keyword, number))
        for constant in found:
            conflicts += add_constant(constants, constant)
            owned.setdefault(keyword, []).append(constant.name)
        for constant, combination_conflict in _combinations(entry, seed, constants):
            conflicts += add_constant(constants, constant)
            owned.setdefault(keyword, []).append(constant.name)
            conflicts += [combination_conflict] if combination_conflict else []
    return constants, conflicts, {k: list(dict.fromkeys(v)) for k, v in owned.items()}


def add_constant(constants: dict[str, Constant], constant: Constant) -> list[Conflict]:
    """Keep the first definition; a later one with another value is a conflict."""
    first = constants.setdefault(constant.name, constant)
    if first.value == constant.value:
        return []
    detail = (
        f"{constant.name} is {first.value:g} in {first.keyword or 'a general table'} (line {first.line}) "
        f"but {constant.value:g} in {constant.keyword or 'a general table'} (line {constant.line}); the first is kept"
    )
    owners = [k for k in dict.fromkeys((first.keyword, constant.keyword)) if k]
    return [conflict("constant_value", constant.name, detail, (first.line, constant.line), keywords=owners)]


def general_constants(seed: Seed) -> dict[str, Constant]:
    """``_TRUE _FALSE _ON _OFF _MAXINT _MININT`` from section 3.2.4."""
    start = seed.find(r"^3\.2\.4 Pre-defined Constants")
    end = seed.find(r"^3\.2\.5 ", start)
    constants = {}
    for number in range(start, end):
        if match := _GENERAL_ROW.match(seed.stripped(number)):
            constants[match["name"]] = Constant(match["name"], float(match["value"]), None, number)
    return constants


def error_constants(errors: Iterable[ErrorCode]) -> dict[str, Constant]:
    """The ``_er`` names chapter 12 gives the MML error codes (first code wins for a shared name)."""
    constants: dict[str, Constant] = {}
    for error in sorted(errors, key=lambda e: e.code):
        if error.constant:
            constants.setdefault(error.constant, Constant(error.constant, float(error.code), None, error.line))
    return constants
