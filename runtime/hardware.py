"""The machine ``mint-run`` simulates for each controller: the checker's profile.

A NextMove PCI is simulated with its two expansion cards, inputs 20 to 59 and
outputs 12 to 35 (000:4077-4078, 4126-4127): ``mint check`` accepts their
channels, since it cannot know what is fitted, and a program it passes runs.
BANK chooses the card the whole-card forms of the I/O keywords address
(``io_banks.py``), so a program written for the main card alone runs as on a
controller without cards. The controllers of the Mint v3 guide have ids of their
own (``dialects/v3/controllers.py``).
"""

from __future__ import annotations

from mintlang.controllers import ControllerProfile, profile
from mintlang.dialect import Dialect
from mintlang.keyworddb.model import Controller
from mintlang.runtime.dialects.v3.controllers import DEFAULT as V3_DEFAULT
from mintlang.runtime.dialects.v3.controllers import PROFILES as V3_PROFILES

CONTROLLERS = (*(member.value for member in Controller), *V3_PROFILES)
"""Every ``--controller`` the simulator takes: the v4 guide's (for v4 and MintMT), then the v3 guide's."""


def machine(controller: Controller | str | None, dialect: Dialect | str = Dialect.V4) -> ControllerProfile:
    """The controller simulated for a program in ``dialect`` (by default the NextMove PCI for v4, the EuroServo
    for v3); one of the other generation's guide, or of none, is a ``ValueError`` naming those that fit."""
    if Dialect(dialect) is Dialect.V3:
        name = str(controller or V3_DEFAULT)
        if name not in V3_PROFILES:
            raise ValueError(f"{name} is not a controller of the Mint v3 guide: use one of {', '.join(V3_PROFILES)}")
        return V3_PROFILES[name]
    if controller in V3_PROFILES:
        raise ValueError(f"{controller} is a controller of the Mint v3 guide: run its programs with dialect v3")
    try:
        return profile(controller or Controller.NEXTMOVE_PCI)
    except ValueError:  # the enum's own message names neither the guide nor the controllers there are
        names = ", ".join(member.value for member in Controller)
        raise ValueError(f"{controller} is not a controller of the Mint v4 guide: use one of {names}") from None
