"""``--verify`` on an application already in Mint v4 says so, rather than comparing it with itself.

A file recognised as Mint v4 is left as it was (``already v4``), so the "v3 original" the verification would
run is the v4 text read as Mint v3: it either stops on its first v4 form (HOMESPEED is no v3 keyword) or is
compared with itself and called equivalent, neither of which verifies a migration. There is no v3 original to
run: the application is incomplete, for that reason. A v3 program still verifies as before.
"""

from __future__ import annotations

import pytest

from mintlang.migrate import migrate
from mintlang.migrate.verification import Verdict, verify

ALREADY = "already Mint v4: there is no Mint v3 original to run (verify the v3 files before --write)"


@pytest.mark.parametrize(
    "program",
    [
        pytest.param("DIM a\nHOMESPEED.0 = 20\na = 1\nPRINT a\n", id="a v4 keyword"),
        pytest.param("DIM a\na = 1\nLOOP\n  a = a + 1\n  IF a > 3 THEN EXIT\nENDL\n", id="DIM and a v4 loop"),
    ],
)
def test_an_application_in_v4_has_no_v3_original(program: str) -> None:
    result = migrate(program)
    assert result.already_v4
    found = verify(result, until_ms=10)
    assert (found.verdict, found.short) == (Verdict.INCOMPLETE, ALREADY)


def test_a_v3_program_still_verifies() -> None:
    found = verify(migrate("a = 1\nPRINT a\n"), until_ms=10)
    assert (found.verdict, found.short) == (Verdict.EQUIVALENT, None)
