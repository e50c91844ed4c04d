"""Mint expressions typed in the editor (watch, hover, the debug console, a breakpoint's condition), evaluated
by the interpreter that runs the program, so they mean what they would mean in a line of it.

An expression is parsed as the operand of a ``PRINT`` in the program's dialect
and compiled by the run's own ``ExpressionCompiler``: variables, array
elements, keywords (``POS.0``, ``IN.3``), functions and constants all resolve
as the program's do. A name the program does not declare is refused rather
than given a fresh slot, so evaluating never grows the program's storage.
"""

from __future__ import annotations

from mintlang import binary32
from mintlang.analysis.rules.addressing import misaddressed
from mintlang.codes import mint_error
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.records import record
from mintlang.runtime.controller import Controller
from mintlang.runtime.dialects import semantics
from mintlang.runtime.errors import MintError, NotSimulated
from mintlang.runtime.interpreter.expressions import Evaluate, ExpressionCompiler
from mintlang.syntax import nodes as n
from mintlang.syntax.parser import parse

_HOST = "PRINT "  # the statement whose operand the typed text becomes


class EvaluationError(Exception):
    """The text is not an expression of the program, or evaluating it raised a Mint error (the message says which)."""


@record
class Compiled:
    text: str
    evaluate: Evaluate


@record
class ExpressionReader:
    """Reads typed text as an expression of the program without running anything: what a breakpoint's condition
    is checked with when the editor sets it, before the run it will be evaluated in exists."""

    dialect: Dialect
    controller: str  # the controller's name: which keywords the parse knows
    scalars: frozenset[str]  # the identities of the program's variables
    arrays: frozenset[str]  # and of its arrays

    @classmethod
    def of(cls, controller: Controller, dialect: Dialect) -> ExpressionReader:
        names = controller.linked.names
        return cls(dialect, controller.table.controller, frozenset(names.scalars), frozenset(names.arrays))

    def read(self, text: str) -> n.Expression:
        """The expression ``text`` spells, in the program's dialect; ``EvaluationError`` naming the column of a
        syntax error, or a name the program does not declare."""
        if not text.strip():
            raise EvaluationError("an empty expression")
        if "\n" in text or "\r" in text:
            raise EvaluationError("an expression is one line")
        document = parse(_HOST + text, self.dialect, controller=self.controller)
        if document.diagnostics:
            problem = document.diagnostics[0]
            column = max(problem.span.start - len(_HOST), 0) + 1
            raise EvaluationError(f"column {column}: {problem.message}")
        statements = document.placed[0].syntax.statements if document.placed else ()
        if len(statements) != 1 or type(statements[0]) is not n.Print:
            raise EvaluationError(f"{text!r} is not an expression")
        items = statements[0].items  # type: ignore[union-attr]
        if statements[0].terminal is not None or len(items) != 1:  # type: ignore[union-attr]
            raise EvaluationError(f"{text!r} is not one expression")
        item = items[0]
        if item.format is not None or item.separator is not None or item.value is None:
            raise EvaluationError(f"{text!r} is not one expression")
        if type(item.value) is n.StringLiteral:
            raise EvaluationError("a string is not a value the debugger can show: Mint's values are numbers")
        keywords = database().keywords_of(self.dialect)
        for node in n.walk_expression(item.value):
            if type(node) is n.VariableRef and node.name.identity not in self.scalars:  # type: ignore[union-attr]
                raise EvaluationError(f"{node.name.text} is not a variable of the program")  # type: ignore[union-attr]
            if type(node) is n.ElementRef and node.name.identity not in self.arrays:  # type: ignore[union-attr]
                raise EvaluationError(f"{node.name.text} is not an array of the program")  # type: ignore[union-attr]
            keyword = keywords.get(node.keyword) if type(node) is n.KeywordRef else None  # type: ignore[union-attr]
            found = misaddressed(node, keyword, self.dialect) if keyword is not None else None  # type: ignore[arg-type]
            if found is not None:  # TIME.2: refused, as the compiler refuses it in a line (mint check's 2003)
                span, detail = found
                raise EvaluationError(f"column {span.start - len(_HOST) + 1}: {mint_error(2003, span, detail).message}")
        return item.value  # type: ignore[return-value]

    def assigns(self, text: str) -> bool:
        """Whether ``text`` read as a line of the program is an assignment (``n = 5``, ``SPEED.0 = 10``),
        whose ``=`` an expression would read as a comparison."""
        document = parse(text, self.dialect, controller=self.controller)
        statements = document.placed[0].syntax.statements if document.placed and not document.diagnostics else ()
        if len(statements) != 1:
            return False
        statement = statements[0]
        writes = isinstance(statement, n.KeywordStatement | n.FunctionStatement) and statement.values is not None
        return writes or isinstance(statement, n.Assignment)


class Evaluator:
    """Compiles and evaluates expressions against one run of the program (a re-run needs a new one)."""

    def __init__(self, controller: Controller, dialect: Dialect) -> None:
        self.reader = ExpressionReader.of(controller, dialect)
        self.compiler = ExpressionCompiler(controller.vm, controller.table, controller.linked.names, semantics(dialect))

    def compile(self, text: str) -> Compiled:
        """``text`` compiled; raises ``EvaluationError`` naming the column of a syntax error."""
        expression = self.reader.read(text)
        try:
            return Compiled(text, self.compiler.compile(expression))
        except MintError as error:
            raise EvaluationError(error.describe()) from None
        except NotSimulated as missing:
            raise EvaluationError(str(missing)) from None

    def evaluate(self, text: str) -> float:
        return run(self.compile(text))


def run(compiled: Compiled) -> float:
    """The value of a compiled expression now; a Mint error it raises becomes an ``EvaluationError``."""
    try:
        return compiled.evaluate()
    except MintError as error:
        raise EvaluationError(error.describe()) from None
    except NotSimulated as missing:
        raise EvaluationError(str(missing)) from None


def shown(value: float) -> str:
    """A value as the editor shows it (``binary32.shortest``)."""
    return binary32.shortest(value)
