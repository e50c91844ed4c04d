"""X-GO-TIMING, X-NUM, X-ARRAY-CFG, X-PRINT, X-UNITS: markers only where the spec row applies."""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate
from tests.migrate.helpers import flagged, one_rule

DELAYED = "v3 ran this when the previous move ended (GO waited); v4 GO does not wait: use PAUSE or MOVEBUFFERFREE"


def test_statement_after_a_blocking_go_is_flagged() -> None:
    source = "FLY = 10 : GO\nOUT2 = 1\nFLY = 20 : GO\nOUT1 = 1 : REM late\n"
    result = one_rule("X-GO-TIMING", source)
    assert result.text == source.replace("OUT1", f"REM MIGRATE: X-GO-TIMING: {DELAYED}\nOUT1")
    assert [item.line for item in result.manual] == [5]


@pytest.mark.parametrize(
    "source",
    [
        "MOVEA = 1 : GO\nOUT1 = 1\n",  # the first GO starts at once in v3 too
        "MOVEA = 1 : GO\nPAUSE IDLE\nMOVEA = 2 : GO\nOUT1 = 1\n",  # waited for the move
        "MOVEA.0 = 1 : GO.0\nMOVEA.1 = 2 : GO.1\nOUT1 = 1\n",  # other axis: GO did not wait
        "MOVEA = 1 : GO\n#next\nMOVEA = 2 : GO\nOUT1 = 1\n",  # a label: the path is not known
        "MOVEA = 1 : GO\nMOVEA = 2 : GO\nMOVEA = 3 : GO\n",  # moves after GO keep their order
    ],
)
def test_go_timing_stays_quiet_where_v3_did_not_wait(source: str) -> None:
    assert flagged("X-GO-TIMING", source) == []


@pytest.mark.parametrize(
    "source",
    [
        "LOOP\n  MOVER = 10 : GO\n  OUT1 = 1\nENDL\n",
        "FOR i = 1 TO 3\n  MOVER = 10 : GO\n  OUT1 = 1\nNEXT\n",
        "REPEAT\n  MOVER = 10 : GO\n  OUT1 = 1\nUNTIL IN2\n",
        "WHILE IN2\n  MOVER = 10 : GO\n  OUT1 = 1\nENDW\n",
        "LOOP\n  FOR i = 1 TO 2\n    PRINT i\n  NEXT\n  MOVER = 10 : GO\n  OUT1 = 1\nENDL\n",  # a loop in its body
    ],
)
def test_the_statement_after_a_go_in_a_loop_is_flagged(source: str) -> None:
    """From the second pass on, the GO waits for the move the pass before started (v3:3405-3412)."""
    result = one_rule("X-GO-TIMING", source)
    assert result.text == source.replace("  OUT1", f"  REM MIGRATE: X-GO-TIMING: {DELAYED}\n  OUT1")


@pytest.mark.parametrize(
    "source",
    [
        "LOOP\n  MOVER = 10 : GO\n  PAUSE IDLE\n  OUT1 = 1\nENDL\n",  # each pass waits for its move
        "FOR i = 0 TO 1\n  MOVEA.0 = 5 : GO.0\n  PAUSE IDLE.0\nNEXT\nMOVEA.1 = 5 : GO.1\nOUT1 = 1\n",
    ],
)
def test_a_loop_whose_moves_end_in_each_pass_stays_quiet(source: str) -> None:
    assert flagged("X-GO-TIMING", source) == []


def test_pause_on_trigger_is_flagged() -> None:
    assert flagged("X-GO-TIMING", "PAUSE !TRIGGER\nPAUSE IN1\n") == [
        "PAUSE on TRIGGER relied on v3's one-move buffer; v4 buffers more moves (MOVEBUFFERFREE)"
    ]


def test_fixed_point_literals() -> None:
    assert flagged("X-NUM", "a = 0.15 * b\nc = 0.5 + 2.25\nd = .004\n") == [
        "0.15 was 38/256 in v3 (1/256 fixed point; PRINT shows 0.148), floating point in v4",  # v3:1173-1181
        # 1/256 = 0.0039..., cut to three places as 1.0039 shows 1.003 (v3:1161-1170)
        ".004 was 1/256 in v3 (1/256 fixed point; PRINT shows 0.003), floating point in v4",
    ]


