"""The semi-mechanical rules: the rewrite when the context is proven, a manual item when not."""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate
from tests.migrate.helpers import flagged, one_rule, rewritten


def test_contouring_is_card_wide_on_nextmove() -> None:
    assert rewritten("S-CONT", "CONTON\nCONTOFF : REM off\n") == (
        "CONTOURMODE[0,1,2] = 1;\nCONTOURMODE[0,1,2] = 0; : REM off\n"
    )
    assert flagged("S-CONT", "CONTON\n", controller="mintdrive") == ["CONTOURMODE is not available on MintDrive"]


def test_servo_off_and_on_become_torque_and_cancel() -> None:
    caveat = "REM MIGRATE: S-SERVOFF: TORQUE = 0 suits a current (torque) amplifier; a velocity drive needs"
    off = rewritten("S-SERVOFF", "SERVOFF[0,1]\nSERVOFF.1\n")
    assert [line for line in off.splitlines() if not line.startswith(caveat)] == ["TORQUE[0,1] = 0;", "TORQUE.1 = 0"]
    assert off.count(caveat) == 2
    # CANCEL leaves a drive the error disabled off (v4:4743): servo on again means the drive enabled
    assert rewritten("S-SERVOC", "SERVOC[0,1] : SERVOC\n") == (
        "CANCEL[0,1] : DRIVEENABLE[0,1] = 1; : CANCEL : DRIVEENABLE = 1;\n"
    )


def test_limits() -> None:
    assert rewritten("S-LIMIT", "DISLIMIT[0,1]\nENLIMIT.0\n") == (
        "LIMITMODE[0,1] = 0; : CANCEL[0,1] : DRIVEENABLE[0,1] = 1;\nLIMITMODE.0 = 1\n"
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
        "VEL written: v4 IDLEVEL takes the idle velocity in other units (v4 guide section 6.7)"
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


def test_ramp_is_scaled_to_sramp_and_the_shape_is_left_to_check() -> None:
    caveat = "REM MIGRATE: S-RAMP: SRAMP shapes the ramps differently from v3 RAMP: check the motion\n"
    assert rewritten("S-RAMP", "RAMP = 1;\nRAMP[0,1] = r, 2.5\n") == (
        f"{caveat}SRAMP = 10;\n{caveat}SRAMP[0,1] = r * 10, 25\n"
    )
    assert rewritten("S-RAMP", "RAMP = 0;\n") == "SRAMP = 0;\n"  # no smoothing in either version


_KEYPAD = (
    "REM MIGRATE: S-TERM: the v3 LCD is a CAN keypadNode in v4: give its node with KEYPADNODE._tmLCD1 = <node>"
    " (v4 guide section 3.9)\n"
)


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("TERM = 1\n", f"{_KEYPAD}TERMINAL = _tmLCD1\n"),
        ("TERM = _serial\n", "TERMINAL = _tmRS232\n"),
        ("TM = _both\n", f"{_KEYPAD}TERMINAL = _tmRS232 + _tmLCD1\n"),
    ],
)
def test_terminal_values_become_bits(source: str, expected: str) -> None:
    assert rewritten("S-TERM", source, controller="nextmove-bx") == expected  # an RS232 port and CAN keypads


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
        ("IF MODE = 18 THEN x = 1\n", "IF AXISMODE = _mdFOLLOW THEN x = 1\n"),  # the clutch is over
    ],
)
def test_mode_tests_become_bit_tests(source: str, expected: str) -> None:
    assert rewritten("S-MODE", source) == expected


