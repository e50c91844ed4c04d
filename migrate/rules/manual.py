"""Manual items: what cannot be rewritten safely is flagged, never dropped or guessed.

The original statement stays; a ``REM MIGRATE: <rule>: <reason>`` line above it
says what to do, and the report lists it. The last rule of this phase flags any
Mint v3 word still left, so nothing reaches the output silently unmigrated; then,
with every marker in place, X-CHECK reads the result as Mint v4 for the target
controller and flags each line still in error that carries no marker yet.
"""

from __future__ import annotations

import re
from bisect import bisect_right
from collections.abc import Callable, Iterable, Iterator, Mapping
from functools import cache
from typing import ClassVar

import mintlang
from mintlang.caching import apart
from mintlang.diagnostics import Diagnostic, Severity, Span
from mintlang.dialect import Dialect
from mintlang.migrate.context import LABEL, Context, FileView, constant_tag, per_pass, statement_tag
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Flag, Rule
from mintlang.migrate.rules.defaults import ReportDefaults
from mintlang.migrate.rules.prologue import IoPrologue
from mintlang.migrate.rules.remarks import missing_rem, takes_operands
from mintlang.migrate.rules.renames import same_value_constants
from mintlang.semantic.events import EventKind, event_of
from mintlang.semantic.units import Unit
from mintlang.semantic.v3_declarations import UNDEFINED_VARIABLE
from mintlang.syntax import nodes as n
from mintlang.syntax.alike import carry_to_v4


def keyword_nodes(
    context: Context, keep: Callable[[str], bool]
) -> Iterator[tuple[FileView, n.Statement, str, n.KeywordRef | n.Call]]:
    """Every keyword and function written in an expression or as a statement whose canonical
    name ``keep`` accepts, name first: the keywords in compile order, then the functions. Only
    the lines that name one are read (a dozen rules ask, each for a few names)."""
    names = context.mentioned(keep)
    for file, use in context.keyword_uses(*names):
        yield file, use.statement, use.keyword.keyword, use.keyword
    for file, _, statement in context.statements(*names):
        for root in n.expressions_of(statement):
            for node in n.walk_expression(root):
                if isinstance(node, n.Call) and keep(node.function):
                    yield file, statement, node.function, node
        if isinstance(statement, n.FunctionStatement) and keep(statement.call.function):
            yield file, statement, statement.call.function, statement.call


class ManualKeywords(Rule):
    """Flags every use of some v3 keywords with one reason (subclasses set both)."""

    rule_class = RuleClass.MANUAL
    phase = Phase.MANUAL
    keywords: ClassVar[frozenset[str]]
    reason: ClassVar[str] = ""
    reasons: ClassVar[Mapping[str, str]] = {}  # per keyword, where one reason does not fit all

    def apply(self, context: Context) -> Iterator[Action]:
        for file, statement, keyword, _ in keyword_nodes(context, self.keywords.__contains__):
            yield self.flag(file, statement.span, f"{keyword}: {self.reasons.get(keyword, self.reason)}")


class PulseFollowing(ManualKeywords):
    """v3 PULSE follows a pulse/direction input with a ramp; the v4 guide's "PULSE replaced by
    STEPPERIO" is a different keyword. The v4 equivalent is FOLLOW (FOLLOWMODE 1) on a master
    source wired to an encoder input: a hardware decision."""

    id = "X-PULSE"
    summary = "PULSE, PULSEVEL, TIMER, WRAP -> manual (FOLLOW with a master source; not STEPPERIO)"
    evidence = "spec X-PULSE; v3:11133-11157; v4:15431, v4:3524-3527, v4:2436"
    keywords = frozenset({"PULSE", "PULSEVEL", "TIMER", "WRAP"})
    reason = "pulse-train input: use FOLLOW with MASTERSOURCE on an encoder input (not STEPPERIO)"


