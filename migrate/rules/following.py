"""Following: v3 chose the master with FOLLOWAXIS, v4 with MASTERSOURCE and MASTERCHANNEL."""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.diagnostics import Span
from mintlang.keyworddb.model import ValueRange
from mintlang.migrate.context import Context, FileView, per_pass, statement_tag
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.addressed import addressed_axes, writes_any
from mintlang.migrate.rules.axes import default_axes, selector_axes, selector_for
from mintlang.migrate.rules.base import Action, Rule, keyword_refs, selector_text, values_text, written
from mintlang.migrate.rules.gearing import master_increments
from mintlang.migrate.rules.literals import integer_literal
from mintlang.migrate.rules.notes import after_configuration
from mintlang.migrate.rules.spelling import like
from mintlang.migrate.rules.statements import Refusal, StatementRule, fill
from mintlang.syntax import nodes as n

_OFF_CONSTANTS = frozenset({"_OFF", "_CFOFF"})


class MasterSource(StatementRule):
    """FOLLOWAXIS becomes MASTERSOURCE and MASTERCHANNEL, which "replace the FOLLOWAXIS keyword"
    (v4:13949):

    * ``FOLLOWAXIS<axes> = m, ...`` with every m an axis 0..2 ->
      ``MASTERSOURCE<axes> = _msPOS; : MASTERCHANNEL<axes> = m, ...`` (MASTERSOURCE first:
      changing it resets MASTERCHANNEL, v4:13947);
    * every m = -1 (follow the SPEED demand) -> ``MASTERSOURCE<axes> = _msSPEED;`` whose
      default channel is the axis itself (v4:13967).

    The ``;`` stands where FOLLOWAXIS sets every axis it addresses; a write that sets fewer gets
    the source once per value instead (``FOLLOWAXIS = 1`` -> ``MASTERSOURCE = _msPOS``).

    Refused (manual item): -2, the pulse timer input (X-PULSE); 3..5, the v3 encoder
    board, which is AUXENCODER hardware in v4 (X-IO-EXP); mixed or computed values; a
    master axis position where the application configures an axis off (v4 then wants
    _msENCODER, v4:13938, and the item gives both statements: changing MASTERSOURCE resets
    MASTERCHANNEL, v4:13947); MintDrive and ServoNode 51, whose MASTERSOURCE takes 2 and 3
    only (v4:13926-13928); and an application that writes SCALE: v3 scaled MASTERINC by the
    master axis' SCALE (v3:3771-3777), v4 scales the master into the slave's user units
    (v4:13972-13977), so unscaled counts (SCALE never written, or written as 1) are the
    only case proven the same. The ramp a MASTERINC gave FOLLOW is S-CLUTCH's.
    """

    id = "S-MASTER"
    rule_class = RuleClass.SEMI
    summary = (
        "FOLLOWAXIS = 0..2 -> MASTERSOURCE = _msPOS; : MASTERCHANNEL = m; FOLLOWAXIS = -1 -> MASTERSOURCE = _msSPEED;"
    )
    evidence = "spec S-MASTER; v3:3771-3777, v3:8199-8209; v4:10773, v4:13925-13977"
    keywords = frozenset({"FOLLOWAXIS"})

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        if statement.values is None:
            return Refusal("FOLLOWAXIS read: the master is MASTERSOURCE and MASTERCHANNEL in v4")
        masters = {integer_literal(value) for value in statement.values if value is not None}
        if masters & {-2}:
            return Refusal("FOLLOWAXIS = -2 follows the pulse timer input: no v4 master source (see X-PULSE)")
        if masters & {3, 4, 5}:
            return Refusal("encoder-board master: MASTERSOURCE = _msAUXENCODER : MASTERCHANNEL = m - 3, if so wired")
        speed = masters == {-1}
        if not speed and not (masters and masters <= {0, 1, 2}):
            return Refusal("FOLLOWAXIS values are not all constant axes 0..2 (or all -1): set MASTERSOURCE by hand")
        if not speed and context.controller.controller in ("mintdrive", "servonode51"):
            return Refusal(f"{context.controller.title} cannot follow an axis position (MASTERSOURCE 2 or 3 only)")
        selector = selector_text(file, statement.keyword)
        source = f"{like(statement.keyword.spelling, 'MASTERSOURCE')}{selector}"
        channel = f"{like(statement.keyword.spelling, 'MASTERCHANNEL')}{selector} = {values_text(file, statement)}"
        if not speed and _configures_off(context):
            encoder = f"{source} = {_places(context, file, statement, '_msENCODER')} : {channel}"  # v4:13936-13947
            return Refusal(
                f"an axis is configured off: if it is the master, write {encoder} "
                "(in this order: MASTERSOURCE resets MASTERCHANNEL)"
            )
        if scale_is_set(context):
            return Refusal("SCALE is set: v4 scales the master into the slave's user units, v3 by the master's SCALE")
        if speed:
            return f"{source} = {_places(context, file, statement, '_msSPEED')}"
        return f"{source} = {_places(context, file, statement, '_msPOS')} : {channel}"


