"""The program front end: ``REM @sim`` and ``REM @expect`` lines inside a Mint program (W-2), ``' @sim`` in MintMT.

Directives live in comments so the program stays valid Mint for the real
controller. The project's lexer finds the comments, so a ``REM`` after ``:``
counts and text inside a string never does.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from functools import partial

from mintlang.analysis.suggestions import did_you_mean
from mintlang.controllers import ControllerProfile
from mintlang.dialect import Dialect
from mintlang.runtime.scenario.collect import Collector
from mintlang.runtime.scenario.directive_words import DIRECTIVE, meant_kind
from mintlang.runtime.scenario.expectations import Origin
from mintlang.runtime.scenario.problems import ScenarioError
from mintlang.runtime.scenario.stimulus import Scenario
from mintlang.syntax.lexer import lex


def parse_directives(
    source_text: str,
    source: str = "program",
    controller: ControllerProfile | None = None,
    dialect: Dialect | str = Dialect.V4,
) -> tuple[Scenario, list[ScenarioError]]:
    """The world and expectations a program's comments script, and every directive that could not be read.

    With ``controller``, a directive for an axis or channel it does not have is one of them. The program is
    in ``dialect``, which names the keywords its expectations read.
    """
    dialect = Dialect(dialect)
    collector = Collector(source, controller, dialect)
    for number, found, kind in _directives(source_text, dialect):
        if kind != found["word"].lower():
            message = f"unknown directive '@{found['word']}'; {did_you_mean('@' + kind)}"
            collector.error(number, message, column=found.start("word"))  # the column of its @, from 1
            continue
        from mintlang.runtime.scenario.directive_bodies import expectation, world  # noqa: PLC0415 - its docstring
        from mintlang.runtime.scenario.phrase import Phrase  # noqa: PLC0415 - as directive_bodies

        phrase = Phrase(found["body"], column=found.start("body") + 1)
        at = found.start("word")  # the column of its @, from 1
        build = (
            partial(world, phrase) if kind == "sim" else partial(expectation, phrase, Origin(source, number), dialect)
        )
        collector.add(number, build, column=at, column_of=phrase.column_of)
    return collector.result()


def ignored_directives(source_text: str, source: str, dialect: Dialect | str = Dialect.V4) -> tuple[str, ...]:
    """A warning for each directive in a file they are not read from (a configuration file), at its ``@``.

    Directives script the program's run, and are read from the program only: one written elsewhere would
    otherwise do nothing in silence, and a check meant to fail the run would pass unnoticed.
    """
    return tuple(
        f"{source}:{number}:{found.start('word')}: @{found['word']} is read only from the program, not from its"
        " configuration file: this one is ignored"
        for number, found, _ in _directives(source_text, Dialect(dialect))
    )


def _directives(source_text: str, dialect: Dialect) -> Iterator[tuple[int, re.Match[str], str]]:
    """Each comment that is a directive, or one slip from one: its line from 1, its match and the kind meant."""
    for number, (_, line) in enumerate(lex(source_text, dialect).lines, start=1):
        if line.comment_start < 0:
            continue
        found = DIRECTIVE.match(line.text, line.comment_start, line.content_end)
        kind = meant_kind(found["word"]) if found is not None else None
        if found is not None and kind is not None:
            yield number, found, kind
