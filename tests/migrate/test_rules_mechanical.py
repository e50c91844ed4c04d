"""The mechanical rules: each rewrite, and each case the rule must leave alone or refuse."""

from __future__ import annotations

import pytest

from mintlang.keyworddb import database
from mintlang.migrate.rules.renames import KEYWORD_RENAMES
from tests.migrate.helpers import flagged, one_rule, rewritten


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("MA = 10 : GO\n", "MOVEA = 10 : GO\n"),
        ("SP.1 = 5\n", "SPEED.1 = 5\n"),
        ("DE = 2000\n", "DECEL = 2000\n"),  # v4 DE is DRIVEENABLE
        ("IM = 15\n", "IMASK = 15\n"),  # v4 IM is INPUTMODE
        ("x = MD.0\n", "x = MODE.0\n"),  # v4 MD is MOTORDIRECTION
        ("GR = 3\n", "GEARN = 3\n"),  # v4 GR is GEARING
        ("PAUSE I3\n", "PAUSE IN3\n"),
        ("X2.0 = 0\n", "XIO2.0 = 0\n"),  # v3:12753; spec M-ABBR: X4 -> XIO4
        ("ma = 1\n", "movea = 1\n"),  # lower case stays lower case
        ("? IN12 & 1\n", "? IN12 & 1\n"),  # symbols and glued channels stay
    ],
)
def test_abbreviations_become_full_v3_names(source: str, expected: str) -> None:
    assert rewritten("M-ABBR", source) == expected


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("GAIN = 2;\n", "KPROP = 2;\n"),
        ("HMSPEED[0,1] = 10,20\n", "HOMESPEED[0,1] = 10,20\n"),
        ("x = backoff.1\n", "x = homebackoff.1\n"),
        ("GN = 1\n", "KPROP = 1\n"),  # the abbreviation is matched by meaning
        ("MFOLERR = 2 : STOPMODE = 1\n", "FOLERRORFATAL = 2 : STOPINPUTMODE = 1\n"),
        ("KINTRANGE = 25 : MASTERINC.0 = 100\n", "KINTLIMIT = 25 : MASTERDISTANCE.0 = 100\n"),
    ],
)
def test_renamed_keywords(source: str, expected: str) -> None:
    assert rewritten("M-REN", source) == expected


def test_renames_cover_the_v4_guides_replaced_by_entries() -> None:
    for old, (new, line) in KEYWORD_RENAMES.items():
        rename = database().rename_of(old)
        assert rename is not None and rename.new == (new,), old
        assert abs(rename.line - line) <= 1, old


def test_fastpos_handler_becomes_fastin() -> None:
    assert rewritten("M-FASTPOS", "#FASTPOS\n  a = FASTPOS.0\nRETURN\n") == "#FASTIN\n  a = FASTPOS.0\nRETURN\n"


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("CONFIG = _servo, _stepper\n", "CONFIG = _cfSERVO, _cfSTEPPER\n"),
        ("HOME = _negindex\n", "HOME = _hmNEGATIVE_SWITCH_INDEX\n"),
        ("OUT1 = _on : OUT2 = _false\n", "OUT1 = _on : OUT2 = _false\n"),  # same name in v4: untouched
        ("x = _jog\n", "x = _jog\n"),  # value differs in v4: left to S-MODE / the final flag
    ],
)
def test_constants_are_renamed_only_when_the_value_is_the_same(source: str, expected: str) -> None:
    assert rewritten("M-CONST", source) == expected


_LATCH_MARKER = "REM MIGRATE: X-FASTLATCH: v4 holds the latch until the handler returns; check FASTSELECT\n"


