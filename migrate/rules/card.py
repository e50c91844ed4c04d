"""S-CARD: the controller's own address is read with NODE in v4, where v3 read CARD."""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.migrate.context import Context
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Rule
from mintlang.migrate.rules.spelling import like
from mintlang.migrate.rules.vocabulary import is_migrator_read
from mintlang.semantic.index import Use
from mintlang.syntax.nodes import identity


class NodeNumber(Rule):
    """v3 ``CARD`` reads the address of the controller on a multi-drop line (0..15, set by DIP
    switches); v4 ``NODE`` reads the node number that plays that part on RS485 and CAN (0..127,
    set in software, 0..15 usable on RS485). A program that reads its own address keeps doing
    so once NODE is given the old switch setting. The v4 entry's format lines say NODEID, but
    its heading, the section on multi-drop and the keyword table all say NODE, which is written.

    The v3 reader takes NODE for a user name. M-IDENT renames a v3 variable called NODE before
    this phase runs; while one is still there (M-IDENT not selected) writing NODE would merge
    it with the keyword, so every CARD is then a manual item. The NODE written here is never
    assigned, which no v3 variable can be, so a second run leaves it alone (``is_migrator_read``).
    """

    id = "S-CARD"
    rule_class = RuleClass.SEMI
    phase = Phase.CONTEXT
    summary = "read of CARD -> NODE (manual while a user variable is named NODE)"
    evidence = "spec S-CARD; v3:6646-6672; v4:14643-14676, v4:2140-2148, v4:18268"

    def apply(self, context: Context) -> Iterator[Action]:
        cards = list(context.keyword_uses("CARD"))
        if not cards:
            return  # whether NODE is a user name (the semantic model) matters only for a CARD
        user = context.model.symbols.variables.get(identity("NODE"))
        clash = user is not None and not is_migrator_read(user)
        for file, use in cards:
            if use.use is not Use.READ:
                yield self.flag(file, use.statement.span, "CARD can only be read (v4: NODE)")
            elif clash:
                yield self.flag(
                    file, use.keyword.span, "CARD is NODE in v4, which this program uses as a variable name"
                )
            elif not context.supports("NODE"):
                yield self.flag(file, use.keyword.span, f"NODE is not available on {context.controller.title}")
            else:
                yield self.replace(file, use.keyword.spelling_span, like(use.keyword.spelling, "NODE"))
