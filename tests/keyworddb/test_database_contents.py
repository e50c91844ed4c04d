"""Facts the keyword database must state, each checked against the manual line cited.

``v4:N`` is line N of the Mint v4 guide (seed 000), ``v3:N`` of the v3 guide (seed 001).
"""

from __future__ import annotations

import json
from importlib import resources
from typing import Any

import pytest

from mintlang.keyworddb import KeywordDatabase, database
from mintlang.keyworddb.model import (
    Addressing,
    Controller,
    ErrorKind,
    KeywordKind,
    MigrationClass,
)


@pytest.fixture(scope="module")
def db() -> KeywordDatabase:
    return database()


def test_loaded_once_per_process() -> None:
    assert database() is database()


# --- counts -------------------------------------------------------------------------------


def test_v4_keyword_count(db: KeywordDatabase) -> None:
    # 216 full + 129 advanced + 34 CAN-guide entries in chapter 10, 9 editor commands (v4:5390-5547),
    # 3 keywords only in the chapter 11 tables and 13 construct words without an entry.
    documented_or_stub = [k for k in db.keywords.values() if "no entry of its own" not in " ".join(k.notes)]
    assert 380 <= len(documented_or_stub) <= 400
    assert sum(not k.documented for k in db.keywords.values()) == 129 + 34 + 3


def test_renames_are_the_77_retired_names(db: KeywordDatabase) -> None:
    assert len(db.renames) == 77
    assert sum(r.status == "removed" for r in db.renames) == 5  # "not available in Mint v4"


def test_error_codes_are_exactly_the_printed_ones(db: KeywordDatabase) -> None:
    # v4:18508 "#-1 ... Success" opens the MML list; there is no "#0" entry.
    expected = {-1, *range(1, 109), 500, 501, 502, *range(2000, 2022), *range(3000, 3008)}
    assert set(db.errors) == expected


# --- v4 keywords --------------------------------------------------------------------------


def test_speed(db: KeywordDatabase) -> None:
    speed = db.keywords["SPEED"]  # v4:16147 "SPEED/SP"
    assert speed.abbreviations == ("SP",)
    assert speed.kind is KeywordKind.PARAMETER
    assert speed.addressing is Addressing.AXIS
    nextmove = speed.attributes_for(Controller.NEXTMOVE_PC)
    assert nextmove is not None  # v4:16169 "NextMove � �  � � 20,000, ... 1.0 ≤ x ≤ 8388607.0"
    assert (nextmove.read, nextmove.write, nextmove.command) == (True, True, False)
    assert nextmove.multi_axis and nextmove.scaled
    assert nextmove.range is not None
    assert (nextmove.range.minimum, nextmove.range.maximum, nextmove.range.fractional) == (1.0, 8388607.0, True)
    mintdrive = speed.attributes_for(Controller.MINTDRIVE)  # v4:16177 "... See below"
    assert mintdrive is not None and mintdrive.range is not None
    # v4:16181-16185: 0 ≤ x ≤ 8000000 at LOOPTIME 500, down to 0 ≤ x ≤ 2000000 at 2000
    assert (mintdrive.range.minimum, mintdrive.range.maximum) == (0.0, 8000000.0)


def test_adc_is_a_read_only_channel_keyword_with_glued_form(db: KeywordDatabase) -> None:
    adc = db.keywords["ADC"]  # v4:6340 "v = ADC.channel", v4:6343 "v = ADCx"
    assert adc.addressing is Addressing.CHANNEL
    assert adc.channel_suffix
    row = adc.attributes[0]  # v4:6358 "All �      -100 ≤ x ≤ 100"
    assert (row.read, row.write) == (True, False)
    assert row.range is not None and (row.range.minimum, row.range.maximum, row.range.fractional) == (-100, 100, False)


def test_camindex_is_read_only(db: KeywordDatabase) -> None:
    row = db.keywords["CAMINDEX"].attributes[0]  # v4:7836 "All �      1 ≤ x ≤ 65535"
    assert (row.read, row.write, row.command) == (True, False, False)


