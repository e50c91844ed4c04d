"""The formatter's two promises, on generated programs and on every program of the corpus: formatting
twice gives what formatting once gives, and a formatted program parses to what it parsed to, whitespace
and letter case aside (the controller reads neither)."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st
from lsprotocol import types

from mintlang.diagnostics import Span
from mintlang.dialect import Dialect
from mintlang.formatting import first_syntax_error
from mintlang.lsp.features.formatting import format_lines
from mintlang.lsp.positions import Positions
from mintlang.lsp.workspace import Analyses, Settings, Snapshot

CORPUS = Path(__file__).parents[1] / "corpus"
PROGRAMS = sorted(path for path in CORPUS.rglob("*") if path.suffix in (".mnt", ".cfg"))
OPTIONS = [types.FormattingOptions(tab_size=2, insert_spaces=True), types.FormattingOptions(4, insert_spaces=False)]


def snapshot_of(text: str, dialect: Dialect = Dialect.V4) -> Snapshot:
    settings = Settings.from_options({"dialect": dialect.value})  # given, as an editor's: over any settings file
    return Analyses(read=lambda uri: None, settings=settings).snapshot("file:///p.mnt", text, 1)


def formatted(text: str, options: types.FormattingOptions, dialect: Dialect = Dialect.V4) -> str:
    snapshot = snapshot_of(text, dialect)
    positions = Positions(text)
    edits = format_lines(snapshot, options, range(positions.line_count))
    assert len({edit.range.start.line for edit in edits}) == len(edits)  # one edit per line: they never overlap
    assert all(edit.range.start.line == edit.range.end.line for edit in edits)
    for span, new in sorted(((positions.span(edit.range), edit.new_text) for edit in edits), reverse=True):
        text = text[: span.start] + new + text[span.end :]
    return text


def shape(value: object) -> object:
    """A syntax tree without its places and letter case: what the controller runs."""
    if isinstance(value, Span):
        return None
    fields = getattr(type(value), "__dataclass_fields__", None)
    if fields is not None:
        return (
            type(value).__name__,
            *(shape(getattr(value, name)) for name in fields if name != "text" or _named(value)),
        )
    if isinstance(value, tuple):
        return tuple(shape(item) for item in value)
    return value.upper() if isinstance(value, str) else value


def _named(value: object) -> bool:
    """A node whose ``text`` is a name or a literal (a line's ``text`` is its raw source)."""
    return type(value).__name__ != "LineSyntax"


def parsed(text: str, dialect: Dialect = Dialect.V4) -> object:
    document = snapshot_of(text, dialect).document
    return [shape(line.syntax) for line in document.placed], shape(document.definitions)


STATEMENTS = [
    "DIM a", "dim b = 2", "#main", "#sub : print a", "loop", "endl", "for i = 1 to 10", "next", "if a > 1 do",
    "else", "endif", "while a < 3", "endw", "repeat", "until a", "a = a + 1", 'print "x  ", a', "rem note  ",
    "gosub main", "return", "end", "DIM xs(3) = 1,", "2, 3", "define fast = speed.0 = 10", "speed.0 = fast", "",
    ": ", 'IF a THEN PRINT "t" : goto main', "exit", "sp[0,1] = 10;", "  REM   spaced    out", "#ONERROR", "&",
]  # fmt: skip
LINES = st.tuples(
    st.sampled_from(["", " ", "  ", "\t", " \t "]),
    st.sampled_from(STATEMENTS),
    st.sampled_from([str, str.lower, str.upper]),
    st.sampled_from(["", " ", "\t", "   "]),
    st.sampled_from(["\n", "\r\n"]),
)


@given(st.lists(LINES, max_size=14), st.sampled_from(OPTIONS))
def test_formatting_twice_is_formatting_once_and_keeps_the_program(lines, options):
    text = "".join(indent + case(statement) + trailing + end for indent, statement, case, trailing, end in lines)
    once = formatted(text, options)
    assert formatted(once, options) == once
    assert parsed(once) == parsed(text)
    if first_syntax_error(snapshot_of(text).document) is not None:
        assert once == text  # left as it is, as mint format leaves it ('&' alone, a continuation without its DIM)
        return
    assert all(line == line.rstrip(" \t") for line in once.splitlines())  # no trailing blanks
    labelled = [line.number for line in snapshot_of(once).document.placed if line.syntax.label is not None]
    assert all(once.splitlines()[number - 1].startswith("#") for number in labelled)  # labels at the margin


MINTMT_STATEMENTS = [
    "Loop", "End Loop", "If (COMMS(1) = 1) Then", "EndIf", "End  if", "Event Comms1", "Event MOVEBUFFERLOW",
    "End Event", "Startup", "End Startup", "MOVER(0) = 10      ' load a move", "GO(0,1)", "' a comment  ",
    "MOVEBUFFERSIZE([0,1]) = 4;", "If POS(0) > 2 Then JOG(1) = 0", "DIM a", "a = a + 1 ' count", "rem  old style",
    "CONTOURPARAMETER([0,1],0) = 10;", "",
]  # fmt: skip
MINTMT_LINES = st.tuples(
    st.sampled_from(["", " ", "  ", "\t"]),
    st.sampled_from(MINTMT_STATEMENTS),
    st.sampled_from([str, str.lower, str.upper]),
    st.sampled_from(["", " ", "\t"]),
    st.sampled_from(["\n", "\r\n"]),
)


@given(st.lists(MINTMT_LINES, max_size=14), st.sampled_from(OPTIONS))
def test_mintmt_formatting_twice_is_formatting_once_and_keeps_the_program_and_its_words(lines, options):
    text = "".join(indent + case(statement) + trailing + end for indent, statement, case, trailing, end in lines)
    once = formatted(text, options, Dialect.MINTMT)
    assert formatted(once, options, Dialect.MINTMT) == once
    assert parsed(once, Dialect.MINTMT) == parsed(text, Dialect.MINTMT)
    # only blanks change: MintMT's words and comments keep their case
    assert [line.strip(" \t") for line in once.splitlines()] == [line.strip(" \t") for line in text.splitlines()]


DIALECT_OF = {"v3": Dialect.V3, "mintmt": Dialect.MINTMT}  # by the corpus folder; v4 otherwise


@pytest.mark.parametrize("path", PROGRAMS, ids=lambda path: str(path.relative_to(CORPUS)))
def test_every_corpus_program_formats_stably_and_keeps_its_parse(path):
    text = path.read_text(encoding="utf-8", errors="replace")
    dialect = next((DIALECT_OF[part] for part in path.relative_to(CORPUS).parts if part in DIALECT_OF), Dialect.V4)
    once = formatted(text, OPTIONS[0], dialect)
    assert formatted(once, OPTIONS[0], dialect) == once
    assert parsed(once, dialect) == parsed(text, dialect)
