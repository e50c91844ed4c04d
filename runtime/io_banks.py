"""I/O banks: a NextMove PCI's main card and its two expansion cards, one bank each, chosen with BANK.

Each expansion card has the main card's 20 digital inputs, 12 digital outputs and a relay
(000:7340-7342, 9388-9389). Inputs and outputs are numbered on across the cards, so ``IN.21``
is input 1 of expansion card 1 (000:4077-4078, 4126-4127); the forms that read or write a whole
card at once (``IN``, ``OUT``, ``IMASK``, ``INPUTACTIVELEVEL``, ``RELAY`` …) address the bank BANK
selects, 0 by default (000:7316-7328, 7344-7365). So the values the keyword tables give for one
card hold for every bank: IMASK's default is 1048575, the card's 20 inputs (000:11896), and
``OUT`` takes 0 to 4095, its 12 outputs (000:14908-14913). Any other controller has one bank.
"""

from __future__ import annotations

from mintlang.controllers import IOBanks
from mintlang.runtime.errors import OUT_OF_RANGE, MintError
from mintlang.runtime.keywords import KeywordTable, per_channel


def with_bit(bits: int, number: int, on: bool) -> int:
    """``bits`` with bit ``number`` set when ``on``, cleared when not: one input, output or relay."""
    bit = 1 << number
    return bits | bit if on else bits & ~bit


class BankSelection:
    """BANK, the bank the whole-card forms of the I/O keywords address (000:7344-7375)."""

    def __init__(self, banks: IOBanks) -> None:
        self.banks = banks
        self.bank = 0  # the main card at power-up (000:7326-7327)

    def register(self, table: KeywordTable) -> None:
        table.register("BANK", read=lambda _: float(self.bank), write=per_channel(self._write))

    def _write(self, _: int | None, value: float) -> None:
        if value != int(value) or not 0 <= value < self.banks.count:
            raise MintError(OUT_OF_RANGE, detail=f"BANK takes 0 to {self.banks.count - 1}, one per card")
        self.bank = int(value)

    def inputs(self, bits: int) -> int:
        """The selected bank's inputs among ``bits``."""
        return self.banks.input_word(bits, self.bank)

    def with_inputs(self, bits: int, word: int) -> int:
        return self.banks.with_input_word(bits, self.bank, word)

    def outputs(self, bits: int) -> int:
        return self.banks.output_word(bits, self.bank)

    def with_outputs(self, bits: int, word: int) -> int:
        return self.banks.with_output_word(bits, self.bank, word)