def test_acceltime_is_write_only_as_the_error_2002_example_says(db: KeywordDatabase) -> None:
    acceltime = db.keywords["ACCELTIME"]
    row = acceltime.attributes[0]  # v4:6234 "All � �  �   1 ≤ x ≤ 8388607" ticks read, write, multi-axis
    # v4:18918 uses "PRINT ..., ACCELTIME" as the example of #2002 "Write only": that example wins
    assert (row.read, row.write, row.multi_axis, row.default) == (False, True, True, None)
    assert row.range is not None and row.range.minimum == 1 and not row.range.fractional
    assert any("#2002" in note and "error example is followed" in note for note in acceltime.notes)


def test_an_access_the_formats_show_but_the_table_lost_is_kept(db: KeywordDatabase) -> None:
    # v4:15460-15461 "RELAY.channel = <expression>" and "value = RELAY.channel"; the table row has one tick
    for name in ("RELAY", "BOOST", "SEXTANT"):
        (row,) = db.keywords[name].attributes
        assert (row.read, row.write) == (True, True), name
        assert any("formats are followed" in note for note in db.keywords[name].notes)
    # v4:11716-11738: IDLE "returns" whether the axis is idle; its write format is a misprint
    (idle,) = db.keywords["IDLE"].attributes
    assert (idle.read, idle.write) == (True, False)
    assert any("table is followed" in note for note in db.keywords["IDLE"].notes)


def test_scale_range_is_positive(db: KeywordDatabase) -> None:
    scale = db.keywords["SCALE"]  # v4:15783-15784
    nextmove, mintdrive = scale.attributes_for(Controller.NEXTMOVE_PC), scale.attributes_for(Controller.MINTDRIVE)
    assert nextmove is not None and nextmove.range is not None
    assert mintdrive is not None and mintdrive.range is not None
    assert (nextmove.range.minimum, nextmove.range.maximum, nextmove.range.fractional) == (0, 8388607, True)
    assert (mintdrive.range.minimum, mintdrive.range.maximum) == (1, 65535)


def test_parameters_of_bracketed_calls(db: KeywordDatabase) -> None:
    assert db.keywords["POW"].parameters == ("x", "y")  # v4:15151 "v = POW(x, y)"
    assert db.keywords["SIN"].parameters == ("angle",)  # v4:15945 "v = SIN(<angle>)"
    assert db.keywords["COMMS"].parameters == ("node?", "element")  # v4:8290 "COMMS( {node, } element)"
    # v4:7912 "CAMTABLE ( axis, position array, {master increment array} )"
    assert db.keywords["CAMTABLE"].parameters == ("axis", "position_array", "master_increment_array?")


@pytest.mark.parametrize(
    ("name", "kind"),
    [
        ("AND", KeywordKind.OPERATOR),
        ("MOD", KeywordKind.OPERATOR),
        ("FOR", KeywordKind.STATEMENT),
        ("ENDIF", KeywordKind.STATEMENT),
        ("SQRT", KeywordKind.FUNCTION),
        ("GO", KeywordKind.COMMAND),
        ("#ONERROR", KeywordKind.EVENT),
        ("LIST", KeywordKind.COMMAND_LINE),
        ("NODE", KeywordKind.PARAMETER),  # v4:14650 "NODEID = <expression>" despite the heading
    ],
)
def test_kinds(db: KeywordDatabase, name: str, kind: KeywordKind) -> None:
    assert db.keywords[name].kind is kind


def test_structure_words_cite_their_construct(db: KeywordDatabase) -> None:
    assert db.keywords["THEN"].line == 11847  # v4:11847 "IF .. THEN"
    assert db.keywords["NEXT"].line == 10878  # v4:10878 "FOR .. NEXT"
    assert all(
        word in db.keywords for word in ("DO", "ELSE", "TO", "STEP", "UNTIL", "ENDW", "ENDL", "USING", "HEX", "BIN")
    )


