"""The machine ``mint-run`` simulates for each controller: the checker's profile, as fitted.

A NextMove PCI takes up to two expansion cards, with inputs 20 to 59 and
outputs 12 to 35, reached through BANK (000:4077-4078, 4126-4127, 4136-4155).
``mint check`` accepts their channels, since it cannot know what is fitted; a
simulation has to be one machine, and it is the main card alone, the one the
keyword tables describe: IMASK and INPUTACTIVELEVEL default to its 20 inputs
(1048575, 000:11896, 12281) and OUT takes 0 to 4095, its 12 outputs (000:14908-14913).
The controllers of the Mint v3 guide have ids of their own (``dialects/v3/controllers.py``).
"""

from __future__ import annotations

from dataclasses import replace

from mintlang.controllers import ChannelRange, ControllerProfile, profile
from mintlang.dialect import Dialect
from mintlang.keyworddb.model import Controller
from mintlang.runtime.dialects.v3.controllers import DEFAULT as V3_DEFAULT
from mintlang.runtime.dialects.v3.controllers import PROFILES as V3_PROFILES

_MAIN_CARD = {Controller.NEXTMOVE_PCI: {"digital_inputs": ChannelRange(0, 19), "digital_outputs": ChannelRange(0, 11)}}


def on_expansion_cards(controller: Controller, kind: str) -> ChannelRange | None:
    """The channels of ``kind`` (``digital_inputs``, ``digital_outputs``) that only expansion cards have, those
    the checker accepts beyond the main card: a program using one is told why the simulation refuses it."""
    main = _MAIN_CARD.get(controller, {}).get(kind)
    return None if main is None else ChannelRange(main.high + 1, getattr(profile(controller), kind).high)


def simulated(controller: Controller | str) -> ControllerProfile:
    """The profile of the v4 controller ``mint-run`` simulates."""
    checked = profile(controller)
    return replace(checked, **_MAIN_CARD.get(checked.controller, {}))


def machine(controller: Controller | str | None, dialect: Dialect | str = Dialect.V4) -> ControllerProfile:
    """The controller simulated for a program in ``dialect`` (by default the NextMove PCI for v4, the EuroServo
    for v3); one of the other generation's guide is a ``ValueError`` naming those that fit."""
    if Dialect(dialect) is Dialect.V3:
        name = str(controller or V3_DEFAULT)
        if name not in V3_PROFILES:
            raise ValueError(f"{name} is not a controller of the Mint v3 guide: use one of {', '.join(V3_PROFILES)}")
        return V3_PROFILES[name]
    if controller in V3_PROFILES:
        raise ValueError(f"{controller} is a controller of the Mint v3 guide: run its programs with dialect v3")
    return simulated(controller or Controller.NEXTMOVE_PCI)
