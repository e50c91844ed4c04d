// The grammar tests (test/grammar/*.mnt) must assert what they say. vscode-tmgrammar-test compares scope
// names exactly, so an exclusion naming a prefix ("- comment" for "no comment here") or a misspelt scope
// holds whatever the grammar does; and it reads one "-" before the excluded scopes ("- a b"): after a
// second ("- a - b") it drops a <--- assertion without a word, and backtracks for minutes on a ^^^ one.
import assert from "node:assert/strict";
import { readdirSync, readFileSync } from "node:fs";
import { test } from "node:test";

import { GRAMMAR_PATH } from "../../scripts/generate-grammar.mjs";

const GRAMMAR_TESTS = new URL("../grammar/", import.meta.url);
// "REM", then the columns asserted (^^^, or <--- and <~~--- from the line's start), then the scopes.
const ASSERTION = /^REM\s*(?:\^+|<~*-+)\s*(.*)$/;

/** Every scope name the grammar can give a token: its own scope and each rule's and capture's name. */
function assignedScopes(grammar) {
  const names = new Set([grammar.scopeName]);
  const visit = (node) => {
    if (Array.isArray(node)) node.forEach(visit);
    else if (node !== null && typeof node === "object") {
      for (const [key, value] of Object.entries(node)) {
        if (key === "name" && typeof value === "string") names.add(value);
        else visit(value);
      }
    }
  };
  visit(grammar.repository);
  return names;
}

/** The assertions of every grammar test: where each is, and the words after its carets or arrow. */
function assertions() {
  const files = readdirSync(GRAMMAR_TESTS).filter((name) => name.endsWith(".mnt"));
  return files.flatMap((file) =>
    readFileSync(new URL(file, GRAMMAR_TESTS), "utf8")
      .split(/\r?\n/)
      .slice(1)
      .map((line, index) => ({ at: `${file}:${index + 2}`, words: ASSERTION.exec(line)?.[1]?.split(/\s+/) }))
      .filter((assertion) => assertion.words !== undefined),
  );
}

test("every scope a grammar test names, required or excluded, is a whole scope the grammar assigns", () => {
  const assigned = assignedScopes(JSON.parse(readFileSync(GRAMMAR_PATH, "utf8")));
  const named = assertions().flatMap(({ at, words }) => words.filter((word) => word !== "-").map((scope) => ({ at, scope })));
  assert.ok(named.length > 200, "the assertions are found");
  assert.deepEqual(named.filter(({ scope }) => !assigned.has(scope)), []);
});

test("a grammar test's excluded scopes follow one '-'", () => {
  const many = assertions().filter(({ words }) => words.filter((word) => word === "-").length > 1);
  assert.deepEqual(many.map(({ at }) => at), []);
});
