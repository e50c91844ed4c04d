"""v3 CANCEL recovered from a motion error with the amplifiers on; v4 CANCEL leaves the drive off.

The v3 guide: a motion error shuts the system down, an abort on every axis, and "the only way to
recover without disconnecting power" is RESET or CANCEL (001:5005); the error handler may CANCEL the
move and RETURN to where the program stopped (001:5030), as its example does after a following error
(001:5048); an abort switches the enable output off (001:5591-5597, 7567). So after a v3 CANCEL the
amplifiers drive the axes again. The v4 guide: CANCEL clears the error but "does not re-enable the
drive" (000:4743-4744), leaves the drive enable outputs as they are (000:8016), a following error
disables the drive (000:10675-10677), and to clear errors keeping the position one uses "CANCEL
followed by DRIVEENABLE" (000:15628). So each v3 ``CANCEL[axes]`` becomes ``CANCEL[axes] :
DRIVEENABLE[axes] = 1;``, as SERVOC's does (S-SERVOC); enabling a drive that is on changes nothing.
"""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate
from mintlang.migrate.verification import Verdict, verify
from tests.migrate.helpers import migrated_twice, rewritten


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        pytest.param("CANCEL\n", "CANCEL : DRIVEENABLE = 1;\n", id="the default axes"),
        pytest.param("CANCEL[0,1]\n", "CANCEL[0,1] : DRIVEENABLE[0,1] = 1;\n", id="a list"),
        pytest.param("CANCEL.2 : REM again\n", "CANCEL.2 : DRIVEENABLE.2 = 1 : REM again\n", id="one axis"),
        pytest.param("CN.0\n", "CANCEL.0 : DRIVEENABLE.0 = 1\n", id="abbreviated"),
        pytest.param(
            "IF ERROR.0 = _maxfe THEN CANCEL : RETURN\n",  # 001:5048
            "IF ERROR.0 = _maxfe THEN CANCEL : DRIVEENABLE = 1; : RETURN\n",
            id="the guide's handler",
        ),
    ],
)
def test_cancel_enables_the_drive_after_it(source: str, expected: str) -> None:
    # after the RESET that enables the amplifiers at power-up (001:11409-11411): one before it gets nothing
    # (test_cancel_at_power_up_enables_no_drive)
    assert migrate(f"RESET\n{source}", only=["M-ABBR", "S-CANCEL"]).text == f"RESET\n{expected}"


def test_the_rewrite_settles() -> None:
    text, manual, again, manual_again = migrated_twice("S-CANCEL", "RESET\nCANCEL[0,1]\n")
    assert (manual, again, manual_again) == ((), text, ())


def test_dislimit_is_left_to_its_own_rule() -> None:
    # S-LIMIT writes DISLIMIT's CANCEL with the DRIVEENABLE already
    assert rewritten("S-CANCEL", "DISLIMIT.0\n") == "DISLIMIT.0\n"


# Axis 0 cannot move, so its first move passes MFOLERR = 50 counts: #ONERROR cancels and returns (001:5048),
# and the program goes on to a second move, which a v4 drive left disabled would refuse (error 40, 000:18659).
HANDLED = """REM @sim plant 0 stalled
RESET[0,1,2]
MFOLERR = 50;
MOVER.0 = 1000 : GO.0
PAUSE IDLE.0
MFOLERR = 10000;
MOVER.0 = 100 : GO.0
WAIT = 100
PRINT "moved on"
END
#ONERROR
  IF ERROR.0 = _maxfe THEN CANCEL : RETURN
  PRINT "Error ", ERR
END
"""


def test_the_program_goes_on_after_the_handler_as_in_v3() -> None:
    verification = verify(migrate(HANDLED), until_ms=300)
    assert verification.verdict is not Verdict.DIVERGES, verification.divergence
