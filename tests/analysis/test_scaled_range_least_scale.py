"""A scaled keyword's constant against its range where every scale factor has a printed minimum.

The range of a scaled keyword holds for the value times the axis's scale factor (000:5648-5649). On a
NextMove a scale factor can be any positive number, so only the sign of a value is checked. On MintDrive
every scale factor is at least 1: SCALE (000:15784), ENCODERSCALE (000:9728) and AUXENCODERSCALE
(000:6761) all print 1 ≤ x ≤ 65535. A value beyond the far end of the range there stays beyond it whatever
the scale, so ``mint-run`` stops on it with error 3 and ``mint check`` reports it.
"""

from __future__ import annotations

import pytest

from tests.analysis.checking import ERROR, found

OUT_OF_RANGE = [("E0003", ERROR, 1)]


@pytest.mark.parametrize(
    ("source", "controller", "expected"),
    [
        # MintDrive SPEED: 0 ≤ x ≤ 8000000 at LOOPTIME 500, less at 1000 and 2000 (000:16179-16185)
        pytest.param("SPEED.0 = 8000001\n", "mintdrive", OUT_OF_RANGE, id="speed-above-every-looptime"),
        pytest.param("SPEED.0 = 8000000\n", "mintdrive", [], id="speed-at-the-top"),
        # MintDrive JOG: -8000000 ≤ x ≤ 8000000 at LOOPTIME 500 (000:12661-12667)
        pytest.param("JOG.0 = -8000001\n", "mintdrive", OUT_OF_RANGE, id="jog-below-every-looptime"),
        pytest.param("JOG.0 = -8000000\n", "mintdrive", [], id="jog-at-the-bottom"),
        # MintDrive FOLERRORFATAL: 0 ≤ x ≤ 32767 (000:10668)
        pytest.param("FOLERRORFATAL.0 = 32768\n", "mintdrive", OUT_OF_RANGE, id="folerrorfatal-above"),
        pytest.param("FOLERRORFATAL.0 = 32767\n", "mintdrive", [], id="folerrorfatal-at-the-top"),
        # MintDrive MASTERDISTANCE: 1 ≤ x ≤ 65535 (000:13857)
        pytest.param("MASTERDISTANCE.0 = 65536\n", "mintdrive", OUT_OF_RANGE, id="masterdistance-above"),
        # ACCEL's minimum is 977 at LOOPTIME 2000 (000:6169-6175): a scale of 2 takes 976 into the range
        pytest.param("ACCEL.0 = 976\n", "mintdrive", [], id="below-a-positive-minimum-a-scale-can-lift"),
        # NextMove's scale factor may be below 1 (SCALE 0 ≤ x ≤ 8388607.0, 000:15783): only the sign is known
        pytest.param("SPEED.0 = 8388608\n", "nextmove-pci", [], id="nextmove-scale-may-shrink-it"),
    ],
)
def test_a_value_beyond_the_range_at_the_least_scale_is_error_3(
    source: str, controller: str, expected: list[tuple[str, str, int]]
) -> None:
    assert found(source, controller=controller) == expected
