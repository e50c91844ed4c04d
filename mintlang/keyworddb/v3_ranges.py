"""The ranges Mint v3's attributes tables print (001 chapter 10), where v4 bounds a keyword more widely or not at all.

The v3 keyword database holds each keyword's access and what became of it in v4, not its range, so
the rows live here, in the core, where ``mint check --dialect v3`` and ``mint-run --dialect v3`` both
read them: a constant written outside is "Out of range" on the v3 controller (001:13136-13138), v4's
error 3, in the checker and in the run alike. A scaled row's range is given at SCALE 1 and holds for
the value in counts, the value times the scale factor (001:13138; SCALE is 1 to 32000, 001:11592).
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType

from mintlang.records import record


@record
class V3Range:
    """One keyword's printed range; ``scaled`` when it holds for the value times the axis's scale factor."""

    lowest: float
    highest: float
    scaled: bool = False


SETTINGS: Mapping[str, V3Range] = MappingProxyType(
    {
        "BAUD": V3Range(300.0, 19200.0),  # 001:6103
        "ECHO": V3Range(0.0, 3.0),  # 001:7504
        "IMASK": V3Range(0.0, 255.0),  # 001:8884: #IN0..#IN7, one bit each
        "IPEND": V3Range(0.0, 255.0),  # 001:9301
        "TERM": V3Range(1.0, 7.0),  # 001:12000
        "WAIT": V3Range(2.0, 65535.0),  # 001:12540
    }
)
"""The controller-wide keywords."""

AXIS_PARAMETERS: Mapping[str, V3Range] = MappingProxyType(
    {
        "ACCEL": V3Range(1000.0, 8_388_607.0, scaled=True),  # 001:5635
        "ACCELTIME": V3Range(2.0, 32_000.0),  # 001:5690
        "BACKOFF": V3Range(1.0, 100.0),  # 001:6047
        "CURRLIMIT": V3Range(1.0, 100.0),  # 001:7059
        "DECEL": V3Range(1000.0, 8_388_607.0, scaled=True),  # 001:7178
        "GAIN": V3Range(0.0, 255.0),  # 001:8302
        "HMSPEED": V3Range(2.0, 5_300_000.0, scaled=True),  # 001:8618, a servo's
        "IDLE": V3Range(0.0, 16_000.0, scaled=True),  # 001:8725
        "JOG": V3Range(-5_300_000.0, 5_300_000.0, scaled=True),  # 001:9326
        "KINT": V3Range(0.0, 255.0),  # 001:9471
        "KINTRANGE": V3Range(0.0, 255.0),  # 001:9516
        "KVEL": V3Range(0.0, 255.0),  # 001:9553
        "KVELFF": V3Range(0.0, 255.0),  # 001:9584
        "MFOLERR": V3Range(0.0, 32_767.0, scaled=True),  # 001:9975
        "SPEED": V3Range(0.0, 5_300_000.0, scaled=True),  # 001:11785
        "TORQUE": V3Range(-100.0, 100.0),  # 001:12109
    }
)
"""The axis parameters, by their v3 names."""