def test_undocumented_stub_keeps_chapter_11_facts(db: KeywordDatabase) -> None:
    remote = db.keywords["REMOTENODE"]  # only in the chapter 11 table, v4:18306 "REMOTENODE RN"
    assert not remote.documented and remote.abbreviations == ("RN",)


# --- lookup -------------------------------------------------------------------------------


def test_lookup_by_abbreviation_in_any_case(db: KeywordDatabase) -> None:
    assert db.lookup("sp") is db.keywords["SPEED"]
    assert db.lookup("Ki") is db.keywords["KINT"]  # v4:12802 "KINT/KI"
    assert db.lookup("?") is db.keywords["PRINT"]
    assert db.lookup("nosuchword") is None


def test_lookup_of_glued_channel(db: KeywordDatabase) -> None:
    assert db.lookup("in3") is db.keywords["IN"]  # v4:11945 "v = INx"
    assert db.lookup("#IN4") is db.keywords["#IN"]  # v4:5914 "#IN0 .. #INx"
    assert db.lookup("#FASTIN") is db.lookup("#fastin2") is db.keywords["#FASTIN"]  # v4:5849
    assert db.lookup("POS1") is None  # POS has no glued form


def test_shared_abbreviations_resolve_as_recorded(db: KeywordDatabase) -> None:
    conflicts = {c["subject"]: c for c in _conflicts() if c["kind"] == "abbreviation"}
    # v4:16408 STOPINPUT/SI vs v4:16339 STEPPERIO/SI (advanced stub)
    assert conflicts["SI"]["resolved_to"] == "STOPINPUT" and db.lookup("si") is db.keywords["STOPINPUT"]
    # v4:16233 SPEEDDEMAND/SPD vs chapter 11 v4:17758 "SPLINESUSPENDTIME SPD"
    assert conflicts["SPD"]["resolved_to"] == "SPEEDDEMAND"
    # chapter 11 gives CLT to CURRENTLIMITTIME (v4:17564) and COMPARELATCH (v4:17825)
    assert set(conflicts["CLT"]["keywords"]) == {"CURRENTLIMITTIME", "COMPARELATCH"}
    assert any("SI is given to" in note for note in db.keywords["STEPPERIO"].notes)


def test_a_shared_abbreviation_names_the_keyword_the_controller_has(db: KeywordDatabase) -> None:
    # v4:11314 HANDLERPENDING/HP (MintDrive only), v4:11581 HOMEPOS/HP (NextMove only)
    assert db.lookup("HP", Controller.NEXTMOVE_PCI) is db.keywords["HOMEPOS"]
    assert db.lookup("hp", Controller.MINTDRIVE) is db.keywords["HANDLERPENDING"]
    # v4:16233 SPEEDDEMAND/SPD (MintDrive, ServoNode), v4:16289 SPLINESUSPENDTIME/SPD (NextMove)
    assert db.lookup("SPD", Controller.NEXTMOVE_BX) is db.keywords["SPLINESUSPENDTIME"]
    assert db.lookup("SPD", Controller.SERVONODE51) is db.keywords["SPEEDDEMAND"]
    # without a controller, or where the controller has both or neither, the recorded choice stands
    assert db.lookup("HP") is db.keywords["HANDLERPENDING"]
    assert db.lookup("HP", Controller.SERVONODE51) is db.keywords["HANDLERPENDING"]
    assert db.lookup("SI", Controller.NEXTMOVE_BX) is db.keywords["STOPINPUT"]


def test_chapter_disagreements_are_noted(db: KeywordDatabase) -> None:
    # v4:10777 "FOLLOWDENOM/FLD" but v4:17621 "FOLLOWDENOM FD"
    assert db.keywords["FOLLOWDENOM"].abbreviations == ("FLD", "FD")
    assert any("FD" in note for note in db.keywords["FOLLOWDENOM"].notes)
    assert db.lookup("fd") is db.keywords["FOLLOWDENOM"]


