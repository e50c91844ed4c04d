"""``mint-run`` / ``mint run`` on the command line: output, exit status, report, trace, expectations, host port."""

from __future__ import annotations

import importlib.util
import json
import os
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from mintlang.cli import main
from mintlang.runtime.comms.packets import ACK, encode_write

PROGRAMS = Path(__file__).parent.parent / "corpus" / "runtime" / "programs"
MOVE = 'RESET.0\nMOVER.0 = 1000 : GO.0\nPAUSE IDLE.0\nPRINT "at ", POS.0\n'


def mint_run(*arguments: str | Path) -> Result:
    return CliRunner().invoke(main, ["run", *(str(argument) for argument in arguments)])


def write(directory: Path, name: str, text: str) -> Path:
    path = directory / name
    path.write_text(text, encoding="utf-8")
    return path


def test_terminal_output_goes_to_stdout_and_the_end_exits_0(tmp_path: Path) -> None:
    result = mint_run(write(tmp_path, "move.mnt", MOVE))
    assert result.exit_code == 0
    assert result.stdout == "at 1000\n"
    assert "end after" in result.stderr


def test_a_run_time_error_exits_1_and_names_the_line(tmp_path: Path) -> None:
    result = mint_run(write(tmp_path, "fail.mnt", "DIM a = 0\nPRINT 1 / a\n"))
    assert result.exit_code == 1
    assert "R2021" in result.stderr and "line 2" in result.stderr


def test_the_stop_line_quotes_a_long_statement_cut_as_mint_check_cuts_a_line(tmp_path: Path) -> None:
    statement = 'PRINT 1 / 0; "' + "x" * 60_000 + '"'  # divides by zero before the 60,000-character string
    result = mint_run(write(tmp_path, "long.mnt", statement + "\n"))
    assert result.exit_code == 1
    # the whole statement is where the run stopped: the first 120 characters as the marked text, 60 of context
    quoted = 'PRINT 1 / 0; "' + "x" * (180 - 14) + "…"
    assert f"at program line 1: {quoted} — R2021" in result.stderr
    warning, stop = result.stderr.split("\n", 1)  # the line is too long to download (W111), then the stop
    assert warning.startswith("warning: program line 1: line has 60015 characters; the controller accepts 255")
    assert len(stop) < 400


def test_a_missing_file_is_a_usage_error(tmp_path: Path) -> None:
    result = mint_run(tmp_path / "absent.mnt")
    assert result.exit_code == 2
    assert "cannot read" in result.stderr
    assert "Traceback" not in result.output


def test_a_bad_sim_directive_is_a_usage_error_with_its_line(tmp_path: Path) -> None:
    result = mint_run(write(tmp_path, "bad.mnt", "PRINT 1\nREM @sim input banana\n"))
    assert result.exit_code == 2
    assert ":2:" in result.stderr


def test_the_json_report_has_the_final_state(tmp_path: Path) -> None:
    result = mint_run(write(tmp_path, "move.mnt", MOVE), "--report", "json", "--controller", "nextmove-bx")
    report = json.loads(result.stdout[result.stdout.index("{") :])
    assert {"time_ms", "stopped", "line", "err", "erl", "outputs"} <= report.keys()
    assert report["stopped"] == "end" and report["err"] == -1
    axis = report["axes"]["0"]
    assert {"pos", "vel", "folerror", "axismode", "axiserror", "axisstatus", "dac"} <= axis.keys()
    assert axis["pos"] == 1000 and len(report["axes"]) == 8


def test_until_ms_bounds_a_program_that_never_ends(tmp_path: Path) -> None:
    result = mint_run(write(tmp_path, "loop.mnt", "LOOP\nENDL\n"), "--until-ms", "500", "--report", "json")
    assert result.exit_code == 0
    report = json.loads(result.stdout)
    assert (report["stopped"], report["time_ms"]) == ("until", 500)


def test_max_wall_s_bounds_a_run_in_real_time(tmp_path: Path) -> None:
    result = mint_run(write(tmp_path, "loop.mnt", "LOOP\nENDL\n"), "--max-wall-s", "0.2", "--report", "json")
    assert result.exit_code == 1
    assert json.loads(result.stdout)["stopped"] == "wall-limit"


def test_a_deadlock_exits_1(tmp_path: Path) -> None:
    result = mint_run(write(tmp_path, "stuck.mnt", "RESET.0\nMOVER.0 = 1\nMOVER.0 = 1\nMOVER.0 = 1\n"))
    assert result.exit_code == 1
    assert "deadlock" in result.stderr and "line 4" in result.stderr


def test_a_trace_is_byte_identical_from_run_to_run(tmp_path: Path) -> None:
    program = PROGRAMS / "pick_and_place.mnt"
    first, second = tmp_path / "first.csv", tmp_path / "second.csv"
    assert mint_run(program, "--trace", first, "--trace-axes", "0,1").exit_code == 0
    assert mint_run(program, "--trace", second, "--trace-axes", "0,1").exit_code == 0
    assert first.read_bytes() == second.read_bytes()
    lines = first.read_text().splitlines()
    assert lines[0].startswith("time_ms,demand.0,pos.0")
    assert len(lines) == 1 + 1711  # one row per tick, 0 to 1710 ms


