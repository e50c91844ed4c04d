"""Names used before they are declared, labels that do not exist, invalid macros.

Mint v4 declares variables at compile time with DIM, in compile order
(configuration, then program, top to bottom): a use earlier in the text than
the DIM is error 3001 even if the DIM follows. GOSUB/GOTO to an unknown label
and a label defined twice are error 3004; a macro name that is not a name, or
a macro defined twice (also across configuration and program) is 3005; a macro
whose text uses another macro fails with a syntax error (3.5).
"""

from __future__ import annotations

import re
from bisect import bisect_left, bisect_right
from collections.abc import Callable, Iterator
from dataclasses import replace
from functools import cache, partial
from itertools import islice

from mintlang.analysis.findings import Finding, mint_error
from mintlang.analysis.rules.flow import runs_off_the_end
from mintlang.analysis.rules.functions import bracketed
from mintlang.analysis.rules.keyword_usage import label_written_with_a_colon
from mintlang.analysis.rules.v3_keywords import successor
from mintlang.analysis.suggestions import closest, did_you_mean, keyword_like
from mintlang.analysis.traversal import Facts, LineScope
from mintlang.diagnostics import Edit, Fix, Span, line_break
from mintlang.dialect import Dialect
from mintlang.keyworddb import database
from mintlang.keyworddb.model import KeywordKind, Use, V3Keyword
from mintlang.keyworddb.usage import refusal
from mintlang.records import record
from mintlang.semantic.model import SemanticModel
from mintlang.semantic.symbols import Occurrence, Symbol, SymbolKind, Unit
from mintlang.semantic.v3_declarations import undefined_variables
from mintlang.syntax import nodes as n
from mintlang.syntax.tokens import TokenKind
from mintlang.syntax.vocabulary import vocabulary


def check(facts: Facts) -> Iterator[Finding]:
    model = facts.model
    if model.program.dialect.modern:
        yield from _undeclared_variables(model, _broken_dims(facts), _prose_after_commands(facts))
    else:
        yield from _v3_undefined_variables(model)
    yield from _labels(facts, _jump_words(facts))
    yield from _macros(model)


_BROKEN_DIM = re.compile(r"\s*DIM\s+([A-Za-z_][A-Za-z0-9_]*(?:\s*,\s*[A-Za-z_][A-Za-z0-9_]*)*)", re.IGNORECASE)


def _broken_dims(facts: Facts) -> dict[str, tuple[Unit, int]]:
    """The names a DIM with a syntax error meant to declare (``DIM x As Integer``, ``DIM a, b``), each with where
    its first such DIM starts: its syntax error is the one diagnostic, not an error 3001 at every later use."""
    sources = {unit: document.source for unit, document in facts.model.documents()}
    found: dict[str, tuple[Unit, int]] = {}
    for unit, line, statement in facts.statements(n.SyntaxError_):
        start, end = line.span(statement.span)
        meant = _BROKEN_DIM.match(sources[unit], start, end)
        for name in meant.group(1).split(",") if meant is not None else ():
            found.setdefault(n.identity(name.strip()), (unit, start))
    return found


def _prose_after_commands(facts: Facts) -> tuple[tuple[Unit, Span], ...]:
    """Where the operands of a command that takes none start and end (``STOP following``, a comment missing its
    REM): its error 2003 is the one diagnostic, not an error 3001 at each word of the comment as well."""
    model = facts.model
    controller, dialect = model.controller.controller, model.program.dialect
    keywords = database().keywords_of(dialect)
    found: list[tuple[Unit, Span]] = []
    for unit, line, statement in facts.statements(n.KeywordStatement):
        keyword = keywords.get(statement.keyword.keyword) if statement.arguments else None  # type: ignore[union-attr]
        if keyword is None or refusal(keyword, controller, dialect, Use.COMMAND) is not None:
            continue  # no operands, or the command itself is refused
        if refusal(keyword, controller, dialect, Use.COMMAND, has_arguments=True) is not None:
            arguments = statement.arguments  # type: ignore[union-attr]
            found.append((unit, line.span(Span(arguments[0].span.start, arguments[-1].span.end))))
    return tuple(found)


def _after(occurrence: Occurrence, place: tuple[Unit, int]) -> bool:
    """Whether ``occurrence`` comes after ``place`` in compile order (the configuration file, then the program)."""
    unit, start = place
    if occurrence.unit is not unit:
        return unit is Unit.CONFIGURATION
    return occurrence.span.start > start


