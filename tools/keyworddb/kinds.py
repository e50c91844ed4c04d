"""Decide a keyword's grammatical kind from its entry.

The guide has no "kind" column; these word lists are the language facts the
brief and chapter 2 of the guide state, and everything else follows from the
attributes table or the format lines.
"""

from __future__ import annotations

from mintlang.keyworddb.model import Attributes, KeywordKind

OPERATORS = frozenset({"AND", "OR", "XOR", "NOT", "MOD", "~"})
STATEMENTS = frozenset(
    {
        *("IF", "THEN", "DO", "ELSE", "ENDIF", "FOR", "TO", "STEP", "NEXT"),
        *("REPEAT", "UNTIL", "WHILE", "ENDW", "LOOP", "ENDL", "EXIT"),
        *("GOSUB", "GOTO", "RETURN", "END", "PAUSE", "DIM", "DEFINE"),
        *("PRINT", "INPUT", "REM", "AXES", "USING", "HEX", "DEC", "BIN", ":", "#"),
    }
)
COMMAND_LINE = frozenset({"CON", "DEL", "EDIT", "FREE", "INS", "LIST", "NEW", "PROG", "RELEASE", "VIEW"})
"""Chapter 9 editor commands, plus VIEW, which only reports to the terminal."""

_ACTION_VERBS = frozenset(
    {
        *("abort", "add", "begin", "bring", "clear", "connect", "connects", "display"),
        *("displays", "execute", "issue", "load", "loads", "perform", "place", "reset"),
        *("resets", "scan", "start", "starts", "interrupt", "output", "print", "write"),
    }
)
"""Quick-reference description openings that mean "does something" rather than "is a value"."""


def kind_from_attributes(rows: tuple[Attributes, ...]) -> KeywordKind | None:
    """Parameter if any row reads or writes it, command if it is only a command."""
    if not rows:
        return None
    if any(row.read or row.write for row in rows) and not all(row.command and not row.write for row in rows):
        return KeywordKind.PARAMETER
    return KeywordKind.COMMAND


def fixed_kind(name: str) -> KeywordKind | None:
    """The kind a name has whatever its entry says: operators, statements, events."""
    if name in OPERATORS:
        return KeywordKind.OPERATOR
    if name in STATEMENTS:
        return KeywordKind.STATEMENT
    if name in COMMAND_LINE:
        return KeywordKind.COMMAND_LINE
    if name.startswith("#"):
        return KeywordKind.EVENT
    return None


def kind_from_description(description: str) -> KeywordKind:
    """For stubs with no entry: a quick-reference phrase starting with an action is a command."""
    words = description.lower().split()
    return KeywordKind.COMMAND if words and words[0] in _ACTION_VERBS else KeywordKind.PARAMETER
