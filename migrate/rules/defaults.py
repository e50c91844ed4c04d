"""v3 power-up defaults that Mint v4 changed, where a program relies on them.

A program relies on a default on an axis when it uses the parameter there (moves
the axis, homes it, waits for IDLE) and never writes it for that axis (``SPEED.1 = 30``
leaves axis 0's SPEED at its default); a write whose axes are not known counts for all.
Only servo axes count: the stepper defaults are the same in both versions
(v3:6940-6948, v4:9005-9050), so an axis given a constant stepper CONFIG is left out.

Two rules share the table. S-DEFAULTS (on by default) reports each default
relied on as a ``REM MIGRATE:`` line at the top of the application carrying the
v4 statement that restores the v3 value. S-DEFAULTS-V3 (opt-in, ``--with``)
writes those statements. Opt-in because the v4 values are the safer ones on a
production machine: FOLERRORFATAL 16000 trips 16 times later than v4's 1000;
an engineer porting a machine that must behave exactly as before asks for them,
everyone else decides per parameter from the report. Where the v3 manual gives
two defaults (SPEED, ACCEL, HMSPEED) nothing is written, only reported. Values
are written where the prologue notes go: after the last CONFIG (a v4 CONFIG
calls DEFAULT, which resets them and SCALE, v4:8481-8482, v4:9006-9059), else at
the top; either way before the program's own SCALE, so they are counts, as the
v3 power-up defaults were.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

from mintlang.migrate.context import Context
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.addressed import (
    MOVES,
    POSITIONAL,
    RAMPED,
    addressed_axes,
    axis_list,
    moved_axes,
    on_target,
    read_axes,
    writes_unplaced,
)
from mintlang.migrate.rules.base import Action, Rule, keyword_refs, written
from mintlang.migrate.rules.notes import after_configuration, prologue_notes
from mintlang.records import record
from mintlang.syntax import nodes as n

_STEPPER_VALUES = frozenset({"_STEPPER", "_MICRO", "_CFSTEPPER"})  # CONFIG 2 and 3: v3:6931-6936


@record
class Default:
    """One parameter whose servo default changed: the v4 statements that restore v3's value."""

    keywords: tuple[str, ...]  # the v4 keywords to write (ACCEL and DECEL: v3 ACCEL also set DECEL)
    written_as: frozenset[str]  # v3 and v4 names whose write means the program sets it itself
    v3_value: int | None  # None: the v3 manual gives two values, so nothing is written for it
    v3_text: str  # the v3 default as the manual gives it
    v4_value: int
    users: Callable[[Context], tuple[int, ...] | None]  # the axes relying on it (None: unknown)

    def statements(self, axes: tuple[int, ...], value: str) -> tuple[str, ...]:
        return tuple(f"{keyword}{axis_list(axes)} = {value};" for keyword in self.keywords)


def _moving(context: Context) -> tuple[int, ...] | None:
    return moved_axes(context, MOVES)


def _profiled(context: Context) -> tuple[int, ...] | None:
    return moved_axes(context, POSITIONAL)


def _ramped(context: Context) -> tuple[int, ...] | None:
    return moved_axes(context, RAMPED)


def _homing(context: Context) -> tuple[int, ...] | None:
    return moved_axes(context, ("HOME",))


def _waiting_for_idle(context: Context) -> tuple[int, ...] | None:
    return read_axes(context, ("IDLE",))


DEFAULTS: tuple[Default, ...] = (
    # v3:9989 MFOLERR 16000; v4:9029, v4:10667 FOLERRORFATAL 1000
    Default(("FOLERRORFATAL",), frozenset({"MFOLERR", "FOLERRORFATAL"}), 16000, "16000", 1000, _moving),
    # v3:8741, v3:8760-8780 IDLE window 16000; v4:9036 IDLEPOS 1000
    Default(("IDLEPOS",), frozenset({"IDLE", "IDLEPOS"}), 16000, "16000", 1000, _waiting_for_idle),
    # v3:11797 says 40000, the CONFIG table v3:6943 says 80000; v4:16169, v4:9050 SPEED 20000
    Default(("SPEED",), frozenset({"SPEED"}), None, "40000 (80000 in the CONFIG table)", 20000, _profiled),
    # The v3 manual disagrees with itself on ACCEL and HMSPEED: the keyword entries give the v4 values
    # (ACCEL 300,000 at v3:5645, HMSPEED 40000 at v3:8632), the CONFIG table others (v3:6945-6947). DECEL
    # follows ACCEL in v3 (v3:5662); v4:6160, v4:9009 ACCEL/DECEL 300000; v4:9035 HOMESPEED 40000.
    Default(
        ("ACCEL", "DECEL"),
        frozenset({"ACCEL", "ACCELTIME", "DECEL"}),
        None,
        "300000 (3000000 in the CONFIG table)",
        300000,
        _ramped,
    ),
    Default(
        ("HOMESPEED",), frozenset({"HMSPEED", "HOMESPEED"}), None, "40000 (20000 in the CONFIG table)", 40000, _homing
    ),
)


