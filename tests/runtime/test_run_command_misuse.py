"""``mint-run`` given awkward programs, files and options: a clear message and exit status, never a traceback."""

from __future__ import annotations

import importlib.util
import json
import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

from tests.runtime.invoking import mint_run, write


def test_program_text_that_looks_like_markup_is_shown_as_written(tmp_path: Path) -> None:
    result = mint_run(write(tmp_path, "markup.mnt", 'DIM x\nx = 0\nPRINT "[/red][bold]", 1/x\n'))
    assert result.exit_code == 1
    assert result.exception is None or isinstance(result.exception, SystemExit)
    assert 'PRINT "[/red][bold]", 1/x' in result.stderr
    assert "R2021" in result.stderr and "[line 3]" in result.stderr


def test_a_compile_error_quoting_markup_keeps_its_line(tmp_path: Path) -> None:
    result = mint_run(write(tmp_path, "markup.mnt", 'DIM x\nPRINT x "[/b]"\n'))
    assert result.exit_code == 1
    assert '"[/b]"' in result.stderr and "[line 2]" in result.stderr


def test_expect_fails_when_the_run_stops_before_a_timed_expectation(tmp_path: Path) -> None:
    program = write(tmp_path, "short.mnt", "WAIT = 30\n")
    late = write(tmp_path, "late.toml", '[[expect]]\nterminal_contains = "never"\nat_ms = 1000\n')
    result = mint_run(program, "--expect", late)
    assert result.exit_code == 1
    assert "not checked" in result.stderr


def test_expect_with_no_expectations_is_not_a_pass(tmp_path: Path) -> None:
    program = write(tmp_path, "fine.mnt", "PRINT 1\n")
    stimulus_only = write(tmp_path, "stimulus.toml", "[[input]]\nchannel = 1\nlevel = 1\nat_ms = 5\n")
    result = mint_run(program, "--expect", stimulus_only)
    assert result.exit_code == 1
    assert "no expectations to check" in result.stderr


def test_expect_fails_a_run_that_stops_on_an_error_even_when_its_expectations_held(tmp_path: Path) -> None:
    program = write(tmp_path, "crash.mnt", "DIM x = 0\nPRINT 1 / x\n")
    held = write(tmp_path, "held.toml", '[[expect]]\nwhat = "x"\nequals = 0\n')
    result = mint_run(program, "--expect", held)
    assert result.exit_code == 1
    assert "The expectation held" in result.stderr and "R2021" in result.stderr


def test_expect_passes_an_error_that_a_stopped_expectation_asks_for(tmp_path: Path) -> None:
    program = write(tmp_path, "crash.mnt", "DIM x = 0\nPRINT 1 / x\n")
    crash = write(tmp_path, "crash.toml", '[[expect]]\nstopped = "error"\n')
    assert mint_run(program, "--expect", crash).exit_code == 0


def test_a_wall_clock_limit_that_is_not_a_number_is_refused(tmp_path: Path) -> None:
    result = mint_run(write(tmp_path, "forever.mnt", "LOOP\nENDL\n"), "--max-wall-s", "nan")
    assert result.exit_code == 2
    assert "--max-wall-s" in result.stderr


def test_an_infinite_wall_clock_limit_means_none(tmp_path: Path) -> None:
    assert mint_run(write(tmp_path, "short.mnt", "WAIT = 5\n"), "--max-wall-s", "inf").exit_code == 0


@pytest.mark.parametrize(
    ("axes", "complaint"),
    [
        ("12", "axis 12: the NextMove PCI has axes 0 to 11"),
        ("-1", "axis -1"),
        ("0,0", "names an axis twice"),
        (",", "name at least one axis"),
    ],
)
def test_trace_axes_must_be_axes_of_the_controller_each_once(tmp_path: Path, axes: str, complaint: str) -> None:
    result = mint_run(write(tmp_path, "p.mnt", "WAIT = 5\n"), "--trace", tmp_path / "t.csv", "--trace-axes", axes)
    assert result.exit_code == 2
    assert complaint in result.stderr
    assert not (tmp_path / "t.csv").exists()


def test_trace_axes_without_a_trace_or_plot_is_a_usage_error(tmp_path: Path) -> None:
    result = mint_run(write(tmp_path, "p.mnt", "WAIT = 5\n"), "--trace-axes", "0")
    assert result.exit_code == 2
    assert "--trace or --plot" in result.stderr


def test_stimulus_for_a_missing_axis_is_a_usage_error_at_the_line_that_names_it(tmp_path: Path) -> None:
    stimulus = write(tmp_path, "switch.toml", '[[input]]\nchannel = 1\nwhen = "enc 99 >= 5"\n')
    result = mint_run(write(tmp_path, "p.mnt", "WAIT = 10\n"), "--stimulus", stimulus)
    assert result.exit_code == 2
    assert "switch.toml:3: the NextMove PCI has no axis 99" in result.stderr


