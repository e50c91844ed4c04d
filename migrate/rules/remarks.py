"""M-REMCOLON (optional): ``stmt REM text`` becomes ``stmt : REM text``.

Both versions accept a REM that follows a statement without a colon (v3:11344-11350,
v4:15510-15515); the v3 guide recommends the colon for future compatibility. A REM
after a label or a THEN is left alone: a colon there would change nothing useful
and a label line takes no statement separator.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.diagnostics import Span
from mintlang.migrate.context import Context, FileView, statement_tag
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Rule
from mintlang.syntax import nodes as n
from mintlang.syntax.tokens import TokenKind

_NO_COLON_AFTER = frozenset({TokenKind.NEWLINE, TokenKind.COLON, TokenKind.LABEL, TokenKind.THEN, TokenKind.MACRO_BODY})


class RemColon(Rule):
    """Inserts ``: `` before a REM that directly follows a statement on its line."""

    id = "M-REMCOLON"
    rule_class = RuleClass.MECHANICAL
    phase = Phase.RENAMES
    optional = True
    summary = "'stmt REM text' -> 'stmt : REM text'"
    evidence = "spec M-REMCOLON; v3:11344-11350; v4:15510-15515"

    def apply(self, context: Context) -> Iterator[Action]:
        """A comment runs to the end of its line, after the line's significant tokens: what comes
        before it is the last of those, or the line break ending the line above."""
        for file in context.files.values():
            for offset, line in file.document.physical:
                previous = line.kinds[-1] if line.kinds else TokenKind.NEWLINE
                if line.comment_start >= 0 and previous not in _NO_COLON_AFTER:
                    start = offset + line.comment_start
                    yield self.replace(file, Span(start, start), ": ")


def missing_rem(context: Context, statement: n.Statement) -> bool:
    """Whether ``statement`` is a keyword that takes no operands written with some (``STOP.0 :
    STOP following``): a comment missing its REM, already broken in v3."""
    if not isinstance(statement, n.KeywordStatement) or not statement.arguments or statement.values is not None:
        return False
    return not takes_operands(context, statement.keyword.keyword)


def missing_rem_spans(context: Context) -> Iterator[tuple[FileView, Span]]:
    """Where the application's comments missing their REM are."""
    no_operands = context.mentioned(lambda name: not takes_operands(context, name))
    for file, line in context.placed(*map(statement_tag, no_operands)):
        for statement in n.flatten_statements(line.syntax.statements):
            if missing_rem(context, statement):
                yield file, line.span(statement.span)


def takes_operands(context: Context, keyword: str) -> bool:
    entry = context.db.keywords.get(keyword)
    return entry is None or entry.takes_operands