class IncrementalMoves(ManualKeywords):
    """v3 INCA/INCR change the end point of a running MOVEA/MOVER and read back a success flag;
    v4 INCA/INCR are a move type of their own that starts from idle with GO."""

    id = "X-INCA"
    summary = "INCA, INCR -> manual (v4 INCA/INCR are their own move type; start the move as INCA/INCR)"
    evidence = "spec X-INCA; v3:3200-3224, v3:9049; v4:12037-12053, v4:3142-3172, v4:4975"
    keywords = frozenset({"INCA", "INCR"})
    reason = "v4 cannot modify a running MOVEA/MOVER: start the move itself as INCA/INCR with GO"


class ServoOnAgain(ManualKeywords):
    """v3 SERVON returns the axis to where it was at SERVOFF; v4 needs the position saved
    when the servo went off, then CANCEL and a MOVEA back."""

    id = "X-SERVON"
    summary = "SERVON -> manual (save POS at SERVOFF; CANCEL : MOVEA = saved : GO)"
    evidence = "spec X-SERVON; v3:11757; v4:15899, v4:2770-2778"
    keywords = frozenset({"SERVON"})
    reason = "save POS where the servo went off, then CANCEL : MOVEA = saved : GO"


class Trigger(ManualKeywords):
    """v3 TRIGGER starts moves on an input; v4 has no equivalent apart from CAM triggers on the
    fast latch: the move must move into an #INn handler."""

    id = "X-TRIGGER"
    summary = "TRIGGER -> manual (start the move from an #INn handler)"
    evidence = "spec X-TRIGGER; v3:4184-4192, v3:12199-12214; v4:7613-7619"
    keywords = frozenset({"TRIGGER"})
    reason = "no v4 equivalent: start the triggered move from an #INn handler"


class ExpansionBoards(ManualKeywords):
    """The 24-bit I/O board and the 3-channel encoder board of v3 do not exist in v4: remote
    I/O is on CAN, extra encoders are AUXENCODER channels."""

    id = "X-IO-EXP"
    summary = "XIO, XIO0..7, XOUT, XENCODER -> manual (CAN remote I/O, AUXENCODER)"
    evidence = "spec X-IO-EXP; v4:6693-6720"
    keywords = frozenset({"XIO", "XOUT", "XENCODER", *(f"XIO{i}" for i in range(8))})
    reason = "expansion board not in Mint v4: use CAN remote I/O or AUXENCODER.channel"


class Keypad(ManualKeywords):
    """The bus keypad, LCD and status LED of v3 are gone; v4 keypads are CAN keypadNodes."""

    id = "X-KEYPAD"
    summary = "KEYS, READKEY, LED -> manual (CAN keypadNode, KEYPADNODE)"
    evidence = "spec X-KEYPAD; v3:9408-9469, v3:2884-2898; v4:2077, v4:15447-15448"
    keywords = frozenset({"KEYS", "READKEY", "LED"})
    reason = "keypad/LED hardware is a CAN keypadNode in v4 (KEYPADNODE): redesign"


class HostTransfer(ManualKeywords):
    """Program/array upload, memory card, card select and MINT/3.28 host keywords have no v4
    keyword: Mint WorkBench transfers data; PEEK/POKE address another memory."""

    id = "X-HOST"
    summary = "LOAD, SAVE, PEEK, POKE, PO, MP, VN, ZZ, $ -> manual (no v4 keyword)"
    evidence = "spec X-HOST; v3:1937-1956; v4:1127-1129, v4:15066-15080, v4:2224"
    keywords = frozenset({"LOAD", "SAVE", "PEEK", "POKE", "PO", "MP", "VN", "ZZ", "$"})
    reason = "no Mint v4 keyword (Mint WorkBench transfers programs and arrays): remove or redesign"
    reasons: ClassVar[Mapping[str, str]] = dict.fromkeys(
        ("PEEK", "POKE", "PO"),
        "replaced by DPRFLOAT/DPRLONG/DPRWORD, which address dual-port RAM, not the option card: redesign",
    )


class AxisConfiguration(ManualKeywords):
    """AXISCON bits map to different v4 features (bit 0 DECEL, 1 aux encoder hardware,
    2 FOLERRORMODE, 3 POSTARGET)."""

    id = "X-AXISCON"
    summary = "AXISCON -> manual (bit by bit: DECEL, AUXENCODER, FOLERRORMODE, POSTARGET)"
    evidence = "spec X-AXISCON; v3:6024-6031"
    keywords = frozenset({"AXISCON"})
    reason = "no v4 keyword: bit 0 is v4 behaviour, bit 2 is FOLERRORMODE, bit 3 reads POSTARGET"