def _undeclared_variables(
    model: SemanticModel, broken_dims: dict[str, tuple[Unit, int]], prose: tuple[tuple[Unit, Span], ...]
) -> Iterator[Finding]:
    renames = database()
    # by their upper-case spellings, as the names are matched whatever their case (LAYR is like layer)
    declared = {symbol.name.upper(): symbol.name for symbol in model.symbols.variables.values() if symbol.definitions}
    places: dict[Unit, _DimPlaces] = {}  # found once per file, for the first name that needs a DIM
    given_as_arrays = cache(partial(_given_as_arrays, model))  # walked once, for the first name that needs it
    for symbol in model.symbols.variables.values():
        undeclared = [
            occurrence
            for occurrence in symbol.references
            if not occurrence.declared_before
            and not _macro_left_in_macro(model, symbol.name, occurrence)
            and not (symbol.identity in broken_dims and _after(occurrence, broken_dims[symbol.identity]))
            and not any(
                unit is occurrence.unit and span.start <= occurrence.span.start < span.end for unit, span in prose
            )
        ]
        if not undeclared:
            continue
        # A Mint v3 word (GAIN, _servo) says what it became, with the rename where that is enough.
        # The squiggles of the file of the first use (the configuration, compiled first, if it uses
        # the name) offer the one DIM that declares it for both files, above that use; a fix edits
        # the file of its diagnostic, so the other file's squiggles offer none. No DIM either when a
        # later DIM exists (a second one would be a double declaration) or when the name is a whole
        # v3 keyword (a variable would silently read 0 where the v3 program read an input).
        was = successor(symbol.name, model.controller)
        old = renames.lookup_v3(symbol.name) if was is None else None
        was_keyword = (was is not None and was.whole_keyword) or (old is not None and old.name == symbol.name.upper())
        declare: dict[Unit, tuple[Fix, ...]] = {}
        if not symbol.definitions and not was_keyword:
            first = min(undeclared, key=lambda use: (use.unit is Unit.PROGRAM, use.span.start))
            if first.unit not in places:
                places[first.unit] = _dim_places(model, first.unit)
            dim = _add_dim(model, symbol, first.unit, first.span, places[first.unit], given_as_arrays)
            declare = {first.unit: (dim,)} if dim is not None else {}
        for occurrence, same_line in _by_line(model, undeclared):
            fixes = declare.get(occurrence.unit, ())
            detail = f"'{occurrence.spelling}' is not declared"
            written = [use.span for use in same_line if use.written_in(model.document(use.unit).source)]
            if was is not None:
                detail += f": it is {was.detail}"
                fixes = (_replace_each(written, was.rename), *fixes) if was.rename and written else fixes
            elif old is not None:  # an abbreviation: a whole v3 keyword has a successor
                detail += f" (in Mint v3 it was the abbreviation of {old.name}; v4: {_v4_words(old)}, see mint-migrate)"
            elif symbol.definitions:
                detail += " (its DIM comes later: declarations must come first)"
            elif (close := closest(occurrence.spelling.upper(), declared)) is not None:
                detail += f"; {did_you_mean(declared[close])}"
                fixes = (_replace_each(written, declared[close]), *fixes) if written else fixes
            elif (constant := _constant_like(occurrence.spelling, model.program.dialect)) is not None:
                detail += f"; did you mean the constant '{constant}'?"  # _hmNEGATIVE_SWTCH
                fixes = (_replace_each(written, constant), *fixes) if written else fixes
            elif (
                not _only_a_variable(model, occurrence)
                and (keyword := _keyword_holding_a_value(occurrence.spelling, model)) is not None
                and _can_stand_there(keyword, symbol, occurrence, model)
            ):
                detail += f"; did you mean the keyword '{keyword}'?"  # SPED = 10
                fixes = (_replace_each(written, keyword), *fixes) if written else fixes
            error = mint_error(3001, occurrence.span, detail, fixes=fixes, from_v3=was is not None or was_keyword)
            yield Finding(occurrence.unit, error)


def _v4_words(old: V3Keyword) -> str:
    """What v4 writes for the v3 keyword ``old``: its own name where v4 reads it still, as the bit keywords
    ``OUT4`` and ``IN2`` (000:14889-14897, 11951), where their successor alone (OUT, IN) is every bit at once."""
    if database().lookup(old.name) is not None:
        return old.name
    return ", ".join(old.v4_names) if old.v4_names else "nothing"


