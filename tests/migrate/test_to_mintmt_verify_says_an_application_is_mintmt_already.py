"""``--verify --to mintmt`` on files already in MintMT says so, rather than that "the v4 original does not compile".

Run after ``--write``, the verification used to read the MintMT text as the Mint v4 original and report
the first MintMT form it met as the original's compile error (a ``'`` comment: "a character constant is
one character in single quotes"), an error in a file the user never wrote in v4. There is no v4 original
to run: the application is incomplete, for that reason. A v4 application still verifies as before.
"""

from __future__ import annotations

import pytest

from mintlang.migrate.mintmt import to_mintmt
from mintlang.migrate.mintmt.verification import verify
from mintlang.migrate.verification import Verdict

ALREADY = "already MintMT: there is no Mint v4 original to run (verify the v4 files before --write)"


@pytest.mark.parametrize(
    ("program", "config"),
    [
        pytest.param("' counts\nDIM a\na = a + 1\n", None, id="program"),
        pytest.param("DIM a\na = a + 1\n", "' set-up\nSPEED(0) = 10\n", id="configuration"),
    ],
)
def test_an_application_with_a_file_in_mintmt_has_no_v4_original(program: str, config: str | None) -> None:
    found = verify(to_mintmt(program, config=config), until_ms=10)
    assert (found.verdict, found.short) == (Verdict.INCOMPLETE, ALREADY)


def test_a_v4_application_still_verifies() -> None:
    found = verify(to_mintmt("REM counts\nDIM a\na = a + 1\n"), until_ms=10)
    assert (found.verdict, found.short) == (Verdict.EQUIVALENT, None)
