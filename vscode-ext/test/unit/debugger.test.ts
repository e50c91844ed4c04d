// The debugger the extension contributes: the manifest against mint-dap's launch arguments, and the
// launch configurations the editor completes.
import assert from "node:assert/strict";
import { readFileSync } from "node:fs";
import * as path from "node:path";
import { test } from "node:test";

import { evaluatableAt } from "../../src/evaluatable";
import { completeLaunch, DEBUG_TYPE, launchConfiguration, launchFor, type Chosen } from "../../src/launch";
import type { ConfigurationChoice } from "../../src/pairing";
import { PYTHON_ARGUMENTS } from "../../src/resolve";

const EXTENSION = path.resolve(__dirname, "..", "..", "..");
const CHECKOUT = path.resolve(EXTENSION, "..");

interface Debugger {
  type: string;
  languages: string[];
  configurationAttributes: { launch: { required: string[]; properties: Record<string, { type: string }> } };
  initialConfigurations: Record<string, unknown>[];
  configurationSnippets: { label: string; body: Record<string, unknown> }[];
}
const manifest = JSON.parse(readFileSync(path.join(EXTENSION, "package.json"), "utf8")) as {
  contributes: { debuggers: Debugger[]; breakpoints: { language: string }[] };
};

const NONE: Chosen = { controller: undefined, dialect: undefined, configPairing: false };
/** The language server's pairing, as `configurationFor` gives it: `choice` for /work/robot/conveyor.mnt. */
const pairing = (choice: ConfigurationChoice | undefined) => async (program: string) => {
  assert.equal(program, "/work/robot/conveyor.mnt");
  return choice;
};
const unasked = async (): Promise<ConfigurationChoice | undefined> => assert.fail("a launch that names its configuration is not paired");

test("the extension contributes one debugger, for Mint programs, where breakpoints can be set", () => {
  const [debuggerEntry, ...others] = manifest.contributes.debuggers;
  assert.equal(others.length, 0);
  assert.equal(debuggerEntry?.type, DEBUG_TYPE);
  assert.deepEqual(debuggerEntry?.languages, ["mint-motion"]);
  assert.deepEqual(manifest.contributes.breakpoints, [{ language: "mint-motion" }]);
});

