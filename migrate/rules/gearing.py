"""S-GEAR: the v3 software gearbox (GEARD, then GEARN) is a FOLLOW move in v4.

v3 sets the ratio as GEARN/GEARD, GEARD (1..32000) first, and GEARN (-32000..32000)
starts following (v3:8343-8450, v3:3758-3802). v4 has FOLLOW (-128..127, fractional,
v4:10721) and, on MintDrive and ServoNode 51 only, FOLLOWDENOM (1..128, v4:10777-10815):
the ratio is FOLLOW/FOLLOWDENOM (v4:3495; the example at v4:3500-3502, FOLLOWDENOM = 11 with
FOLLOW = 10 "for 1.1", contradicts that formula and the FOLLOWDENOM entry's own example,
so the formula is taken).
"""

from __future__ import annotations

from collections.abc import Iterator
from fractions import Fraction

from mintlang.migrate.context import Context, FileView, name_tag, per_pass, statement_tag
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.axes import axis_values, default_axes, selector_axes, selector_for
from mintlang.migrate.rules.base import Action, Rule
from mintlang.migrate.rules.literals import integer_literal
from mintlang.migrate.rules.spelling import like
from mintlang.migrate.rules.statements import Refusal
from mintlang.records import record
from mintlang.semantic.index import Use
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n

DENOMINATORS = range(1, 129)  # FOLLOWDENOM (v4:10798)
RATIOS = (Fraction(-128), Fraction(127))  # FOLLOW (v4:10721)
_MANTISSA = 1 << 24  # v4 numbers are floats with a 24-bit mantissa (v4:715-720)


@record
class Gear:
    """What the application proves about one axis' gearbox."""

    denominator: int  # the one literal GEARD value written to the axis
    numerators: frozenset[int]  # every literal GEARN value written to it
    clutch: bool  # a MASTERINC is in force: v3 ramps up to the ratio over it

    def keeps_denominator(self, context: Context) -> bool:
        """Whether FOLLOWDENOM can hold the denominator and FOLLOW every numerator as written."""
        return (
            context.supports("FOLLOWDENOM")
            and self.denominator in DENOMINATORS
            and all(RATIOS[0] <= numerator <= RATIOS[1] for numerator in self.numerators)
        )


def exact(ratio: Fraction) -> bool:
    """Whether a v4 float holds ``ratio`` exactly (a power-of-two denominator, 24-bit numerator)."""
    return ratio.denominator & (ratio.denominator - 1) == 0 and abs(ratio.numerator) < _MANTISSA


