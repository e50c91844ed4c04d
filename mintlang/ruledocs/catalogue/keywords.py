"""Keywords used in a way their attributes or the controller do not allow."""

from __future__ import annotations

from mintlang.ruledocs.model import Example, FixSafety, Group, RuleDoc

GROUP = Group(
    "Keyword use",
    "Each keyword of the v4 guide says whether it can be read, written or run as a command, which "
    "controllers have it and what values it takes. These codes are uses the keyword does not allow.",
    (
        RuleDoc(
            2000,
            catches="A value assigned to a keyword that can only be read (`CAMINDEX = 4`, a function: "
            "`ABS(1) = 5`) or that is a command (`STOP = 1`, `BEEP = 1`).",
            why="The keyword's attribute table says it cannot be written; the compiler refuses the "
            "assignment, and the value the author meant to set is never set.",
            example=Example(
                before="CAMINDEX = 4\n",
                after="DIM index\nindex = CAMINDEX\nPRINT index\n",
            ),
            manual=("v4:18905", "v4:5586"),
            fix="Read the keyword, or set the parameter that does accept a value.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            2002,
            catches="A keyword that can only be written, read in an expression or a PRINT (`PRINT ACCELTIME`).",
            why="Write-only keywords hold no value to read back; the compiler rejects the read.",
            example=Example(
                before='PRINT "Acceleration time is ", ACCELTIME\n',
                after="ACCELTIME = 200\n",
            ),
            manual=("v4:18915", "v4:6212"),
            fix="Keep the value in a variable when it has to be read back.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            3,
            catches="A constant value assigned to a keyword outside the range its entry gives "
            "(`SCALE = -3`, `KPROP.0 = -1`), or a mode keyword's value its table does not list (`HOME.0 = 5`). "
            "For a scaled keyword the range applies after the scale factor, known only when the program runs; "
            "as the factor is always positive, only a sign no factor can mend is reported (`SPEED = -5`, "
            "`ACCEL = 0`). Also a constant given to ACOS or ASIN outside -1 to 1, or to LOG that is not "
            "above 0 (`ACOS(2)`, `LOG(0)`): those functions have no answer there. In Mint v3 (`--dialect v3`) "
            "the ranges are the v3 guide's, given at SCALE 1 (`WAIT = 1`, `GAIN = 300`), v3's \"Out of range\".",
            why="The controller raises the error when the line runs and stops the program (or calls "
            "#ONERROR); the parameter keeps its old value.",
            example=Example(
                before="KPROP.0 = -1\n",
                after="KPROP.0 = 1\n",
            ),
            manual=("v4:18518", "v4:4611", "v4:5586", "v4:6279", "v4:13723", "v3:13136"),
            fix="The right value comes from the machine, not from the program.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            17,
            catches="A keyword the target controller does not support (`CIRCLEA` on a MintDrive, "
            "`AUTO` on a NextMove), according to the controllers its entry lists.",
            why="The program may be correct for another controller; on this one the keyword fails. "
            "Check the `--controller` option (or `mint.controller` in the editor) before changing the code.",
            example=Example(
                before="CIRCLEA[0,1] = 10, 10, 90\n",
                after="MOVEA.0 = 10\nGO.0\n",
                controller="mintdrive",
            ),
            manual=("v4:18570", "v4:8142"),
            fix="The replacement depends on what the controller offers instead.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            "W114",
            catches="AUTO anywhere but as the very first command of the configuration file (after a REM, "
            "after another statement, or in the program file), and PROTECT with a password anywhere but as "
            "the very first command of the program file.",
            why="AUTO makes the controller run the configuration and the program at power-up only from "
            "that first place; anywhere else it is silently ignored, and a machine meant to start on its "
            "own waits at the prompt. PROTECT's place is the program's first line, as AUTO's is the "
            "configuration's: elsewhere the buffers are left open to anyone at the command line. "
            "Writing PROTECT (PROTECT = _on) may stand anywhere.",
            example=Example(
                before="REM start-up\nAUTO\n",
                after="AUTO\nREM start-up\n",
                controller="mintdrive",
                with_program="PRINT 1\n",
            ),
            manual=("v4:6633", "v4:5280", "v4:15375"),
            fix="Move AUTO to the first line of the configuration file, PROTECT to the first line of the program.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            "W118",
            catches="PRINT or LINE formatting a number with USING and more than 15 integer or 15 "
            "fractional digits, or INPUT accepting one with more than 15 integer or 3 fractional digits "
            "(a negative integer count asks for a sign, not for more digits).",
            why="The controller prints at most 15 digits on each side of the point, and its formatted input "
            "takes at most 15 before it and 3 after it; the guide gives no error for a larger count, so the "
            "field is not the width the program asks for.",
            example=Example(
                before="DIM a = 123.5\nPRINT a USING 16, 2\n",
                after="DIM a = 123.5\nPRINT a USING 15, 2\n",
            ),
            manual=("v4:15313", "v4:13657", "v4:12247"),
            fix="Ask for 15 digits or fewer (3 or fewer after the point for INPUT).",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            "W119",
            catches="SOFTLIMITREVERSE set at or above SOFTLIMITFORWARD on the same axis, when the program "
            "writes each of them once on that axis with a constant. A write without axes is on the AXES "
            "default, every axis from 0, while neither file writes AXES.",
            why="The reverse software limit must be less than the forward one; with the two crossed, "
            "no position is inside both limits, so the soft limits do not guard the travel the program "
            "means them to. The guide gives no error number for it, so the controller's reaction is not known.",
            example=Example(
                before="SOFTLIMITFORWARD.0 = 100\nSOFTLIMITREVERSE.0 = 200\n",
                after="SOFTLIMITFORWARD.0 = 200\nSOFTLIMITREVERSE.0 = 100\n",
            ),
            manual=("v4:16000", "v4:16098"),
            fix="Swap the two values, or correct the one that was mistyped.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            "W122",
            catches="One value after the '=' of a keyword whose brackets list two axes or more, with no ';' "
            "after it (`DRIVEENABLE[0,1,2] = 1`). Two values or more are not reported: the guide's own "
            "`MOVEA[0,1,2] = 10,20` moves the first two axes only, on purpose. Nor are vector and circle moves, "
            "whose values are one position of all their axes: one value there is error 2001.",
            why="The values go to the listed axes in order, so the one value sets the first axis only and the "
            "others keep what they had; a ';' after the last value is what gives it to every axis left. A "
            "drive left disabled or a speed left at its old value is found only when the machine runs.",
            example=Example(
                before="DRIVEENABLE[0,1,2] = 1\n",
                after="DRIVEENABLE[0,1,2] = 1;\n",
            ),
            manual=("v4:630", "v4:656", "v4:578", "v3:1109"),
            fix="Write ';' after the value to give it to every axis listed, or list only the axis meant. The "
            "fix writes the ';': it changes what the line does, so it is unsafe.",
            safety=FixSafety.UNSAFE,
        ),
    ),
)
