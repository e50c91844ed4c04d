"""``#REM Main loop``, as the guide prints one line of its non-volatile example (000:1027), is a label named REM
followed by a statement: a label is ``#`` and a name (000:1842-1844) and a statement may follow it on its line,
so ``Main loop`` is read as a command, error 3007. The message says that a comment is REM without the '#'
(000:15497-15515)."""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.checking import covered


@pytest.mark.parametrize("line", ["#REM Main loop", "#rem set up the axes"])
def test_the_word_after_a_rem_label_is_told_the_comment(line: str) -> None:
    source = f"GOSUB main\nEND\n#main\n{line}\nRETURN\n"
    (diagnostic,) = [d for d in mintlang.check(source) if d.code == "E3007"]
    label, word = line.split()[:2]
    assert covered(source, diagnostic) == word
    assert diagnostic.message == (
        f"Keyword not defined: '{word}' is not a keyword ({label} is a label named REM, and a statement"
        " follows it: a comment is written REM, without '#')"
    )


def test_another_label_keeps_the_plain_message() -> None:
    (diagnostic,) = [d for d in mintlang.check("#start Main loop\nRETURN\n") if d.code == "E3007"]
    plain = "Keyword not defined: 'Main' is not a keyword (check the spelling and the abbreviation)"
    assert diagnostic.message == plain
