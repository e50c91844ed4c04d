"""What the words of a directive say: the world record of a ``@sim`` line, the expectation of an ``@expect`` line.

Apart from ``directives``, which finds the directives, so that a program without any (most runs) does
not import the builders and the phrase reader (3 million instructions of a tiny ``mint-run``).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import cast

from mintlang.dialect import Dialect
from mintlang.runtime.scenario import builders
from mintlang.runtime.scenario.expectations import Comparison, Expectation, Origin
from mintlang.runtime.scenario.phrase import Phrase
from mintlang.runtime.scenario.problems import Invalid
from mintlang.runtime.scenario.stimulus import PlantModel, WorldRecord


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
            parameters[name] = phrase.as_number(word, f"the value of {name}")
        else:
            raise phrase.mistake(f"unexpected {word!r}: give parameters as name=value")
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


def world(phrase: Phrase) -> WorldRecord:
    """The world record a ``@sim`` directive sets."""
    record = _DIRECTIVES[phrase.choice("a directive", tuple(_DIRECTIVES))](phrase)
    phrase.end()
    return record


def _when(phrase: Phrase, words: dict[str, int]) -> int | None:
    """``at end``, ``at <ms>`` or nothing (the end)."""
    if not phrase.accept("at") or phrase.accept("end"):
        return None
    words["at_ms"] = phrase.taken() + 1
    return phrase.milliseconds()


def expectation(phrase: Phrase, origin: Origin, dialect: Dialect) -> Expectation:
    """``<target> <op> <value> [± <tol>] [at ...]``, ``no <target>``, ``terminal contains|is "..."``,
    ``stopped <why>``; a value the builders refuse is placed at its word, as the reader places its own."""
    words: dict[str, int] = {}  # the builders' key of each value -> the word it was read from
    try:
        expectation = _expectation(phrase, origin, dialect, words)
    except Invalid as problem:
        if problem.column or problem.key not in words:
            raise
        raise phrase.placed(problem, words[problem.key]) from None
    phrase.end()
    return expectation


def _expectation(phrase: Phrase, origin: Origin, dialect: Dialect, words: dict[str, int]) -> Expectation:
    if phrase.accept("stopped"):
        why = phrase.word("why the run stopped").lower()
        words["stopped"] = phrase.taken()
        return builders.stopped_expectation(why, origin)
    if phrase.accept("terminal"):
        exact = phrase.choice("how the terminal is matched", ("contains", "is")) == "is"
        text = phrase.text("the text")
        words["terminal_contains"] = phrase.taken()
        return builders.terminal_expectation(text, _when(phrase, words), origin, exact=exact)
    if phrase.accept("no"):
        what = phrase.word("a keyword or variable")
        words["what"] = phrase.taken()
        return builders.value_expectation(
            what, Comparison.EQUAL, 0.0, tolerance=0.0, at_ms=_when(phrase, words), origin=origin, dialect=dialect
        )
    what = phrase.word("a keyword or variable")
    words["what"] = phrase.taken()
    comparison = Comparison(phrase.choice("a comparison", tuple(Comparison)))
    value = phrase.number("a value to compare with")
    tolerance = phrase.number("a tolerance") if phrase.accept("±") or phrase.accept("+-") else 0.0
    words["tolerance"] = phrase.taken()
    return builders.value_expectation(
        what, comparison, value, tolerance=tolerance, at_ms=_when(phrase, words), origin=origin, dialect=dialect
    )
