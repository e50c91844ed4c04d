"""Reads whose meaning moved to another keyword, and MODE/ERROR tests that became bit tests."""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from types import MappingProxyType

from mintlang.migrate.context import Context, FileView, per_pass
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Rule, selector_text
from mintlang.migrate.rules.renames import same_value_constants
from mintlang.migrate.rules.spelling import like
from mintlang.semantic.index import Use
from mintlang.syntax import nodes as n
from mintlang.syntax.parents import ancestors, parent_of

# v3 keyword read -> v4 keyword giving the same value.
READ_RENAMES: Mapping[str, str] = MappingProxyType(
    {"MOVEA": "POSTARGET", "MOVER": "POSTARGET", "OFFSET": "POSREMAINING", "HOME": "HOMESWITCH"}
)


class ReadRenames(Rule):
    """Reading MOVEA/MOVER gave the move's end position (v4: POSTARGET, MOVEA is write-only),
    reading OFFSET the distance left (POSREMAINING), HOME the home switch (HOMESWITCH: v4
    HOME reads the homing phase). Reading INCA/INCR (success
    flag) or CAM (segment size) has no v4 counterpart: manual item."""

    id = "S-READ"
    rule_class = RuleClass.SEMI
    phase = Phase.CONTEXT
    summary = "read of MOVEA/MOVER -> POSTARGET, OFFSET -> POSREMAINING, HOME -> HOMESWITCH"
    evidence = "spec S-READ; v3:3185-3186, v3:10415-10433, v3:3509; v4:14507, v4:14517, v4:3129-3141, v4:11454"

    def apply(self, context: Context) -> Iterator[Action]:
        for file, use in context.keyword_reads(*READ_RENAMES, "INCA", "INCR", "CAM"):
            keyword = use.keyword
            new = READ_RENAMES.get(keyword.keyword)
            if new is None:
                yield self.flag(file, keyword.span, f"reading {keyword.keyword} has no v4 counterpart")
            elif context.supports(new):
                yield self.replace(file, keyword.spelling_span, like(keyword.spelling, new))
            else:
                yield self.flag(file, keyword.span, f"reading {keyword.keyword}: {new} is not on this controller")


PULSE = 5  # v3 MODE _pulse: pulse following (v3:10040-10061)
# v3 MODE value -> v4 AXISMODE bit (v3:10040-10061 vs v4:7139-7171); 0 means idle.
MODE_BITS: Mapping[int, str] = MappingProxyType(
    {
        1: "_mdTORQUE",  # _servoff: SERVOFF is TORQUE = 0 after S-SERVOFF
        2: "_mdLINEAR",
        3: "_mdJOG",
        4: "_mdCIRCULAR",
        6: "_mdTORQUE",
        7: "_mdHOMING",
        8: "_mdOFFSET",
        9: "_mdFOLLOW",
        15: "_mdFLY",
        16: "_mdCAM",
        18: "_mdFOLLOW",
    }
)
# v3 ERROR value -> v4 AXISERROR bits (v3:4995-5010 vs v4:6967-7081).
ERROR_BITS: Mapping[int, str] = MappingProxyType(
    {1: "_erABORT", 2: "_erFOLLOWING_ERROR", 3: "(_erFWD_HARD_LIMIT | _erREV_HARD_LIMIT)", 11: "_erERROR_INPUT"}
)
_BY_HAND = "rewrite this test by hand"
# v3 values no v4 bit stands for: what they meant, and what to do instead (v3:5003, v3:10046-10058).
MODE_WITHOUT_BIT: Mapping[int, tuple[str, str]] = MappingProxyType(
    {
        PULSE: ("pulse following", "once X-PULSE makes it a FOLLOW, test _mdFOLLOW"),
        11: ("MOVECAM cam segment", _BY_HAND),
        17: ("joystick, MINT/3.28 only", _BY_HAND),
    }
)
ERROR_WITHOUT_BIT: Mapping[int, tuple[str, str]] = MappingProxyType(
    {13: ("digital output fault, SmartMove only", _BY_HAND)}
)


