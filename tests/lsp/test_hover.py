"""Hover on keywords in any spelling, constants, variables, arrays, macros and labels."""

from __future__ import annotations

import pytest
from lsprotocol import types

from tests.lsp.conftest import corpus, document, open_document, position, published, uri_of

pytestmark = pytest.mark.asyncio


async def hover_at(client, uri, text, needle, shift=0) -> str | None:
    found = await client.text_document_hover_async(
        types.HoverParams(text_document=document(uri), position=position(text, needle, shift))
    )
    return found.contents.value if found is not None else None


async def test_keyword_full_abbreviated_and_lower_case(client, tmp_path):
    text = "DIM a\nSPEED[0] = 10\nsp.1 = 20\na = In3\n"
    uri = uri_of(tmp_path / "keywords.mnt")
    await open_document(client, uri, text)
    full = await hover_at(client, uri, text, "SPEED")
    assert "**SPEED** (abbreviation SP)" in full
    assert "SPEED[axes] = <expression>" in full
    assert "Addressing: by axis" in full
    assert "Access: read, write" in full
    assert "Controllers: NextMove PCI" in full
    assert "Slew speed" in full
    assert full.endswith("- Here: axis 0")
    assert await hover_at(client, uri, text, "sp.1") == full.replace("- Here: axis 0", "- Here: axis 1")
    glued = await hover_at(client, uri, text, "In3", 1)
    assert "**IN**" in glued and "channel 3" in glued


async def test_a_keyword_without_a_format_has_no_empty_code_block(client, tmp_path):
    text = "DIM a\nIF a THEN a = 1\n"
    uri = uri_of(tmp_path / "then.mnt")
    await open_document(client, uri, text)
    then = await hover_at(client, uri, text, "THEN")
    assert "**THEN**" in then and "```" not in then


async def test_the_rem_of_a_comment_is_a_keyword(client, tmp_path):
    text = "rem a note\n"
    uri = uri_of(tmp_path / "rem.mnt")
    await open_document(client, uri, text)
    assert "**REM**" in await hover_at(client, uri, text, "rem", 1)
    assert await hover_at(client, uri, text, "note", 1) is None
    bare = "REM\n"
    await open_document(client, uri_of(tmp_path / "bare.mnt"), bare)
    assert "**REM**" in await hover_at(client, uri_of(tmp_path / "bare.mnt"), bare, "REM", 3)


async def test_the_operators_and_separator_written_as_symbols_are_keywords(client, tmp_path):
    # ~ is the bitwise NOT (000:1292, 1340-1341) and ':' separates statements on a line, as & is AND
    text = "DIM a\na = ~a : a = a & 1\n"
    uri = uri_of(tmp_path / "symbols.mnt")
    await open_document(client, uri, text)
    assert (await hover_at(client, uri, text, "~")).startswith("**~** — operator")
    assert (await hover_at(client, uri, text, ": ")).startswith("**:** — statement")
    assert (await hover_at(client, uri, text, "&")).startswith("**AND** (abbreviation &) — operator")
    assert (await hover_at(client, uri, text, "~a", 1)).startswith("**a** — variable")  # a word wins at its start


async def test_a_command_line_keyword_is_named_in_words(client, tmp_path):
    # RELEASE is for the command line, or the configuration file, never a program (000:934-939)
    text = "RELEASE\n"
    uri = uri_of(tmp_path / "release.cfg")
    await open_document(client, uri, text)
    assert (await hover_at(client, uri, text, "RELEASE")).startswith("**RELEASE** — command line\n")


async def test_constant_shows_its_value(client, tmp_path):
    text = "DIM a\na = _TRUE\n"
    uri = uri_of(tmp_path / "constant.mnt")
    await open_document(client, uri, text)
    assert "= `1`" in await hover_at(client, uri, text, "_TRUE", 2)