@pytest.mark.parametrize("source", ["IF MODE > 2 THEN x = 1\n", "x = MODE\n", "IF MODE + 1 = 3 THEN x = 1\n"])
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


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        # a comparison used as a value is 1 or 0 in v3: the bare mask would be 32, 4 ...
        ("a = MODE.0 = _homing\n", "a = (AXISMODE.0 & _mdHOMING) <> 0\n"),
        ("PRINT ERROR.1 = _maxfe\n", "PRINT (AXISERROR.1 & _erFOLLOWING_ERROR) <> 0\n"),
        ("b = b + (MODE = _jog)\n", "b = b + ((AXISMODE & _mdJOG) <> 0)\n"),
        # AND is bitwise: (AXISMODE & 4) AND 1 is 0, so its operands get the 1-or-0 form too
        (
            "IF MODE = _jog AND ERROR = 0 THEN x = 1\n",
            "IF (AXISMODE & _mdJOG) <> 0 AND AXISERROR = 0 THEN x = 1\n",
        ),
        # OR and NOT only ask whether a value is zero: the bare mask stays in a condition
        (
            "WHILE MODE = _jog OR !(ERROR.1 = _maxfe)\n",
            "WHILE (AXISMODE & _mdJOG) OR !((AXISERROR.1 & _erFOLLOWING_ERROR))\n",
        ),
        ("REPEAT : UNTIL MODE.2 = _offset\n", "REPEAT : UNTIL (AXISMODE.2 & _mdOFFSET)\n"),
    ],
)
def test_a_test_used_as_a_value_keeps_the_v3_one_or_zero(source: str, expected: str) -> None:
    assert migrate(source, only=["S-MODE", "S-ERROR"]).text == expected


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        # M-CONST renames _idle (0) to _mdIDLE and _abort (1) to _erABORT before S-MODE/S-ERROR run
        ("PAUSE MODE = _idle\n", "PAUSE AXISMODE = 0\n"),
        ("IF MODE.1 <> _idle THEN x = 1\n", "IF AXISMODE.1 <> 0 THEN x = 1\n"),
        ("IF ERROR = _abort THEN x = 1\n", "IF (AXISERROR & _erABORT) THEN x = 1\n"),
        ("IF MODE = _linear THEN x = 1\n", "IF (AXISMODE & _mdLINEAR) THEN x = 1\n"),
    ],
)
def test_constants_renamed_first_are_still_tested(source: str, expected: str) -> None:
    result = migrate(source, only=["M-CONST", "S-MODE", "S-ERROR"])
    assert result.text == expected
    assert result.manual == ()


def test_error_13_has_no_bit() -> None:
    assert flagged("S-ERROR", "IF ERROR = 13 THEN x = 1\n") == [
        "v3 ERROR 13 (digital output fault, SmartMove only) has no AXISERROR bit: rewrite this test by hand"
    ]


def test_input_handlers_get_negative_edges() -> None:
    source = "LOOP : ENDL\n#IN0\nRETURN\n#IN3\nRETURN\n"
    text = rewritten("S-INEDGE", source)
    # inputs 1 and 2 have no handler and come before #IN3: masked off (000:5055-5057)
    prologue = "INPUTMODE = INPUTMODE | 9\nINPUTNEGTRIGGER = INPUTNEGTRIGGER | 9\nIMASK = IMASK & 0xFFFF9\n"
    assert "".join(line for line in text.splitlines(keepends=True) if "REM MIGRATE:" not in line) == (prologue + source)
    result = one_rule("S-INEDGE", source, config="AUTO\n")
    assert result.configuration is not None
    assert result.configuration.text == "AUTO\n" + prologue


PRIORITY = (
    "v3 ran #IN7 first and let handlers interrupt each other, v4 runs #IN0 first and one at a time"
    " (v3 guide section 5.3.2, v4 guide section 8.9): check what they share"
)


@pytest.mark.parametrize(
    ("source", "reasons"),
    [
        pytest.param("LOOP : ENDL\n#IN5\nRETURN\n", [], id="one handler: no order to keep"),
        # v3 serves simultaneous inputs from #IN7 down, one handler interruptible by another (v3:2549);
        # v4 from #IN0 up, one at a time (v4:5062-5064): a counter that input 1 resets ends otherwise
        pytest.param(
            "LOOP : ENDL\n#IN5\n  n = n + 1\nRETURN\n#IN1\n  n = 0\nRETURN\n",
            [f"#IN5, #IN1: {PRIORITY}"],
            id="two handlers: flagged once, at the first",
        ),
    ],
)
def test_several_input_handlers_are_flagged_for_their_reversed_priority(source: str, reasons: list[str]) -> None:
    result = one_rule("S-INEDGE", source)
    assert [(item.reason, item.original_line) for item in result.manual] == [(reason, 2) for reason in reasons]


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
        ("AXES[a]\ny = ENCODER\n", "ENCODER reads one channel: write ENCODER.<channel>"),
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


