"""Turns a (possibly cached) lark tree of one logical line into syntax nodes.

Tree leaves only say which token of the line they stand for; texts and spans
come from the ``LogicalLine``, so one cached tree serves every line with the
same token kinds.
"""

from __future__ import annotations

from collections.abc import Callable

from lark import Token, Tree

from mintlang.diagnostics import Span
from mintlang.syntax import nodes as n
from mintlang.syntax.lines import LogicalLine
from mintlang.syntax.vocabulary import Vocabulary

Child = Tree | Token
_new = tuple.__new__  # builds Span without its Python-level constructor: spans are made per node

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


def number_value(text: str) -> float:
    """The value of a valid Mint number literal: decimal, binary (leading 0) or 0x hex."""
    digits = text.replace("_", "")
    if digits[:2] in ("0x", "0X"):
        return float(int(digits[2:], 16))
    if len(digits) > 1 and digits[0] == "0" and "." not in digits:
        return float(int(digits, 2))
    return float(digits)


class LineBuilder:
    """Builds the statements of one logical line."""

    def __init__(self, line: LogicalLine, words: Vocabulary) -> None:
        self._line = line
        self._words = words

    # ------------------------------------------------------------- helpers

    def _text(self, token: Token) -> str:
        return self._line.texts[token.start_pos]  # type: ignore[index]

    def _span(self, token: Token) -> Span:
        index = token.start_pos
        return _new(Span, (self._line.starts[index], self._line.ends[index]))  # type: ignore[index]

    def _name(self, token: Token) -> n.Name:
        return n.Name(self._text(token), self._span(token))

    def _tree_span(self, tree: Child) -> Span:
        if isinstance(tree, Token):
            return self._span(tree)
        meta = tree.meta
        if meta.empty:  # an empty optional part: a zero-width span where its parent starts
            return Span(0, 0)
        return _new(Span, (self._line.starts[meta.start_pos], self._line.ends[meta.end_pos]))

    @staticmethod
    def _trees(tree: Tree) -> list[Tree]:
        return [child for child in tree.children if isinstance(child, Tree)]

    # ----------------------------------------------------------- the line

    def line(self, tree: Tree) -> tuple[n.Name | None, tuple[n.Statement, ...]]:
        label: n.Name | None = None
        body = tree.children[-1]
        first = tree.children[0]
        if isinstance(first, Token) and first.type == "LABEL":
            text = self._text(first)
            label = n.Name(text[1:], self._span(first))
        return label, self.body(body)  # type: ignore[arg-type]

    def body(self, tree: Tree) -> tuple[n.Statement, ...]:
        statements: list[n.Statement] = []
        for part in self._trees(tree):  # segment* and last
            for statement in self._trees(part):
                statements.append(self.statement(statement))
        return tuple(statements)

    def statement(self, tree: Tree) -> n.Statement:
        rule = _STATEMENTS.get(tree.data)  # type: ignore[arg-type]
        if rule is not None:
            return rule(self, tree)  # type: ignore[return-value]
        token = tree.children[0]
        return n.BlockWord(self._tree_span(tree), token.type)  # type: ignore[union-attr]

    # ---------------------------------------------------------- statements

    def _assignment(self, tree: Tree) -> n.Assignment:
        name, _, value = tree.children
        return n.Assignment(
            self._tree_span(tree), n.VariableRef(self._span(name), self._name(name)), self.expression(value)
        )

    def _element_assignment(self, tree: Tree) -> n.Assignment:
        name, _, index, close, _, value = tree.children
        target_span = Span(self._span(name).start, self._span(close).end)  # type: ignore[arg-type]
        target = n.ElementRef(target_span, self._name(name), self.expression(index))  # type: ignore[arg-type]
        return n.Assignment(self._tree_span(tree), target, self.expression(value))

    def _bare_name(self, tree: Tree) -> n.BareName:
        token = tree.children[0]
        return n.BareName(self._span(token), self._name(token))  # type: ignore[arg-type]

    def _keyword_statement(self, tree: Tree) -> n.KeywordStatement:
        keyword_token = tree.children[0]
        selector: n.Selector | None = None
        terminal: n.Expression | None = None
        values: tuple[n.Expression | None, ...] | None = None
        fill = False
        arguments: tuple[n.Expression | n.StringLiteral, ...] = ()
        using: tuple[n.Expression, ...] = ()
        for child in tree.children[1:]:
            if isinstance(child, Token):
                continue
            if child.data in ("bracket_selector", "dot_selector"):
                selector = self.selector(child)
            elif child.data == "terminal":
                terminal = self._terminal(child)
            elif child.data == "values":
                values, fill = self._values(child)
            elif child.data == "command_arguments":
                arguments, using = self._command_arguments(child)
        ref = self._keyword_ref(keyword_token, selector)  # type: ignore[arg-type]
        return n.KeywordStatement(self._tree_span(tree), ref, terminal, values, fill, arguments, using)

    def _command_arguments(
        self, tree: Tree
    ) -> tuple[tuple[n.Expression | n.StringLiteral, ...], tuple[n.Expression, ...]]:
        arguments: list[n.Expression | n.StringLiteral] = []
        using: tuple[n.Expression, ...] = ()
        for child in tree.children:
            if isinstance(child, Tree) and child.data == "using":
                using = self._using(child)
            elif isinstance(child, Token) and child.type == "STRING":
                arguments.append(self._string(child))
            elif not _is_comma(child):
                arguments.append(self.expression(child))
        return tuple(arguments), using

    def _function_statement(self, tree: Tree) -> n.FunctionStatement:
        function, _, arguments, close, *rest = tree.children
        span = Span(self._span(function).start, self._span(close).end)  # type: ignore[arg-type]
        call = self._make_call(function, span, self._arguments(arguments), bracketed=True)  # type: ignore[arg-type]
        values: tuple[n.Expression | None, ...] | None = None
        fill = False
        if rest:
            values, fill = self._values(rest[-1])  # type: ignore[arg-type]
        return n.FunctionStatement(self._tree_span(tree), call, values, fill)

    def _values(self, tree: Tree) -> tuple[tuple[n.Expression | None, ...], bool]:
        values = tuple(self.expression(child.children[0]) if child.children else None for child in self._trees(tree))
        last = tree.children[-1]
        fill = isinstance(last, Token) and last.type == "SEMICOLON"
        return values, fill

    def _arguments(self, tree: Tree) -> tuple[n.Expression, ...]:
        return tuple(self.expression(child) for child in tree.children if not _is_comma(child))

    def _terminal(self, tree: Tree) -> n.Expression:
        return self._leaf_expression(tree.children[1])  # type: ignore[arg-type]

    def _if_then(self, tree: Tree) -> n.IfThen:
        _, condition, _, body = tree.children
        return n.IfThen(self._tree_span(tree), self.expression(condition), self.body(body))  # type: ignore[arg-type]

    def _if_do(self, tree: Tree) -> n.IfDo:
        return n.IfDo(self._tree_span(tree), self.expression(tree.children[1]))

    def _for(self, tree: Tree) -> n.For:
        children = tree.children
        step = self.expression(children[7]) if len(children) > 7 else None
        return n.For(
            self._tree_span(tree),
            self._name(children[1]),  # type: ignore[arg-type]
            self.expression(children[3]),
            self.expression(children[5]),
            step,
        )

    def _until(self, tree: Tree) -> n.Until:
        return n.Until(self._tree_span(tree), self.expression(tree.children[1]))

    def _while(self, tree: Tree) -> n.While:
        return n.While(self._tree_span(tree), self.expression(tree.children[1]))

    def _jump(self, tree: Tree) -> n.Jump:
        word, target = tree.children
        label = target.children[0]  # type: ignore[union-attr]
        return n.Jump(self._tree_span(tree), word.type, self._name(label))  # type: ignore[union-attr, arg-type]

    def _pause(self, tree: Tree) -> n.Pause:
        condition = self.expression(tree.children[1]) if len(tree.children) > 1 else None
        return n.Pause(self._tree_span(tree), condition)

    def _dim(self, tree: Tree) -> n.Dim:
        children = tree.children
        modifier = children[1] if isinstance(children[1], Token) and children[1].type == "KEYWORD" else None
        rest = children[2:] if modifier is not None else children[1:]
        name = self._name(rest[0])  # type: ignore[arg-type]
        size: n.Expression | None = None
        values: tuple[n.Expression, ...] = ()
        fill = False
        if len(rest) > 1 and isinstance(rest[1], Token) and rest[1].type == "LPAR":
            size = self.expression(rest[2])
        last = children[-1]
        if isinstance(last, Tree) and last.data == "dim_values":
            values = tuple(self.expression(child) for child in last.children if not _is_separator(child))
            fill = isinstance(last.children[-1], Token) and last.children[-1].type == "SEMICOLON"
        offline = self._text(modifier).upper() if modifier is not None else None
        return n.Dim(self._tree_span(tree), name, size, values, fill, offline)

    def _define(self, tree: Tree) -> n.Define:
        children = tree.children
        name_token = children[1].children[0]  # type: ignore[union-attr]
        body_span = self._span(children[3]) if len(children) > 3 else None  # type: ignore[arg-type]
        return n.Define(
            self._tree_span(tree),
            self._name(name_token),  # type: ignore[arg-type]
            name_token.type == "NAME",  # type: ignore[union-attr]
            body_span,
        )

    def _axes(self, tree: Tree) -> n.Axes:
        selector = self.selector(tree.children[1]) if len(tree.children) > 1 else None  # type: ignore[arg-type]
        return n.Axes(self._tree_span(tree), selector)

    def _print(self, tree: Tree) -> n.Print:
        terminal: n.Expression | None = None
        items: tuple[n.PrintItem, ...] = ()
        using: tuple[n.Expression, ...] = ()
        for child in self._trees(tree):
            if child.data == "terminal":
                terminal = self._terminal(child)
            elif child.data == "print_items":
                items = self._print_items(child)
            elif child.data == "using":
                using = self._using(child)
        return n.Print(self._tree_span(tree), terminal, items, using)

    def _print_items(self, tree: Tree) -> tuple[n.PrintItem, ...]:
        items: list[n.PrintItem] = []
        pending: Tree | None = None
        for child in tree.children:
            assert isinstance(child, Tree)
            if child.data == "separator":
                separator = self._text(child.children[0])  # type: ignore[arg-type]
                span = self._tree_span(pending) if pending is not None else self._tree_span(child)
                span = Span(span.start, self._tree_span(child).end)
                items.append(n.PrintItem(span, *self._print_value(pending), separator))
                pending = None
            else:
                pending = child
        if pending is not None:
            items.append(n.PrintItem(self._tree_span(pending), *self._print_value(pending), None))
        return tuple(items)

    def _print_value(self, item: Tree | None) -> tuple[n.Expression | n.StringLiteral | None, str | None]:
        if item is None:
            return None, None
        if item.data == "print_item":
            return self._string(item.children[0]), None  # type: ignore[arg-type]
        if item.data == "print_value":
            return self.expression(item.children[0]), None
        return self.expression(item.children[1]), "HEX" if item.data == "print_hex" else "BIN"

    def _using(self, tree: Tree) -> tuple[n.Expression, ...]:
        return tuple(self.expression(child) for child in tree.children[1:] if not _is_comma(child))

    def _input(self, tree: Tree) -> n.Input:
        terminal: n.Expression | None = None
        prompt: n.StringLiteral | None = None
        target: n.VariableRef | n.ElementRef | None = None
        using: tuple[n.Expression, ...] = ()
        for child in tree.children[1:]:
            if isinstance(child, Token):
                if child.type == "STRING":
                    prompt = self._string(child)
            elif child.data == "terminal":
                terminal = self._terminal(child)
            elif child.data == "input_target":
                target = self._target(child)
            elif child.data == "using":
                using = self._using(child)
        assert target is not None  # the grammar requires it
        return n.Input(self._tree_span(tree), terminal, prompt, target, using)

    def _target(self, tree: Tree) -> n.VariableRef | n.ElementRef:
        name = self._name(tree.children[0])  # type: ignore[arg-type]
        if len(tree.children) == 1:
            return n.VariableRef(name.span, name)
        return n.ElementRef(self._tree_span(tree), name, self.expression(tree.children[2]))

    def _string(self, token: Token) -> n.StringLiteral:
        text = self._text(token)
        closed = len(text) > 1 and not text[-1].isalnum() and text[-1] in '"\u201c\u201d\u201e\u201f\u2033'
        return n.StringLiteral(self._span(token), text, text[1:-1] if closed else text[1:])

    # ----------------------------------------------------------- selectors

    def selector(self, tree: Tree) -> n.Selector:
        span = self._tree_span(tree)
        if tree.data == "bracket_selector":
            items_tree = next(child for child in self._trees(tree) if child.data == "axis_items")
            items = tuple(
                self.expression(item.children[0]) if item.children else None for item in self._trees(items_tree)
            )
            return n.Selector(span, False, items)
        values = [child for child in tree.children if isinstance(child, Tree) and child.data == "dot_value"]
        return n.Selector(span, True, tuple(self._dot_value(value) for value in values))

    def _dot_value(self, value: Tree) -> n.Expression:
        if len(value.children) == 3:  # ( expr )
            return n.Parenthesised(self._tree_span(value), self.expression(value.children[1]))
        return self._leaf_expression(value.children[0])  # type: ignore[arg-type]

    # --------------------------------------------------------- expressions

    def expression(self, tree: Child) -> n.Expression:
        if isinstance(tree, Token):
            return self._leaf_expression(tree)
        return _EXPRESSIONS[tree.data](self, tree)  # type: ignore[index]

    def _leaf_expression(self, token: Token) -> n.Expression:
        kind = token.type
        if kind == "NUMBER":
            text = self._text(token)
            return n.Number(self._span(token), text, number_value(text))
        if kind == "CONSTANT":
            return n.ConstantRef(self._span(token), self._text(token).upper())
        if kind == "CHAR":
            text = self._text(token)
            return n.CharConstant(self._span(token), text, ord(text[1].upper()))
        if kind == "KEYWORD":
            return self._keyword_ref(token, None)
        name = self._name(token)
        return n.VariableRef(name.span, name)

    def _binary(self, tree: Tree) -> n.Binary:
        left, operator, right = tree.children
        return n.Binary(
            self._tree_span(tree),
            _OPERATORS[operator.type],
            self.expression(left),
            self.expression(right),  # type: ignore[union-attr]
        )

    def _unary(self, tree: Tree) -> n.Unary:
        operator, operand = tree.children
        return n.Unary(self._tree_span(tree), _OPERATORS[operator.type], self.expression(operand))  # type: ignore[union-attr]

    def _bare_call(self, tree: Tree) -> n.Call:
        function, operand = tree.children
        return self._make_call(function, self._tree_span(tree), (self.expression(operand),), bracketed=False)  # type: ignore[arg-type]

    def _call(self, tree: Tree) -> n.Call:
        function, _, arguments, _ = tree.children
        return self._make_call(function, self._tree_span(tree), self._arguments(arguments), bracketed=True)  # type: ignore[arg-type]

    def _make_call(
        self, function: Token, span: Span, arguments: tuple[n.Expression, ...], *, bracketed: bool
    ) -> n.Call:
        spelling = self._text(function)
        name = self._words.keyword_name(spelling) or spelling.upper()
        return n.Call(span, name, spelling, self._span(function), arguments, bracketed)

    def _parenthesised(self, tree: Tree) -> n.Parenthesised:
        return n.Parenthesised(self._tree_span(tree), self.expression(tree.children[1]))

    def _number(self, tree: Tree) -> n.Expression:
        """Number, character, constant and variable leaves."""
        return self._leaf_expression(tree.children[0])  # type: ignore[arg-type]

    def _element(self, tree: Tree) -> n.ElementRef:
        name = self._name(tree.children[0])  # type: ignore[arg-type]
        return n.ElementRef(self._tree_span(tree), name, self.expression(tree.children[2]))

    def _keyword_read(self, tree: Tree) -> n.KeywordRef:
        selector = self.selector(tree.children[1]) if len(tree.children) > 1 else None  # type: ignore[arg-type]
        return self._keyword_ref(tree.children[0], selector)  # type: ignore[arg-type]

    def _keyword_ref(self, token: Token, selector: n.Selector | None) -> n.KeywordRef:
        spelling = self._text(token)
        spelling_span = self._span(token)
        words = self._words
        name = words.keyword_name(spelling) or spelling.upper()
        channel: int | None = None
        if spelling.upper() not in words.canonical:
            split = words.split_channel(spelling)
            if split is not None:
                name, channel = split
        end = selector.span.end if selector is not None else spelling_span.end
        return n.KeywordRef(Span(spelling_span.start, end), name, spelling, spelling_span, selector, channel)


