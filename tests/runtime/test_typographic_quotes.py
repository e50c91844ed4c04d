"""Typographic quotes: mint check and mint-run read them alike and both say so.

The controller's strings are delimited by double quotes (000:15299), but the guide's own
examples are typeset with curly ones (000:4730: PRINT “ERL :”, ERL), so a
program copied from it has them. mint check warns (W101) and its safe fix writes plain quotes;
mint-run runs the program as that fix writes it and warns on stderr and in the JSON report for
each line, rather than run it in silence.
"""

from __future__ import annotations

import json
from pathlib import Path

import mintlang
from tests.runtime.running import simulate
from tests.runtime.test_run_command import mint_run, write

CURLY = 'DIM e = 3\nPRINT \u201cERL :\u201d, e\nPRINT \u201cok\u201d : PRINT \u2018A\u2019\nPRINT "plain"\n'


def test_the_checker_warns_on_each_curly_string_and_finds_no_error() -> None:
    codes = [d.code for d in mintlang.check(CURLY)]
    assert codes == ["W101", "W101", "W101"]


def test_the_run_prints_what_the_fixed_program_prints_and_notes_each_line() -> None:
    # a comma prints the next item directly after the last (000:15300-15301); 'A' is 65 (000:801-811)
    result = simulate(CURLY)
    assert result.terminal == "ERL :3\nok\n65\nplain\n"
    assert [note.split(":")[0] for note in result.read_leniently] == ["program line 2", "program line 3"]


def test_a_program_with_plain_quotes_has_nothing_read_leniently() -> None:
    assert simulate('PRINT "plain"\n').read_leniently == ()


def test_mint_run_warns_on_stderr_and_in_its_report(tmp_path: Path) -> None:
    result = mint_run(write(tmp_path, "curly.mnt", "PRINT \u201cHello\u201d\n"), "--report", "json")
    assert "warning: program line 1: typographic quotes read as plain ones" in result.stderr
    report = json.loads(result.stdout[result.stdout.index("{") :])
    assert len(report["read_leniently"]) == 1 and result.stdout.startswith("Hello\n")
