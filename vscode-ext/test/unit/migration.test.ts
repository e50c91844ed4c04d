// "Mint: Migrate file to v4" and "Mint: Replace v3 keywords" against the source actions the language
// server offers: the whole migration only where the server offers it (a v3 file), applied as the
// server's edit, whose change annotation needs confirmation (VS Code previews it); in a v4 file the
// user is asked before the v3 keywords alone are replaced.
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import * as path from "node:path";
import { test } from "node:test";

import { MIGRATE_KIND, planMigration, planReplacement, REPLACE_KIND } from "../../src/migration";

interface Action {
  readonly title: string;
  readonly kind: string;
}
const kindOf = (action: Action): string => action.kind;
const MIGRATE = { title: "Migrate this file to Mint v4", kind: MIGRATE_KIND };
const REPLACE = { title: "Replace v3 keywords", kind: REPLACE_KIND };
const EXPAND = { title: "Expand SP to SPEED", kind: "refactor.rewrite" };

test("a v3 file is migrated whole, through the server's edit that needs confirmation", () => {
  assert.deepEqual(planMigration([REPLACE, MIGRATE], kindOf, "old.mnt"), { step: "apply", action: MIGRATE });
});

test("a v4 file is never migrated whole: the user is asked before its v3 keywords alone are replaced", () => {
  const plan = planMigration([EXPAND, REPLACE], kindOf, "axes.mnt");
  assert.equal(plan.step, "ask");
  assert.ok(plan.step === "ask");
  assert.equal(plan.action, REPLACE);
  assert.match(plan.question, /^axes\.mnt reads as Mint v4/);
  assert.equal(plan.answer, "Replace v3 keywords");
});

test("a file without v3 words is left alone, and the user told why", () => {
  assert.deepEqual(planMigration([EXPAND], kindOf, "new.mnt"), {
    step: "none",
    message: "new.mnt has no Mint v3 keyword to migrate.",
  });
});

test("Replace v3 keywords applies the renames alone, even where the whole migration is offered", () => {
  assert.deepEqual(planReplacement([MIGRATE, REPLACE], kindOf, "old.mnt"), { step: "apply", action: REPLACE });
  assert.deepEqual(planReplacement([MIGRATE], kindOf, "old.mnt"), {
    step: "none",
    message: "old.mnt has no Mint v3 keyword to replace.",
  });
});

test("the server offers these kinds, and its whole migration needs confirmation", () => {
  const server = readFileSync(path.resolve(__dirname, "..", "..", "..", "..", "lsp", "features", "migration.py"), "utf8");
  assert.equal(MIGRATE_KIND, "source.migrateToV4");
  assert.equal(REPLACE_KIND, "source.replaceV3Keywords");
  assert.match(server, /MIGRATE_KIND = f"\{types\.CodeActionKind\.Source\.value\}\.migrateToV4"/);
  assert.match(server, /REPLACE_KIND = f"\{types\.CodeActionKind\.Source\.value\}\.replaceV3Keywords"/);
  assert.match(server, /needs_confirmation=True/);
});