_B = LineBuilder
_STATEMENTS: dict[str, Callable[[LineBuilder, Tree], n.Statement]] = {
    "assignment": _B._assignment,
    "element_assignment": _B._element_assignment,
    "bare_name": _B._bare_name,
    "keyword_statement": _B._keyword_statement,
    "function_statement": _B._function_statement,
    "if_do": _B._if_do,
    "for_": _B._for,
    "until": _B._until,
    "while_": _B._while,
    "gosub": _B._jump,
    "goto": _B._jump,
    "pause": _B._pause,
    "dim": _B._dim,
    "define": _B._define,
    "axes": _B._axes,
    "print_": _B._print,
    "input_": _B._input,
    "if_then": _B._if_then,
}
_EXPRESSIONS: dict[str, Callable[[LineBuilder, Tree], n.Expression]] = {
    "binary": _B._binary,
    "unary": _B._unary,
    "bare_call": _B._bare_call,
    "call": _B._call,
    "parenthesised": _B._parenthesised,
    "number": _B._number,
    "char": _B._number,
    "constant": _B._number,
    "variable": _B._number,
    "element": _B._element,
    "keyword_read": _B._keyword_read,
}


def _is_comma(child: Child) -> bool:
    return isinstance(child, Token) and child.type == "COMMA"


def _is_separator(child: Child) -> bool:
    return isinstance(child, Token) and child.type in ("COMMA", "SEMICOLON")
