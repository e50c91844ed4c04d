"""Realistic generated Mint programs and Python files of the same length, for benchmarks.

The program is what a machine builder writes: declarations, set-up of
several axes, a main loop of moves with I/O handshakes, a menu over the
terminal, homing and event handlers. A fixed seed makes it the same on
every run.
"""

from __future__ import annotations

import random
import re

_BLOCKS = (
    lambda r, i, v: [f"DIM speed{v}", f"DIM target{v}(20) = {r.randint(1, 99)},{r.randint(1, 99)};"],
    lambda r, i, v: [
        f"SPEED[0,1] = {r.randint(10, 500)},{r.randint(10, 500)}",
        f"ACCEL = {r.randint(100, 5000)};",
        f"MOVEA = target{v}(1), target{v}(2) : GO[0,1]",
        "PAUSE IDLE[0,1]",
    ],
    lambda r, i, v: [
        f"IF IN{i % 16} AND speed{v} > {r.randint(1, 100)} DO",
        f"  OUT{i % 8} = _ON : WAIT = {r.randint(10, 200)}",
        "ELSE",
        f'  PRINT "speed ", speed{v}; " at ", POS.0 USING 5,2',
        "ENDIF",
    ],
    lambda r, i, v: [
        f"FOR speed{v} = 1 TO {r.randint(2, 20)} STEP 2",
        f"  MOVER.{i % 4} = speed{v} * 1.5 + SIN {r.randint(0, 90)} : GO.{i % 4}",
        "  PAUSE IDLE.0",
        "NEXT",
    ],
    lambda r, i, v: ["REM ---- next station ----", ""],
    lambda r, i, v: [
        f"WHILE !IN{i % 16}",
        f"  JOG.1 = ADC.0 * {r.randint(1, 9)} - 127 : REM follow the joystick",
        "ENDW",
        "STOP.1",
    ],
)


def mint_program(lines: int, seed: int = 2002, *, names: int = 30) -> str:
    """A well-formed Mint v4 program of exactly ``lines`` lines.

    It declares ``names`` variables and as many arrays; the default repeats lines as
    a program of a few hundred lines does, more make most lines distinct.
    """
    rng = random.Random(seed)
    body: list[str] = ["REM Generated benchmark program", "DIM key", "GOSUB init", "LOOP"]
    index = 0
    while len(body) < lines - 12:
        index += 1
        body.extend("  " + text if text else text for text in rng.choice(_BLOCKS)(rng, index, index % names))
    body[1:1] = [f"DIM speed{n}" for n in range(names)] + [f"DIM target{n}(20)" for n in range(names)]
    body = body[: lines - 8]
    body += ["  key = INKEY", "  IF key = 'Q' THEN EXIT", "ENDL", "END", "#init", "AXES[0,1,2,3]", "RETURN", "#ONERROR"]
    body += ["PRINT ERR : RETURN"]
    return "\n".join(body[:lines]) + "\n"


_PYTHON_BLOCKS = (
    lambda r, i, v: [f"speed{v} = 0", f"target{v} = [{r.randint(1, 99)}, {r.randint(1, 99)}] * 10"],
    lambda r, i, v: [
        f"speed[0], speed[1] = {r.randint(10, 500)}, {r.randint(10, 500)}",
        f"accel = {r.randint(100, 5000)}",
        f"move_to(target{v}[1], target{v}[2]); go(0, 1)",
        "wait_idle(0, 1)",
    ],
    lambda r, i, v: [
        f"if inputs[{i % 16}] and speed{v} > {r.randint(1, 100)}:",
        f"    outputs[{i % 8}] = ON; wait({r.randint(10, 200)})",
        "else:",
        f'    print("speed ", speed{v}, " at ", pos[0])',
        "    pass",
    ],
    lambda r, i, v: [
        f"for speed{v} in range(1, {r.randint(2, 20)}, 2):",
        f"    mover[{i % 4}] = speed{v} * 1.5 + sin({r.randint(0, 90)}); go({i % 4})",
        "    wait_idle(0)",
        "    pass",
    ],
    lambda r, i, v: ["# ---- next station ----", ""],
    lambda r, i, v: [
        f"while not inputs[{i % 16}]:",
        f"    jog[1] = adc[0] * {r.randint(1, 9)} - 127  # follow the joystick",
        "    pass",
        "stop(1)",
    ],
)


# The same program in MintMT's spelling (mintlang/MINTMT.md): ' comments, round-bracket addressing, Then
# ending a line for DO, two-word closers; AXES keeps v4's square brackets (MT-4) and 'Q' its code.
_MINTMT_SPELLING = (
    (re.compile(r"\bREM\b"), "'"),
    (re.compile(r"\b(?!AXES)([A-Z]+)\[([^\]]*)\]"), r"\1(\2)"),
    (re.compile(r"\b([A-Z]+)\.(\d+)\b"), r"\1(\2)"),
    (re.compile(r" DO$", re.MULTILINE), " Then"),
    (re.compile(r"^(\s*)ENDIF$", re.MULTILINE), r"\1End If"),
    (re.compile(r"^ENDL$", re.MULTILINE), "End Loop"),
    (re.compile(r"'Q'"), "81"),
)


def mintmt_program(lines: int, seed: int = 2002, *, names: int = 30) -> str:
    """``mint_program`` written as MintMT: the same lines and statements, for the MintMT row of a benchmark."""
    text = mint_program(lines, seed, names=names)
    for pattern, replacement in _MINTMT_SPELLING:
        text = pattern.sub(replacement, text)
    return text


def python_program(lines: int, seed: int = 2002, *, names: int = 30) -> str:
    """The Python counterpart of ``mint_program``: the same blocks and declarations, lines and about as
    many tokens."""
    rng = random.Random(seed)
    body: list[str] = ["# Generated benchmark program", "key = 0", "init()", "while True:"]
    index = 0
    while len(body) + 2 * names < lines - 3:
        index += 1
        block = rng.randrange(len(_PYTHON_BLOCKS))
        body.extend("    " + text if text else text for text in _PYTHON_BLOCKS[block](rng, index, index % names))
    body[1:1] = [f"speed{n} = 0" for n in range(names)] + [f"target{n} = [0] * 20" for n in range(names)]
    body = body[: lines - 3]
    if body[-1].endswith(":"):  # the last block was cut after its header
        body[-1] = "    pass"
    body += ["    key = inkey()", "    if key == 'Q': break", "print(err)"]
    return "\n".join(body[:lines]) + "\n"