def _places(context: Context, file: FileView, statement: n.KeywordStatement, constant: str) -> str:
    """``constant`` for each axis FOLLOWAXIS sets: ``;`` where it sets every axis it names (or fills them
    itself), else once per value with its skipped places, since a v3 write sets the first axes of the
    list one value each (v3:1029-1066) and MASTERSOURCE resets the MASTERCHANNEL of every axis it is
    written on (v4:13947)."""
    selector = selector_text(file, statement.keyword)
    values = statement.values or ()
    axes = selector_axes(statement.keyword)
    if axes is None and statement.keyword.selector is None:
        axes = default_axes(context, file, statement.span.start)
    if statement.fill or (axes is not None and len(values) >= len(axes) and None not in values):
        return f"{constant}{fill(selector)}"
    return ", ".join(constant if value is not None else "" for value in values)


@per_pass
def scale_is_set(context: Context) -> bool:
    """Whether any axis may have a SCALE other than 1 (every use a write of literal 1s is not)."""
    for _, _, statement, keyword in keyword_refs(context, "SCALE"):
        if not (
            isinstance(statement, n.KeywordStatement)
            and written(statement, keyword)
            and statement.values
            and all(isinstance(value, n.Number) and value.value == 1 for value in statement.values)
        ):
            return True
    return False


@per_pass
def _configures_off(context: Context) -> bool:
    for _, _, statement in context.statements(statement_tag("CONFIG")):
        if isinstance(statement, n.KeywordStatement) and statement.keyword.keyword == "CONFIG":
            for value in statement.values or ():
                if (isinstance(value, n.Number) and value.value == 0) or (
                    isinstance(value, n.ConstantRef) and value.name in _OFF_CONSTANTS
                ):
                    return True
    return False


class DefaultMaster(Rule):
    """The master a v3 slave followed without a FOLLOWAXIS: by default axis 0 followed axis 1 and
    axis 1 axis 0 (v3:8199). v4's default master is channel 0's position for every axis
    (v4:9048-9050, v4:13925), the same for axis 1 but axis 0 itself for axis 0 (error 70,
    v4:18757-18761). So an application whose axis 0 follows (FOLLOW, FLY, CAM, a gearbox) and
    never chooses a master gets ``MASTERSOURCE.0 = _msPOS : MASTERCHANNEL.0 = 1``, as the v4
    guide's own port of the flying shear does (v4:3781-3804); an axis above 1 that follows with
    no FOLLOWAXIS has no documented v3 default: manual item. A target that takes neither value
    (MintDrive's master is its auxiliary encoder or a virtual axis, MASTERSOURCE 2 or 3 and
    MASTERCHANNEL 0, v4:13800-13804, v4:13918-13923) gets a manual item at the first following
    statement instead of a line it would reject."""

    id = "S-MASTER-DEFAULT"
    rule_class = RuleClass.SEMI
    phase = Phase.INSERTIONS
    summary = "axis 0 follows with no FOLLOWAXIS -> 'MASTERSOURCE.0 = _msPOS : MASTERCHANNEL.0 = 1' (v3's default)"
    evidence = "spec S-MASTER; v3:8199; v4:9048-9050, v4:13925, v4:3781-3804, v4:18757-18761"

    def apply(self, context: Context) -> Iterator[Action]:
        if writes_any(context, ("FOLLOWAXIS", "MASTERSOURCE", "MASTERCHANNEL")):
            return
        followers: set[int] = set()
        first: tuple[FileView, Span] | None = None  # where axis 0 first follows
        for file, line, statement, keyword in keyword_refs(context, *_FOLLOWING):
            if not written(statement, keyword):
                continue
            axes = None
            if isinstance(statement, n.KeywordStatement):
                axes = addressed_axes(context, file, statement, line.origin + statement.span.start)
            span = line.span(statement.span)
            if axes is None:
                yield self.flag(file, span, "the axes here are not known: choose the master (v3 default)")
                continue
            for axis in axes:
                if axis > 1 and axis not in followers:
                    yield self.flag(file, span, f"axis {axis} follows with no FOLLOWAXIS: choose its master")
            if first is None and 0 in axes:
                first = (file, span)
            followers.update(axes)
        if first is None or not context.supports("MASTERCHANNEL"):
            return
        source, channel = _range(context, "MASTERSOURCE"), _range(context, "MASTERCHANNEL")
        if (source is None or source.holds(0.0)) and (channel is None or channel.holds(1.0)):
            yield after_configuration(context, ["MASTERSOURCE.0 = _msPOS : MASTERCHANNEL.0 = 1"])
        else:
            taken = " and ".join(f"{name} {limits.text}" for name, limits in _ranges(source, channel))
            yield self.flag(*first, f"v3 axis 0 followed axis 1; this controller takes only {taken}: choose the master")


