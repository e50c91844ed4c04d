"""Markdown descriptions of keywords, constants and user symbols (hover, completion details)."""

from __future__ import annotations

import re
from urllib.parse import unquote

from mintlang.analysis.rules.events import unavailable
from mintlang.analysis.rules.v3_keywords import successor
from mintlang.controllers import ControllerProfile, profile
from mintlang.diagnostics import split_lines
from mintlang.dialect import Dialect
from mintlang.keyworddb import database, supplements
from mintlang.keyworddb.model import Addressing, Controller, Keyword, MigrationClass, V3Keyword
from mintlang.lsp.addressed import placed_line
from mintlang.lsp.workspace import Snapshot
from mintlang.semantic.events import event_of
from mintlang.semantic.index import line_facts
from mintlang.semantic.symbols import Occurrence, Symbol, SymbolKind
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n
from mintlang.syntax.nodes import character_code, relocate


def _access(read: bool, write: bool, command: bool) -> str:
    return ", ".join(word for word, flag in (("read", read), ("write", write), ("command", command)) if flag) or "—"


def round_brackets(label: str, name: str) -> str:
    """A v4 format as MintMT writes it (MT-18): the axes or channel after the keyword in round brackets,
    ``MOVER[axes] = …`` as ``MOVER(axes) = …`` and ``ADC.channel`` as ``ADC(channel)``."""
    addressed = re.compile(rf"\b({re.escape(name)})(?:\[([^\]]*)\]|\.(\w+))", re.IGNORECASE)
    return addressed.sub(lambda found: f"{found[1]}({found[2] or found[3]})", label)


def keyword(word: Keyword, controller: Controller, spelling: str = "", dialect: Dialect = Dialect.V4) -> str:
    """Full name, formats (as the dialect writes them), access, addressing, default, range, controllers,
    summary and the entry's See-also list."""
    title = f"**{word.name}**"
    if word.abbreviations:
        title += f" (abbreviation {', '.join(word.abbreviations)})"
    lines = [f"{title} — {word.kind.value.replace('_', ' ')}", ""]  # command_line reads "command line"
    if word.formats:
        formats = word.formats
        if dialect is Dialect.MINTMT:
            formats = tuple(round_brackets(label, word.name) for label in formats)
        lines += ["```mint", *formats, "```", ""]
    if word.summary:
        lines += [word.summary, ""]
    own = supplements.attributes_for(word, controller, dialect)
    row = own or (word.attributes[0] if word.attributes else None)
    if row is not None and own is None:  # HOMEINPUT on NextMove PCI: another controller's row, said so
        mine = profile(controller).title
        lines.append(f"- Attributes: the guide's row for {_titles(row.controllers)} (it prints none for {mine})")
    elif own is not None and not word.attributes:  # MOVEBUFFERSIZE, an Advanced-guide entry: the tools' row
        lines.append("- Attributes: the guide prints no table: the row mint check and mint-run take")
    if row is not None:
        lines.append(f"- Access: {_access(row.read, row.write, row.command)}")
    if word.addressing is not Addressing.NONE:
        lines.append(f"- Addressing: by {word.addressing.value}")
    channel = spelling[len(spelling.rstrip("0123456789")) :] if word.channel_suffix else ""
    if channel and spelling.upper() != word.name:
        lines.append(f"- Written here for channel {int(channel)}")
    if row is not None and row.default:
        lines.append(f"- Default: {row.default}")
    held = supplements.held_range(word.name, row, controller, dialect)  # as both tools hold values, on this controller
    if held is not None:  # a Scaled row's range is the value's times its scale factor (000:5647-5649)
        lines.append(f"- Range: {held.text}" + (", of the value times its scale factor" if row.scaled else ""))
    lines.append(f"- Controllers: {_titles(word.controllers) or 'not listed in the guide'}")
    if not word.available_on(controller):
        lines.append(f"- **Not available on {profile(controller).title}**")
    if word.see_also:
        lines.append(f"- See also: {', '.join(word.see_also)}")
    return "\n".join(lines)


def _titles(controllers: tuple[Controller, ...]) -> str:
    """The controllers as the guide names them, "" for none (an advanced stub's quick-reference row)."""
    return ", ".join(profile(c).title for c in controllers)


_MIGRATION = {
    MigrationClass.NONE: "nothing to do",
    MigrationClass.MECHANICAL: "mint-migrate rewrites it",
    MigrationClass.SEMI: "mint-migrate rewrites it where the statement shows what it means, and flags it otherwise",
    MigrationClass.MANUAL: "mint-migrate flags it with a REM MIGRATE line for you to port",
}


