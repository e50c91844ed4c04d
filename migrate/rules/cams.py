"""S-CAM: a v3 cam started on the implicit tables cam<n>/minc<n>; v4 names its tables with
CAMTABLE and loads the cam with CAM, which GO starts.

v3 CAM (relative) and CAMA (absolute within the cycle) take 0 one shot, 1 continuous,
2 one shot on the fast interrupt, 3 continuous restarted by each fast interrupt, and
CAMA +4 positions absolute to the motor (v3:6333-6431, v3:3861-3960). The v4 CAM value
is a bit pattern (v4:7595-7619) and the tables are any arrays given to CAMTABLE
(v4:7898-7962); a cam waits for GO unless triggered by the fast latch (v4:7613-7619,
v4:3872). Both keep the segment count in the first element of the position table.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from types import MappingProxyType

from mintlang.migrate.context import Context, FileView, statement_tag
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.axes import axis_values, selector_for
from mintlang.migrate.rules.base import Action, Rule, keyword_refs
from mintlang.migrate.rules.following import scale_is_set
from mintlang.migrate.rules.literals import integer_literal
from mintlang.migrate.rules.spelling import like
from mintlang.migrate.rules.statements import Refusal
from mintlang.semantic.symbols import SymbolKind
from mintlang.syntax import nodes as n

# v3 CAM value -> v4 CAM bits (spec S-CAM).
CAM_BITS: Mapping[int, str] = MappingProxyType(
    {0: "0", 1: "_cmCONTINUOUS", 2: "_cmTRIGGER", 3: "_cmCONTINUOUS + _cmTRIGGER + _cmRETRIGGER"}
)
_ABSOLUTE = ("_cmABSOLUTE", "_cmABSOLUTE + _cmT_ABSOLUTE")  # CAMA, CAMA + 4
_TRIGGERED = frozenset({2, 3})
_CONTINUOUS = frozenset({1, 3})
_CAM_AXES = frozenset({0, 1})  # v3 cams run on axes 0 and 1 only (v3:6372)


def cam_bits(keyword: str, value: int) -> str | None:
    """The v4 CAM value for a v3 ``CAM``/``CAMA`` value, or None outside v3's range."""
    if keyword == "CAM":
        return CAM_BITS.get(value)
    if not 0 <= value <= 7:
        return None
    base = CAM_BITS[value % 4]
    return _ABSOLUTE[value // 4] if base == "0" else f"{_ABSOLUTE[value // 4]} + {base}"


class Cams(Rule):
    """``CAM.n = m`` / ``CAMA.n = m`` become ``CAMTABLE(n, cam<n>, minc<n> or NULL) :
    CAM.n = <bits> : GO.n`` (no GO for the fast-interrupt modes, which the latch starts).

    The arrays stay as they are: v3's cam<n> and minc<n> are the tables of axis n. Mode 2
    gets a manual item as well: v3 started a one-shot triggered cam again on each later fast
    interrupt, even mid-cam (v3:3949), which _cmTRIGGER alone does not do and
    _cmRETRIGGER does only after the cam ends (v4:7616-7619).

    Manual items: computed axes or values, an axis other than 0 and 1, no ``DIM cam<n>``,
    fast-interrupt and started modes in one statement, a program using CAMSTART or CAMEND
    (CAMTABLE resets them, v4:7960), a minc table while SCALE is set (v3 minc is counts,
    v4 master tables are the master's user units, v3:3888, v4:7953: the item gives the
    statement to write once the table is converted), and a cam
    written while an earlier continuous cam may run: v3 queued it ("stop at the end of the
    cycle", v3:3916-3936), v4 loads no move during a cam (v4:7726-7727) and stops at the
    end with STOP (v4:3892-3898). Reading CAM is S-READ's manual item.

    A CAM already preceded by CAMTABLE on its line is this rule's output (v3 has no
    CAMTABLE) and is left alone.
    """

    id = "S-CAM"
    rule_class = RuleClass.SEMI
    phase = Phase.CONTEXT
    summary = "CAM/CAMA.n = m -> CAMTABLE(n, cam<n>, minc<n>|NULL) : CAM.n = <_cm bits> : GO.n"
    evidence = "spec S-CAM; v3:3861-3960, v3:6333-6431; v4:3844-3931, v4:7539-7751, v4:7898-7974"

    def apply(self, context: Context) -> Iterator[Action]:
        ranged = next(keyword_refs(context, "CAMSTART", "CAMEND"), None) is not None
        continuous: set[int] = set()
        for file, _, statement in context.statements(statement_tag("CAM"), statement_tag("CAMA")):
            if not _cam_write(statement):
                continue
            assert isinstance(statement, n.KeywordStatement)
            pairs = axis_values(context, file, statement)
            axes = {axis for axis, _ in pairs}
            queued = bool(axes & continuous)
            continuous |= {axis for axis, value in pairs if _runs_on(file, statement, value)}
            if _migrated(file, statement):
                continue
            result = Refusal(
                "an earlier continuous cam may still run: v3 queued this cam, v4 needs STOP : PAUSE IDLE first"
            )
            if not queued:
                result = self._rewrite(context, file, statement, pairs, ranged)
            if isinstance(result, Refusal):
                yield self.flag(file, statement.span, result)
                continue
            yield self.replace(file, statement.span, result)
            if any(integer_literal(value) == 2 for _, value in pairs):
                yield self.flag(
                    file,
                    statement.span,
                    "v3 also restarted this one-shot cam on later fast interrupts (v3:3949): consider _cmRETRIGGER",
                )

    @staticmethod
    def _rewrite(
        context: Context,
        file: FileView,
        statement: n.KeywordStatement,
        pairs: tuple[tuple[int, n.Expression], ...],
        ranged: bool,
    ) -> str | Refusal:
        word = statement.keyword.keyword
        if not pairs:
            return Refusal(f"{word}: the axes are not constant; write CAMTABLE, CAM and GO by hand")
        if ranged:
            return Refusal("CAMTABLE resets CAMSTART and CAMEND: place CAMTABLE(axis, cam, minc) before they are set")
        modes = [integer_literal(value) for _, value in pairs]
        bits = [cam_bits(word, mode) if mode is not None else None for mode in modes]
        if None in bits:
            return Refusal(f"{word} value is not a constant v3 mode (0..3, CAMA 0..7)")
        triggered = {mode % 4 in _TRIGGERED for mode in modes if mode is not None}
        if len(triggered) > 1:
            return Refusal("fast-interrupt and started cams in one statement: GO only the started axes")
        tables = []
        in_counts = []  # master tables to convert by hand
        for axis, _ in pairs:
            table = _tables(context, axis)
            if isinstance(table, Refusal):
                return table
            positions, masters = table
            if masters is not None and scale_is_set(context):
                in_counts.append(masters)
            tables.append(f"{like(statement.keyword.spelling, 'CAMTABLE')}({axis}, {positions}, {masters or 'NULL'})")
        selector = selector_for(tuple(axis for axis, _ in pairs))
        cam = f"{like(statement.keyword.spelling, 'CAM')}{selector} = {', '.join(str(bit) for bit in bits)}"
        go = [] if triggered == {True} else [f"{like(statement.keyword.spelling, 'GO')}{selector}"]
        written = " : ".join([*tables, cam, *go])
        if in_counts:
            names = " and ".join(in_counts)
            verb = "is" if len(in_counts) == 1 else "are"
            return Refusal(
                f"{names} {verb} in counts, a v4 master table in the master's user units: SCALE is set; "
                f"once {names} {verb} in those units, write {written}"
            )
        return written


def _tables(context: Context, axis: int) -> tuple[str, str | None] | Refusal:
    """``cam<n>`` and ``minc<n>`` (None if not declared) as the program spells them, or why not."""
    if axis not in _CAM_AXES:
        return Refusal(f"v3 runs cams on axes 0 and 1 only, not on axis {axis}")
    positions = _array(context, f"cam{axis}")
    if positions is None:
        return Refusal(f"no DIM cam{axis}: v3 took axis {axis}'s cam table from cam{axis}")
    return positions, _array(context, f"minc{axis}")


def _array(context: Context, name: str) -> str | None:
    symbol = context.model.symbols.variables.get(n.identity(name))
    if symbol is None or symbol.kind is not SymbolKind.ARRAY or not symbol.definitions:
        return None
    return symbol.name


def _cam_write(statement: n.Statement) -> bool:
    return (
        isinstance(statement, n.KeywordStatement)
        and statement.keyword.keyword in ("CAM", "CAMA")
        and statement.values is not None
    )


def _migrated(file: FileView, statement: n.Statement) -> bool:
    return "CAMTABLE" in file.text[file.line_start(statement.span.start) : statement.span.start].upper()


def _runs_on(file: FileView, statement: n.KeywordStatement, value: n.Expression) -> bool:
    """Whether the cam written keeps running (continuous), in v3 numbers or in this rule's output."""
    mode = integer_literal(value)
    if mode is not None and not _migrated(file, statement):
        return mode % 4 in _CONTINUOUS
    return "_CMCONTINUOUS" in file.slice(value.span).upper()
