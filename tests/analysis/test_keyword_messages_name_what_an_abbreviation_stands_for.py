"""A message that refuses a keyword as a name says which keyword an abbreviation stands for.

A user who writes ``DIM spd`` means a speed, and has no reason to know that SPD abbreviates a
keyword (DIM of a keyword is a syntax error, 000:9189-9192; a macro's name must not be one either).
The guide gives SPD to two keywords: SPLINESUSPENDTIME on NextMove (000:16289) and SPEEDDEMAND on
MintDrive and ServoNode (000:16233), so the keyword named is the controller's. PS is POS (000:15088).
"""

from __future__ import annotations

import pytest

import mintlang


def _message(text: str, controller: str = "nextmove-pci") -> tuple[str, str]:
    (diagnostic,) = [d for d in mintlang.check(text, controller=controller) if d.code.startswith("E")]
    return diagnostic.code, diagnostic.message


@pytest.mark.parametrize(
    ("controller", "keyword"), [("nextmove-pci", "SPLINESUSPENDTIME"), ("mintdrive", "SPEEDDEMAND")]
)
def test_dim_of_an_abbreviation_names_the_controllers_keyword(controller: str, keyword: str) -> None:
    code, message = _message("DIM spd\n", controller)
    assert code == "E2003"
    assert f"'spd' (short for {keyword}) is a keyword" in message


@pytest.mark.parametrize("name", ["pos", "IN3"])  # IN3: input 3, IN with its channel glued on
def test_dim_of_a_keyword_written_whole_names_it_once(name: str) -> None:
    code, message = _message(f"DIM {name}\n")
    assert code == "E2003"
    assert f"'{name}' is a keyword" in message
    assert "short for" not in message


def test_a_macro_named_by_an_abbreviation_names_the_keyword() -> None:
    code, message = _message("DEFINE ps = 1\n")
    assert code == "E3005"
    assert "'ps' (short for POS) is a keyword and cannot name a macro" in message


def test_a_macro_named_by_a_number_is_not_called_a_keyword() -> None:
    code, message = _message("DEFINE 100 = 3\n")
    assert code == "E3005"
    assert "keyword" not in message


def test_an_abbreviated_keyword_with_its_channel_glued_on_names_the_channel_form() -> None:
    # OUT is abbreviated OT (000:14879) and OUTx is a form of OUT (000:14896)
    code, message = _message("DIM OT2\n")
    assert code == "E2003"
    assert "'OT2' (short for OUT2) is a keyword" in message
