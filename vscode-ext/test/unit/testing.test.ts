import assert from "node:assert/strict";
import { spawnSync } from "node:child_process";
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from "node:fs";
import * as os from "node:os";
import * as path from "node:path";
import { test } from "node:test";

import { testCommand, type Host, type Resolution } from "../../src/resolve";
import { parseCollected, parseLcov, parseOutcomes, parsePlace, UnreadableReport } from "../../src/testing/reports";

const NONE = { serverPath: "", pythonPath: "" } as const;
const HOST: Host = {
  platform: "linux",
  pathEnv: "/usr/bin",
  workspaceFolders: ["/work/cell"],
  isExecutable: (file) => file === "/work/cell/.venv/bin/mint",
};

function commandOf(resolution: Resolution): readonly string[] {
  assert.ok(resolution.ok, resolution.ok ? "" : resolution.message);
  return [resolution.command.command, ...resolution.command.args];
}

test("the Testing view lists tests and runs them through mint test, reporting in JSON", () => {
  assert.deepEqual(commandOf(testCommand({ collectOnly: true, paths: ["/work/cell"] }, NONE, HOST)), [
    "/work/cell/.venv/bin/mint",
    "test",
    "--format",
    "json",
    "--collect-only",
    "--",
    "/work/cell",
  ]);
  const covered = testCommand({ collectOnly: false, paths: ["/work/cell/-a.mnt"], lcov: "/tmp/l.info" }, NONE, HOST);
  assert.deepEqual(commandOf(covered).slice(1), ["test", "--format", "json", "--coverage", "--lcov", "/tmp/l.info", "--", "/work/cell/-a.mnt"]);
  const python = { serverPath: "", pythonPath: "/usr/bin/python3" };
  const host = { ...HOST, isExecutable: (file: string) => file === "/usr/bin/python3" };
  assert.deepEqual(commandOf(testCommand({ collectOnly: true, paths: ["/w"] }, python, host)).slice(0, 4), [
    "/usr/bin/python3",
    "-m",
    "mintlang",
    "test",
  ]);
});

test("the tests found are read with their scenario files", () => {
  const listed = parseCollected(
    JSON.stringify({ tests: [{ program: "/w/a.mnt", scenario: null }, { program: "/w/b.mnt", scenario: "/w/b.scenario.toml" }] }),
  );
  assert.deepEqual(listed, [
    { program: "/w/a.mnt", scenario: undefined },
    { program: "/w/b.mnt", scenario: "/w/b.scenario.toml" },
  ]);
});

test("output that is not the report is an UnreadableReport naming what came", () => {
  assert.throws(() => parseCollected("Traceback (most recent call last)"), UnreadableReport);
  assert.throws(() => parseOutcomes(JSON.stringify({ tests: "none" })), /"tests" is not a list/);
  assert.throws(() => parseOutcomes(JSON.stringify({ tests: [{ program: "a", verdict: "maybe" }] })), /unknown verdict: maybe/);
});

test("an expectation's origin is its file and line; a scenario's expectation has no line", () => {
  assert.deepEqual(parsePlace("/w/a:b.mnt:12"), { file: "/w/a:b.mnt", line: 12 });
  assert.equal(parsePlace("/w/b.scenario.toml expect #2"), undefined);
});

test("each outcome carries the expectations that did not hold, where they are written", () => {
  const report = {
    summary: { passed: 1, failed: 2, error: 1 },
    tests: [
      { program: "/w/a.mnt", verdict: "passed", stopped: "end", message: "", seconds: 0.5, checks: [] },
      {
        program: "/w/b.mnt",
        verdict: "failed",
        stopped: "end",
        message: "",
        seconds: 0.25,
        checks: [
          { what: "a", when: "end", expected: "= 3", actual: "2", held: false, origin: "/w/b.mnt:1", detail: "off by -1" },
          { what: "b", when: "end", expected: "= 1", actual: "1", held: true, origin: "/w/b.mnt:2", detail: "" },
        ],
      },
      { program: "/w/c.mnt", verdict: "failed", stopped: "error", message: "ERR 2015 at line 4", seconds: 0, checks: [] },
      { program: "/w/d.mnt", verdict: "error", stopped: "", message: "d.mnt:3: FOR without NEXT", seconds: 0, checks: [] },
    ],
  };
  assert.deepEqual(parseOutcomes(JSON.stringify(report)), [
    { program: "/w/a.mnt", verdict: "passed", seconds: 0.5, failures: [] },
    {
      program: "/w/b.mnt",
      verdict: "failed",
      seconds: 0.25,
      failures: [{ message: "a at end: expected = 3, got 2 (off by -1)", place: { file: "/w/b.mnt", line: 1 } }],
    },
    { program: "/w/c.mnt", verdict: "failed", seconds: 0, failures: [{ message: "stopped error: ERR 2015 at line 4", place: undefined }] },
    { program: "/w/d.mnt", verdict: "error", seconds: 0, failures: [{ message: "d.mnt:3: FOR without NEXT", place: undefined }] },
  ]);
});

