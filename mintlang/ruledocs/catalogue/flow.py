"""Blocks that do not match, and control flow that goes where the author did not mean."""

from __future__ import annotations

from mintlang.ruledocs.model import Example, FixSafety, Group, RuleDoc

_NESTED_WRONGLY = (
    "Blocks must close in the reverse order they open: the compiler keeps them on a stack and expects "
    "the innermost one to close first. It rejects the program at the first closing word that does not "
    "match, and the message says which block is still open."
)

GROUP = Group(
    "Blocks and control flow",
    "IF .. DO, FOR, REPEAT, WHILE and LOOP blocks, subroutines, and jumps. The block errors stop the "
    "program from compiling; the warnings are paths through the program that are legal but rarely meant.",
    (
        RuleDoc(
            2009,
            catches="A NEXT whose FOR is not the innermost open block: a loop opened inside the FOR "
            "closes after the NEXT, or there is no FOR at all.",
            why=_NESTED_WRONGLY,
            example=Example(
                before='DIM i\nDIM d\nFOR i = 1 TO 10\n  REPEAT\n    INPUT "Distance", d\n  NEXT\nUNTIL d > 100\n',
                after='DIM i\nDIM d\nFOR i = 1 TO 10\n  REPEAT\n    INPUT "Distance", d\n  UNTIL d > 100\nNEXT\n',
            ),
            manual=("v4:18954", "v4:1707"),
            fix="Which block should end first is the author's decision.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            2011,
            catches="An ELSE or ENDIF with no IF .. DO open: most often a block written with THEN, which "
            "makes a one-line IF, or a second ELSE in the same block.",
            why="Only IF .. DO opens a block; IF .. THEN ends at the end of its line, so the ELSE and ENDIF "
            "below it belong to nothing and the compiler rejects them.",
            example=Example(
                before="DIM a = 1\nDIM b = 2\nIF a > b THEN\n  PRINT a\nENDIF\n",
                after="DIM a = 1\nDIM b = 2\nIF a > b DO\n  PRINT a\nENDIF\n",
            ),
            manual=("v4:18979", "v4:1589"),
            fix="Change the THEN of the IF above to DO, where a bare IF .. THEN stands at the same depth.",
            safety=FixSafety.UNSAFE,
        ),
        RuleDoc(
            2012,
            catches="An ENDW whose WHILE is not the innermost open block, or an ENDW with no WHILE.",
            why=_NESTED_WRONGLY,
            example=Example(
                before='DIM d\nWHILE d = 0\n  REPEAT\n    INPUT "Distance", d\n  ENDW\nUNTIL d > 100\n',
                after='DIM d\nWHILE d = 0\n  REPEAT\n    INPUT "Distance", d\n  UNTIL d > 100\nENDW\n',
            ),
            manual=("v4:19000", "v4:1778"),
            fix="Which block should end first is the author's decision.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            2013,
            catches="An UNTIL whose REPEAT is not the innermost open block, or an UNTIL with no REPEAT.",
            why=_NESTED_WRONGLY,
            example=Example(
                before='DIM d\nREPEAT\n  WHILE d = 0\n    INPUT "Distance", d\n  UNTIL d > 100\nENDW\n',
                after='DIM d\nREPEAT\n  WHILE d = 0\n    INPUT "Distance", d\n  ENDW\nUNTIL d > 100\n',
            ),
            manual=("v4:19011", "v4:1747"),
            fix="Which block should end first is the author's decision.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            2014,
            catches="An ENDL whose LOOP is not the innermost open block, or an ENDL with no LOOP.",
            why=_NESTED_WRONGLY,
            example=Example(
                before='DIM d\nLOOP\n  WHILE d = 0\n    INPUT "Distance", d\n  ENDL\nENDW\n',
                after='DIM d\nLOOP\n  WHILE d = 0\n    INPUT "Distance", d\n  ENDW\nENDL\n',
            ),
            manual=("v4:19022", "v4:1797"),
            fix="Which block should end first is the author's decision.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            2010,
            catches="A RETURN the main program reaches, with no GOSUB to return to: one written in the main "
            "program in place of END (an error), or the one ending the first subroutine when a main program "
            "without END runs on into it (a warning, since a file may be a fragment of a larger program); "
            "and a GOTO of the main program into a subroutine or event handler (a MintMT Event block) whose "
            "code returns, reported at the GOTO.",
            why="The controller stops with error 2010 at that RETURN (End Event). When the main program runs "
            "on, it first runs the subroutine below it as if it were called (an #ONERROR handler runs with no "
            "error).",
            example=Example(
                before='DIM running = 1\nWHILE running\n  running = IN.0\nENDW\nPRINT "stopped"\nRETURN\n',
                after='DIM running = 1\nWHILE running\n  running = IN.0\nENDW\nPRINT "stopped"\nEND\n',
            ),
            manual=("v4:18965", "v4:1841"),
            fix="END belongs where the main program should stop.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            "W106",
            catches="Statements that nothing can reach: after END, RETURN, GOTO or EXIT, with no label "
            "before them. The guide's own layouts, a lone END or RETURN after an endless main loop and a "
            "lone RETURN after a handler's own END, are not reported, nor what the compiler does wherever "
            "it stands: a DEFINE, an array's DIM, a DIM "
            "without a value.",
            why="Code that never runs is usually a mistake: a label was forgotten, or an END placed too "
            "early. At best it misleads the reader about what the program does.",
            example=Example(
                before='PRINT "ready"\nEND\nPRINT "done"\n',
                after='PRINT "ready"\nPRINT "done"\nEND\n',
            ),
            manual=("v4:262", "v4:9839", "v4:967", "v4:1104"),
            fix="Remove the unreachable statements, with any block opened among them and its closing word.",
            safety=FixSafety.UNSAFE,
        ),
        RuleDoc(
            "W107",
            catches="A subroutine without RETURN that runs on into the next one. A label that only GOTO "
            "reaches is a place in the code around it, and is not reported.",
            why="The first subroutine silently runs the second one's code too, and that RETURN then ends "
            "both: rarely what the author meant.",
            example=Example(
                before="GOSUB first\nGOSUB second\nEND\n#first\nPRINT 1\n#second\nPRINT 2\nRETURN\n",
                after="GOSUB first\nGOSUB second\nEND\n#first\nPRINT 1\nRETURN\n#second\nPRINT 2\nRETURN\n",
            ),
            manual=("v4:1841",),
            fix="A RETURN may be missing, or the fall-through may be meant.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            "W113",
            catches="GOTO from inside an event handler (before its RETURN), an IF block or a loop to a label "
            "outside it. One warning at the GOTO names the handler and every block it leaves, each with the line "
            "it opens on.",
            why="The handler or block is never closed: the controller keeps it on its stack. Done repeatedly, as "
            "in a loop, this overflows the stack (error 2015) when the program runs.",
            example=Example(
                before="DIM i\nFOR i = 1 TO 10\n  IF IN.0 THEN GOTO done\nNEXT\n#done\nPRINT i\n",
                after="DIM i\nFOR i = 1 TO 10\n  IF IN.0 THEN EXIT\nNEXT\nPRINT i\n",
            ),
            manual=("v4:11178", "v4:1828"),
            fix="EXIT leaves a loop cleanly; the rest depends on the program.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            "W115",
            catches="A subroutine that calls itself, directly or through others, with GOSUB.",
            why="Each GOSUB nests one level until its RETURN. A routine that calls itself nests deeper with "
            "every call, and the controller stops with a stack overflow (2015) at its limit of 100 levels "
            "(50 on NextMove PC). A warning, since the call may be conditional.",
            example=Example(
                before="DIM n = 5\nGOSUB count\nEND\n#count\nn = n - 1\nIF n > 0 THEN GOSUB count\nRETURN\n",
                after="DIM n = 5\nGOSUB count\nEND\n#count\nWHILE n > 0\n  n = n - 1\nENDW\nRETURN\n",
            ),
            manual=("v4:1904", "v4:11134"),
            fix="Turning a recursion into a loop is a rewrite.",
            safety=FixSafety.NONE,
        ),
    ),
)
