"""A v3 IF line with a syntax error still opens its block, and every rule runs past it.

``IF a 3 DO`` lacks its comparison: an error in v3 already (001:2120-2131, THEN or DO after a condition),
which the migration reports and leaves as it is (X-COMMENTED). S-DEFAULTS asks which writes a constant IF
condition keeps from running (001:2009); this IF has no condition to read, so the SPEED write inside it may
run, and the rule failed on it instead ('rule S-DEFAULTS failed: AssertionError'), leaving the file unmigrated.
"""

from __future__ import annotations

from mintlang.migrate import migrate


def test_an_if_line_in_error_is_reported_and_the_file_migrated() -> None:
    result = migrate("IF a 3 DO\n  SPEED = 4\n  MOVER = 1 : GO\nENDIF\n")
    assert [(item.rule, item.original_line) for item in result.manual if item.rule == "X-COMMENTED"] == [
        ("X-COMMENTED", 1)
    ]
    assert not any("SPEED" in item.reason for item in result.manual if item.rule == "S-DEFAULTS")