def relied_on(context: Context) -> Iterator[tuple[Default, tuple[int, ...]]]:
    """Each changed default the application relies on, with the servo axes of the target that rely on it."""
    steppers = _stepper_axes(context)
    for default in DEFAULTS:
        set_on = _set_on(context, default)
        if set_on is None:
            continue
        users = on_target(context, default.users(context))
        servo = tuple(axis for axis in users if axis not in steppers and axis not in set_on)
        if servo:
            yield default, servo


def _set_on(context: Context, default: Default) -> tuple[int, ...] | None:
    """The axes the application writes the parameter on, or None when a write's axes are not
    known (computed, a write the v3 reader takes for a variable's or cannot parse, as the M-REN
    rename of a fill: ``MFOLERR = 5;`` read as ``FOLERRORFATAL = 5;``): then it may set it on all.
    A write a constant IF condition keeps from running is none: the program never writes it (spec
    S-DEFAULTS); one that depends on the run (``IF IN1 THEN``) counts, as the spec asks only about
    programs that never write it."""
    axes = moved_axes(context, default.written_as, True)
    if axes is None or writes_unplaced(context, default.written_as):
        return None
    return axes


def _stepper_axes(context: Context) -> set[int]:
    """Axes a CONFIG write with constant axes makes stepper or micro-stepper."""
    found: set[int] = set()
    for file, line, statement, keyword in keyword_refs(context, "CONFIG"):
        if not written(statement, keyword):
            continue
        assert isinstance(statement, n.KeywordStatement)
        axes = addressed_axes(context, file, statement, line.origin + statement.span.start) or ()
        values = statement.values or ()
        for position, axis in enumerate(axes):
            value = values[min(position, len(values) - 1)] if values else None
            if _is_stepper(value):
                found.add(axis)
    return found


def _is_stepper(value: n.Expression | None) -> bool:
    match value:
        case n.Number(value=number):
            return number in {2, 3}
        case n.ConstantRef(name=name):
            return name.upper() in _STEPPER_VALUES
        case n.VariableRef(name=name):
            return name.text.upper() in _STEPPER_VALUES
    return False


class ReportDefaults(Rule):
    """A default the program relies on is reported at the top of the application with the v4
    statement that restores the v3 value; the program still compiles and nothing changes
    behind the user's back (see the module docstring for why writing them is opt-in)."""

    id = "S-DEFAULTS"
    rule_class = RuleClass.MANUAL
    phase = Phase.MANUAL
    summary = "moves/HOME/IDLE relying on a changed default -> REM MIGRATE line with the v4 statement"
    evidence = "spec S-DEFAULTS; v3:9989, v3:8741, v3:11797, v3:6940-6948; v4:9005-9050, v4:10667, v4:16169"
    notes = True

    def apply(self, context: Context) -> Iterator[Action]:
        notes = []
        for default, axes in relied_on(context):
            value = "<value>" if default.v3_value is None else str(default.v3_value)
            restore = " : ".join(default.statements(axes, value))
            how = "" if default.v3_value is None else " (--with S-DEFAULTS-V3 writes it)"
            notes.append(f"{restore} : REM v3 default {default.v3_text}, v4 {default.v4_value}{how}")
        yield from prologue_notes(context, self.id, notes)


class KeepV3Defaults(Rule):
    """Writes the statements S-DEFAULTS reports, for a port that must behave exactly like the
    v3 machine. SPEED is left to the report: the v3 manual gives two different defaults. ACCEL
    and its DECEL share a line, the form S-ACCEL writes, so a second migration leaves them be."""

    id = "S-DEFAULTS-V3"
    rule_class = RuleClass.SEMI
    phase = Phase.INSERTIONS
    optional = True
    summary = "changed default relied on -> 'FOLERRORFATAL[axes] = 16000;' etc. at the top (opt-in)"
    evidence = "spec S-DEFAULTS; v3:9989, v3:8741, v3:6945-6948, v3:5662; v4:9005-9050, v4:10667"

    def apply(self, context: Context) -> Iterator[Action]:
        lines = [
            " : ".join(default.statements(axes, str(default.v3_value)))
            for default, axes in relied_on(context)
            if default.v3_value is not None
        ]
        if lines:
            yield after_configuration(context, lines)
