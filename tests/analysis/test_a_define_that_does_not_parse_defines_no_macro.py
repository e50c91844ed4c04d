"""A DEFINE whose name the controller cannot read defines no macro, so it is no unused macro either.

``DEFINE 100 = "100"`` is not valid, the macro name must be alphanumeric (000:19103-19105); ``05`` is no
number at all, a leading zero making it binary (000:755-760), and ``_`` alone names nothing, an
underscore beginning a name only before a letter or digit (000:882-884). The one finding is the
statement's own error; "macro defined but never used" (W105) would warn about a macro that is not there.
"""

from __future__ import annotations

import pytest

import mintlang


@pytest.mark.parametrize(("source", "code"), [("DEFINE 05 = 1\n", "E2003"), ("DEFINE _ = 1\n", "E2003")])
def test_the_statement_s_error_is_the_one_finding(source: str, code: str) -> None:
    assert [d.code for d in mintlang.check(source + "END\n")] == [code]


def test_a_define_that_parses_and_is_never_used_is_still_w105() -> None:
    assert [d.code for d in mintlang.check("DEFINE speed1 = 1\nEND\n")] == ["W105"]