def _v3_undefined_variables(model: SemanticModel) -> Iterator[Finding]:
    """A Mint v3 read of a variable that nothing declared earlier in the text: an assignment, FOR or INPUT
    declares it (001:1352-1367), so the controller's compiler stops with "Undefined Variables" (001:12971-12973)."""
    for occurrence, _ in _by_line(model, list(undefined_variables(model))):
        detail = (
            f"'{occurrence.spelling}' is read before anything declares it: in Mint v3 an assignment, FOR or INPUT "
            "earlier in the text declares a variable"
        )
        error = mint_error(3001, occurrence.span, detail)
        yield Finding(occurrence.unit, replace(error, message=f"{_V3_TITLE}: {detail}"))


_V3_TITLE = "Undefined Variables"  # the v3 guide's name for the error (001:12971)


def _constant_like(spelling: str, dialect: Dialect) -> str | None:
    """The predefined constant an undeclared name is most likely a misspelling of: every constant begins with
    ``_``, and case does not matter (000:843-844); a name without it is one only with it put back (``TRUE`` for
    ``_true``, 000:1003)."""
    constants = database().constants_of(dialect)
    if not spelling.startswith("_"):
        constant = constants.get(f"_{spelling.upper()}")
        return constant.name if constant is not None else None
    meant = closest(spelling.upper(), constants)
    return constants[meant].name if meant is not None else None


def _keyword_holding_a_value(spelling: str, model: SemanticModel) -> str | None:
    """The keyword an undeclared name is most likely a misspelling of (``SPED = 10``), of those read or written."""
    return keyword_like(spelling.upper(), model.controller.controller, values=True, dialect=model.program.dialect)


def _can_stand_there(keyword: str, symbol: Symbol, occurrence: Occurrence, model: SemanticModel) -> bool:
    """Whether ``keyword`` can stand where the name is written: with an index (``xpos(a)``) only a function, as
    v4 addresses axes and channels in square brackets or after a dot (MintMT writes them in round brackets
    too, MT-18); given a value (``state = LIMITFORWARD.0``) only a keyword that can be written."""
    dialect = model.program.dialect
    word = database().keywords_of(dialect).get(keyword)
    if word is None:
        return True
    if symbol.kind is SymbolKind.ARRAY and dialect is not Dialect.MINTMT and word.kind is not KeywordKind.FUNCTION:
        return False
    row = word.attributes_for(model.controller.controller) if occurrence.is_write else None
    return row is None or row.write


def _only_a_variable(model: SemanticModel, occurrence: Occurrence) -> bool:
    """Whether the name stands where no keyword can: the variable of a FOR (000:10887; a keyword as the loop
    counter is an error, 000:18449-18451) or of an INPUT (000:12212)."""
    placed = model.document(occurrence.unit).placed
    line = placed[bisect_right(placed, occurrence.span.start, key=_first_token) - 1]
    for statement in n.walk_statements(line.syntax.statements):
        if isinstance(statement, n.For):
            named = statement.variable.span
        elif isinstance(statement, n.Input):
            named = statement.target.name.span
        else:
            continue
        if line.span(named) == occurrence.span:
            return True
    return False


def _by_line(model: SemanticModel, uses: list[Occurrence]) -> Iterator[tuple[Occurrence, list[Occurrence]]]:
    """The first use of a name on each line, with all its uses there: one diagnostic says it for the line."""
    lines: dict[tuple[Unit, int], list[Occurrence]] = {}
    for use in sorted(uses, key=lambda use: use.span.start):
        lines.setdefault((use.unit, model.document(use.unit).line_index.position(use.span.start).line), []).append(use)
    for same_line in lines.values():
        yield same_line[0], same_line


def _replace_each(spans: list[Span], text: str) -> Fix:
    """Write ``text`` for the name at every one of ``spans`` (its uses on one line, as written there)."""
    return Fix(f"Replace with {text}", tuple(Edit(span, text) for span in spans))


def _macro_left_in_macro(model: SemanticModel, name: str, occurrence: Occurrence) -> bool:
    """A macro's name that came from another macro's text: its definition is the error (2003, at run time)."""
    return n.identity(name) in model.symbols.macros and _written_at(model, occurrence.unit, occurrence.span) != name


