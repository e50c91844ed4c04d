"""A v3 analog input read a whole count, so the migrated formula takes the whole part of the v4 percentage.

The v3 guide: ANALOGUE1..3 convert with 10 bits and read 0 to 1023 (001:5748-5760), one part in 1024
with 0 V at 512 (001:4368-4376, 5768). v4 ADC reads a percentage of the range, -100 to 100
(000:6358-6363), which S-ANALOG turns back into counts with (ADC + 100) * 1024 / 200. A percentage
between two counts gave a count with a fraction, which v3 never read: at 0.1 % of +-10 V the v3
input reads 512 (100.1 * 1024 / 200 = 512.512, whole part 512), and the program's ``A1 = 512`` held
in v3 but not after migration. v4's INT takes the whole part (000:12544-12565), here of a value that
is never below 0 (ADC reads from -100), so it is no INT of a sign whose rounding changed (X-NUM).
"""

from __future__ import annotations

from mintlang.migrate import migrate
from mintlang.migrate.verification import Verdict, verify
from mintlang.runtime.scenario import AdcLevel, Scenario
from tests.migrate.helpers import rewritten


def test_the_count_is_the_whole_part() -> None:
    assert rewritten("S-ANALOG", "x = A1\n").splitlines()[-1] == "x = INT((ADC.0 + 100) * 1024 / 200) - (ADC.0 >= 100)"


def test_the_joystick_keeps_its_subtraction() -> None:  # 001:4375
    migrated = rewritten("S-ANALOG", "JOG = A1 - 512\n").splitlines()[-1]
    assert migrated == "JOG = (INT((ADC.0 + 100) * 1024 / 200) - (ADC.0 >= 100)) - 512"


def test_the_whole_part_is_no_int_of_a_sign() -> None:
    assert [item.rule for item in migrate("x = A1 - 512\n").manual] == ["S-ANALOG"]


def test_a_comparison_with_a_count_holds_as_in_v3() -> None:
    # 0.1 % reads 512 (512.512 -> 512) and 50.1 % reads 768 (150.1 * 1024 / 200 = 768.512 -> 768)
    program = 'WAIT = 2\nIF A1 = 512 THEN PRINT "centre"\nIF A2 = 768 THEN PRINT "three quarters"\n'
    levels = Scenario(adc=(AdcLevel(time_ms=0, channel=0, percent=0.1), AdcLevel(time_ms=0, channel=1, percent=50.1)))
    found = verify(migrate(program), scenario=levels, until_ms=100)
    assert found.verdict is Verdict.EQUIVALENT, found.divergence


def test_the_full_scale_reads_the_top_count_as_in_v3() -> None:
    # 10 bits read 0 to 1023 (001:5748-5750): at +10 V (ADC 100 %, 000:6358) v3 reads 1023, where 200 * 1024 / 200
    # is 1024, a count v3 never read
    program = 'WAIT = 2\nIF A1 = 1023 THEN PRINT "full scale"\nPRINT A1 - 512\n'
    levels = Scenario(adc=(AdcLevel(time_ms=0, channel=0, percent=100.0),))
    found = verify(migrate(program), scenario=levels, until_ms=100)
    assert found.verdict is Verdict.EQUIVALENT, found.divergence
