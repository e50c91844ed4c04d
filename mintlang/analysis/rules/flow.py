"""Control flow a reader can get wrong: dead code, falling into subroutines, jumps out of blocks.

* Statements after END, RETURN, GOTO or EXIT that nothing can reach (W106).
* Main program code that runs on into the first subroutine without END:
  its RETURN then fails with error 2010 (the manual's own example, 12.4).
  Reported at that RETURN as a warning: the file may be a fragment.
* A subroutine without RETURN that runs on into the next one (W107).
* GOTO out of an open IF block or loop: the block is never closed, and done
  repeatedly this overflows the controller's stack (2015, see GOTO in 10.3).
* EXIT outside any loop (W112).
"""

from __future__ import annotations

import math
from collections.abc import Iterator

from mintlang.analysis.findings import Finding, mint_error, own
from mintlang.analysis.traversal import Facts
from mintlang.diagnostics import Severity
from mintlang.semantic.blocks import LOOPS, Block
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.symbols import Unit
from mintlang.syntax import nodes as n
from mintlang.syntax.parser import Document

_TERMINATORS = frozenset({"END", "RETURN", "EXIT"})
_RECEIVERS = frozenset({"ELSE", "ENDIF", "NEXT", "ENDW", "ENDL"})  # reached from elsewhere in their block


def _ends_flow(statement: n.Statement) -> bool:
    match statement:
        case n.BlockWord(word=word):
            return word in _TERMINATORS
        case n.Jump(word="GOTO"):
            return True
    return False


def _receives_flow(statement: n.Statement) -> bool:
    return isinstance(statement, n.Until) or (isinstance(statement, n.BlockWord) and statement.word in _RECEIVERS)


def check(facts: Facts) -> Iterator[Finding]:
    model = facts.model
    for unit, document in model.documents():
        yield from _reachability(unit, document)
        yield from _jumps_out_of_blocks(unit, document, model)


def _reachability(unit: Unit, document: Document) -> Iterator[Finding]:
    reachable = True
    reported = False  # one W106 per unreachable run
    running = False  # some statement has run since the last entry point
    subroutine: n.Name | None = None  # None while in the main program
    falling_from_main = False
    loops = 0
    for line in document.lines:
        if line.label is not None:
            if reachable and running:
                if subroutine is None:
                    falling_from_main = True
                else:
                    detail = f"#{subroutine.text} has no RETURN here and runs on into #{line.label.text}"
                    yield Finding(unit, own("W107", line.label.span, detail))
            elif falling_from_main:
                falling_from_main = False
            subroutine, reachable, reported, running = line.label, True, False, False
        for statement in line.statements:
            if _receives_flow(statement):
                reachable = True
            elif not reachable and not reported:
                yield Finding(unit, own("W106", statement.span, "this code can never run"))
                reported = True
            running = running or reachable
            loops = _loop_depth(statement, loops)
            if isinstance(statement, n.BlockWord) and statement.word == "EXIT" and loops == 0:
                yield Finding(unit, own("W112", statement.span, "EXIT is not inside a FOR, REPEAT, WHILE or LOOP"))
            for inner in n.walk_statements((statement,)):
                if falling_from_main and isinstance(inner, n.BlockWord) and inner.word == "RETURN":
                    detail = (
                        "the main program has no END and runs on into "
                        f"#{subroutine.text if subroutine else ''}, so this RETURN has no GOSUB to return to"
                    )
                    yield Finding(unit, mint_error(2010, inner.span, detail, severity=Severity.WARNING))
                    falling_from_main = False
            if _ends_flow(statement):
                reachable = False
                falling_from_main = False


def _loop_depth(statement: n.Statement, depth: int) -> int:
    match statement:
        case n.For() | n.While() | n.BlockWord(word="REPEAT" | "LOOP"):
            return depth + 1
        case n.Until() | n.BlockWord(word="NEXT" | "ENDW" | "ENDL"):
            return max(0, depth - 1)
    return depth


def _jumps_out_of_blocks(unit: Unit, document: Document, model: SemanticModel) -> Iterator[Finding]:
    blocks = model.structures[unit].blocks
    labels = {line.label.identity: line.number for line in document.lines if line.label is not None}
    for line in document.lines:
        for statement in n.walk_statements(line.statements):
            if not (isinstance(statement, n.Jump) and statement.word == "GOTO"):
                continue
            target = labels.get(statement.label.identity)
            if target is None:
                continue
            left = [block for block in blocks if _contains(block, line.number) and not _contains(block, target)]
            if left:
                kind = left[-1].kind
                what = "loop" if kind in LOOPS else "IF block"
                detail = (
                    f"GOTO {statement.label.text} leaves the {kind.value} {what} of line {left[-1].opener_line} "
                    "open; repeated, this overflows the stack"
                )
                yield Finding(unit, mint_error(2015, statement.span, detail))


def _contains(block: Block, line: int) -> bool:
    end = block.closer_line if block.closer_line is not None else math.inf
    return block.opener_line <= line <= end