# v4 calls #TIMER, #CANn, #COMMSn, #FASTIN and #FASTINn as event handlers (000:1884-1900); v3 reserves none of
# them, its fast-latch handler being #FASTPOS (001:2585-2587), so each is a v3 subroutine (spec M-LABEL).
@pytest.mark.parametrize(
    ("source", "expected"),
    [
        pytest.param(
            "GOSUB timer\nGOTO Can1\nEND\n#timer\nRETURN\n#Can1\nRETURN\n",
            "GOSUB timer_u\nGOTO Can1_u\nEND\n#timer_u\nRETURN\n#Can1_u\nRETURN\n",
            id="timer-and-can",
        ),
        pytest.param(
            "GOSUB fastin\nEND\n#fastin\nRETURN\n", "GOSUB fastin_u\nEND\n#fastin_u\nRETURN\n", id="v3-fastin"
        ),
        pytest.param(
            "#FASTIN\n  a = FASTPOS.0\nRETURN\n", "#FASTIN_u\n  a = FASTPOS.0\nRETURN\n", id="v3-fastin-alone"
        ),
        pytest.param("#FASTIN2\nRETURN\n", "#FASTIN2_u\nRETURN\n", id="numbered-fastin"),
        pytest.param(  # the handler a migration wrote from #FASTPOS, under X-FASTLATCH's marker
            f"{_LATCH_MARKER}#FASTIN\nRETURN\n", f"{_LATCH_MARKER}#FASTIN\nRETURN\n", id="migrated-fastin-kept"
        ),
        pytest.param(  # a scalar DIM is v4 (v3 DIMs arrays only, 001:7299): the markers were dealt with
            "DIM a\n#FASTIN\n  a = FASTPOS.0\nRETURN\n",
            "DIM a\n#FASTIN\n  a = FASTPOS.0\nRETURN\n",
            id="v4-fastin-kept",
        ),
    ],
)
def test_user_labels_named_like_v4_events_are_renamed_with_their_jumps(source: str, expected: str) -> None:
    assert rewritten("M-LABEL", source) == expected


def test_user_names_that_are_v4_keywords_are_renamed_everywhere() -> None:
    source = "node = 1\nView = node + 1\nPRINT VIEW, NODE\nkp = 2\n"
    assert rewritten("M-IDENT", source) == "node_u = 1\nView_u = node_u + 1\nPRINT VIEW_u, NODE_u\nkp_u = 2\n"


def test_renamed_names_stay_unique_in_ten_characters() -> None:
    assert rewritten("M-IDENT", "node = 1\nnode_u = 2\n") == "node_u2 = 1\nnode_u = 2\n"
    assert rewritten("M-IDENT", "inputactivelevel = 1\n") == "inputact_u = 1\n"  # ten significant characters


def test_a_reserved_long_name_is_renamed_in_each_spelling_of_its_ten_characters() -> None:
    # INPUTACTIVELEVEL is a v4 keyword; inputactivityx is the same variable (INPUTACTIV) to v3.
    source = "inputactivelevel = 1\nx = inputactivityx\n"
    assert rewritten("M-IDENT", source) == "inputact_u = 1\nx = inputact_u\n"


def test_a_long_name_sharing_ten_characters_with_no_v4_word_is_kept() -> None:
    source = "masterincrement = 1\nx = masterincrement\n"  # MASTERINCR..., no v4 keyword
    assert rewritten("M-IDENT", source) == source


def test_zero_becomes_pos_zero_on_every_axis() -> None:
    assert rewritten("M-ZERO", "ZERO[0,1]\nZERO.2\nZERO\n") == "POS[0,1] = 0;\nPOS.2 = 0\nPOS = 0;\n"


def test_boost_is_written_where_the_controller_has_it() -> None:
    source = "BOOSTON[4,5] : BOOSTOFF.1\n"
    assert rewritten("M-BOOST", source, controller="nextmove-pc") == "BOOST[4,5] = 1; : BOOST.1 = 0\n"
    assert flagged("M-BOOST", source) == ["BOOST is not available on NextMove PCI"]  # one line, one marker


def test_not_available_statements_become_comments() -> None:
    assert rewritten("M-NOTAVAIL", "COMMSON\n  BEEPOFF : REM quiet\n") == (
        "REM COMMSON: not available in Mint v4 (v4 guide section 10.3 COMMSON), removed by mint-migrate\n"
        "  REM BEEPOFF: not available in Mint v4 (v4 guide section 10.3 BEEPOFF), removed by mint-migrate : REM quiet\n"
    )


def test_not_available_statement_sharing_a_line_is_flagged() -> None:
    assert flagged("M-NOTAVAIL", "COMMSON : a = 1\n") == [
        "COMMSON is not available in Mint v4 (v4 guide section 10.3 COMMSON): delete it"
    ]


