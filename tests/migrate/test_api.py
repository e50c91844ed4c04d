"""The library API the language server uses: whole-file migration and single-rule quick fixes."""

from __future__ import annotations

from mintlang.migrate import RuleClass, migrate, rules, rules_at


def test_result_carries_text_changes_manual_items_and_counts() -> None:
    source = "HMSPEED = 2\nLOAD 3\n"
    result = migrate(source, controller="mintdrive")
    reason = "LOAD: no Mint v4 keyword (Mint WorkBench transfers programs and arrays): remove or redesign"
    assert result.text == f"HOMESPEED = 2\nREM MIGRATE: X-HOST: {reason}\nLOAD 3\n"
    assert [(c.rule, c.line, c.original, c.replacement) for c in result.changes] == [
        ("M-REN", 1, "HMSPEED", "HOMESPEED")
    ]
    assert [(m.rule, m.line) for m in result.manual] == [("X-HOST", 3)]
    assert result.rule_counts == {"M-REN": 1, "X-HOST": 1}


def test_manual_items_are_numbered_as_editors_number_lines() -> None:
    # a form feed (page break) is not a line end: the item flags line 3 as the editor shows it
    result = migrate("REM page one\x0cpage two\nHMSPEED = 2\nLOAD 3\n", controller="mintdrive")
    assert [(m.rule, m.line) for m in result.manual] == [("X-HOST", 4)]
    assert result.text.split("\n")[3] == "LOAD 3"


def test_change_spans_point_into_the_original() -> None:
    source = "a = 1 : HS = 10\n"
    result = migrate(source, controller="mintdrive", only=["M-ABBR", "M-REN"])
    for change in result.changes:
        assert source[change.span.start : change.span.end] == change.original == "HS"


def test_edits_reproduce_the_migrated_text() -> None:
    source = "REM x\nGAIN = 2\nSIN(30)\nb = 1\n"
    result = migrate(source)
    text = source
    for edit in sorted(result.edits(), key=lambda e: e.span.start, reverse=True):
        text = text[: edit.span.start] + edit.text + text[edit.span.end :]
    assert text == result.text


def test_quick_fixes_at_an_offset() -> None:
    source = "x = 1 : HMSPEED = 10\n"
    fixes = {info.id: edits for info, edits in rules_at(source, source.index("HMSPEED") + 2)}
    assert list(fixes) == ["M-REN"]
    (edit,) = fixes["M-REN"]
    assert source[edit.span.start : edit.span.end] == "HMSPEED" and edit.text == "HOMESPEED"
    assert rules_at(source, source.index("1")) == ()  # nothing to fix in "x = 1"


def test_rules_are_documented() -> None:
    infos = rules()
    assert len({info.id for info in infos}) == len(infos)
    for info in infos:
        assert info.summary and info.evidence
        assert info.rule_class in RuleClass
