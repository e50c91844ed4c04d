// The checked-in grammar must be what the generator makes from the current keyword database.
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { test } from "node:test";

import { GRAMMAR_PATH, generateGrammar, readKeywords, renderGrammar } from "../../scripts/generate-grammar.mjs";

const keywords = readKeywords(); // v4's and MintMT's

test("syntaxes/mint.tmLanguage.json is up to date with the keyword database (npm run generate)", () => {
  assert.equal(readFileSync(GRAMMAR_PATH, "utf8"), renderGrammar(keywords));
});

test("every keyword and word abbreviation of the database, v4's and MintMT's, is highlighted", () => {
  const grammar = generateGrammar(keywords);
  const rules = [...grammar.repository.keyword.patterns, ...grammar.repository.channel.patterns];
  const highlighted = (word) => rules.some((rule) => new RegExp(rule.match.replace("(?i)", ""), "i").test(word));
  const words = keywords
    .filter((keyword) => keyword.kind !== "event")
    .flatMap((keyword) => [keyword.name, ...keyword.abbreviations])
    .filter((spelling) => /^[A-Za-z]\w*$/.test(spelling));
  assert.ok(words.length > 400);
  assert.deepEqual(words.filter((word) => !highlighted(word)), []);
});

test("the generator rejects a keyword kind it has no colour for", () => {
  const unknown = [{ name: "FOO", abbreviations: [], kind: "gadget", channel_suffix: false }];
  assert.throws(() => generateGrammar(unknown), /unknown kind 'gadget'/);
});
