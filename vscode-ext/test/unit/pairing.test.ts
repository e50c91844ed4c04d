import assert from "node:assert/strict";
import { test } from "node:test";

import { configurationOf, isPairedConfig, programOf } from "../../src/pairing";

const folder = (names: readonly string[]) => (dir: string) => {
  assert.equal(dir, "/project");
  return names;
};

test("a .cfg beside a .mnt of the same name is Mint", () => {
  assert.equal(isPairedConfig("/project/conveyor.cfg", folder(["conveyor.mnt", "conveyor.cfg"])), true);
});

test("names and extensions compare without case", () => {
  assert.equal(isPairedConfig("/project/CONVEYOR.CFG", folder(["Conveyor.MNT"])), true);
});

test("a .cfg without its program is left alone", () => {
  assert.equal(isPairedConfig("/project/conveyor.cfg", folder(["other.mnt", "conveyor.cfg", "conveyor.mnt.bak"])), false);
});

test("only .cfg files are paired, and the folder is not read for others", () => {
  const unread = () => assert.fail("the folder must not be listed");
  assert.equal(isPairedConfig("/project/conveyor.ini", unread), false);
  assert.equal(isPairedConfig("/project/conveyor.mnt", unread), false);
  assert.equal(isPairedConfig("/project/cfg", unread), false);
});

test("mint.configPairing decides which files are configurations, as in the server", () => {
  const names = folder(["conveyor.mnt", "setup_conveyor.cfg", "conveyor.cfg", "conveyor.ini"]);
  assert.equal(isPairedConfig("/project/setup_conveyor.cfg", names, "setup_<name>.cfg"), true);
  assert.equal(isPairedConfig("/project/conveyor.cfg", names, "setup_<name>.cfg"), false);
  assert.equal(isPairedConfig("/project/conveyor.ini", names, "<name>.ini"), true);
  // The prefix compares with case, the suffix without (lsp/workspace.py, partner()).
  assert.equal(isPairedConfig("/project/SETUP_conveyor.cfg", names, "setup_<name>.cfg"), false);
  assert.equal(isPairedConfig("/project/setup_conveyor.CFG", names, "setup_<name>.cfg"), true);
});

test("a pattern without <name> or without a suffix pairs nothing, and a program is never a configuration", () => {
  const unread = () => assert.fail("the folder must not be listed");
  assert.equal(isPairedConfig("/project/conveyor.cfg", unread, ""), false);
  assert.equal(isPairedConfig("/project/conveyor.cfg", unread, "config.cfg"), false);
  assert.equal(isPairedConfig("/project/conveyor", unread, "<name>"), false);
  assert.equal(isPairedConfig("/project/a.mnt", unread, "<name>.mnt"), false);
});

test("a program's configuration file is the name the pattern gives, as it is listed, when it exists", () => {
  const names = folder(["conveyor.mnt", "conveyor.cfg", "setup_conveyor.cfg", "OTHER.MNT", "other.CFG"]);
  assert.equal(configurationOf("/project/conveyor.mnt", names), "/project/conveyor.cfg");
  assert.equal(configurationOf("/project/conveyor.mnt", names, "setup_<name>.cfg"), "/project/setup_conveyor.cfg");
  // Whatever the case of the names, as in the server (lsp/workspace.py, _sibling()).
  assert.equal(configurationOf("/project/OTHER.MNT", names), "/project/other.CFG");
  assert.equal(configurationOf("/project/missing.mnt", names), undefined);
  const unread = () => assert.fail("the folder must not be listed");
  assert.equal(configurationOf("/project/conveyor.mnt", unread, ""), undefined);
  assert.equal(configurationOf("/project/conveyor.cfg", unread), undefined);
});

test("the exact name wins over one differing only in case", () => {
  const names = folder(["APP.CFG", "app.cfg", "app.mnt", "APP.mnt"]);
  assert.equal(configurationOf("/project/app.mnt", names), "/project/app.cfg");
  assert.equal(programOf("/project/APP.CFG", names), "/project/APP.mnt");
});

test("a program is never its own configuration file, whatever the pattern says", () => {
  const names = folder(["conveyor.mnt", "conveyor_setup.mnt"]);
  assert.equal(configurationOf("/project/conveyor.mnt", names, "<name>.mnt"), undefined);
  assert.equal(configurationOf("/project/conveyor.mnt", names, "<name>_setup.MNT"), undefined);
});

test("a configuration file's program is found beside it, as it is listed", () => {
  const names = folder(["conveyor.mnt", "conveyor.cfg", "setup_conveyor.cfg", "Other.Mnt", "other.cfg", "lone.cfg"]);
  assert.equal(programOf("/project/conveyor.cfg", names), "/project/conveyor.mnt");
  assert.equal(programOf("/project/setup_conveyor.cfg", names, "setup_<name>.cfg"), "/project/conveyor.mnt");
  assert.equal(programOf("/project/other.cfg", names), "/project/Other.Mnt");
  assert.equal(programOf("/project/lone.cfg", names), undefined);
  const unread = () => assert.fail("the folder must not be listed");
  assert.equal(programOf("/project/conveyor.mnt", unread), undefined);
  assert.equal(programOf("/project/conveyor.cfg", unread, ""), undefined);
});
