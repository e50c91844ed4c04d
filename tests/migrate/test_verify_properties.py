"""Properties of ``verify``: a migration that only renames and declares behaves as its original.

Generated v3 programs of statements whose meaning v4 keeps (assignments of whole
numbers, sums and differences, PRINT, OUT bits, relative moves with a wait) are
migrated and verified: each must be equivalent, whatever the order of the
statements. v3 computes in 256ths and v4 in binary32, which agree exactly on
whole numbers up to 2^23 (V3-2, NM-1), so nothing here may diverge.
"""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from mintlang.migrate import migrate
from mintlang.migrate.verification import Verdict, verify
from mintlang.runtime.scenario import DrivesEnabled, Scenario

DRIVES = Scenario(drives=(DrivesEnabled(),))
PROLOGUE = "SPEED = 20000 : ACCEL = 200000\n"  # v3's ACCEL also sets DECEL; the migration writes it

small = st.integers(min_value=-1000, max_value=1000)
names = st.sampled_from(["a", "b", "count"])
statements = st.one_of(
    st.builds("{} = {}".format, names, small),
    st.builds("{} = {} + {}".format, names, names, small),
    st.builds("{} = {} - {}".format, names, small, names),
    st.builds("PRINT {}".format, names),
    st.builds('PRINT "n=", {}, {}'.format, names, small),
    st.builds("OUT{} = {}".format, st.integers(0, 7), st.integers(0, 1)),
    st.builds("MOVER.0 = {} : GO.0 : PAUSE IDLE.0".format, small),
)


@settings(max_examples=25)  # each example is two simulated runs
@given(st.lists(statements, min_size=1, max_size=8))
def test_a_program_of_statements_v4_keeps_verifies_equivalent(lines: list[str]) -> None:
    # every name is assigned before anything reads it, as the v3 compiler requires (V3-13)
    program = PROLOGUE + "a = 0 : b = 0 : count = 0\n" + "\n".join(lines) + "\n"
    found = verify(migrate(program), scenario=DRIVES, until_ms=3000)
    assert found.verdict is Verdict.EQUIVALENT, (found.divergence, found.short)