class AbsentFeatures(ManualKeywords):
    """Commissioning and hardware features with a different v4 model (DAC monitor, data
    capture, inverters, frequency output)."""

    id = "X-MISC-ABSENT"
    summary = "AUX, CAPTURE, DATETIME, DIR, FREQ -> manual (LOOPTIME: S-LOOPTIME)"
    evidence = "spec X-MISC-ABSENT, §8; v4:8084, v4:10931"
    keywords = frozenset({"AUX", "CAPTURE", "DATETIME", "DIR", "FREQ"})
    reasons: ClassVar[Mapping[str, str]] = {
        "AUX": "no v4 keyword: the DAC monitor is DACMONITORAXIS/DACMONITORMODE (advanced)",
        "CAPTURE": "v4 data capture is CAPTUREMODE and friends (advanced)",
        "DATETIME": "no v4 keyword: capture duration is set with the v4 CAPTURE keywords (advanced)",
        "DIR": "no v4 keyword (inverter direction); if a variable was meant, DIM it",
        "FREQ": "FREQ is an advanced v4 feature with other units",
    }


class EnableOutput(ManualKeywords):
    """v3 ENABLE drives the common enable output; v4 has RELAY or per-axis DRIVEENABLE,
    depending on the wiring."""

    id = "X-ENABLE"
    summary = "ENABLE -> manual (RELAY.0 or DRIVEENABLE[axes], as wired)"
    evidence = "spec X-ENABLE; v3:7567, v3:11729; v4:9577, v4:9258-9305"
    keywords = frozenset({"ENABLE"})
    reason = "RELAY.0 if the relay is the enable signal, else DRIVEENABLE[axes]"


class ErrorCodes(ManualKeywords):
    """v3 ERR codes 0..15 have no 1:1 v4 counterpart (motion errors are ERR = 500 plus
    AXISERROR bits): every read of ERR is flagged, a test of it and a printed or stored code
    alike, which shows another number (a following error is 11 in v3, 500 in v4); even
    ``IF ERR`` tests another thing, v3's ERR 0 being Out of range."""

    id = "X-ERR"
    summary = "ERR -> manual (v4: ERR = 500 for motion errors, AXISERROR bits)"
    evidence = "spec X-ERR; v3:4918-4937; v4:18503-18893"
    keywords = frozenset({"ERR"})
    reason = "v3 error numbers differ: motion errors are ERR = 500 with AXISERROR bits in v4"


class PowerUpAgain(ManualKeywords):
    """v3 DEFAULT put back v3's power-up values (v3:7247-7251) and left the dedicated limit, home,
    stop and error inputs and the amplifier enable as the hardware had them; v4 DEFAULT puts back
    v4's values and unassigns the inputs and the drive enable output the prologue asks for
    (v4:9004-9059), which nothing here can write for the user. v3 DEFAULT also reset what RESET
    resets, the guide telling them apart only by the parameters RESET leaves (v3:7244-7251): the
    outputs, TIME and IMASK (v3:11438-11442), which v4 DEFAULT leaves."""

    id = "X-DEFAULT"
    summary = "DEFAULT -> manual (v4 DEFAULT unassigns the inputs and the drive enable output, sets v4's values)"
    evidence = "v3:7244-7251, v3:9989, v3:8741, v3:11797, v3:11438-11442; v4:9004-9059"
    keywords = frozenset({"DEFAULT"})
    reason = (
        "v4 DEFAULT unassigns the limit, home, stop, error inputs and drive enable output, sets v4's values "
        "(FOLERRORFATAL 1000, IDLEPOS 1000, SPEED 20000), keeps OUT, TIME, IMASK (v3 cleared them): redo them after it"
    )