test("a run stopped short or refused is shown where it stopped, in the program or its configuration file", () => {
  const stopped = (verdict: string, message: string, place: string | null) => ({
    program: "/w/cell.mnt",
    verdict,
    stopped: "error",
    message,
    place,
    seconds: 0,
    checks: [],
  });
  const report = {
    tests: [
      stopped("failed", "R2016: CONFIGURATION Invalid index [line 2]", "/w/cell.cfg:2"),
      stopped("error", "C2009: PROGRAM NEXT w/o FOR [line 3]", "/w/cell.mnt:3"),
      stopped("failed", "wall-clock limit", null),
    ],
  };
  assert.deepEqual(
    parseOutcomes(JSON.stringify(report)).map((outcome) => outcome.failures[0]?.place),
    [{ file: "/w/cell.cfg", line: 2 }, { file: "/w/cell.mnt", line: 3 }, undefined],
  );
});

test("a run that failed an expectation and was stopped by an error shows both", () => {
  const report = {
    tests: [
      {
        program: "/w/cell.mnt",
        verdict: "failed",
        stopped: "error",
        message: "R2016: PROGRAM Invalid index [line 4]",
        place: "/w/cell.mnt:4",
        stop_failed: true,
        seconds: 0,
        checks: [{ what: "b", when: "end", expected: "= 1", actual: "0", held: false, origin: "/w/cell.mnt:1", detail: "" }],
      },
    ],
  };
  assert.deepEqual(parseOutcomes(JSON.stringify(report))[0]?.failures, [
    { message: "b at end: expected = 1, got 0", place: { file: "/w/cell.mnt", line: 1 } },
    { message: "stopped error: R2016: PROGRAM Invalid index [line 4]", place: { file: "/w/cell.mnt", line: 4 } },
  ]);
});

test("an lcov tracefile gives each file's lines, branch outcomes and event handlers", () => {
  const tracefile = [
    "TN:",
    "SF:/w/a.mnt",
    "FN:7,#TIMER",
    "FN:9,#IN0",
    "FNDA:3,#TIMER",
    "FNDA:0,#IN0",
    "FNF:2",
    "FNH:1",
    "BRDA:2,0,0,4",
    "BRDA:2,0,1,0",
    "BRDA:5,1,0,-",
    "BRF:3",
    "BRH:1",
    "DA:1,1",
    "DA:2,4",
    "DA:5,0",
    "LF:3",
    "LH:2",
    "end_of_record",
    "TN:",
    "SF:/w/a.cfg",
    "DA:1,1",
    "end_of_record",
    "",
  ].join("\n");
  const [program, configuration] = parseLcov(tracefile);
  assert.ok(program !== undefined && configuration !== undefined);
  assert.equal(program.file, "/w/a.mnt");
  assert.deepEqual([...program.lines], [
    [1, 1],
    [2, 4],
    [5, 0],
  ]);
  assert.deepEqual(program.branches, [
    { line: 2, label: "0", taken: 4 },
    { line: 2, label: "1", taken: 0 },
    { line: 5, label: "0", taken: 0 },
  ]);
  assert.deepEqual(program.handlers, [
    { name: "#TIMER", line: 7, runs: 3 },
    { name: "#IN0", line: 9, runs: 0 },
  ]);
  assert.deepEqual([...configuration.lines], [[1, 1]]);
});

// The Python of the mintlang checkout this extension lives in, when it has been set up.
const CHECKOUT_PYTHON = path.resolve(__dirname, "..", "..", "..", "..", ".venv", "bin", "python");

test("mint test's own output reads as the Testing view expects", { skip: !existsSync(CHECKOUT_PYTHON) && "no ../.venv" }, () => {
  const folder = mkdtempSync(path.join(os.tmpdir(), "mint-tests-"));
  try {
    const program = path.join(folder, "cell.mnt");
    // Line 2 runs; the IF on line 3 is taken, so line 4 runs; the expectation (line 6) fails: a is 2.
    writeFileSync(program, "DIM a\na = 1 + 1\nIF a > 1 DO\n  PRINT a\nENDIF\nREM @expect a = 3\n");
    const host: Host = { ...HOST, workspaceFolders: [], isExecutable: (file) => file === CHECKOUT_PYTHON };
    const settings = { serverPath: "", pythonPath: CHECKOUT_PYTHON };
    const run = (resolution: Resolution): string => {
      const [command, ...args] = commandOf(resolution);
      const finished = spawnSync(command ?? "", args, { cwd: folder, encoding: "utf8", timeout: 60_000 });
      assert.ok(finished.status === 0 || finished.status === 1, finished.stderr);
      return finished.stdout;
    };
    assert.deepEqual(parseCollected(run(testCommand({ collectOnly: true, paths: [folder] }, settings, host))), [
      { program, scenario: undefined },
    ]);
    const lcov = path.join(folder, "lcov.info");
    const [outcome] = parseOutcomes(run(testCommand({ collectOnly: false, paths: [program], lcov }, settings, host)));
    assert.equal(outcome?.verdict, "failed");
    assert.deepEqual(outcome?.failures.map((failure) => failure.place), [{ file: program, line: 6 }]);
    const [covered] = parseLcov(readFileSync(lcov, "utf8"));
    assert.equal(covered?.file, program);
    assert.deepEqual([2, 3, 4].map((line) => covered?.lines.get(line)), [1, 1, 1]);
    assert.deepEqual(
      covered?.branches.map((branch) => branch.taken),
      [1, 0],
    );
  } finally {
    rmSync(folder, { recursive: true, force: true });
  }
});