class Gearing(Rule):
    """GEARD/GEARN become FOLLOWDENOM/FOLLOW, with explicit axes (v4 defaults to other axes):

    * MintDrive and ServoNode 51, denominator 1..128 and every numerator -128..127:
      ``GEARD = d`` -> ``FOLLOWDENOM.a = d``, ``GEARN = n`` -> ``FOLLOW.a = n`` (exact);
    * otherwise ``GEARN = n`` -> ``FOLLOW.a = n / d``; GEARD becomes ``FOLLOWDENOM.a = 1``
      where FOLLOWDENOM exists, and a REM line on NextMove (it has no FOLLOWDENOM). A ratio
      a v4 float cannot hold exactly also gets a manual item: v3's integer ratio did not drift.
    * An application that sets MASTERINC (MASTERDISTANCE) on the axis gets
      ``FOLLOWMODE.a = _fmCLUTCH`` before FOLLOW: v3 ramped up to the ratio over MASTERINC
      and down again on STOP, which is v4's clutch mode (v4:10857-10861, v3:3780-3801).

    The denominator at a GEARN is proven when every GEARD of that axis writes one literal
    (v3 refuses GEARN before GEARD, v3:8377) and no CANCEL, DISLIMIT or RESET can set it back
    to 1 (v3:6584; v4's leave FOLLOW and FOLLOWDENOM as they are, v4:7985-8016): one in the
    program, or in the configuration file after a GEARD. Manual items: computed values or axes, two
    GEARD values for one axis, a ratio outside FOLLOW's range, a MASTERINC of 1 (v3: no
    clutch, v3:3801) or a computed one, reads, and a GEARD sharing its line on NextMove.
    ``MODE = 18`` (gearbox) is S-MODE's ``_mdFOLLOW``.
    """

    id = "S-GEAR"
    rule_class = RuleClass.SEMI
    phase = Phase.CONTEXT
    summary = (
        "GEARD = d / GEARN = n -> FOLLOWDENOM.a = d / FOLLOW.a = n (or FOLLOW.a = n / d); + _fmCLUTCH if MASTERINC"
    )
    evidence = "spec S-GEAR; v3:8343-8450, v3:3758-3802; v4:10699-10815, v4:10857-10861, v4:3493-3502, v4:13871-13873"

    def apply(self, context: Context) -> Iterator[Action]:
        gears = _gears(context)
        for file, use in context.keyword_uses("GEARN", "GEARD"):
            statement = use.statement
            if use.use is Use.READ or not isinstance(statement, n.KeywordStatement) or not statement.values:
                yield self.flag(file, statement.span, f"reading {use.keyword.keyword}: read FOLLOW (the ratio) in v4")
                continue
            proven = _proven(gears, axis_values(context, file, statement))
            if isinstance(proven, Refusal):
                yield self.flag(file, statement.span, proven)
                continue
            selector = selector_for(tuple(axis for axis, _, _ in proven))
            if statement.keyword.keyword == "GEARD":
                result = _denominators(context, file, statement, proven, selector)
                if isinstance(result, Refusal):
                    yield self.flag(file, statement.span, result)
                else:
                    yield self.replace(file, statement.span, result)
                continue
            yield self.replace(file, statement.span, _follow(context, statement, proven, selector))
            if not all(gear.keeps_denominator(context) or exact(_ratio(gear, value)) for _, gear, value in proven):
                yield self.flag(file, statement.span, "FOLLOW = n / d is a float ratio: v3's n/d could not drift")


Proven = list[tuple[int, Gear, n.Expression]]


def _proven(gears: dict[int, Gear | Refusal], pairs: tuple[tuple[int, n.Expression], ...]) -> Proven | Refusal:
    """Each written axis with its proven gearbox and the value written, or the first refusal."""
    if not pairs:
        return Refusal("the axes are not constant: write FOLLOW[axes] = n / d by hand")
    proven: Proven = []
    for axis, value in pairs:
        gear = gears[axis]
        if isinstance(gear, Refusal):
            return gear
        proven.append((axis, gear, value))
    return proven


def _denominators(
    context: Context, file: FileView, statement: n.KeywordStatement, proven: Proven, selector: str
) -> str | Refusal:
    if not context.supports("FOLLOWDENOM"):
        if not file.last_on_its_line(statement):
            return Refusal(f"{context.controller.title} has no FOLLOWDENOM: FOLLOW takes n / d; delete this GEARD")
        return f"REM {file.slice(statement.span)}: folded into FOLLOW = n / d by mint-migrate"
    values = ", ".join(str(gear.denominator) if gear.keeps_denominator(context) else "1" for _, gear, _ in proven)
    return f"{like(statement.keyword.spelling, 'FOLLOWDENOM')}{selector} = {values}"


def _follow(context: Context, statement: n.KeywordStatement, proven: Proven, selector: str) -> str:
    spelling = statement.keyword.spelling
    values = ", ".join(
        str(integer_literal(value))
        if gear.keeps_denominator(context)
        else f"{integer_literal(value)} / {gear.denominator}"
        for _, gear, value in proven
    )
    follow = f"{like(spelling, 'FOLLOW')}{selector} = {values}"
    if any(gear.clutch for _, gear, _ in proven):
        return f"{like(spelling, 'FOLLOWMODE')}{selector} = _fmCLUTCH : {follow}"
    return follow


def _ratio(gear: Gear, value: n.Expression) -> Fraction:
    return Fraction(integer_literal(value) or 0, gear.denominator)


