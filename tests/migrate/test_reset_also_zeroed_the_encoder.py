"""S-RESET: v3 RESET also zeroed ENCODER; v4 RESET zeroes POS only.

RESET's table in the v3 guide lists "ENCODER 0" beside POS, OUT and TIME (001:11427-11446). In v4
RESET clears the errors and zeroes the axis position (000:15624-15629), and ENCODER, independent of
POS, "can only be manually zeroed or changed" (000:9615-9623). A program that resets an axis and
then measures with ENCODER read from 0 in v3 and reads on from where it was in v4: the RESET is
flagged with what v3 did, as it is for OUT, TIME and IMASK.
"""

from __future__ import annotations

from mintlang.migrate import migrate
from tests.migrate.helpers import flagged


def test_a_reset_in_a_program_reading_encoder_is_flagged() -> None:
    assert flagged("S-RESET", "RESET[0,1]\nx = ENCODER.0\n") == [
        "v3 RESET also did ENCODER.<channel> = 0; v4 RESET does not: add what later code relies on"
    ]


def test_a_configuration_reset_before_any_encoder_use_is_left_alone() -> None:
    result = migrate("x = ENCODER.0\n", config="RESET[0,1]\n", only=["S-RESET"])
    assert result.manual == () and result.configuration is not None and result.configuration.manual == ()
