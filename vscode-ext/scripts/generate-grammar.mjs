// Writes syntaxes/mint.tmLanguage.json from the keyword database, so the highlighter knows
// exactly the words (keywords and predefined constants) the checker knows. Run by `npm run generate`;
// the output is checked in and test/unit/grammar-up-to-date.test.mjs fails when it falls behind the database.
// One grammar serves Mint v4 and MintMT (mintlang/MINTMT.md): MintMT's keywords, its ' comments,
// its block words (Event NAME, Startup, End Loop/If/Event/Startup) are added to v4's.
import { readFileSync, writeFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const DATA = join(here, "..", "..", "mintlang", "keyworddb", "data");
export const KEYWORDS_PATHS = [join(DATA, "keywords_v4.json"), join(DATA, "keywords_mintmt.json")];
export const CONSTANTS_PATHS = [join(DATA, "constants_v4.json"), join(DATA, "constants_mintmt.json")];
export const GRAMMAR_PATH = join(here, "..", "syntaxes", "mint.tmLanguage.json");

// Block structure and jumps: coloured as control flow whatever kind the database gives them.
const CONTROL = [
  "IF", "THEN", "DO", "ELSE", "ENDIF", "FOR", "TO", "STEP", "NEXT", "REPEAT", "UNTIL", "WHILE",
  "ENDW", "LOOP", "ENDL", "EXIT", "GOSUB", "GOTO", "RETURN", "END", "PAUSE", "DIM", "DEFINE",
];

// Scope per database kind. Operators (AND, OR, XOR, NOT, MOD) are words here; their symbol
// abbreviations (& | ! %) are matched by the operator rule.
const SCOPE_BY_KIND = {
  operator: "keyword.operator.word.mint-motion",
  function: "support.function.mint-motion",
  statement: "keyword.other.statement.mint-motion",
  command: "keyword.other.command.mint-motion",
  command_line: "keyword.other.command-line.mint-motion",
  parameter: "keyword.other.parameter.mint-motion",
};
// When one spelling belongs to keywords of different kinds (an abbreviation shared by two
// keywords), the first kind in this list decides its colour.
const KIND_PRIORITY = ["operator", "function", "statement", "command", "command_line", "parameter"];

const WORD = /^[A-Za-z][A-Za-z0-9_]*$/;

// The rest of a line holding one statement: blanks, then a comment (REM or MintMT's ') or nothing.
const LINE_END = "[ \\t]*(?:$|['\u2018\u2019]|[Rr][Ee][Mm]\\b)";

// A quote, one character and a quote is v4's character constant 'A'; any other quote starts a
// MintMT comment (in MintMT the quote always does, but 'A' there is a comment either way).
const CHARACTER = "['\u2018\u2019][^'\u2018\u2019\\r\\n]['\u2018\u2019]";

const escape = (text) => text.replace(/[.*+?^${}()|[\]\\]/g, "\\$&");

/** Longest first, so no alternative can shadow a longer word that starts with it. */
const alternation = (words) =>
  [...new Set(words)].sort((a, b) => b.length - a.length || (a < b ? -1 : a > b ? 1 : 0)).join("|");

const wordRule = (words, name) => ({ match: `(?i)\\b(?:${alternation(words)})\\b`, name });

// The numbers of the numbered event handlers (000:1889-1900): #FASTIN alone or #FASTINx, #INx, and only
// #COMMS1 .. #COMMS5; written as the guide writes them, without a leading zero (#IN01 is a plain label: a
// number led by a zero is binary, 000:744-760).
const NUMBER = "(?:0|[1-9][0-9]*)";
const EVENT_NUMBERS = { "#FASTIN": `${NUMBER}?`, "#IN": NUMBER, "#COMMS": "[1-5]" };

// CAMTABLE's "no table" argument (000:7958): a reserved word the database lists neither as keyword nor constant.
const RESERVED_CONSTANTS = ["NULL"];

/**
 * The grammar as a plain object, from the parsed keyword database: its keywords and its predefined constants
 * (only those: a user's variable may begin with '_' as well, DIM _myVar2, 000:884-893).
 */
export function generateGrammar(keywords, constants) {
  const control = new Set(CONTROL);
  const spellings = new Map(); // upper-case spelling -> kind
  const channelled = new Map(); // kind -> keywords written with a channel number glued on: IN3, OUT12
  const events = []; // event handler labels without their '#': IN, TIMER
  const symbols = []; // abbreviations that are not words, of keywords that are not operators: ?
  for (const keyword of keywords) {
    if (keyword.kind === "event") {
      const numbers = keyword.channel_suffix ? EVENT_NUMBERS[keyword.name] : "";
      if (numbers === undefined) throw new Error(`keyword database: no numbers known for the event ${keyword.name}`);
      events.push(escape(keyword.name.slice(1)) + numbers);
      continue;
    }
    for (const spelling of [keyword.name, ...keyword.abbreviations]) {
      if (!WORD.test(spelling)) {
        // Names such as ':' and '~' are punctuation and operators, matched by those rules.
        if (spelling !== keyword.name && keyword.kind !== "operator") symbols.push(escape(spelling));
        continue;
      }
      const upper = spelling.toUpperCase();
      const known = spellings.get(upper);
      if (known === undefined || KIND_PRIORITY.indexOf(keyword.kind) < KIND_PRIORITY.indexOf(known)) {
        spellings.set(upper, keyword.kind);
      }
    }
    if (keyword.channel_suffix && WORD.test(keyword.name)) {
      channelled.set(keyword.kind, [...(channelled.get(keyword.kind) ?? []), keyword.name]);
    }
  }
  for (const word of CONTROL) spellings.delete(word);

  const byKind = new Map(KIND_PRIORITY.map((kind) => [kind, []]));
  for (const [spelling, kind] of spellings) {
    if (!byKind.has(kind)) throw new Error(`keyword database: unknown kind '${kind}' for ${spelling}`);
    byKind.get(kind).push(spelling);
  }
  const keywordRules = [
    // MintMT's closers are two words, one token: End Loop, End If, End Event, End Startup.
    { match: "(?i)\\bEnd[ \\t]+(?:Loop|If|Event|Startup)\\b", name: "keyword.control.mint-motion" },
    {
      // MintMT's event handler: Event NAME alone on its line (a v4 program may call a variable event).
      match: `(?i)^[ \\t]*(Event)[ \\t]+([A-Za-z_][A-Za-z0-9_]*)(?=${LINE_END})`,
      captures: {
        1: { name: "keyword.control.mint-motion" },
        2: { name: "entity.name.function.event.mint-motion" },
      },
    },
    {
      // MintMT's power-up block: Startup alone on its line.
      match: `(?i)^[ \\t]*(Startup)(?=${LINE_END})`,
      captures: { 1: { name: "keyword.control.mint-motion" } },
    },
    {
      // The word after GOSUB and GOTO names a label, even when it spells a keyword (GOSUB home), and so does
      // a whole number: a label is any run of letters and digits (#10, GOSUB 10; 000:1843-1844).
      match: "(?i)\\b(GOSUB|GOTO)[ \\t]+([A-Za-z_][A-Za-z0-9_]*|[0-9]+\\b(?!\\.))",
      captures: {
        1: { name: "keyword.control.mint-motion" },
        2: { name: "entity.name.function.label.mint-motion" },
      },
    },
    wordRule([...control], "keyword.control.mint-motion"),
    ...KIND_PRIORITY.filter((kind) => byKind.get(kind).length > 0).map((kind) =>
      wordRule(byKind.get(kind), SCOPE_BY_KIND[kind]),
    ),
  ];

  return {
    $schema: "https://raw.githubusercontent.com/martinring/tmlanguage/master/tmlanguage.json",
    name: "Mint",
    scopeName: "source.mint-motion",
    comment:
      "Generated by scripts/generate-grammar.mjs from mintlang/keyworddb/data: keywords and constants of v4 and MintMT. Do not edit.",
    patterns: [
      { include: "#comment" },
      { include: "#label" },
      { include: "#string" },
      { include: "#character" },
      { include: "#constant" },
      { include: "#channel" },
      { include: "#keyword" },
      { include: "#number" },
      { include: "#operator" },
      { include: "#punctuation" },
    ],
    repository: {
      comment: {
        patterns: [
          {
            // REM only as a whole word: REMOTEIN is a keyword, REMARK a name.
            match: "(?i)\\b(REM)\\b.*$",
            name: "comment.line.rem.mint-motion",
            captures: { 1: { name: "punctuation.definition.comment.mint-motion" } },
          },
          {
            // MintMT's ' comment, at a line start or after code; not where a character constant starts.
            match: `(?!${CHARACTER})(['\u2018\u2019]).*$`,
            name: "comment.line.single-quote.mint-motion",
            captures: { 1: { name: "punctuation.definition.comment.mint-motion" } },
          },
        ],
      },
      label: {
        // '#name' is a label only as the first word of a line; elsewhere '#' selects a terminal.
        patterns: [
          {
            match: `(?i)^[ \\t]*(#)(${alternation(events)})\\b`,
            captures: {
              1: { name: "punctuation.definition.label.mint-motion" },
              2: { name: "entity.name.function.event.mint-motion" },
            },
          },
          {
            match: "^[ \\t]*(#)([A-Za-z0-9_]+)",
            captures: {
              1: { name: "punctuation.definition.label.mint-motion" },
              2: { name: "entity.name.function.label.mint-motion" },
            },
          },
        ],
      },
      string: {
        // Word processors turn "..." into typographic quotes; the lexer accepts either at each end.
        begin: "[\"\u201c\u201d\u201e\u201f\u2033]",
        end: "[\"\u201c\u201d\u201e\u201f\u2033]|$",
        name: "string.quoted.double.mint-motion",
        beginCaptures: { 0: { name: "punctuation.definition.string.begin.mint-motion" } },
        endCaptures: { 0: { name: "punctuation.definition.string.end.mint-motion" } },
      },
      character: {
        match: CHARACTER,
        name: "constant.character.mint-motion",
      },
      constant: wordRule(
        [...constants.map((constant) => constant.name.toUpperCase()), ...RESERVED_CONSTANTS],
        "constant.language.mint-motion",
      ),
      channel: {
        patterns: [...channelled].map(([kind, names]) => ({
          match: `(?i)\\b(${alternation(names)})([0-9]+)\\b`,
          captures: {
            1: { name: SCOPE_BY_KIND[kind] },
            2: { name: "constant.numeric.channel.mint-motion" },
          },
        })),
      },
      keyword: {
        patterns: [
          ...keywordRules,
          ...(symbols.length > 0 ? [{ match: alternation(symbols), name: "keyword.other.statement.mint-motion" }] : []),
        ],
      },
      number: {
        patterns: [
          { match: "\\b0[xX][0-9A-Fa-f_]+\\b", name: "constant.numeric.hex.mint-motion" },
          // A leading zero makes a whole number binary: 011011, 0110_1001. With a fraction it is a
          // decimal (01.5, 05.25), as the lexer reads it (mintlang/syntax/lexer.py, _number_issue).
          { match: "\\b0[01_]+\\b(?!\\.)", name: "constant.numeric.binary.mint-motion" },
          {
            // 05, 0xZZ, and digits run into letters or '_' (12abc, 1_000): one bad number to the lexer.
            match: "\\b(?:0[0-9A-Za-z_]+\\b(?!\\.)|[0-9]+[A-Za-z_][0-9A-Za-z_]*(?:\\.[0-9]*)?)",
            name: "invalid.illegal.numeric.mint-motion",
          },
          {
            // After a keyword, '.n' is the dot parameter (SPEED.1), not the number .n.
            match: "(?<=[A-Za-z0-9_\\]])(\\.)([0-9]+)",
            captures: {
              1: { name: "punctuation.accessor.mint-motion" },
              2: { name: "constant.numeric.decimal.mint-motion" },
            },
          },
          { match: "(?:\\b[0-9]+(?:\\.[0-9]*)?|\\.[0-9]+)", name: "constant.numeric.decimal.mint-motion" },
        ],
      },
      operator: {
        patterns: [
          { match: "<>|<=|>=|[<>=]", name: "keyword.operator.comparison.mint-motion" },
          { match: "[-+*/%^]", name: "keyword.operator.arithmetic.mint-motion" },
          { match: "[&|!~]", name: "keyword.operator.logical.mint-motion" },
          { match: "#", name: "keyword.operator.terminal.mint-motion" },
        ],
      },
      punctuation: {
        patterns: [
          { match: ":", name: "punctuation.separator.statement.mint-motion" },
          { match: "[,;]", name: "punctuation.separator.mint-motion" },
          { match: "\\.", name: "punctuation.accessor.mint-motion" },
          { match: "[()]", name: "punctuation.parenthesis.mint-motion" },
          { match: "[\\[\\]]", name: "punctuation.brackets.mint-motion" },
        ],
      },
    },
  };
}

const readAll = (paths) => paths.flatMap((path) => JSON.parse(readFileSync(path, "utf8")));

/** The keywords of every dialect the grammar colours: v4's, then MintMT's own. */
export const readKeywords = () => readAll(KEYWORDS_PATHS);

/** The predefined constants of every dialect the grammar colours: v4's, then MintMT's own. */
export const readConstants = () => readAll(CONSTANTS_PATHS);

/** The grammar file's exact text, as written to disk. */
export function renderGrammar(keywords, constants) {
  return JSON.stringify(generateGrammar(keywords, constants), null, 2) + "\n";
}

if (process.argv[1] !== undefined && import.meta.url === pathToFileURL(process.argv[1]).href) {
  writeFileSync(GRAMMAR_PATH, renderGrammar(readKeywords(), readConstants()));
  console.log(`wrote ${GRAMMAR_PATH}`);
}