def v3_keyword(word: V3Keyword) -> str:
    """What a v3 keyword was and what porting it to v4 takes: the question of anyone reading a v3 file."""
    title = f"**{word.name}**"
    if word.abbreviations:
        title += f" (abbreviation {', '.join(word.abbreviations)})"
    lines = [f"{title} — Mint v3 keyword", ""]
    if word.formats:
        lines += ["```mint", *word.formats, "```", ""]
    lines.append(f"- Access: {_access(word.read, word.write, word.command)}")
    if word.addressing is not Addressing.NONE:
        lines.append(f"- Addressing: by {word.addressing.value}")
    if word.v4_names:
        lines.append(f"- Mint v4: {', '.join(word.v4_names)} ({word.status})")
    else:
        lines.append(f"- Mint v4: {word.status}")
    lines.append(f"- Migration: {_MIGRATION[word.migration]}")
    successor = next((found for name in word.v4_names if (found := database().keywords.get(name)) is not None), None)
    if successor is not None and successor.summary:
        lines += ["", f"In Mint v4, {successor.name}: {successor.summary}"]
    return "\n".join(lines)


def v3_word(text: str, controller: ControllerProfile) -> str | None:
    """A Mint v3 keyword or constant left in v4 code: what it became on ``controller``, then its v3 entry
    as the v3 dialect shows it; None for any other word."""
    was = successor(text, controller)
    old = database().lookup_v3(text)
    if was is not None:
        became = was.detail
    elif old is not None:
        what = "keyword" if old.name == text.upper() else f"abbreviation of {old.name}"
        became = f"a Mint v3 {what}; Mint v4: {', '.join(old.v4_names) or 'nothing'}"
    else:
        return None
    lines = [f"**{text}** is not Mint v4: it is {became}"]
    return "\n\n".join([*lines, v3_keyword(old)] if old is not None else lines)


def character(text: str) -> str:
    """A character constant counts as the code of its upper case, which is worth saying for ``'a'``."""
    code = character_code(text)
    note = f" (as '{chr(code)}': character constants count in upper case)" if chr(code) != text[1] else ""
    return f"**{text}** = `{code}` — character constant{note}"


# Words the manual reserves without a keyword entry or a value, which the lexer reads as constants.
_RESERVED = {
    "NULL": (
        "reserved word — stands where CAMTABLE takes an array and none is given: `CAMTABLE(0, myCam, NULL)` "
        "sets a cam with no master distance table, every segment then taking MASTERDISTANCE"
    ),
}


def _number(value: float) -> int | float:
    return int(value) if value == int(value) else value


def _constant_facts(name: str, dialect: Dialect) -> tuple[str, int | float, str] | None:
    """A predefined constant of the dialect: its name as its table writes it, its value and what it is."""
    if dialect is Dialect.V3:
        old = database().v3_constants.get(name.upper())
        if old is None:
            return None
        successor = f"Mint v4: {old.v4_name}" if old.v4_name else "Mint v4 has no such constant"
        return old.name, _number(old.value), f"Mint v3 predefined constant; {successor}"
    record = database().constants_of(dialect).get(name.upper())
    if record is None:
        return None
    owners = database().listing(record.name, dialect) or ((record.keyword,) if record.keyword else ())
    what = f"predefined constant of {_and(owners)}" if owners else "predefined constant"
    return record.name, _number(record.value), what


def _and(names: tuple[str, ...]) -> str:
    """``A``, ``A and B``, ``A, B and C``."""
    return names[0] if len(names) == 1 else f"{', '.join(names[:-1])} and {names[-1]}"


def _refused(name: str, dialect: Dialect, controller: Controller | None) -> str | None:
    """Where the keyword whose entry defines the constant refuses it on ``controller``, as both tools hold a write
    of it there (``_cfSTEPPER``: CONFIG takes 0, 1, 5 on NextMove BX, 000:8431-8443); None where it takes it."""
    if controller is None or not dialect.modern:
        return None
    record = database().constants_of(dialect).get(name.upper())
    word = database().keywords_of(dialect).get(record.keyword) if record is not None and record.keyword else None
    row = supplements.attributes_for(word, controller, dialect) if word is not None else None
    if record is None or word is None or row is None or not row.write:
        return None
    held = supplements.narrowed(word.name, row.range, controller)
    if held is None or held.holds(record.value):
        return None
    return f"not a value {word.name} accepts on {profile(controller).title} ({held.text})"


def constant(name: str, dialect: Dialect = Dialect.V4, controller: Controller | None = None) -> str | None:
    """Markdown for hover: a reserved word's use, or a constant's value and what it is (and where its keyword
    refuses it on ``controller``)."""
    if name.upper() in _RESERVED:
        return f"**{name.upper()}** — {_RESERVED[name.upper()]}"
    facts = _constant_facts(name, dialect)
    if facts is None:
        return None
    refused = _refused(name, dialect, controller)
    note = f"\n\n{refused[0].upper()}{refused[1:]}" if refused is not None else ""
    return f"**{facts[0]}** = `{facts[1]}` — {facts[2]}{note}"


