"""Statement rewrites: a v3 command or write becomes the v4 statement(s) that do the same.

Each rule rewrites whole statements it can prove equivalent and flags the rest;
the statement's selector (``[0,1]``, ``.1``) and values are copied as written.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import ClassVar

from mintlang.diagnostics import Span
from mintlang.migrate.citations import cite, in_file
from mintlang.migrate.context import Context, FileView, statement_tag
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Rule, same_text, selector_text
from mintlang.migrate.rules.power_up import before_switch_on
from mintlang.migrate.rules.spelling import like
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n


class Refusal(str):
    """Why a rule cannot rewrite a statement: the text of the manual item."""


class StatementRule(Rule):
    """A rule over the statements of some v3 keywords: ``rewrite`` gives the new text or a refusal."""

    keywords: ClassVar[frozenset[str]]
    phase = Phase.CONTEXT

    def apply(self, context: Context) -> Iterator[Action]:
        for file, _, statement in context.statements(*map(statement_tag, self.keywords)):
            if isinstance(statement, n.KeywordStatement) and statement.keyword.keyword in self.keywords:
                word = statement.keyword.keyword
                if statement.values is not None and _command_in_v3(context, word):  # ZERO = 5 (E2000 in v3)
                    result: str | Refusal | None = Refusal(f"not valid Mint v3 either: {word} is a command, no value")
                else:
                    result = self.rewrite(context, file, statement)
                if isinstance(result, Refusal):
                    yield self.flag(file, statement.span, result)
                elif result is not None:
                    yield self.replace(file, statement.span, result)
                    if (caveat := self.caveat(context, statement)) is not None:
                        yield self.flag(file, statement.span, caveat)

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        raise NotImplementedError

    def caveat(self, context: Context, statement: n.KeywordStatement) -> str | None:
        """What the user must still check about a rewrite, reported as a manual item beside it."""
        return None

    @staticmethod
    def unsupported(context: Context, keyword: str) -> Refusal | None:
        if context.supports(keyword):
            return None
        return Refusal(f"{keyword} is not available on {context.controller.title}")


def _command_in_v3(context: Context, keyword: str) -> bool:
    """Whether the v3 guide ticks ``keyword`` as a command that takes no value (ZERO, SERVOC, PON):
    given one, the statement was already an error on the v3 controller."""
    entry = context.db.lookup_v3(keyword)
    return entry is not None and entry.command and not entry.write


def fill(selector: str) -> str:
    """``;`` fills every axis of a bracket or default list; a dot names one axis."""
    return "" if selector.startswith(".") else ";"


def write(file: FileView, statement: n.KeywordStatement, keyword: str, value: str) -> str:
    """``KEYWORD<selector> = value`` with the statement's own selector, filling its axes."""
    selector = selector_text(file, statement.keyword)
    return f"{like(statement.keyword.spelling, keyword)}{selector} = {value}{fill(selector)}"


class Zero(StatementRule):
    """``ZERO[axes]`` becomes ``POS[axes] = 0;``: the v4 guide says ZERO was replaced by POS,
    and the trailing ``;`` zeroes every listed (or default) axis as ZERO did."""

    id = "M-ZERO"
    rule_class = RuleClass.MECHANICAL
    summary = "ZERO[axes] -> POS[axes] = 0;"
    evidence = "spec M-ZERO; v4:17428; v3:1109"
    keywords = frozenset({"ZERO"})

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        return write(file, statement, "POS", "0")


class Boost(StatementRule):
    """``BOOSTON``/``BOOSTOFF`` become ``BOOST[axes] = 1;``/``= 0;`` (BOOST exists on NextMove PC only)."""

    id = "M-BOOST"
    rule_class = RuleClass.MECHANICAL
    summary = "BOOSTON[axes]/BOOSTOFF[axes] -> BOOST[axes] = 1;/0;"
    evidence = "spec M-BOOST; v4:7425-7461; v3:6293"
    keywords = frozenset({"BOOSTON", "BOOSTOFF"})

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        return self.unsupported(context, "BOOST") or write(
            file, statement, "BOOST", "1" if statement.keyword.keyword == "BOOSTON" else "0"
        )


