"""``mint.dialect = auto``: a text is MintMT when it shows a form only MintMT has, Mint v4 otherwise."""

from __future__ import annotations

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from mintlang.detection import MintMTForm, detect_dialect, detect_dialect_after, first_mintmt_form
from mintlang.dialect import Dialect
from tests.corpus_files import CorpusCase, cases

MINTMT_LISTINGS = cases("mintmt")
V4_EXAMPLES = [case for folder in ("v4/valid", "v4/invalid", "v4/runtime") for case in cases(folder)]


@pytest.mark.parametrize("case", MINTMT_LISTINGS, ids=lambda case: case.name)
def test_every_listing_of_the_mintmt_notes_reads_as_mintmt(case: CorpusCase) -> None:
    assert detect_dialect(case.source) is Dialect.MINTMT


@pytest.mark.parametrize("case", V4_EXAMPLES, ids=lambda case: case.name)
def test_every_example_of_the_v4_guide_reads_as_v4(case: CorpusCase) -> None:
    assert detect_dialect(case.source) is Dialect.V4


@pytest.mark.parametrize(
    "text",
    [
        pytest.param("' Main code block\n", id="quote comment at a line start"),
        pytest.param("MOVER.0 = 10  ' relative move\n", id="quote comment after code"),
        pytest.param("a = 1 ‘ typographic quote\n", id="typographic quote comment"),
        pytest.param("LOOP\nEnd Loop\n", id="End Loop"),
        pytest.param("IF a = 1 DO\nEnd If\n", id="End If"),
        pytest.param("IF a = 1 DO : b = 2 : End  if\n", id="End If after a colon, two spaces, lower case"),
        pytest.param("Event Comms1\nEnd Event\n", id="Event block"),
        pytest.param("event movebufferlow\n", id="Event line in lower case"),
        pytest.param("Startup\n", id="Startup line"),
        pytest.param("MOVER(0) = 10\n", id="round-bracket addressing"),
        pytest.param("a = POS(1)\n", id="round-bracket addressing in an expression"),
        pytest.param("LOOP\nEND\tLOOP\n", id="End Loop with a tab"),
        pytest.param("MOVER (0) = 10\n", id="a space before the bracket"),
        pytest.param("PRINT 1\r\nPRINT 2\r' note\rPRINT 3\r\n", id="among lines ended by CR LF and CR"),
        pytest.param("PRINT 1\n" * 500 + "a = 1 ’ note\n" + "PRINT 2\n" * 500, id="one line among a thousand"),
    ],
)
def test_a_form_only_mintmt_has_makes_the_text_mintmt(text: str) -> None:
    assert detect_dialect(text) is Dialect.MINTMT


@pytest.mark.parametrize(
    ("text", "form"),
    [
        pytest.param("a = 1\r\nb = 2\r\nc = 3 ' note\r\n", MintMTForm(3, "a ' comment"), id="lines ended by CR LF"),
        pytest.param("a = 1\rb = 2\rEnd If\r", MintMTForm(3, "End If"), id="lines ended by CR alone"),
        pytest.param(
            "x = 1\r\n\ry = 2\nStartup", MintMTForm(4, "Startup"), id="mixed line ends, the last line unended"
        ),
        pytest.param("REM (x)\n\nMOVER(0) = 1\n", MintMTForm(3, "MOVER(…)"), id="a bracket in a comment above"),
        pytest.param(
            "a = 'A' : b = ABS(c)\n\n\nEvent x\n", MintMTForm(4, "Event x"), id="no form on a line with a quote"
        ),
    ],
)
def test_the_first_form_is_named_with_its_line(text: str, form: MintMTForm) -> None:
    assert first_mintmt_form(text) == form


