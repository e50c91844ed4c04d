"""The pairing rule every tool shares: ``<name>.mnt`` runs after the configuration file the pattern names beside it,
names compared without regard to case."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from mintlang.pairing import Pairing, listed_as, names_in, partner_on_disk
from mintlang.semantic.units import Unit

DEFAULT = Pairing("", ".cfg")


@pytest.mark.parametrize(
    ("name", "expected"),
    [
        ("conveyor.mnt", (Unit.PROGRAM, "conveyor.cfg")),
        ("CONVEYOR.MNT", (Unit.PROGRAM, "CONVEYOR.cfg")),
        ("conveyor.cfg", (Unit.CONFIGURATION, "conveyor.mnt")),
        ("CONVEYOR.CFG", (Unit.CONFIGURATION, "CONVEYOR.mnt")),
        (".cfg", (Unit.PROGRAM, None)),  # no name before the suffix: no program's
        ("notes.txt", (Unit.PROGRAM, None)),
    ],
)
def test_the_default_pattern(name: str, expected: tuple[Unit, str | None]) -> None:
    assert DEFAULT.partner_name(name) == expected


def test_a_pattern_with_a_prefix_compares_the_prefix_with_its_case_and_the_suffix_without() -> None:
    pairing = Pairing.from_pattern("setup_<name>.txt")
    assert pairing == Pairing("setup_", ".txt")
    assert pairing.partner_name("press.mnt") == (Unit.PROGRAM, "setup_press.txt")
    assert pairing.partner_name("setup_press.TXT") == (Unit.CONFIGURATION, "press.mnt")
    assert pairing.partner_name("SETUP_press.txt") == (Unit.PROGRAM, None)


def test_a_pattern_without_name_turns_pairing_off_and_one_with_a_folder_is_refused() -> None:
    assert Pairing.from_pattern("") is None
    assert Pairing.from_pattern("setup.cfg") is None
    with pytest.raises(ValueError, match="beside its program"):
        Pairing.from_pattern("cfg/<name>.cfg")
    with pytest.raises(ValueError, match="beside its program"):
        Pairing.from_pattern("cfg\\<name>.cfg")


def test_a_program_is_never_a_configuration() -> None:
    assert Pairing.from_pattern("<name>.mnt").partner_name("a.mnt") == (Unit.PROGRAM, None)
    assert Pairing.from_pattern("<name>.MNT").partner_name("a.MNT") == (Unit.PROGRAM, None)


def test_the_name_written_as_asked_wins_over_one_differing_in_case() -> None:
    assert listed_as("app.cfg", ["APP.CFG", "app.cfg"]) == "app.cfg"
    assert listed_as("app.cfg", ["other.cfg", "APP.CFG", "App.Cfg"]) == "APP.CFG"
    assert listed_as("app.cfg", ["other.cfg"]) is None


def test_the_partner_on_disk_is_found_in_any_case_and_only_if_it_exists(tmp_path: Path) -> None:
    (tmp_path / "APP.MNT").write_text("PRINT 1\n", encoding="utf-8")
    (tmp_path / "app.cfg").write_text("DIM a\n", encoding="utf-8")
    (tmp_path / "lonely.mnt").write_text("PRINT 1\n", encoding="utf-8")
    assert partner_on_disk(tmp_path / "APP.MNT") == (Unit.PROGRAM, tmp_path / "app.cfg")
    assert partner_on_disk(tmp_path / "app.cfg") == (Unit.CONFIGURATION, tmp_path / "APP.MNT")
    assert partner_on_disk(tmp_path / "lonely.mnt") == (Unit.PROGRAM, None)
    assert partner_on_disk(tmp_path / "APP.MNT", "") == (Unit.PROGRAM, None)


def test_a_folder_is_listed_again_when_a_file_appears(tmp_path: Path) -> None:
    os.utime(tmp_path, ns=(1_000_000_000, 1_000_000_000))
    assert names_in(tmp_path) == ()
    (tmp_path / "APP.CFG").write_text("", encoding="utf-8")  # a new entry changes the folder's time
    assert names_in(tmp_path) == ("APP.CFG",)


_NAME_CHARACTERS = st.characters(blacklist_characters="/\\<>", blacklist_categories=("Cs",))


@given(
    stem=st.text(_NAME_CHARACTERS, min_size=1, max_size=12),
    prefix=st.text(_NAME_CHARACTERS, max_size=6),
    suffix=st.text(_NAME_CHARACTERS, min_size=1, max_size=6),
)
def test_a_programs_configuration_leads_back_to_the_program(stem: str, prefix: str, suffix: str) -> None:
    pairing = Pairing(prefix, suffix)
    program = stem + ".mnt"
    configuration = pairing.configuration_name(program)
    if configuration is not None:  # None only where the configuration's name would be a program's
        assert pairing.program_name(configuration) == program
