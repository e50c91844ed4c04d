"""Compiles a lark tree of one logical line into a function that builds its syntax nodes.

A parse depends only on the line's token kinds, so one tree serves every line
with the same kinds (``grammar.py`` caches them). Walking that tree again for
every such line would repeat the same decisions (which child is the selector,
which token the name); instead the tree is compiled once into nested closures
that only read the line's texts and offsets and create the nodes. Tree leaves
hold their token's index in the line (``Token.start_pos``) and subtrees the
indices of their first and last token (``Tree.meta``).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TypeVar

from mintlang.diagnostics import Span
from mintlang.syntax import nodes as n
from mintlang.syntax.lark_runtime import Token, Tree
from mintlang.syntax.lines import LogicalLine
from mintlang.syntax.spans import span as _span
from mintlang.syntax.vocabulary import Vocabulary

Child = Tree | Token
T = TypeVar("T")
K = TypeVar("K")
V = TypeVar("V")
Make = Callable[[LogicalLine, Vocabulary], T]
LineResult = tuple[n.Name | None, tuple[n.Statement, ...]]
LineBuilder = Callable[[LogicalLine, Vocabulary], LineResult]


_OPERATORS = {
    "AND": "AND",
    "OR": "OR",
    "XOR": "XOR",
    "MOD": "MOD",
    "NOT": "NOT",
    "EQUAL": "=",
    "NOTEQUAL": "<>",
    "LESSTHAN": "<",
    "MORETHAN": ">",
    "LESSEQUAL": "<=",
    "MOREEQUAL": ">=",
    "PLUS": "+",
    "MINUS": "-",
    "STAR": "*",
    "SLASH": "/",
    "TILDE": "~",
}
_QUOTES = '"\u201c\u201d\u201e\u201f\u2033'


# --------------------------------------------------------------- small pieces


def _index(token: Child) -> int:
    return token.start_pos  # type: ignore[union-attr, return-value]


def _edges(tree: Child) -> tuple[int, int]:
    """Indices of the first and last token under ``tree``."""
    if isinstance(tree, Token):
        return _index(tree), _index(tree)
    return tree.meta.start_pos, tree.meta.end_pos


def _span_of(first: int, last: int) -> Make[Span]:
    def make(line: LogicalLine, _: Vocabulary) -> Span:
        return _span(line.starts[first], line.ends[last])

    return make


def _tree_span(tree: Child) -> Make[Span]:
    return _span_of(*_edges(tree))


def _trees(tree: Tree) -> list[Tree]:
    return [child for child in tree.children if isinstance(child, Tree)]


def _is_token(child: Child, kind: str) -> bool:
    return isinstance(child, Token) and child.type == kind


def _is_separator(child: Child) -> bool:
    return _is_token(child, "COMMA") or _is_token(child, "SEMICOLON")


def _constant(value: T) -> Make[T]:
    return lambda line, words: value


def _sequence(makers: list[Make[T]]) -> Make[tuple[T, ...]]:
    if not makers:
        return _constant(())
    if len(makers) == 1:
        (only,) = makers
        return lambda line, words: (only(line, words),)
    if len(makers) == 2:  # axes [0,1], two values: without the comprehension's frame
        first, second = makers
        return lambda line, words: (first(line, words), second(line, words))
    return lambda line, words: tuple([make(line, words) for make in makers])


def _optional(child: Child | None, compile_child: Callable[[Child], Make[T]]) -> Make[T | None]:
    return compile_child(child) if child is not None else _constant(None)


def _name(token: Child) -> Make[n.Name]:
    index = _index(token)

    def make(line: LogicalLine, _: Vocabulary) -> n.Name:
        return n.Name(line.texts[index], _span(line.starts[index], line.ends[index]))

    return make


def _string(token: Child) -> Make[n.StringLiteral]:
    index = _index(token)

    def make(line: LogicalLine, _: Vocabulary) -> n.StringLiteral:
        text = line.texts[index]
        closed = len(text) > 1 and text[-1] in _QUOTES
        span = _span(line.starts[index], line.ends[index])
        return n.StringLiteral(span, text, text[1:-1] if closed else text[1:])

    return make


# ----------------------------------------------------------------- the line


def compile_line(tree: Tree) -> LineBuilder:
    """A builder for every line whose token kinds parsed to ``tree``."""
    first = tree.children[0]
    body = _body(tree.children[-1])  # type: ignore[arg-type]
    if not _is_token(first, "LABEL"):
        return lambda line, words: (None, body(line, words))
    index = _index(first)

    def make(line: LogicalLine, words: Vocabulary) -> LineResult:
        label = n.Name(line.texts[index][1:], _span(line.starts[index], line.ends[index]))
        return label, body(line, words)

    return make


def _body(tree: Tree) -> Make[tuple[n.Statement, ...]]:
    return _sequence([_statement(statement) for part in _trees(tree) for statement in _trees(part)])


def _statement(tree: Tree) -> Make[n.Statement]:
    compile_rule = _STATEMENTS.get(tree.data)  # type: ignore[arg-type]
    if compile_rule is not None:
        return compile_rule(tree)
    span = _tree_span(tree)
    word = tree.children[0].type  # type: ignore[union-attr]
    return lambda line, words: n.BlockWord(span(line, words), word)


# -------------------------------------------------------------- statements


def _assignment(tree: Tree) -> Make[n.Statement]:
    name_token, _, value = tree.children
    span, name, expression = _tree_span(tree), _name(name_token), _expression(value)

    def make(line: LogicalLine, words: Vocabulary) -> n.Statement:
        written = name(line, words)
        return n.Assignment(span(line, words), n.VariableRef(written.span, written), expression(line, words))

    return make


def _element_assignment(tree: Tree) -> Make[n.Statement]:
    name_token, _, index, close, _, value = tree.children
    span, target_span = _tree_span(tree), _span_of(_index(name_token), _index(close))
    name, index_of, expression = _name(name_token), _expression(index), _expression(value)

    def make(line: LogicalLine, words: Vocabulary) -> n.Statement:
        target = n.ElementRef(target_span(line, words), name(line, words), index_of(line, words))
        return n.Assignment(span(line, words), target, expression(line, words))

    return make


def _bare_name(tree: Tree) -> Make[n.Statement]:
    name = _name(tree.children[0])

    def make(line: LogicalLine, words: Vocabulary) -> n.Statement:
        written = name(line, words)
        return n.BareName(written.span, written)

    return make


def _keyword_statement(tree: Tree) -> Make[n.Statement]:
    parts = {child.data: child for child in _trees(tree)}
    selector_tree = parts.get("bracket_selector") or parts.get("dot_selector") or parts.get("address_selector")
    keyword = _keyword_ref(tree.children[0], selector_tree)  # type: ignore[arg-type]
    terminal = _optional(parts.get("terminal"), _terminal)
    values, fill = _values(parts["values"]) if "values" in parts else (_constant(None), False)
    arguments, using, formats, trailing, semicolons = (
        _command_arguments(parts["command_arguments"])
        if "command_arguments" in parts
        else (_constant(()), _constant(()), (), False, ())
    )
    span = _tree_span(tree)

    def make(line: LogicalLine, words: Vocabulary) -> n.Statement:
        return n.KeywordStatement(
            span(line, words),
            keyword(line, words),
            terminal(line, words),
            values(line, words),
            fill,
            arguments(line, words),
            using(line, words),
            formats,
            trailing,
            semicolons,
        )

    return make


_CommandArguments = tuple[
    Make[tuple[n.Expression | n.StringLiteral, ...]],
    Make[tuple[n.Expression, ...]],
    tuple[str | None, ...],
    bool,
    tuple[int, ...],
]


def _command_arguments(tree: Tree) -> _CommandArguments:
    """The operands, the USING, how each operand prints (HEX, DEC, BIN), whether a separator ends them, and
    which of them a semicolon follows."""
    arguments: list[Make[n.Expression | n.StringLiteral]] = []
    formats: list[str | None] = []
    semicolons: list[int] = []
    using: Make[tuple[n.Expression, ...]] = _constant(())
    trailing = False
    for child in tree.children:
        trailing = isinstance(child, Tree) and child.data == "separator"
        if trailing:
            if _is_token(child.children[0], "SEMICOLON"):  # type: ignore[union-attr]
                semicolons.append(len(arguments) - 1)
        elif isinstance(child, Tree) and child.data == "using":
            using = _using(child)
        elif isinstance(child, Tree) and child.data == "modified_argument":
            arguments.append(_expression(child.children[1]))
            formats.append(str(child.children[0]).upper())
        elif _is_token(child, "STRING"):
            arguments.append(_string(child))
            formats.append(None)
        else:
            arguments.append(_expression(child))
            formats.append(None)
    return _sequence(arguments), using, tuple(formats) if any(formats) else (), trailing, tuple(semicolons)


def _function_statement(tree: Tree) -> Make[n.Statement]:
    function, _, arguments, close, *rest = tree.children
    call = _call_of(function, _span_of(_index(function), _index(close)), _arguments(arguments), bracketed=True)  # type: ignore[arg-type]
    values, fill = _values(rest[-1]) if rest else (_constant(None), False)  # type: ignore[arg-type]
    span = _tree_span(tree)
    return lambda line, words: n.FunctionStatement(span(line, words), call(line, words), values(line, words), fill)


def _values(tree: Tree) -> tuple[Make[tuple[n.Expression | None, ...]], bool]:
    places = [_expression(child.children[0]) if child.children else _constant(None) for child in _trees(tree)]
    return _sequence(places), _is_token(tree.children[-1], "SEMICOLON")  # type: ignore[arg-type]


def _arguments(tree: Tree) -> Make[tuple[n.Expression, ...]]:
    return _sequence([_expression(child) for child in tree.children if not _is_token(child, "COMMA")])


def _terminal(tree: Child) -> Make[n.Expression]:
    return _leaf(tree.children[1])  # type: ignore[union-attr]


def _if_then(tree: Tree) -> Make[n.Statement]:
    _, condition, _, body = tree.children
    span, test, statements = _tree_span(tree), _expression(condition), _body(body)  # type: ignore[arg-type]
    return lambda line, words: n.IfThen(span(line, words), test(line, words), statements(line, words))


def _condition_statement(node: Callable[..., n.Statement]) -> Callable[[Tree], Make[n.Statement]]:
    """IF .. DO, UNTIL and WHILE: a keyword and one condition."""

    def compile_rule(tree: Tree) -> Make[n.Statement]:
        span, condition = _tree_span(tree), _expression(tree.children[1])
        return lambda line, words: node(span(line, words), condition(line, words))

    return compile_rule


def _for(tree: Tree) -> Make[n.Statement]:
    children = tree.children
    span, variable = _tree_span(tree), _name(children[1])
    start, end = _expression(children[3]), _expression(children[5])
    step = _expression(children[7]) if len(children) > 7 else _constant(None)

    def make(line: LogicalLine, words: Vocabulary) -> n.Statement:
        return n.For(span(line, words), variable(line, words), start(line, words), end(line, words), step(line, words))

    return make


def _jump(tree: Tree) -> Make[n.Statement]:
    word, target = tree.children
    span, label, kind = _tree_span(tree), _name(target.children[0]), word.type  # type: ignore[union-attr]
    return lambda line, words: n.Jump(span(line, words), kind, label(line, words))


def _event(tree: Tree) -> Make[n.Statement]:
    span, name = _tree_span(tree), _name(tree.children[1].children[0])  # type: ignore[union-attr]
    return lambda line, words: n.EventBlock(span(line, words), name(line, words))


def _pause(tree: Tree) -> Make[n.Statement]:
    span = _tree_span(tree)
    condition = _expression(tree.children[1]) if len(tree.children) > 1 else _constant(None)
    return lambda line, words: n.Pause(span(line, words), condition(line, words))


def _dim(tree: Tree) -> Make[n.Statement]:
    children = tree.children
    modifier = children[1] if _is_token(children[1], "KEYWORD") else None
    rest = children[2:] if modifier is not None else children[1:]
    name = _name(rest[0])
    has_size = len(rest) > 1 and _is_token(rest[1], "LPAR")
    size = _expression(rest[2]) if has_size else _constant(None)
    last = children[-1]
    listed = isinstance(last, Tree) and last.data == "dim_values"
    listed_values = [child for child in last.children if not _is_separator(child)] if listed else []  # type: ignore[union-attr]
    values = _sequence([_expression(child) for child in listed_values])
    fill = listed and _is_token(last.children[-1], "SEMICOLON")  # type: ignore[union-attr]
    modifier_index = _index(modifier) if modifier is not None else None
    span = _tree_span(tree)

    def make(line: LogicalLine, words: Vocabulary) -> n.Statement:
        offline = line.texts[modifier_index].upper() if modifier_index is not None else None
        return n.Dim(span(line, words), name(line, words), size(line, words), values(line, words), fill, offline)

    return make


def _define(tree: Tree) -> Make[n.Statement]:
    children = tree.children
    name_token = children[1].children[0]  # type: ignore[union-attr]
    is_word = name_token.type == "NAME"  # type: ignore[union-attr]
    body = _tree_span(children[3]) if len(children) > 3 else _constant(None)
    span, name = _tree_span(tree), _name(name_token)
    return lambda line, words: n.Define(span(line, words), name(line, words), is_word, body(line, words))


def _axes(tree: Tree) -> Make[n.Statement]:
    span = _tree_span(tree)
    selector = _selector(tree.children[1], tree.children[0]) if len(tree.children) > 1 else _constant(None)  # type: ignore[arg-type]
    return lambda line, words: n.Axes(span(line, words), selector(line, words))


def _print(tree: Tree) -> Make[n.Statement]:
    parts = {child.data: child for child in _trees(tree)}
    terminal = _optional(parts.get("terminal"), _terminal)
    items = _print_items(parts["print_items"])
    using = _using(parts["using"]) if "using" in parts else _constant(())
    span = _tree_span(tree)
    return lambda line, words: n.Print(span(line, words), terminal(line, words), items(line, words), using(line, words))


def _print_items(tree: Tree) -> Make[tuple[n.PrintItem, ...]]:
    items: list[Make[n.PrintItem]] = []
    pending: Tree | None = None
    for child in tree.children:
        assert isinstance(child, Tree)
        if child.data == "separator":
            first = _edges(pending)[0] if pending is not None else _edges(child)[0]
            items.append(_print_item(pending, _span_of(first, _edges(child)[1]), child.children[0]))
            pending = None
        else:
            pending = child
    if pending is not None:
        items.append(_print_item(pending, _tree_span(pending), None))
    return _sequence(items)


_PRINT_MODIFIERS = {"print_hex": "HEX", "print_dec": "DEC", "print_bin": "BIN"}


def _print_item(item: Tree | None, span: Make[Span], separator: Child | None) -> Make[n.PrintItem]:
    value: Make[n.Expression | n.StringLiteral | None]
    style: str | None = None
    if item is None:
        value = _constant(None)
    elif item.data == "print_item":
        value = _string(item.children[0])
    elif item.data == "print_value":
        value = _expression(item.children[0])
    else:
        value, style = _expression(item.children[1]), _PRINT_MODIFIERS[item.data]
    separator_index = _index(separator) if separator is not None else None

    def make(line: LogicalLine, words: Vocabulary) -> n.PrintItem:
        written = line.texts[separator_index] if separator_index is not None else None
        return n.PrintItem(span(line, words), value(line, words), style, written)

    return make


def _using(tree: Tree) -> Make[tuple[n.Expression, ...]]:
    return _sequence([_expression(child) for child in tree.children[1:] if not _is_token(child, "COMMA")])


def _input(tree: Tree) -> Make[n.Statement]:
    parts = {child.data: child for child in _trees(tree)}
    prompt_token = next((child for child in tree.children if _is_token(child, "STRING")), None)
    prompt = _optional(prompt_token, _string)
    terminal = _optional(parts.get("terminal"), _terminal)
    target = _target(parts["input_target"])
    using = _using(parts["using"]) if "using" in parts else _constant(())
    span = _tree_span(tree)

    def make(line: LogicalLine, words: Vocabulary) -> n.Statement:
        return n.Input(
            span(line, words), terminal(line, words), prompt(line, words), target(line, words), using(line, words)
        )

    return make


def _target(tree: Tree) -> Make[n.VariableRef | n.ElementRef]:
    if len(tree.children) == 1:
        return _variable(tree.children[0])
    return _element(tree)


# ---------------------------------------------------------------- selectors


def _selector(tree: Tree, keyword: Child) -> Make[n.Selector]:
    span = _tree_span(tree)
    if tree.data == "address_selector":
        return _address_selector(tree, keyword)
    if tree.data == "bracket_selector":
        items_tree = next(child for child in _trees(tree) if child.data == "axis_items")
        items, dot = _axis_items(items_tree), False
    else:
        items, dot = _sequence([_dot_value(child) for child in _trees(tree) if child.data == "dot_value"]), True
    index = _index(keyword)

    def make(line: LogicalLine, words: Vocabulary) -> n.Selector:
        at, found = span(line, words), items(line, words)
        indices = _dot_indices(line, words, index, found) if dot and len(found) > 1 else 0
        if any(type(item) is not n.Number for item in found):  # an expression: ``.(a+1)``
            return n.Selector(at, dot, found, indices)
        key = (at, dot, indices, *map(id, found))
        return _selectors.get(key) or _kept(_selectors, key, n.Selector(at, dot, found, indices))

    return make


def _dot_indices(line: LogicalLine, words: Vocabulary, index: int, found: tuple[n.Expression | None, ...]) -> int:
    """How many values after the axis's are a MintMT keyword's indices in v4's dot form: the move buffer note
    writes the inter-vector angle ``CONTOURPARAMETER.axis.0`` (004:223), as ``CONTOURPARAMETER(axis, 0)``."""
    upper = line.texts[index].upper()
    return min(words.indices.get(words.canonical.get(upper, upper), 0), len(found) - 1)


def _axis_items(tree: Tree) -> Make[tuple[n.Expression | None, ...]]:
    return _sequence([_expression(item.children[0]) if item.children else _constant(None) for item in _trees(tree)])


def _address_selector(tree: Tree, keyword: Child) -> Make[n.Selector]:
    """MintMT's ``(axes, indices)``: a ``[..]`` list inside gives its axes in place; how many items are
    indices is the keyword's to say (``words.indices``), so it is counted when the line is built."""
    span, index = _tree_span(tree), _index(keyword)
    parts: list[Make[tuple[n.Expression | None, ...]]] = []
    after_group: int | None = None  # the items after a [..] list of axes: they can only be indices
    for item in _trees(next(child for child in _trees(tree) if child.data == "address_items")):
        group = next((child for child in _trees(item) if child.data == "axis_items"), None)
        if group is not None:
            parts.append(_axis_items(group))
            after_group = 0
        else:
            parts.append(_sequence([_expression(item.children[0]) if item.children else _constant(None)]))
            after_group = after_group + 1 if after_group is not None else None

    def make(line: LogicalLine, words: Vocabulary) -> n.Selector:
        items = tuple(item for part in parts for item in part(line, words))
        upper = line.texts[index].upper()
        name = words.canonical.get(upper, upper)
        given = max(len(items) - 1, 0) if after_group is None else after_group
        return n.Selector(span(line, words), False, items, min(words.indices.get(name, 0), given))

    return make


