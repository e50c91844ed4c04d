"""Arithmetic the controller cannot do: a division whose divisor is always zero, a power NextMove does not take."""

from __future__ import annotations

from mintlang.ruledocs.model import Example, FixSafety, Group, RuleDoc

GROUP = Group(
    "Arithmetic",
    "Expressions are worked out when the line runs, so the controller's arithmetic errors stop a "
    "program that compiled. Where a divisor is a number, or folds to one from numbers and constants, "
    "the checker knows the result before the program runs.",
    (
        RuleDoc(
            2021,
            catches="A `/` or a `MOD` (`%`) whose divisor is zero whatever the program does: `0`, "
            "`0.0`, `(0)`, `-0`, a macro defined as 0, or numbers and constants that work out to 0 "
            "(`(2 - 2)`, `NOT 1`), worked out as the controller holds numbers (an 8-bit exponent and "
            "a 24-bit mantissa), so `(0.1 + 0.2 - 0.3)` is 0 too. A divisor read from a variable, an "
            "array or a keyword such as VEL is not reported: it is zero only at times, which the program "
            "has to test.",
            why="The program compiles, and the controller raises this error each time the line runs.",
            example=Example(
                before="DEFINE move_time = 0\nDIM distance = 400\nPRINT distance / move_time\n",
                after="DEFINE move_time = 2\nDIM distance = 400\nPRINT distance / move_time\n",
            ),
            manual=("v4:19063", "v4:1276", "v4:14019"),
            fix="Divide by the value that was meant, or test the divisor before dividing.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            "W121",
            catches="POW on a NextMove controller (PCI, PC or BX) with an index from 0 to 1, `0` and `1` "
            "included, where the index is a number or works out to one before the program runs "
            "(`POW(x, 0.5)`, `POW(x, 1 / 3)`, a macro defined as 0.5). An index read from a variable is "
            "not reported.",
            why="On NextMove the index of POW must be below 0 or above 1; MintDrive and ServoNode 51 take "
            "any index. The guide names no error for one in between, so what the controller answers is "
            "not known; mint-run works the power out as the other controllers do.",
            example=Example(
                before="DIM area = 2\nPRINT POW(area, 0.5)\n",
                after="DIM area = 2\nPRINT SQRT(area)\n",
            ),
            manual=("v4:15163", "v4:15151", "v4:16303"),
            fix="Write a square root with SQRT, leave out an index of 1, and write 1 for an index of 0; "
            "for another fraction, find the power another way.",
            safety=FixSafety.NONE,
        ),
    ),
)
