// The checked-in grammar must be what the generator makes from the current keyword database.
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import { test } from "node:test";

import { GRAMMAR_PATH, generateGrammar, readConstants, readKeywords, renderGrammar } from "../../scripts/generate-grammar.mjs";

const keywords = readKeywords(); // v4's and MintMT's
const constants = readConstants(); // likewise

test("syntaxes/mint.tmLanguage.json is up to date with the keyword database (npm run generate)", () => {
  assert.equal(readFileSync(GRAMMAR_PATH, "utf8"), renderGrammar(keywords, constants));
});

test("every keyword and word abbreviation of the database, v4's and MintMT's, is highlighted", () => {
  const grammar = generateGrammar(keywords, constants);
  const rules = [...grammar.repository.keyword.patterns, ...grammar.repository.channel.patterns];
  const highlighted = (word) => rules.some((rule) => new RegExp(rule.match.replace("(?i)", ""), "i").test(word));
  const words = keywords
    .filter((keyword) => keyword.kind !== "event")
    .flatMap((keyword) => [keyword.name, ...keyword.abbreviations])
    .filter((spelling) => /^[A-Za-z]\w*$/.test(spelling));
  assert.ok(words.length > 400);
  assert.deepEqual(words.filter((word) => !highlighted(word)), []);
});

test("the predefined constants of the database and NULL are constants; other names beginning with '_' are not", () => {
  const rule = new RegExp(generateGrammar(keywords, constants).repository.constant.match.replace("(?i)", ""), "i");
  const names = constants.map((constant) => constant.name);
  assert.ok(names.length > 200);
  assert.deepEqual(names.filter((name) => !rule.test(name) || !rule.test(name.toLowerCase())), []);
  assert.ok(rule.test("NULL"), "CAMTABLE's no-table argument, 000:7958");
  // A user variable may begin with an underscore (000:884-893).
  assert.ok(!rule.test("_myVar2"));
});

test("the generator rejects a numbered event whose numbers it does not know", () => {
  const unknown = [{ name: "#GADGET", abbreviations: [], kind: "event", channel_suffix: true }];
  assert.throws(() => generateGrammar(unknown, []), /no numbers known for the event #GADGET/);
});

test("the generator rejects a keyword kind it has no colour for", () => {
  const unknown = [{ name: "FOO", abbreviations: [], kind: "gadget", channel_suffix: false }];
  assert.throws(() => generateGrammar(unknown, []), /unknown kind 'gadget'/);
});