class ChangedMeaning(ManualKeywords):
    """Keywords whose v4 form needs context this migrator does not compute yet (the spec's
    M-DISPLAY): each use is flagged with the v4 form to write. CAM/CAMA, GEARN/GEARD and
    CARD have rules of their own (S-CAM, S-GEAR, S-CARD), which flag what they cannot prove."""

    id = "X-CHANGED"
    summary = "DISPLAY -> manual with the v4 form"
    evidence = "spec M-DISPLAY"
    keywords = frozenset({"DISPLAY"})
    reason = "use VIEW VAR / VIEW ARRAY at the command line"


class Password(Rule):
    """v3 reads the rest of PROTECT's line as the password, spaces, punctuation and a REM included
    (v3:11089-11092); v4 reads one word of letters and digits (v4:15393-15394). A v3 password of more
    than that reads in v4 as another password with statements after it, or not at all: a person
    chooses the new one."""

    id = "X-PROTECT"
    rule_class = RuleClass.MANUAL
    phase = Phase.MANUAL
    summary = "PROTECT with spaces or punctuation in its password -> manual (v4: letters and digits)"
    evidence = "v3:11089-11092; v4:15393-15394"

    def apply(self, context: Context) -> Iterator[Action]:
        for file, use in context.keyword_uses("PROTECT"):
            statement = use.statement
            if not isinstance(statement, n.KeywordStatement) or len(statement.arguments) != 1:
                continue
            word = statement.arguments[0]
            if isinstance(word, n.VariableRef) and not word.name.text.isalnum():
                reason = f"v4 reads the v3 password {word.name.text!r} otherwise: choose one word of letters and digits"
                yield self.flag(file, statement.span, reason)


class OnError(Rule):
    """Every #ONERROR needs review: v4 also calls it for interpreter errors (a ``RESET : RUN``
    handler can loop), the default error actions may have disabled the drive, and CANCEL
    does not re-enable it."""

    id = "X-ONERROR"
    rule_class = RuleClass.MANUAL
    phase = Phase.MANUAL
    summary = "#ONERROR -> manual review (interpreter errors too; drive may be disabled)"
    evidence = "spec X-ONERROR; v3:4916; v4:4579-4619, v4:4743-4747, v4:6087-6088"

    def apply(self, context: Context) -> Iterator[Action]:
        for file, line in context.placed(LABEL):
            label = line.syntax.label
            event = event_of(label.text) if label is not None else None
            if event is not None and event.kind is EventKind.ONERROR:
                reason = "v4 also calls #ONERROR for program errors; drive may stay disabled"
                yield self.flag(file, line.span(line.syntax.span), reason)


class FastLatch(Rule):
    """The fast-latch handler behaves differently in v4: the latch is held until the handler
    returns, FASTPOS must be re-armed, and the fast input is chosen per controller."""

    id = "X-FASTLATCH"
    rule_class = RuleClass.MANUAL
    phase = Phase.MANUAL
    summary = "#FASTPOS/#FASTIN handler -> manual review (latch re-arming, FASTSELECT)"
    evidence = "spec X-FASTLATCH; v3:5468, v3:7375; v4:4962-4963, v4:10444-10446, v4:5865-5888"

    def apply(self, context: Context) -> Iterator[Action]:
        for file, line in context.placed(LABEL):
            label = line.syntax.label
            event = event_of(label.text, Dialect.V3) if label else None
            v4_event = event_of(label.text) if label else None
            if (event and event.kind is EventKind.FASTPOS) or (v4_event and v4_event.kind is EventKind.FASTIN):
                reason = "v4 holds the latch until the handler returns; check FASTSELECT"
                yield self.flag(file, line.span(line.syntax.span), reason)


@per_pass
def v4_errors(context: Context) -> tuple[tuple[FileView, tuple[Diagnostic, ...]], ...]:
    """Each file with the errors ``mint check`` finds in it as Mint v4 on the target controller.

    The lines of the pass's v3 reading that Mint v4 reads alike are carried over (``carry_to_v4``):
    only the others are lexed and parsed again, and the two readings share those lines' syntax."""
    files = context.files
    configuration = files.get(Unit.CONFIGURATION)
    target = context.controller.controller
    with apart(context.v4_shelf):  # the v4 readings' lines are of no use to the v3 readings of the run
        for file in context.compiled:
            carry_to_v4(file.document, target)
        analysis = mintlang.check_application(
            files[Unit.PROGRAM].text,
            dialect="v4",
            controller=target,
            config=configuration.text if configuration is not None else None,
        )
    return _per_file(context, analysis)


