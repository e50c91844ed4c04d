"""The controller's fixed tables, stack, memory and line length."""

from __future__ import annotations

from mintlang.ruledocs.model import Example, FixSafety, Group, RuleDoc

_PC = "nextmove-pc"  # the smallest tables (3.9): the examples stay short


def _numbered(template: str, count: int) -> str:
    """``template`` (with ``{n}``) once for each of 1 .. ``count``."""
    return "".join(template.format(n=n, next=n + 1) for n in range(1, count + 1))


def _chain(depth: int) -> str:
    """A main program calling a chain of ``depth`` subroutines, each calling the next."""
    return "GOSUB s1\nEND\n" + _numbered("#s{n}\nGOSUB s{next}\nRETURN\n", depth - 1) + f"#s{depth}\nRETURN\n"


GROUP = Group(
    "Controller limits",
    "Variables, labels and macros live in tables of a fixed size, blocks and calls nest on a stack of a "
    "fixed depth, and programs share the controller's memory: 255 of each name and 100 GOSUB levels on "
    "most controllers, 100 names and 50 levels on NextMove PC.",
    (
        RuleDoc(
            2015,
            catches="More macros than the controller holds, or blocks nested deeper than it allows (FOR "
            "loops 50 levels, the other loops together 50, IF blocks 255; 20, 20 and 100 on NextMove PC).",
            why="The compiler keeps macros and open blocks on fixed stacks and stops with a stack overflow "
            "when one is full.",
            example=Example(
                before=_numbered("DEFINE m{n} = {n}\n", 101),
                after=_numbered("DEFINE m{n} = {n}\n", 100),
                controller=_PC,
            ),
            manual=("v4:19033", "v4:1904"),
            fix="Merge macros, or move nested code into subroutines.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            3000,
            catches="More labels in a file than the controller holds (255; 100 on NextMove PC).",
            why="Labels live in a table of a fixed size; the compiler rejects the program when it is full.",
            example=Example(
                before=_numbered("#s{n}\nRETURN\n", 101),
                after=_numbered("#s{n}\nRETURN\n", 100),
                controller=_PC,
            ),
            manual=("v4:19071", "v4:1904"),
            fix="Merge subroutines that differ only in a value into one taking a variable.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            3002,
            catches="More variables than the controller's table leaves a program (253 of its 255; 98 of 100 on "
            "NextMove PC: COMMS and GROUPCOMMS always take two), counting the configuration file's and the "
            "program's together. An array counts as one variable.",
            why="Variables live in a table of a fixed size; the compiler rejects the program when it is full.",
            example=Example(
                before=_numbered("DIM v{n}\n", 99),
                after="DIM v(99)\n",
                controller=_PC,
            ),
            manual=("v4:19085", "v4:1904", "v4:18465"),
            fix="Gather related values in an array.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            3003,
            catches="Arrays and compiled code that cannot fit the controller's Mint user memory (four bytes "
            "an array element, about half the program's size for the code), or a configuration file larger "
            "than its buffer. The estimate counts only what is certain, so it errs towards silence.",
            why="The controller cannot store the compiled program and stops with 'Out of memory' when compiling it.",
            example=Example(
                before="DIM samples(11000)\nsamples(1) = 1\n",
                after="DIM samples(1000)\nsamples(1) = 1\n",
                controller="mintdrive",
            ),
            manual=("v4:19088", "v4:5094"),
            fix="Smaller arrays, or data kept elsewhere.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            "W111",
            catches="A line longer than the controller's 255 characters, comments included (127 in Mint v3).",
            why="The controller does not accept a longer line when the program is downloaded; a v3 "
            "controller's compiler stops on it with 'Line too long'.",
            example=Example(
                before="REM " + "calibration notes " * 14 + "\nPRINT 1\n",
                after="REM" + " calibration notes" * 7 + "\nREM" + " calibration notes" * 7 + "\nPRINT 1\n",
            ),
            manual=("v4:18455", "v4:255", "v3:5144", "v3:12999"),
            fix="Split the statement at a colon, or shorten names or comments.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            "W116",
            catches="A chain of GOSUBs from the main program or an event handler deeper than the "
            "controller's 100 levels (50 on NextMove PC).",
            why="Each GOSUB nests one level until its RETURN; beyond the limit the controller stops with "
            "a stack overflow (2015). A warning, since the calls may be conditional.",
            example=Example(
                before=_chain(51),
                after=_chain(50),
                controller=_PC,
            ),
            manual=("v4:1904", "v4:11134"),
            fix="Flatten the chain of calls.",
            safety=FixSafety.NONE,
        ),
    ),
)