@pytest.mark.parametrize(
    ("controller", "source", "expected"),
    [
        ("nextmove-pci", "IMASK = 15\n", "IMASK = 15 | 0xFFF00\n"),
        ("nextmove-pc", "IM = 000001111\n", "IMASK = 000001111 | 0xFFFF00\n"),
        ("nextmove-bx", "IMASK = IMASK AND 011\n", "IMASK = IMASK AND (011 | 0xFF00)\n"),
        ("mintdrive", "IMASK = 255\n", "IMASK = 255 | 0x3FF00\n"),
        ("nextmove-pci", "IMASK = IMASK OR 4\n", "IMASK = IMASK OR 4\n"),
        ("nextmove-pci", "x = IMASK : PRINT IMASK & 3\n", "x = (IMASK & 255) : PRINT IMASK & 3\n"),
        ("servonode51", "IMASK = 15\n", "IMASK = 15\n"),
    ],
)
def test_input_mask_keeps_the_handlers_of_inputs_above_7_enabled(controller: str, source: str, expected: str) -> None:
    assert migrate(source, only=["M-ABBR", "S-IMASK"], controller=controller).text == expected


@pytest.mark.parametrize("source", ["IMASK = a\n", "IMASK = 256\n", "IMASK = IMASK AND b\n", "IMASK = IMASK + 1\n"])
def test_input_mask_computed_or_out_of_range_is_flagged(source: str) -> None:
    assert flagged("S-IMASK", source) == [
        "v4 IMASK has a bit per input (default 0xFFFFF): keep the bits of inputs 8 and up set"
    ]


def test_input_byte_is_masked_to_the_v3_inputs() -> None:
    source = "JOG = IN\nBINARY IN\nIF IN & 15 THEN x = 1\nPAUSE IN AND 12\ny = IN3 + IN.2\n"
    assert rewritten("S-IN", source) == (
        "JOG = (IN & 255)\nBINARY (IN & 255)\nIF IN & 15 THEN x = 1\nPAUSE IN AND 12\ny = IN3 + IN.2\n"
    )
    assert rewritten("S-IN", "a = IN & 511\n") == "a = (IN & 255) & 511\n"
    assert rewritten("S-IN", "JOG = IN\n", controller="servonode51") == "JOG = IN\n"


def test_input_byte_with_input_handlers_reads_the_input_states() -> None:
    assert rewritten("S-IN", "JOG = IN\n#IN1\nRETURN\n") == "JOG = (INSTATE & 255)\n#IN1\nRETURN\n"


def test_binary_becomes_print_bin_before_each_number() -> None:
    result = one_rule("S-BINARY", 'BINARY "12 in binary is : ",12\nBINARY a, " ", b\n')
    assert result.text == (
        "REM MIGRATE: S-BINARY: v4 PRINT BIN has no 8-digit zero padding (v3 00001100, v4 1100) and prints"
        " a negative in 24 bits; v3 printed 8 bits at most and dropped fractions\n"
        'PRINT "12 in binary is : ",BIN 12\n'
        "REM MIGRATE: S-BINARY: v4 PRINT BIN has no 8-digit zero padding (v3 00001100, v4 1100) and prints"
        " a negative in 24 bits; v3 printed 8 bits at most and dropped fractions\n"
        'PRINT BIN a, " ", BIN b\n'
    )
    assert migrate("binary in\n", only=["S-IN", "S-BINARY"]).text.endswith("print bin (in & 255)\n")


def test_binary_output_migrates_once() -> None:
    """BIN is a v4 word the v3 reader takes for a name: it must not be renamed on a second run."""
    first = migrate('BINARY "x", IN\n').text
    assert migrate(first).text == first


