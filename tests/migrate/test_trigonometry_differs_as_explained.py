"""SIN, COS and TAN: the migration keeps v3's thousandths (M-TRIG) and says the values differ slightly, and
``--verify`` reports what that changes as explained, not as a divergence, while still finding real ones.

v3 looks the functions up in a table of whole thousandths, about a tenth of a degree apart: ``SIN 30`` is
500 and ``COS(30)`` 866 (001:2061-2069, 001:7039-7051). v4 returns the fraction (000:8676-8679): cos 30°
is 0.8660254, so the migrated ``(COS(30) * 1000)`` is 866.025..., which v3 never printed; sin 30° is 0.5
exactly, so ``(SIN(30) * 1000)`` is 500 in both.
"""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

from click.testing import CliRunner

from mintlang.migrate import migrate
from mintlang.migrate.cli import migrate as command
from mintlang.migrate.verification import Divergence, Verdict, Verification, verify
from mintlang.migrate.verification.explained import WHAT_IF, split
from mintlang.runtime.scenario import DrivesEnabled, Scenario

DRIVES = Scenario(drives=(DrivesEnabled(),))
COSINE = "a = COS(30)\nPRINT a\n"
# No SPEED: v3's default is 40000 counts/s, v4's 20000 (S-DEFAULTS), so the move parts from about 73 ms
# (tests/migrate/test_verify.py works it out): a divergence no trigonometry explains.
COSINE_AND_DEFAULT_SPEED = "a = COS(30)\nPRINT a\nMOVEA.0 = 100000 : GO.0 : PAUSE IDLE.0\n"


def test_a_printed_cosine_differs_only_as_m_trig_explains() -> None:
    found = verify(migrate(COSINE), scenario=DRIVES, until_ms=100)
    assert found.verdict is Verdict.EXPLAINED
    divergence = found.divergence
    assert divergence is not None
    assert (divergence.what, divergence.explained_by, divergence.what_if) == ("terminal", "M-TRIG", None)
    assert divergence.v3 == "'866'"
    assert divergence.v4.startswith("'866.02")
    assert found.differences == (divergence,)


def test_a_sine_both_give_alike_is_equivalent() -> None:
    found = verify(migrate("a = SIN(30)\nPRINT a\n"), scenario=DRIVES, until_ms=100)
    assert found.verdict is Verdict.EQUIVALENT
    assert found.differences == ()


def test_a_real_divergence_beside_the_cosine_still_diverges() -> None:
    found = verify(migrate(COSINE_AND_DEFAULT_SPEED), scenario=DRIVES, until_ms=500)
    assert found.verdict is Verdict.DIVERGES
    divergence = found.divergence
    assert divergence is not None
    assert (divergence.what, divergence.explained_by) == ("axis 0 velocity", None)
    assert 73 <= divergence.time_ms <= 78
    assert float(divergence.v4) == 20000
    assert [(d.what, d.explained_by) for d in found.differences] == [
        ("terminal", "M-TRIG"),
        ("axis 0 velocity", None),
    ]


def _with_go_printed_wrong(original: str) -> Verification:
    """``--verify`` of the migration of ``original`` with its ``PRINT "go"`` made to print "GO": a fault no rule
    explains, which must be told as a terminal divergence."""
    result = migrate(original)
    altered = replace(result, text=result.text.replace('PRINT "go"', 'PRINT "GO"'))
    found = verify(altered, scenario=DRIVES, until_ms=100)
    assert found.verdict is Verdict.DIVERGES
    divergence = found.divergence
    assert divergence is not None
    assert (divergence.what, divergence.v3, divergence.v4) == ("terminal", "'go'", "'GO'")
    assert divergence.explained_by is None
    return found


def test_a_wrong_print_after_the_cosine_diverges_in_the_run_given_v3s_values() -> None:
    # v4's own run differs first at the cosine; given v3's values, it differs where "go" became "GO"
    found = _with_go_printed_wrong(COSINE + 'PRINT "go"\n')
    divergence = found.divergence
    assert divergence is not None
    assert divergence.what_if is not None and "M-TRIG" in divergence.what_if
    assert found.differences == (divergence,)


def test_a_wrong_print_before_the_cosine_is_v4s_own_difference() -> None:
    found = _with_go_printed_wrong('PRINT "go"\n' + COSINE)
    assert found.divergence is not None
    assert found.divergence.what_if is None


def test_the_migration_report_says_which_lines_differ_and_why(tmp_path: Path) -> None:
    path = tmp_path / "cell.mnt"
    path.write_text(COSINE)
    text = CliRunner().invoke(command, [str(path)])
    # the migration declares a above the program (M-DIM): line 1 becomes line 2
    assert f"{path}: M-TRIG on lines 2 (original 1): values differ slightly" in text.stdout
    data = json.loads(CliRunner().invoke(command, ["--format", "json", str(path)]).stdout)
    (trig,) = [change for change in data["files"][0]["changes"] if change["rule"] == "M-TRIG"]
    assert (trig["original"], trig["replacement"]) == ("COS(30)", "(COS(30) * 1000)")
    assert "values differ slightly" in trig["differs"]
    assert all("differs" not in change for change in data["files"][0]["changes"] if change["rule"] != "M-TRIG")


def test_verify_passes_an_explained_difference_and_says_so(tmp_path: Path) -> None:
    path = tmp_path / "cell.mnt"
    path.write_text(COSINE)
    result = CliRunner().invoke(command, ["--verify", "--until-ms", "100", str(path)])
    assert result.exit_code == 0
    lines = result.stdout.splitlines()
    assert lines[0] == f"{path}: differs only as M-TRIG explains, from 0 ms: terminal (v3 character 1 / v4 character 1)"
    assert lines[1] == f"  v3: '866'  at {path}:2"
    assert lines[3].startswith("  explained: M-TRIG values differ slightly")
    assert lines[-1] == "1 application verified: 1 explained"
    data = json.loads(
        CliRunner().invoke(command, ["--verify", "--until-ms", "100", "--format", "json", str(path)]).stdout
    )
    application = data["applications"][0]
    assert (application["verdict"], application["divergence"]["explained_by"]) == ("explained", "M-TRIG")
    assert data["totals"]["explained"] == 1


def test_verify_fails_on_a_real_divergence_beside_an_explained_one(tmp_path: Path) -> None:
    path = tmp_path / "cell.mnt"
    path.write_text(COSINE_AND_DEFAULT_SPEED)
    result = CliRunner().invoke(command, ["--verify", "--drives", "enabled", "--until-ms", "500", str(path)])
    assert result.exit_code == 1
    assert result.stdout.splitlines()[0].startswith(f"{path}: diverges at ")
    assert "also differs: terminal at 0 ms (v3 '866', v4 '866.02" in result.stdout
    assert "explained by M-TRIG)" in result.stdout


def test_a_channel_only_the_what_if_run_differs_in_is_no_divergence() -> None:
    # v4's own run differs from v3 on the terminal alone; given v3's values it differs there and on an axis,
    # where v4's own run agrees with v3: only the terminal is the migration's difference
    def difference(what: str, v4: str) -> Divergence:
        return Divergence(10, what, "1", v4, None, None)

    found = [difference("terminal", "'707.1067'")]
    still = [difference("terminal", "'GO'"), difference("axis 0 position", "5")]
    diverging, explained = split(found, still)
    assert [(d.what, d.v4, d.what_if) for d in diverging] == [("terminal", "'GO'", WHAT_IF)]
    assert explained == []
