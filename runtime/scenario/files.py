"""The file front end: a scenario written in TOML (``mint-run --stimulus/--expect FILE``).

Every table is read through checks that name the key and its line, and all
mistakes of a file are gathered before one ``ScenarioFileError`` is raised.
"""

from __future__ import annotations

import datetime
import math
import re
import tomllib
from collections.abc import Callable, Mapping
from functools import partial
from pathlib import Path

from mintlang.analysis.suggestions import closest, did_you_mean
from mintlang.controllers import ControllerProfile
from mintlang.dialect import Dialect
from mintlang.runtime.scenario import builders
from mintlang.runtime.scenario.collect import Collector
from mintlang.runtime.scenario.expectations import Comparison, Expectation, Origin
from mintlang.runtime.scenario.phrase import Phrase
from mintlang.runtime.scenario.problems import Invalid, ScenarioError, ScenarioFileError
from mintlang.runtime.scenario.stimulus import Scenario, WorldRecord
from mintlang.runtime.scenario.toml_layout import Layout, Section
from mintlang.source import read_regular

_TOML_LINE = re.compile(r"at line (\d+)")
_COMPARISONS = {
    "equals": Comparison.EQUAL,
    "not_equal": Comparison.NOT_EQUAL,
    "at_least": Comparison.AT_LEAST,
    "at_most": Comparison.AT_MOST,
    "above": Comparison.ABOVE,
    "below": Comparison.BELOW,
}


class _Entry:
    """One table of the file; each read checks the value's type and blames the key's line."""

    __slots__ = ("_section", "_values", "dialect", "name", "origin")

    def __init__(
        self,
        name: str,
        values: Mapping[str, object],
        section: Section,
        source: str,
        dialect: Dialect = Dialect.V4,
    ) -> None:
        """``dialect``: the language of the program, which names the keywords an expectation reads."""
        self.name = name
        self._values = values
        self._section = section
        self.origin = Origin(source, section.line)
        self.dialect = dialect

    def __contains__(self, key: str) -> bool:
        return key in self._values

    def line_of(self, key: str) -> int:
        return self._section.line_of(key)

    def written(self) -> list[str]:
        """The keys the entry has, as written."""
        return list(self._values)

    def allow(self, *keys: str) -> None:
        """Refuse any key not in ``keys``, naming the keys that would do."""
        if unexpected := [key for key in self._values if key not in keys]:
            listed = ", ".join(repr(key) for key in unexpected)
            message = f"unknown key {listed} in {self.name}; it takes {', '.join(keys)}{_meant(unexpected, keys)}"
            raise Invalid(message, self.line_of(unexpected[0]))

    def value(self, key: str) -> object:
        if key not in self._values:
            raise Invalid(f"{self.name} needs {key}", self._section.line)
        return self._values[key]

    def _wrong(self, key: str, kind: str) -> Invalid:
        return Invalid(f"{key} must be {kind}, not {_as_written(self._values[key])}", self.line_of(key))

    def integer(self, key: str, default: int | None = None) -> int:
        if default is not None and key not in self:
            return default
        value = self.value(key)
        if isinstance(value, int) and not isinstance(value, bool):
            return value
        raise self._wrong(key, "a whole number")

    def number(self, key: str, default: float | None = None) -> float:
        if default is not None and key not in self:
            return default
        value = self.value(key)
        if isinstance(value, int | float) and not isinstance(value, bool) and math.isfinite(value):
            return float(value)
        raise self._wrong(key, "a number")

    def text(self, key: str) -> str:
        value = self.value(key)
        if isinstance(value, str):
            return value
        raise self._wrong(key, "text in quotes")


def _as_written(value: object) -> str:
    """``value`` as TOML writes it (``true``, ``2026-11-29``, ``[1, 2]``), for a message quoting the file."""
    match value:
        case bool():
            return "true" if value else "false"
        case datetime.date() | datetime.time():
            return value.isoformat()
        case list():
            return f"[{', '.join(map(_as_written, value))}]"
        case dict():
            return "{ " + ", ".join(f"{key} = {_as_written(item)}" for key, item in value.items()) + " }"
        case _:
            return repr(value)


def _misspelt(written: list[str], known: tuple[str, ...]) -> tuple[str, str] | None:
    """The first word of ``written`` that is surely a misspelling of one of ``known``, and that one."""
    return next(((word, meant) for word in written if (meant := closest(word, known)) is not None), None)


