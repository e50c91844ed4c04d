"""Per-tick traces: a CSV of axis and I/O state, and a plot of it.

A trace row is taken for every servo tick, so tracing turns off the
simulator's tick skipping; the same program and stimulus give the same bytes.
Rows stream to the CSV file as the run makes them and the plot keeps a
bounded summary of them, so memory does not grow with the length of a run.
Plotting needs matplotlib (the ``plot`` extra; the message says how to add it); nothing else does.
"""

from __future__ import annotations

import csv
from collections.abc import Callable
from pathlib import Path
from typing import IO, TYPE_CHECKING

from mintlang.runtime.controller import Controller
from mintlang.runtime.simulation import Interrupt

if TYPE_CHECKING:
    from matplotlib.axes import Axes as MatplotlibAxes

AXIS_COLUMNS = ("demand", "pos", "vel", "folerror", "axismode", "axiserror", "dac")
FIRST_COLUMN = "time_ms"
PLOTTED = {"pos": "POS", "vel": "VEL", "folerror": "FOLERROR"}  # column to panel title, top to bottom
PLOT_SPANS = 1024  # spans a plotted series keeps at most: one or two points for each pixel of the image's width
IO_CHANGES = 20_000  # changes of the input and output words a plot keeps; later ones are not drawn
# The encoder reads whole counts while the demand has fractions: a following error within half a count is that
# rounding, below what the encoder can tell, and the plot draws it as 0 (the CSV keeps it).
QUANTISATION_COUNTS = 0.5


class PlotUnavailable(Exception):
    """matplotlib is not installed."""


