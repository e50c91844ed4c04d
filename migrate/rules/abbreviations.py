"""M-ABBR: expand every Mint v3 abbreviation to its full v3 keyword name, first of all.

Several v3 abbreviations are other keywords in v4 (``DE`` DECEL → DRIVEENABLE,
``IM`` IMASK → INPUTMODE, ``MD`` MODE → MOTORDIRECTION, ``GR`` GEARN → GEARING,
``DT`` DATETIME → DRIVETYPE, ``EO`` ECHO → the old ENOUTPUT): left alone, they
would still compile and do something else. Writing the full v3 name first lets
every later rule match full names only, and the output never depends on what
two letters mean in which version.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.diagnostics import Span
from mintlang.dialect import Dialect
from mintlang.migrate.context import Context
from mintlang.migrate.model import Phase, RuleClass
from mintlang.migrate.rules.base import Action, Rule
from mintlang.migrate.rules.spelling import like
from mintlang.syntax.tokens import WORDS, TokenKind
from mintlang.syntax.vocabulary import vocabulary

_JUMPS = frozenset({TokenKind.GOSUB, TokenKind.GOTO})


class ExpandAbbreviations(Rule):
    """A v3 abbreviation (``MA``, ``SP``, ``DE``, ``I3``, ``A1``) becomes the full v3 name.

    Symbols (``?``, ``&``, ``|``, ``!``, ``%``) mean the same in v4 and stay. A word after GOSUB
    or GOTO names a label (``GOSUB ma`` jumps to ``#ma``) and stays as written, as the label does.
    """

    id = "M-ABBR"
    rule_class = RuleClass.MECHANICAL
    phase = Phase.ABBREVIATIONS
    summary = "v3 abbreviation (MA, DE, IM, MD, GR, DT, I3, A1 ...) -> full v3 keyword name"
    evidence = "spec M-ABBR, §9; v3 keyword entries; v4:9258 DE, v4:12313 IM, v4:14092 MD, v4:10949 GR, v4:9517 DT"

    def apply(self, context: Context) -> Iterator[Action]:
        """Reads each line's significant tokens (words are never trivia), not the lossless stream,
        and cuts the text of the words only: this runs over every token of the application."""
        canonical = vocabulary(Dialect.V3).canonical
        for file in context.files.values():
            for offset, line in file.document.physical:
                line_text = line.text
                before = None
                for kind, start, end in zip(line.kinds, line.starts, line.ends, strict=True):
                    jumped_to, before = before in _JUMPS, kind
                    if kind not in WORDS or jumped_to:  # GOSUB ma names the label #ma, not MOVEA
                        continue
                    text = line_text[start:end]
                    if not text.isalnum():
                        continue
                    name = canonical.get(text.upper())  # not IN12 -> IN: a glued channel stays
                    if name is not None and name != text.upper():
                        yield self.replace(file, Span(offset + start, offset + end), like(text, name))