def _gears(context: Context) -> dict[int, Gear | Refusal]:
    """Per axis with a GEARD or GEARN write: what is proven about its gearbox, or why not."""
    denominators: dict[int, set[int | None]] = {}
    numerators: dict[int, set[int | None]] = {}
    reset: set[int] | None = set()  # axes whose GEARD a reset can set back to 1 (None: every axis)
    for file, _, statement in context.statements(*map(statement_tag, ("GEARD", "GEARN", *_RESETS))):
        if not isinstance(statement, n.KeywordStatement):
            continue
        word = statement.keyword.keyword
        if word in ("GEARD", "GEARN"):
            found = denominators if word == "GEARD" else numerators
            for axis, value in axis_values(context, file, statement):
                found.setdefault(axis, set()).add(integer_literal(value))
        elif word in _RESETS and reset is not None:
            axes = selector_axes(statement.keyword)
            if axes is None and statement.keyword.selector is None:
                axes = default_axes(context, file, statement.span.start)
            if file.unit is Unit.PROGRAM:
                reset = None if axes is None else reset | set(axes)
            else:  # the configuration file runs first: it resets only a gearbox it set up before
                reset |= denominators.keys() if axes is None else denominators.keys() & set(axes)
    increments = master_increments(context)
    gears: dict[int, Gear | Refusal] = {}
    for axis in denominators.keys() | numerators.keys():
        gear = _gear(axis, denominators.get(axis, set()), numerators.get(axis, set()), increments)
        if isinstance(gear, Gear) and gear.denominator != 1 and (reset is None or axis in reset):
            gear = Refusal(
                f"a CANCEL, DISLIMIT or RESET of axis {axis} sets its GEARD back to 1 in v3: "
                "write FOLLOW = n / d by hand"
            )
        gears[axis] = gear
    return gears


# v3 CANCEL, DISLIMIT and RESET set GEARN and GEARD back to 0 and 1 (v3:6584, v3:7469, v3:11427-11446)
_RESETS = ("CANCEL", "DISLIMIT", "RESET")


def _gear(
    axis: int, denominators: set[int | None], numerators: set[int | None], increments: dict[int, set[int | None]] | None
) -> Gear | Refusal:
    if not denominators:
        return Refusal(f"no GEARD for axis {axis}: v3 needs GEARD before GEARN")
    denominator = next(iter(denominators)) if len(denominators) == 1 else None
    if denominator is None or denominator < 1:
        return Refusal(f"GEARD of axis {axis} is computed or takes several values: write FOLLOW = n / d by hand")
    known = frozenset(numerator for numerator in numerators if numerator is not None)
    if len(known) != len(numerators):
        return Refusal(f"GEARN of axis {axis} is computed: FOLLOW takes -128..127, write FOLLOW = n / d by hand")
    if any(not RATIOS[0] <= Fraction(numerator, denominator) <= RATIOS[1] for numerator in known):
        return Refusal(f"a gear ratio of axis {axis} is outside FOLLOW's -128..127")
    if increments is None:
        return Refusal("MASTERINC is written to computed axes: choose FOLLOWMODE (clutch or not) by hand")
    written = increments.get(axis, set())
    if None in written or 1 in written:
        return Refusal(f"MASTERINC of axis {axis} may be 1 (v3: no clutch): choose FOLLOWMODE by hand")
    return Gear(denominator, known, bool(written))


@per_pass
def master_increments(context: Context) -> dict[int, set[int | None]] | None:
    """The literal MASTERINC (MASTERDISTANCE after M-REN) values per axis; None for computed axes.

    A MASTERDISTANCE written without axes reads to the v3 parser as an assignment to a name.
    """
    found: dict[int, set[int | None]] = {}
    written = (statement_tag("MASTERINC"), statement_tag("MASTERDISTANCE"), name_tag("MASTERDISTANCE"))
    for file, _, statement in context.statements(*written):
        if isinstance(statement, n.KeywordStatement) and statement.keyword.keyword in ("MASTERINC", "MASTERDISTANCE"):
            pairs = axis_values(context, file, statement)
            if not pairs:
                return None
        elif _assigns(statement, "MASTERDISTANCE"):
            axes = default_axes(context, file, statement.span.start)
            if not axes:
                return None
            pairs = ((axes[0], statement.value),)
        else:
            continue
        for axis, value in pairs:
            found.setdefault(axis, set()).add(integer_literal(value))
    return found


def _assigns(statement: n.Statement, name: str) -> bool:
    return (
        isinstance(statement, n.Assignment)
        and isinstance(statement.target, n.VariableRef)
        and statement.target.name.identity == n.identity(name)
    )