class Envelope:
    """One plotted series in bounded memory: the lowest and the highest point of each span of ticks.

    When there are more than ``limit`` spans, each pair merges into one twice
    as long, so a run of any length keeps between ``limit / 2`` and ``limit``.
    A span's two extremes, drawn in time order, keep the peaks (a following
    error spike) that keeping every n-th tick would skip; until the first
    merge every tick is its own span, so a short run is drawn point by point.
    """

    def __init__(self, limit: int = PLOT_SPANS) -> None:
        self.limit = limit
        self.ticks = 1  # the length of a span
        self.spans: list[list[float]] = []  # [span number, time of the low, low, time of the high, high]

    def add(self, time: float, value: float) -> None:
        number = time // self.ticks
        spans = self.spans
        if spans and spans[-1][0] == number:
            span = spans[-1]
            if value < span[2]:
                span[1], span[2] = time, value
            elif value > span[4]:
                span[3], span[4] = time, value
            return
        spans.append([number, time, value, time, value])
        if len(spans) > self.limit:
            self._merge_pairs()

    def _merge_pairs(self) -> None:
        self.ticks *= 2
        merged: list[list[float]] = []
        for number, *extremes in self.spans:
            if merged and merged[-1][0] == number // 2:
                span = merged[-1]
                if extremes[1] < span[2]:
                    span[1], span[2] = extremes[0], extremes[1]
                if extremes[3] > span[4]:
                    span[3], span[4] = extremes[2], extremes[3]
            else:
                merged.append([number // 2, *extremes])
        self.spans = merged

    def points(self) -> tuple[list[float], list[float]]:
        """Times and values to draw: each span's extremes in the order they happened."""
        times: list[float] = []
        values: list[float] = []
        for _number, low_time, low, high_time, high in self.spans:
            for time, value in sorted({(low_time, low), (high_time, high)}):
                times.append(time)
                values.append(value)
        return times, values


class Changes:
    """A digital word as it changed: (time, value) pairs, the first ``IO_CHANGES`` of them."""

    def __init__(self) -> None:
        self.points: list[tuple[float, int]] = []
        self.complete = True  # False once a change could not be kept

    def add(self, time: float, value: int) -> None:
        if self.points and self.points[-1][1] == value:
            return
        if len(self.points) >= IO_CHANGES:
            self.complete = False
            return
        self.points.append((time, value))

    def bits(self) -> list[int]:
        """The bits that were ever on."""
        ever = 0
        for _, value in self.points:
            ever |= value
        return [bit for bit in range(ever.bit_length()) if ever >> bit & 1]


class Trace:
    """The observer behind ``--trace`` and ``--plot``, for the axes ``axes`` names.

    Between ``open`` and ``close`` each row goes to ``csv_path`` (if any) as
    it is taken, so nothing but the plot's summary stays in memory. A write
    that fails ends the run (``Interrupt``) and is kept in ``failure``, for
    the caller to report after the results. Unless the axes were ``chosen``,
    the plot shows only those that moved.
    """

    def __init__(self, axes: tuple[int, ...], csv_path: Path | None, *, plotting: bool, chosen: bool = True) -> None:
        self.axes = axes
        self.chosen = chosen
        self.csv_path = csv_path
        self.failure: OSError | None = None
        self.scales = dict.fromkeys(axes, 1.0)  # each axis's SCALE when last recorded: the plot's units
        self.io = {"IN": Changes(), "OUT": Changes()} if plotting else {}
        self.last_time = 0.0  # of the last row recorded
        self._stream: IO[str] | None = None
        self._write_row: Callable[[list[str]], object] | None = None
        self.plotted = {(number, column): Envelope() for number in axes for column in PLOTTED} if plotting else {}
        self._plotted_columns = [
            (1 + axes.index(number) * len(AXIS_COLUMNS) + AXIS_COLUMNS.index(column), envelope, number, column)
            for (number, column), envelope in self.plotted.items()
        ]

    def open(self) -> None:
        """Start the CSV file with its header; raises ``OSError`` when it cannot be opened."""
        if self.csv_path is not None:
            self._stream = self.csv_path.open("w", encoding="utf-8", newline="")
            self._write_row = csv.writer(self._stream, lineterminator="\n").writerow
            self._write_row(self.header())

    def close(self) -> None:
        """Write out the rows still buffered; one that does not fit (a full disk) becomes ``failure``."""
        if self._stream is None:
            return
        try:
            self._stream.close()
        except OSError as error:
            self.failure = self.failure or error

    def header(self) -> list[str]:
        columns = [FIRST_COLUMN]
        for number in self.axes:
            columns += [f"{name}.{number}" for name in AXIS_COLUMNS]
        return [*columns, "in", "out", "relay"]

    def record(self, controller: Controller, tick: int) -> None:
        row = self._row(controller, tick)
        if self._write_row is not None:
            try:
                self._write_row([_cell(value) for value in row])
            except OSError as error:
                self.failure = error
                raise Interrupt(f"cannot write {self.csv_path}: {error.strerror or error}") from None
        for index, envelope, number, column in self._plotted_columns:
            value = row[index]
            if column == "folerror" and abs(value * self.scales[number]) <= QUANTISATION_COUNTS:
                value = 0.0
            envelope.add(row[0], value)
        self.last_time = row[0]
        if self.io:
            self.io["IN"].add(row[0], controller.io.active)
            self.io["OUT"].add(row[0], controller.io.out)

    def _row(self, controller: Controller, tick: int) -> list[float]:
        row: list[float] = [float(tick)]
        for number in self.axes:
            axis = controller.axes[number]
            scale = axis.scale
            self.scales[number] = scale
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
        return row

    def moved(self) -> tuple[int, ...]:
        """The axes whose position, velocity or following error ever changed (all, if the axes were chosen)."""
        if self.chosen:
            return self.axes
        return tuple(
            number
            for number in self.axes
            if any(len(set(self.plotted[number, column].points()[1])) > 1 for column in PLOTTED)
        )

    def plot(self, path: Path, title: str = "") -> None:
        """Position, velocity and following error against time, one line per axis that moved, then the
        inputs and outputs that were ever on as lanes."""
        _matplotlib()
        from matplotlib import pyplot  # noqa: PLC0415 - optional dependency, loaded only when plotting

        axes = self.moved()
        lanes = [(name, bit) for name, changes in self.io.items() for bit in changes.bits()]
        figure, panels = pyplot.subplots(
            len(PLOTTED) + (1 if lanes else 0),
            1,
            sharex=True,
            figsize=(11, 8 + (0.25 * len(lanes) if lanes else 0)),
            gridspec_kw={"height_ratios": [3] * len(PLOTTED) + ([max(1, len(lanes) // 3)] if lanes else [])},
        )
        for panel, (column, name) in zip(panels, PLOTTED.items(), strict=False):
            for number in axes:
                panel.plot(*self.plotted[number, column].points(), label=self._axis_label(number))
            panel.set_ylabel(f"{name} ({self.units(axes, per_second=column == 'vel')})")
            if column == "folerror":
                panel.set_title("within half a count drawn as 0", fontsize="small", loc="right")
            panel.grid(True)
            if axes:
                panel.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
        if not axes:
            panels[0].set_title("no axis moved", fontsize="small")
        if lanes:
            self._draw_lanes(panels[-1], lanes)
        panels[-1].set_xlabel("time (ms)")
        if title:
            figure.suptitle(title)
        figure.tight_layout()
        figure.savefig(path)
        pyplot.close(figure)

    def _axis_label(self, number: int) -> str:
        scale = self.scales[number]
        return f"axis {number}" if scale == 1 else f"axis {number} (SCALE {scale:g})"

    def units(self, axes: tuple[int, ...], *, per_second: bool) -> str:
        """Counts where SCALE is 1, the user units SCALE sets elsewhere; both named when the axes differ."""
        rate = "/s" if per_second else ""
        scaled = {self.scales[number] != 1 for number in axes}
        if scaled == {True, False}:
            return f"user units{rate}; counts{rate} at SCALE 1"
        return f"user units{rate}" if scaled == {True} else f"counts{rate}"

    def _draw_lanes(self, panel: MatplotlibAxes, lanes: list[tuple[str, int]]) -> None:
        """Each input or output bit that was ever on, as a step line in a lane of its own."""
        for lane, (name, bit) in enumerate(lanes):
            changes = self.io[name].points
            times = [time for time, _ in changes] + [self.last_time]
            levels = [lane + 0.8 * (value >> bit & 1) for _, value in changes]
            panel.step(times, [*levels, levels[-1]], where="post")
        panel.set_yticks([lane + 0.4 for lane in range(len(lanes))])
        panel.set_yticklabels([f"{name}{bit}" for name, bit in lanes])
        incomplete = [name for name, changes in self.io.items() if not changes.complete]
        label = "I/O" + (f" (first {IO_CHANGES} changes of {', '.join(incomplete)})" if incomplete else "")
        panel.set_ylabel(label)
        panel.grid(True, axis="x")


def _cell(value: float) -> str:
    return repr(value) if value != int(value) else str(int(value))


def _matplotlib() -> None:
    try:
        import matplotlib  # noqa: PLC0415 - optional dependency, loaded only when plotting
    except ImportError as missing:
        from mintlang.extras import this_installation  # noqa: PLC0415 - reads the distribution's metadata: only here

        raise PlotUnavailable(f"plotting needs matplotlib: {this_installation('plot')}") from missing
    matplotlib.use("Agg")


def image_types() -> frozenset[str]:
    """The file extensions ``plot`` can write (it picks the format by the extension)."""
    _matplotlib()
    from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: PLC0415

    return frozenset(FigureCanvasAgg.get_supported_filetypes())