def _dot_value(tree: Tree) -> Make[n.Expression]:
    if len(tree.children) == 3:  # ( expr )
        span, inner = _tree_span(tree), _expression(tree.children[1])
        return lambda line, words: n.Parenthesised(span(line, words), inner(line, words))
    return _leaf(tree.children[0])


# -------------------------------------------------------------- expressions


def _expression(tree: Child) -> Make[n.Expression]:
    if isinstance(tree, Token):
        return _leaf(tree)
    return _EXPRESSIONS[tree.data](tree)  # type: ignore[index]


# One node for every equal number, selector and keyword at the same place of a line: programs
# write a few constants (0, 1, 100) and keywords (IDLE.0, POS.1) in the same columns line after
# line, and a node of each took a tenth of a check's memory. Like a whole line's syntax
# (``parser``), such a node names no place. A key names the shared nodes inside by ``id()``:
# the node it maps to holds them, so no other object can have their ids while the key is in its
# table. Each table is emptied when full, so it stays small whatever the input.
_numbers: dict[tuple[int, int, str], n.Number] = {}
_selectors: dict[tuple[object, ...], n.Selector] = {}
_keywords: dict[tuple[object, ...], n.KeywordRef] = {}
_SHARED_KEPT = 100_000


def _kept(table: dict[K, V], key: K, node: V) -> V:
    """``node``, which ``table`` now holds for ``key``: callers look ``key`` up first (``table.get(key) or``),
    so a node found costs no call."""
    if len(table) >= _SHARED_KEPT:
        table.clear()
    table[key] = node
    return node