def test_equality_on_fractions_and_fractional_loops() -> None:
    assert flagged("X-NUM", "IF a / 3 = b THEN c = 1\nIF a = b THEN c = 2\nFOR i = 0 TO 1 STEP 0.25\nNEXT\n") == [
        "'=' on a fractional value: v3 compared 1/256 fixed-point values, v4 floating point",
        "fractional FOR: v3 counted in 1/256 steps, the number of passes can differ in v4",
    ]


def test_arrays_in_the_configuration_file() -> None:
    result = one_rule("X-ARRAY-CFG", "DIM b(3)\n", config="AUTO\nDIM a(10)\na(1) = 5\n")
    assert result.configuration is not None
    reasons = [item.reason for item in result.configuration.manual]
    assert reasons == [
        "v4 deletes array data when the configuration runs: DIM it in the program",
        "v4 deletes array data when the configuration runs: fill it in the program",
    ]
    assert result.text == "DIM b(3)\n" and not result.manual


def test_output_formats() -> None:
    source = 'PRINT USING 3, x\nPRINT "ERROR: axis 0"\nPRINT "Limit error"\nPRINT x\nBINARY x\n'
    assert flagged("X-PRINT", source) == [
        "USING layout: v4 prints numbers with up to 4 decimals; check what reads this output",
        "v4 error messages read 'R0003: ...': a host parsing v3 'ERROR:' text must change",
        "BINARY output: v4 prints with PRINT BIN, without the 8-digit padding",
    ]


def test_changed_units() -> None:
    # one item for a block of gain writes on consecutive lines, whether v3 (GAIN) or v4 (KPROP) names
    gains = "GAIN = 2 : KVEL = 10\nKPROP.1 = 3\nx = KINT\n"
    assert flagged("X-UNITS", gains) == ["servo gains changed units and loop rate in v4: re-tune"]
    assert len(flagged("X-UNITS", "KPROP = 1.5;\nx = 1\nKVEL = 2;\n")) == 2
    assert flagged("X-UNITS", "TORQUE = 50\nTORQUE = 0\n", controller="mintdrive") == [
        "MintDrive TORQUE 100 is nominal current (v3 100 was peak)"
    ]
    assert flagged("X-UNITS", "TORQUE = 50\n") == []


def test_a_tuning_block_keeps_one_item_when_other_items_go_between_its_lines() -> None:
    # 0.1, 2.3 and 2.7 are no multiples of 1/256: X-NUM puts an item above each gain line
    result = migrate("KPROP = 0.1\nKVEL = 2.3\nKVELFF = 2.7\n")
    assert [item.rule for item in result.manual] == ["X-NUM", "X-UNITS", "X-NUM", "X-NUM"]
    assert len(flagged("X-UNITS", "KPROP = 1\nREM velocity loop\nKVEL = 2\n")) == 2  # the user's line splits it


@pytest.mark.parametrize("rule", ["X-GO-TIMING", "X-NUM", "X-PRINT", "X-UNITS"])
def test_markers_are_idempotent_and_leave_the_bytes(rule: str) -> None:
    source = "MOVER = 1 : GO\r\nMOVER = 2 : GO\r\nOUT1 = 1\r\na = 0.1\r\nPRINT USING 2, a\r\nGAIN = 1\r\n"
    once = one_rule(rule, source).text
    assert once != source
    assert "".join(line for line in once.splitlines(keepends=True) if "REM MIGRATE:" not in line) == source
    assert one_rule(rule, once).text == once


def test_a_move_loaded_while_the_axis_homes_is_flagged() -> None:
    # v3's GO waited for the datum; v4 refuses a move on a homing axis (v4:11473-11475)
    assert flagged("X-GO-TIMING", "AXES[0,1]\nHOME = 1;\nVECTORA = 10, 20 : GO\n") == [
        "v3 GO waited for the datum; v4 loads no move while the axis homes (error 10): PAUSE IDLE first"
    ]
    assert flagged("X-GO-TIMING", "AXES[0,1]\nHOME = 1;\nPAUSE IDLE\nVECTORA = 10, 20 : GO\n") == []