def _meant(written: list[str], known: tuple[str, ...]) -> str:
    """``; did you mean 'tolerance'?`` for the first of ``written`` misspelt from ``known``; else nothing."""
    found = _misspelt(written, known)
    return f"; {did_you_mean(found[1])}" if found is not None else ""


def _one_of(entry: _Entry, keys: tuple[str, ...]) -> str:
    """The one key of ``keys`` the entry has; an entry has exactly one."""
    present = [key for key in keys if key in entry]
    if len(present) > 1:
        raise Invalid(f"{entry.name} has both {' and '.join(present)}", entry.line_of(present[-1]))
    if not present:
        needed = f"needs one of {', '.join(keys)}"
        if (found := _misspelt(entry.written(), keys)) is not None:
            word, meant = found
            message = f"unknown key {word!r} in {entry.name}, which {needed}; {did_you_mean(meant)}"
            raise Invalid(message, entry.line_of(word))
        written = [repr(key) for key in entry.written()]
        raise Invalid(
            f"{entry.name} {needed}" + (f" (it has {', '.join(written)})" if written else ""), entry.origin.line
        )
    return present[0]


def _input(entry: _Entry) -> WorldRecord:
    if "when" in entry:
        entry.allow("channel", "when")
        return builders.position_input(entry.integer("channel"), Phrase(entry.text("when")))
    entry.allow("channel", "level", "at_ms")
    return builders.input_level(entry.integer("at_ms"), entry.integer("channel"), entry.integer("level"))


def _index(entry: _Entry) -> WorldRecord:
    entry.allow("axis", "every", "width")
    return builders.index_pulse(entry.integer("axis"), entry.integer("every"), entry.integer("width", 1))


def _fastin(entry: _Entry) -> WorldRecord:
    entry.allow("channel", "at_ms")
    return builders.fast_input(entry.integer("at_ms"), entry.integer("channel"))


def _adc(entry: _Entry) -> WorldRecord:
    entry.allow("channel", "percent", "at_ms")
    return builders.adc_level(entry.integer("at_ms"), entry.integer("channel"), entry.number("percent"))


def _key(entry: _Entry) -> WorldRecord:
    entry.allow("text", "at_ms")
    return builders.keys(entry.integer("at_ms"), entry.text("text"))


def _host(entry: _Entry) -> WorldRecord:
    match _one_of(entry, ("write", "read", "raw")):
        case "write":
            entry.allow("write", "data", "node", "at_ms")
            node = entry.integer("node", builders.DEFAULT_NODE)
            return builders.host_write(entry.integer("at_ms"), entry.integer("write"), entry.text("data"), node)
        case "read":
            entry.allow("read", "node", "at_ms")
            node = entry.integer("node", builders.DEFAULT_NODE)
            return builders.host_read(entry.integer("at_ms"), entry.integer("read"), node)
        case _:
            entry.allow("raw", "at_ms")
            return builders.host_raw(entry.integer("at_ms"), entry.text("raw"))


def _when(entry: _Entry) -> int | None:
    """``at = "end"``, ``at_ms = <ms>`` or neither: None stands for the end of the run."""
    if "at" in entry and "at_ms" in entry:
        raise Invalid(f"{entry.name} has both at and at_ms", entry.line_of("at_ms"))
    if "at" in entry and entry.value("at") != "end":
        message = f'at is "end"; for a time write at_ms = <ms>, not at = {_as_written(entry.value("at"))}'
        raise Invalid(message, entry.line_of("at"))
    return entry.integer("at_ms") if "at_ms" in entry else None


def _expect(entry: _Entry) -> Expectation:
    match _one_of(entry, ("what", "terminal_contains", "terminal_is", "stopped")):
        case "what":
            key = _one_of(entry, tuple(_COMPARISONS))
            entry.allow("what", key, "tolerance", "at", "at_ms")
            return builders.value_expectation(
                entry.text("what"),
                _COMPARISONS[key],
                entry.number(key),
                tolerance=entry.number("tolerance", 0.0),
                at_ms=_when(entry),
                origin=entry.origin,
                dialect=entry.dialect,
            )
        case "terminal_contains":
            entry.allow("terminal_contains", "at", "at_ms")
            return builders.terminal_expectation(entry.text("terminal_contains"), _when(entry), entry.origin)
        case "terminal_is":
            entry.allow("terminal_is", "at", "at_ms")
            return builders.terminal_expectation(entry.text("terminal_is"), _when(entry), entry.origin, exact=True)
        case _:
            entry.allow("stopped")
            return builders.stopped_expectation(entry.text("stopped"), entry.origin)


