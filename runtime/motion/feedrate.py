"""FEEDRATE, FEEDRATEMODE and FEEDRATEOVERRIDE: a slew speed kept with each move, on the NextMoves.

The v4 guide gives the model (000:16186-16230, 3300-3305; the keywords are
NextMove's, 000:17611-17613), MintMT's notes the same (004:250-280, MT-15):
SPEED and FEEDRATE are one slew speed written two ways. In speed mode
(``FEEDRATEMODE`` 0, at power-up) every move runs at the master's SPEED in
force, and a change reaches the move in progress; in feedrate mode (1,
MintMT's ``_frFEEDRATE``, MT-3) each MOVE, VECTOR or CIRCLE keeps the speed
in force when it was loaded. ``FEEDRATEOVERRIDE`` is a percentage of SPEED
for the moves that keep none. The other bits of ``FEEDRATEMODE``
(accelerations, jerks, fast traverse) are named by the MintMT note without
their values, and by the v4 guide not at all: they are not simulated.
"""

from __future__ import annotations

from mintlang.runtime.errors import NotSimulated
from mintlang.runtime.keywords import KeywordTable, per_channel
from mintlang.runtime.motion.commands import Motion
from mintlang.runtime.ranges import ranged

SPEED_MODE = 0
FEEDRATE_MODE = 1  # _frFEEDRATE (MT-3)


def register(table: KeywordTable, motion: Motion) -> None:
    speed = table.get("SPEED")
    assert speed is not None and speed.read is not None and speed.write is not None, "the motion registers SPEED"
    table.register("FEEDRATE", read=speed.read, write=speed.write)

    def read_mode(channel: int | None) -> float:
        return float(FEEDRATE_MODE if motion.axis(channel).store_feedrate else SPEED_MODE)

    def write_mode(channel: int | None, value: float) -> None:
        axis = motion.axis(channel)
        if value not in (SPEED_MODE, FEEDRATE_MODE):
            raise NotSimulated("FEEDRATEMODE", "bits but _frFEEDRATE, whose values the guides do not give")
        axis.store_feedrate = value == FEEDRATE_MODE

    def read_override(channel: int | None) -> float:
        return motion.axis(channel).speed_override * 100.0

    def write_override(channel: int | None, value: float) -> None:
        axis = motion.axis(channel)
        axis.speed_override = value / 100.0
        motion.rates_changed(axis)

    # a set of bits: a whole number, 0 or more, as its row says (004:278)
    mode = ranged("FEEDRATEMODE", table.controller, write_mode, table.dialect, channel=motion.axis_number)
    table.register("FEEDRATEMODE", read=read_mode, write=per_channel(mode))
    # MT-15: above 0
    override = ranged("FEEDRATEOVERRIDE", table.controller, write_override, table.dialect, channel=motion.axis_number)
    table.register("FEEDRATEOVERRIDE", read=read_override, write=per_channel(override))