@pytest.mark.parametrize(
    "text",
    [
        pytest.param("", id="empty"),
        pytest.param("a = 'A'\n", id="character constant"),
        pytest.param("IF key = '1' THEN GOSUB teach\n", id="character constant before more code"),
        pytest.param("REM dialect: mintmt\nREM ' not a comment start\n", id="REM comments"),
        pytest.param('PRINT "it\'s"\n', id="quote inside a string"),
        pytest.param("DIM event\nevent = 1\n", id="a variable called event"),
        pytest.param("LOOP\nENDL\nIF a DO\nENDIF\n", id="v4 closers"),
        pytest.param("MOVER.0 = 10 : MOVER[1] = 5\n", id="dot and square-bracket addressing"),
        pytest.param("a = ABS(b) + (c)\n", id="function call and parentheses"),
        # LOCATE x, y and LINE n, ... (000:13675, 000:13630) take no axes: the bracket groups an operand
        pytest.param("LOCATE (col + 1), 2\n", id="a bracketed first operand of LOCATE"),
        pytest.param('LINE (row), "speed"\n', id="a bracketed first operand of LINE"),
        pytest.param("END\n", id="END alone"),
        # legal v3, where adc is no keyword: the array's elements (001:7303-7353)
        pytest.param("DIM adc(4) = 1,2,3,4\n? adc(3)\n", id="an array named like a keyword"),
        # v3 keeps an array on the memory card with DIM OFFLINE (001:1588-1589)
        pytest.param("DIM OFFLINE adc(4)\nadc(1) = 5\n", id="an offline array named like a keyword"),
    ],
)
def test_without_such_a_form_the_text_is_v4(text: str) -> None:
    assert detect_dialect(text) is Dialect.V4


_LINES = st.sampled_from(
    [
        "PRINT 1",
        "Loop",
        "End Loop",
        "ENDL",
        "' a note",
        "REM note",
        "MOVER(0) = 10",
        "MOVER.0 = 10",
        "a = 'A'",
        "",
        "DIM mover(2)",
    ]
)
_TEXTS = st.lists(_LINES, max_size=8).map("\n".join)


@given(
    first=_TEXTS,
    edits=st.lists(st.tuples(st.floats(0, 1), st.integers(0, 12), _LINES | st.sampled_from(["\n", "\r", "'", "("]))),
)
@example(  # a DIM typed straight after a number: the lexer reads it, a word boundary would not
    first="PRINT 1\nPRINT 1\nPRINT 1\nPRINT 1\nPRINT 1\nMOVER(0) = 10",
    edits=[(0.0, 2, "MOVER.0 = 10"), (0.125, 0, "DIM mover(2)")],
)
def test_detecting_after_each_edit_from_the_last_text_is_detecting_afresh(
    first: str, edits: list[tuple[float, int, str]]
) -> None:
    """The language server reads only the lines an edit changed, whatever the texts."""
    text, found = first, detect_dialect(first)
    for where, removed, typed in edits:
        offset = int(where * len(text))
        edited = text[:offset] + typed + text[offset + removed :]
        found = detect_dialect_after(text, found, edited)
        assert found is detect_dialect(edited)
        text = edited


@pytest.mark.parametrize(
    ("previous", "edited"),
    [
        pytest.param("DIM mover(2)\nMOVER(0) = 10\n", "MOVER(0) = 10\n", id="the DIM removed"),
        pytest.param("MOVER(0) = 10\n", "DIM mover(2)\nMOVER(0) = 10\n", id="a DIM typed above"),
        pytest.param("DIM mover(2)\nPRINT 1\n", "DIM mover(2)\nMOVER(0) = 10\n", id="an element typed"),
        pytest.param("MOVER(0) = 10\n", "DIM OFFLINE mover(2)\nMOVER(0) = 10\n", id="a DIM OFFLINE typed above"),
    ],
)
def test_an_edit_to_an_array_declaration_elsewhere_is_seen(previous: str, edited: str) -> None:
    """Whether ``NAME(`` is MintMT's addressing depends on a ``DIM NAME(`` on another line."""
    assert detect_dialect_after(previous, detect_dialect(previous), edited) is detect_dialect(edited)
