"""Digital and analog I/O, TIME, and how keywords address axes and channels (spec §8, NM-10, T-7)."""

from __future__ import annotations

from tests.runtime.running import simulate


def test_reading_an_edge_triggered_input_returns_its_latched_edge_once() -> None:
    # IO-1: the latched edge is returned and reading clears it; INSTATE shows the level and clears nothing
    source = """REM @sim input 2 1 at 10
REM @sim input 2 0 at 20
INPUTMODE = 4
INPUTPOSTRIGGER = 4
WAIT = 50
PRINT IN.2, INSTATE.2, IN.2
"""
    assert simulate(source).terminal == "100\n"


def test_a_trigger_bit_of_an_input_not_edge_triggered_is_not_set() -> None:
    # 000:12424-12425: setting it "will have no effect": the bits of inputs 0 and 1 read back 0 and INPUTMODE
    # set later does not arm them, so the falling edge at 20 ms is not latched; INPUTMODE = 0x00F00F keeps
    # inputs 0-3 and 12-15
    source = """REM @sim input 0 1 at 10
REM @sim input 0 0 at 20
INPUTNEGTRIGGER = 3
PRINT INPUTNEGTRIGGER
INPUTMODE = 1
WAIT = 50
PRINT IN.0
INPUTMODE = 0x00F00F
INPUTNEGTRIGGER = 0xFFFF
INPUTPOSTRIGGER = 0x5FFA
PRINT INPUTNEGTRIGGER, " ", INPUTPOSTRIGGER
"""
    assert simulate(source).terminal == "0\n0\n61455 20490\n"


def test_a_level_input_reads_active_while_its_level_is_and_active_low_inverts_it() -> None:
    source = """REM @sim input 1 1 at 10
WAIT = 20
PRINT IN.1, IN1, IN
INPUTACTIVELEVEL = 0
WAIT = 2
PRINT IN.1, IN.0
"""
    assert simulate(source).terminal == "112\n01\n"


def test_outputs_are_recorded_bit_by_bit_and_out_of_range_is_error_3() -> None:
    result = simulate("OUT = 5\nOUT.1 = 1\nOUT.0 = 0\nRELAY = 1\nPRINT OUT\n")
    assert (result.terminal, result.outputs, result.relay) == ("6\n", 6, 1)
    assert simulate("DIM a = 256\nOUT = a\n").err == 3  # NextMove BX has eight outputs (IO-3)
    # a constant out of range is still a run-time error, as the manual prints SCALE = -3's (000:4600-4606)
    assert simulate("OUT = 256\n").stop.message.startswith("R0003")


def test_adc_values_come_from_the_scenario_in_percent() -> None:
    assert simulate("REM @sim adc 2 42.5 at 5\nWAIT = 10\nPRINT ADC.2\n").terminal == "42.5\n"


def test_writing_time_sets_its_origin() -> None:
    assert simulate("WAIT = 100\nTIME = 1000\nWAIT = 50\nPRINT TIME\n").terminal == "1050\n"


def test_a_skipped_place_leaves_its_axis_and_a_semicolon_fills_the_rest() -> None:
    # NM-10: SPEED = ,10 sets only the second default axis; SPEED[0,1,2] = 10,20; sets 10, 20, 20
    source = 'AXES[0,1,2]\nSPEED = ,10\nPRINT SPEED.0, " ", SPEED.1\nSPEED[0,1,2] = 10,20;\nPRINT SPEED.2\n'
    assert simulate(source).terminal == "20000 10\n20\n"


def test_a_keyword_without_axes_reads_the_first_default_axis_and_a_list_ands_them() -> None:
    # v4 guide 3.1.1: PAUSE IDLE with AXES[0,1] waits for axis 0 only; IDLE[0,1] is both
    source = """AXES[1,0]
JOG.0 = 100
PRINT IDLE, " ", IDLE[0,1], " ", IDLE.1
"""
    assert simulate(source).terminal == "1 0 1\n"


def test_imask_starts_with_every_input_of_the_controller() -> None:
    # EV-7: by default every input may call its handler, e.g. 65535 on a NextMove BX
    assert simulate("PRINT IMASK\n").terminal == "65535\n"
