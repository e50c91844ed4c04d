"""What each controller supports: channel ranges, name-table and nesting limits.

Figures from the Mint v4 reference guide (MN1262): the "Dot Parameters" table
(section 10.2, line 5613), the digital I/O of sections 7.2 and 7.3, the memory
map of 9.1, the interpreter limitations of section 3.9 (lines
1904-1976), the #INx and #FASTINx entries (lines 5848-5950) and the 255
character line limit (line 255).
"""

from __future__ import annotations

from mintlang.dialect import Dialect
from mintlang.keyworddb.model import Controller
from mintlang.records import record


@record
class ChannelRange:
    """Inclusive range of valid numbers; ``None`` where the controller has none."""

    low: int
    high: int

    def __contains__(self, value: object) -> bool:
        return isinstance(value, int) and self.low <= value <= self.high

    def __str__(self) -> str:
        return str(self.low) if self.low == self.high else f"{self.low} to {self.high}"


@record
class NestingLimits:
    if_blocks: int
    for_loops: int
    gosub: int
    other_loops: int  # WHILE, LOOP and REPEAT combined
    loops_and_ifs: int  # the three loop kinds plus IF blocks


V3_NESTING = NestingLimits(if_blocks=30, for_loops=8, gosub=20, other_loops=30, loops_and_ifs=30)
"""Mint v3's: GOSUB 20, IF .. DO 30, FOR 8, LOOP/REPEAT/WHILE 10 each, 30 combined (001:2381-2409): the
per-kind 10 is not enforced (the v4 model counts WHILE, LOOP and REPEAT together), so other_loops holds
the combined 30."""


def nesting_of(controller: ControllerProfile, dialect: Dialect) -> NestingLimits:
    """The nesting limits a program in ``dialect`` is held to on ``controller``: a Mint v3 controller's own."""
    return V3_NESTING if dialect is Dialect.V3 else controller.nesting


@record
class ControllerProfile:
    controller: Controller
    title: str
    axes: ChannelRange
    digital_inputs: ChannelRange
    digital_outputs: ChannelRange
    adc: ChannelRange
    dac: ChannelRange | None
    auxiliary_dac: ChannelRange | None
    encoders: ChannelRange
    auxiliary_encoders: ChannelRange
    fast_inputs: frozenset[int]  # x of the #FASTINx handlers the controller calls
    max_variables: int
    max_labels: int
    max_macros: int
    nesting: NestingLimits
    user_memory: int  # bytes for the compiled code and the arrays (9.1)
    configuration_buffer: int  # bytes for the configuration file's source (9.1)
    max_line_length: int = 255
    # #FASTINx answers digital input x (NextMove PCI, MintDrive, ServoNode 51), not an input of its own (000:5868-5888)
    fast_inputs_are_digital_inputs: bool = False

    @property
    def axis_count(self) -> int:
        return self.axes.high + 1


_FULL_NESTING = NestingLimits(if_blocks=255, for_loops=50, gosub=100, other_loops=50, loops_and_ifs=255)
_PC_NESTING = NestingLimits(if_blocks=100, for_loops=20, gosub=50, other_loops=20, loops_and_ifs=255)

