"""The semi-mechanical rules: the rewrite when the context is proven, a manual item when not."""

from __future__ import annotations

import pytest

from tests.migrate.helpers import flagged, one_rule, rewritten


def test_contouring_is_card_wide_on_nextmove() -> None:
    assert rewritten("S-CONT", "CONTON\nCONTOFF : REM off\n") == (
        "CONTOURMODE[0,1,2] = 1;\nCONTOURMODE[0,1,2] = 0; : REM off\n"
    )
    assert flagged("S-CONT", "CONTON\n", controller="mintdrive") == ["CONTOURMODE is not available on MintDrive"]


def test_servo_off_and_on_become_torque_and_cancel() -> None:
    assert rewritten("S-SERVOFF", "SERVOFF[0,1]\nSERVOFF.1\n") == "TORQUE[0,1] = 0;\nTORQUE.1 = 0\n"
    assert rewritten("S-SERVOC", "SERVOC[0,1] : SERVOC\n") == "CANCEL[0,1] : CANCEL\n"


def test_limits() -> None:
    assert rewritten("S-LIMIT", "DISLIMIT[0,1]\nENLIMIT.0\n") == (
        "LIMITMODE[0,1] = 0; : CANCEL[0,1]\nLIMITMODE.0 = 1\n"
    )


@pytest.mark.parametrize(
    ("controller", "expected"),
    [
        ("nextmove-pci", "EVENTDISABLE = EVENTDISABLE | 0xA0\nEVENTDISABLE = EVENTDISABLE & 0x15F\n"),
        ("mintdrive", "HANDLERDISABLE = HANDLERDISABLE | 0x42\nHANDLERDISABLE = HANDLERDISABLE & 0x1BD\n"),
    ],
)
def test_interrupt_disable_uses_the_controllers_event_bits(controller: str, expected: str) -> None:
    assert rewritten("S-INT", "DINT\nEINT\n", controller=controller) == expected


def test_idle_write_is_idlepos_and_idle_read_stays() -> None:
    assert rewritten("S-WRITE", "IDLE = .5;\nPAUSE IDLE[0,1]\n") == "IDLEPOS = .5;\nPAUSE IDLE[0,1]\n"
    assert flagged("S-WRITE", "VEL.0 = 2\n") == [
        "VEL written: v4 IDLEVEL takes the idle velocity in other units (v4:3046)"
    ]


def test_current_limit_is_one_write_per_dac_channel_on_nextmove() -> None:
    assert rewritten("S-CURR", "AXES[0,1]\nCURRLIMIT = 100;\n") == (
        "AXES[0,1]\nDACLIMITMAX.0 = 100 : DACLIMITMAX.1 = 100\n"
    )
    assert rewritten("S-CURR", "CURRLIMIT[2] = 50\n") == "DACLIMITMAX.2 = 50\n"
    assert rewritten("S-CURR", "CURRLIMIT = 80\n", controller="mintdrive") == "CURRENTLIMIT = 80\n"


def test_current_limit_on_computed_axes_is_flagged() -> None:
    reasons = flagged("S-CURR", "AXES[a]\nCURRLIMIT = 100;\n")
    assert reasons == ["DACLIMITMAX takes one channel per write and the axes here are not constant"]


def test_ramp_is_scaled_to_sramp() -> None:
    assert rewritten("S-RAMP", "RAMP = 1;\nRAMP[0,1] = r, 2.5\n") == "SRAMP = 10;\nSRAMP[0,1] = r * 10, 25\n"


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("TERM = 1\n", "TERMINAL = _tmLCD1\n"),
        ("TERM = _serial\n", "TERMINAL = _tmRS232\n"),
        ("TM = _both\n", "TERMINAL = _tmRS232 + _tmLCD1\n"),
    ],
)
def test_terminal_values_become_bits(source: str, expected: str) -> None:
    assert rewritten("S-TERM", source) == expected


def test_terminal_vt52_is_flagged() -> None:
    assert flagged("S-TERM", "TERM = 6\n") == [
        "TERM value is not 1, 2 or 3 (VT52 mode and computed values have no v4 equivalent)"
    ]


def test_config_values_and_drive_disable_after_reset() -> None:
    assert rewritten("S-CONFIG", "CONFIG = _micro, 1\n") == "CONFIG = _cfSTEPPER, 1\n"
    assert rewritten("S-CONFIG", "RESET\nCONFIG = _servo\n") == (
        "RESET\nDRIVEENABLE = 0; : CONFIG = _servo : DRIVEENABLE = 1;\n"
    )
    assert flagged("S-CONFIG", "CONFIG = _inverter\n") == ["CONFIG = _inverter: Mint v4 has no inverter configuration"]


def test_accel_also_sets_decel() -> None:
    assert rewritten("S-ACCEL", "ACCEL = 500; : REM a\nACCELTIME.1 = 20\n") == (
        "ACCEL = 500; : DECEL = 500; : REM a\nACCELTIME.1 = 20 : DECELTIME.1 = 20\n"
    )
    assert rewritten("S-ACCEL", "ACCEL = 5 : DECEL = 5\n") == "ACCEL = 5 : DECEL = 5\n"  # its own output


def test_accel_refusals() -> None:
    assert flagged("S-ACCEL", "AXISCON = 1\nACCEL = 5\n") == [
        "AXISCON is used: decide whether DECEL must follow this write"
    ]
    assert flagged("S-ACCEL", "DECEL = 300\n") == ["v3 ignored DECEL unless AXISCON bit 0 was set; v4 obeys it"]