async def test_null_says_it_stands_for_no_master_distance_table(client, tmp_path):
    # the guide's cam example (000:3912-3913): NULL where CAMTABLE takes its master distance table
    text = "DIM slave(3) = 2, 10, 20\nMASTERDISTANCE = 20\nCAMTABLE(0, slave, NULL)\n"
    uri = uri_of(tmp_path / "cam.mnt")
    await open_document(client, uri, text)
    null = await hover_at(client, uri, text, "NULL", 1)
    assert null.startswith("**NULL** — reserved word")
    assert "CAMTABLE" in null and "no master distance table" in null and "MASTERDISTANCE" in null


async def test_a_v3_constant_shows_its_v3_value_and_its_v4_successor(client, tmp_path):
    # the v3 guide's table of constants (001:1325, 1327): _limit is 3 for ERROR, _servo 1 for CONFIG
    client.workspace_did_change_configuration(types.DidChangeConfigurationParams(settings={"mint": {"dialect": "v3"}}))
    text = "CONFIG = _servo\nIF ERROR = _limit THEN DL\n"
    uri = uri_of(tmp_path / "old_constants.mnt")
    await open_document(client, uri, text)
    assert await hover_at(client, uri, text, "_servo", 1) == (
        "**_servo** = `1` — Mint v3 predefined constant; Mint v4: _cfSERVO"
    )
    assert await hover_at(client, uri, text, "_limit", 1) == (
        "**_limit** = `3` — Mint v3 predefined constant; Mint v4 has no such constant"
    )


async def test_an_abbreviation_two_keywords_share_names_the_controllers_one(client, tmp_path):
    text = "DIM a\na = HP.0\n"
    uri = uri_of(tmp_path / "home.mnt")
    assert await open_document(client, uri, text) == []  # NextMove PCI: HOMEPOS, available
    assert "**HOMEPOS**" in await hover_at(client, uri, text, "HP", 1)
    client.workspace_did_change_configuration(
        types.DidChangeConfigurationParams(settings={"mint": {"controller": "mintdrive"}})
    )
    await published(client, uri)
    assert "**HANDLERPENDING**" in await hover_at(client, uri, text, "HP", 1)


async def test_a_v3_keyword_says_what_it_became_and_what_migrating_it_takes(client, tmp_path):
    client.workspace_did_change_configuration(types.DidChangeConfigurationParams(settings={"mint": {"dialect": "v3"}}))
    text = "HS.0 = 100\nKEYS\n"
    uri = uri_of(tmp_path / "old.mnt")
    await open_document(client, uri, text)
    renamed = await hover_at(client, uri, text, "HS", 1)
    assert renamed.startswith("**HMSPEED** (abbreviation HS) — Mint v3 keyword")
    assert "- Addressing: by axis" in renamed and "- Mint v4: HOMESPEED (renamed)" in renamed
    assert "- Migration: mint-migrate rewrites it" in renamed and "In Mint v4, HOMESPEED: " in renamed
    removed = await hover_at(client, uri, text, "KEYS", 1)
    assert "- Mint v4: removed" in removed and "REM MIGRATE" in removed


async def test_a_character_constant_shows_its_code_in_upper_case(client, tmp_path):
    text = "DIM k\nk = INKEY\nIF k = 'y' OR k = 'N' THEN PRINT k\n"
    uri = uri_of(tmp_path / "keys.mnt")
    await open_document(client, uri, text)
    lower = await hover_at(client, uri, text, "'y'", 1)
    assert lower.startswith("**'y'** = `89` — character constant") and "'Y'" in lower
    assert await hover_at(client, uri, text, "'N'", 3) == "**'N'** = `78` — character constant"


