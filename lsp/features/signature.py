"""Signature help: the manual's formats of the keyword whose operands the cursor is in (in a v3 file, the v3
guide's).

The parameters are read from each format itself: the comma-separated items in
the brackets after a function's name, or after the ``=`` of a keyword written
to (braces, the manual's optional parts, are trimmed off). A repeated last
item (``{,<expression> ...}``, or a value per axis) stays active for every
further value, and a format whose operands are all written is not offered; a
terminal (``PRINT #1, ...``) is not counted as an operand. The values of PRINT
and LINE, as many as the line holds, are separated by commas or semicolons,
their last item staying active for every further value; after USING (PRINT,
INPUT) the operands are the USING clause's own, ``<int>`` and ``<frac>``. In an
expression the read form (``v = ...``) comes first, at the start of a
statement the written one.
"""

from __future__ import annotations

from lsprotocol import types

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.lsp.describe import round_brackets
from mintlang.lsp.lookup import prefix_tokens, significant
from mintlang.lsp.server import MintServer
from mintlang.lsp.workspace import Settings
from mintlang.records import record
from mintlang.syntax.tokens import Token, TokenKind

_STATEMENT_BREAKS = frozenset({TokenKind.COLON, TokenKind.THEN, TokenKind.DO, TokenKind.ELSE, TokenKind.LABEL})
_KEYWORDS = frozenset({TokenKind.KEYWORD, TokenKind.FUNCTION, TokenKind.PRINT, TokenKind.INPUT, TokenKind.PAUSE})
_FUNCTION = TokenKind.FUNCTION
_TRIM = " {}"
_OPENERS = {"[": "]", "(": ")"}
_USING = "USING"


@record
class Callee:
    """The keyword whose operands the cursor is in (completion reads it too)."""

    keyword: Token
    operand: int  # index of the operand under the cursor
    bracketed: bool  # the cursor is inside the brackets after a function's name
    in_expression: bool
    using: bool = False  # the cursor is in a USING clause (PRINT a USING 5, 2)
    addressing: bool = False  # the cursor is in the axes or channels after the keyword (CIRCLEA[0,1])
    printed: bool = False  # PRINT's or LINE's values: as many as the line holds, the last format item repeated


def _starts_statement(tokens: list[Token], index: int) -> bool:
    return index == 0 or tokens[index - 1].kind in _STATEMENT_BREAKS


def callee_at(tokens: list[Token], settings: Settings) -> Callee | None:
    """The keyword the cursor's operands belong to, and where the cursor is among them."""
    depth = commas = semicolons = 0
    using: int | None = None  # the operand in a USING clause
    for index in range(len(tokens) - 1, -1, -1):
        token = tokens[index]
        if token.kind in _STATEMENT_BREAKS and depth == 0:
            return None
        if token.kind in (TokenKind.RPAR, TokenKind.RSQB):
            depth += 1
        elif token.kind in (TokenKind.LPAR, TokenKind.LSQB, TokenKind.ADDRESS):
            if depth == 0 and token.kind is TokenKind.LPAR and index > 0 and tokens[index - 1].kind is _FUNCTION:
                return Callee(tokens[index - 1], commas, True, not _starts_statement(tokens, index - 1))
            if depth == 0 and token.kind is not TokenKind.LPAR and index > 0 and _addressed(tokens, index - 1):
                return Callee(tokens[index - 1], commas, False, False, addressing=True)
            depth = max(0, depth - 1)
        elif token.kind is TokenKind.COMMA and depth == 0:
            commas += 1
        elif token.kind is TokenKind.SEMICOLON and depth == 0:
            semicolons += 1
        elif token.kind is TokenKind.USING and depth == 0 and using is None:
            using, commas, semicolons = commas, 0, 0
        elif token.kind in _KEYWORDS and depth == 0 and _starts_statement(tokens, index):
            if using is not None:
                return Callee(token, using, False, False, using=True)
            printed = token.kind is TokenKind.PRINT or settings.words.keyword_name(token.text) == "LINE"
            if printed:
                commas += semicolons  # their values are separated by ';' as by ',' (000:15298-15299, 13657)
            return Callee(token, commas - _terminal_commas(tokens, index), False, False, printed=printed)
    return None


def _terminal_commas(tokens: list[Token], index: int) -> int:
    """1 where a comma follows the terminal after the keyword at ``index`` (``PRINT #1, a``), else 0: the
    guide writes the terminal without one (``LOCATE #3 10,10``, ``LINE #3 2, ...``: 000:13693, 13660)."""
    after = tokens[index + 1 : index + 4]
    return int(len(after) == 3 and after[0].kind is TokenKind.HASH and after[2].kind is TokenKind.COMMA)


def _addressed(tokens: list[Token], index: int) -> bool:
    """A keyword starting a statement whose axes or channels open after it (``CIRCLEA[``, MintMT's ``MOVER(``)."""
    return tokens[index].kind is TokenKind.KEYWORD and _starts_statement(tokens, index)


