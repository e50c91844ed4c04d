"""Statements the controller's compiler cannot read."""

from __future__ import annotations

from mintlang.ruledocs.model import Example, FixSafety, Group, RuleDoc

GROUP = Group(
    "Syntax",
    "Statements the compiler cannot read. The controller compiles the whole program before it runs a "
    "line of it, so one of these stops the program from starting at all.",
    (
        RuleDoc(
            2003,
            catches="A statement the grammar of Mint does not allow: a bracket opened and never closed, an "
            "operator with nothing after it, a command used where a value is needed, an expression where the "
            "syntax takes only a number or a simple variable (an array's size, an axis in brackets), an axis or "
            "channel number on a keyword whose formats take none (`TIME.5`), a second number after a dot "
            "(`POS.1.5`, `OUT1.2`: a dot names one axis or channel), INPUT into an array element, a "
            "string that is not closed before the end of the line, a function given more or "
            "fewer values than its format takes (`POW(2)`, `SIN(1, 2)`), a command given more or fewer operands "
            "than its format writes (`LOCATE 10`, `LINE 1`), or an EXIT outside any loop of its "
            "subroutine (raised when it runs: an EXIT never leaves a caller's loop).",
            why="The compiler stops at the first statement it cannot read and the program never starts. The "
            "controller's message names only the line, not what is wrong in it.",
            example=Example(
                before="DIM a = 1\nDIM b = 2\nIF (a > b THEN PRINT a\n",
                after="DIM a = 1\nDIM b = 2\nIF (a > b) THEN PRINT a\n",
            ),
            manual=("v4:18920", "v4:4611", "v4:9167", "v4:18430", "v4:10224", "v4:15152", "v4:13685", "v4:16737"),
            fix="The message says what was found where, and what to write depends on the intent.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            2004,
            catches="A closing bracket with no opening bracket to match it.",
            why="The compiler rejects the statement; an expression with a bracket too many usually also "
            "groups its terms in a way the author did not mean.",
            example=Example(
                before="DIM a\nDIM b = 1\na = (b + 2) * 3)\nPRINT a\n",
                after="DIM a\nDIM b = 1\na = (b + 2) * 3\nPRINT a\n",
            ),
            manual=("v4:18925", "v4:1412"),
            fix="Which bracket is the stray one depends on what the expression should compute.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            2005,
            catches="A parameter keyword standing alone as a statement, neither read nor given a value "
            "(`SPEED` on its own line, `COMMS(1)`), a keyword given `=` and no value (`SPEED.0 =`, "
            "`SPEED = ,`), PAUSE with no condition, a function written as a statement (`SIN(30)`), or AXES "
            "without the list of axes in a program.",
            why="A parameter is a value: as a statement it does nothing the compiler can make sense of. "
            "It is often a line whose `= value` was lost, or a comment missing its REM.",
            example=Example(
                before="SPEED : REM slew speed\n",
                after="SPEED = 2000 : REM slew speed\n",
            ),
            manual=("v4:18930", "v4:6883"),
            fix="The value to give the parameter is the author's to choose.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            2007,
            catches="An IF whose condition is not followed by THEN or DO.",
            why="Without THEN (one line) or DO (a block up to ENDIF), the compiler cannot tell where the "
            "condition ends and rejects the program.",
            example=Example(
                before='DIM a = 1\nDIM b = 2\nIF (a < b) PRINT "a is less than b"\n',
                after='DIM a = 1\nDIM b = 2\nIF (a < b) THEN PRINT "a is less than b"\n',
            ),
            manual=("v4:18944", "v4:1570", "v4:1589"),
            fix="THEN for one statement, DO for a block; the checker does not guess which.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            2008,
            catches="A FOR statement without TO between its start and end values.",
            why="A FOR loop needs a variable, a start and an end (`FOR i = 1 TO 10`); without TO the "
            "compiler cannot read the loop and the program does not start.",
            example=Example(
                before="DIM i\nFOR i = 1, 10\n  PRINT i\nNEXT\n",
                after="DIM i\nFOR i = 1 TO 10\n  PRINT i\nNEXT\n",
            ),
            manual=("v4:18949", "v4:1707"),
            fix="The statement has to be rewritten with TO.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            2001,
            catches="An empty place in a list of axes in brackets (`SPEED[0,,2]`, `SPEED[0,1,]`), a circle "
            "given one of its two axes (`CIRCLEA[0] = 10, 0, 90`), or a vector move with one of its positions "
            "left out (`VECTORR[0,1] = ,100`).",
            why="Each place in the brackets names an axis; an empty one leaves the controller without an "
            "axis to apply the value to.",
            example=Example(
                before="SPEED[0,,2] = 1000\n",
                after="SPEED[0,1,2] = 1000\n",
            ),
            manual=("v4:18909", "v4:544", "v4:8152", "v4:17031"),
            fix="Which axis was meant is not written anywhere.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            2006,
            catches="An editor command (NEW, EDIT, LIST ...) written in a program, or a reserved keyword used "
            "as a variable or label name (`FOR loop = 1 TO 10`, `INPUT x, SPEED`), as DO is after THEN "
            "(`IF a THEN DO`: the two forms of IF written together).",
            why="Editor commands work only at the controller's command line. Keywords are reserved: a "
            "variable called LOOP or SPEED cannot be declared, so the statement is rejected. RELEASE in a "
            "configuration file and RUN PROG / RUN CON are allowed, as the guide uses them.",
            example=Example(
                before="DIM count\nFOR loop = 1 TO 10\n  count = count + 1\nNEXT\n",
                after="DIM count\nDIM i\nFOR i = 1 TO 10\n  count = count + 1\nNEXT\n",
            ),
            manual=("v4:18935", "v4:5509", "v4:1573", "v4:1594"),
            fix="Renaming a variable means choosing a new name for every use; after IF, which of THEN and DO "
            "was meant depends on the lines that follow.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            3007,
            catches="A word used as a keyword that the target controller does not have: a misspelling "
            "(`IDL` for IDLE, offered with the keyword it resembles), a wrong abbreviation, or a Mint v3 "
            "keyword written with an axis (`HMSPEED.0`), which is said with what it became in v4.",
            why="The compiler cannot translate a word it does not know, so the program does not start. "
            "Abbreviations make typing mistakes easy to miss when reading.",
            example=Example(
                before="PAUSE IDL.0\n",
                after="PAUSE IDLE.0\n",
            ),
            manual=("v4:19111", "v4:5558"),
            fix="Replace the word with the keyword it resembles, or with the v4 keyword a v3 one was "
            "renamed to; offered only when there is one such keyword.",
            safety=FixSafety.UNSAFE,
        ),
        RuleDoc(
            "W101",
            catches="A string delimited by typographic quotes (“ ” or ‘ ’), as a word processor or a PDF "
            "turns the plain quotes of the guide's examples into.",
            why="The controller knows only the plain quote characters; a string opened or closed with a "
            "typographic one is not a string to it.",
            example=Example(
                before="PRINT “Homing axis 0”\n",
                after='PRINT "Homing axis 0"\n',
            ),
            manual=("v4:15299", "v4:802"),
            fix="Replace the typographic quotes that delimit the string with plain ones.",
            safety=FixSafety.SAFE,
        ),
    ),
)