def test_a_host_port_in_use_is_a_usage_error_that_names_it(tmp_path: Path) -> None:
    with socket.create_server(("127.0.0.1", 0)) as taken:
        port = taken.getsockname()[1]
        result = mint_run(write(tmp_path, "p.mnt", "WAIT = 5\n"), "--host-port", str(port))
    assert result.exit_code == 2
    assert result.stderr == f"mint-run: cannot listen on 127.0.0.1:{port}: Address already in use\n"


@pytest.mark.parametrize("option", ["--trace", "--plot"])
def test_an_output_never_replaces_the_program(tmp_path: Path, option: str) -> None:
    program = write(tmp_path, "p.mnt", "WAIT = 5\n")
    result = mint_run(program, option, program)
    assert result.exit_code == 2
    assert result.stderr == f"mint-run: cannot write {program}: it is also the program\n"
    assert program.read_text() == "WAIT = 5\n"


def test_a_trace_never_replaces_the_configuration_or_a_scenario(tmp_path: Path) -> None:
    program = write(tmp_path, "p.mnt", "WAIT = 5\n")
    config = write(tmp_path, "c.mnt", "RESETALL\n")
    scenario = write(tmp_path, "s.toml", '[[expect]]\nstopped = "end"\n')
    assert "it is also the configuration" in mint_run(program, "--config", config, "--trace", config).stderr
    assert "it is also a scenario file" in mint_run(program, "--expect", scenario, "--trace", scenario).stderr


def test_a_trace_replaces_an_earlier_trace_but_no_other_file(tmp_path: Path) -> None:
    program = write(tmp_path, "p.mnt", "WAIT = 5\n")
    trace = tmp_path / "t.csv"
    assert mint_run(program, "--trace", trace).exit_code == 0
    assert mint_run(program, "--trace", trace).exit_code == 0
    notes = write(tmp_path, "notes.txt", "keep me\n")
    result = mint_run(program, "--trace", notes)
    assert result.exit_code == 2
    assert "it exists and is not a trace" in result.stderr
    assert notes.read_text() == "keep me\n"


@pytest.mark.skipif(importlib.util.find_spec("matplotlib") is None, reason="the plot extra is not installed")
@pytest.mark.parametrize("name", ["out.xyz", "out"])
def test_a_plot_needs_an_image_extension_before_the_run(tmp_path: Path, name: str) -> None:
    result = mint_run(write(tmp_path, "p.mnt", 'PRINT "ran"\n'), "--plot", tmp_path / name)
    assert result.exit_code == 2
    assert "name an image by its extension (" in result.stderr and "png" in result.stderr
    assert result.stdout == ""  # refused before running


@pytest.mark.parametrize("option", ["--trace", "--plot"])
def test_an_output_in_a_missing_directory_is_refused_before_the_run(tmp_path: Path, option: str) -> None:
    target = tmp_path / "absent" / "out.png"
    result = mint_run(write(tmp_path, "p.mnt", 'PRINT "ran"\n'), option, target)
    assert result.exit_code == 2
    assert result.stderr == f"mint-run: cannot write {target}: {target.parent}: no such directory\n"
    assert result.stdout == ""


def test_an_output_that_is_a_directory_is_refused(tmp_path: Path) -> None:
    result = mint_run(write(tmp_path, "p.mnt", "WAIT = 5\n"), "--trace", tmp_path)
    assert result.exit_code == 2
    assert result.stderr == f"mint-run: cannot write {tmp_path}: it is a directory\n"


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="no /dev/full, the device that is always full")
@pytest.mark.parametrize(("wait", "stopped"), [(5, "end"), (5000, "interrupted")])
def test_a_trace_that_fails_to_write_keeps_the_report(tmp_path: Path, wait: int, stopped: str) -> None:
    # a short trace fails when it is closed, a long one when its first rows are written: that ends the run
    full = Path("/dev/full")
    result = mint_run(write(tmp_path, "p.mnt", f"WAIT = {wait}\n"), "--trace", full, "--report", "json")
    assert result.exit_code == 2
    assert json.loads(result.stdout)["stopped"] == stopped
    assert f"{stopped} after" in result.stderr
    assert result.stderr.endswith(f"mint-run: cannot write {full}: No space left on device\n")


def start(program: Path, *arguments: str | Path, unbuffered: bool = True) -> subprocess.Popen[str]:
    """``mint-run`` in its own process, with Ctrl-C at its default (a shell's background job ignores it).

    ``unbuffered`` makes Python flush each line into the pipe; without it the
    pipe is block-buffered, as when a user pipes ``mint-run`` into ``tee``.
    """
    environment = {key: value for key, value in os.environ.items() if key != "PYTHONUNBUFFERED"}
    if unbuffered:
        environment["PYTHONUNBUFFERED"] = "1"
    return subprocess.Popen(
        [sys.executable, "-m", "mintlang.runtime", str(program), *(str(argument) for argument in arguments)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env={**environment, "COLUMNS": "200"},
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),  # noqa: PLW1509 - no threads yet
    )


