"""Arithmetic the controller cannot do: a division whose divisor is always zero."""

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
    ),
)