# The statements whose condition is only tested for zero or not (v3:2009, v3:13999, v4:1439-1440).
CONDITIONS = (n.IfThen, n.IfDo, n.While, n.Until, n.Pause)


def truth_only(statement: n.Statement, node: n.Expression) -> bool:
    """Whether only the truth of ``node`` is used: it is the condition of an IF, WHILE, UNTIL or
    PAUSE, or reaches it through brackets, NOT and OR, which treat every non-zero value alike.
    AND does not: it is bitwise (v3:14033-14039, v4:1306-1307), so the masks of two different bits
    AND to 0; as a value (``a = MODE = _jog``), an operand of ``+`` or ``=``, v3's 1 or 0 is used."""
    for parent in ancestors(statement, node):
        logical = (isinstance(parent, n.Unary) and parent.operator == "NOT") or (
            isinstance(parent, n.Binary) and parent.operator == "OR"
        )
        if not (logical or isinstance(parent, n.Parenthesised)):
            return False
        node = parent
    return isinstance(statement, CONDITIONS) and statement.condition is node


@per_pass
def _constant_values(context: Context) -> dict[str, int]:
    """Upper-case constant -> its v3 value: the v3 constants, and the v4 names M-CONST gives
    those whose value did not change (shared across a pass; callers must not change it)."""
    constants = context.db.v3_constants
    values = {name: int(constant.value) for name, constant in constants.items()}
    for name, v4 in same_value_constants(context).items():
        values.setdefault(v4.upper(), values[name])
    return values


class BitTest(Rule):
    """Base of S-MODE and S-ERROR: ``KW[.n] = k`` and ``KW[.n] <> k`` become bit tests of
    the v4 keyword that give v3's 1 or 0 (``(AXISMODE & _mdJOG) <> 0``); where only the truth
    of the test is used (a condition) the bare mask says the same. Any other use of the v3
    value is flagged."""

    phase = Phase.CONTEXT
    rule_class = RuleClass.SEMI
    keyword: str
    target: str
    bits: Mapping[int, str]
    without_bit: Mapping[int, tuple[str, str]]  # v3 values with no v4 bit: their meaning, the advice
    exact: frozenset[int] = frozenset()  # values that mean "this bit and no other"

    def apply(self, context: Context) -> Iterator[Action]:
        for file, use in context.keyword_uses(self.keyword):
            parent = parent_of(use.statement, use.keyword) if use.use is Use.READ else None
            value = self._compared_value(context, use.keyword, parent)
            special = self._special(context, file, use.statement, parent, value)
            if special is not None:
                assert isinstance(parent, n.Binary)
                yield self.replace(file, parent.span, special)
                continue
            if value in self.without_bit:
                meaning, advice = self.without_bit[value]
                reason = f"v3 {self.keyword} {value} ({meaning}) has no {self.target} bit: {advice}"
                yield self.flag(file, use.keyword.span, reason)
                continue
            if value is None or (value != 0 and value not in self.bits):
                yield self.flag(file, use.keyword.span, self.refusal)
                continue
            assert isinstance(parent, n.Binary)
            truth = truth_only(use.statement, parent)
            yield self.replace(file, parent.span, self._test(file, use.keyword, parent.operator, value, truth=truth))

    def _compared_value(self, context: Context, keyword: n.KeywordRef, parent: n.Expression | None) -> int | None:
        """The constant ``keyword`` is compared with by ``=`` or ``<>``, as a v3 value. A v4
        constant M-CONST wrote for a v3 one of the same value (``_idle`` -> ``_mdIDLE``,
        ``_abort`` -> ``_erABORT``) stands for that value: the renames run first."""
        if not isinstance(parent, n.Binary) or parent.operator not in ("=", "<>"):
            return None
        other = parent.right if parent.left is keyword else parent.left
        if isinstance(other, n.Number) and other.value == int(other.value):
            return int(other.value)
        if isinstance(other, n.ConstantRef):
            return _constant_values(context).get(other.name)
        if isinstance(other, n.VariableRef):  # the v3 reader takes a v4 constant for a name
            return _constant_values(context).get(other.name.text.upper())
        return None

    def _special(
        self, context: Context, file: FileView, statement: n.Statement, parent: n.Expression | None, value: int | None
    ) -> str | None:
        """A use whose v4 form is not a bit test of the same value (none by default)."""
        return None

    def _test(self, file: FileView, keyword: n.KeywordRef, operator: str, value: int, *, truth: bool) -> str:
        """The v4 test; a v3 comparison gave 1 or 0, and so does every form written here except
        the bare mask ``(AXISMODE & _mdJOG)``, which is kept where only its truth is used."""
        read = like(keyword.spelling, self.target) + selector_text(file, keyword)
        if value == 0:
            return f"{read} {operator} 0"
        if value in self.exact:
            return f"{read} {operator} {self.bits[value]}"
        test = f"({read} & {self.bits[value]})"
        if operator == "<>":
            return f"{test} = 0"
        return test if truth else f"{test} <> 0"

    @property
    def refusal(self) -> str:
        return f"{self.keyword} was a value, {self.target} is a bit pattern: rewrite this use as a bit test"