# --- constants and errors -----------------------------------------------------------------


def test_general_constants(db: KeywordDatabase) -> None:
    assert db.constants["_TRUE"].value == 1  # v4:857
    assert db.constants["_MAXINT"].value == 8388607  # v4:862
    assert db.constants["_MININT"].value == -8388607  # v4:863
    assert db.constants["_TRUE"].keyword is None


def test_keyword_constants(db: KeywordDatabase) -> None:
    home = db.constants["_HMPOSITIVE_SWITCH_INDEX"]  # v4:11421 "3 _hmPOSITIVE_SWITCH_INDEX"
    assert (home.name, home.value, home.keyword) == ("_hmPOSITIVE_SWITCH_INDEX", 3, "HOME")
    assert "_hmPOSITIVE_SWITCH_INDEX" in db.keywords["HOME"].constants
    assert db.constants["_MDLINEAR"].value == 2  # v4:7141 bit 1 of AXISMODE
    assert db.constants["_MDCAM"].value == 1024  # v4:7161 bit 10
    assert db.constants["_TMLCD1"].value == 8  # v4:16698 "0x08 _tmLCD1"
    assert db.constants["_ERINVALID_AXIS"].value == 2  # v4:18514 "#2 ... (_erINVALID_AXIS)"


def test_errors(db: KeywordDatabase) -> None:
    assert db.errors[3001].title == "Variable undefined, use DIM"  # v4:19073
    assert db.errors[2003].title == "Syntax error"
    assert db.errors[101].constant == "_erREMOTE_DOWNLOAD_IN_PROGRESS"  # wrapped onto v4:18858
    assert db.errors[2].kind is ErrorKind.MML and db.errors[500].kind is ErrorKind.MINT


# --- v3 -----------------------------------------------------------------------------------


def test_hmspeed_rename(db: KeywordDatabase) -> None:
    rename = db.rename_of("hmspeed")  # v4:11356 "HMSPEED/HS ... replaced by HOMESPEED"
    assert rename is not None and rename.new == ("HOMESPEED",) and rename.old_abbreviation == "HS"
    assert db.rename_of("PEEK").new == ("DPRFLOAT", "DPRLONG", "DPRWORD")  # v4:15065


def test_v3_lookups(db: KeywordDatabase) -> None:
    hmspeed = db.lookup_v3("hs")  # v3:8618 "HMSPEED/HS"
    assert hmspeed is not None and hmspeed.name == "HMSPEED"
    assert hmspeed.v4_names == ("HOMESPEED",) and hmspeed.migration is MigrationClass.MECHANICAL
    decel = db.lookup_v3("DE")  # v3:7178 "DECEL/DE"; DE is DRIVEENABLE in v4
    assert decel is not None and decel.name == "DECEL"
    assert db.lookup("de") is db.keywords["DRIVEENABLE"]
    in3 = db.lookup_v3("i3")  # v3:8975 "IN0/IO .. IN7/I7"
    assert in3 is not None and in3.name == "IN3" and in3.v4_names == ("IN",)


@pytest.mark.parametrize(
    ("name", "function"),
    [
        ("PEEK", True),  # v3:10732 "v = PEEK(<expression>)", no v4 keyword of that name
        ("ABS", True),  # v3:5603 "v = ABS(<expression>)"
        ("POKE", False),  # v3:10815 "POKE <address>,<expression>"
        ("POS", False),
    ],
)
def test_v3_functions_are_those_the_guide_calls_with_brackets(db: KeywordDatabase, name: str, function: bool) -> None:
    assert db.v3_keywords[name].function is function


@pytest.mark.parametrize("bit", range(8))
def test_v3_expanded_io_bits_are_abbreviated_x0_to_x7(db: KeywordDatabase, bit: int) -> None:
    # v3:12720 "XIO/XI XIO0..7"; v3:12753 "X2 is the abbreviated keyword for XIO2"
    keyword = db.lookup_v3(f"x{bit}")
    assert keyword is not None and keyword.name == f"XIO{bit}"


