"""The controllers of the Mint v3 guide that ``mint-run --dialect v3`` simulates, and their axis and I/O counts.

The v3 guide covers EuroSystem (ES/D: 2 servo or 3 stepper axes), EuroStep
(ES/S: 3 stepper), EuroServo (ES/M3: 3 servo), SmartSystem/1-3 (SMS), SmartMove/1-3
(SMM, "functionally equivalent to SmartSystem/3" where the tables omit it) and
SmartStep (SST/3), EuroSystem/STE and EuroStep/STE (001:175-191). Stepper axes
are not simulated, so the servo controllers are offered: at most 3 axes
(001:550), 8 digital inputs and 8 outputs (001:4284), one fast interrupt input
(001:2585-2627) and two analog inputs, three on a 3 axis servo controller
(001:4364, 001:5770).

Each is simulated on the machine of the v4 runtime (its servo tick, profiler and
plants) with that machine's keyword ranges, cut down to these counts, with the
v3 guide's nesting limits (001:2381-2389, 001:12946-12955: FOR 8, the figure three
tables give, not the 10 of the FOR entry, 001:8246).

The dedicated inputs (a home and a limit input per axis, one stop and one error
input: 001:3470-3595, 4542-4612, 7841-7876) have no numbers of their own in v3;
the simulation gives them the channels after the 8 user inputs, so a scenario can
drive them like any input (V3-8): home inputs 8 to 10, limit inputs 11 to 13, the
stop input 14, the error input 15. A switch reads active when open (high), as v3's
home and limit switches are closed in normal running (001:3470, 3595).
"""

from __future__ import annotations

from dataclasses import replace
from types import MappingProxyType

from mintlang.controllers import V3_NESTING, ChannelRange, ControllerProfile, profile
from mintlang.keyworddb.model import Controller

BASE_MACHINE = Controller.NEXTMOVE_PCI  # the v4 machine whose keyword ranges and timing a v3 controller runs on
DEFAULT = "euroservo"
USER_INPUTS = 8
HOME_INPUT, LIMIT_INPUT, STOP_INPUT, ERROR_INPUT = 8, 11, 14, 15  # the dedicated inputs' channels (axis 0's)


def _servo_controller(title: str, axes: int) -> ControllerProfile:
    analog_inputs = 3 if axes == 3 else 2
    return replace(
        profile(BASE_MACHINE),
        title=title,
        axes=ChannelRange(0, axes - 1),
        digital_inputs=ChannelRange(0, ERROR_INPUT),
        digital_outputs=ChannelRange(0, 7),
        adc=ChannelRange(0, analog_inputs - 1),
        dac=ChannelRange(0, axes - 1),
        encoders=ChannelRange(0, axes - 1),
        auxiliary_encoders=ChannelRange(0, -1),
        fast_inputs=frozenset({0}),
        max_variables=50,
        max_labels=40,
        nesting=V3_NESTING,
    )


PROFILES = MappingProxyType(
    {
        "euroservo": _servo_controller("EuroServo (ES/M3)", 3),
        "eurosystem": _servo_controller("EuroSystem (ES/D)", 2),
        "smartsystem-1": _servo_controller("SmartSystem/1", 1),
        "smartsystem-2": _servo_controller("SmartSystem/2", 2),
        "smartsystem-3": _servo_controller("SmartSystem/3", 3),
        "smartmove-1": _servo_controller("SmartMove/1", 1),
        "smartmove-2": _servo_controller("SmartMove/2", 2),
        "smartmove-3": _servo_controller("SmartMove/3", 3),
    }
)
"""The v3 controllers by ``--controller`` id."""
