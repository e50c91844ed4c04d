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
from mintlang.runtime.scenario.stimulus import PlantModel, WorldRecord


def _at(phrase: Phrase) -> int:
    phrase.keyword("at")
    return phrase.milliseconds()


def _plant(phrase: Phrase) -> WorldRecord:
    """``plant <axis> <model>`` then the model's values, bare in order (``velamp 40``) or named (``k=40``)."""
    axis = phrase.integer("an axis", "axis")
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
    channel = phrase.integer("an input channel", "channel")
    if phrase.accept("when"):
        phrase.mark("when")
        return builders.position_input(channel, phrase)
    word = phrase.word("a level (0 or 1) or 'when'", "level")
    if not word.isdecimal():  # a whole number out of range is the builder's to name
        raise phrase.mistake(f"expected a level (0 or 1) or 'when', not {word!r}")
    level = int(word)
    return builders.input_level(_at(phrase), channel, level)


def _index(phrase: Phrase) -> WorldRecord:
    axis = phrase.integer("an axis", "axis")
    phrase.keyword("every")
    every = phrase.integer("the counts between pulses", "every")
    width = phrase.integer("a width in counts", "width") if phrase.accept("width") else 1
    return builders.index_pulse(axis, every, width)


def _fastin(phrase: Phrase) -> WorldRecord:
    channel = phrase.integer("a fast input channel", "channel")
    return builders.fast_input(_at(phrase), channel)


def _adc(phrase: Phrase) -> WorldRecord:
    channel = phrase.integer("an ADC channel", "channel")
    percent = phrase.number("a level in percent", "percent")
    return builders.adc_level(_at(phrase), channel, percent)


def _key(phrase: Phrase) -> WorldRecord:
    text = phrase.text("the keys", "text")
    return builders.keys(_at(phrase), text)


def _host(phrase: Phrase) -> WorldRecord:
    match phrase.choice("a host action", ("write", "read", "raw")):
        case "write":
            address = phrase.integer("a comms address", "write")
            data = phrase.text("the data")
            return builders.host_write(_at(phrase), address, data)
        case "read":
            address = phrase.integer("a comms address", "read")
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


def _when(phrase: Phrase) -> int | None:
    """``at end``, ``at <ms>`` or nothing (the end)."""
    if not phrase.accept("at") or phrase.accept("end"):
        return None
    return phrase.milliseconds()


def expectation(phrase: Phrase, origin: Origin, dialect: Dialect) -> Expectation:
    """``<target> <op> <value> [± <tol>] [at ...]``, ``no <target>``, ``terminal contains|is "..."``,
    ``stopped <why>``."""
    expectation = _expectation(phrase, origin, dialect)
    phrase.end()
    return expectation


def _expectation(phrase: Phrase, origin: Origin, dialect: Dialect) -> Expectation:
    if phrase.accept("stopped"):
        why = phrase.word("why the run stopped", "stopped").lower()
        return builders.stopped_expectation(why, origin)
    if phrase.accept("terminal"):
        exact = phrase.choice("how the terminal is matched", ("contains", "is")) == "is"
        text = phrase.text("the text", "terminal_contains")
        return builders.terminal_expectation(text, _when(phrase), origin, exact=exact)
    if phrase.accept("no"):
        what = phrase.word("a keyword or variable", "what")
        return builders.value_expectation(
            what, Comparison.EQUAL, 0.0, tolerance=0.0, at_ms=_when(phrase), origin=origin, dialect=dialect
        )
    what = phrase.word("a keyword or variable", "what")
    comparison = Comparison(phrase.choice("a comparison", tuple(Comparison)))
    value = phrase.number("a value to compare with")
    tolerance = phrase.number("a tolerance", "tolerance") if phrase.accept("±") or phrase.accept("+-") else 0.0
    return builders.value_expectation(
        what, comparison, value, tolerance=tolerance, at_ms=_when(phrase), origin=origin, dialect=dialect
    )