def test_a_range_knows_which_bounds_it_includes(db: KeywordDatabase) -> None:
    out = db.keywords["OUT"].attributes_for(Controller.NEXTMOVE_PCI)
    assert out is not None and out.range is not None
    assert (out.range.minimum_included, out.range.maximum_included) == (True, False)  # 0 ≤ x < 4096
    assert out.range.holds(0) and out.range.holds(4095) and not out.range.holds(4096)


@pytest.mark.parametrize(
    ("name", "controller", "text"),
    [
        # 000:11961-11962: IN reads the whole word (0 ≤ x ≤ 1048575 on NextMove PCI) or one channel (0 or 1)
        pytest.param("IN", Controller.NEXTMOVE_PCI, "0 ≤ x ≤ 1048575; one channel: 0 or 1", id="word-then-channel"),
        # 000:14110-14111: "0 – Forward" and "1 – Reverse", one mode a line
        pytest.param("MOTORDIRECTION", Controller.MINTDRIVE, "0 – Forward; 1 – Reverse", id="mode-a-line"),
    ],
)
def test_a_range_printed_on_two_lines_keeps_them_apart(
    db: KeywordDatabase, name: str, controller: Controller, text: str
) -> None:
    row = db.keywords[name].attributes_for(controller)
    assert row is not None and row.range is not None
    assert row.range.text == text


@pytest.mark.parametrize(
    ("name", "text", "bounds"),
    [
        pytest.param(  # 000:6169-6175
            "ACCEL",
            "15625 ≤ x ≤ 8388607 at LOOPTIME 500; 3907 ≤ x ≤ 8388607 at LOOPTIME 1000; "
            "977 ≤ x ≤ 8388607 at LOOPTIME 2000",
            (977, 8388607),
            id="accel",
        ),
        pytest.param(  # 000:11614-11620
            "HOMESPEED",
            "16 ≤ x ≤ 8,000,000 at LOOPTIME 500; 8 ≤ x ≤ 4,000,000 at LOOPTIME 1000; "
            "4 ≤ x ≤ 2,000,000 at LOOPTIME 2000",
            (4, 8000000),
            id="homespeed",
        ),
    ],
)
def test_a_range_per_looptime_shows_each_and_bounds_their_span(
    db: KeywordDatabase, name: str, text: str, bounds: tuple[float, float]
) -> None:
    row = db.keywords[name].attributes_for(Controller.MINTDRIVE)
    assert row is not None and row.range is not None
    assert (row.range.text, (row.range.minimum, row.range.maximum)) == (text, bounds)


def test_v3_constants(db: KeywordDatabase) -> None:
    posindex = db.v3_constants["_POSINDEX"]  # v3:1333
    assert posindex.value == 3 and posindex.v4_name == "_hmPOSITIVE_SWITCH_INDEX"
    assert db.v3_constants["_LIMIT"].v4_name is None  # a pair of v4 bits, no single constant


def _conflicts() -> list[dict[str, Any]]:
    return json.loads(resources.files("mintlang.keyworddb").joinpath("data", "conflicts.json").read_text("utf-8"))


@pytest.mark.parametrize(
    ("name", "default"),
    [
        ("HOMESPEED", "1000, 500 (step)"),  # 000:11607-11608: "1000" then "500 (step)" on the next line
        ("ACCEL", "300,000, 3000 (step)"),  # 000:6164-6165
        ("DECEL", "300,000, 3000 (step)"),  # 000:8884-8885
        ("SPEED", "20,000, 1000 (stepper)"),  # the one the guide prints with its comma
    ],
)
def test_a_default_per_axis_type_wrapped_onto_two_lines_keeps_the_two_apart(
    db: KeywordDatabase, name: str, default: str
) -> None:
    row = db.keywords[name].attributes_for(Controller.NEXTMOVE_PCI)
    assert row is not None and row.default == default
