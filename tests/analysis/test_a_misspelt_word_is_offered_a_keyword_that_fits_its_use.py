"""A misspelt word is offered the keyword its use fits, not merely the one spelt most like it.

``GOO`` is one letter from GO and from GOTO. GO is written with axes or alone on the default axes
(``GO[axes]``, a dot parameter of an axis: 000:11037-11040; ``MA = 10 : GO``: 000:11121), while GOTO
names a label and takes no axes (``GOTO label_name``: 000:11187-11188), as GOSUB does (000:11146).
So ``GOO.0`` and ``GOO`` alone mean GO, and ``GOO start`` means GOTO.
"""

from __future__ import annotations

import mintlang


def _error_3007(source: str) -> mintlang.Diagnostic:
    (error,) = [d for d in mintlang.check(source) if d.code == "E3007"]
    return error


def test_a_word_with_an_axis_is_offered_a_keyword_that_takes_one() -> None:
    error = _error_3007("MOVER.0 = 10\nGOO.0\n")
    assert error.message.endswith("'GOO' is not a keyword (did you mean 'GO'?)")


def test_a_word_alone_is_not_offered_a_jump_which_names_its_label() -> None:
    error = _error_3007("MOVER.0 = 10\nGOO\n")
    assert error.message.endswith("'GOO' is not a keyword (did you mean 'GO'?)")


def test_a_word_before_a_label_is_still_offered_the_jump() -> None:
    error = _error_3007("GOO start\nEND\n#start\nEND\n")
    assert error.message.endswith("'GOO' is not a keyword (did you mean 'GOTO'?)")