def _written_at(model: SemanticModel, unit: Unit, span: Span) -> str:
    """The text at ``span``: a name's own spelling, or the name of the macro whose text it came from."""
    return model.document(unit).source[span.start : span.end]


def _add_dim(  # noqa: PLR0917 - the name, where it is used, and what is known of the file
    model: SemanticModel,
    symbol: Symbol,
    unit: Unit,
    span: Span,
    places: _DimPlaces,
    given_as_arrays: Callable[[], frozenset[str]],
) -> Fix | None:
    """Insert ``DIM name`` on its own line with the file's other DIMs, else at the top: never inside a loop.

    After the last DIM outside any block above the first use, with its indentation; without one, above
    the file's first statement (its opening remarks stay first, and an AUTO or PROTECT that opens the
    file stays first too). A DIM list continued over lines stays whole either way. A name written with
    an index is an array, whose DIM needs its size: the largest index written as a number (the elements
    count from 1); None when an index is computed, as the size is then the author's to choose, and None
    for a name a function takes where its format writes an array (CAMTABLE's position array,
    ``given_as_arrays``): a DIM without a size would make a plain variable of it.
    """
    declared = symbol.name
    if symbol.kind is not SymbolKind.ARRAY and symbol.identity in given_as_arrays():
        return None
    if symbol.kind is SymbolKind.ARRAY:
        size = _largest_index(model, symbol)
        if size is None:
            return None
        declared = f"{symbol.name}({size})"
    document = model.document(unit)
    index = document.line_index
    placed = document.placed
    using = bisect_right(placed, span.start, key=_first_token) - 1
    dims_above = bisect_left(places.dims, using)
    if dims_above:
        dim = placed[places.dims[dims_above - 1]]
        after = index.position(dim.span(dim.syntax.span).end).line
        start, indented = index.line_start(after + 1), dim.number
    else:
        statements = [placed[at] for at in places.first_statements if at <= using]
        first = statements[1] if _opens_file(statements[0]) and len(statements) > 1 else statements[0]
        start, indented = index.line_start(first.number), first.number
    text = document.source
    indent_start = indent_end = index.line_start(indented)
    while indent_end < len(text) and text[indent_end] in " \t":
        indent_end += 1
    newline = line_break(text)
    declaration = f"{text[indent_start:indent_end]}DIM {declared}{newline}"
    return Fix(f"Declare '{declared}' with DIM", (Edit(Span(start, start), declaration),))


def _largest_index(model: SemanticModel, symbol: Symbol) -> int | None:
    """The largest whole number an array is indexed with anywhere in the application; None when no index is
    a number, and None when one is computed (``vals(i)`` in a FOR loop): a size read off the numbers alone
    would be too small for it, and the fixed program would stop with 2016 (Invalid index) when it runs."""
    indexes = [
        element.index
        for facts in model.lines.facts()
        for element in facts.elements
        if element.name.identity == symbol.identity
    ]
    numbers = [index.value for index in indexes if type(index) is n.Number]
    if len(numbers) < len(indexes):
        return None
    whole = [int(number) for number in numbers if number == int(number) and number >= 1]
    return max(whole, default=None)


def _given_as_arrays(model: SemanticModel) -> frozenset[str]:
    """The names functions are given where their formats take an array: ``CAMTABLE ( axis, position array,
    {master increment array} )`` reads the cam's segments from arrays (000:7907, 7932-7934)."""
    dialect = model.program.dialect
    return frozenset(
        argument.name.identity
        for facts in model.lines.facts()
        for call in facts.calls
        for at, argument in enumerate(call.arguments)
        if type(argument) is n.VariableRef and at in _array_places(call.function, dialect)
    )


@cache
def _array_places(function: str, dialect: Dialect) -> frozenset[int]:
    """The places among a function's bracketed values where its format writes an array."""
    found = bracketed(function, dialect)
    items = found[0].replace("{", "").replace("}", "").split(",") if found is not None else []
    return frozenset(at for at, item in enumerate(items) if "array" in item.lower())


def _first_token(line: n.PlacedLine) -> int:
    return line.origin + line.syntax.span.start