def test_baud_9600_is_the_rate_every_serial_controller_has() -> None:
    assert rewritten("S-BAUD", "BAUD = 9600\n", controller="mintdrive") == "SERIALBAUD._tmRS232 = 9600\n"
    assert flagged("S-BAUD", "BAUD = 1200 : REM slow\n", controller="nextmove-bx") == [
        "use SERIALBAUD._tmRS232 = <rate> with a rate the v4 guide section 10.3 SERIALBAUD table lists"
    ]
    assert flagged("S-BAUD", "BAUD = b\n", controller="servonode51") == [
        "use SERIALBAUD._tmRS232 = <rate> with a rate the v4 guide section 10.3 SERIALBAUD table lists"
    ]
    assert flagged("S-BAUD", "BAUD = 9600\n") == [
        "NextMove PCI has no serial port (SERIALBAUD is not on it): remove the BAUD; "
        "its host terminal is the dual port RAM, _tmDPR (v4 guide section 10.3 TERMINAL)"
    ]


def test_dac_counts_become_percent_one_channel_per_write() -> None:
    source = "AXES[0,1]\nDAC = 1024, a + b\nDAC[2] = -5;\nx = DAC[1]\n"
    assert rewritten("S-DAC", source) == (
        "AXES[0,1]\nDAC.0 = 1024 * 100 / 2047 : DAC.1 = (a + b) * 100 / 2047\n"
        "DAC.2 = (-5) * 100 / 2047\nx = (DAC.1 * 2047 / 100)\n"
    )
    assert rewritten("S-DAC", "AUXDAC = 3\n", controller="mintdrive") == "AUXDAC.0 = 3 * 100 / 2047\n"


def test_dac_on_a_stepper_application_is_rewritten_and_flagged() -> None:
    result = one_rule("S-DAC", "CONFIG.0 = _stepper\nDAC.0 = 4\n")
    assert result.text == (
        "CONFIG.0 = _stepper\n"
        "REM MIGRATE: S-DAC: v4 writes DAC only on an axis with CONFIG = _cfOFF (v3 also allowed a stepper axis)\n"
        "DAC.0 = 4 * 100 / 2047\n"
    )


@pytest.mark.parametrize(
    ("source", "reason"),
    [
        ("DAC.0 = DAC.0 + 1\n", "DAC value reads an analog output: convert by hand"),
        ("AXES[a]\nDAC = 4\n", "DAC: the axes are not constant; DAC.n = v * 100 / 2047"),
        ("x = DAC\n", "DAC: read one constant channel as DAC.n (v4 % of 10 V)"),
        ("? DEMAND.1\n", "DEMAND: read DAC.n (v4 % of +-10 V, as DEMAND was %)"),
    ],
)
def test_dac_refusals(source: str, reason: str) -> None:
    assert flagged("S-DAC", source) == [reason]


def test_dac_on_a_controller_without_it_is_left_to_the_platform_rule() -> None:
    result = migrate("AUXDAC = 3\n", only=["S-DAC", "X-PLATFORM"])
    assert [item.rule for item in result.manual] == ["X-PLATFORM"]


def test_reset_that_nothing_relies_on_is_left_alone() -> None:
    assert migrate("RESET[0,1]\nMOVEA = 10 : GO\n", only=["S-RESET"]).manual == ()
    startup = migrate("OUT0 = 1\nx = TIME\n", config="AUTO\nRESET\n", only=["S-RESET"])
    assert startup.manual == () and startup.configuration is not None and startup.configuration.manual == ()


@pytest.mark.parametrize(
    ("source", "reason"),
    [
        ("OUT0 = 1\nRESET\n", "v3 RESET also did OUT = 0; v4 RESET does not: add what later code relies on"),
        (
            "RESET[0,1]\nx = TIME : IMASK = 3\n",
            "v3 RESET also did TIME = 0 : IMASK = <all ones>; v4 RESET does not: add what later code relies on",
        ),
    ],
)
def test_reset_in_a_program_using_what_v3_cleared_is_flagged(source: str, reason: str) -> None:
    assert flagged("S-RESET", source) == [reason]


