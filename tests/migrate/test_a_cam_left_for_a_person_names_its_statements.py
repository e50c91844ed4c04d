"""S-CAM: a cam left for a person because its master table is in counts gives the v4 statements to write.

v3 took a cam's master increments from minc<n> in quadrature counts (001:3880-3888) and started it at
once (001:3893-3897); v4 takes the master table in the master's user units and loads the cam with CAMTABLE
and CAM, which GO starts (000:7953, 000:3862-3873). Where SCALE is set the table must be converted by
hand, and the item says what to write once it is: the statement the rule would have written.
"""

from __future__ import annotations

import pytest

from tests.migrate.helpers import flagged

TABLES = "DIM cam0(4) = 3,1,2,3\nDIM minc0(3) = 10,10,10\nDIM cam1(3) = 2,5,5\nDIM minc1(2) = 20,20\n"


@pytest.mark.parametrize(
    ("cam", "table", "statement"),
    [
        ("CAM.0 = 0", "minc0", "CAMTABLE(0, cam0, minc0) : CAM.0 = 0 : GO.0"),
        ("cam.1 = 1", "minc1", "camtable(1, cam1, minc1) : cam.1 = _cmCONTINUOUS : go.1"),
    ],
)
def test_a_master_table_in_counts_is_left_with_the_statement_to_write(cam: str, table: str, statement: str) -> None:
    assert flagged("S-CAM", f"SCALE = 4;\n{TABLES}{cam}\n") == [
        f"{table} is in counts, a v4 master table in the master's user units: SCALE is set; "
        f"once {table} is in those units, write {statement}"
    ]