def test_offline_arrays_lose_the_word_offline() -> None:
    assert rewritten("M-OFFLINE", "DIM OFFLINE xpos(1000)\n") == "DIM xpos(1000)\n"


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("x = SIN(30)\n", "x = (SIN(30) * 1000)\n"),
        ("x = SIN 90 + a\n", "x = (SIN(90) * 1000) + a\n"),  # v3 binding of the bracketless call
        ("x = cos(a) * tan(b)\n", "x = (cos(a) * 1000) * (tan(b) * 1000)\n"),
        ("x = (SIN(30) * 1000)\n", "x = (SIN(30) * 1000)\n"),  # its own output
    ],
)
def test_trigonometry_keeps_v3_thousandths(source: str, expected: str) -> None:
    assert rewritten("M-TRIG", source) == expected


def test_tilde_keeps_eight_bits() -> None:
    assert rewritten("M-TILDE", "OUT = ~OUT\nx = (~y & 255)\n") == "OUT = (~OUT & 255)\nx = (~y & 255)\n"


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("IF a = 1 AND b = 2 OR c THEN d = 1\n", "IF (a = 1 AND b = 2) OR c THEN d = 1\n"),
        ("x = a | b & c | d\n", "x = a | (b & c) | d\n"),
        ("x = a AND b\n", "x = a AND b\n"),
        ("x = (a OR b) AND c\n", "x = (a OR b) AND c\n"),
    ],
)
def test_mixed_and_or_get_v3_brackets(source: str, expected: str) -> None:
    assert rewritten("M-PREC", source) == expected


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        ("SCALE = 2.5\n", "SCALE = INT(2.5)\n"),
        ("SCALE[0,1] = 400, s / 2\n", "SCALE[0,1] = 400, INT(s / 2)\n"),
        ("SCALE = 400;\n", "SCALE = 400;\n"),
        ("SCALE = INT(s)\n", "SCALE = INT(s)\n"),
    ],
)
def test_scale_stays_an_integer(source: str, expected: str) -> None:
    assert rewritten("M-SCALE", source) == expected


def test_variables_are_declared_at_the_top_in_first_use_order() -> None:
    source = "REM title\nREM\nGOSUB init\nEND\n#init\n  b = 2\n  FOR a = 1 TO b : INPUT c : NEXT\nRETURN\n"
    assert rewritten("M-DIM", source) == (
        "REM title\nREM\nDIM b\nDIM a\nDIM c\n"
        "GOSUB init\nEND\n#init\n  b = 2\n  FOR a = 1 TO b : INPUT c : NEXT\nRETURN\n"
    )


def test_declarations_follow_protect_and_auto() -> None:
    assert rewritten("M-DIM", "PROTECT abc\nx = 1\n").startswith("PROTECT abc\nDIM x\n")
    result = one_rule("M-DIM", "y = x\n", config="AUTO\nx = 1\n")
    assert result.configuration is not None and result.configuration.text == "AUTO\nDIM x\nx = 1\n"
    assert result.text == "DIM y\ny = x\n"  # x is declared in the configuration file and visible here


def test_arrays_are_not_redeclared_and_undimensioned_arrays_are_flagged() -> None:
    assert rewritten("M-DIM", "DIM d(5)\nFOR d = 1 TO 5 : d(d) = 0 : NEXT\n") == (
        "DIM d(5)\nFOR d = 1 TO 5 : d(d) = 0 : NEXT\n"
    )
    assert flagged("M-DIM", "PRINT pos_x(1)\n") == ["array 'pos_x' is used but never dimensioned"]


def test_default_axes_depend_on_the_controller() -> None:
    assert rewritten("M-AXES", "STOP\n", controller="nextmove-bx") == "AXES[0,1,2]\nSTOP\n"
    assert rewritten("M-AXES", "STOP\n", controller="mintdrive") == "STOP\n"
    assert rewritten("M-AXES", "AXES[0]\nSTOP\n") == "AXES[0]\nSTOP\n"
    result = one_rule("M-AXES", "STOP\n", config="AUTO\nRESET\n")
    assert result.configuration is not None and result.configuration.text == "AUTO\nAXES[0,1,2]\nRESET\n"


def test_a_comment_missing_its_rem_declares_nothing() -> None:
    # the v3 guide's GEARN example ends "STOP.0 : STOP following" (v3:3780-3792): STOP takes no
    # operands, so "following" is a comment missing its REM (X-COMMENTED), not a variable
    source = "x = 1\nFOLLOW.0 = 2\nSTOP.0 : STOP following\n"
    assert rewritten("M-DIM", source) == "DIM x\n" + source