@record
class _DimPlaces:
    """Where a file can take a DIM, found once per file: a search per undeclared name, in a file of
    many unclosed blocks, took time in the square of the file's length."""

    dims: list[int]  # the indices in ``placed`` of the lines with a DIM outside every block, in order
    first_statements: list[int]  # those of its first two lines with a statement or a label


_DIM = frozenset({n.Dim})


def _dim_places(model: SemanticModel, unit: Unit) -> _DimPlaces:
    placed = model.document(unit).placed
    nested = _nested_ranges(model, unit)
    with_dims = ((at, placed[at]) for at in model.lines.places_with_kinds(unit, _DIM))  # IF .. THEN bodies too
    dims = [at for at, line in with_dims if _declares(line) and not _inside(nested, line.number)]
    statements = (at for at, line in enumerate(placed) if line.syntax.statements or line.syntax.label is not None)
    return _DimPlaces(dims, list(islice(statements, 2)))


def _nested_ranges(model: SemanticModel, unit: Unit) -> tuple[list[int], list[int]]:
    """The lines inside a block of ``unit`` (between its opener and its closer), as the starts and ends of
    ranges ``[start, end)`` merged and in order."""
    last = model.document(unit).line_index.position(len(model.document(unit).source)).line
    ranges = sorted(
        (block.opener.line + 1, block.closer.line if block.closer is not None else last + 1)
        for block in model.structures[unit].blocks
    )
    starts: list[int] = []
    ends: list[int] = []
    for start, end in ranges:
        if ends and start <= ends[-1]:
            ends[-1] = max(ends[-1], end)
        elif start < end:
            starts.append(start)
            ends.append(end)
    return starts, ends


def _inside(ranges: tuple[list[int], list[int]], number: int) -> bool:
    starts, ends = ranges
    at = bisect_right(starts, number) - 1
    return at >= 0 and number < ends[at]


def _declares(line: n.PlacedLine) -> bool:
    return any(type(statement) is n.Dim for statement in line.syntax.statements)


def _opens_file(line: n.PlacedLine) -> bool:
    """AUTO or PROTECT, which must be the first command of their file."""
    first = line.syntax.statements[0] if line.syntax.statements else None
    return type(first) is n.KeywordStatement and first.keyword.keyword in ("AUTO", "PROTECT")  # type: ignore[union-attr]


def _jump_words(facts: Facts) -> dict[tuple[Unit, Span], str]:
    """GOSUB or GOTO, by the file and span of the label each names."""
    return {
        (unit, line.span(statement.label.span)): statement.word  # type: ignore[union-attr]
        for unit, line, statement in facts.statements(n.Jump)
    }


def _labels(facts: Facts, jumps: dict[tuple[Unit, Span], str]) -> Iterator[Finding]:
    model = facts.model
    runs_on = cache(partial(runs_off_the_end, facts=facts))  # the flow followed once per file, if at all
    colons = cache(partial(_labels_written_with_a_colon, facts))  # read once per file, if a label is missing
    for unit, table in model.symbols.labels.items():
        defined = [symbol.name for symbol in table.values() if symbol.definitions]
        for symbol in table.values():
            first = symbol.definitions[0].spelling if symbol.definitions else ""
            for duplicate in symbol.definitions[1:]:
                detail = f"label #{duplicate.spelling} is already defined{_same_ten(duplicate.spelling, first)}"
                yield Finding(unit, mint_error(3004, duplicate.span, detail))
            if not symbol.definitions:
                for reference in symbol.references:
                    detail = f"no label #{reference.spelling} in this file"
                    colon = colons(unit).get(reference.spelling.upper())
                    if colon is not None:  # its hash makes the label: creating one would make two
                        number, written, fix = colon
                        detail += f": '{written}:' on line {number} is not one (a label is written #{written})"
                        fixes: tuple[Fix, ...] = (fix,)
                    else:
                        detail += _defined_in_other_file(model, unit, symbol)
                        word = jumps.get((unit, reference.span))
                        fixes = _label_fixes(model, unit, reference, defined, word, runs_on=runs_on)
                    yield Finding(unit, mint_error(3004, reference.span, detail, fixes=fixes))


