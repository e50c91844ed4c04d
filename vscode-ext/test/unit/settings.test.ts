import assert from "node:assert/strict";
import { test } from "node:test";

import { initializationOptions, readSettings, type Section } from "../../src/settings";

const section = (values: Record<string, unknown>): Section => ({ get: (key) => values[key] });

test("an empty configuration gives the defaults", () => {
  assert.deepEqual(readSettings(section({})), {
    serverPath: "",
    pythonPath: "",
    controller: "nextmove-pci",
    dialect: "v4",
    pairConfigFiles: true,
    configPairing: "<name>.cfg",
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
  const settings = readSettings(section({ configPairing: " setup_<name>.cfg ", debounceMs: 400 }));
  assert.equal(settings.configPairing, "setup_<name>.cfg");
  assert.equal(settings.debounceMs, 400);
  // An empty pattern is kept: the server then pairs no configuration file.
  assert.equal(readSettings(section({ configPairing: "" })).configPairing, "");
  for (const debounceMs of [-1, 1.5, "200", null]) {
    assert.equal(readSettings(section({ debounceMs })).debounceMs, 150, String(debounceMs));
  }
});

test("the server is initialised with every setting it reads, and no paths", () => {
  const settings = readSettings(
    section({ controller: "servonode51", dialect: "v3", configPairing: "<name>.ini", debounceMs: 0, serverPath: "/x" }),
  );
  assert.deepEqual(initializationOptions(settings), {
    controller: "servonode51",
    dialect: "v3",
    configPairing: "<name>.ini",
    debounceMs: 0,
  });
});
