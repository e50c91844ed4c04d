// language-configuration.json: comment toggling, pairs, folding markers and indentation rules,
// with the regular expressions run on Mint lines as VS Code runs them.
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { test } from "node:test";

const configuration = JSON.parse(readFileSync(new URL("../../language-configuration.json", import.meta.url), "utf8"));
const regex = ({ pattern, flags }) => new RegExp(pattern, flags);
const increase = regex(configuration.indentationRules.increaseIndentPattern);
const decrease = regex(configuration.indentationRules.decreaseIndentPattern);
const foldStart = regex(configuration.folding.markers.start);
const foldEnd = regex(configuration.folding.markers.end);

const OPENERS = [
  "IF x > 1 DO",
  "  if IN.1 and IN.5 do",
  "IF ERROR.0 = _limit DO      : REM Limit error",
  "IF x DO REM the block starts here",
  "IF x DO : y = 1",
  "IF x DO : REM ENDIF comes later",
  "FOR i = 1 TO 10",
  "FOR i = 1 TO 10 : REM NEXT is below",
  "WHILE IDLE = 0",
  "LOOP",
  "REPEAT",
];
const ONE_LINERS = [
  "IF x THEN GOTO done",
  "IF x THEN PRINT \"DO it now\"",
  "IF x THEN y = 1 : REM DO this later",
  "IF x THEN y = 1 REM DO this later",
  "IF x DO : y = 1 : ENDIF",
  "FOR i = 1 TO 3 : NEXT",
  "WHILE x : ENDW",
  "LOOP : EXIT : ENDL",
  "REPEAT : UNTIL IDLE",
  "FORWARD = 1",
  "REM FOR each axis",
  "x = DO_IT",
];
const CLOSERS = ["ENDIF", "  next", "ENDW", "ENDL", "UNTIL IDLE.0"];

test("block openers indent the next line and start a fold", () => {
  for (const line of OPENERS) {
    assert.match(line, increase, line);
    assert.match(line, foldStart, line);
  }
});

test("one-line blocks, single-line IF … THEN and words in strings or comments do neither", () => {
  for (const line of ONE_LINERS) {
    assert.doesNotMatch(line, increase, line);
    assert.doesNotMatch(line, foldStart, line);
  }
});

test("closers outdent themselves and end a fold; ELSE outdents itself and indents the next line", () => {
  for (const line of CLOSERS) {
    assert.match(line, decrease, line);
    assert.match(line, foldEnd, line);
  }
  assert.match("ELSE", decrease);
  assert.match("  else", increase);
  assert.doesNotMatch("ELSE", foldStart);
  assert.doesNotMatch("NEXTMOVE = 1", decrease);
  assert.doesNotMatch("ENDIFS = 1", foldEnd);
});

test("a label starts a fold that a RETURN at the start of a line ends; labels keep the manual's flat layout", () => {
  for (const label of ["#home", "#IN3", "#TIMER"]) {
    assert.match(label, foldStart, label);
    assert.doesNotMatch(label, increase, label);
  }
  assert.match("RETURN", foldEnd);
  // An early RETURN inside the subroutine's body (indented under an IF) does not end it.
  assert.doesNotMatch("  RETURN", foldEnd);
  assert.doesNotMatch("PRINT #1, x", foldStart);
});

test("comments toggle as 'REM ': a bare REM would take REMOTEIN.1 = 5 for a commented line", () => {
  assert.equal(configuration.comments.lineComment, "REM ");
  assert.equal(configuration.comments.blockComment, undefined);
});

test("double quotes pair up; typographic ones are highlighted but not typed, as the controller rejects them", () => {
  const pairs = configuration.autoClosingPairs.map(({ open, close }) => open + close);
  assert.deepEqual(pairs, ["()", "[]", "\"\""]);
  for (const quote of ["\u201c", "\u2018"]) {
    assert.ok(!pairs.some((pair) => pair.includes(quote)), quote);
  }
});

test("a single quote neither closes nor surrounds: it starts a comment (004's ' Wait until …), not a pair", () => {
  // A pair's notIn cannot help: as ' is typed to start a comment, the text before it is code, so
  // x = 1 ' became x = 1 '' and every comment began with a stray quote.
  const opens = configuration.autoClosingPairs.map(({ open }) => open);
  const surrounds = configuration.surroundingPairs.map(([open]) => open);
  assert.ok(!opens.includes("'"), "autoClosingPairs");
  assert.ok(!surrounds.includes("'"), "surroundingPairs");
});

// MintMT's blocks (004's examples): a multi-line If … Then ends at EndIf or End If, Loop at End Loop,
// Event NAME at End Event, Startup at End Startup; an If … Then with statements after Then is one line.
const MINTMT_OPENERS = [
  "If (COMMS(1) = 1) And (MOVEBUFFERFREE(0) > 0) Then",
  "  If (COMMS(1) = 1) Then",
  "If key = 'A' Then ' the key typed",
  "Event MOVEBUFFERLOW",
  "event Comms1 ' a comment after it",
  "Startup",
];
const MINTMT_ONE_LINERS = ["If x Then GO(0)", "If x Then y = 1 ' Then", "event = 1", "Eventual = 1", "Startup = 1"];
const MINTMT_CLOSERS = ["End If", "  EndIf", "End Loop", "End Event", "end startup"];

test("MintMT's block openers indent the next line and start a fold; a one-line If … Then does neither", () => {
  for (const line of MINTMT_OPENERS) {
    assert.match(line, increase, line);
    assert.match(line, foldStart, line);
  }
  for (const line of MINTMT_ONE_LINERS) {
    assert.doesNotMatch(line, increase, line);
    assert.doesNotMatch(line, foldStart, line);
  }
});

test("MintMT's End words outdent themselves and end a fold, and start none", () => {
  for (const line of MINTMT_CLOSERS) {
    assert.match(line, decrease, line);
    assert.match(line, foldEnd, line);
    assert.doesNotMatch(line, foldStart, line);
    assert.doesNotMatch(line, increase, line);
  }
  assert.doesNotMatch("EndLoop = 1", foldEnd);
});
