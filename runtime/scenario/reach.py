"""Stimulus checked against the controller's profile.

A channel or axis the controller lacks would make its stimulus vanish without
a word (an input bit nobody samples) or crash the run (an encoder that is not
there), so both front ends refuse it at the line that wrote it.
"""

from __future__ import annotations

from collections.abc import Container

from mintlang.controllers import ControllerProfile
from mintlang.runtime.scenario.expectations import Expectation
from mintlang.runtime.scenario.problems import Invalid
from mintlang.runtime.scenario.stimulus import (
    AdcLevel,
    FastInput,
    IndexPulse,
    InputLevel,
    PlantChoice,
    PositionInput,
    WorldRecord,
)


def _has(  # noqa: PLR0917 - the message names each
    controller: ControllerProfile, what: str, number: int, numbers: Container[int], listed: str, key: str
) -> None:
    if number not in numbers:
        raise Invalid(f"the {controller.title} has no {what} {number} (it has {listed})", key=key)


def check_reach(record: WorldRecord | Expectation, controller: ControllerProfile) -> None:
    """Raise ``Invalid`` when ``record`` drives an axis or channel ``controller`` does not have."""
    axes, inputs, adc, fast = controller.axes, controller.digital_inputs, controller.adc, controller.fast_inputs
    match record:
        case PlantChoice(axis=axis) | IndexPulse(axis=axis):
            _has(controller, "axis", axis, axes, f"axes {axes}", "axis")
        case InputLevel(channel=channel):
            _has(controller, "input", channel, inputs, f"inputs {inputs}", "channel")
        case PositionInput(channel=channel, axis=axis):
            _has(controller, "input", channel, inputs, f"inputs {inputs}", "channel")
            _has(controller, "axis", axis, axes, f"axes {axes}", "when")
        case FastInput(channel=channel):
            fast_listed = f"fast inputs {', '.join(map(str, sorted(fast)))}"
            _has(controller, "fast input", channel, fast, fast_listed, "channel")
        case AdcLevel(channel=channel):
            _has(controller, "ADC channel", channel, adc, f"ADC channels {adc}", "channel")