async def test_symbols_say_where_they_are_declared(client, tmp_path):
    text = corpus("ch01_l0144_xy_example.mnt") + "DEFINE fast = 100 * 2\nDIM b\nb = fast\n"
    uri = uri_of(tmp_path / "xy.mnt")
    await open_document(client, uri, text)
    array = await hover_at(client, uri, text, "xpos(a)")
    assert array.startswith("**xpos**(10) — array, declared at line 7 of the program (xy.mnt)")
    assert "variable, declared at line 21" in await hover_at(client, uri, text, "a = 1 to", 0)
    assert "label, at line 14" in await hover_at(client, uri, text, "GOSUB init", 7)
    macro = await hover_at(client, uri, text, "b = fast", 5)
    assert "macro, defined at line 41" in macro and "DEFINE fast = 100 * 2" in macro


async def test_event_handler_and_nothing_on_blank(client, tmp_path):
    text = "END\n#ONERROR\nRETURN\n\n"
    uri = uri_of(tmp_path / "events.mnt")
    await open_document(client, uri, text)
    assert "event handler (ONERROR)" in await hover_at(client, uri, text, "#ONERROR", 2)
    assert await hover_at(client, uri, text, "\n\n", 1) is None


async def test_a_v3_word_in_v4_code_says_what_it_became(client, tmp_path):
    # the case: a v4 program whose only v3 word is HMSPEED (HOMESPEED in v4)
    text = "DEFINE xAxis = 0\nDEFINE zAxis = 2\nHMSPEED[xAxis, zAxis] = 20, 10\nDIM a\na = _servo\n"
    uri = uri_of(tmp_path / "v3.mnt")
    await open_document(client, uri, text)
    old = await hover_at(client, uri, text, "HMSPEED", 2)
    assert old.startswith("**HMSPEED** is not Mint v4: it is a Mint v3 keyword, replaced by HOMESPEED in v4")
    assert "- Mint v4: HOMESPEED (renamed)" in old  # the v3 entry, as the v3 dialect shows it
    assert "In Mint v4, HOMESPEED:" in old
    constant = await hover_at(client, uri, text, "_servo", 1)
    assert constant.startswith("**_servo** is not Mint v4: it is a Mint v3 constant; v4 uses _cfSERVO")


async def test_a_declared_variable_named_like_a_v3_word_is_the_users(client, tmp_path):
    text = "DIM gain\ngain = 2\n"
    uri = uri_of(tmp_path / "gain.mnt")
    await open_document(client, uri, text)
    assert (await hover_at(client, uri, text, "gain = ")).startswith("**gain** — variable")


# The guide's examples: DIM with a value (3.2.5, "DIM aVar = 100"), an array filled by ";" (3.7,
# "DIM y_position(10) = 10,0;"), and scale factors set through macros in the configuration file
# (3.5, "DEFINE g1 = [0,1,2,3] / SF.g1 = 10;").
CONFIGURATION = "DEFINE g1 = [0,1,2,3]\nDEFINE xAxis = 0\nSF.g1 = 10;\nSPEED[0,1] = 500, 600\nDIM aVar = 100\n"
PROGRAM = (
    "DIM y_position(10) = 10,0;\nDIM thisIsAVariable\n"
    "REM Home both axes\nREM and wait for them\nGOSUB init\nEND\n\n"
    "REM Home both axes\nREM and wait for them\n#init : REM called once\n"
    "SPEED.xAxis = 20\nSCALE[1,2] = 4 : OUT.3 = 1\nthisIsAVariable = aVar + y_position(1)\nRETURN\n"
)


async def test_a_variable_says_its_initial_value_and_its_file(client, tmp_path):
    (tmp_path / "cell.cfg").write_text(CONFIGURATION, encoding="utf-8")
    uri = uri_of(tmp_path / "cell.mnt")
    await open_document(client, uri, PROGRAM)
    configured = await hover_at(client, uri, PROGRAM, "aVar +")
    assert configured.startswith("**aVar** — variable, declared at line 5 of the configuration file (cell.cfg)")
    assert "- Initial value: `100`, set when the DIM runs" in configured
    bare = await hover_at(client, uri, PROGRAM, "thisIsAVariable =")
    assert "- Initial value: none written (0 when first declared)" in bare
    filled = await hover_at(client, uri, PROGRAM, "y_position(1)")
    assert "- Initial values: `10, 0`, then `0` for the rest (;), set when the program is compiled" in filled