def _labels_written_with_a_colon(facts: Facts, unit: Unit) -> dict[str, tuple[int, str, Fix]]:
    """Other BASICs' labels in ``unit`` (``Init:`` first on its line), by their names upper-cased: the line,
    the name as written and the fix that writes it as Mint's label, placed in the file."""
    found: dict[str, tuple[int, str, Fix]] = {}
    for where, line, statement in facts.statements(n.BareName):
        name, text = statement.name, line.syntax.text
        fix = label_written_with_a_colon(text, name.span) if where is unit else None
        if fix is not None and text[name.span.start : name.span.end] == name.text:
            placed = tuple(Edit(line.span(edit.span), edit.text) for edit in fix.edits)
            found.setdefault(name.text.upper(), (line.number, name.text, replace(fix, edits=placed)))
    return found


def _label_fixes(
    model: SemanticModel,
    unit: Unit,
    reference: Occurrence,
    defined: list[str],
    word: str | None,
    *,
    runs_on: Callable[[Unit], bool],
) -> tuple[Fix, ...]:
    """The label it resembles, where the name is written here (not in a macro's text); and the label made,
    at the end of the file: a subroutine that returns for a GOSUB, a bare label for a GOTO. A subroutine
    goes where the program cannot run into it (the manual's structure: main program, END, subroutines,
    000:279-295), so an END comes first when the code above could run past the end of the file: ending
    there is what the controller did anyway (``runs_on``: whether a file's code can run past its end)."""
    fixes: list[Fix] = []
    by_case = {name.upper(): name for name in defined}
    close = closest(reference.spelling.upper(), by_case, likeness=0.7)
    if close is not None and reference.written_in(model.document(unit).source):
        fixes.append(Fix(f"Change to #{by_case[close]}", (Edit(reference.span, by_case[close]),)))
    text = model.document(unit).source
    newline = line_break(text)
    finish_last_line = newline if text and not text.endswith(("\n", "\r")) else ""
    stop = f"END{newline}" if word == "GOSUB" and runs_on(unit) else ""
    body = f"{newline}RETURN" if word == "GOSUB" else ""
    label = f"{finish_last_line}{stop}{newline}#{reference.spelling}{body}{newline}"
    kind = "subroutine" if word == "GOSUB" else "label"
    fixes.append(Fix(f"Create {kind} #{reference.spelling}", (Edit(Span(len(text), len(text)), label),)))
    return tuple(fixes)


def _defined_in_other_file(model: SemanticModel, unit: Unit, symbol: Symbol) -> str:
    other = Unit.PROGRAM if unit is Unit.CONFIGURATION else Unit.CONFIGURATION
    if symbol.identity in model.symbols.labels[other] and model.symbols.labels[other][symbol.identity].definitions:
        return f" (it is in the {other.value} file, and subroutines are not shared between the two)"
    return ""


def each_line(scope: LineScope) -> Iterator[Finding]:
    """A DEFINE whose name is no name."""
    for statement in scope.facts.statements:
        if type(statement) is n.Define and not statement.name_is_word:
            text = statement.name.text
            words = vocabulary(scope.dialect, scope.controller.controller)
            what = f"{words.quoted(text)} is a keyword and" if words.keyword_name(text) else f"'{text}'"
            detail = f"{what} cannot name a macro"
            yield Finding(scope.unit, mint_error(3005, statement.name.span, detail))


def _macros(model: SemanticModel) -> Iterator[Finding]:
    for symbol in model.symbols.macros.values():
        if symbol.kind is not SymbolKind.MACRO:
            continue
        first = symbol.definitions[0]
        for duplicate in symbol.definitions[1:]:
            detail = f"macro '{duplicate.spelling}' is already defined{_same_ten(duplicate.spelling, first.spelling)}"
            yield Finding(duplicate.unit, mint_error(3005, duplicate.span, detail))
    yield from _macro_in_macro(model)


def _same_ten(spelling: str, first: str) -> str:
    """Why two different spellings are one name."""
    return "" if spelling.upper() == first.upper() else f" ('{first}' has the same first ten characters)"


def _macro_in_macro(model: SemanticModel) -> Iterator[Finding]:
    for unit, document in model.documents():
        for definition in document.definitions:
            for index, (kind, text) in enumerate(definition.body):
                if kind is TokenKind.NAME and n.identity(text) in model.symbols.macros:
                    detail = f"the text of macro '{definition.name}' uses macro '{text}', which Mint does not expand"
                    # 000:1549-1553: the syntax error comes when the macro is used, at run time
                    yield Finding(unit, mint_error(2003, definition.token_span(index), detail, at_run_time=True))
                    break
