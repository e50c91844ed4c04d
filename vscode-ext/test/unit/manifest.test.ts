// package.json against the language server it drives: the settings the server reads, their
// types, enums and defaults, and how the commands are offered.
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import * as path from "node:path";
import { test } from "node:test";

import { CONTROLLERS, DIALECT_CHOICES, DIALECTS, SERVER_READS } from "../../src/settings";

const EXTENSION = path.resolve(__dirname, "..", "..", "..");
const CHECKOUT = path.resolve(EXTENSION, "..");

interface Property {
  type: string | string[];
  items?: { type: string };
  default: unknown;
  enum?: string[];
  pattern?: string;
  minimum?: number;
}
interface MenuItem {
  command: string;
  when?: string;
  group?: string;
}
interface Manifest {
  activationEvents: string[];
  contributes: {
    languages: { id: string; extensions?: string[]; filenamePatterns?: string[]; filenames?: string[] }[];
    commands: { command: string; title: string; category: string; icon?: string }[];
    menus: Record<string, MenuItem[]>;
    configuration: { properties: Record<string, Property> };
  };
}

const manifest = JSON.parse(readFileSync(path.join(EXTENSION, "package.json"), "utf8")) as Manifest;
const properties = manifest.contributes.configuration.properties;
const property = (name: string): Property => {
  const found = properties[name];
  assert.ok(found, `${name} is contributed`);
  return found;
};

/** The string values of a Python StrEnum class in the checkout. */
function pythonEnum(file: string, name: string): string[] {
  const source = readFileSync(path.join(CHECKOUT, file), "utf8");
  const body = source.split(new RegExp(`^class ${name}\\(StrEnum\\):`, "m"))[1]?.split(/^\S/m)[0] ?? "";
  return [...body.matchAll(/^\s+[A-Z0-9_]+ = "([^"]+)"/gm)].map((match) => match[1] ?? "");
}

test("the language is mint-motion, for .mnt files only: .cfg is claimed by content, not globally", () => {
  const [language, ...others] = manifest.contributes.languages;
  assert.equal(others.length, 0);
  assert.equal(language?.id, "mint-motion");
  assert.deepEqual(language?.extensions, [".mnt"]);
  assert.equal(language?.filenamePatterns, undefined);
  assert.equal(language?.filenames, undefined);
});

test("mint.controller and mint.dialect offer exactly what the server and the tools accept", () => {
  const controllers = pythonEnum("mintlang/keyworddb/model.py", "Controller");
  const dialects = pythonEnum("mintlang/dialect.py", "Dialect");
  assert.deepEqual([...controllers].sort(), [...CONTROLLERS].sort());
  assert.deepEqual([...dialects].sort(), [...DIALECTS].sort());
  assert.deepEqual(property("mint.controller").enum, [...CONTROLLERS]);
  assert.deepEqual(property("mint.dialect").enum, [...DIALECTS, "auto"]);
  assert.deepEqual(property("mint.dialect").enum, [...DIALECT_CHOICES]);
  const workspace = readFileSync(path.join(CHECKOUT, "lsp", "workspace.py"), "utf8");
  assert.equal(/^AUTO = "(\w+)"/m.exec(workspace)?.[1], "auto", "the server's word for detection");
});