class NotAvailable(StatementRule):
    """COMMSON/COMMSOFF (v4 decodes comms packets by itself) and BEEPON/BEEPOFF (no keypad
    key-click) have no v4 statement: the statement becomes a REM saying so, also after other
    code (``RESET : REM COMMSON ...``). One with code after it, or the body of a THEN, is
    flagged instead, so that nothing else is commented out."""

    id = "M-NOTAVAIL"
    rule_class = RuleClass.MECHANICAL
    summary = "COMMSON, COMMSOFF, BEEPON, BEEPOFF -> REM line stating they are not available in v4"
    evidence = "spec M-NOTAVAIL; v4:8379-8387, v4:2299-2302, v4:7392-7397"
    keywords = frozenset({"COMMSON", "COMMSOFF", "BEEPON", "BEEPOFF"})

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        word = statement.keyword.keyword
        entry = context.db.rename_of(word)  # the v4 guide's "removed" entry of the keyword
        where = in_file(cite(f"v4:{entry.line}")) if entry is not None else "v4 guide"
        if not file.last_on_its_line(statement):
            return Refusal(f"{word} is not available in Mint v4 ({where}): delete it")
        return f"REM {file.slice(statement.span)}: not available in Mint v4 ({where}), removed by mint-migrate"


class Contouring(StatementRule):
    """``CONTON``/``CONTOFF`` become ``CONTOURMODE[0,1,2] = 1;``/``= 0;``: v3 contouring is
    card-wide ("all three axes"), v4 sets it per axis; CONTOURMODE is NextMove only."""

    id = "S-CONT"
    rule_class = RuleClass.SEMI
    summary = "CONTON/CONTOFF -> CONTOURMODE[0,1,2] = 1;/0; (NextMove only)"
    evidence = "spec S-CONT; v3:7033; v4:8505, v4:8510, v4:8567, v4:8571-8575"
    keywords = frozenset({"CONTON", "CONTOFF"})

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        value = "1" if statement.keyword.keyword == "CONTON" else "0"
        selector = selector_text(file, statement.keyword) or "[0,1,2]"
        keyword = like(statement.keyword.spelling, "CONTOURMODE")
        return self.unsupported(context, "CONTOURMODE") or f"{keyword}{selector} = {value}{fill(selector)}"


class DoneBesides(Rule):
    """A v3 statement that did more than the v4 statement of its name gets, after it, the v4 write
    that does the rest, ``restore``, unless the line has it there already (a second migration)."""

    rule_class = RuleClass.SEMI
    phase = Phase.CONTEXT
    keywords: ClassVar[frozenset[str]]

    def apply(self, context: Context) -> Iterator[Action]:
        for file, line in context.lines(*map(statement_tag, self.keywords)):
            statements = n.flatten_statements(line.statements)
            for position, statement in enumerate(statements):
                if not (isinstance(statement, n.KeywordStatement) and statement.keyword.keyword in self.keywords):
                    continue
                if not self.relied_on(context, file, statement):
                    continue
                restore = self.restore(file, statement)
                if any(same_text(file.slice(later.span), restore) for later in statements[position + 1 :]):
                    continue  # written already (a second migration)
                yield self.replace(file, Span(statement.span.end, statement.span.end), f" : {restore}")

    def relied_on(self, context: Context, file: FileView, statement: n.KeywordStatement) -> bool:
        """Whether the rest matters after this statement: always, unless a subclass knows better."""
        return True

    def restore(self, file: FileView, statement: n.KeywordStatement) -> str:
        raise NotImplementedError


class CancelEnables(DoneBesides):
    """``CANCEL[axes]`` is followed by ``DRIVEENABLE[axes] = 1;``. v3 CANCEL recovered the system a
    motion error shut down, amplifiers on (v3:5005, v3:5030, v3:5591-5597); v4 CANCEL leaves the drive
    its error disabled off, and the guide clears an error keeping the position with "CANCEL followed
    by DRIVEENABLE" (v4:4743-4744, v4:8016, v4:15628). Enabling a drive that is on changes nothing.
    A CANCEL that runs at power-up, before anything switched the amplifiers on, left them off
    (v3:11409-11411), and gets nothing."""

    id = "S-CANCEL"
    summary = "CANCEL[axes] -> CANCEL[axes] : DRIVEENABLE[axes] = 1; (v3 CANCEL switched the amplifiers on)"
    evidence = (
        "v3:5005, v3:5030, v3:5048, v3:5591-5597, v3:11409-11411; v4:4743-4744, v4:8016, v4:10675-10677, v4:15628"
    )
    keywords: ClassVar[frozenset[str]] = frozenset({"CANCEL"})

    def relied_on(self, context: Context, file: FileView, statement: n.KeywordStatement) -> bool:
        return not before_switch_on(context, file, statement.span.start)

    def restore(self, file: FileView, statement: n.KeywordStatement) -> str:
        return write(file, statement, "DRIVEENABLE", "1")


