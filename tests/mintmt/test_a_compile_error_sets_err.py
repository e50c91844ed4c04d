"""A program the controller's compiler rejects sets ``ERR`` and ``ERL`` in MintMT as in v4.

MintMT is Mint v4 where the notes show nothing else (MINTMT.md, MT-1), and they say nothing of errors.
In v4 an error found while the program compiles stops it before it runs (000:4563-4568), printed as a
compile-time error (000:4584-4588), and ``ERR`` and ``ERL`` hold its number and line
(runtime/BEHAVIOUR.md, EV-14). mint-run printed the MintMT error but left ``ERR`` at -1 and ``ERL`` at 0,
as only v3 (whose ``ERR`` holds what ``#ONERROR`` can see, 001:4916) should."""

from __future__ import annotations

import pytest

from mintlang.runtime.run import run_source
from mintlang.runtime.simulation import Limits


@pytest.mark.parametrize(
    ("source", "err", "erl"),
    [
        pytest.param('PRINT "before"\nPRINT (\n', 2003.0, 2.0, id="syntax"),
        pytest.param("Dim a\na = b\n", 3001.0, 2.0, id="undeclared-variable"),
        pytest.param("Loop\n  PRINT 1\n", 2014.0, 1.0, id="loop-never-closed"),
    ],
)
def test_err_and_erl_hold_the_compile_error(source: str, err: float, erl: float) -> None:
    result = run_source(source, dialect="mintmt", config="RESETALL\n", limits=Limits(until_ms=1000))
    assert result.refused
    assert (result.err, result.erl) == (err, erl)
