"""``ABS SIN 200`` is scaled by 1000 once: the rewrite keeps brackets the next pass still recognises.

v3 SIN, COS and TAN return thousandths and a function written without brackets takes the operand after
it (``SIN 90 + a`` is ``(SIN(90)) + a``, 001:2063-2081), so ``ABS SIN 200`` is ABS(-342) = 342 in v3; v4
returns the fraction (000:8676-8679). M-TRIG wrote ``ABS (SIN(200) * 1000)``, which the parser reads as
ABS called with ``SIN(200) * 1000`` in its own brackets: the next pass no longer saw its own output and
multiplied again, ``ABS ((SIN(200) * 1000) * 1000)``, 342000. M-TILDE's ``(~x & 255)`` had the same
trouble (harmless there: the mask is idempotent, but the text grew a second ``& 255``).
"""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        pytest.param("w = ABS SIN 200\n", "w = ABS ((SIN(200) * 1000))\n", id="abs-sin"),
        pytest.param("w = INT COS a + 1\n", "w = INT ((COS(a) * 1000)) + 1\n", id="int-cos-then-plus"),
        pytest.param("w = ABS ~w\n", "w = ABS ((~w & 255))\n", id="abs-tilde"),
        pytest.param("w = ABS(SIN 200)\n", "w = ABS((SIN(200) * 1000))\n", id="bracketed-abs-unchanged"),
    ],
)
def test_the_value_is_scaled_once(source: str, expected: str) -> None:
    result = migrate(source, only=["M-TRIG", "M-TILDE"])
    assert result.text == expected
    assert migrate(result.text, only=["M-TRIG", "M-TILDE"]).text == expected
