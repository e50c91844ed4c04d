"""The program front end: ``REM @sim`` and ``REM @expect`` lines inside a Mint program (W-2), ``' @sim`` in MintMT.

Directives live in comments so the program stays valid Mint for the real
controller. The project's lexer finds the comments, so a ``REM`` after ``:``
counts and text inside a string never does.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import partial
from typing import cast

from mintlang.analysis.suggestions import did_you_mean
from mintlang.controllers import ControllerProfile
from mintlang.dialect import Dialect
from mintlang.runtime.scenario import builders
from mintlang.runtime.scenario.collect import Collector
from mintlang.runtime.scenario.directive_words import DIRECTIVE, meant_kind
from mintlang.runtime.scenario.expectations import Comparison, Expectation, Origin
from mintlang.runtime.scenario.phrase import Phrase, to_number
from mintlang.runtime.scenario.problems import Invalid, ScenarioError
from mintlang.runtime.scenario.stimulus import PlantModel, Scenario, WorldRecord
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
    for number, (_, line) in enumerate(lex(source_text, dialect).lines, start=1):
        if line.comment_start < 0:
            continue
        found = DIRECTIVE.match(line.text, line.comment_start, line.content_end)
        kind = meant_kind(found["word"]) if found is not None else None
        if found is None or kind is None:
            continue
        if kind != found["word"].lower():
            message = f"unknown directive '@{found['word']}'; {did_you_mean('@' + kind)}"
            collector.error(number, message, column=found.start("word"))  # the column of its @, from 1
            continue
        phrase = Phrase(found["body"])
        if kind == "sim":
            collector.add(number, partial(_world, phrase))
        else:
            collector.add(number, partial(_expectation, phrase, Origin(source, number), dialect))
    return collector.result()


def _at(phrase: Phrase) -> int:
    phrase.keyword("at")
    return phrase.milliseconds()


def _plant(phrase: Phrase) -> WorldRecord:
    """``plant <axis> <model>`` then the model's values, bare in order (``velamp 40``) or named (``k=40``)."""
    axis = phrase.integer("an axis")
    model = cast(PlantModel, phrase.choice("a plant model", tuple(builders.PLANTS)))
    bare = iter(builders.PLANTS[model].names)
    parameters: dict[str, float] = {}
    while phrase.peek() is not None:
        word = phrase.word("a parameter")
        if phrase.accept("="):
            parameters[word.lower()] = phrase.number(f"the value of {word}")
        elif (name := next(bare, None)) is not None:
            parameters[name] = to_number(word, f"the value of {name}")
        else:
            raise Invalid(f"unexpected {word!r}: give parameters as name=value")
    return builders.plant(axis, model, parameters)


def _input(phrase: Phrase) -> WorldRecord:
    channel = phrase.integer("an input channel")
    if phrase.accept("when"):
        return builders.position_input(channel, phrase)
    level = phrase.integer("a level (0 or 1) or 'when'")
    return builders.input_level(_at(phrase), channel, level)


def _index(phrase: Phrase) -> WorldRecord:
    axis = phrase.integer("an axis")
    phrase.keyword("every")
    every = phrase.integer("the counts between pulses")
    width = phrase.integer("a width in counts") if phrase.accept("width") else 1
    return builders.index_pulse(axis, every, width)


def _fastin(phrase: Phrase) -> WorldRecord:
    channel = phrase.integer("a fast input channel")
    return builders.fast_input(_at(phrase), channel)


def _adc(phrase: Phrase) -> WorldRecord:
    channel = phrase.integer("an ADC channel")
    percent = phrase.number("a level in percent")
    return builders.adc_level(_at(phrase), channel, percent)


def _key(phrase: Phrase) -> WorldRecord:
    text = phrase.text("the keys")
    return builders.keys(_at(phrase), text)


def _host(phrase: Phrase) -> WorldRecord:
    match phrase.choice("a host action", ("write", "read", "raw")):
        case "write":
            address = phrase.integer("a comms address")
            data = phrase.text("the data")
            return builders.host_write(_at(phrase), address, data)
        case "read":
            address = phrase.integer("a comms address")
            return builders.host_read(_at(phrase), address)
        case _:
            hex_words = []
            while (word := phrase.peek()) is not None and word.lower() != "at":
                hex_words.append(phrase.word("hex bytes"))
            return builders.host_raw(_at(phrase), " ".join(hex_words))


def _drives(phrase: Phrase) -> WorldRecord:
    phrase.keyword("enabled")
    return builders.drives_enabled()


_DIRECTIVES: dict[str, Callable[[Phrase], WorldRecord]] = {
    "drives": _drives,
    "plant": _plant,
    "input": _input,
    "index": _index,
    "fastin": _fastin,
    "adc": _adc,
    "key": _key,
    "host": _host,
}


def _world(phrase: Phrase) -> WorldRecord:
    record = _DIRECTIVES[phrase.choice("a directive", tuple(_DIRECTIVES))](phrase)
    phrase.end()
    return record


def _when(phrase: Phrase) -> int | None:
    """``at end``, ``at <ms>`` or nothing (the end)."""
    if not phrase.accept("at") or phrase.accept("end"):
        return None
    return phrase.milliseconds()


def _expectation(phrase: Phrase, origin: Origin, dialect: Dialect) -> Expectation:
    """``<target> <op> <value> [± <tol>] [at ...]``, ``no <target>``, ``terminal contains|is "..."``,
    ``stopped <why>``."""
    expectation: Expectation
    if phrase.accept("stopped"):
        expectation = builders.stopped_expectation(phrase.word("why the run stopped").lower(), origin)
    elif phrase.accept("terminal"):
        exact = phrase.choice("how the terminal is matched", ("contains", "is")) == "is"
        text = phrase.text("the text")
        expectation = builders.terminal_expectation(text, _when(phrase), origin, exact=exact)
    elif phrase.accept("no"):
        what = phrase.word("a keyword or variable")
        expectation = builders.value_expectation(
            what, Comparison.EQUAL, 0.0, tolerance=0.0, at_ms=_when(phrase), origin=origin, dialect=dialect
        )
    else:
        what = phrase.word("a keyword or variable")
        comparison = Comparison(phrase.choice("a comparison", tuple(Comparison)))
        value = phrase.number("a value to compare with")
        tolerance = phrase.number("a tolerance") if phrase.accept("±") or phrase.accept("+-") else 0.0
        expectation = builders.value_expectation(
            what, comparison, value, tolerance=tolerance, at_ms=_when(phrase), origin=origin, dialect=dialect
        )
    phrase.end()
    return expectation
