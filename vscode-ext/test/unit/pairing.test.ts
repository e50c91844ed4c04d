import assert from "node:assert/strict";
import { test } from "node:test";

import { isPairedConfig } from "../../src/pairing";

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
