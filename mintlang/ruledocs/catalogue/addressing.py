"""Axes, I/O channels, CAN nodes and terminals addressed by number."""

from __future__ import annotations

from mintlang.ruledocs.model import Example, FixSafety, Group, RuleDoc

GROUP = Group(
    "Axes and channels",
    "Keywords address axes in brackets (`SPEED[0,1]`) or after a dot (`SPEED.0`), and I/O channels, CAN "
    "nodes and terminals after a dot. A constant number is checked against the controller: the motion "
    "library would raise these errors when the line runs.",
    (
        RuleDoc(
            2,
            catches="An axis number the controller does not have (`SPEED.10` on an 8-axis NextMove PC).",
            why="The motion library rejects the axis when the line runs: the program stops there, or "
            "#ONERROR is called, and the move or setting is not made.",
            example=Example(
                before="SPEED.10 = 5000\n",
                after="SPEED.7 = 5000\n",
                controller="nextmove-pc",
            ),
            manual=("v4:18514", "v4:677"),
            fix="The axis to use is the machine's.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            4,
            catches="A channel number beyond the controller's channels for that keyword: ADC and DAC "
            "channels, encoders and auxiliary encoders, capture channels.",
            why="The channel does not exist on this controller; the line fails when it runs.",
            example=Example(
                before="CAPTUREMODE.30 = 2\n",
                after="CAPTUREMODE.3 = 2\n",
            ),
            manual=("v4:18522",),
            fix="The channel to use depends on the wiring.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            7,
            catches="A digital input number beyond the controller's inputs (`IN.70` on a NextMove PCI, "
            "whose inputs are 0 to 59).",
            why="Reading an input that does not exist fails when the line runs.",
            example=Example(
                before="DIM switch\nswitch = IN.70\nPRINT switch\n",
                after="DIM switch\nswitch = IN.7\nPRINT switch\n",
            ),
            manual=("v4:18532", "v4:11937"),
            fix="The input to read depends on the wiring.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            8,
            catches="A digital output number beyond the controller's outputs (`OUT.40` on a NextMove PCI, "
            "whose outputs are 0 to 35).",
            why="Setting an output that does not exist fails when the line runs; the device meant to be "
            "switched is not.",
            example=Example(
                before="OUT.40 = 1\n",
                after="OUT.4 = 1\n",
            ),
            manual=("v4:18536", "v4:14879"),
            fix="The output to set depends on the wiring.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            26,
            catches="A CAN node number outside 0 to 63 in a REMOTE keyword (`REMOTEIN.2.65`).",
            why="No CAN node can have that number; the access fails when the line runs.",
            example=Example(
                before="PRINT REMOTEIN.2.65\n",
                after="PRINT REMOTEIN.2.5\n",
            ),
            manual=("v4:18604", "v4:15536"),
            fix="The node number is the node's configured address.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            31,
            catches="A CAN bus number other than 1 or 2 in a REMOTE keyword (`REMOTEIN.12.4`).",
            why="The controller has two CAN buses at most; the access fails when the line runs.",
            example=Example(
                before="PRINT REMOTEIN.12.4\n",
                after="PRINT REMOTEIN.1.4\n",
            ),
            manual=("v4:18623", "v4:15536"),
            fix="Which bus the node is on is the machine's.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            35,
            catches="A terminal number that names no terminal, where COMMSMODE or SERIALBAUD take one "
            "(`COMMSMODE.5 = 1`).",
            why="There is no such terminal; the setting fails when the line runs.",
            example=Example(
                before="COMMSMODE.5 = 1\n",
                after="COMMSMODE._tmRS485 = 1\n",
            ),
            manual=("v4:18637", "v4:8338"),
            fix="Write the terminal's constant (`_tmRS232`, `_tmRS485`).",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            36,
            catches="A terminal that exists but is not a serial one, given to COMMSMODE or SERIALBAUD "
            "(`COMMSMODE._tmLCD1 = 1`).",
            why="These keywords configure the RS232 and RS485 ports only; any other terminal fails when the line runs.",
            example=Example(
                before="COMMSMODE._tmLCD1 = 1\n",
                after="COMMSMODE._tmRS232 = 1\n",
            ),
            manual=("v4:18642", "v4:8338"),
            fix="Name the serial port the setting is for.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            2017,
            catches="More axes in brackets than the controller has (`SPEED[0,1,3]` on a one-axis MintDrive), "
            "more values than the addressed axes can take (`SPEED[0,1] = 10, 20, 30`, `MOVEA.0 = 10, 20`, "
            "more values than the controller has axes to the default axes, or more than the AXES list set just "
            "before gives them: `AXES[0,1]` then `SPEED = 10, 20, 30`), or a circle with more "
            "than its two axes or three values (`CIRCLEA[0,1,2] = 10, 0, 90`, `CIRCLER[0,1] = 5, 5, 90, 1`), "
            "or a second value for a channel keyword, which addresses one channel a call (`OUT.1 = 1, 0`), "
            "or for a keyword that addresses nothing (`TIMEREVENT = 100, 200`).",
            why="The compiler rejects the statement; where the AXES list decides, the line fails when it runs. "
            "A value with no axis to go to usually means an axis was left out of the list.",
            example=Example(
                before="SPEED[0,1] = 10, 20, 30\n",
                after="SPEED[0,1,2] = 10, 20, 30\n",
            ),
            manual=("v4:19047", "v4:572", "v4:590", "v4:677", "v4:8152", "v4:547"),
            fix="Either an axis or a value is missing, and only the author knows which.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            2018,
            catches="An axis listed twice in brackets (`SPEED[2,2,3]`, `AXES[0,1,1,2]`).",
            why="Each axis takes one value; naming one twice is rejected, and is usually a typing mistake "
            "for another axis.",
            example=Example(
                before="SPEED[2,2,3] = 5000\n",
                after="SPEED[1,2,3] = 5000\n",
            ),
            manual=("v4:19053", "v4:544"),
            fix="Which axis was meant is not written anywhere.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            "I201",
            catches="A single axis or channel written in brackets (`POS[1]`) where the dot (`POS.1`) says "
            "the same. A hint: reported only when selected (`--select I`).",
            why="The guide recommends the dot for one axis: the compiled code is smaller and runs faster. "
            "The program is correct either way.",
            example=Example(
                before="DIM b\nb = POS[1]\nPRINT b\n",
                after="DIM b\nb = POS.1\nPRINT b\n",
            ),
            manual=("v4:677",),
            fix="Write the axis after a dot; a macro gets the double dot it needs (`MOVER..xAxis`).",
            safety=FixSafety.SAFE,
        ),
    ),
)