def _number(start: int, end: int, text: str) -> n.Number:
    key = (start, end, text)
    return _numbers.get(key) or _kept(_numbers, key, n.Number(_span(start, end), text, n.number_value(text)))


def _leaf(token: Child) -> Make[n.Expression]:
    kind = token.type  # type: ignore[union-attr]
    index = _index(token)
    if kind == "NUMBER":

        def number(line: LogicalLine, _: Vocabulary) -> n.Expression:
            return _number(line.starts[index], line.ends[index], line.texts[index])

        return number
    if kind == "CONSTANT":

        def constant(line: LogicalLine, _: Vocabulary) -> n.Expression:
            return n.ConstantRef(_span(line.starts[index], line.ends[index]), line.texts[index].upper())

        return constant
    if kind == "CHAR":

        def char(line: LogicalLine, _: Vocabulary) -> n.Expression:
            text = line.texts[index]
            return n.CharConstant(_span(line.starts[index], line.ends[index]), text, n.character_code(text))

        return char
    if kind == "KEYWORD":
        return _keyword_ref(token, None)
    return _variable(token)


def _variable(token: Child) -> Make[n.VariableRef]:
    name = _name(token)

    def make(line: LogicalLine, words: Vocabulary) -> n.VariableRef:
        written = name(line, words)
        return n.VariableRef(written.span, written)

    return make