async def test_an_axis_parameter_says_its_axes_and_what_the_configuration_file_sets(client, tmp_path):
    (tmp_path / "cell.cfg").write_text(CONFIGURATION, encoding="utf-8")
    uri = uri_of(tmp_path / "cell.mnt")
    await open_document(client, uri, PROGRAM)
    speed = await hover_at(client, uri, PROGRAM, "SPEED.xAxis", 2)
    assert speed.endswith("- Here: axis 0\n- The configuration file sets axis 0 to `500` (line 4)")
    scale = await hover_at(client, uri, PROGRAM, "SCALE[1,2]", 2)
    assert scale.endswith(
        "- Here: axes 1, 2\n"
        "- The configuration file sets axis 1 to `10` (line 3)\n"
        "- The configuration file sets axis 2 to `10` (line 3)"
    )
    assert (await hover_at(client, uri, PROGRAM, "OUT.3", 1)).endswith("- Here: output 3")


async def test_what_the_configuration_file_sets_follows_the_values_written(client, tmp_path):
    """The default axes take the values in turn (000:590-640), so all of them are shown; an axis past the last
    value is not set (000:578-580) unless a ';' fills the rest with the last value (000:656-659)."""
    (tmp_path / "axes.cfg").write_text("SPEED = 5, 6\nSPEED[0,1,2] = 8, 9\nSCALE[0,1,2] = 2, 3;\n", encoding="utf-8")
    text = "SPEED.2 = 1\nSCALE.2 = 1\nSPEED.1 = 1\n"
    uri = uri_of(tmp_path / "axes.mnt")
    await open_document(client, uri, text)
    assert (await hover_at(client, uri, text, "SPEED.2")).endswith(
        "- Here: axis 2\n- The configuration file sets the default axes to `5, 6` (line 1)"
    )
    assert (await hover_at(client, uri, text, "SCALE.2")).endswith(
        "- Here: axis 2\n- The configuration file sets axis 2 to `3` (line 3)"
    )
    assert (await hover_at(client, uri, text, "SPEED.1")).endswith(
        "- Here: axis 1\n"
        "- The configuration file sets the default axes to `5, 6` (line 1)\n"
        "- The configuration file sets axis 1 to `9` (line 2)"
    )


async def test_a_label_shows_the_remarks_above_it(client, tmp_path):
    uri = uri_of(tmp_path / "cell.mnt")
    await open_document(client, uri, PROGRAM)
    label = await hover_at(client, uri, PROGRAM, "GOSUB init", 7)
    assert label.endswith("\n\nHome both axes\nand wait for them\ncalled once")


@pytest.mark.parametrize(
    ("word", "formats", "misprint"),
    [
        # 000:14643 heads the entry NODE (abbreviation ND), 000:14653-14654 print NODEID in its formats
        ("NODE", "NODE = <expression>\nv = NODE", "NODEID"),
        # 000:14317 heads it MOTORPOLEPITCH, 000:14327 writes MOTOREPOLEPITCH, 000:14328 MOTORPOLEPITCH again
        ("MOTORPOLEPITCH", "MOTORPOLEPITCH = <expression>\nv = MOTORPOLEPITCH", "MOTOREPOLEPITCH"),
    ],
)
async def test_a_format_the_guide_misprints_shows_the_keyword_to_write(client, tmp_path, word, formats, misprint):
    text = f"{word} = 3\n"
    uri = uri_of(tmp_path / "misprint.mnt")
    await open_document(client, uri, text)
    shown = await hover_at(client, uri, text, word)
    assert f"```mint\n{formats}\n```" in shown
    assert misprint not in shown