test("every setting the server reads is contributed, with its type and the server's default", () => {
  const workspace = readFileSync(path.join(CHECKOUT, "lsp", "workspace.py"), "utf8");
  const read = [...workspace.matchAll(/\("(\w+)", "\w+", \w+\)/g)].map((match) => match[1]);
  assert.deepEqual(read, [...SERVER_READS], "Settings.from_options reads these, and the extension sends them");
  assert.equal(property("mint.controller").type, "string");
  assert.equal(property("mint.controller").default, "nextmove-pci");
  assert.equal(property("mint.dialect").type, "string");
  assert.equal(property("mint.dialect").default, "v4");
  assert.equal(property("mint.configPairing").type, "string");
  assert.match(workspace, /config_pairing: str = DEFAULT_PATTERN/);
  const pairing = readFileSync(path.join(CHECKOUT, "mintlang", "pairing.py"), "utf8");
  assert.equal(property("mint.configPairing").default, /^DEFAULT_PATTERN = "([^"]*)"/m.exec(pairing)?.[1]);
  assert.equal(property("mint.debounceMs").type, "integer");
  assert.equal(property("mint.debounceMs").minimum, 0);
  assert.equal(property("mint.debounceMs").default, Number(/debounce_ms: int = (\d+)/.exec(workspace)?.[1]));
  // None in the server: the errors and warnings, not the hints; a list of codes or prefixes otherwise.
  assert.match(workspace, /select: tuple\[str, \.\.\.\] \| None = None/);
  assert.deepEqual(property("mint.select").type, ["array", "null"]);
  assert.deepEqual(property("mint.select").items, { type: "string" });
  assert.equal(property("mint.select").default, null);
  assert.match(workspace, /ignore: tuple\[str, \.\.\.\] = \(\)/);
  assert.equal(property("mint.ignore").type, "array");
  assert.deepEqual(property("mint.ignore").items, { type: "string" });
  assert.deepEqual(property("mint.ignore").default, []);
  assert.match(workspace, /rules_url: str \| None = None/);
  assert.deepEqual(property("mint.rulesUrl").type, ["string", "null"]);
  assert.equal(property("mint.rulesUrl").default, null);
  for (const name of ["mint.serverPath", "mint.pythonPath"]) {
    assert.equal(property(name).type, "string");
    assert.equal(property(name).default, "");
  }
  assert.equal(property("mint.pairConfigFiles").type, "boolean");
});

test("mint.configPairing accepts a file name with <name> in the program's folder, or nothing", () => {
  const pattern = new RegExp(property("mint.configPairing").pattern ?? "");
  for (const good of ["<name>.cfg", "setup_<name>.cfg", "<name>.ini", ""]) {
    assert.match(good, pattern);
  }
  for (const bad of ["config.cfg", "cfg/<name>.cfg", "..\\<name>.cfg"]) {
    assert.doesNotMatch(bad, pattern);
  }
});

test("the commands are titled 'Mint: …' and offered only where they apply", () => {
  const titles = Object.fromEntries(manifest.contributes.commands.map((c) => [c.command, `${c.category}: ${c.title}`]));
  assert.deepEqual(titles, {
    "mint.migrateFile": "Mint: Migrate file to v4",
    "mint.replaceV3Keywords": "Mint: Replace v3 keywords",
    "mint.runInSimulator": "Mint: Run in simulator",
    "mint.debugInSimulator": "Mint: Debug in simulator",
    "mint.runFor": "Mint: Run on for a simulated time…",
  });
  const menus = manifest.contributes.menus;
  const when = (menu: string, command: string) => menus[menu]?.find((item) => item.command === command)?.when ?? "";
  // By language rather than a case-sensitive resourceExtname == .mnt: DOS-era programs are often CONVEYOR.MNT.
  for (const command of ["mint.migrateFile", "mint.replaceV3Keywords"]) {
    assert.equal(when("explorer/context", command), "resourceLangId == mint-motion", command);
    assert.equal(when("commandPalette", command), "editorLangId == mint-motion", command);
  }
  // A configuration file opened as Mint is not a program to run.
  for (const [menu, key] of [["explorer/context", "resourceLangId"], ["editor/title/run", "resourceLangId"], ["commandPalette", "editorLangId"]]) {
    assert.equal(when(menu ?? "", "mint.runInSimulator"), `${key} == mint-motion && resourceExtname =~ /^\\.mnt$/i`, menu);
    // "Debug in simulator" sits beside it, wherever it is offered.
    assert.equal(when(menu ?? "", "mint.debugInSimulator"), when(menu ?? "", "mint.runInSimulator"), menu);
  }
  const extension = /=~ \/(.*)\/i$/.exec(when("explorer/context", "mint.runInSimulator"))?.[1] ?? "";
  assert.match(".MNT", new RegExp(extension, "i"));
  assert.doesNotMatch(".cfg", new RegExp(extension, "i"));
});

test("the extension activates for Mint files, for workspaces that hold them, and to start its debugger", () => {
  // workspaceContains globs are case-sensitive off Windows: a folder of DOS-era CONVEYOR.MNT programs
  // must start the extension (its Testing view) too, as the Testing view's watcher already sees them.
  assert.deepEqual(manifest.activationEvents, ["onLanguage:mint-motion", "workspaceContains:**/*.{mnt,MNT}", "onDebugResolve:mint"]);
  const controller = readFileSync(path.join(EXTENSION, "src", "testing", "controller.ts"), "utf8");
  assert.match(controller, /createFileSystemWatcher\("\*\*\/\*\.\{mnt,MNT,toml\}"\)/);
});