def _binary(tree: Tree) -> Make[n.Expression]:
    left_tree, operator, right_tree = tree.children
    span, symbol = _tree_span(tree), _OPERATORS[operator.type]  # type: ignore[union-attr]
    left, right = _expression(left_tree), _expression(right_tree)
    return lambda line, words: n.Binary(span(line, words), symbol, left(line, words), right(line, words))


def _unary(tree: Tree) -> Make[n.Expression]:
    operator, operand_tree = tree.children
    span, symbol, operand = _tree_span(tree), _OPERATORS[operator.type], _expression(operand_tree)  # type: ignore[union-attr]
    return lambda line, words: n.Unary(span(line, words), symbol, operand(line, words))


def _bare_call(tree: Tree) -> Make[n.Expression]:
    function, operand = tree.children
    return _call_of(function, _tree_span(tree), _sequence([_expression(operand)]), bracketed=False)


def _call(tree: Tree) -> Make[n.Expression]:
    function, _, arguments, _ = tree.children
    return _call_of(function, _tree_span(tree), _arguments(arguments), bracketed=True)  # type: ignore[arg-type]


def _call_of(
    function: Child, span: Make[Span], arguments: Make[tuple[n.Expression, ...]], *, bracketed: bool
) -> Make[n.Call]:
    index = _index(function)

    def make(line: LogicalLine, words: Vocabulary) -> n.Call:
        spelling = line.texts[index]
        name = words.keyword_name(spelling) or spelling.upper()
        spelling_span = _span(line.starts[index], line.ends[index])
        return n.Call(span(line, words), name, spelling, spelling_span, arguments(line, words), bracketed)

    return make