def test_reset_in_the_configuration_after_an_output_write_is_flagged() -> None:
    result = migrate("x = 1\n", config="AUTO\nOUT = 3\nRESET\n", only=["S-RESET"])
    assert result.configuration is not None
    assert [item.reason for item in result.configuration.manual] == [
        "v3 RESET also did OUT = 0; v4 RESET does not: add what later code relies on"
    ]


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("FOLLOWAXIS[0] = 2\n", "MASTERSOURCE[0] = _msPOS; : MASTERCHANNEL[0] = 2\n"),
        ("AXES[0,1]\nFOLLOWAXIS = 2,2\n", "AXES[0,1]\nMASTERSOURCE = _msPOS; : MASTERCHANNEL = 2,2\n"),
        ("followaxis.1 = 0 : REM master\n", "mastersource.1 = _msPOS : masterchannel.1 = 0 : REM master\n"),
        ("FOLLOWAXIS[0,1] = -1,-1\n", "MASTERSOURCE[0,1] = _msSPEED;\n"),
        ("SCALE = 1,1\nFOLLOWAXIS.0 = 1\n", "SCALE = 1,1\nMASTERSOURCE.0 = _msPOS : MASTERCHANNEL.0 = 1\n"),
    ],
)
def test_followaxis_becomes_master_source_and_channel(source: str, expected: str) -> None:
    assert rewritten("S-MASTER", source) == expected


@pytest.mark.parametrize(
    ("source", "reason", "controller"),
    [
        ("FOLLOWAXIS = -2\n", "FOLLOWAXIS = -2 follows the pulse timer input: no v4 master source (see X-PULSE)", ""),
        (
            "FOLLOWAXIS = 4\n",
            "encoder-board master: MASTERSOURCE = _msAUXENCODER : MASTERCHANNEL = m - 3, if so wired",
            "",
        ),
        (
            "FOLLOWAXIS = 2, -1\n",
            "FOLLOWAXIS values are not all constant axes 0..2 (or all -1): set MASTERSOURCE by hand",
            "",
        ),
        (
            "SCALE = 400\nFOLLOWAXIS = 1\n",
            "SCALE is set: v4 scales the master into the slave's user units, v3 by the master's SCALE",
            "",
        ),
        (
            "CONFIG.1 = _off\nFOLLOWAXIS = 1\n",
            "an axis is configured off: if it is the master, write MASTERSOURCE = _msENCODER : MASTERCHANNEL = 1 "
            "(in this order: MASTERSOURCE resets MASTERCHANNEL)",
            "",
        ),
        ("FOLLOWAXIS = 1\n", "MintDrive cannot follow an axis position (MASTERSOURCE 2 or 3 only)", "mintdrive"),
    ],
)
def test_followaxis_refusals(source: str, reason: str, controller: str) -> None:
    assert flagged("S-MASTER", source, controller=controller or "nextmove-pci") == [reason]


def test_followaxis_speed_on_mintdrive() -> None:
    assert rewritten("S-MASTER", "FOLLOWAXIS = -1\n", controller="mintdrive") == "MASTERSOURCE = _msSPEED\n"


@pytest.mark.parametrize("controller", ["nextmove-pci", "nextmove-bx", "mintdrive"])
def test_input_terminal_dac_master_and_reset_rewrites_migrate_once(controller: str) -> None:
    source = (
        "IMASK = 000001111 : IMASK = IMASK AND 3 : x = IMASK\nJOG = IN\nBINARY IN\nDAC[0] = 1024\n"
        "y = DAC[1]\nAUXDAC = 5\nBAUD = 9600\nFOLLOWAXIS[0] = 1\nFOLLOWAXIS.1 = -1\nOUT0 = 1\nRESET\n"
    )
    first = migrate(source, controller=controller).text
    assert migrate(first, controller=controller).text == first