def constant_detail(name: str, dialect: Dialect, controller: Controller | None = None) -> str | None:
    """Plain text beside a constant offered by completion (an item's detail is not Markdown)."""
    facts = _constant_facts(name, dialect)
    if facts is None:
        return None
    refused = _refused(name, dialect, controller)
    return f"= {facts[1]} — {facts[2]}" + (f"; {refused}" if refused is not None else "")


def _where(snapshot: Snapshot, unit: Unit, offset: int) -> str:
    file = snapshot.files.get(unit)
    line = file.positions.position(offset).line + 1 if file is not None else None
    place = "the configuration file" if unit is Unit.CONFIGURATION else "the program"
    name = f" ({unquote(file.uri.rpartition('/')[2])})" if file is not None else ""
    return f"line {line} of {place}{name}" if line is not None else place


def macro_body(snapshot: Snapshot, name: str) -> str | None:
    """The text the macro ``name`` (an identity) stands for, exactly as its definition writes it."""
    model = snapshot.model
    definition = model.program.macros.get(name)
    symbol = model.symbols.macros.get(name)
    where = symbol.definition if symbol is not None else None
    if definition is None or definition.body_span is None or where is None:
        return None
    return model.document(where.unit).source[definition.body_span.start : definition.body_span.end]


_SHOWN_VALUES = 12  # an array's first values in a hover; cam tables run to thousands


def _dim(snapshot: Snapshot, definition: Occurrence) -> tuple[str, n.Dim] | None:
    """The source of the file of ``definition`` (a DIM's name) and its DIM statement."""
    line = placed_line(snapshot, definition.unit, definition.span.start)
    if line is None:
        return None
    for statement in line_facts(definition.unit, line).statements:
        if type(statement) is n.Dim and line.span(statement.name.span) == definition.span:
            return snapshot.model.document(definition.unit).source, relocate(statement, line.origin)
    return None


def _initial(snapshot: Snapshot, found: Symbol) -> str:
    """What a variable or array holds before the program writes it, as its DIM says."""
    declared = _dim(snapshot, found.definition) if found.definition is not None else None
    if declared is None:
        return ""
    source, dim = declared
    values = [source[value.span.start : value.span.end] for value in dim.values]
    if found.kind is SymbolKind.VARIABLE:
        if not values:
            return "\n- Initial value: none written (0 when first declared)"
        return f"\n- Initial value: `{values[0]}`, set when the DIM runs"
    if not values:
        return "\n- Initial values: none written (0)"
    shown = ", ".join(values[:_SHOWN_VALUES]) + (f", … ({len(values)} values)" if len(values) > _SHOWN_VALUES else "")
    rest = f", then `{values[-1]}` for the rest (;)" if dim.fill else ""
    return f"\n- Initial values: `{shown}`{rest}, set when the program is compiled"


def _remarks(snapshot: Snapshot, definition: Occurrence) -> str:
    """The REM lines right above a label, and a REM on its own line: what its author says it does."""
    file = snapshot.files.get(definition.unit)
    if file is None:
        return ""
    source, positions = snapshot.model.document(definition.unit).source, file.positions
    number = positions.position(definition.span.start).line
    lines = split_lines(source)
    said = [_REMARK.match(lines[number][definition.span.end - positions.line_start(number) :].lstrip(" \t:"))]
    above = number - 1
    while above >= 0 and (remark := _REMARK.match(lines[above].strip())) is not None:
        said.insert(0, remark)
        above -= 1
    text = "\n".join(words for remark in said if remark is not None and (words := remark.group(1).strip()))
    return f"\n\n{text}" if text else ""


_REMARK = re.compile(r"REM\b(.*)", re.IGNORECASE)


def symbol(snapshot: Snapshot, found: Symbol) -> str:
    definition = found.definition
    where = f"declared at {_where(snapshot, definition.unit, definition.span.start)}" if definition else "not declared"
    if found.kind is SymbolKind.ARRAY:
        size = f"({found.array_size})" if found.array_size is not None else "()"
        return f"**{found.name}**{size} — array, {where}{_initial(snapshot, found)}"
    if found.kind is SymbolKind.VARIABLE:
        return f"**{found.name}** — variable, {where}{_initial(snapshot, found)}"
    if found.kind is SymbolKind.MACRO:
        body = macro_body(snapshot, found.identity)
        value = f"\n\n```mint\nDEFINE {found.name} = {body}\n```" if body is not None else ""
        return f"**{found.name}** — macro, {where.replace('declared', 'defined')}{value}"
    dialect = snapshot.settings.dialect
    event = event_of(found.name, dialect)
    never = unavailable(event, snapshot.model.controller, dialect) if event else None  # #IN7 on ServoNode 51
    kind = f"event handler ({event.kind.value})" if event and never is None else "label"
    where = f"at {_where(snapshot, definition.unit, definition.span.start)}" if definition else "never defined"
    remarks = _remarks(snapshot, definition) if definition else ""
    note = f"\n\nNot an event handler here: {never}" if never is not None else ""
    return f"**#{found.name}** — {kind}, {where}{note}{remarks}"