def _parenthesised(tree: Tree) -> Make[n.Expression]:
    span, inner = _tree_span(tree), _expression(tree.children[1])
    return lambda line, words: n.Parenthesised(span(line, words), inner(line, words))


def _single_leaf(tree: Tree) -> Make[n.Expression]:
    """Number, character, constant and variable leaves wrapped in a one-token tree."""
    return _leaf(tree.children[0])


def _element(tree: Tree) -> Make[n.ElementRef]:
    span, name, index = _tree_span(tree), _name(tree.children[0]), _expression(tree.children[2])
    return lambda line, words: n.ElementRef(span(line, words), name(line, words), index(line, words))


def _keyword_read(tree: Tree) -> Make[n.Expression]:
    selector = tree.children[1] if len(tree.children) > 1 else None
    return _keyword_ref(tree.children[0], selector)  # type: ignore[arg-type]


def _keyword_ref(token: Child, selector_tree: Tree | None) -> Make[n.KeywordRef]:
    index = _index(token)
    selector = _selector(selector_tree, token) if selector_tree is not None else _constant(None)
    last = _edges(selector_tree)[1] if selector_tree is not None else index

    def make(line: LogicalLine, words: Vocabulary) -> n.KeywordRef:
        spelling = line.texts[index]
        upper = spelling.upper()
        name = words.canonical.get(upper)
        channel: int | None = None
        if name is None:
            split = words.split_channel(upper)
            name, channel = split if split is not None else (upper, None)
        start = line.starts[index]
        spelling_span = _span(start, line.ends[index])
        span = _span(start, line.ends[last])
        selected = selector(line, words)
        if selected is None:
            key: tuple[object, ...] = (span, name, spelling, channel)  # the spelling's span starts the keyword's
        elif any(type(item) is not n.Number for item in selected.items):
            return n.KeywordRef(span, name, spelling, spelling_span, selected, channel)
        else:
            addressed = (selected.span, selected.dot, selected.indices, *map(id, selected.items))
            key = (span, name, spelling, channel, *addressed)
        return _keywords.get(key) or _kept(
            _keywords, key, n.KeywordRef(span, name, spelling, spelling_span, selected, channel)
        )

    return make


_STATEMENTS: dict[str, Callable[[Tree], Make[n.Statement]]] = {
    "assignment": _assignment,
    "element_assignment": _element_assignment,
    "bare_name": _bare_name,
    "keyword_statement": _keyword_statement,
    "function_statement": _function_statement,
    "if_do": _condition_statement(n.IfDo),
    "for_": _for,
    "until": _condition_statement(n.Until),
    "while_": _condition_statement(n.While),
    "gosub": _jump,
    "goto": _jump,
    "pause": _pause,
    "event_": _event,
    "dim": _dim,
    "define": _define,
    "axes": _axes,
    "print_": _print,
    "input_": _input,
    "if_then": _if_then,
}
_EXPRESSIONS: dict[str, Callable[[Tree], Make[n.Expression]]] = {
    "binary": _binary,
    "unary": _unary,
    "bare_call": _bare_call,
    "call": _call,
    "parenthesised": _parenthesised,
    "number": _single_leaf,
    "char": _single_leaf,
    "constant": _single_leaf,
    "variable": _single_leaf,
    "element": _element,
    "keyword_read": _keyword_read,
}