test("the launch attributes are exactly the arguments mint-dap reads", () => {
  const launch = readFileSync(path.join(CHECKOUT, "runtime", "debugger", "launch.py"), "utf8");
  const read = new Set([...launch.matchAll(/arguments\.get\("(\w+)"/g)].map((match) => match[1]));
  const attributes = manifest.contributes.debuggers[0]?.configurationAttributes.launch;
  assert.deepEqual(Object.keys(attributes?.properties ?? {}).sort(), [...read].sort());
  assert.deepEqual(attributes?.required, ["program"]);
});

test("the initial configuration and the snippets launch a program with the contributed type", () => {
  const entry = manifest.contributes.debuggers[0];
  const bodies = [...(entry?.initialConfigurations ?? []), ...(entry?.configurationSnippets ?? []).map((snippet) => snippet.body)];
  assert.ok(bodies.length >= 3);
  for (const body of bodies) {
    assert.equal(body["type"], DEBUG_TYPE);
    assert.equal(body["request"], "launch");
    assert.match(String(body["program"]), /file|\.mnt/);
  }
});

test("mint-dap starts from mint.pythonPath as a module", () => {
  assert.deepEqual(PYTHON_ARGUMENTS["mint-dap"], ["-m", "mintlang.runtime.debugger"]);
});

test("F5 with no launch.json debugs the program in the editor, stopped on entry, with the file the server pairs", async () => {
  const launch = async (choice: ConfigurationChoice | undefined) => {
    const completion = await completeLaunch({}, "/work/robot/conveyor.mnt", NONE, pairing(choice));
    assert.ok(completion.ok);
    return completion.launch;
  };
  const program = launchFor("/work/robot/conveyor.mnt");
  const config = "/work/robot/setup_conveyor.cfg";
  assert.deepEqual(await launch({ config }), { ...program, config });
  assert.deepEqual(await launch({ noConfig: true }), { ...program, noConfig: true });
  // No server to ask: mint-dap pairs the program by the project's settings itself.
  assert.deepEqual(await launch(undefined), program);
  const dap = readFileSync(path.join(CHECKOUT, "runtime", "debugger", "launch.py"), "utf8");
  assert.match(dap, /settings\.partner\(program\)/, "mint-dap pairs an unpaired program by its settings");
});

test("a launch.json entry keeps what it says and gains only the settings the user chose", async () => {
  const given = { type: "mint", request: "launch", name: "mine", program: "/work/robot/a.mnt", noConfig: true, dialect: "v3" };
  const chosen: Chosen = { controller: "euroservo", dialect: "mintmt", configPairing: true };
  const completion = await completeLaunch(given, undefined, chosen, unasked);
  assert.ok(completion.ok);
  assert.deepEqual(completion.launch, { ...given, controller: "euroservo" });
  const named = { type: "mint", request: "launch", name: "line", program: "/work/robot/a.mnt", config: "/work/robot/line.cfg" };
  assert.deepEqual(await completeLaunch(named, undefined, NONE, unasked), { ok: true, launch: named });
});

test("the configuration file a launch tells mint-dap of is saved before it starts; none named, mint-dap pairs it", () => {
  const program = launchFor("/work/robot/a.mnt");
  assert.deepEqual(launchConfiguration({ ...program, config: "/work/robot/line.cfg" }), { config: "/work/robot/line.cfg" });
  assert.deepEqual(launchConfiguration({ ...program, noConfig: true }), { noConfig: true });
  assert.equal(launchConfiguration(program), undefined);
});

test("with nothing to debug the completion says what to open", async () => {
  assert.equal((await completeLaunch({}, undefined, NONE, unasked)).ok, false);
  assert.equal((await completeLaunch({}, "/work/robot/notes.txt", NONE, unasked)).ok, false);
});

test("'Run on for a simulated time' is offered while a Mint debug session is stopped, and mint-dap serves its request", () => {
  const menus = (JSON.parse(readFileSync(path.join(EXTENSION, "package.json"), "utf8")) as {
    contributes: { menus: Record<string, { command: string; when?: string }[]> };
  }).contributes.menus;
  for (const menu of ["commandPalette", "debug/toolbar"]) {
    assert.equal(menus[menu]?.find((item) => item.command === "mint.runFor")?.when, "debugType == mint && debugState == stopped", menu);
  }
  const session = readFileSync(path.join(CHECKOUT, "runtime", "debugger", "session.py"), "utf8");
  assert.match(session, /"runFor": self\.run_for/);
});

test("hovering evaluates a name with its axis or element, not the bare name", () => {
  const line = "  MOVEA.0 = table(3) + POS.1 * gain";
  const hovered = (at: string) => {
    const found = evaluatableAt(line, line.indexOf(at));
    return found && line.slice(found[0], found[1]);
  };
  assert.equal(hovered("table"), "table(3)");
  assert.equal(hovered("POS"), "POS.1");
  assert.equal(hovered("gain"), "gain");
  assert.equal(hovered("MOVEA"), "MOVEA.0");
  assert.equal(evaluatableAt(line, line.indexOf("=")), undefined);
});

test("hovering takes a bracketed axis whole, and leaves an address it cannot take whole unevaluated", () => {
  // POS[0] is the guide's own way of reading an axis (000:15305); the bare POS would read the default axis
  const hovered = (line: string, at: string) => {
    const found = evaluatableAt(line, line.indexOf(at));
    return found && line.slice(found[0], found[1]);
  };
  assert.equal(hovered('PRINT "a = ",a," POS = ",POS[1]', "POS["), "POS[1]");
  assert.equal(hovered("MOVEA(0) = POS(1) + 5", "POS"), "POS(1)");
  const partial: [string, string][] = [["x = POS[0,1]", "POS"], ["x = POS.axis", "POS"], ["MOVER(k) = 2", "MOVER"], ["y = table(i)", "table"]];
  for (const [line, at] of partial) {
    assert.equal(evaluatableAt(line, line.indexOf(at)), undefined, line);
  }
});
