"""One diagnostic where one is enough, and help where a word is misspelt (issue 17, item 8).

An undeclared name is said once per line, at its first use there, and the fix that
respells it respells every use on that line. A word that is no keyword but resembles
one (``IDL`` for ``IDLE``, v4 guide §10.3) is offered that keyword, as a misspelt
variable is offered the declared name it resembles. Hints (I…) are asked for.
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

import mintlang
from mintlang.analysis.suggestions import one_slip_apart
from mintlang.diagnostics import Diagnostic, Edit


def apply(source: str, edits: tuple[Edit, ...]) -> str:
    for edit in sorted(edits, key=lambda edit: edit.span.start, reverse=True):
        source = source[: edit.span.start] + edit.text + source[edit.span.end :]
    return source


def coded(source: str, code: str, **options: object) -> list[Diagnostic]:
    return [d for d in mintlang.check_application(source, **options).program if d.code == code]  # type: ignore[arg-type]


def test_an_undeclared_name_is_reported_at_its_first_use_on_each_line() -> None:
    source = "y = y + y * y\nPRINT y, y\n"
    found = coded(source, "E3001")
    assert [(d.span.start, d.span.end) for d in found] == [(0, 1), (20, 21)]


def test_the_first_use_on_a_line_is_the_leftmost_whatever_the_order_of_the_uses() -> None:
    source = "PRINT b, b\nb = 1\n"
    assert [d.span.start for d in coded(source, "E3001")] == [6, 11]


def test_the_respelling_fix_respells_every_use_on_the_line() -> None:
    source = "DIM total\ntotal = totl + totl * 2\n"
    (error,) = coded(source, "E3001")
    assert error.message.endswith("did you mean 'total'?")
    respell = error.fixes[0]
    assert apply(source, respell.edits) == "DIM total\ntotal = total + total * 2\n"


def test_a_v3_keyword_used_twice_on_a_line_is_renamed_on_the_whole_line() -> None:
    source = "DIM a\na = GAIN + GAIN\nPRINT a\n"
    (error,) = coded(source, "E3001")
    assert "replaced by KPROP" in error.message
    assert apply(source, error.fixes[0].edits) == "DIM a\na = KPROP + KPROP\nPRINT a\n"


@pytest.mark.parametrize(
    ("source", "word", "keyword"),
    [
        pytest.param("PAUSE IDL[0]\n", "IDL", "IDLE", id="read-in-a-statement"),
        pytest.param("SPED.0 = 10\n", "SPED", "SPEED", id="written-with-an-axis"),
        # keywords are read in any case (000:5562-5564): the message quotes the word as the program spells it
        pytest.param("Sped.0 = 10\n", "Sped", "SPEED", id="written-in-mixed-case"),
        pytest.param("STOPP\n", "STOPP", "STOP", id="a-statement-of-its-own"),
        # two letters swapped: difflib finds IDEL only 0.75 like IDLE, and 0.86 like the editor's DEL
        pytest.param("PAUSE IDEL.0\n", "IDEL", "IDLE", id="two-letters-swapped"),
        # other BASICs end WHILE with WEND; Mint with ENDW (v4 guide §3.7.3), not END
        pytest.param("DIM i\nWHILE i < 3\n  i = i + 1\nWEND\nPRINT i\n", "WEND", "ENDW", id="another-basic"),
        # a misspelt command with its arguments: the grammar stops after the name, which is the mistake
        pytest.param('PRNT "hello"\n', "PRNT", "PRINT", id="a-command-with-a-string"),
        pytest.param("PAUS IDLE.0\n", "PAUS", "PAUSE", id="a-command-with-a-keyword"),
        pytest.param("GOSUBB there\nEND\n#there\nRETURN\n", "GOSUBB", "GOSUB", id="a-command-with-a-label"),
    ],
)
def test_a_misspelt_keyword_is_offered_the_keyword(source: str, word: str, keyword: str) -> None:
    (error,) = coded(source, "E3007")
    assert error.message.endswith(f"'{word}' is not a keyword (did you mean '{keyword}'?)")
    (fix,) = error.fixes
    fixed = apply(source, fix.edits)
    assert fixed == source.replace(word, keyword, 1)
    assert coded(fixed, "E3007") == []


def test_a_word_like_no_keyword_gets_no_suggestion() -> None:
    (error,) = coded("QWXZ.1 = 2\n", "E3007")
    assert "did you mean" not in error.message and error.fixes == ()


def test_a_name_used_as_a_command_is_an_unknown_keyword_at_the_name() -> None:
    source = 'QWXZ "label"\n'
    (error,) = coded(source, "E3007")
    assert source[error.span.start : error.span.end] == "QWXZ" and error.fixes == ()
    assert coded(source, "E2003") == []


def test_an_undeclared_name_like_a_keyword_that_holds_a_value_is_offered_it_beside_the_dim() -> None:
    # SPEED is read and written (v4 guide §10.3 SPEED); FOR holds no value, so 'foo' is offered no FOR
    (speed,) = coded("SPED = 10\n", "E3001")
    assert speed.message.endswith("did you mean the keyword 'SPEED'?")
    # two fixes: the choice is the author's, --fix applies neither
    assert [fix.title for fix in speed.fixes] == ["Replace with SPEED", "Declare 'SPED' with DIM"]
    (foo,) = coded("foo = 5\n", "E3001")
    assert "did you mean" not in foo.message


@pytest.mark.parametrize(
    "source",
    [
        # v4 addresses an axis in square brackets or after a dot, never in round ones (000:14497): POS(a) is no
        # reading of POS, so xpos(a) is offered no POS
        pytest.param("DIM a\nFOR a = 1 TO 2\n  MOVEA = xpos(a) : GO\nNEXT\n", id="indexed-as-an-array"),
        # INSTATE is read only (000:12486-12509): a name given a value is offered no read-only keyword
        pytest.param("state = LIMITFORWARD.0\n", id="given-a-value"),
    ],
)
def test_no_keyword_is_offered_where_it_could_not_stand(source: str) -> None:
    for undeclared in coded(source, "E3001"):
        assert "did you mean the keyword" not in undeclared.message
        assert not [fix.title for fix in undeclared.fixes if fix.title.startswith("Replace")]


def test_an_editor_command_is_never_offered_in_a_program() -> None:
    # DEL, LIST, NEW … work at the command line only (v4 guide §3.2): a program that writes one is error 2006
    for source in ("DELL\n", "LISTT\n", "NEWW\n"):
        (error,) = coded(source, "E3007")
        assert all(word not in error.message for word in ("'DEL'", "'LIST'", "'NEW'")), error.message


def _slips(word: str, other: str) -> int:
    """The optimal string alignment distance (insertions, deletions, substitutions, neighbours swapped)."""
    rows = [list(range(len(other) + 1))] + [[i] + [0] * len(other) for i in range(1, len(word) + 1)]
    for i in range(1, len(word) + 1):
        for j in range(1, len(other) + 1):
            cost = word[i - 1] != other[j - 1]
            rows[i][j] = min(rows[i - 1][j] + 1, rows[i][j - 1] + 1, rows[i - 1][j - 1] + cost)
            if i > 1 and j > 1 and word[i - 1] == other[j - 2] and word[i - 2] == other[j - 1]:
                rows[i][j] = min(rows[i][j], rows[i - 2][j - 2] + 1)
    return rows[-1][-1]


@given(st.text("ABCD", max_size=6), st.text("ABCD", max_size=6))
def testone_slip_apart_is_an_alignment_distance_of_one(word: str, other: str) -> None:
    assert one_slip_apart(word, other) == (_slips(word, other) == 1)


def test_a_keyword_of_another_controller_is_not_offered() -> None:
    # CIRCLEA is ticked for the NextMove controllers only (v4 guide §10.3 CIRCLEA), not MintDrive
    source = "CIRCLEAA[0,1] = 1, 1, 90\n"
    (on_nextmove,) = coded(source, "E3007")
    (on_mintdrive,) = coded(source, "E3007", controller="mintdrive")
    assert "did you mean 'CIRCLEA'?" in on_nextmove.message
    assert "CIRCLEA'" not in on_mintdrive.message and on_mintdrive.fixes == ()


def test_hints_are_off_unless_selected() -> None:
    source = "DIM b\nb = POS[1]\nPRINT b\n"
    assert coded(source, "I201") == []
    assert len(coded(source, "I201", select=("I",))) == 1
    assert len(coded(source, "I201", select=("I201",))) == 1
    assert coded(source, "I201", select=("E", "W")) == []


_NAMES = st.sampled_from(["alpha", "beta", "gamma"])
_LINES = st.lists(st.lists(_NAMES, min_size=1, max_size=4), min_size=1, max_size=6)


@given(_LINES)
def test_each_undeclared_name_is_reported_once_on_each_line_that_uses_it(lines: list[list[str]]) -> None:
    source = "".join("PRINT " + ", ".join(names) + "\n" for names in lines)
    index = mintlang.LineIndex(source)
    found = [(index.position(d.span.start).line, source[d.span.start : d.span.end]) for d in coded(source, "E3001")]
    expected = [(number, name) for number, names in enumerate(lines, start=1) for name in dict.fromkeys(names)]
    assert sorted(found) == sorted(expected)
