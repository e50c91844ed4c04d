"""Completion: only what is valid at the cursor, without waiting for a new analysis.

The cursor's line is lexed as typed; user names come from the last analysis.

After GOSUB/GOTO: labels; after ``#`` at the start of a line: the labels jumped
to and not yet written, and the event handlers of the controller the program
does not have yet; after DIM: the names used and not declared; after FOR and INPUT: the
variables, arrays and macros naming one that they can fill; after MintMT's
``Event``: the events its blocks handle;
after ``_``: predefined constants; at the start of a statement: commands,
writable parameters, variables, macros and block snippets (ELSE, ENDL ...
only where they close the innermost block, ELSE only before that IF's own ELSE,
EXIT inside any loop; MintMT's End Loop, End If, End Event, End Startup too,
and its Event and Startup only outside every block); inside an
expression: readable keywords, functions, variables, arrays and macros; after
a complete operand: the operators and the words that continue the statement
being written (THEN in an IF, TO in a FOR ...); after a keyword's dot
(``SPEED.``, ``IN.``): the axes or channels it addresses on the controller and
the macros that name them. Nothing inside comments, strings and character
constants, after a number's decimal point, or where a new name is being
declared (DEFINE).
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from lsprotocol import types

from mintlang.analysis.rules.addressing import addressed
from mintlang.controllers import ChannelRange
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Controller, Keyword, KeywordKind, Use
from mintlang.keyworddb.usage import refusal
from mintlang.lsp import describe, mintmt_words
from mintlang.lsp.features.signature import callee_at
from mintlang.lsp.features.symbols import gosub_targets, label_kind, sections
from mintlang.lsp.lookup import WORD_KINDS, prefix_tokens, significant
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Settings, Snapshot
from mintlang.records import record
from mintlang.semantic.blocks import Block, BlockKind
from mintlang.semantic.events import Event, event_of
from mintlang.semantic.symbols import Symbol, SymbolKind
from mintlang.syntax import nodes as n
from mintlang.syntax.common import shared_ends
from mintlang.syntax.lines import MacroDefinition
from mintlang.syntax.tokens import Token, TokenKind

SNIPPETS = {
    "IF … DO … ENDIF": "IF ${1:condition} DO\n\t$0\nENDIF",
    "FOR … NEXT": "FOR ${1:i} = ${2:1} TO ${3:10}\n\t$0\nNEXT",
    "WHILE … ENDW": "WHILE ${1:condition}\n\t$0\nENDW",
    "LOOP … ENDL": "LOOP\n\t$0\nENDL",
    "REPEAT … UNTIL": "REPEAT\n\t$0\nUNTIL ${1:condition}",
}
_V4_SPELT = frozenset({"IF … DO … ENDIF", "LOOP … ENDL"})  # MintMT writes these blocks otherwise
_STATEMENT_STARTERS = frozenset({TokenKind.COLON, TokenKind.THEN, TokenKind.DO, TokenKind.ELSE, TokenKind.LABEL})
_OPERAND_ENDS = frozenset(
    {TokenKind.NUMBER, TokenKind.CHAR, TokenKind.STRING, TokenKind.CONSTANT, TokenKind.NAME, TokenKind.RPAR}
)
# After these only a new name or the end of the statement can come.
_NOTHING_AFTER = frozenset(
    {TokenKind.DIM, TokenKind.DEFINE, TokenKind.RETURN, TokenKind.END, TokenKind.ENDIF, TokenKind.ENDW}
    | {TokenKind.ENDL, TokenKind.NEXT, TokenKind.LOOP, TokenKind.REPEAT}
)
_LOOPS = frozenset({BlockKind.FOR, BlockKind.LOOP, BlockKind.REPEAT, BlockKind.WHILE})
# The words that close or go on with a block, valid only where the innermost block open is of a kind given (a
# closing word closes the level the last opening word opened, 000:1918-1921; the checker's E2009-E2014 name that
# block): ELSE and ENDIF in an IF .. DO (000:11797-11803), each loop's closer in its loop; EXIT leaves any of the
# four loops around it (000:10236-10243); MintMT's End Loop and End If as v4's ENDL and ENDIF (004:102-125), End
# Event and End Startup in theirs.
_INSIDE = {
    "ELSE": frozenset({BlockKind.IF}),
    "ENDIF": frozenset({BlockKind.IF}),
    "NEXT": frozenset({BlockKind.FOR}),
    "ENDW": frozenset({BlockKind.WHILE}),
    "ENDL": frozenset({BlockKind.LOOP}),
    "UNTIL": frozenset({BlockKind.REPEAT}),
    "EXIT": _LOOPS,
    "ENDEVENT": frozenset({BlockKind.EVENT}),
    "ENDSTARTUP": frozenset({BlockKind.STARTUP}),
}
# MintMT's Event and Startup start a statement outside every block only: no other block may hold them (MT-13).
_OUTSIDE_EVERY_BLOCK = frozenset({TokenKind.EVENT, TokenKind.STARTUP})
# NULL stands for no array where CAMTABLE takes its optional master distance table, its third operand (000:7958).
_NULL_OPERANDS = {"CAMTABLE": 2}
# A line that may open, go on with or close a block, in any dialect (v4 IF .. DO, MintMT If .. Then and End If):
# once one changes, an older analysis no longer tells which blocks are open where.
_BLOCK_WORD = re.compile(
    r"\b(?:IF|THEN|DO|ELSE|ENDIF|FOR|NEXT|REPEAT|UNTIL|WHILE|ENDW|LOOP|ENDL|END|EVENT|STARTUP)\b", re.IGNORECASE
)
_UNARY = frozenset({"NOT", "~"})  # the operators that can start an operand
_CONTINUATIONS = frozenset({"THEN", "DO", "TO", "STEP", "USING"})  # statement words that follow an operand
_SINGLE_QUOTES = "'\u2018\u2019"
_PARTIAL_WORDS = WORD_KINDS | {TokenKind.HASH}
_HIDDEN = frozenset({KeywordKind.EVENT, KeywordKind.COMMAND_LINE})
# A label as the outline names it (symbols.label_kind); completion has no kind for a key, a place in the code.
_SUBROUTINE, _PLACE = types.CompletionItemKind.Function, types.CompletionItemKind.Reference
_LABEL_KINDS = {types.SymbolKind.Function: _SUBROUTINE, types.SymbolKind.Key: _PLACE}
_SYMBOL_KINDS = {
    SymbolKind.VARIABLE: types.CompletionItemKind.Variable,
    SymbolKind.ARRAY: types.CompletionItemKind.Variable,
    SymbolKind.MACRO: types.CompletionItemKind.Constant,
}


def _begun(token: Token) -> bool:
    """Whether ``token`` is a constant or name begun: ``_`` or ``__`` alone is no name yet (000:882-884)."""
    return token.kind is TokenKind.INVALID and token.text.startswith("_")


def _keyword_item(word: Keyword, settings: Settings) -> types.CompletionItem:
    """An item naming the dialect and controller it was offered for: its documentation, written when the
    editor resolves it, describes the record of that dialect (MintMT's CONTOURMODE, not v4's) on that one."""
    kind = types.CompletionItemKind.Function if word.kind is KeywordKind.FUNCTION else types.CompletionItemKind.Keyword
    detail = (
        f"{word.kind.value}, abbreviation {', '.join(word.abbreviations)}" if word.abbreviations else word.kind.value
    )
    data = {"keyword": word.name, "dialect": settings.dialect.value, "controller": settings.controller.value}
    return types.CompletionItem(label=word.name, kind=kind, detail=detail, data=data)


def _starts_statement(word: Keyword, settings: Settings) -> bool:
    """Whether ``word`` may start a statement: a command, or a parameter given a value, as ``mint check`` judges
    it (``usage.refusal``: ERR, whose every format reads it, is no statement though the guide gives it no table)."""
    if word.kind is KeywordKind.STATEMENT:
        return word.name[:1].isalpha() and word.name not in _CONTINUATIONS
    if word.kind is KeywordKind.COMMAND:
        return True
    uses = (Use.WRITE, Use.COMMAND)
    return word.kind is KeywordKind.PARAMETER and any(
        refusal(word, settings.controller, settings.dialect, use) is None for use in uses
    )


def _continuations(words: frozenset[str], settings: Settings) -> Iterator[types.CompletionItem]:
    """After a complete operand: operators, and ``words``, those that go on with the statement."""
    for word in database().keywords.values():
        binary = word.kind is KeywordKind.OPERATOR and word.name.isalpha() and word.name not in _UNARY
        if binary or word.name in words:
            yield _keyword_item(word, settings)


def _current_statement(before: list[Token]) -> list[Token]:
    """The tokens of the statement the cursor is in: those after the last word or colon that starts one."""
    starts = [index for index, token in enumerate(before) if token.kind in _STATEMENT_STARTERS]
    return before[starts[-1] + 1 :] if starts else before


def _statement_words(snapshot: Snapshot, before: list[Token]) -> frozenset[str]:
    """The words that may go on with the statement the cursor is in, after an operand: THEN or DO in an IF
    (000:11797, 11853), TO once a FOR has its '=' and then STEP (000:10887), USING once in a PRINT, INPUT or
    LINE (000:15295, 12212, 13657); none in any other statement."""
    statement = _current_statement(before)
    if not statement:
        return frozenset()
    written = {token.kind for token in statement[1:]}
    first = statement[0]
    if first.kind is TokenKind.IF:
        return frozenset({"THEN", "DO"})
    if first.kind is TokenKind.FOR:
        if TokenKind.STEP in written or TokenKind.EQUAL not in written:
            return frozenset()
        return frozenset({"STEP"} if TokenKind.TO in written else {"TO"})
    formatted = first.kind in (TokenKind.PRINT, TokenKind.INPUT) or (
        first.kind is TokenKind.KEYWORD and snapshot.settings.words.keyword_name(first.text) == "LINE"
    )
    return frozenset({"USING"}) if formatted and TokenKind.USING not in written else frozenset()


def _at_a_name_filled(before: list[Token]) -> bool:
    """Whether the cursor is where the statement takes a name it writes, never a value read: FOR's counter
    (FOR <variable> = ..., 000:10889), and INPUT's variable, after INPUT, its terminal or its prompt and comma
    (INPUT {#<terminal>} {string,} variable, 000:12212)."""
    kinds = [token.kind for token in _current_statement(before)]
    if kinds == [TokenKind.FOR]:
        return True
    if kinds[:1] != [TokenKind.INPUT]:
        return False
    rest = kinds[3:] if kinds[1:2] == [TokenKind.HASH] else kinds[1:]
    return rest in ([], [TokenKind.STRING, TokenKind.COMMA])


@record
class OpenBlocks:
    """The blocks open at the cursor: the kinds of them all, the innermost's kind, and whether the innermost's
    ELSE stands above the cursor (an IF .. DO takes one ELSE, 000:1593-1600)."""

    kinds: frozenset[BlockKind]
    innermost: BlockKind | None
    after_else: bool


def _around(blocks: list[Block], here: int) -> OpenBlocks:
    """What ``blocks``, those open at line ``here`` (1-based), allow there: the innermost opened last."""
    innermost = max(blocks, key=lambda block: block.opener, default=None)
    if innermost is None:
        return OpenBlocks(frozenset(), None, after_else=False)
    after_else = innermost.middle is not None and innermost.middle.line < here
    return OpenBlocks(frozenset(block.kind for block in blocks), innermost.kind, after_else)


def _open_blocks(snapshot: Snapshot, line: int) -> OpenBlocks:
    """The blocks open at ``line`` (0-based): opened on it or above, closed on it, below or never."""
    here = line + 1
    return _around(
        [
            block
            for block in snapshot.model.structures[snapshot.unit].blocks
            if block.opener.line <= here and (block.closer is None or here <= block.closer.line)
        ],
        here,
    )


def _open_blocks_now(snapshot: Snapshot, source: str, line: int) -> OpenBlocks | None:
    """The blocks open at ``line`` (0-based) of ``source``, the text now, from ``snapshot``, an
    analysis of it that may be a few keystrokes old (completion does not wait for a new one, and the editor asks
    right after each keystroke): while the lines changed since hold no block word, every block stands where it
    stood, those below moved by the lines added. None when a changed line may hold one: not known."""
    old = snapshot.document.source
    if old.count("\r") != old.count("\r\n") or source.count("\r") != source.count("\r\n"):
        return None  # a lone CR ends a line too: not worth counting for completion
    start, same_end = shared_ends(old, source)
    if old[start - 1 : start] in ("", "\n") and all(
        part == "" or part.endswith("\n")
        for part in (old[start : len(old) - same_end], source[start : len(source) - same_end])
    ):
        end, new_stop = len(old) - same_end, len(source) - same_end  # whole lines added or removed
    else:  # the changed lines, whole: from the start of the first to the end of the last
        start = old.rfind("\n", 0, start) + 1
        end, new_stop = _line_end(old, len(old) - same_end) + 1, _line_end(source, len(source) - same_end) + 1
    old_lines, new_lines = old[start:end], source[start:new_stop]
    if _BLOCK_WORD.search(old_lines) or _BLOCK_WORD.search(new_lines):
        return None
    first = old.count("\n", 0, start)
    old_end, new_end = first + old_lines.count("\n"), first + new_lines.count("\n")
    if line < first:
        return _open_blocks(snapshot, line)
    if line >= new_end:
        return _open_blocks(snapshot, line - (new_end - old_end))
    return _around(  # a changed line: inside the blocks around the change, opened above it and closed below
        [
            block
            for block in snapshot.model.structures[snapshot.unit].blocks
            if block.opener.line <= first and (block.closer is None or block.closer.line > old_end)
        ],
        first + 1,
    )


def _line_end(text: str, offset: int) -> int:
    """Where the line holding ``offset`` ends: its line break, or the end of the text."""
    end = text.find("\n", offset)
    return len(text) if end < 0 else end


def _in_its_block(name: str, blocks: OpenBlocks | None) -> bool:
    """Whether a keyword can start a statement inside ``blocks`` (None: the blocks are not known)."""
    if blocks is None or name not in _INSIDE:
        return True
    if name == "EXIT":
        return bool(_LOOPS & blocks.kinds)
    return blocks.innermost in _INSIDE[name] and not (name == "ELSE" and blocks.after_else)


def _keywords(snapshot: Snapshot, statement: bool, blocks: OpenBlocks | None = None) -> Iterator[types.CompletionItem]:
    if snapshot.settings.dialect is Dialect.V3:
        for old in database().v3_keywords.values():
            if old.name[:1].isalpha() and (old.write or old.command if statement else old.read):
                detail = f"Mint v3, abbreviation {', '.join(old.abbreviations)}" if old.abbreviations else "Mint v3"
                yield types.CompletionItem(label=old.name, kind=types.CompletionItemKind.Keyword, detail=detail)
        return
    controller, mintmt = snapshot.settings.controller, snapshot.settings.dialect is Dialect.MINTMT
    if mintmt and statement:
        yield from _mintmt_block_words(blocks)
    for word in database().keywords_of(snapshot.settings.dialect).values():
        if word.kind in _HIDDEN or not word.available_on(controller) or (mintmt and word.name in mintmt_words.REPLACED):
            continue
        row = word.attributes_for(controller)
        if statement:
            valid = _starts_statement(word, snapshot.settings) and _in_its_block(word.name, blocks)
        else:
            valid = (
                word.kind is KeywordKind.FUNCTION
                or word.name in _UNARY
                or (row.read if row else word.kind is KeywordKind.PARAMETER)
            )
        if valid:
            yield _keyword_item(word, snapshot.settings)


def _symbols(snapshot: Snapshot) -> Iterator[types.CompletionItem]:
    """The declared variables, arrays and macros; each one's description is written when the editor
    shows it (``completionItem/resolve``): writing thousands per keystroke made completion slow."""
    symbols = snapshot.model.symbols
    for symbol in (*symbols.variables.values(), *symbols.macros.values()):
        if symbol.definitions:
            yield types.CompletionItem(
                label=symbol.name,
                kind=_SYMBOL_KINDS[symbol.kind],
                detail=symbol.kind.value,
                data={"symbol": symbol.identity, "macro": symbol.kind is SymbolKind.MACRO, "uri": snapshot.uri},
            )


def _names_filled(snapshot: Snapshot) -> Iterator[types.CompletionItem]:
    """The variables and arrays, and the macros whose text is a name: the controller reads a macro's text in
    its place (000:9110), and a number where a name is filled is a syntax error (2003)."""
    macros = snapshot.model.program.macros
    for item in _symbols(snapshot):
        definition = macros.get(item.data["symbol"]) if item.data["macro"] else None
        if definition is None or [kind for kind, _ in definition.body] == [TokenKind.NAME]:
            yield item


def _symbol_description(snapshot: Snapshot, data: dict[str, object]) -> str | None:
    """What hover says of the symbol a completion item names, in the document's latest analysis."""
    symbols = snapshot.model.symbols
    table = symbols.macros if data.get("macro") else symbols.variables
    found = table.get(str(data.get("symbol")))
    return describe.symbol(snapshot, found) if found is not None else None


def _labels(snapshot: Snapshot) -> Iterator[types.CompletionItem]:
    """The labels a jump may name, but the event handlers, which the controller calls: each named as the outline
    names it (``label_kind``), a subroutine or a place in the code."""
    for section in sections(snapshot):
        if not section.is_event:
            kind, detail = label_kind(section)
            yield types.CompletionItem(label=section.symbol.name, kind=_LABEL_KINDS[kind], detail=detail)


def event_names(snapshot: Snapshot) -> list[str]:
    """The handlers the configured controller calls: #ONERROR, #IN0 .. #INx, #FASTINx ...; in a v3 program the
    v3 guide's: #ONERROR, #STOP, #IN0 .. #IN7 and #FASTPOS (001:414-417, 2523-2525)."""
    if snapshot.settings.dialect is Dialect.V3:
        handlers = (name.removeprefix("#") for name in database().v3_keywords if name.startswith("#"))
        return [name for name in handlers if event_of(name, Dialect.V3) is not None]
    target = snapshot.model.controller
    numbered = {
        "IN": range(target.digital_inputs.low, target.digital_inputs.high + 1),
        "FASTIN": sorted(target.fast_inputs),
        "COMMS": range(1, 6),
    }
    names: list[str] = []
    for word in database().keywords.values():
        if word.kind is not KeywordKind.EVENT or not word.available_on(snapshot.settings.controller):
            continue
        base = word.name.lstrip("#")
        if event_of(base, snapshot.settings.dialect) is not None:
            names.append(base)
        names.extend(f"{base}{number}" for number in numbered.get(base, ()))
    return names


def _constants(dialect: Dialect, controller: Controller) -> Iterator[types.CompletionItem]:
    """The dialect's own predefined constants: v3's are its own (001:1309-1336), none of them v4's; each detail
    says where its keyword refuses it on ``controller``."""
    db = database()
    records = db.v3_constants if dialect is Dialect.V3 else db.constants_of(dialect)
    for name in (constant.name for constant in records.values()):
        detail = describe.constant_detail(name, dialect, controller)
        yield types.CompletionItem(label=name, kind=types.CompletionItemKind.EnumMember, detail=detail)


def _mintmt_block_word_fits(kind: TokenKind, blocks: OpenBlocks | None) -> bool:
    """Whether MintMT's block word of ``kind`` can start a statement inside ``blocks`` (None: not known)."""
    if kind in _OUTSIDE_EVERY_BLOCK:
        return blocks is None or not blocks.kinds
    return _in_its_block(kind.value, blocks)


def _mintmt_block_words(blocks: OpenBlocks | None) -> Iterator[types.CompletionItem]:
    for kind in mintmt_words.COMPLETED:
        if not _mintmt_block_word_fits(kind, blocks):
            continue
        word = mintmt_words.WORDS[kind]
        yield types.CompletionItem(
            label=word.spelling,
            kind=types.CompletionItemKind.Keyword,
            detail="MintMT block",
            documentation=types.MarkupContent(kind=types.MarkupKind.Markdown, value=mintmt_words.describe(word)),
        )


def _event_blocks_elsewhere(snapshot: Snapshot, line: int) -> set[Event | None]:
    """The events MintMT's Event blocks handle, but for one on ``line`` (0-based), being typed."""
    placed = {found.number: found for found in snapshot.document.placed}  # by 1-based line, as blocks are
    handled: set[Event | None] = set()
    for block in snapshot.model.structures[snapshot.unit].blocks:
        if block.kind is not BlockKind.EVENT or block.opener.line == line + 1 or block.opener.line not in placed:
            continue
        opener = n.flatten_statements(placed[block.opener.line].syntax.statements)[block.opener.index]
        if isinstance(opener, n.EventBlock):
            handled.add(event_of(opener.name.text, Dialect.MINTMT))
    return handled


def _event_blocks(snapshot: Snapshot, line: int) -> Iterator[types.CompletionItem]:
    """After MintMT's ``Event`` on ``line``: the events a block can handle, the notes' spelt as they spell them,
    then v4's handlers' the controller calls; not those the program handles already, by an Event block or a
    label, as a second handler of an event is an error (MT-13)."""
    spelt = {event_of(name, Dialect.MINTMT) for name in mintmt_words.EVENT_BLOCK_NAMES}
    v4 = [name for name in event_names(snapshot) if event_of(name, Dialect.MINTMT) not in spelt]
    handled = _handled_elsewhere(snapshot, line) | _event_blocks_elsewhere(snapshot, line)
    for name in (*mintmt_words.EVENT_BLOCK_NAMES, *v4):
        if event_of(name, Dialect.MINTMT) in handled:
            continue
        yield types.CompletionItem(
            label=name,
            kind=types.CompletionItemKind.Event,
            documentation=types.MarkupContent(kind=types.MarkupKind.Markdown, value=mintmt_words.event_name(name)),
        )


def _snippets(dialect: Dialect, blocks: OpenBlocks | None) -> Iterator[types.CompletionItem]:
    snippets = SNIPPETS
    if dialect is Dialect.MINTMT:  # MintMT's own spellings of the blocks it writes otherwise
        snippets = {label: body for label, body in SNIPPETS.items() if label not in _V4_SPELT} | {
            label: body
            for label, body in mintmt_words.SNIPPETS.items()
            if blocks is None or not blocks.kinds or label not in mintmt_words.TOP_LEVEL_SNIPPETS
        }
    for label, body in snippets.items():
        yield types.CompletionItem(
            label=label,
            kind=types.CompletionItemKind.Snippet,
            insert_text=body,
            insert_text_format=types.InsertTextFormat.Snippet,
            filter_text=label.split()[0],
        )


def _inside_text(tokens: list[Token]) -> bool:
    """A comment runs to the end of the line; a string or character constant is open until its closing quote."""
    last = tokens[-1]
    if last.kind is TokenKind.COMMENT:
        return True
    if last.kind is TokenKind.STRING:
        return len(last.text) < 2 or last.text[-1] != last.text[0]
    quoted = [token for token in tokens if token.text[:1] in _SINGLE_QUOTES]
    return bool(quoted) and (len(quoted[-1].text) < 2 or quoted[-1].text[-1] not in _SINGLE_QUOTES)


def _handled_elsewhere(snapshot: Snapshot, line: int) -> set[object]:
    """The events whose handler the program already has, on a line other than ``line`` (0-based): a second
    handler of one event is a label defined twice (E3004), and the one on the cursor's line is being typed."""
    positions, dialect = snapshot.positions, snapshot.settings.dialect
    return {
        event_of(label.name, dialect)
        for label in snapshot.model.symbols.labels[snapshot.unit].values()
        if any(positions.position(definition.span.start).line != line for definition in label.definitions)
    }


def _after_hash(snapshot: Snapshot, hash_: Token, cursor: types.Position) -> list[types.CompletionItem]:
    """Label names replacing the ``#...`` typed so far, whichever characters the client counts as a word: the
    labels jumped to that no other line defines, then the handlers of the events the program does not handle
    already, by a label or by MintMT's Event block (MT-13)."""
    typed = types.Range(start=types.Position(cursor.line, cursor.character - len(hash_.text)), end=cursor)
    handled = _handled_elsewhere(snapshot, cursor.line) | _event_blocks_elsewhere(snapshot, cursor.line)
    events = [name for name in event_names(snapshot) if event_of(name, snapshot.settings.dialect) not in handled]
    called = gosub_targets(snapshot)
    kinds = {
        label.references[0].spelling: _SUBROUTINE if label.identity in called else _PLACE
        for label in _labels_to_write(snapshot, cursor.line)
    }
    kinds.update(dict.fromkeys(events, types.CompletionItemKind.Event))
    return [
        types.CompletionItem(
            label=f"#{name}",
            kind=kind,
            filter_text=f"#{name}",
            text_edit=types.TextEdit(range=typed, new_text=f"#{name}"),
        )
        for name, kind in kinds.items()
    ]


def _labels_to_write(snapshot: Snapshot, line: int) -> list[Symbol]:
    """The labels a jump names that no line but ``line`` (0-based, the one being typed) defines, as first named."""
    positions = snapshot.positions
    return [
        label
        for label in snapshot.model.symbols.labels[snapshot.unit].values()
        if label.references
        and all(positions.position(definition.span.start).line == line for definition in label.definitions)
    ]


def _undeclared(snapshot: Snapshot) -> Iterator[types.CompletionItem]:
    """The names the program uses that no DIM declares (each an error 3001), as first written; none in Mint v3,
    whose variables need no DIM, which makes arrays (001:1525-1528)."""
    if snapshot.settings.dialect is Dialect.V3:
        return
    for symbol in snapshot.model.symbols.variables.values():
        if symbol.references and not symbol.definitions:
            yield types.CompletionItem(label=symbol.references[0].spelling, kind=types.CompletionItemKind.Variable)


def _macro_numbers(definition: MacroDefinition) -> list[int] | None:
    """The numbers a macro's text is: ``0`` gives [0], ``[0,1]`` gives [0, 1]; None for any other text."""
    body = [text for _, text in definition.body]
    if body[:1] == ["["] and body[-1:] == ["]"]:
        body = body[1:-1:2] if all(comma == "," for comma in body[2:-1:2]) else []
    if body and all(text.isdigit() for text in body):
        return [int(text) for text in body]
    return None


def _addressed_by(keyword: Token, snapshot: Snapshot) -> tuple[str, ChannelRange] | None:
    name = snapshot.settings.words.keyword_name(keyword.text)
    return addressed(name, snapshot.model.controller) if name is not None else None


def _after_address(snapshot: Snapshot, before: list[Token], typed: types.Range) -> list[types.CompletionItem] | None:
    """After ``KW.``: the numbers KW addresses on the controller, then the macros that name valid ones.

    The dot before a macro is only a delimiter (3.5: ``SF.g1`` where g1 is ``[0,1]``), so a macro
    naming one number is written after two (``MOVER..xAxis``), or after ``.^`` or ``..`` as typed.
    MintMT's round bracket (``MOVER(``) takes the same numbers and any of those macros by name.
    None when the cursor is not after a keyword's dot or bracket.
    """
    kinds = [token.kind for token in before[-3:]]
    delimited = kinds[-2:] in ([TokenKind.DOT, TokenKind.DOT], [TokenKind.DOT, TokenKind.CIRCUMFLEX])
    bracketed = kinds[-1:] == [TokenKind.ADDRESS]
    if kinds[-1:] != [TokenKind.DOT] and not delimited and not bracketed:
        return None
    keyword = before[-3] if delimited and len(before) >= 3 else before[-2] if len(before) >= 2 else None
    found = _addressed_by(keyword, snapshot) if keyword is not None and keyword.kind is TokenKind.KEYWORD else None
    if found is None:
        return []
    noun, valid = found
    items = [] if delimited else [_number_item(noun, number) for number in range(valid.low, valid.high + 1)]
    for definition in snapshot.model.program.macros.values():
        numbers = _macro_numbers(definition)
        if not numbers or not all(number in valid for number in numbers) or (len(numbers) > 1 and noun != "axis"):
            continue
        listed = definition.body[0][1] == "["
        if not (delimited and listed):  # KW..[0,1] is no selector
            text = definition.name if delimited or listed or bracketed else f".{definition.name}"
            names = f"{noun if len(numbers) == 1 else 'axes'} {', '.join(map(str, numbers))}"
            items.append(_macro_item(definition.name, text, names, typed))
    return items


_AXIS_LIST_ENTRIES = frozenset({TokenKind.NUMBER, TokenKind.NAME, TokenKind.COMMA})


def _in_axis_list(snapshot: Snapshot, before: list[Token], typed: types.Range) -> list[types.CompletionItem] | None:
    """In an axis keyword's square brackets (``SPEED[0,``): the axes of the controller, the variables and the
    macros that name one valid axis, since an axis there is a number or a simple variable and never an
    expression (000:580-588: ``MOVER[a+1]`` is invalid, and so a keyword or function there is 2003); nothing
    right after an axis, where only ``,`` or ``]`` can come, and nothing in a channel keyword's brackets,
    which take none (000:560: ``ADC.0``, never ``ADC[0]``). None when the cursor is in no such list."""
    opened = next((at for at in range(len(before) - 1, -1, -1) if before[at].kind not in _AXIS_LIST_ENTRIES), None)
    if opened is None or opened == 0 or before[opened].kind is not TokenKind.LSQB:
        return None
    keyword = before[opened - 1]
    found = _addressed_by(keyword, snapshot) if keyword.kind is TokenKind.KEYWORD else None
    if found is None:
        return None
    if found[0] != "axis" or before[-1].kind not in (TokenKind.LSQB, TokenKind.COMMA):
        return []
    valid = found[1]
    items = [_number_item("axis", number) for number in range(valid.low, valid.high + 1)]
    items.extend(item for item in _symbols(snapshot) if item.detail == SymbolKind.VARIABLE.value)
    for definition in snapshot.model.program.macros.values():
        numbers = _macro_numbers(definition)
        if numbers is not None and len(numbers) == 1 and numbers[0] in valid and definition.body[0][1] != "[":
            items.append(_macro_item(definition.name, definition.name, f"axis {numbers[0]}", typed))
    return items


def _number_item(noun: str, number: int) -> types.CompletionItem:
    kind = types.CompletionItemKind.Value
    return types.CompletionItem(label=str(number), kind=kind, detail=f"{noun} {number}", sort_text=f"0{number:04d}")


def _macro_item(name: str, text: str, names: str, typed: types.Range) -> types.CompletionItem:
    return types.CompletionItem(
        label=name,
        kind=types.CompletionItemKind.Constant,
        detail=f"macro for {names}",
        sort_text=f"1{name}",
        filter_text=name,
        text_edit=types.TextEdit(range=typed, new_text=text),
    )


def complete(
    snapshot: Snapshot, prefix: str, cursor: types.Position, blocks: OpenBlocks | None = None
) -> list[types.CompletionItem]:
    """Items for the cursor at the end of ``prefix`` (its line so far); names come from ``snapshot``, and the
    words that close a block only where ``blocks``, those open at the cursor, let them (all, when None)."""
    tokens = prefix_tokens(prefix, snapshot.settings.dialect)
    if tokens and _inside_text(tokens):
        return []
    before = significant(tokens)
    partial: Token | None = None
    if before and before[-1].end == len(prefix) and (before[-1].kind in _PARTIAL_WORDS or _begun(before[-1])):
        partial = before.pop()  # the word being typed
    if partial is not None and partial.text.startswith("#"):
        return _after_hash(snapshot, partial, cursor) if partial.kind is TokenKind.LABEL or not before else []
    typed = types.Range(
        start=types.Position(cursor.line, cursor.character - (len(partial.text) if partial else 0)), end=cursor
    )
    dotted = _after_address(snapshot, before, typed)
    if dotted is not None:
        return dotted
    listed = _in_axis_list(snapshot, before, typed)
    if listed is not None:
        return listed
    previous = before[-1] if before else None
    if previous is not None and previous.kind is TokenKind.EVENT:
        return list(_event_blocks(snapshot, cursor.line))
    if previous is not None and previous.kind is TokenKind.DIM:
        return list(_undeclared(snapshot))
    if previous is not None and (previous.kind in _NOTHING_AFTER or previous.text.endswith(".")):
        return []  # a new name, a complete statement, or the decimals of a number
    if partial is not None and partial.text.startswith("_"):
        return list(_constants(snapshot.settings.dialect, snapshot.settings.controller))
    if previous is not None and previous.kind in (TokenKind.GOSUB, TokenKind.GOTO):
        return list(_labels(snapshot))
    if _at_a_name_filled(before):
        return list(_names_filled(snapshot))
    statement = previous is None or previous.kind in _STATEMENT_STARTERS
    if previous is not None and previous.kind is TokenKind.KEYWORD:
        # A keyword that starts the statement is a command or a parameter (GO, SPEED): what follows is
        # its axes or "=", nothing to complete; anywhere else it is a value read (IF IN3 ...).
        starts = len(before) == 1 or before[-2].kind in _STATEMENT_STARTERS
        return [] if starts else list(_continuations(_statement_words(snapshot, before), snapshot.settings))
    if not statement and previous is not None and previous.kind in _OPERAND_ENDS:
        return list(_continuations(_statement_words(snapshot, before), snapshot.settings))
    items = [*_keywords(snapshot, statement, blocks), *_symbols(snapshot)]
    if statement:
        return items + list(_snippets(snapshot.settings.dialect, blocks))
    return _null(snapshot, before) + items


def _null(snapshot: Snapshot, before: list[Token]) -> list[types.CompletionItem]:
    """NULL, first, where the cursor is in an operand that takes it; else nothing."""
    operand = callee_at(before, snapshot.settings)
    name = snapshot.settings.words.keyword_name(operand.keyword.text) if operand is not None else None
    if operand is None or not operand.bracketed or _NULL_OPERANDS.get(name or "") != operand.operand:
        return []
    text = describe.constant("NULL")
    documentation = types.MarkupContent(kind=types.MarkupKind.Markdown, value=text) if text else None
    return [
        types.CompletionItem(
            label="NULL", kind=types.CompletionItemKind.Constant, detail="no array", documentation=documentation
        )
    ]


def register(server: MintServer) -> None:
    @server.feature(
        types.TEXT_DOCUMENT_COMPLETION,
        types.CompletionOptions(trigger_characters=["_", "#", "."], resolve_provider=True),
    )
    def completion(params: types.CompletionParams) -> types.CompletionList:
        typing = server.typing(params.text_document.uri, params.position)
        if typing is None:
            return types.CompletionList(is_incomplete=False, items=[])
        snapshot, prefix = typing
        document = server.document(params.text_document.uri)
        assert document is not None  # ``typing`` answers only for an open document
        line = params.position.line
        current = snapshot.version == document.version
        blocks = _open_blocks(snapshot, line) if current else _open_blocks_now(snapshot, document.source, line)
        items = complete(snapshot, prefix, params.position, blocks)
        return types.CompletionList(is_incomplete=False, items=items)

    @server.feature(types.COMPLETION_ITEM_RESOLVE)
    def resolve(item: types.CompletionItem) -> types.CompletionItem:
        data = item.data if isinstance(item.data, dict) else {}
        if "symbol" in data:
            snapshot = server.analyses.latest(str(data.get("uri")))
            text = _symbol_description(snapshot, data) if snapshot is not None else None
        else:
            text = _keyword_description(data, server.analyses.settings)
        if text is not None:
            item.documentation = types.MarkupContent(kind=types.MarkupKind.Markdown, value=text)
        return item


def _keyword_description(data: dict[str, object], settings: Settings) -> str | None:
    """The keyword of an item in the dialect and on the controller it was offered for (``settings``' for an
    item that does not say)."""
    name, dialect, controller = data.get("keyword"), data.get("dialect"), data.get("controller")
    if not isinstance(name, str):
        return None
    offered = Dialect(dialect) if dialect in set(Dialect) else settings.dialect
    on = Controller(controller) if controller in set(Controller) else settings.controller
    word = database().keywords_of(offered).get(name.upper()) or database().lookup(name)
    return describe.keyword(word, on, dialect=offered) if word is not None else None
