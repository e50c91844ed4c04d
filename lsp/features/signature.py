"""Signature help: the manual's formats of the keyword whose operands the cursor is in."""

from __future__ import annotations

from lsprotocol import types

from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Keyword
from mintlang.lsp.lookup import prefix_tokens, significant
from mintlang.lsp.server import MintServer
from mintlang.syntax.tokens import Token, TokenKind
from mintlang.syntax.vocabulary import vocabulary

_STATEMENT_BREAKS = frozenset({TokenKind.COLON, TokenKind.THEN, TokenKind.DO, TokenKind.ELSE, TokenKind.LABEL})
_KEYWORDS = frozenset({TokenKind.KEYWORD, TokenKind.FUNCTION, TokenKind.PRINT, TokenKind.INPUT, TokenKind.PAUSE})


def _callee(tokens: list[Token]) -> tuple[Token, int] | None:
    """The keyword the cursor's operands belong to, and the index of the operand under the cursor."""
    depth = commas = 0
    for index in range(len(tokens) - 1, -1, -1):
        token = tokens[index]
        if token.kind in _STATEMENT_BREAKS and depth == 0:
            return None
        if token.kind in (TokenKind.RPAR, TokenKind.RSQB):
            depth += 1
        elif token.kind in (TokenKind.LPAR, TokenKind.LSQB):
            if (
                depth == 0
                and token.kind is TokenKind.LPAR
                and index > 0
                and tokens[index - 1].kind is TokenKind.FUNCTION
            ):
                return tokens[index - 1], commas
            depth = max(0, depth - 1)
        elif token.kind is TokenKind.COMMA and depth == 0:
            commas += 1
        elif token.kind in _KEYWORDS and depth == 0 and (index == 0 or tokens[index - 1].kind in _STATEMENT_BREAKS):
            return token, commas
    return None


def _signature(word: Keyword, text: str) -> types.SignatureInformation:
    parameters = [types.ParameterInformation(label=name) for name in word.parameters if name in text]
    return types.SignatureInformation(label=text, documentation=word.summary or None, parameters=parameters or None)


def signature_help(prefix: str, dialect: Dialect) -> types.SignatureHelp | None:
    """The formats of the keyword whose operands end ``prefix`` (the cursor's line so far)."""
    found = _callee(significant(prefix_tokens(prefix, dialect)))
    if found is None:
        return None
    token, operand = found
    name = vocabulary(dialect).keyword_name(token.text)
    word = database().lookup(name or token.text)
    if word is None or not word.formats:
        return None
    signatures = [_signature(word, text) for text in word.formats]
    return types.SignatureHelp(signatures=signatures, active_signature=0, active_parameter=operand)


def register(server: MintServer) -> None:
    @server.feature(
        types.TEXT_DOCUMENT_SIGNATURE_HELP,
        types.SignatureHelpOptions(trigger_characters=["(", ",", " "], retrigger_characters=[","]),
    )
    def help_(params: types.SignatureHelpParams) -> types.SignatureHelp | None:
        typing = server.typing(params.text_document.uri, params.position)
        return signature_help(typing[1], server.analyses.settings.dialect) if typing is not None else None
