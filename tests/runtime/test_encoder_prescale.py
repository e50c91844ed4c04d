"""``ENCODERPRESCALE`` divides the encoder's counts the controller sees, for ``POS`` and ``ENCODER`` alike.

The guide: it scales the encoder input down by its value, 1, 2, 4 … 128 (1 at power-up, after DEFAULT too),
so a 4000-count encoder at 2 is seen as 2000 counts a turn, and both POS and ENCODER read those counts
(000:9022, 9658-9699). A divider in front of the counter changes the rate it counts at, not what it has
counted. An ideal plant's encoder reads the demand, which is in the counts the controller sees; a velocity
amplifier turns the motor at so many of the encoder's own counts a second per % of DAC.
"""

from __future__ import annotations

from tests.runtime.running import simulate


def test_the_guide_example_sets_axis_1_and_every_other_axis_reads_1() -> None:
    # 000:9697-9699: ENCODERPRESCALE.1 = 4; the default is 1 (000:9022)
    assert simulate('ENCODERPRESCALE.1 = 4\nPRINT ENCODERPRESCALE.1, " ", ENCODERPRESCALE.0\n').terminal == "4 1\n"


def test_a_divider_other_than_a_power_of_two_up_to_128_is_error_3() -> None:
    # the range: 1, 2, 4, 8, 16, 32, 64, 128 (000:9680-9681)
    handler = 'END\n#ONERROR\nPRINT ERR, " ", ERRAXIS\nRETURN\n'
    assert simulate("ENCODERPRESCALE.0 = 3\n" + handler).terminal == "3 0\n"
    assert simulate("ENCODERPRESCALE.0 = 256\n" + handler).terminal == "3 0\n"


def test_the_counts_seen_go_on_from_what_was_counted_at_the_new_rate() -> None:
    # open loop (TORQUE), 10 % of DAC on a velamp of 100 counts/s per %: 1000 of the encoder's counts a second.
    # 500 ms undivided: 500 counts; then divided by 2: 500 counts/s, 250 more in 500 ms, and VEL reads 500
    source = (
        "REM @sim plant 0 velamp 100\nTORQUE.0 = 10\nWAIT = 500\n"
        'PRINT ENCODER.0, " ", POS.0\nENCODERPRESCALE.0 = 2\nWAIT = 500\n'
        'PRINT ENCODER.0, " ", POS.0, " ", VEL.0, " ", ENCODERVEL.0\n'
    )
    assert simulate(source).terminal == "500 500\n750 750 500 500\n"


def test_default_sets_the_divider_back_to_1() -> None:
    # DEFAULT's table: ENCODERPRESCALE 1 (000:9022)
    assert simulate("ENCODERPRESCALE.0 = 8\nDEFAULT.0\nPRINT ENCODERPRESCALE.0\n").terminal == "1\n"


def test_a_move_on_the_ideal_plant_ends_on_its_target_in_the_counts_seen() -> None:
    source = 'ENCODERPRESCALE.0 = 4\nMOVER.0 = 1000 : GO.0\nPAUSE IDLE.0\nPRINT POS.0, " ", ENCODER.0\n'
    assert simulate(source).terminal == "1000 1000\n"