def test_offset_needs_go_on_nextmove_only() -> None:
    assert rewritten("S-OFFSET", "OFFSET.1 = 10\n") == "OFFSET.1 = 10 : GO.1\n"
    assert rewritten("S-OFFSET", "OFFSET.1 = 10 : GO.1\n") == "OFFSET.1 = 10 : GO.1\n"
    assert rewritten("S-OFFSET", "OFFSET = 10\n", controller="mintdrive") == "OFFSET = 10\n"


def test_reads_that_moved_to_other_keywords() -> None:
    assert rewritten("S-READ", "PAUSE POS.0 = MOVEA.0\nx = OFFSET + HOME.1\nMOVEA = 5\n") == (
        "PAUSE POS.0 = POSTARGET.0\nx = POSREMAINING + HOMESWITCH.1\nMOVEA = 5\n"
    )
    assert flagged("S-READ", "IF !INCR THEN x = 1\n") == ["reading INCR has no v4 counterpart"]


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("IF MODE = _jog THEN x = 1\n", "IF (AXISMODE & _mdJOG) THEN x = 1\n"),
        ("IF MODE.1 <> 2 THEN x = 1\n", "IF (AXISMODE.1 & _mdLINEAR) = 0 THEN x = 1\n"),
        ("PAUSE MODE[0] = _idle\n", "PAUSE AXISMODE[0] = 0\n"),
        ("IF MODE = 18 THEN x = 1\n", "IF (AXISMODE & _mdFOLLOW) THEN x = 1\n"),
    ],
)
def test_mode_tests_become_bit_tests(source: str, expected: str) -> None:
    assert rewritten("S-MODE", source) == expected


@pytest.mark.parametrize(
    "source", ["PAUSE MODE = _pulse\n", "IF MODE > 2 THEN x = 1\n", "x = MODE\n", "IF MODE = 17 THEN x = 1\n"]
)
def test_mode_uses_without_a_bit_are_flagged(source: str) -> None:
    assert flagged("S-MODE", source) == ["MODE was a value, AXISMODE is a bit pattern: rewrite this use as a bit test"]


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        (
            "IF ERROR.1 = _limit DO\n",
            "IF (AXISERROR.1 & (_erFWD_HARD_LIMIT | _erREV_HARD_LIMIT)) DO\n",
        ),
        ("IF ERROR = _maxfe THEN CANCEL\n", "IF (AXISERROR & _erFOLLOWING_ERROR) THEN CANCEL\n"),
        ("IF ERROR.0 <> 11 THEN x = 1\n", "IF (AXISERROR.0 & _erERROR_INPUT) = 0 THEN x = 1\n"),
        ("PAUSE ERROR = 0\n", "PAUSE AXISERROR = 0\n"),
    ],
)
def test_error_tests_become_bit_tests(source: str, expected: str) -> None:
    assert rewritten("S-ERROR", source) == expected


def test_error_13_has_no_bit() -> None:
    assert flagged("S-ERROR", "IF ERROR = 13 THEN x = 1\n") == [
        "ERROR was a value, AXISERROR is a bit pattern: rewrite this use as a bit test"
    ]


def test_input_handlers_get_negative_edges() -> None:
    source = "LOOP : ENDL\n#IN0\nRETURN\n#IN3\nRETURN\n"
    assert rewritten("S-INEDGE", source) == (
        "INPUTMODE = INPUTMODE | 9\nINPUTNEGTRIGGER = INPUTNEGTRIGGER | 9\n" + source
    )
    result = one_rule("S-INEDGE", source, config="AUTO\n")
    assert result.configuration is not None
    assert result.configuration.text == "AUTO\nINPUTMODE = INPUTMODE | 9\nINPUTNEGTRIGGER = INPUTNEGTRIGGER | 9\n"


def test_channel_keywords_take_one_channel_in_dot_syntax() -> None:
    source = "ENCWRAP[0,1] = 100, 200\nx = ENCODER[1] + ENCODER.0 + FASTENC.2\nPRESCALE = 4;\n"
    assert rewritten("S-CHAN", source) == (
        "ENCODERWRAP.0 = 100 : ENCODERWRAP.1 = 200\n"
        "x = ENCODER.1 + ENCODER.0 + FASTENCODER.2\n"
        "ENCODERPRESCALE.0 = 4 : ENCODERPRESCALE.1 = 4 : ENCODERPRESCALE.2 = 4\n"
    )


@pytest.mark.parametrize(
    ("source", "reason"),
    [
        ("PRESCALE.1 = 3\n", "ENCODERPRESCALE takes a power of two from 1 to 128 only"),
        ("y = ENCODER\n", "ENCODER reads one channel: write ENCODER.<channel>"),
    ],
)
def test_channel_refusals(source: str, reason: str) -> None:
    assert flagged("S-CHAN", source) == [reason]


def test_echo_keeps_the_prompt_bit() -> None:
    assert rewritten("S-ECHO", "ECHO = 3\nECHO = a + 1\nPOFF : PON\n") == (
        "ECHO = 3 | (ECHO & 4)\nECHO = (a + 1) | (ECHO & 4)\nECHO = ECHO & 3 : ECHO = ECHO | 4\n"
    )
    assert rewritten("S-ECHO", "ECHO = 3 | (ECHO & 4)\n") == "ECHO = 3 | (ECHO & 4)\n"  # its own output


def test_error_input() -> None:
    assert rewritten("S-ERRORIN", "ERRORIN = 2\n") == "ERRORINPUT = -1;\n"
    assert flagged("S-ERRORIN", "ERRORIN = 1\n") == [
        "ERRORINPUT takes the error input's number (-1 none); set its level with INPUTACTIVELEVEL"
    ]