def test_a_current_limit_of_zero_is_rewritten_and_reported() -> None:
    # v3 CURRLIMIT ranges 1..100 (v3:7073); v4 DACLIMITMAX = 0 is legal and holds the output at 0 V (v4:8815)
    assert rewritten("S-CURR", "CURRLIMIT[2] = 0\n") == (
        "REM MIGRATE: S-CURR: CURRLIMIT below v3's 1..100: the v4 limit 0 holds the output at 0 V\nDACLIMITMAX.2 = 0\n"
    )


def test_axis_0_following_without_followaxis_gets_v3s_default_master() -> None:
    # v3: axis 0 followed axis 1 by default (v3:8199); v4's default master is channel 0, itself (v4:9048-9050)
    text = rewritten("S-MASTER-DEFAULT", "AXES[0]\nFLY = 1.5 : GO\n")
    assert text == "MASTERSOURCE.0 = _msPOS : MASTERCHANNEL.0 = 1\nAXES[0]\nFLY = 1.5 : GO\n"
    assert rewritten("S-MASTER-DEFAULT", "FOLLOWAXIS.0 = 2\nFOLLOW.0 = 1\n") == "FOLLOWAXIS.0 = 2\nFOLLOW.0 = 1\n"
    assert rewritten("S-MASTER-DEFAULT", "FOLLOW.1 = 2\n") == "FOLLOW.1 = 2\n"  # v4's channel 0 is v3's default


def test_axis_0_following_on_a_controller_without_axis_masters_is_left_to_the_user() -> None:
    # MintDrive takes MASTERSOURCE 2 or 3 (aux encoder, virtual axis) and MASTERCHANNEL 0 only
    # (v4:13800-13804, v4:13918-13923): _msPOS and channel 1 would be errors, so the first
    # following statement gets the choice instead of an invalid line
    reasons = flagged("S-MASTER-DEFAULT", "GEARD.0 = 10\nGEARN.0 = 2\n", controller="mintdrive")
    expected = "v3 axis 0 followed axis 1; this controller takes only MASTERSOURCE 2, 3 and MASTERCHANNEL 0"
    assert reasons == [f"{expected}: choose the master"]
    result = one_rule("S-MASTER-DEFAULT", "GEARD.0 = 10\nGEARN.0 = 2\n", controller="mintdrive")
    assert [item.original_line for item in result.manual] == [2]  # GEARN, v3's FOLLOW


def test_an_axis_above_1_following_without_followaxis_is_left_to_the_user() -> None:
    assert flagged("S-MASTER-DEFAULT", "FOLLOW.2 = 1\n") == ["axis 2 follows with no FOLLOWAXIS: choose its master"]


def test_pause_until_pulse_following_after_an_offset_waits_for_the_offset_to_end() -> None:
    # v3:4274-4278: the axis is back in pulse following when the offset is done; v4:14809
    source = "OFFSET = 100 : GO\nPAUSE MODE = _pulse\n"
    assert rewritten("S-MODE", source) == "OFFSET = 100 : GO\nPAUSE !(AXISMODE & _mdOFFSET)\n"


def test_a_follow_with_a_master_increment_gets_the_clutch_mode_v3_ramped_with() -> None:
    # v3 FOLLOW ramped over MASTERINC (v3:3716-3730); v4 only in FOLLOWMODE 2 (v4:3529-3535)
    source = "MASTERINC.0 = 100\nFOLLOW.0 = 1\n"
    assert rewritten("S-CLUTCH", source) == "MASTERINC.0 = 100\nFOLLOWMODE.0 = _fmCLUTCH : FOLLOW.0 = 1\n"
    assert rewritten("S-CLUTCH", "FOLLOW.0 = 1\n") == "FOLLOW.0 = 1\n"  # no master increment: no clutch
    assert flagged("S-CLUTCH", "MASTERINC.0 = 1\nFOLLOW.0 = 1\n") == [
        "a MASTERINC here may be 1 (v3: no clutch): choose FOLLOWMODE by hand"
    ]