@per_pass
def v3_errors(context: Context) -> tuple[tuple[FileView, tuple[Diagnostic, ...]], ...]:
    """Each file with the errors ``mint check --dialect v3`` finds in it (the pass's own parse), but a variable
    read before v3 declares it: M-DIM declares every variable the program reads and flags an array it cannot
    size, so that error is M-DIM's to resolve, not a line to report as broken in v3 already."""
    return tuple(
        (file, tuple(d for d in errors if d.mint_error != UNDEFINED_VARIABLE))
        for file, errors in _per_file(context, mintlang.analyse(context.model))
    )


def _per_file(context: Context, analysis: mintlang.Analysis) -> tuple[tuple[FileView, tuple[Diagnostic, ...]], ...]:
    found = [(Unit.PROGRAM, analysis.program), (Unit.CONFIGURATION, analysis.configuration)]
    return tuple(
        (context.files[unit], tuple(d for d in diagnostics if d.severity is Severity.ERROR))
        for unit, diagnostics in found
        if unit in context.files
    )


def by_statement(file: FileView, diagnostics: Iterable[Diagnostic]) -> dict[Span, list[Diagnostic]]:
    """Diagnostics grouped by the statement holding them (an IF .. THEN with its body is one), so
    that one marker goes above the line the statement starts on, not inside a DIM list that
    continues over several lines; a diagnostic outside every statement keeps its own span."""
    groups: dict[Span, list[Diagnostic]] = {}
    for diagnostic in diagnostics:
        offset = diagnostic.span.start
        found = bisect_right(file.line_starts, offset) - 1
        holding = [s for s in file.line(found).statements if s.span.start <= offset] if found >= 0 else []
        groups.setdefault(holding[-1].span if holding else diagnostic.span, []).append(diagnostic)
    return groups


_ON_LINE = re.compile(r" on line \d+")


def _without_line_numbers(message: str) -> str:
    """A block message without the line it names: that counts lines of the text as this pass sees it (notes
    already inserted), which is neither the original nor the result a reader holds."""
    return _ON_LINE.sub("", message)


def _leftover_reason(context: Context, keyword: str) -> str:
    """Why X-V3 flags ``keyword``: a v3 keyword, or a word written like one that neither keyword list
    knows, such as the v3 guide's misprint ``HMPSEED.2 = 10`` (v3:8708), never a Mint v3 keyword."""
    if context.db.lookup_v3(keyword) is None:
        return f"{keyword} is no Mint v3 or v4 keyword the migrator knows (misprint?): no automatic rewrite"
    return f"{keyword} is Mint v3 only: no automatic rewrite"


def _messages(diagnostics: Iterable[Diagnostic], *, codes: bool = False) -> str:
    """The different messages of some diagnostics, in order, each once."""
    return "; ".join(dict.fromkeys(f"{d.code} {d.message}" if codes else d.message for d in diagnostics))


