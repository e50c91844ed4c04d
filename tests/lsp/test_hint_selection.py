"""``mint.select`` in the editor, as ``--select`` on the command line: hints (I…) appear only when selected."""

from __future__ import annotations

from mintlang.lsp.workspace import Analyses, Settings

HINTED = "DIM b\nb = POS[1]\nPRINT b\n"


def codes(settings: Settings) -> list[str]:
    analyses = Analyses(read=lambda _: None, settings=settings)
    return [d.code for d in analyses.snapshot("file:///work/hinted.mnt", HINTED, 1).diagnostics]


def test_select_reads_a_list_or_a_comma_separated_text() -> None:
    assert Settings.from_options({"mint": {"select": ["e", "I201"]}}).select == ("E", "I201")
    assert Settings.from_options({"mint": {"select": "E, W,I"}}).select == ("E", "W", "I")


def test_a_select_that_is_no_list_of_codes_keeps_the_one_before() -> None:
    before = Settings(select=("I",))
    assert Settings.from_options({"mint": {"select": 3}}, before).select == ("I",)


def test_the_editor_shows_hints_only_when_selected() -> None:
    assert codes(Settings()) == []
    assert codes(Settings.from_options({"mint": {"select": "E,W,I"}})) == ["I201"]
