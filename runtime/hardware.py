"""The machine ``mint-run`` simulates for each controller: the checker's profile, as fitted.

A NextMove PCI takes up to two expansion cards, with inputs 20 to 59 and
outputs 12 to 35, reached through BANK (000:4077-4078, 4126-4127, 4136-4155).
``mint check`` accepts their channels, since it cannot know what is fitted; a
simulation has to be one machine, and it is the main card alone, the one the
keyword tables describe: IMASK and INPUTACTIVELEVEL default to its 20 inputs
(1048575, 000:11896, 12281) and OUT takes 0 to 4095, its 12 outputs (000:14908-14913).
"""

from __future__ import annotations

from dataclasses import replace

from mintlang.controllers import ChannelRange, ControllerProfile, profile
from mintlang.keyworddb.model import Controller

_MAIN_CARD = {Controller.NEXTMOVE_PCI: {"digital_inputs": ChannelRange(0, 19), "digital_outputs": ChannelRange(0, 11)}}


def simulated(controller: Controller | str) -> ControllerProfile:
    """The profile of the controller ``mint-run`` simulates."""
    checked = profile(controller)
    return replace(checked, **_MAIN_CARD.get(checked.controller, {}))
