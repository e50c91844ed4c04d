"""``mint-migrate --verify``: the report in text and JSON, the exit status, and bad input.

The programs and their expected verdicts are those of test_verify.py, worked out
there by hand; here they go through the command line.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from mintlang.migrate.cli import migrate

EQUIVALENT = 'SCALE = 10\nSPEED = 100 : ACCEL = 1000\nPRINT "go"\nMOVEA.0 = 50 : GO.0\nPAUSE IDLE.0\nPRINT POS.0\n'
DEFAULT_SPEED = "MOVEA.0 = 100000 : GO.0 : PAUSE IDLE.0\n"  # v3 cruises at 40000 counts/s, v4 at 20000
TIMING = "SPEED = 20000 : ACCEL = 100000\nMOVER.0 = 10000 : GO.0\nMOVER.0 = 10000 : GO.0\nOUT0 = 1\nPAUSE IDLE.0\n"
SHORT_MOVES = TIMING.replace("10000 :", "2000 :")
NOT_SIMULATED = 'PRINT "a"\nCOMMSON\n'


def run(tmp_path: Path, program: str, *arguments: str) -> tuple[int, str, str]:
    path = tmp_path / "demo.mnt"
    path.write_text(program)
    result = CliRunner().invoke(migrate, ["--verify", "--drives", "enabled", *arguments, str(path)])
    return result.exit_code, result.stdout, result.stderr


def test_an_equivalent_migration_passes_and_says_over_how_long(tmp_path: Path) -> None:
    code, output, errors = run(tmp_path, EQUIVALENT, "--until-ms", "2000")
    assert code == 0
    assert output.splitlines()[0] == f"{tmp_path / 'demo.mnt'}: equivalent over 602 ms"
    assert "1 application verified: 1 equivalent" in output
    assert errors == ""
    assert (tmp_path / "demo.mnt").read_text() == EQUIVALENT  # --verify writes nothing


def test_a_divergence_fails_with_its_time_lines_and_values(tmp_path: Path) -> None:
    code, output, _ = run(tmp_path, DEFAULT_SPEED, "--until-ms", "500")
    path = tmp_path / "demo.mnt"
    lines = output.splitlines()
    assert code == 1
    assert lines[0].startswith(f"{path}: diverges at ") and lines[0].endswith(" ms: axis 0 velocity")
    assert lines[1].startswith("  v3: ") and lines[1].endswith(f"at {path}:1")
    assert lines[2] == f"  v4: 20000  at migrated {path}:10"  # below the 9 notes (no AXES: every axis is named)
    assert "not verified: " in output and "S-DEFAULTS SPEED[0] = <value>;" in output


def test_the_json_report_carries_the_verdict_the_first_divergence_and_what_was_not_verified(tmp_path: Path) -> None:
    code, output, _ = run(tmp_path, DEFAULT_SPEED, "--until-ms", "500", "--format", "json")
    data = json.loads(output)
    application = data["applications"][0]
    divergence = application["divergence"]
    assert code == 1
    assert data["totals"] == {"equivalent": 0, "timing": 0, "explained": 0, "diverges": 1, "incomplete": 0}
    assert (application["verdict"], application["compared_ms"], application["incomplete"]) == ("diverges", 500, None)
    assert (application["v3_controller"], application["v4_controller"]) == ("euroservo", "nextmove-pci")
    assert divergence["what"] == "axis 0 velocity" and 73 <= divergence["time_ms"] <= 78
    assert divergence["v3"]["line"] == 1 and divergence["v4"] == {
        "value": "20000",
        "file": str(tmp_path / "demo.mnt"),
        "line": 10,
    }
    assert application["stopped"]["v3"]["reason"] == "until"
    speed = [item for item in application["not_verified"] if item["rule"] == "S-DEFAULTS" and "SPEED" in item["reason"]]
    assert speed and speed[0]["note"] and speed[0]["original_line"] is None
    assert application["disabled"] == []


def test_a_timing_difference_x_go_timing_flagged_passes_unless_manual_items_fail(tmp_path: Path) -> None:
    code, output, _ = run(tmp_path, TIMING, "--until-ms", "2000")
    assert code == 0
    headline = "timing differs (X-GO-TIMING) at 0 ms: OUT bit 0 (OUT 0 / 1)"
    assert output.splitlines()[0] == f"{tmp_path / 'demo.mnt'}: {headline}"
    # the flag is on OUT0 = 1, line 4 of the original; the notes exist in the migrated file only
    assert f"not verified: {tmp_path / 'demo.mnt'}:4: X-GO-TIMING" in output
    assert f"not verified: migrated {tmp_path / 'demo.mnt'}:1 (note): S-PROLOGUE" in output
    assert run(tmp_path, TIMING, "--until-ms", "2000", "--fail-on", "manual")[0] == 1


def test_an_incomplete_comparison_does_not_pass(tmp_path: Path) -> None:
    code, output, _ = run(tmp_path, NOT_SIMULATED, "--until-ms", "100")
    assert code == 2
    expected = "incomplete: COMMSON (command) is not simulated by mint-run"  # at 0 ms: nothing was compared
    assert output.splitlines()[0] == f"{tmp_path / 'demo.mnt'}: {expected}"


def test_a_scenario_file_gives_both_runs_their_stimulus(tmp_path: Path) -> None:
    scenario = tmp_path / "press.toml"
    scenario.write_text("[[input]]\nchannel = 0\nlevel = 1\nat_ms = 100\n")
    code, output, _ = run(tmp_path, 'PAUSE IN0\nPRINT "pressed"\n', "--scenario", str(scenario))
    assert code == 0
    assert output.splitlines()[0].endswith(": equivalent over 100 ms")


@pytest.mark.parametrize(
    ("scenario", "message"),
    [
        (None, "cannot read the file: No such file or directory"),
        ('[[input]]\nchannel = 3\nlevel = 1\nat_ms = "x"\n', ":4: at_ms must be a whole number, not 'x'"),
        ("[[input\n", ":1: not valid TOML: "),
    ],
    ids=["missing", "wrong value", "not TOML"],
)
def test_a_bad_scenario_file_is_one_line_naming_it(tmp_path: Path, scenario: str | None, message: str) -> None:
    path = tmp_path / "stimulus.toml"
    if scenario is not None:
        path.write_text(scenario)
    code, output, errors = run(tmp_path, EQUIVALENT, "--scenario", str(path))
    assert code == 2
    assert output == ""
    assert len(errors.splitlines()) == 1
    assert errors.startswith(f"mint-migrate: {path}") and message in errors
    assert "Traceback" not in errors


@pytest.mark.parametrize(
    ("arguments", "message"),
    [
        (["--until-ms", "100"], "--until-ms: only with --verify"),
        (["--scenario", "x.toml", "--v3-controller", "smartmove-1"], "--scenario, --v3-controller: only with --verify"),
        (["--verify", "--write"], "--write, --verify: choose one of these modes"),
    ],
)
def test_verify_options_are_checked(tmp_path: Path, arguments: list[str], message: str) -> None:
    path = tmp_path / "demo.mnt"
    path.write_text(EQUIVALENT)
    result = CliRunner().invoke(migrate, [*arguments, str(path)])
    assert result.exit_code == 2
    assert result.stderr == f"mint-migrate: {message}\n"


def test_a_timing_difference_beside_a_real_one_fails_and_each_is_told(tmp_path: Path) -> None:
    # Without S-ACCEL the v4 program keeps v4's DECEL of 300000 counts/s², where v3's ACCEL = 100000 also set
    # DECEL (001:5662). 2000 counts are too short to reach SPEED: v3 peaks at sqrt(2000 * 100000) = 14142
    # counts/s, 141.4 ms into the move (from 2 ms), v4 only at sqrt(2 * 2000 * 100000 * 300000 / 400000) =
    # 17321, so v4 reaches speeds v3 never does: a real difference, not one of timing. Both rise at 100 per ms;
    # past v3's peak they part at 200 per ms, and v3's velocity leaves the tube (1% + 1000, matched up to
    # 2 ms either side) once 100(t - 4) - (14142 - 100(t - 143.4)) > 1150, t > 150.2 ms (VEL, over 2 ms of
    # whole counts, may show it a little later); that comes after OUT0's timing difference at 0 ms, and fails
    # the run.
    code, output, _ = run(tmp_path, SHORT_MOVES, "--until-ms", "2000", "--skip", "S-ACCEL")
    lines = output.splitlines()
    assert code == 1
    assert lines[0] == f"{tmp_path / 'demo.mnt'}: diverges at 0 ms: OUT bit 0 (OUT 0 / 1)"
    assert lines[3].startswith("  also differs: axis 0 velocity at ")
    assert 151 <= int(lines[3].split(" at ")[1].split(" ms")[0]) <= 156
    v3, v4 = (float(value.split()[-1]) for value in lines[3].removesuffix(")").split("(")[1].split(", "))
    assert v4 - v3 > 1150


def test_a_rem_sim_line_that_cannot_be_read_names_its_program_and_the_others_are_verified(tmp_path: Path) -> None:
    bad = tmp_path / "bad.mnt"
    bad.write_text("REM @sim input banana\nPRINT 1\n")
    good = tmp_path / "good.mnt"
    good.write_text(EQUIVALENT)
    result = CliRunner().invoke(migrate, ["--verify", "--drives", "enabled", str(bad), str(good)])
    assert result.exit_code == 2
    assert result.stderr == f"mint-migrate: {bad}:1:16: expected an input channel as a whole number, not 'banana'\n"
    assert result.stdout.splitlines()[0] == f"{good}: equivalent over 602 ms"


def test_the_json_report_names_what_kept_an_application_from_being_verified(tmp_path: Path) -> None:
    good, missing = tmp_path / "good.mnt", tmp_path / "typo.mnt"
    good.write_text(EQUIVALENT)
    result = CliRunner().invoke(
        migrate, ["--verify", "--drives", "enabled", "--format", "json", str(good), str(missing)]
    )
    data = json.loads(result.stdout)
    assert result.exit_code == 2
    assert [row["program"] for row in data["applications"]] == [str(good)]
    assert data["problems"] == [f"no such file or directory: {missing}"]
    assert result.stderr == f"mint-migrate: no such file or directory: {missing}\n"


def test_an_incomplete_comparison_says_how_far_it_went(tmp_path: Path) -> None:
    # 40 assignments take the slices of 0 and 1 ms; v3 stops on COMMSON in the slice of 2 ms, part way
    # through it, so the runs are known up to 1 ms
    code, output, _ = run(tmp_path, "a = 1\n" * 40 + "COMMSON\n", "--until-ms", "100")
    assert code == 2
    expected = "incomplete: no difference over 1 ms, then COMMSON (command) is not simulated by mint-run"
    assert output.splitlines()[0] == f"{tmp_path / 'demo.mnt'}: {expected}"


def test_the_shared_output_options_apply_to_the_verification_report(tmp_path: Path) -> None:
    report = tmp_path / "verified.json"
    code, output, _ = run(
        tmp_path, DEFAULT_SPEED, "--until-ms", "500", "--format", "json", "--output-file", str(report)
    )
    assert code == 1
    assert output == ""
    assert json.loads(report.read_text())["totals"]["diverges"] == 1
    assert run(tmp_path, DEFAULT_SPEED, "--until-ms", "500", "--exit-zero")[0] == 0  # a divergence is the gate
    assert run(tmp_path, NOT_SIMULATED, "--until-ms", "100", "--exit-zero")[0] == 2  # incomplete is not done
    quiet = run(tmp_path, DEFAULT_SPEED, "--until-ms", "500", "-q")[1].splitlines()
    assert len(quiet) == 3  # the verdict and each run's side, without what was not verified or the totals


def test_the_settings_table_gives_verify_options_defaults_that_other_modes_ignore(tmp_path: Path) -> None:
    (tmp_path / "mint.toml").write_text('[migrate]\nuntil-ms = 300\ndrives = "enabled"\n')
    program = tmp_path / "demo.mnt"
    program.write_text(DEFAULT_SPEED)
    assert CliRunner().invoke(migrate, [str(program)]).exit_code == 0  # a dry run: not "only with --verify"
    verified = CliRunner().invoke(migrate, ["--verify", "--format", "json", str(program)])
    assert json.loads(verified.stdout)["applications"][0]["compared_ms"] == 300
