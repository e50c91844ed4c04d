"""The ranges Mint v3's attributes tables print (001 chapter 10), where v4 bounds a keyword more widely or not at all.

The v3 keyword database holds each keyword's access and what became of it in v4, not its range, so
the rows live here, in the core, where ``mint check --dialect v3`` and ``mint-run --dialect v3`` both
read them: a constant written outside is "Out of range" on the v3 controller (001:13136-13138), v4's
error 3, in the checker and in the run alike. A scaled row's range is given at SCALE 1 and holds for
the value in counts, the value times the scale factor (001:13138; SCALE is 1 to 32000, 001:11592).
A row marked ``whole`` picks a setting or a bit pattern, which a fraction does not name: printed without
".0", it takes none (001:169), as v4 refuses a fraction for a mode keyword.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from types import MappingProxyType

from mintlang.records import record


@record
class V3Range:
    """One keyword's printed range; ``scaled`` when it holds for the value times the axis's scale factor."""

    lowest: float
    highest: float
    scaled: bool = False
    whole: bool = False  # a fraction is out of range
    rounded_down: bool = False  # a fraction is rounded down before the range holds it (SCALE, 001:11610)

    def holds(self, value: float) -> bool:
        """Whether ``value`` (in counts, for a scaled row) is in the range."""
        value = math.floor(value) if self.rounded_down else value
        return self.lowest <= value <= self.highest and not (self.whole and not value.is_integer())


SETTINGS: Mapping[str, V3Range] = MappingProxyType(
    {
        "BAUD": V3Range(300.0, 19200.0),  # 001:6103
        "ECHO": V3Range(0.0, 3.0),  # 001:7504
        "ENABLE": V3Range(0.0, 1.0, whole=True),  # 001:7558: 0 or 1
        "ERRORIN": V3Range(0.0, 2.0, whole=True),  # 001:7852, the three settings of 001:7863-7866
        "IMASK": V3Range(0.0, 255.0),  # 001:8884: #IN0..#IN7, one bit each
        "IPEND": V3Range(0.0, 255.0),  # 001:9301
        "OUT": V3Range(0.0, 255.0),  # 001:10527, 001:4344-4345
        **{f"OUT{bit}": V3Range(0.0, 1.0, whole=True) for bit in range(8)},  # 001:10622, one output each
        "TERM": V3Range(1.0, 7.0),  # 001:12000
        "TIME": V3Range(0.0, 65535.0),  # CONFLICT: 2 in the table (001:12047), its example writes 0 (001:12060)
        "WAIT": V3Range(2.0, 65535.0),  # 001:12540
    }
)
"""The controller-wide keywords."""

AXIS_PARAMETERS: Mapping[str, V3Range] = MappingProxyType(
    {
        "ACCEL": V3Range(1000.0, 8_388_607.0, scaled=True),  # 001:5635
        "ACCELTIME": V3Range(2.0, 32_000.0),  # 001:5690
        "AXISCON": V3Range(0.0, 255.0, whole=True),  # 001:6015, a bit pattern
        "BACKOFF": V3Range(1.0, 100.0),  # 001:6047
        "CURRLIMIT": V3Range(1.0, 100.0),  # 001:7059
        "DECEL": V3Range(1000.0, 8_388_607.0, scaled=True),  # 001:7178
        "GAIN": V3Range(0.0, 255.0),  # 001:8302
        "HOME": V3Range(0.0, 6.0, whole=True),  # 001:8677, a homing sequence
        "HMSPEED": V3Range(2.0, 5_300_000.0, scaled=True),  # 001:8618, a servo's
        "IDLE": V3Range(0.0, 16_000.0, scaled=True),  # 001:8725
        "JOG": V3Range(-5_300_000.0, 5_300_000.0, scaled=True),  # 001:9326
        "KINT": V3Range(0.0, 255.0),  # 001:9471
        "KINTRANGE": V3Range(0.0, 255.0),  # 001:9516
        "KVEL": V3Range(0.0, 255.0),  # 001:9553
        "KVELFF": V3Range(0.0, 255.0),  # 001:9584
        "MFOLERR": V3Range(0.0, 32_767.0, scaled=True),  # 001:9975
        # CONFLICT: 65000 (001:960), 32000 (001:97), 3200 (001:11592, read as a dropped 0)
        "SCALE": V3Range(1.0, 32_000.0, rounded_down=True),
        "SPEED": V3Range(0.0, 5_300_000.0, scaled=True),  # 001:11785
        "STOPMODE": V3Range(1.0, 2.0, whole=True),  # 001:11908: 1 stops, 2 cancels (001:11917-11926)
        "TORQUE": V3Range(-100.0, 100.0),  # 001:12109
    }
)
"""The axis parameters, by their v3 names."""
