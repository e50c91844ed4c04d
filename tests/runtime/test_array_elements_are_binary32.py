"""An array's initial values are held as any Mint v4 number is, binary32 (000:714-716, NM-6).

``DIM a(1) = 0.1`` then ``a(1) = 0.1`` compares the element with the literal, both 0.1 rounded
to binary32 (0.100000001490116...), so the test holds as it does for a scalar; an element kept as
the written double would differ from every literal 0.1 the program compares it with.
"""

from __future__ import annotations

from tests.runtime.running import simulate


def test_an_initial_value_equals_the_same_literal_as_a_scalar_does() -> None:
    program = 'DIM a(1) = 0.1\nDIM b = 0.1\nIF a(1) = 0.1 THEN PRINT "array"\nIF b = 0.1 THEN PRINT "scalar"\n'
    assert simulate(program).terminal == "array\nscalar\n"


def test_an_initial_value_and_an_assigned_one_are_the_same_number() -> None:
    program = 'DIM a(2) = 0.7\na(2) = 0.7\nIF a(1) = a(2) THEN PRINT "same"\n'
    assert simulate(program).terminal == "same\n"
