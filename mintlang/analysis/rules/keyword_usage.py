"""Keywords used the way their attributes allow.

Writing a keyword that is read-only or a command is error 2000 (``CAMINDEX = 4``);
reading one that is write-only is 2002 (``PRINT ACCELTIME``); naming a
parameter on its own as a statement is 2005 (``SPEED``); editor commands in a
program are 2006 (``NEW``); a word that is no keyword of the target
controller is 3007.
"""

from __future__ import annotations

from collections.abc import Iterator

from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.traversal import Facts, Use
from mintlang.keyworddb import database
from mintlang.keyworddb.model import Keyword, KeywordKind
from mintlang.semantic.model import SemanticModel
from mintlang.syntax import nodes as n


def check(facts: Facts) -> Iterator[Finding]:
    model = facts.model
    db = database()
    controller = model.controller.controller
    for use in facts.keyword_uses:
        ref = use.keyword
        keyword = db.keywords.get(ref.keyword)
        if keyword is None:
            if db.rename_of(ref.spelling) is not None:
                continue  # an old v3 keyword: the v3-keyword rule names its replacement
            detail = f"'{ref.spelling}' is not a keyword (check the spelling and the abbreviation)"
            yield Finding(use.unit, mint_error(3007, ref.spelling_span, detail))
            continue
        if keyword.kind is KeywordKind.COMMAND_LINE:
            detail = f"{keyword.name} is an editor command: it works only at the command line, not in a program"
            yield Finding(use.unit, mint_error(2006, ref.spelling_span, detail))
            continue
        if keyword.controllers and controller not in keyword.controllers:
            detail = f"{keyword.name} is not available on {model.controller.title}"
            yield Finding(use.unit, mint_error(17, ref.spelling_span, detail))
            continue
        problem = _misuse(keyword, use.use, model, use.statement)
        if problem is not None:
            code, detail = problem
            yield Finding(use.unit, mint_error(code, ref.spelling_span, detail))
    for unit, _, statement in facts.statements:
        if isinstance(statement, n.BareName) and db.rename_of(statement.name.text) is None:
            detail = f"'{statement.name.text}' is not a keyword (check the spelling and the abbreviation)"
            yield Finding(unit, mint_error(3007, statement.span, detail))


def _misuse(keyword: Keyword, use: Use, model: SemanticModel, statement: n.Statement) -> tuple[int, str] | None:
    attributes = keyword.attributes_for(model.controller.controller)
    if attributes is None:
        return None
    name = keyword.name
    if use is Use.WRITE and not attributes.write:
        what = "a command" if attributes.command else "read only"
        return 2000, f"{name} is {what} and cannot be given a value"
    if use is Use.READ and not attributes.read:
        if attributes.write:
            return 2002, f"{name} can only be written, not read"
        return 2003, f"{name} is a command and gives no value"
    if use is Use.COMMAND and not attributes.command:
        assert isinstance(statement, n.KeywordStatement)
        if not statement.arguments:
            return 2005, f"{name} must be read or given a value here (for example '{name} = …')"
        return 2003, f"{name} takes a value with '=': '{name} = …'"
    return None