def test_expectations_decide_the_exit_status_and_print_a_table(tmp_path: Path) -> None:
    program = PROGRAMS / "pick_and_place.mnt"
    held = mint_run(program, "--expect", PROGRAMS / "pick_and_place.toml")
    assert held.exit_code == 0 and "All 5 expectations held" in held.stderr
    failing = write(tmp_path, "wrong.toml", '[[expect]]\nwhat = "POS.0"\nequals = 5\n')
    failed = mint_run(program, "--expect", failing)
    assert failed.exit_code == 1 and "1 of 1 expectation failed" in failed.stderr


def test_plotting_without_matplotlib_says_how_to_install_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # as if the optional extra were not installed
    result = mint_run(write(tmp_path, "move.mnt", MOVE), "--plot", tmp_path / "plot.png")
    assert result.exit_code == 2
    assert "plotting needs matplotlib: pip install " in result.stderr and "[plot]" in result.stderr


@pytest.mark.skipif(importlib.util.find_spec("matplotlib") is None, reason="the plot extra is not installed")
def test_plotting_draws_position_velocity_and_following_error(tmp_path: Path) -> None:
    image = tmp_path / "plot.png"
    assert mint_run(write(tmp_path, "move.mnt", MOVE), "--plot", image, "--trace-axes", "0").exit_code == 0
    assert image.read_bytes().startswith(b"\x89PNG")


def test_a_host_program_talks_to_the_running_simulation_over_tcp(tmp_path: Path) -> None:
    program = write(tmp_path, "host.mnt", 'PAUSE COMMS(1) = 7\nPRINT "host wrote ", COMMS(1)\n')
    process = subprocess.Popen(
        [sys.executable, "-m", "mintlang.runtime", str(program), "--host-port", "0", "--max-wall-s", "30"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env={**os.environ, "COLUMNS": "200"},
    )
    try:
        assert process.stderr is not None
        line = process.stderr.readline()
        port = int(line.rsplit(":", 1)[1])
        with socket.create_connection(("127.0.0.1", port), timeout=10) as host:
            host.sendall(encode_write(2, 1, [7]))
            deadline = time.monotonic() + 10
            reply = b""
            while not reply and time.monotonic() < deadline:
                reply = host.recv(16)
        assert reply == ACK
        stdout, _ = process.communicate(timeout=30)
    finally:
        process.kill()
    assert process.returncode == 0
    assert stdout == "host wrote 7\n"


def test_the_report_lists_settings_the_simulation_does_not_model(tmp_path: Path) -> None:
    result = mint_run(write(tmp_path, "settings.mnt", "ECHO = 0\nGEARING = 50\nPRINT GEARING\n"), "--report", "json")
    report = json.loads(result.stdout[result.stdout.index("{") :])
    assert result.stdout.startswith("50\n")
    assert report["inert_settings"] == ["ECHO", "GEARING"]


def test_drives_start_disabled_and_the_error_says_how_to_enable_them(tmp_path: Path) -> None:
    program = write(tmp_path, "move.mnt", "MOVER.0 = 10 : GO.0\nPAUSE IDLE.0\nPRINT POS.0\n")
    refused = mint_run(program)
    assert refused.exit_code == 1
    assert "R0040" in refused.stderr and "--drives enabled" in refused.stderr
    enabled = mint_run(program, "--drives", "enabled")
    assert (enabled.exit_code, enabled.stdout) == (0, "10\n")


def test_a_compile_error_is_reported_with_its_number_and_line_in_the_json_report(tmp_path: Path) -> None:
    result = mint_run(write(tmp_path, "open.mnt", "DIM a\nFOR a = 1 TO 2\nPRINT a\n"), "--report", "json")
    printed, report_text = result.stdout.split("\n", 1)
    report = json.loads(report_text)
    assert printed == "C2009: PROGRAM NEXT w/o FOR [line 2]"
    assert (report["stopped"], report["err"], report["erl"]) == ("error", 2009, 2)
    assert report["message"].startswith("C2009")


def test_a_compile_error_quotes_the_line_it_is_on_even_where_nothing_is_written(tmp_path: Path) -> None:
    # the FOR has no TO (error 2008, 000:18949-18952): the place of the error is the end of the statement, and the
    # stop line showed ':  —' with nothing between; it quotes the line, as a run-time error quotes its statement
    result = mint_run(write(tmp_path, "no_to.mnt", "DIM i\r\n  FOR i = 1 : NEXT\r\nPRINT i\r\n"))
    assert result.exit_code == 1
    assert "at program line 2: FOR i = 1 : NEXT — C2008: PROGRAM TO expected" in result.stderr


def test_a_run_paced_to_real_time_stops_at_the_wall_clock_limit_even_inside_a_long_wait(tmp_path: Path) -> None:
    program = write(tmp_path, "wait.mnt", "PRINT 1\nWAIT = 5000\nPRINT 2\n")
    result = mint_run(program, "--realtime", "--max-wall-s", "0.5", "--report", "json")
    report = json.loads(result.stdout[result.stdout.index("{") :])
    assert (report["stopped"], report["time_ms"], report["line"]) == ("wall-limit", 500, 2)
