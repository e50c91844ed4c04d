"""``mint-run``'s outputs on long runs: the trace streams in bounded memory, and the report can go to a file."""

from __future__ import annotations

import csv
import importlib.util
import json
import tracemalloc
from pathlib import Path

import pytest

from mintlang.runtime.trace import Envelope
from tests.runtime.invoking import mint_run, write

BUSY = "DIM i\nLOOP\n  i = i + 1\nENDL\n"
NO_MATPLOTLIB = pytest.mark.skipif(importlib.util.find_spec("matplotlib") is None, reason="no plot extra")


def peak_bytes(*arguments: str | Path) -> int:
    tracemalloc.start()
    try:
        assert mint_run(*arguments).exit_code == 0
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


@pytest.mark.parametrize("plot", [False, pytest.param(True, marks=NO_MATPLOTLIB)])
def test_the_memory_of_a_traced_run_does_not_grow_with_its_length(tmp_path: Path, plot: bool) -> None:
    program = write(tmp_path, "busy.mnt", BUSY)
    outputs = ["--trace", tmp_path / "t.csv", "--trace-axes", "0,1", *(["--plot", tmp_path / "p.png"] if plot else [])]
    assert mint_run(program, "--until-ms", "10", *outputs).exit_code == 0  # imports and caches, paid for once
    short = peak_bytes(program, "--until-ms", "1000", *outputs)
    long = peak_bytes(program, "--until-ms", "10000", *outputs)
    assert long < short + 1_000_000  # keeping the 9000 rows more would take over 5 MB
    assert len((tmp_path / "t.csv").read_text().splitlines()) == 1 + 10001


@pytest.mark.parametrize(
    ("program", "options", "stopped"),
    [
        ("WAIT = 30\n", [], "end"),
        ("WAIT = 30\nDIM x = 0\nPRINT 1 / x\n", [], "error"),
        ("RESET.0\nMOVER.0 = 1\nMOVER.0 = 1\nMOVER.0 = 1\n", [], "deadlock"),
        (BUSY, ["--until-ms", "300"], "until"),
        (BUSY, ["--max-wall-s", "0.3"], "wall-limit"),
    ],
)
def test_the_trace_holds_every_tick_however_the_run_stops(
    tmp_path: Path, program: str, options: list[str], stopped: str
) -> None:
    trace, report = tmp_path / "t.csv", tmp_path / "report.json"
    mint_run(write(tmp_path, "p.mnt", program), "--trace", trace, "--report-file", report, *options)
    assert json.loads(report.read_text())["stopped"] == stopped
    rows = list(csv.reader(trace.open(newline="")))
    assert {len(row) for row in rows} == {len(rows[0])}
    assert [int(row[0]) for row in rows[1:]] == list(range(json.loads(report.read_text())["time_ms"] + 1))


def test_the_report_file_holds_the_json_report_and_leaves_stdout_to_the_program(tmp_path: Path) -> None:
    program = write(tmp_path, "p.mnt", 'PRINT "no newline";\nWAIT = 5\n')
    report = tmp_path / "report.json"
    alone = mint_run(program, "--report-file", report)
    assert (alone.exit_code, alone.stdout) == (0, mint_run(program).stdout)
    both = mint_run(program, "--report", "json", "--report-file", report)
    assert both.exit_code == 0
    assert both.stdout == f"{alone.stdout}\n{report.read_text()}"
    assert json.loads(report.read_text())["stopped"] == "end"


def test_the_report_file_is_written_when_the_run_fails(tmp_path: Path) -> None:
    report = tmp_path / "report.json"
    result = mint_run(write(tmp_path, "p.mnt", "DIM x = 0\nPRINT 1 / x\n"), "--report-file", report)
    assert result.exit_code == 1
    assert (json.loads(report.read_text())["stopped"], json.loads(report.read_text())["err"]) == ("error", 2021)


def test_the_report_file_never_replaces_an_input_or_another_output(tmp_path: Path) -> None:
    program = write(tmp_path, "p.mnt", "WAIT = 5\n")
    scenario = write(tmp_path, "s.toml", '[[expect]]\nstopped = "end"\n')
    trace = tmp_path / "t.csv"
    for arguments, role in [
        ((program, "--report-file", program), "the program"),
        ((program, "--expect", scenario, "--report-file", scenario), "a scenario file"),
        ((program, "--trace", trace, "--report-file", trace), "the --trace file"),
    ]:
        result = mint_run(*arguments)
        assert result.exit_code == 2
        assert result.stderr == f"mint-run: cannot write {arguments[-1]}: it is also {role}\n"
        assert result.stdout == ""  # refused before running
    assert program.read_text() == "WAIT = 5\n"
    assert not trace.exists()


def test_a_report_file_that_is_a_directory_is_refused_before_the_run(tmp_path: Path) -> None:
    result = mint_run(write(tmp_path, "p.mnt", 'PRINT "ran"\n'), "--report-file", tmp_path)
    assert result.exit_code == 2
    assert result.stderr == f"mint-run: cannot write {tmp_path}: it is a directory\n"
    assert result.stdout == ""


def test_an_envelope_keeps_a_bounded_number_of_spans_and_every_peak() -> None:
    envelope = Envelope(limit=64)
    for tick in range(100_000):
        envelope.add(float(tick), 50.0 if tick == 77_777 else float(tick % 10))
    assert 32 <= len(envelope.spans) <= 64
    times, values = envelope.points()
    assert times == sorted(times) and (77_777.0, 50.0) in zip(times, values, strict=True)
    assert (min(values), max(values)) == (0.0, 50.0)


def test_an_envelope_draws_a_short_series_point_by_point() -> None:
    envelope = Envelope(limit=64)
    samples = [(float(tick), float(tick * tick % 7)) for tick in range(64)]
    for time, value in samples:
        envelope.add(time, value)
    assert envelope.points() == ([time for time, _ in samples], [value for _, value in samples])