class ModeTest(BitTest):
    """v3 MODE returned one mode number; v4 AXISMODE is a bit pattern, so ``MODE = _jog``
    becomes ``(AXISMODE & _mdJOG) <> 0``, or ``(AXISMODE & _mdJOG)`` as a condition. Modes 9 and 18
    (following, gearing) become ``AXISMODE = _mdFOLLOW``: v3 MODE read 8 during an OFFSET on the follow
    and 15 during a clutch (v3:3704-3709, v3:3736), where v4 keeps the FOLLOW bit and adds OFFSET or FLY
    (v4:7119-7120, v4:14791-14793), so only the exact pattern says the offset or the clutch is over.
    Modes with no v4 bit (5 pulse following, 11, 17), order comparisons and arithmetic on MODE are flagged."""

    id = "S-MODE"
    summary = (
        "MODE[.n] = k / <> k -> (AXISMODE[.n] & _mdX) <> 0 / ... = 0 (the bare mask as a condition); "
        "MODE = 0 or _idle -> AXISMODE = 0"
    )
    evidence = "spec S-MODE; v3:10040-10061; v4:14045, v4:7094-7176"
    keyword = "MODE"
    target = "AXISMODE"
    bits = MODE_BITS
    without_bit = MODE_WITHOUT_BIT
    exact = frozenset({9, 18})

    def _special(
        self, context: Context, file: FileView, statement: n.Statement, parent: n.Expression | None, value: int | None
    ) -> str | None:
        """``PAUSE MODE = _pulse`` in a program that offsets waits for the OFFSET to end, the axis back in
        pulse following (v3:4274-4278): ``PAUSE !(AXISMODE & _mdOFFSET)`` (v4:14809), as the spec says."""
        if value != PULSE or type(statement) is not n.Pause or statement.condition is not parent:
            return None
        if not isinstance(parent, n.Binary) or parent.operator != "=":
            return None
        if next(context.keyword_uses("OFFSET"), None) is None:
            return None
        keyword = parent.left if isinstance(parent.left, n.KeywordRef) else parent.right
        assert isinstance(keyword, n.KeywordRef)
        return f"!({like(keyword.spelling, self.target)}{selector_text(file, keyword)} & _mdOFFSET)"


class ErrorTest(BitTest):
    """v3 ERROR returned one error number; v4 AXISERROR is a bit pattern ("Note the use of the
    error constants as bits and not values"). _limit is both hard-limit bits, spelled out
    because the v4 text swaps the names of the combined constants."""

    id = "S-ERROR"
    summary = "ERROR[.n] = _limit/_maxfe/_abort/_external -> (AXISERROR[.n] & <bits>) <> 0; ERROR = 0 -> AXISERROR = 0"
    evidence = "spec S-ERROR; v3:4995-5010; v4:9962, v4:6967-7081, v4:7035-7037"
    keyword = "ERROR"
    target = "AXISERROR"
    bits = ERROR_BITS
    without_bit = ERROR_WITHOUT_BIT
