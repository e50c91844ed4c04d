"""``--list-rules`` and the reports cite the guides by section, which a reader of the printed
guide can look up, never by a line of the project's text extraction.

The expected sections were read in the guides: v4:3027 is the heading "6.7 AXISMODE and
IDLE", the next heading "6.8 Controlled Motion" is at v4:3051; chapter 10.3 "Mint Keywords"
lists the v4 keywords, ACCEL's entry at v4:6143; the v3 guide's keyword chapter is "10. MINT
Keywords" (v3:5368), ACCEL's entry at v3:5635, ACCELTIME's at v3:5690.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.manual import sections
from mintlang.manual.headings import tables
from mintlang.manual.places import section
from mintlang.migrate.citations import cite
from mintlang.migrate.cli import migrate as command
from tests.migrate.golden import GOLDEN

LINE_CITATION = re.compile(r"\bv[34]:\d")
SEEDS = Path("/work/shared/seeds")
MANUALS = {"v4": SEEDS / "000_f3c82d19754128dd.txt", "v3": SEEDS / "001_fad843a00628250f.txt"}


@pytest.mark.parametrize(
    ("dialect", "line", "place"),
    [
        ("v4", 3027, "§6.7"),  # the heading itself
        ("v4", 3046, "§6.7"),
        ("v4", 3050, "§6.7"),
        ("v4", 3051, "§6.8"),
        ("v4", 6178, "§10.3 ACCEL"),  # inside the keyword chapter: the entry too
        ("v3", 5662, "§10 ACCEL"),
        ("v3", 5728, "§10 ACCELTIME"),
        ("v4", 10, ""),  # the safety notices before chapter 1
    ],
)
def test_a_line_is_cited_by_its_section(dialect: str, line: int, place: str) -> None:
    assert section(dialect, line) == place


def test_a_run_of_citations_names_each_guide_and_place_once() -> None:
    assert cite("spec S-ACCEL; v3:5662, v3:5728, 7203; v4:6178, v4:6180-6190") == (
        "spec S-ACCEL; v3 guide §10 ACCEL, §10 ACCELTIME, §10 DECEL; v4 guide §10.3 ACCEL"
    )
    assert cite("other units (v4:3046)") == "other units (v4 guide §6.7)"
    assert cite("see v4:10") == "see v4 guide"


def test_list_rules_cites_no_line_of_a_text_extraction() -> None:
    output = CliRunner().invoke(command, ["--list-rules"]).output
    assert "v4 guide §" in output and not LINE_CITATION.search(output)


def test_the_golden_outputs_and_reports_cite_no_line_of_a_text_extraction() -> None:
    for path in sorted(GOLDEN.glob("*/expected*")):
        assert not LINE_CITATION.search(path.read_text()), path


@pytest.mark.skipif(not all(path.exists() for path in MANUALS.values()), reason="the manuals are not here")
def test_the_committed_table_is_what_the_manuals_headings_give() -> None:
    found_sections, found_entries = tables(MANUALS)
    assert {dialect: tuple(rows) for dialect, rows in found_sections.items()} == sections.SECTIONS
    assert {dialect: tuple(rows) for dialect, rows in found_entries.items()} == sections.ENTRIES