PROFILES: dict[Controller, ControllerProfile] = {
    Controller.NEXTMOVE_PCI: ControllerProfile(
        Controller.NEXTMOVE_PCI,
        "NextMove PCI",
        axes=ChannelRange(0, 11),
        # Two expansion cards add inputs 20-59 and outputs 12-35 (7.2, 7.3); the checker
        # cannot know what is fitted, so it accepts the largest configuration.
        digital_inputs=ChannelRange(0, 59),
        digital_outputs=ChannelRange(0, 35),
        adc=ChannelRange(0, 11),
        dac=ChannelRange(0, 11),
        auxiliary_dac=None,
        encoders=ChannelRange(0, 11),
        auxiliary_encoders=ChannelRange(0, 2),
        fast_inputs=frozenset({0, 1, 2, 3}),
        fast_inputs_are_digital_inputs=True,
        max_variables=255,
        max_labels=255,
        max_macros=255,
        nesting=_FULL_NESTING,
        user_memory=1024 * 1024,
        configuration_buffer=8 * 1024,
    ),
    Controller.NEXTMOVE_PC: ControllerProfile(
        Controller.NEXTMOVE_PC,
        "NextMove PC",
        axes=ChannelRange(0, 7),
        digital_inputs=ChannelRange(0, 23),
        digital_outputs=ChannelRange(0, 11),
        adc=ChannelRange(0, 7),
        dac=ChannelRange(0, 7),
        auxiliary_dac=None,
        encoders=ChannelRange(0, 7),
        auxiliary_encoders=ChannelRange(0, 0),
        fast_inputs=frozenset({0}),
        max_variables=100,
        max_labels=100,
        max_macros=100,
        nesting=_PC_NESTING,
        user_memory=100 * 1024,
        configuration_buffer=8 * 1024,
    ),
    Controller.NEXTMOVE_BX: ControllerProfile(
        Controller.NEXTMOVE_BX,
        "NextMove BX",
        axes=ChannelRange(0, 7),
        digital_inputs=ChannelRange(0, 15),
        digital_outputs=ChannelRange(0, 7),
        adc=ChannelRange(0, 7),
        dac=ChannelRange(0, 3),
        auxiliary_dac=None,
        encoders=ChannelRange(0, 3),
        auxiliary_encoders=ChannelRange(0, 0),
        fast_inputs=frozenset({0, 1, 2, 3}),
        max_variables=255,
        max_labels=255,
        max_macros=255,
        nesting=_FULL_NESTING,
        user_memory=248 * 1024,
        configuration_buffer=8 * 1024,
    ),
    Controller.MINTDRIVE: ControllerProfile(
        Controller.MINTDRIVE,
        "MintDrive",
        axes=ChannelRange(0, 0),
        digital_inputs=ChannelRange(0, 17),
        digital_outputs=ChannelRange(0, 8),
        adc=ChannelRange(0, 3),
        # The channel table prints N/A, but DAC is the drive's speed demand on MintDrive (8720-8793) and
        # footnote 7 (5666) says MintDrive does not tell axis keywords from channel keywords: axis 0.
        dac=ChannelRange(0, 0),
        auxiliary_dac=ChannelRange(0, 3),
        encoders=ChannelRange(0, 0),
        auxiliary_encoders=ChannelRange(0, 0),
        fast_inputs=frozenset({0, 2}),
        fast_inputs_are_digital_inputs=True,
        max_variables=255,
        max_labels=255,
        max_macros=255,
        nesting=_FULL_NESTING,
        user_memory=40 * 1024,
        configuration_buffer=4 * 1024,
    ),
    Controller.SERVONODE51: ControllerProfile(
        Controller.SERVONODE51,
        "ServoNode 51",
        axes=ChannelRange(0, 0),
        digital_inputs=ChannelRange(0, 5),
        digital_outputs=ChannelRange(0, 2),
        adc=ChannelRange(0, 0),
        dac=None,
        auxiliary_dac=ChannelRange(0, 1),
        encoders=ChannelRange(0, 0),
        auxiliary_encoders=ChannelRange(0, 0),
        fast_inputs=frozenset({0, 2}),
        fast_inputs_are_digital_inputs=True,
        max_variables=255,
        max_labels=255,
        max_macros=255,
        nesting=_FULL_NESTING,
        user_memory=40 * 1024,
        configuration_buffer=4 * 1024,
    ),
}


def profile(controller: Controller | str) -> ControllerProfile:
    """The profile of a controller given by enum or id (``"nextmove-bx"``)."""
    return PROFILES[Controller(controller)]


_CARD_IO = {Controller.NEXTMOVE_PCI: (20, 12)}  # inputs and outputs of one card (000:7340-7342)


@record
class IOBanks:
    """``count`` banks of ``inputs`` digital inputs, ``outputs`` digital outputs and one relay each."""

    count: int
    inputs: int
    outputs: int

    def input_word(self, bits: int, bank: int) -> int:
        """The inputs of ``bank`` among ``bits`` (one bit per input of the controller), as bits from 0."""
        return _word(bits, bank, self.inputs)

    def with_input_word(self, bits: int, bank: int, word: int) -> int:
        """``bits`` with the inputs of ``bank`` replaced by ``word``."""
        return _with_word(bits, bank, self.inputs, word)

    def output_word(self, bits: int, bank: int) -> int:
        return _word(bits, bank, self.outputs)

    def with_output_word(self, bits: int, bank: int, word: int) -> int:
        return _with_word(bits, bank, self.outputs, word)

    @property
    def output_words(self) -> int:
        """How many words a bank's outputs make, one bit an output: a card's word is below this (``OUT``'s
        0 ≤ x < 4096 on a NextMove PCI, 000:14908-14913), as is ``MOVEOUT``'s pattern (MT-22)."""
        return 1 << self.outputs


def io_banks(profile: ControllerProfile) -> IOBanks:
    """The banks of ``profile``'s controller: one a card where its I/O is whole cards' worth, else one; the
    simulator and ``mint check`` (MintMT's ``MOVEOUT``) read the same."""
    inputs, outputs = profile.digital_inputs.high + 1, profile.digital_outputs.high + 1
    card = _CARD_IO.get(profile.controller)
    if card is not None:  # not a Mint v3 controller simulated on this one's machine (dialects/v3/controllers.py)
        cards = inputs // card[0]
        if (cards * card[0], cards * card[1]) == (inputs, outputs):
            return IOBanks(cards, *card)
    return IOBanks(1, inputs, outputs)


def _word(bits: int, bank: int, width: int) -> int:
    return bits >> (bank * width) & ((1 << width) - 1)


def _with_word(bits: int, bank: int, width: int, word: int) -> int:
    shift = bank * width
    mask = ((1 << width) - 1) << shift
    return bits & ~mask | (word << shift) & mask