class ResetAlsoRestored(DoneBesides):
    """A v3 statement of the reset family (CANCEL, DISLIMIT, RESET) also undid what another
    statement had set (v3:11427-11446), which the v4 statement of the same name leaves as it
    is: in an application that uses ``changed_by``, each of them that can run after it gets the
    v4 write that undoes it, ``restore``. One in the configuration file before the first
    ``changed_by`` runs while the setting is still as at power-up and is left as it is."""

    changed_by: ClassVar[str]  # the v3 keyword whose effect the reset undid
    needs: ClassVar[str]  # the v4 keyword of the restore, which the target must have

    def apply(self, context: Context) -> Iterator[Action]:
        if next(iter(context.keyword_uses(self.changed_by)), None) is None or not context.supports(self.needs):
            return  # a target without it has the changing statement flagged already
        yield from super().apply(context)

    def relied_on(self, context: Context, file: FileView, statement: n.KeywordStatement) -> bool:
        _, change = next(iter(context.keyword_uses(self.changed_by)))
        changed_from = (_ORDER[change.unit], change.statement.span.start)
        return file.unit is not Unit.CONFIGURATION or (_ORDER[file.unit], statement.span.start) >= changed_from


class ContouringCancelled(ResetAlsoRestored):
    """v3 CANCEL, DISLIMIT and RESET also switched contouring off (v3:6584, v3:7469,
    v3:11427-11446); v4 CANCEL and RESET leave CONTOURMODE as it is (v4:7985-8016,
    v4:15624-15629): after a CONTON each gets what S-CONT writes for CONTOFF. DISLIMIT's own
    S-LIMIT rewrite ends in the CANCEL, so the CONTOURMODE goes after the whole of it."""

    id = "S-CONT-OFF"
    summary = "CANCEL, DISLIMIT, RESET after a CONTON -> ... : CONTOURMODE[0,1,2] = 0; (v3 turned contouring off)"
    evidence = "v3:6584, v3:7469, v3:11427-11446; v4:7985-8016, v4:15624-15629, v4:8571-8575"
    keywords: ClassVar[frozenset[str]] = frozenset({"CANCEL", "DISLIMIT", "RESET"})
    changed_by = "CONTON"
    needs = "CONTOURMODE"

    def restore(self, file: FileView, statement: n.KeywordStatement) -> str:
        return "CONTOURMODE[0,1,2] = 0;"


class LimitsReset(ResetAlsoRestored):
    """v3 RESET enabled the limits again after a DISLIMIT (v3:7471, v3:11427-11446), CANCEL did
    not; v4 RESET leaves LIMITMODE as it is (v4:15624-15629): after a DISLIMIT each RESET gets
    what S-LIMIT writes for ENLIMIT, on the axes the RESET names."""

    id = "S-LIMIT-RESET"
    summary = "RESET after a DISLIMIT -> RESET[axes] : LIMITMODE[axes] = 1; (v3 RESET enabled the limits)"
    evidence = "v3:7471, v3:11427-11446; v4:15624-15629, v4:13446-13497"
    keywords: ClassVar[frozenset[str]] = frozenset({"RESET"})
    changed_by = "DISLIMIT"
    needs = "LIMITMODE"

    def restore(self, file: FileView, statement: n.KeywordStatement) -> str:
        return write(file, statement, "LIMITMODE", "1")


_ORDER = {Unit.CONFIGURATION: 0, Unit.PROGRAM: 1}  # compile order: the configuration file runs first


class ServoOff(StatementRule):
    """``SERVOFF[axes]`` becomes ``TORQUE[axes] = 0;``: the v4 guide replaces SERVOFF by TORQUE
    and uses ``TQ.0 = 0`` to let a shaft be turned by hand; v3 SERVOFF kept the amplifier
    enabled with zero demand, which is what TORQUE = 0 does on a current-mode amplifier."""

    id = "S-SERVOFF"
    rule_class = RuleClass.SEMI
    summary = "SERVOFF[axes] -> TORQUE[axes] = 0;"
    evidence = "spec S-SERVOFF; v3:11722; v4:15892, v4:2748-2767"
    keywords = frozenset({"SERVOFF"})

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        return self.unsupported(context, "TORQUE") or write(file, statement, "TORQUE", "0")

    def caveat(self, context: Context, statement: n.KeywordStatement) -> str | None:
        return "TORQUE = 0 suits a current (torque) amplifier; a velocity drive needs DRIVEENABLE = 0 instead"


