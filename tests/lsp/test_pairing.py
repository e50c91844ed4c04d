"""Which configuration file goes with which program (``mint.configPairing``), named as the client names files."""

from __future__ import annotations

from pathlib import Path

from mintlang.lsp.workspace import Settings, partner
from mintlang.semantic.units import Unit

DEFAULT = Settings()


def test_the_partner_is_written_as_the_client_writes_uris() -> None:
    # VS Code on Windows escapes the drive's colon; a round trip through a path would not
    assert partner("file:///c%3A/Machines/Press%201/press.mnt", DEFAULT) == (
        Unit.PROGRAM,
        "file:///c%3A/Machines/Press%201/press.cfg",
    )
    assert partner("file:///c%3A/Machines/press.cfg", DEFAULT) == (
        Unit.CONFIGURATION,
        "file:///c%3A/Machines/press.mnt",
    )


def test_a_partner_on_disk_is_found_whatever_the_case_of_its_name(tmp_path: Path) -> None:
    (tmp_path / "APP.MNT").write_text("PRINT 1\n", encoding="utf-8")
    (tmp_path / "app.cfg").write_text("DIM a\n", encoding="utf-8")
    assert partner((tmp_path / "APP.MNT").as_uri(), DEFAULT) == (Unit.PROGRAM, (tmp_path / "app.cfg").as_uri())
    assert partner((tmp_path / "app.cfg").as_uri(), DEFAULT) == (Unit.CONFIGURATION, (tmp_path / "APP.MNT").as_uri())


def test_an_open_document_not_yet_on_disk_is_found_whatever_the_case_of_its_name(tmp_path: Path) -> None:
    program = (tmp_path / "APP.MNT").as_uri()
    unsaved = (tmp_path / "app.cfg").as_uri()  # opened in the editor, never saved
    elsewhere = (tmp_path / "other" / "app.cfg").as_uri()
    assert partner(program, DEFAULT, opened=[elsewhere, unsaved]) == (Unit.PROGRAM, unsaved)
    assert partner(program, DEFAULT, opened=[elsewhere]) == (Unit.PROGRAM, (tmp_path / "APP.cfg").as_uri())


def test_a_pattern_names_a_file_beside_the_program_never_a_folder() -> None:
    assert Settings.from_options({"mint": {"configPairing": "cfg/<name>.cfg"}}).config_pairing == "<name>.cfg"
    assert Settings.from_options({"mint": {"configPairing": "setup_<name>.txt"}}).config_pairing == "setup_<name>.txt"
    paired = Settings(config_pairing="setup_<name>.txt")
    assert partner("file:///m/press.mnt", paired) == (Unit.PROGRAM, "file:///m/setup_press.txt")
    assert partner("file:///m/setup_press.txt", paired) == (Unit.CONFIGURATION, "file:///m/press.mnt")


def test_a_program_is_never_a_configuration_and_other_files_have_no_partner() -> None:
    assert partner("file:///m/press.mnt", Settings(config_pairing="<name>.mnt")) == (Unit.PROGRAM, None)
    assert partner("file:///m/notes.txt", DEFAULT) == (Unit.PROGRAM, None)
    assert partner("untitled:Untitled-1", DEFAULT) == (Unit.PROGRAM, None)
