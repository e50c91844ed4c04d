"""Variables, arrays, labels and macros: declared, defined once, used, and told apart."""

from __future__ import annotations

from mintlang.ruledocs.model import Example, FixSafety, Group, RuleDoc

_NEVER_USED = (
    "It is usually left over from an edit, or the use is misspelt. On the controller it costs an entry "
    "in a table with a fixed size (3.9)."
)

GROUP = Group(
    "Names",
    "Variables must be declared with DIM before they are used, labels and macros defined once; only the "
    "first ten characters of a name count. These codes are names the compiler rejects, or that are "
    "defined and never used.",
    (
        RuleDoc(
            3001,
            catches="A name used as a variable before any DIM declares it, in compile order (the "
            "configuration file, then the program, top to bottom). Reported once per line, at the first "
            "use. A Mint v3 keyword or constant read this way is said with what it became in v4. In a "
            "Mint v3 program (no DIM for variables) it is a read of a variable before any assignment, FOR "
            'or INPUT earlier in the text declares it, the v3 guide\'s "Undefined Variables".',
            why="Mint v4 declares every variable at compile time: an undeclared name stops the program "
            "from compiling. It is often a misspelling of a declared name, which the message then offers.",
            example=Example(
                before='PRINT "Current axis speed is ", axis_speed\n',
                after='DIM axis_speed = 100\nPRINT "Current axis speed is ", axis_speed\n',
            ),
            manual=("v4:19073", "v4:865", "v4:9157", "v3:1352", "v3:12971"),
            fix="Declare the name with DIM (with the file's other DIMs, never inside a loop), or respell "
            "it as the declared name it resembles, or as the v4 keyword a v3 one became.",
            safety=FixSafety.UNSAFE,
        ),
        RuleDoc(
            3004,
            catches="A GOSUB or GOTO to a label the file does not define, or a label defined twice.",
            why="The compiler cannot resolve the jump and rejects the program. Each file's labels serve "
            "that file only: a GOSUB in the program does not reach a subroutine of the configuration file, "
            "and the message then says where the label is.",
            example=Example(
                before="GOSUB homing\nEND\n#home\nHOME.0 = 1\nRETURN\n",
                after="GOSUB homing\nEND\n#homing\nHOME.0 = 1\nRETURN\n",
            ),
            manual=("v4:19099", "v4:1841", "v4:11134"),
            fix="Change the jump to the label it resembles, or create the missing subroutine (a label and "
            "RETURN for a GOSUB) at the end of the file, after an END when the code above would run on into it. "
            "Where the label is written as other BASICs write it (`Init:` first on its line), write it `#Init`: "
            "safe when nothing but a comment follows the colon.",
            safety=FixSafety.UNSAFE,
        ),
        RuleDoc(
            3005,
            catches="A DEFINE whose name is not a name (`DEFINE 100 = 100`), or a macro defined twice, also "
            "once in the configuration file and once in the program.",
            why="Macros are replaced by their text before the program compiles; a macro without a valid, "
            "unique name cannot be replaced, and the compiler rejects the definition.",
            example=Example(
                before="DEFINE fast = 100\nDEFINE fast = 200\nSPEED.0 = fast\n",
                after="DEFINE fast = 100\nDEFINE faster = 200\nSPEED.0 = fast\nSPEED.1 = faster\n",
            ),
            manual=("v4:19103", "v4:1451", "v4:9098"),
            fix="Rename or remove one definition.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            3006,
            catches="Both #FASTIN and one of #FASTIN0, #FASTIN1 ... defined in the same program.",
            why="#FASTIN handles every fast input and #FASTINx one of them; the controller cannot route a "
            "latch to both, and rejects the program.",
            example=Example(
                before="PRINT 1\nEND\n#FASTIN\nPRINT 1\nRETURN\n#FASTIN0\nPRINT 2\nRETURN\n",
                after="PRINT 1\nEND\n#FASTIN0\nPRINT 2\nRETURN\n",
            ),
            manual=("v4:19108", "v4:1884"),
            fix="Keep one kind of handler.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            2016,
            catches="An array element whose index, known when compiling, lies outside 1 to the array's "
            "size (`speeds(0)`, `speeds(101)` in an array of 100), an element of a name that is not an "
            "array, or a COMMS element outside 1 to 255 (`COMMS(0)`).",
            why="Arrays are numbered from 1, not 0; an index outside them fails when the line runs.",
            example=Example(
                before="DIM speeds(100)\nspeeds(101) = 2000\n",
                after="DIM speeds(100)\nspeeds(100) = 2000\n",
            ),
            manual=("v4:19038", "v4:1057"),
            fix="The index or the array's size is wrong, and only the author knows which.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            45,
            catches="A write to a COMMS element that the controller maps onto a parameter it only reads: "
            "an axis's position, velocity, mode, errors, demand, encoder, idle flag or following error "
            "(`COMMS(100)` to `COMMS(107)` for axis 0, 15 elements an axis), the digital inputs, the "
            "analog channels, the error data, the status words and the build number.",
            why="Those elements report the controller's state to a host; the write fails when the line runs.",
            example=Example(
                before="COMMS(100) = 0\n",
                after="COMMS(1) = 0\n",
            ),
            manual=("v4:2566", "v4:18676"),
            fix="Use one of the 99 general elements, or write the parameter's own keyword where it can be written.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            46,
            catches="A read or a write of a COMMS element that the controller's extended map reserves: offsets "
            "8 to 14 of each axis's 15 elements (`COMMS(108)` to `COMMS(114)` for axis 0), and offsets 1, 3 and "
            "18 to 34 of the I/O block that starts at `COMMS(220)`.",
            why="Those elements hold nothing for a program or a host; the access fails when the line runs.",
            example=Example(
                before="PRINT COMMS(108)\n",
                after="PRINT COMMS(107)\n",
            ),
            manual=("v4:2566", "v4:18679"),
            fix="Use one of the 99 general elements, or an element the map gives a parameter.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            "W103",
            catches="A variable declared with DIM and never used. A routine made only of DIMs is the "
            "guide's way to keep variables between runs, and is not reported.",
            why=_NEVER_USED,
            example=Example(
                before="DIM spare\nDIM a = 1\nPRINT a\n",
                after="DIM a = 1\nPRINT a\n",
            ),
            manual=("v4:865", "v4:1904"),
            fix="Remove the DIM, or use the variable where it was meant to be.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            "W104",
            catches="A label no GOSUB or GOTO names. Event handlers (#ONERROR, #IN0 ...) are called by "
            "the controller and are never reported.",
            why=_NEVER_USED,
            example=Example(
                before="GOSUB setup\nEND\n#setup\nPRINT 1\nRETURN\n#unused\nPRINT 2\nRETURN\n",
                after="GOSUB setup\nEND\n#setup\nPRINT 1\nRETURN\n",
            ),
            manual=("v4:1841", "v4:1904"),
            fix="Remove the subroutine, or call it where it was meant to run.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            "W105",
            catches="A macro defined with DEFINE and never used, in the program or its configuration file.",
            why=_NEVER_USED,
            example=Example(
                before="DEFINE fast = 100\nDEFINE slow = 10\nSPEED.0 = fast\n",
                after="DEFINE fast = 100\nSPEED.0 = fast\n",
            ),
            manual=("v4:1451", "v4:1904"),
            fix="Remove the DEFINE, or use the macro.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            "W108",
            catches="Two spellings of a name that agree in their first ten characters "
            "(`thisIsAVariable1`, `thisIsAVariable2`).",
            why="Only the first ten characters of a variable, label or macro name count: the controller "
            "takes both spellings for one name, which is rarely what the author meant.",
            example=Example(
                before="DIM thisIsAVariable1 = 1\nPRINT thisIsAVariable1\nPRINT thisIsAVariable2\n",
                after="DIM first = 1\nDIM second = 2\nPRINT first\nPRINT second\n",
            ),
            manual=("v4:865", "v4:1904"),
            fix="Choose names that differ within ten characters.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            "W109",
            catches="An event handler the controller cannot call: #INx for an input it does not have, "
            "#FASTINx for a latch input it lacks, #CAN, #COMMS handlers beyond the ones it has; in MintMT an "
            "Event block for such an event too, and Event MOVEBUFFERLOW on a controller but a NextMove.",
            why="Such a label is an ordinary subroutine that nothing calls: the event it was written for "
            "is never handled.",
            example=Example(
                before="PRINT 1\nEND\n#IN99\nPRINT 2\nRETURN\n",
                after="PRINT 1\nEND\n#IN9\nPRINT 2\nRETURN\n",
            ),
            manual=("v4:1884",),
            fix="The input to handle depends on the wiring.",
            safety=FixSafety.NONE,
        ),
        RuleDoc(
            "W102",
            catches="A Mint v3 event label left in v4 code: #FASTPOS, which v4 calls #FASTIN.",
            why="v4 compiles it as an ordinary label that no event calls: the fast position latch is "
            "silently never handled.",
            example=Example(
                before="PRINT 1\nEND\n#FASTPOS\nPRINT 2\nRETURN\n",
                after="PRINT 1\nEND\n#FASTIN\nPRINT 2\nRETURN\n",
            ),
            manual=("v4:5910", "v4:1884"),
            fix="Rename the label to #FASTIN (with the same input number, if it has one), and the GOSUBs and "
            "GOTOs that name it with it; mint-migrate converts the rest of a v3 program. The handler then runs "
            "on each fast latch.",
            safety=FixSafety.UNSAFE,
        ),
    ),
)