def _range(context: Context, keyword: str) -> ValueRange | None:
    """The values the target controller takes for ``keyword`` (None: no range printed)."""
    attributes = context.db.lookup(keyword).attributes_for(context.controller.controller)
    return None if attributes is None else attributes.range


def _ranges(source: ValueRange | None, channel: ValueRange | None) -> Iterator[tuple[str, ValueRange]]:
    for name, limits in (("MASTERSOURCE", source), ("MASTERCHANNEL", channel)):
        if limits is not None:
            yield name, limits


_FOLLOWING = ("FOLLOW", "FLY", "CAM", "CAMA", "GEARN")


class Clutch(StatementRule):
    """v3 FOLLOW ramped up to (and down from) its ratio over MASTERINC when one was set
    (v3:3716-3730); v4 does that only in FOLLOWMODE 2, ``_fmCLUTCH`` (v4:3529-3535, v4:3605-3630),
    its default mode 0 starting and stopping at once (v4:3491-3492, v4:3546). So a FOLLOW on an
    axis whose MASTERINC is a literal other than 1 becomes ``FOLLOWMODE.a = _fmCLUTCH : FOLLOW.a = r``
    in an application that chooses no FOLLOWMODE; a MASTERINC that may be 1 (no clutch in v3) or
    is computed leaves the choice to the user."""

    id = "S-CLUTCH"
    rule_class = RuleClass.SEMI
    summary = "FOLLOW on an axis with MASTERINC -> FOLLOWMODE = _fmCLUTCH : FOLLOW (v3 ramped over MASTERINC)"
    evidence = "spec S-GEAR, S-MASTER; v3:3716-3730; v4:3491-3492, v4:3529-3535, v4:3546, v4:3605-3630"
    keywords = frozenset({"FOLLOW"})

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        if statement.values is None or writes_any(context, ("FOLLOWMODE",)):
            return None
        increments = master_increments(context)
        axes = addressed_axes(context, file, statement, statement.span.start)
        if increments is None or axes is None:
            return Refusal("MASTERINC or FOLLOW axes are computed: choose FOLLOWMODE (clutch or not) by hand")
        written = [increments.get(axis, set()) for axis in axes]
        if not any(written):
            return None
        if any(None in values or 1 in values for values in written):
            return Refusal("a MASTERINC here may be 1 (v3: no clutch): choose FOLLOWMODE by hand")
        # only the axes that ramped: v3 locked the others at once (v3:3700), and v4 refuses FOLLOWMODE
        # on an axis already following (v4:3546)
        selector = selector_for(tuple(axis for axis, values in zip(axes, written, strict=True) if values))
        mode = f"{like(statement.keyword.spelling, 'FOLLOWMODE')}{selector} = _fmCLUTCH{fill(selector)}"
        return f"{mode} : {file.slice(statement.span)}"
