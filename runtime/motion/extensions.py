"""The motion keywords beyond lines and jogs (homing, circles, following, cams, feedrates), each in its own module.

Each entry registers its keywords on the table and drives the axes through
``Motion``; the simulator calls every entry once when it builds a controller.
"""

from __future__ import annotations

from collections.abc import Callable

from mintlang.runtime.keywords import KeywordTable
from mintlang.runtime.motion import (
    cams,
    circles,
    contouring,
    feedrate,
    flying,
    following,
    homing,
    idle_masters,
    incremental,
    master,
    offset,
)
from mintlang.runtime.motion.commands import Motion

Extension = Callable[[KeywordTable, Motion], None]

EXTENSIONS: tuple[Extension, ...] = (
    homing.register,
    circles.register,
    incremental.register,
    offset.register,
    contouring.register,
    feedrate.register,
    master.register,
    following.register,
    flying.register,
    cams.register,
    idle_masters.register,
)
