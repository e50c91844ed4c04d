"""Two invariants of ``--to mintmt`` on generated v4 texts (lines of v4 forms in any case, indentation,
trailing comments and line breaks, mixed, after a byte-order mark or not): it is lossless — the migrated
text, less the marker lines it wrote, is the source with each reported change made and nothing else — and
it is idempotent."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from mintlang.migrate.mintmt import to_mintmt

FORMS = (
    "REM note",
    "GO.0",
    "GO[0,1]",
    "MOVER.1 = 10",
    "SPEED[0,1] = 5;",
    "x = POS.0 + POS[1]",
    "LOOP",
    "ENDL",
    "IF a DO",
    "ENDIF",
    "IF a THEN b = 1",
    "WHILE a",
    "ENDW",
    "REPEAT",
    "UNTIL a",
    'PRINT "REM .0 [1]"',
    "DIM a = 'A'",
    "#COMMS1",
    "#sub",
    "RETURN",
    "END",
    "DEFINE ax = 0",
    "SPEED.ax = 1",
    "SPEED.(a+1) = 2",
    "AXES[0,1]",
    "DIM event",
    "",
)

_line = st.tuples(
    st.sampled_from(["", "  ", "\t"]),
    st.sampled_from(FORMS),
    st.sampled_from([str, str.upper, str.lower]),
    st.sampled_from(["", "   ", " REM why", " : rem  why"]),
    st.sampled_from(["\n", "\r\n", "\r"]),
).map(lambda parts: parts[0] + parts[2](parts[1]) + parts[3] + parts[4])
BOM = "\ufeff"
programs = st.tuples(st.sampled_from(["", BOM]), st.lists(_line, max_size=12).map("".join)).map("".join)


def _without_markers(text: str) -> str:
    mark = BOM if text.startswith(BOM) else ""
    lines = text.removeprefix(mark).splitlines(keepends=True)
    return mark + "".join(line for line in lines if not line.lstrip().startswith("REM MIGRATE:"))


@settings(max_examples=300, deadline=None)
@given(programs)
def test_only_the_reported_changes_and_the_markers_differ(source: str) -> None:
    result = to_mintmt(source)
    expected, position = [], 0
    for change in result.changes:
        assert source[change.span.start : change.span.end] == change.original
        expected += [source[position : change.span.start], change.replacement]
        position = change.span.end
    expected.append(source[position:])
    assert _without_markers(result.text) == "".join(expected)


@settings(max_examples=300, deadline=None)
@given(programs)
def test_migrating_twice_is_migrating_once(source: str) -> None:
    once = to_mintmt(source)
    twice = to_mintmt(once.text)
    assert twice.text == once.text
    assert twice.changes == ()