_ARRAYS: dict[str, Callable[[_Entry], WorldRecord | Expectation]] = {
    "input": _input,
    "index": _index,
    "fastin": _fastin,
    "adc": _adc,
    "key": _key,
    "host": _host,
    "expect": _expect,
}


def _drives(value: object) -> WorldRecord:
    """``drives = "enabled"``: without it the drives start disabled, as at power-up."""
    if value != "enabled":
        raise Invalid(f'drives is "enabled" (without it they start disabled, as at power-up), not {_as_written(value)}')
    return builders.drives_enabled()


def _plant(axis_key: str, choice: object, section: Section, source: str) -> WorldRecord:
    """``<axis> = "<model>"`` or ``<axis> = { model = "<model>", <parameter> = <number> ... }``."""
    if not axis_key.isdigit():
        raise Invalid(f"the keys of [plant] are axis numbers, not {axis_key!r}")
    if isinstance(choice, str):
        return builders.plant(int(axis_key), choice, {})
    if not isinstance(choice, dict):
        raise Invalid(f'plant {axis_key} is a model ("ideal") or a table ({{ model = "velamp", k = 40 }})')
    entry = _Entry(f"plant {axis_key}", choice, Section(section.line_of(axis_key), {}), source)
    parameters = {key: entry.number(key) for key in choice if key != "model"}
    return builders.plant(int(axis_key), entry.text("model"), parameters)


def _read(document: Mapping[str, object], layout: Layout, collector: Collector) -> None:
    for name, value in document.items():
        if name == "plant" and isinstance(value, dict):
            section = layout.table(name)
            for axis_key, choice in value.items():
                build = partial(_plant, axis_key, choice, section, collector.source)
                collector.add(section.line_of(axis_key), build)
        elif name in _ARRAYS and isinstance(value, list) and all(isinstance(item, dict) for item in value):
            for index, table in enumerate(value):
                entry = _Entry(f"[[{name}]]", table, layout.entry(name, index), collector.source, collector.dialect)
                collector.add(entry.origin.line, partial(_ARRAYS[name], entry), entry.line_of)
        elif name == "drives":
            collector.add(layout.top_line(name), partial(_drives, value))
        elif name in _ARRAYS or name == "plant":
            shape = "a table: write [plant]" if name == "plant" else f"a list of tables: write [[{name}]]"
            collector.error(layout.top_line(name), f"{name} is {shape}")
        else:
            known = ("drives", "plant", *_ARRAYS)
            message = f"unknown entry {name!r}; a scenario has {', '.join(known)}{_meant([name], known)}"
            collector.error(layout.top_line(name), message)


def _document(path: Path) -> tuple[str, dict[str, object]]:
    source = str(path)
    try:
        text = read_regular(path).decode("utf-8")
    except OSError as problem:
        raise ScenarioFileError([ScenarioError(source, 0, f"cannot read the file: {problem.strerror}")]) from None
    except UnicodeDecodeError:
        raise ScenarioFileError([ScenarioError(source, 0, "the file is not UTF-8 text")]) from None
    try:
        return text, tomllib.loads(text)
    except tomllib.TOMLDecodeError as problem:
        found = _TOML_LINE.search(str(problem))
        line = int(found[1]) if found else 0
        raise ScenarioFileError([ScenarioError(source, line, f"not valid TOML: {problem}")]) from None


def load_scenario(
    path: str | Path, controller: ControllerProfile | None = None, dialect: Dialect | str = Dialect.V4
) -> Scenario:
    """The scenario a TOML file describes; ``ScenarioFileError`` lists every mistake with its line.

    With ``controller``, an entry for an axis or channel it does not have is a mistake too. Expectations
    name keywords in the program's ``dialect``.
    """
    path = Path(path)
    text, document = _document(path)
    collector = Collector(str(path), controller, Dialect(dialect))
    _read(document, Layout(text), collector)
    scenario, errors = collector.result()
    if errors:
        raise ScenarioFileError(sorted(errors, key=lambda error: error.line))
    return scenario
