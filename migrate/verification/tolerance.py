"""How close the v4 run must stay to the v3 run to count as the same behaviour, and why.

Both runs are the same simulator (1 ms servo tick, 2 ms profiler, the same
plants and servo law), so most of a correct migration compares exactly. What
is allowed for is what differs by design:

* **Time, 2 ms.** A slice runs 20 statements a tick (runtime/BEHAVIOUR.md,
  "Slices"), and the migrator inserts statements (``DIM``, ``DECEL`` after
  ``ACCEL``, ``AXES``), so a statement can run a tick later in v4 and the move
  it starts one 2 ms profiler tick later. Every sample is compared with the
  other run's samples up to 2 ms either side (a tube, as signal comparisons of
  simulation results do), and a printed character or a stop may come up to
  2 ms apart. Anything later is a timing difference (X-GO-TIMING when the
  migrator flagged it).
* **Position, 1 count + SCALE/256 counts.** v3 numbers are 24.8 fixed point:
  a written position or a computed one is off by up to a 256th of a user unit
  (V3-2, X-NUM), which is SCALE/256 counts; the encoder reads whole counts.
* **Velocity, 1% + 1000 counts/s.** ``VEL`` is measured from whole encoder
  counts over a 2 ms sample (AX-4), so it moves in steps of 500 counts/s, and
  two runs a count apart at each end of the sample read up to 1000 apart; 1%
  covers rates v3 held in 256ths.
* **Printed numbers, 0.001 + 2/256 + 2^-23 of the value.** v3 prints three
  decimals cut, v4 four (V3-4, PR-1, X-PRINT); v3 rounds a written number to
  the nearest 256th and cuts a product or quotient to one (V3-2); v4 numbers are
  binary32, 24 significant bits (NM-1). Text around the numbers must be equal.
  A run of digits beyond the largest v3 number, 8388607.996 (v3:1157), is no one
  number but several printed side by side (``PRINT a, b``, v3:10980): its digits
  must be equal.
* **The horizon.** Runs cut off at ``--until-ms`` have no samples after it, so
  their last 2 ms have only half a tube: they are not held against the other
  run, and what one run printed in them may still be missing from the other.
  A run that ended by the horizon holds its last state and prints nothing more.
"""

from __future__ import annotations

TIME_MS = 2
COUNTS = 1.0
STEPS = 256  # v3 fraction resolution (V3-2)
VELOCITY_SHARE = 0.01
VELOCITY_COUNTS = 1000.0  # a count at each end of VEL's 2 ms sample
PRINTED_DECIMALS = 0.001
PRINTED_STEPS = 2 / STEPS
PRINTED_SHARE = 2.0**-23
V3_LARGEST = 8388607.996  # v3:1157


def position(scale: float) -> float:
    """The largest POS difference (user units) of an axis of ``scale`` counts per unit."""
    return (COUNTS + scale / STEPS) / scale


def velocity(v3: float, v4: float, scale: float) -> float:
    """The largest VEL difference (user units/s) between these two readings."""
    return VELOCITY_SHARE * max(abs(v3), abs(v4)) + VELOCITY_COUNTS / scale


def printed(v3: float, v4: float) -> float:
    """The largest difference between two printed numbers (none for numbers printed side by side)."""
    largest = max(abs(v3), abs(v4))
    if largest > V3_LARGEST:
        return 0.0
    return PRINTED_DECIMALS + PRINTED_STEPS + PRINTED_SHARE * largest