class ServoOn(StatementRule):
    """``SERVOC[axes]`` becomes ``CANCEL[axes] : DRIVEENABLE[axes] = 1;``. CANCEL "starts the axis
    servoing in its current position but retains all positional data", but leaves the drive as it
    is (v4:4743, v4:8016), and the default action of a v4 limit or following error disables it
    (v4:13497, v4:10677): v3's servo-on after such an error needs the drive enabled again, as the
    v4 guide's own handler does (v4:4769-4771). Enabling a drive that is on changes nothing."""

    id = "S-SERVOC"
    rule_class = RuleClass.SEMI
    summary = "SERVOC[axes] -> CANCEL[axes] : DRIVEENABLE[axes] = 1;"
    evidence = "spec S-SERVOC; v4:15887, v4:2764-2767, v4:4743-4747, v4:4769-4771"
    keywords = frozenset({"SERVOC"})

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        cancel = f"{like(statement.keyword.spelling, 'CANCEL')}{selector_text(file, statement.keyword)}"
        return f"{cancel} : {write(file, statement, 'DRIVEENABLE', '1')}"


class Limits(StatementRule):
    """``DISLIMIT[axes]`` becomes ``LIMITMODE[axes] = 0; : CANCEL[axes] : DRIVEENABLE[axes] = 1;``
    (v3 DISLIMIT also cancelled the limit error; CANCEL leaves the drive the error disabled off, so
    it is enabled again, as the spec's S-LIMIT asks) and ``ENLIMIT[axes]`` becomes ``LIMITMODE[axes] = 1;``."""

    id = "S-LIMIT"
    rule_class = RuleClass.SEMI
    summary = "DISLIMIT -> LIMITMODE[axes] = 0; : CANCEL[axes] : DRIVEENABLE[axes] = 1;; ENLIMIT -> LIMITMODE = 1;"
    evidence = "spec S-LIMIT; v3:7453; v4:9239, v4:9863, v4:13478-13497"
    keywords = frozenset({"DISLIMIT", "ENLIMIT"})

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        if statement.keyword.keyword == "ENLIMIT":
            return write(file, statement, "LIMITMODE", "1")
        cancel = like(statement.keyword.spelling, "CANCEL") + selector_text(file, statement.keyword)
        enable = write(file, statement, "DRIVEENABLE", "1")  # CANCEL leaves the drive the error disabled off
        return f"{write(file, statement, 'LIMITMODE', '0')} : {cancel} : {enable}"


class Interrupts(StatementRule):
    """``DINT``/``EINT`` disable/enable the #INn and #FASTPOS handlers: in v4 that is the
    fast-latch and digital-input bits of EVENTDISABLE (NextMove bits 5 and 7) or of
    HANDLERDISABLE (MintDrive bits 1 and 6). Pending flags stay set in both versions."""

    id = "S-INT"
    rule_class = RuleClass.SEMI
    summary = "DINT/EINT -> EVENTDISABLE = EVENTDISABLE | 0xA0 / & 0x15F (MintDrive: HANDLERDISABLE 0x42)"
    evidence = "spec S-INT; v3:2554, v3:7375; v4:9229, v4:9572, v4:4358-4367, v4:10140-10162, v4:4530-4539"
    keywords = frozenset({"DINT", "EINT"})
    masks: ClassVar[dict[str, tuple[int, int]]] = {"EVENTDISABLE": (0xA0, 0x1FF), "HANDLERDISABLE": (0x42, 0x1FF)}

    def rewrite(self, context: Context, file: FileView, statement: n.KeywordStatement) -> str | Refusal | None:
        for keyword, (bits, width) in self.masks.items():
            if context.supports(keyword):
                word = like(statement.keyword.spelling, keyword)
                if statement.keyword.keyword == "DINT":
                    return f"{word} = {word} | 0x{bits:X}"
                return f"{word} = {word} & 0x{width & ~bits:X}"
        return Refusal(f"{context.controller.title} has neither EVENTDISABLE nor HANDLERDISABLE")


class DropOffline(Rule):
    """``DIM OFFLINE name(n)`` kept an array on the v3 memory card; v4 has no memory card,
    so the word OFFLINE is dropped and the array lives in ordinary memory."""

    id = "M-OFFLINE"
    rule_class = RuleClass.MECHANICAL
    phase = Phase.CONTEXT
    summary = "DIM OFFLINE name(n) -> DIM name(n)"
    evidence = "spec §11 (OFFLINE: drop from DIM OFFLINE), X-HOST; v3:1588"

    def apply(self, context: Context) -> Iterator[Action]:
        for file, _, statement in context.statements(n.Dim):
            if isinstance(statement, n.Dim) and statement.modifier is not None:
                for token in file.document.tokens_in(statement.span.start, statement.name.span.start):
                    if token.start < statement.span.start:
                        continue
                    if token.start >= statement.name.span.start:
                        break
                    if token.text.upper() == "OFFLINE":
                        end = token.end
                        while end < statement.name.span.start and file.text[end] in " \t":
                            end += 1
                        yield self.replace(file, Span(token.start, end), "")
