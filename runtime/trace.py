"""Per-tick traces: a CSV of axis and I/O state, and a plot of it.

A trace row is written for every servo tick, so tracing turns off the
simulator's tick skipping; the same program and stimulus give the same bytes.
Plotting needs matplotlib (``pip install mintlang[plot]``); nothing else does.
"""

from __future__ import annotations

import csv
from pathlib import Path
from typing import IO

from mintlang.runtime.controller import Controller

AXIS_COLUMNS = ("demand", "pos", "vel", "folerror", "axismode", "axiserror", "dac")
FIRST_COLUMN = "time_ms"


class PlotUnavailable(Exception):
    """matplotlib is not installed."""


class Trace:
    """Collects one row per tick for the axes that ``axes`` names."""

    def __init__(self, axes: tuple[int, ...]) -> None:
        self.axes = axes
        self.rows: list[tuple[float, ...]] = []

    def header(self) -> list[str]:
        columns = [FIRST_COLUMN]
        for number in self.axes:
            columns += [f"{name}.{number}" for name in AXIS_COLUMNS]
        return [*columns, "in", "out", "relay"]

    def record(self, controller: Controller, tick: int) -> None:
        row: list[float] = [float(tick)]
        for number in self.axes:
            axis = controller.axes[number]
            scale = axis.scale
            row += [
                axis.position(axis.demand),
                axis.position(axis.measured),
                axis.velocity_counts() / scale,
                (axis.demand - axis.measured) / scale,
                float(axis.axismode),
                float(axis.axiserror),
                axis.dac,
            ]
        row += [float(controller.io.active), float(controller.io.out), float(controller.io.relay)]
        self.rows.append(tuple(row))

    def write_csv(self, stream: IO[str]) -> None:
        writer = csv.writer(stream, lineterminator="\n")
        writer.writerow(self.header())
        for row in self.rows:
            writer.writerow([repr(value) if value != int(value) else str(int(value)) for value in row])

    def plot(self, path: Path) -> None:
        """Position, velocity and following error against time, one line per axis."""
        _matplotlib()
        from matplotlib import pyplot  # noqa: PLC0415 - optional dependency, loaded only when plotting

        figure, panels = pyplot.subplots(3, 1, sharex=True, figsize=(10, 8))
        times = [row[0] for row in self.rows]
        for offset, number in enumerate(self.axes):
            base = 1 + offset * len(AXIS_COLUMNS)
            for panel, column in zip(panels, (1, 2, 3), strict=True):
                panel.plot(times, [row[base + column] for row in self.rows], label=f"axis {number}")
        for panel, title in zip(panels, ("POS", "VEL", "FOLERROR"), strict=True):
            panel.set_ylabel(title)
            panel.grid(True)
            panel.legend(loc="upper right")
        panels[-1].set_xlabel("time (ms)")
        figure.tight_layout()
        figure.savefig(path)
        pyplot.close(figure)


def _matplotlib() -> None:
    try:
        import matplotlib  # noqa: PLC0415 - optional dependency, loaded only when plotting
    except ImportError as missing:
        raise PlotUnavailable("plotting needs matplotlib: pip install 'mintlang[plot]'") from missing
    matplotlib.use("Agg")


def image_types() -> frozenset[str]:
    """The file extensions ``plot`` can write (it picks the format by the extension)."""
    _matplotlib()
    from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: PLC0415

    return frozenset(FigureCanvasAgg.get_supported_filetypes())
