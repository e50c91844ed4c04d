"""The global error output (``GLOBALERROROUTPUT``): a safety output the controller drops on any axis error.

An asynchronous error on any axis deactivates it at once, before the error's default action has run,
and the program must activate it again itself (000:10987-10991). By default it is the relay
(000:11014). When it is also a drive's enable output, that drive is disabled whatever the error's
mode (000:10992-10994).
"""

from __future__ import annotations

from mintlang.keyworddb import database
from mintlang.runtime.drive_enable import NO_OUTPUT, check_output
from mintlang.runtime.io import RELAY0, DigitalIO
from mintlang.runtime.keywords import KeywordTable, per_channel
from mintlang.runtime.motion.commands import Motion


class GlobalErrorOutput:
    def __init__(self, motion: Motion, io: DigitalIO) -> None:
        self.motion = motion
        self.io = io
        self.output = RELAY0

    def trip(self) -> None:
        """An axis error latched: the output inactive, and every drive it enables disabled."""
        if self.output == NO_OUTPUT:
            return
        self.io.drive_enable(self.output, False)
        for axis in self.motion.axes:
            if axis.enabled and int(axis.parameters["DRIVEENABLEOUTPUT"]) == self.output:
                self.motion.crash_group(axis)
                axis.disable()

    def write(self, _: int | None, value: float) -> None:
        check_output("GLOBALERROROUTPUT", value, self.io)
        self.output = int(value)


def install(table: KeywordTable, motion: Motion, io: DigitalIO) -> None:
    """On the controllers that have one (NextMove), every axis error drops the global error output."""
    if not database().keywords["GLOBALERROROUTPUT"].available_on(table.controller):
        return
    output = GlobalErrorOutput(motion, io)
    for axis in motion.axes:
        axis.error_signal = output.trip
    table.register("GLOBALERROROUTPUT", read=lambda _: float(output.output), write=per_channel(output.write))
