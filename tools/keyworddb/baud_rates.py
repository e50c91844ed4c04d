"""The baud rates each controller takes, read from SERIALBAUD's table (000:15856-15863).

The table has a column per port, grouped under a controller ("NextMove MintDrive ServoNode 51" over
"RS232 RS485 RS232 RS485 RS232"), and a row per rate whose ticks are garbled into a run without their
columns; a '*' marks the port's default (000:15856). A row ticking every column is read in order, and so
sets the default of the ports it stars. A row whose stars are as many as the ports still without a
default gives those ports the rate. Any other tick could be any port's, so its rate is allowed on every
port. A controller takes the rates of its ports.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from mintlang.keyworddb.model import Controller
from tools.keyworddb.attributes import controllers_of_label
from tools.keyworddb.checkmarks import TICK

_HEADER = re.compile(r"^Baud Rate (?P<ports>.+)$")
_ROW = re.compile(r"^(?P<rate>\d{4,6})\b(?P<ticks>.*)$")
_LABEL = re.compile(r"NextMove(?: PCI| PC| BX)?|MintDrive|ServoNode(?: 51)?")
_TICK = re.compile(re.escape(TICK) + r"\*?")


def _port_groups(ports: Sequence[str]) -> list[list[int]]:
    """The columns of each controller: a run of ports that starts again at the first port's name."""
    groups: list[list[int]] = []
    for column, port in enumerate(ports):
        if port == ports[0] or not groups:
            groups.append([])
        groups[-1].append(column)
    return groups


def _columns_of_rates(rows: Sequence[tuple[float, list[str]]], width: int) -> dict[float, set[int]]:
    """The columns each rate may be ticked in."""
    columns: dict[float, set[int]] = {}
    defaulted: set[int] = set()
    for rate, ticks in rows:  # the rows that tick every column first: they place the defaults
        if len(ticks) == width:
            columns[rate] = set(range(width))
            defaulted |= {column for column, tick in enumerate(ticks) if tick.endswith("*")}
    for rate, ticks in rows:
        if rate in columns:
            continue
        starred = [tick for tick in ticks if tick.endswith("*")]
        left = [column for column in range(width) if column not in defaulted]
        if len(starred) == len(ticks) == len(left):
            columns[rate] = set(left)
        else:
            columns[rate] = set(range(width))
    return columns


def baud_rates(lines: Sequence[str], supported: tuple[Controller, ...]) -> dict[Controller, tuple[float, ...]]:
    """Each supported controller's rates, or none when the table cannot be laid out."""
    header = next((index for index, line in enumerate(lines) if _HEADER.match(line)), None)
    if header is None:
        return {}
    ports = _HEADER.match(lines[header])["ports"].split()  # type: ignore[index]
    label_line = next((line for line in reversed(lines[:header]) if line), "")
    labels = _LABEL.findall(label_line)
    groups = _port_groups(ports)
    rows = [
        (float(match["rate"]), _TICK.findall(match["ticks"]))
        for line in lines[header + 1 :]
        if (match := _ROW.match(line))
    ]
    if not rows:
        return {}
    if len(labels) != len(groups):  # the columns cannot be told apart: every rate everywhere
        every = tuple(sorted(rate for rate, _ in rows))
        return dict.fromkeys(supported, every)
    columns = _columns_of_rates(rows, len(ports))
    result: dict[Controller, tuple[float, ...]] = {}
    for label, group in zip(labels, groups, strict=True):
        rates = tuple(sorted(rate for rate, where in columns.items() if where & set(group)))
        for controller in controllers_of_label(label, supported):
            result[controller] = rates
    return result