class InvalidInV3(Rule):
    """A line that is already an error in Mint v3 (what ``mint check --dialect v3`` reports) and
    still an error in v4 at the same place, or an unknown word used as a statement (``COMMON``,
    ``RME``), was already broken in the v3 listing: it is reported, not "fixed". The error must
    be there in v4 too because the rule reads the migrated text: the v4 it wrote is no Mint v3,
    and migrating it again must flag nothing. Its code may differ: v3 and v4 name some errors
    differently (``PRINT VER``: v3 a command given no value, v4 a syntax error)."""

    id = "X-COMMENTED"
    rule_class = RuleClass.MANUAL
    phase = Phase.MANUAL
    summary = "line invalid in v3 already (mint check --dialect v3 errors, misprints, unknown words) -> manual"
    evidence = "spec X-COMMENTED; v3:7345-7350 (the v3 guide's own error examples)"

    def apply(self, context: Context) -> Iterator[Action]:
        named = list(self._named(context))
        yield from named
        lines = {(flag.unit, context.files[flag.unit].line_number(flag.span.start)) for flag in named}
        in_v3 = v3_errors(context)
        # no rule after this one in the pass asks for the v3 model, and with its lines' facts it held 12 times
        # the program's size beside the Mint v4 reading (the peak of a run with a v3 error), and through the
        # rest of the pass and the next one's reading
        context.forget_model()
        if not any(errors for _, errors in in_v3):
            return  # reading the file as Mint v4 is the costly part, and only a v3 error needs it
        in_v4 = {(file.unit, d.span.start) for file, errors in v4_errors(context) for d in errors}
        for file, errors in in_v3:
            both = [d for d in errors if (file.unit, d.span.start) in in_v4]
            for span, diagnostics in by_statement(file, both).items():
                if (file.unit, file.line_number(span.start)) not in lines:
                    yield self.flag(file, span, f"not valid Mint v3 either ({_messages(diagnostics)})")

    def _named(self, context: Context) -> Iterator[Flag]:
        """The errors given a reason of their own: unknown words, a comment missing its REM,
        unmatched blocks and labels."""
        no_operands = context.mentioned(lambda name: not takes_operands(context, name))
        for file, line in context.placed(n.BareName, *map(statement_tag, no_operands)):
            for statement in n.flatten_statements(line.syntax.statements):
                span = line.span(statement.span)
                if isinstance(statement, n.BareName) and context.db.lookup(statement.name.text) is None:
                    yield self.flag(file, span, f"'{statement.name.text}' is not a Mint keyword (misprint?)")
                elif missing_rem(context, statement):  # STOP following
                    assert isinstance(statement, n.KeywordStatement)
                    name = statement.keyword.keyword
                    yield self.flag(file, span, f"{name} takes no operands (a comment missing REM?)")
        for unit, structure in context.model.structures.items():
            for diagnostic in structure.diagnostics:
                if diagnostic.severity is Severity.ERROR:
                    reason = f"blocks do not match: {_without_line_numbers(diagnostic.message)}"
                    yield self.flag(context.files[unit], diagnostic.span, reason)
        for unit, labels in context.model.symbols.labels.items():
            for label in labels.values():
                for duplicate in label.definitions[1:]:
                    yield self.flag(context.files[unit], duplicate.span, f"label #{label.name} is defined twice")
                if not label.definitions:
                    for jump in label.references:
                        yield self.flag(context.files[unit], jump.span, f"label #{label.name} is not in this file")


class Platform(Rule):
    """A keyword the target controller does not have (its "Controllers Supported" list), such
    as AUTO on NextMove PCI."""

    id = "X-PLATFORM"
    rule_class = RuleClass.MANUAL
    phase = Phase.MANUAL
    summary = "keyword not available on the target controller -> manual"
    evidence = "v4 chapter 10 'Controllers Supported' of each keyword (e.g. v4:6633 AUTO)"

    def apply(self, context: Context) -> Iterator[Action]:
        keywords = context.db.keywords
        for file, statement, keyword, _ in keyword_nodes(context, lambda k: k in keywords and not context.supports(k)):
            yield self.flag(file, statement.span, f"{keyword} is not available on {context.controller.title}")


class LeftoverV3(Rule):
    """Whatever is still Mint v3 after every other rule: a keyword v4 does not have (or
    lists as replaced), a v3 constant whose v4 value differs. Nothing is left silently."""

    id = "X-V3"
    rule_class = RuleClass.MANUAL
    phase = Phase.MANUAL
    summary = "any Mint v3 keyword or constant no rule could rewrite -> manual"
    evidence = "spec §1 step 7, §8, §11; v4 'replaced by' entries"
    covered: ClassVar[frozenset[str]] = frozenset().union(*(rule.keywords for rule in ManualKeywords.__subclasses__()))

    def apply(self, context: Context) -> Iterator[Action]:
        db = context.db
        for file, statement, keyword, _ in keyword_nodes(context, lambda name: self._left(context, name)):
            if not _flagged(file, statement.span.start):
                yield self.flag(file, statement.span, _leftover_reason(context, keyword))
        same = same_value_constants(context)
        changed = [name for name in db.v3_constants if name not in same]
        for file, _, statement in context.statements(*map(constant_tag, changed)):
            if _flagged(file, statement.span.start):
                continue
            for root in n.expressions_of(statement):
                for node in n.walk_expression(root):
                    if isinstance(node, n.ConstantRef) and node.name in db.v3_constants and node.name not in same:
                        yield self.flag(file, statement.span, f"{node.name.lower()} has another value in v4")

    def _left(self, context: Context, keyword: str) -> bool:
        """Whether ``keyword`` is Mint v3 only and no rule of its own flags it."""
        db = context.db
        return keyword not in self.covered and (db.lookup(keyword) is None or db.rename_of(keyword) is not None)


