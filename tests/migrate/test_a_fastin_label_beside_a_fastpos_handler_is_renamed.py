"""A v3 subroutine ``#fastin`` in a program with a ``#FASTPOS`` handler is renamed with its jumps.

v3 reserves ``#FASTPOS`` for the position latch (001:2469-2476, 001:2585-2627); ``#fastin`` is a label like any
other there. M-FASTPOS writes ``#FASTPOS`` as ``#FASTIN`` (000:5910-5912), and v4 calls a ``#FASTIN`` on every
fast latch (000:1884-1900): kept as written, the subroutine would be a second #FASTIN (error 3006, and ``GOSUB
fastin`` would run the latch handler). A lone ``#FASTIN`` is still taken as what M-FASTPOS wrote.
"""

from __future__ import annotations

from mintlang.migrate import migrate

SOURCE = "GOSUB fastin\nEND\n#FASTPOS\n? 4 : RETURN\n#fastin\n? 5 : RETURN\n"


def test_the_subroutine_and_its_jump_are_renamed() -> None:
    assert migrate(SOURCE, only=["M-LABEL"]).text == SOURCE.replace("fastin", "fastin_u")


def test_the_migration_has_one_fast_latch_handler_and_keeps_the_subroutine() -> None:
    result = migrate(SOURCE)
    labels = [line for line in result.text.splitlines() if line.startswith("#")]
    assert labels == ["#FASTIN", "#fastin_u"]
    assert "GOSUB fastin_u" in result.text
    assert not [item for item in result.manual if item.rule == "X-COMMENTED"]
