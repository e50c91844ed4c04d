import assert from "node:assert/strict";
import { test } from "node:test";

import { readSettings, serverSettings, type Inspection, type Section } from "../../src/settings";

const section = (values: Record<string, unknown>): Section => ({ get: (key) => values[key] });

test("an empty configuration gives the defaults", () => {
  assert.deepEqual(readSettings(section({})), {
    serverPath: "",
    pythonPath: "",
    controller: "nextmove-pci",
    dialect: "v4",
    pairConfigFiles: true,
    debounceMs: 150,
  });
});

test("valid values are kept, paths trimmed", () => {
  const settings = readSettings(
    section({ serverPath: " /opt/mint-lsp ", pythonPath: "python3", controller: "mintdrive", dialect: "v3", pairConfigFiles: false }),
  );
  assert.equal(settings.serverPath, "/opt/mint-lsp");
  assert.equal(settings.pythonPath, "python3");
  assert.equal(settings.controller, "mintdrive");
  assert.equal(settings.dialect, "v3");
  assert.equal(settings.pairConfigFiles, false);
});

test("values of the wrong type or outside the enums fall back to the defaults", () => {
  const settings = readSettings(section({ serverPath: 3, controller: "nextmove-xyz", dialect: "V4", pairConfigFiles: "no" }));
  assert.equal(settings.serverPath, "");
  assert.equal(settings.controller, "nextmove-pci");
  assert.equal(settings.dialect, "v4");
  assert.equal(settings.pairConfigFiles, true);
});

test("the server's own settings are read, bad ones fall back to its defaults", () => {
  assert.equal(readSettings(section({ debounceMs: 400 })).debounceMs, 400);
  for (const debounceMs of [-1, 1.5, "200", null]) {
    assert.equal(readSettings(section({ debounceMs })).debounceMs, 150, String(debounceMs));
  }
});

/** A section whose settings are set where `scopes` says: key -> where -> value. */
const inspectable = (scopes: Record<string, Inspection>) => ({ inspect: (key: string) => scopes[key] });

test("the server is told only the settings the user set, null for the others, and no paths", () => {
  const sent = serverSettings(
    inspectable({
      controller: { globalValue: "servonode51" },
      dialect: { globalValue: "v3", workspaceValue: "auto" },
      select: { workspaceValue: ["E"], workspaceFolderValue: ["W1", "I201"] },
      serverPath: { globalValue: "/x" },
      // What VS Code reports for a setting set nowhere: the default alone, which is not sent.
      debounceMs: { defaultValue: 150 } as Inspection,
    }),
  );
  assert.deepEqual(sent, {
    controller: "servonode51",
    dialect: "auto",
    configPairing: null,
    debounceMs: null,
    select: ["W1", "I201"],
    ignore: null,
    rulesUrl: null,
  });
});

test("a value set to what happens to be the default is still the user's, and sent", () => {
  const sent = serverSettings(inspectable({ dialect: { globalValue: "v4" }, ignore: { workspaceValue: [] } }));
  assert.equal(sent.dialect, "v4");
  assert.deepEqual(sent.ignore, []);
});

test("mint.dialect may be mintmt or auto", () => {
  assert.equal(readSettings(section({ dialect: "mintmt" })).dialect, "mintmt");
  assert.equal(readSettings(section({ dialect: "auto" })).dialect, "auto");
});