class StillInvalid(Rule):
    """The migrator promises valid Mint v4 except on flagged lines: the result is read again as
    Mint v4 for the target controller (spec §1 step 8), and a line with an error no rule could
    rewrite gets a marker with the checker's message. Most are what a smaller controller lacks:
    a second or third axis on a one-axis MintDrive or ServoNode 51 (#2017, #2), an input channel
    (#7) or a value (#3), also in lines the migrator wrote from the v3 ones. A line that already
    carries a marker is not flagged again; this runs last so that it sees every marker."""

    id = "X-CHECK"
    rule_class = RuleClass.MANUAL
    phase = Phase.CHECK
    summary = "line still invalid Mint v4 on the target (axes, channels, values it lacks) or too long -> manual"
    evidence = "spec §1 step 8; v4:18514-18532 (#2, #3, #7), v4:19047 (#2017), v4:254-256 (255 characters)"

    def apply(self, context: Context) -> Iterator[Action]:
        title = context.controller.title
        invalid: list[tuple[FileView, Span, list[Diagnostic]]] = []
        flagged: set[tuple[Unit, int]] = set()
        for file, errors in v4_errors(context):
            for span, diagnostics in by_statement(file, errors).items():
                if not _flagged(file, span.start):
                    flagged.add((file.unit, file.line_start(span.start)))
                    invalid.append((file, span, diagnostics))
        limit = context.controller.max_line_length
        long: list[tuple[FileView, Span]] = []
        for file in context.files.values():
            for line in _longer_than(limit).finditer(file.text):
                if (file.unit, line.start()) not in flagged and not _flagged(file, line.start()):
                    long.append((file, Span(line.start(), line.end())))
        marked = [(file, span.start) for file, span, _ in invalid] + [(file, span.start) for file, span in long]
        for file, span, diagnostics in invalid:
            message = _in_migrated_lines(_messages(diagnostics, codes=True), file, marked)
            yield self.flag(file, span, f"not valid Mint v4 on {title}: {message}")
        for file, span in long:
            reason = f"line of {span.end - span.start} characters: {title} takes {limit}; split it"
            yield self.flag(file, span, reason)


_LINE_NUMBER = re.compile(r"\bline (\d+)")


def _in_migrated_lines(message: str, file: FileView, marked: Iterable[tuple[FileView, int]]) -> str:
    """``message`` with each line it names numbered as in the migrated file: the checker numbered the text
    before this rule's markers, and each marker above a line moves it down one (one below the command that
    opens the file moves only the lines after it)."""
    moved = sorted(
        place.line_number(offset) + (1 if place.in_opening_command(offset) else 0)
        for place, offset in marked
        if place is file
    )
    return _LINE_NUMBER.sub(lambda found: f"line {int(found[1]) + bisect_right(moved, int(found[1]))}", message)


@cache
def _longer_than(limit: int) -> re.Pattern[str]:
    """A physical line of more than ``limit`` characters, whatever ends the lines (LF, CR LF or a lone CR):
    rewrites lengthen lines, ``SIN(a)`` becomes ``(SIN(a) * 1000)``."""
    return re.compile(rf"(?<![^\r\n])[^\r\n]{{{limit + 1},}}")


# Rules whose markers are notes for the whole application: they sit above the first line of code
# (notes.py), but say nothing about it.
_APPLICATION_NOTES = frozenset({IoPrologue.id, ReportDefaults.id})


def _flagged(file: FileView, offset: int) -> bool:
    """Whether an earlier rule already put a manual item on the line of ``offset``."""
    return any(rule not in _APPLICATION_NOTES for rule in file.markers_on(offset))
