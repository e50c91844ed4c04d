"""Settings the simulator accepts and remembers but that change nothing it models.

They configure hardware the simulation has no counterpart for: terminal
channels and echo (the simulator has one merged terminal), keypads, DAC output modes,
gearing compensation (the ideal plant has no lag to compensate, spec FG-7) and the
network a remote comms access goes over (COMMSMODE, 000:2376-2379: remote access is
not simulated; the controller's own comms array is the same in either mode).
A program that sets them runs on; reading one back gives what was written. The
report lists the ones a run used, so nobody mistakes them for simulated. Of
``ECHO`` only bit 1 is read, by the controller's error messages (``shows_errors``):
its other bits are the command line's, which a run has not.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Mapping

from mintlang.runtime.errors import MintError
from mintlang.runtime.keywords import KeywordTable, per_channel
from mintlang.runtime.ranges import ranged
from mintlang.terminals import SERIAL_PORT_KEYWORDS, serial_port_error

INERT_SETTINGS: dict[str, float] = {
    "TERMINAL": 123.0,
    "ECHO": 7.0,
    "PROTECT": 0.0,
    "KEYPADNODE": 0.0,
    "DACMODE": 0.0,
    "GEARING": 0.0,
    "GEARINGMODE": 0.0,
    "COMMSMODE": 0.0,  # CANopen (000:8360, 8367)
}
_ECHO_ERROR_MESSAGES = 0b10


class InertSettings:
    def __init__(self, settings: Mapping[str, float] = INERT_SETTINGS) -> None:
        """``settings``: each setting's name and value at power-up."""
        self.settings = settings
        self.values: dict[tuple[str, int | None], float] = {}
        self.used: set[str] = set()

    def register(self, table: KeywordTable, *, write_only: Collection[str] = ()) -> None:
        """Each setting, range-checked as its attributes table says (``ECHO`` 0 to 7): inert is not lax.
        One in ``write_only`` gets no reader, so reading it is the dialect's "Write only" error."""
        for name, default in self.settings.items():
            write = ranged(name, table.controller, self.writer(name))
            read = None if name in write_only else self._reader(name, default)
            table.register(name, read=read, write=per_channel(write))

    def shows_errors(self) -> bool:
        """Whether ECHO's bit 1, set at power-up (7, 000:9539), has the controller show its error messages on
        the terminal (000:9549): ``ECHO = 0`` leaves only what the program prints (000:9560-9562)."""
        return bool(int(self.values.get(("ECHO", None), self.settings["ECHO"])) & _ECHO_ERROR_MESSAGES)

    def _reader(self, name: str, default: float) -> Callable[[int | None], float]:
        def read(channel: int | None) -> float:
            return self.values.get((name, channel), default)

        return read

    def writer(self, name: str) -> Callable[[int | None, float], None]:
        """Remember what is written to ``name``, and that the run used it."""

        def write(channel: int | None, value: float) -> None:
            found = serial_port_error(name, channel) if name in SERIAL_PORT_KEYWORDS and channel is not None else None
            if found is not None:
                raise MintError(found[0], detail=found[1])
            self.used.add(name)
            self.values[(name, channel)] = value

        return write
