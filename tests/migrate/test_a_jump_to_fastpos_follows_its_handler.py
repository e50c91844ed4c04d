"""A GOSUB or GOTO to the ``#FASTPOS`` handler follows it to its v4 name, ``#FASTIN``.

v3 reserves ``#FASTPOS`` for the position latch (001:2469-2476) and, like any label, a GOSUB names it
without the ``#`` (001:2461). M-FASTPOS writes the handler as ``#FASTIN`` (000:5910-5912): a ``GOSUB fastpos``
left as it was named a label the migrated file no longer has (error 3004), and the report said the label
was not in the file, which it was. A jump to a FASTPOS the file does not define stays flagged as v3 flagged it.
"""

from __future__ import annotations

from mintlang.migrate import migrate


def test_the_jump_is_renamed_with_the_handler() -> None:
    source = "GOSUB fastpos\nEND\n#FASTPOS\n? 4 : RETURN\n"
    assert migrate(source, only=["M-FASTPOS"]).text == "GOSUB fastin\nEND\n#FASTIN\n? 4 : RETURN\n"
    assert not [item for item in migrate(source).manual if item.rule == "X-COMMENTED"]


def test_a_jump_to_a_fastpos_the_file_does_not_define_is_left_flagged() -> None:
    result = migrate("GOTO fastpos\n")
    assert result.text.endswith("GOTO fastpos\n")
    assert [item.reason for item in result.manual if item.rule == "X-COMMENTED"] == [
        "label #fastpos is not in this file"
    ]
