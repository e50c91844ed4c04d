"""A label must be the first thing on its line (000:1872-1876, the guide's invalid ``a = 10 : #label1``):
written after code it is a syntax error that names the label and marks it whole, ``#`` and name."""

from __future__ import annotations

import pytest

import mintlang


@pytest.mark.parametrize("dialect", ["v4", "v3"])
def test_a_label_after_code_is_a_syntax_error_naming_it(dialect: str) -> None:
    source = "DIM a\na = 10 : #label1\n"
    [error] = [d for d in mintlang.check(source, dialect=dialect) if d.code == "E2003"]
    assert source[error.span.start : error.span.end] == "#label1"
    assert error.message == "Syntax error: #label1 follows code: a label must begin its line"