def test_ctrl_c_stops_the_run_and_still_reports_it_and_writes_the_trace(tmp_path: Path) -> None:
    program = write(tmp_path, "forever.mnt", 'PRINT "started"\nDIM i\nLOOP\n  i = i + 1\nENDL\n')
    trace = tmp_path / "t.csv"
    process = start(program, "--max-wall-s", "30", "--trace", trace, "--report", "json")
    try:
        assert process.stdout is not None
        assert process.stdout.readline() == "started\n"
        process.send_signal(signal.SIGINT)
        stdout, stderr = process.communicate(timeout=30)
    finally:
        process.kill()
    assert process.returncode == 130
    assert "Traceback" not in stderr
    assert "interrupted after" in stderr and "— Ctrl-C" in stderr
    assert json.loads(stdout)["stopped"] == "interrupted"
    assert trace.read_text().startswith("time_ms,")


def test_sigterm_stops_the_run_and_still_writes_the_report_and_a_complete_trace(tmp_path: Path) -> None:
    program = write(tmp_path, "forever.mnt", "DIM i\nLOOP\n  i = i + 1\nENDL\n")
    trace, report = tmp_path / "t.csv", tmp_path / "report.json"
    process = start(program, "--max-wall-s", "30", "--trace", trace, "--report-file", report)
    try:
        deadline = time.monotonic() + 30
        while (not trace.exists() or trace.stat().st_size < 100_000) and time.monotonic() < deadline:
            time.sleep(0.05)  # until the run is well into its loop
        process.send_signal(signal.SIGTERM)
        _, stderr = process.communicate(timeout=30)
    finally:
        process.kill()
    assert process.returncode == 143
    assert "Traceback" not in stderr
    assert "interrupted after" in stderr and "— terminated (SIGTERM)" in stderr
    assert json.loads(report.read_text())["stopped"] == "interrupted"
    rows = trace.read_text().split("\n")
    assert rows.pop() == ""  # the last row is whole, with its newline
    assert {row.count(",") for row in rows} == {rows[0].count(",")}
    assert [int(row.split(",", 1)[0]) for row in rows[1:]] == list(range(len(rows) - 1))


def test_a_reader_that_goes_away_ends_the_run_quietly(tmp_path: Path) -> None:
    program = write(tmp_path, "flood.mnt", f'LOOP\n  PRINT "{"x" * 80}"\nENDL\n')
    process = start(program, "--max-wall-s", "30")
    try:
        assert process.stdout is not None and process.stderr is not None
        process.stdout.readline()
        process.stdout.close()  # as `| head -1` does after its line
        stderr = process.stderr.read()
        process.wait(timeout=30)
    finally:
        process.kill()
    assert process.returncode == 141
    assert "Traceback" not in stderr and "Exception ignored" not in stderr
    assert "stdout was closed (broken pipe)" in stderr


def test_a_run_paced_to_real_time_shows_each_line_in_a_pipe_as_it_is_printed(tmp_path: Path) -> None:
    program = write(tmp_path, "slow.mnt", 'PRINT "homing"\nWAIT = 20000\nPRINT "homed"\n')
    process = start(program, "--realtime", "--max-wall-s", "60", unbuffered=False)
    started = time.monotonic()
    try:
        assert process.stdout is not None
        assert process.stdout.readline() == "homing\n"
        assert time.monotonic() - started < 15  # during the 20 s wait, not when the run ends and flushes
    finally:
        process.kill()
        process.communicate()


def test_the_program_cannot_be_its_own_configuration(tmp_path: Path) -> None:
    program = write(tmp_path, "app.mnt", "DIM a\nPRINT a\n")
    result = mint_run(program, "--config", program)
    assert result.exit_code == 2
    assert f"--config {program} is the program {program} itself: name the configuration file" in result.stderr


def test_a_binary_file_is_refused_before_the_run(tmp_path: Path) -> None:
    binary = tmp_path / "dump.mnt"
    binary.write_bytes(b"\x00\x01\x02")
    result = mint_run(binary)
    assert result.exit_code == 2
    assert result.stderr == f"mint-run: {binary}:1:1: not Mint text (a NUL byte): not run\n"


def test_a_mint_v3_keyword_stops_the_run_before_it_starts(tmp_path: Path) -> None:
    # GAIN is no v4 keyword (replaced by KPROP): the controller rejects it, so a run must not treat it as a variable
    result = mint_run(write(tmp_path, "old.mnt", "GAIN = 2\nPRINT KPROP.0\n"))
    assert result.exit_code == 1 and result.stdout == "C3001: PROGRAM Variable undefined, use DIM [line 1]\n"
    assert "C3001" in result.stderr and "replaced by KPROP" in result.stderr


def test_a_directive_of_the_program_is_reported_at_the_programs_path(tmp_path: Path) -> None:
    program = write(tmp_path, "press.mnt", "REM @sim plant 0 stalled\nREM @sim plant 0 ideal\nPRINT 1\n")
    result = mint_run(program)
    assert result.exit_code == 2
    assert f"{program}:2:5: axis 0 already has a plant (line 1)" in result.stderr  # at its @
