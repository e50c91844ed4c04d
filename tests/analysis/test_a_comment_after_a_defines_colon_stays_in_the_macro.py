"""A ``:`` before the REM of a DEFINE line is part of the macro's text, and the error it causes where the macro is
used says so.

A macro's text may hold several statements joined by ``:`` (000:1560); REM leaves out only what follows it
(000:15510-15511), so ``DEFINE fast = 5000 : REM mm/s`` gives ``fast`` the text ``5000 :``. Used as one value of
a list, ``SPEED[0,1] = fast, slow`` reads ``SPEED[0,1] = 5000 : , 100 :``: a syntax error (2003) at the ``,``;
in a condition, ``IF POS.0 > fast THEN`` loses its THEN (2007). Without the ``:`` (``DEFINE fast = 5000 REM
mm/s``) the macro is ``5000`` and both lines are right.
"""

from __future__ import annotations

import mintlang

_HINT = "a ':' from a macro's text ends the statement before it"
_DEFINES = "DEFINE fast = 5000 {}REM mm/s\nDEFINE slow = 100 {}REM mm/s\n"


def test_a_list_cut_by_the_macros_colon_is_told_why() -> None:
    (error,) = mintlang.check(_DEFINES.format(": ", ": ") + "SPEED[0,1] = fast, slow\n")
    assert error.code == "E2003" and _HINT in error.message


def test_a_condition_cut_by_it_is_told_too() -> None:
    found = mintlang.check("DEFINE fast = 5000 : REM mm/s\nIF POS.0 > fast THEN PRINT 1\n")
    assert found[0].code == "E2007" and _HINT in found[0].message


def test_a_rem_without_the_colon_leaves_the_macro_a_value() -> None:
    source = _DEFINES.format("", "") + "SPEED[0,1] = fast, slow\nIF POS.0 > fast THEN PRINT 1\n"
    assert mintlang.check(source) == []


def test_an_error_of_its_own_is_not_blamed_on_a_macro() -> None:
    (error,) = mintlang.check("SPEED = 5 : , 6\n")
    assert error.code == "E2003" and _HINT not in error.message
