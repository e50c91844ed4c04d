"""An undeclared name CAMTABLE takes as an array gets no ``DIM name`` fix.

CAMTABLE is written ``CAMTABLE ( axis, position array, {master increment array} )``
(000:7907) and reads the cam's segments from ordinary user arrays (000:7932-7934), which DIM
declares with their number of elements (``DIM array_name(<no_of_elements>)``, 000:9167);
a DIM without one declares a variable (000:9169). So the fix that declares an undeclared
name by a bare ``DIM name`` would leave a variable where CAMTABLE wants an array, and the
size is the author's to choose: the error stays, with no fix. A name used elsewhere too is
declared as before.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.placed import placed


@pytest.mark.parametrize(
    ("source", "name"),
    [
        pytest.param("CAMTABLE(0, slave, NULL)\n", "slave", id="position-array"),
        pytest.param("DIM slave(3) = 2, 10, 20\nCAMTABLE ( 0, slave, increments )\n", "increments", id="master-array"),
    ],
)
def test_an_array_camtable_takes_is_not_declared_by_a_bare_dim(source: str, name: str) -> None:
    assert placed(source, "code", "text", "fixes") == [("E3001", name, 0)]


def test_a_name_given_elsewhere_is_still_declared() -> None:
    source = "DIM slave(3) = 2, 10, 20\nCAMTABLE(0, slave, NULL)\nMASTERDISTANCE = gap\n"
    [finding] = mintlang.check(source)
    [fix] = finding.fixes
    assert (finding.code, [edit.text for edit in fix.edits]) == ("E3001", ["DIM gap\n"])
