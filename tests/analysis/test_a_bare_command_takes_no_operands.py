"""A command whose format is its name alone is error 2003 when operands follow it.

BEEP (000:7386-7387), BOL (000:7410-7411), CLS, which takes only a terminal after '#'
(000:8263-8264), TRON (000:16921-16922), TROFF (000:16903-16904), VER (000:17163-17164) and AUTO
(000:6642-6643) print no attribute table, only that format: ``BEEP 3`` or ``CLS 2`` does not match
the statement's syntax (#2003, 000:18920), as ``ABORT 1`` does not. They passed mint check. A
command that takes axes is told so; one that takes none, such as ABORT (000:6067-6068), is not.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.placed import placed


@pytest.mark.parametrize(
    ("source", "controller"),
    [
        pytest.param("BEEP 3\n", "nextmove-pci", id="BEEP"),
        pytest.param("BOL 1\n", "nextmove-pci", id="BOL"),
        pytest.param("CLS 2\n", "nextmove-pci", id="CLS-without-its-hash"),
        pytest.param("TRON 1\n", "nextmove-pci", id="TRON"),
        pytest.param("TROFF 0\n", "nextmove-pci", id="TROFF"),
        pytest.param("VER 4\n", "nextmove-bx", id="VER"),
        pytest.param("AUTO 1\n", "nextmove-bx", id="AUTO"),
    ],
)
def test_operands_after_a_bare_command_are_error_2003(source: str, controller: str) -> None:
    # AUTO in a program is also the warning that it is ignored there (W114); the error is the one asked about
    assert placed(source, "code", "line", "column", codes="E", controller=controller) == [("E2003", 1, 1)]


@pytest.mark.parametrize(
    "source",
    [
        pytest.param("BEEP\n", id="BEEP"),
        pytest.param("CLS #3\n", id="CLS-on-a-terminal"),
        pytest.param('LOOP\nBOL:PRINT "Axis 0 position : ", POS.0,\nENDL\n', id="BOL-before-a-colon"),
        pytest.param("TRON\nTROFF\nVER\n", id="TRON-TROFF-VER"),
    ],
)
def test_the_bare_commands_of_the_manual_pass(source: str) -> None:
    assert mintlang.check(source) == []


def test_words_after_a_bare_command_are_its_one_error() -> None:
    # a comment whose REM is missing is the command's error 2003, not an undeclared variable as well
    assert placed("BEEP when done\n", "code") == [("E2003",)]


@pytest.mark.parametrize(
    ("source", "said"),
    [
        pytest.param("BEEP 3\n", "BEEP takes no operands", id="BEEP"),
        pytest.param("ABORT 1\n", "ABORT takes no operands", id="ABORT"),
        pytest.param("STOP 1\n", "STOP takes no operands, only its axes ('STOP[axes]')", id="STOP"),
    ],
)
def test_the_message_mentions_axes_only_for_a_command_that_takes_them(source: str, said: str) -> None:
    (diagnostic,) = mintlang.check(source)
    assert said in diagnostic.message
    assert ("axes" in diagnostic.message) == ("[axes]" in said)
