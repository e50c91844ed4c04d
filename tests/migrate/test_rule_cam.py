"""S-CAM: CAM/CAMA on cam<n>/minc<n> become CAMTABLE + CAM (v4 bits) + GO."""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate
from mintlang.migrate.rules.cams import cam_bits
from tests.migrate.helpers import flagged, one_rule, rewritten

TABLES = "DIM cam0(4) = 3,1,2,3\nDIM minc0(3) = 10,10,10\nDIM cam1(3) = 2,5,5\n"


@pytest.mark.parametrize(
    ("keyword", "value", "bits"),
    [
        ("CAM", 0, "0"),
        ("CAM", 1, "_cmCONTINUOUS"),
        ("CAM", 2, "_cmTRIGGER"),
        ("CAM", 3, "_cmCONTINUOUS + _cmTRIGGER + _cmRETRIGGER"),
        ("CAM", 4, None),
        ("CAMA", 0, "_cmABSOLUTE"),
        ("CAMA", 1, "_cmABSOLUTE + _cmCONTINUOUS"),
        ("CAMA", 4, "_cmABSOLUTE + _cmT_ABSOLUTE"),
        ("CAMA", 7, "_cmABSOLUTE + _cmT_ABSOLUTE + _cmCONTINUOUS + _cmTRIGGER + _cmRETRIGGER"),
        ("CAMA", 8, None),
    ],
)
def test_mode_map(keyword: str, value: int, bits: str | None) -> None:
    assert cam_bits(keyword, value) == bits


def test_cam_gets_its_tables_and_go() -> None:
    assert rewritten("S-CAM", TABLES + "CAM.0 = 0 : REM once\ncama[0,1] = 1, 1\n") == TABLES + (
        "CAMTABLE(0, cam0, minc0) : CAM.0 = 0 : GO.0 : REM once\n"
        "camtable(0, cam0, minc0) : camtable(1, cam1, NULL) : "
        "cam[0,1] = _cmABSOLUTE + _cmCONTINUOUS, _cmABSOLUTE + _cmCONTINUOUS : go[0,1]\n"
    )


def test_fast_interrupt_modes_need_no_go() -> None:
    result = one_rule("S-CAM", TABLES + "CAM.1 = 3\n")
    assert result.text == TABLES + "CAMTABLE(1, cam1, NULL) : CAM.1 = _cmCONTINUOUS + _cmTRIGGER + _cmRETRIGGER\n"
    assert result.manual == ()


def test_one_shot_triggered_cam_notes_the_v3_restart() -> None:
    result = one_rule("S-CAM", TABLES + "CAM.1 = 2\n")
    assert result.text.endswith("CAMTABLE(1, cam1, NULL) : CAM.1 = _cmTRIGGER\n")
    assert [item.reason for item in result.manual] == [
        "v3 also restarted this one-shot cam on later fast interrupts (v3 guide section 6.7.3): consider _cmRETRIGGER"
    ]


@pytest.mark.parametrize(
    ("source", "reason"),
    [
        ("CAM.0 = 1\n", "no DIM cam0: v3 took axis 0's cam table from cam0"),
        (TABLES + "CAM.0 = m\n", "CAM value is not a constant v3 mode (0..3, CAMA 0..7)"),
        (TABLES + "CAM.2 = 0\n", "v3 runs cams on axes 0 and 1 only, not on axis 2"),
        (TABLES + "CAM[0,1] = 0, 2\n", "fast-interrupt and started cams in one statement: GO only the started axes"),
        (TABLES + "CAM.(a) = 0\n", "CAM: the axes are not constant; write CAMTABLE, CAM and GO by hand"),
        (
            TABLES + "CAMSTART.0 = 2\nCAM.0 = 0\n",
            "CAMTABLE resets CAMSTART and CAMEND: place CAMTABLE(axis, cam, minc) before they are set",
        ),
        (
            "SCALE = 4\n" + TABLES + "CAM.0 = 0\n",
            "minc0 is in counts, a v4 master table in the master's user units: SCALE is set; "
            "once minc0 is in those units, write CAMTABLE(0, cam0, minc0) : CAM.0 = 0 : GO.0",
        ),
    ],
)
def test_unproven_context_is_manual(source: str, reason: str) -> None:
    assert flagged("S-CAM", source) == [reason]


def test_stop_at_end_idiom_is_manual_and_the_first_cam_is_migrated() -> None:
    result = one_rule("S-CAM", TABLES + "CAMA = 1\nPAUSE IN1\nCAMA = 0\n")
    assert result.text == TABLES + (
        "CAMTABLE(0, cam0, minc0) : CAM.0 = _cmABSOLUTE + _cmCONTINUOUS : GO.0\nPAUSE IN1\n"
        "REM MIGRATE: S-CAM: an earlier continuous cam may still run: v3 queued this cam, "
        "v4 needs STOP : PAUSE IDLE first\nCAMA = 0\n"
    )


@pytest.mark.parametrize("mode", [0, 1, 2, 3])
def test_second_run_changes_nothing(mode: int) -> None:
    first = migrate(TABLES + f"CAM.0 = {mode}\nPAUSE IN1\nCAMA.0 = 0\n")
    second = migrate(first.text)
    assert second.text == first.text and second.changes == ()
    assert [(item.rule, item.line) for item in second.manual] == [(item.rule, item.line) for item in first.manual]