def _items(label: str, start: int, end: int) -> list[tuple[int, int]]:
    """Offsets of the comma-separated items of ``label[start:end]``, spaces and braces trimmed."""
    items = []
    for piece in label[start:end].split(","):
        first, last = start, start + len(piece)
        while first < last and label[first] in _TRIM:
            first += 1
        while last > first and label[last - 1] in _TRIM:
            last -= 1
        if first < last:
            items.append((first, last))
        start += len(piece) + 1
    return items


def _parameters(label: str, name: str, callee: Callee) -> list[tuple[int, int]]:
    """The operands of one format: inside the brackets after ``name``, after its ``=``, after the
    name of a statement (PRINT, PAUSE) up to its USING clause, or in that clause."""
    at = label.upper().find(name)
    if at < 0:
        return []
    after = at + len(name)
    clause = label.find("{" + _USING, after)  # PRINT, INPUT: {USING <int> {,<frac>}}, reached by its word
    if callee.using:
        return _items(label, clause + len(_USING) + 1, len(label)) if clause >= 0 else []
    if callee.addressing:  # CIRCLEA[axis0,axis1] = ...: the operands in the brackets after the name
        closer = _OPENERS.get(label[after : after + 1])
        closing = label.find(closer, after) if closer else -1
        return _items(label, after + 1, closing) if closing > after else []
    if callee.bracketed:
        opening = label.find("(", after)
        closing = label.rfind(")")
        return _items(label, opening + 1, closing) if 0 <= opening < closing else []
    equals = label.find("=", after)
    if equals >= 0:
        return _items(label, equals + 1, len(label))
    if label[after:].lstrip().startswith("("):  # CAMTABLE ( axis, ... ): all its operands are in the brackets closed
        return []
    if label[after : after + 1] in _OPENERS:  # a command's axes: GO[axes], MintMT's GO(axes)
        after = label.find(_OPENERS[label[after]], after) + 1
    if label[after:].lstrip().startswith("{#"):  # the terminal (PRINT #1, ...) is no operand
        after = label.find("}", after) + 1
    return _items(label, after, clause if clause >= 0 else len(label))


@record
class _Entry:
    """A keyword's name, formats and summary as the dialect's guide gives them."""

    name: str
    formats: tuple[str, ...]
    summary: str


def _entry(spelling: str, settings: Settings) -> _Entry | None:
    """The entry of the keyword ``spelling`` names: in a v3 file the v3 guide's (v3's AUXDAC is one output,
    ``AUXDAC = <expr>``: 001:5929, where v4's addresses a channel), else the dialect's own."""
    if settings.dialect is Dialect.V3:
        old = database().lookup_v3(spelling)
        return _Entry(old.name, old.formats, "") if old is not None else None
    word = settings.keyword(spelling)
    return _Entry(word.name, word.formats, word.summary) if word is not None else None


def _signature(word: _Entry, label: str, callee: Callee) -> types.SignatureInformation | None:
    """The format ``label`` with the operand under the cursor active; None when the format takes no such
    operand: an active parameter past the last means the first to the client (LSP 3.17, SignatureHelp)."""
    parameters = _parameters(label, word.name, callee)
    active = callee.operand
    last = label[slice(*parameters[-1])] if parameters else ""
    repeated = callee.printed or "..." in last or "[axes]" in label or "(axes)" in label
    if active >= len(parameters) and parameters:
        if not repeated:
            return None
        active = len(parameters) - 1  # a repeated last operand, or one value per axis
    return types.SignatureInformation(
        label=label,
        documentation=word.summary or None,
        parameters=[types.ParameterInformation(label=item) for item in parameters] or None,
        active_parameter=active if parameters else None,
    )


def signature_help(prefix: str, settings: Settings) -> types.SignatureHelp | None:
    """The formats of the keyword whose operands end ``prefix`` (the cursor's line so far)."""
    callee = callee_at(significant(prefix_tokens(prefix, settings.dialect)), settings)
    if callee is None:
        return None
    word = _entry(callee.keyword.text, settings)
    formats = [label for label in word.formats if word.name in label.upper()] if word is not None else []
    if word is None or not formats:
        return None
    if settings.dialect is Dialect.MINTMT:
        formats = [round_brackets(label, word.name) for label in formats]
    formats.sort(key=lambda label: label.startswith("v =") != callee.in_expression)  # the form in use first
    signatures = [found for label in formats if (found := _signature(word, label, callee)) is not None]
    if not signatures:
        return None
    return types.SignatureHelp(
        signatures=signatures, active_signature=0, active_parameter=signatures[0].active_parameter
    )


def register(server: MintServer) -> None:
    @server.feature(
        types.TEXT_DOCUMENT_SIGNATURE_HELP,
        types.SignatureHelpOptions(trigger_characters=["(", ",", " "], retrigger_characters=[","]),
    )
    def help_(params: types.SignatureHelpParams) -> types.SignatureHelp | None:
        typing = server.typing(params.text_document.uri, params.position)
        return signature_help(typing[1], typing[0].settings) if typing is not None else None
