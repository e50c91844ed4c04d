"""``OUTX(channel)``, one digital output (004:148), is checked against the controller's outputs as v4's
``OUT.channel`` is, and so is the channel of an output move: a channel it lacks is error 8 (000:18536), in
``mint check`` as in ``mint-run``."""

from __future__ import annotations

import mintlang


def _findings(source: str, controller: str = "nextmove-pci") -> list[tuple[str, str, int]]:
    analysis = mintlang.check_application(source, dialect="mintmt", controller=controller)
    return [(d.code, d.message, d.span.start) for d in analysis.program]


def test_the_last_output_of_the_second_expansion_card_is_fine() -> None:
    """A NextMove PCI's outputs are 0 to 11 and the two expansion cards' 12 to 35 (runtime/BEHAVIOUR.md, IO-8)."""
    assert _findings("OUTX(35) = _ON\nPrint OUTX(0)\n") == []


def test_an_output_the_controller_lacks_is_error_8_written_or_read() -> None:
    detail = "Digital output specified out of range: OUTX channel 36 does not exist on NextMove PCI (channels 0 to 35)"
    assert _findings("OUTX(36) = 1\nPrint OUTX(36)\n") == [("E0008", detail, 5), ("E0008", detail, 24)]


def test_outputs_are_the_controllers_own() -> None:
    ((code, message, _),) = _findings("OUTX(9) = 1\n", "mintdrive")
    assert (code, message) == (
        "E0008",
        "Digital output specified out of range: OUTX channel 9 does not exist on MintDrive (channels 0 to 8)",
    )


def test_an_output_move_on_an_output_the_controller_lacks_is_error_8() -> None:
    """MOVEOUTX and MOVEPULSEOUTX name an output channel after the axis (004:297-299, MT-22)."""
    source = "MOVEOUTX(0,35) = 0\nMOVEOUTX(0,36) = 1\nMOVEPULSEOUTX(0, 40) = 100\n"
    assert _findings(source) == [
        (
            "E0008",
            "Digital output specified out of range: MOVEOUTX channel 36 does not exist on NextMove PCI "
            "(channels 0 to 35)",
            30,
        ),
        (
            "E0008",
            "Digital output specified out of range: MOVEPULSEOUTX channel 40 does not exist on NextMove PCI "
            "(channels 0 to 35)",
            55,
        ),
    ]
