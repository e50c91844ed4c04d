import assert from "node:assert/strict";
import { spawnSync } from "node:child_process";
import { existsSync, mkdtempSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import * as path from "node:path";
import { test } from "node:test";

import {
  displayCommand,
  fileCommand,
  isMissingModule,
  PYTHON_ARGUMENTS,
  resolveTool,
  toolArguments,
  type Host,
  type Resolution,
  type Tool,
} from "../../src/resolve";

const NONE = { serverPath: "", pythonPath: "", controller: "nextmove-pci" } as const;
/** Neither mint.controller nor mint.dialect set by the user: the project's mint.toml decides. */
const UNSET = { controller: undefined, dialect: undefined } as const;

function posix(files: readonly string[], options: { folders?: readonly string[]; path?: string } = {}): Host {
  return {
    platform: "linux",
    pathEnv: options.path ?? "/usr/local/bin:/usr/bin",
    workspaceFolders: options.folders ?? ["/work/robot"],
    isExecutable: (file) => files.includes(file),
  };
}

function commandOf(resolution: Resolution): readonly string[] {
  assert.ok(resolution.ok, resolution.ok ? "" : resolution.message);
  return [resolution.command.command, ...resolution.command.args];
}

test("the workspace .venv comes before PATH", () => {
  const host = posix(["/work/robot/.venv/bin/mint-lsp", "/usr/bin/mint-lsp"]);
  const resolution = resolveTool("mint-lsp", NONE, host);
  assert.deepEqual(commandOf(resolution), ["/work/robot/.venv/bin/mint-lsp"]);
  assert.equal(resolution.ok && resolution.command.source, "the workspace's .venv");
});

test("every workspace folder's .venv is searched, in order", () => {
  const host = posix(["/work/b/.venv/bin/mint-lsp"], { folders: ["/work/a", "/work/b"] });
  assert.deepEqual(commandOf(resolveTool("mint-lsp", NONE, host)), ["/work/b/.venv/bin/mint-lsp"]);
});

test("PATH is searched in order when there is no .venv", () => {
  const host = posix(["/usr/bin/mint-lsp", "/opt/bin/mint-lsp"], { path: "/usr/local/bin::/usr/bin:/opt/bin" });
  assert.deepEqual(commandOf(resolveTool("mint-lsp", NONE, host)), ["/usr/bin/mint-lsp"]);
});

test("an untrusted workspace (no folders) falls through to PATH", () => {
  const host = posix(["/work/robot/.venv/bin/mint-lsp", "/usr/bin/mint-lsp"], { folders: [] });
  assert.deepEqual(commandOf(resolveTool("mint-lsp", NONE, host)), ["/usr/bin/mint-lsp"]);
});

test("mint.serverPath wins over everything", () => {
  const host = posix(["/opt/mint/bin/mint-lsp", "/work/robot/.venv/bin/mint-lsp"]);
  const settings = { serverPath: "/opt/mint/bin/mint-lsp", pythonPath: "/usr/bin/python3" };
  assert.deepEqual(commandOf(resolveTool("mint-lsp", settings, host)), ["/opt/mint/bin/mint-lsp"]);
});

test("mint.serverPath may be relative to the workspace or use ${workspaceFolder}", () => {
  const host = posix(["/work/robot/tools/mint-lsp"]);
  assert.deepEqual(commandOf(resolveTool("mint-lsp", { ...NONE, serverPath: "tools/mint-lsp" }, host)), [
    "/work/robot/tools/mint-lsp",
  ]);
  assert.deepEqual(commandOf(resolveTool("mint-lsp", { ...NONE, serverPath: "${workspaceFolder}/tools/mint-lsp" }, host)), [
    "/work/robot/tools/mint-lsp",
  ]);
});

test("a mint.serverPath that does not exist is an error, not skipped", () => {
  const host = posix(["/usr/bin/mint-lsp"]);
  const resolution = resolveTool("mint-lsp", { ...NONE, serverPath: "/nowhere/mint-lsp" }, host);
  assert.equal(resolution.ok, false);
  assert.match(resolution.ok ? "" : resolution.message, /mint\.serverPath is set to '\/nowhere\/mint-lsp'/);
});

test("mint.pythonPath runs the server as a module", () => {
  const host = posix(["/work/robot/.venv/bin/python", "/usr/bin/mint-lsp"]);
  const resolution = resolveTool("mint-lsp", { ...NONE, pythonPath: ".venv/bin/python" }, host);
  assert.deepEqual(commandOf(resolution), ["/work/robot/.venv/bin/python", "-m", "mintlang.lsp"]);
});

test("a bare mint.pythonPath is looked up on PATH", () => {
  const host = posix(["/usr/bin/python3"]);
  assert.deepEqual(commandOf(resolveTool("mint-lsp", { ...NONE, pythonPath: "python3" }, host)), [
    "/usr/bin/python3",
    "-m",
    "mintlang.lsp",
  ]);
});

test("a mint.pythonPath that does not exist is an error", () => {
  const resolution = resolveTool("mint-run", { ...NONE, pythonPath: "/nowhere/python" }, posix([]));
  assert.equal(resolution.ok, false);
  assert.match(resolution.ok ? "" : resolution.message, /mint\.pythonPath/);
});

test("nothing found: the message names the tool and where it looked", () => {
  const resolution = resolveTool("mint-run", NONE, posix(["/usr/bin/mint-lsp"]));
  assert.equal(resolution.ok, false);
  const message = resolution.ok ? "" : resolution.message;
  assert.match(message, /^mint-run was not found/);
  assert.match(message, /\/work\/robot\/\.venv, PATH/);
  assert.match(message, /mint\.serverPath or mint\.pythonPath/);
});

test("the tools are found beside mint.serverPath, else by the usual search", () => {
  const settings = { ...NONE, serverPath: "/opt/mint/bin/mint-lsp" };
  assert.deepEqual(commandOf(resolveTool("mint-run", settings, posix(["/opt/mint/bin/mint-lsp", "/opt/mint/bin/mint-run"]))), [
    "/opt/mint/bin/mint-run",
  ]);
  assert.deepEqual(commandOf(resolveTool("mint-run", settings, posix(["/opt/mint/bin/mint-lsp", "/usr/bin/mint-run"]))), [
    "/usr/bin/mint-run",
  ]);
});

test("Windows: Scripts folder, .exe names, ; in PATH", () => {
  const host: Host = {
    platform: "win32",
    pathEnv: "C:\\Windows;C:\\Python312\\Scripts",
    workspaceFolders: ["C:\\work\\robot"],
    isExecutable: (file) => ["C:\\work\\robot\\.venv\\Scripts\\mint-lsp.exe", "C:\\Python312\\Scripts\\mint-run.exe"].includes(file),
  };
  assert.deepEqual(commandOf(resolveTool("mint-lsp", NONE, host)), ["C:\\work\\robot\\.venv\\Scripts\\mint-lsp.exe"]);
  assert.deepEqual(commandOf(resolveTool("mint-run", NONE, host)), ["C:\\Python312\\Scripts\\mint-run.exe"]);
});

test("a run simulates the file for the controller and dialect the user set, bounded in real time", () => {
  assert.deepEqual(toolArguments("mint-run", "/p/a.mnt", { controller: "nextmove-bx", dialect: "mintmt" }), [
    "--controller",
    "nextmove-bx",
    "--dialect",
    "mintmt",
    "--max-wall-s",
    "30",
    "/p/a.mnt",
  ]);
});

test("a run leaves what the user did not set, and auto, to the project's mint.toml", () => {
  assert.deepEqual(toolArguments("mint-run", "/p/a.mnt", UNSET), ["--max-wall-s", "30", "/p/a.mnt"]);
  assert.deepEqual(toolArguments("mint-run", "/p/a.mnt", { controller: undefined, dialect: "auto" }), [
    "--max-wall-s",
    "30",
    "/p/a.mnt",
  ]);
});

test("a run gets the program's configuration file before the program, or is told it has none", () => {
  assert.deepEqual(toolArguments("mint-run", "/p/a.mnt", { controller: "mintdrive", dialect: undefined }, { config: "/p/a.cfg" }), [
    "--config",
    "/p/a.cfg",
    "--controller",
    "mintdrive",
    "--max-wall-s",
    "30",
    "/p/a.mnt",
  ]);
  const host = posix(["/usr/bin/mint-run"]);
  assert.deepEqual(commandOf(fileCommand("mint-run", "/p/a.mnt", NONE, UNSET, host, { config: "/p/a.cfg" })).slice(0, 3), [
    "/usr/bin/mint-run",
    "--config",
    "/p/a.cfg",
  ]);
  assert.deepEqual(toolArguments("mint-run", "/p/a.mnt", UNSET, { noConfig: true }), ["--no-config", "--max-wall-s", "30", "/p/a.mnt"]);
});

// The Python of the mintlang checkout this extension lives in, when it has been set up.
const CHECKOUT_PYTHON = path.resolve(__dirname, "..", "..", "..", "..", ".venv", "bin", "python");

test("every mint.pythonPath command line starts its tool", { skip: !existsSync(CHECKOUT_PYTHON) && "no ../.venv" }, () => {
  for (const tool of Object.keys(PYTHON_ARGUMENTS) as Tool[]) {
    const run = spawnSync(CHECKOUT_PYTHON, [...PYTHON_ARGUMENTS[tool], "--help"], { encoding: "utf8", timeout: 60_000 });
    assert.equal(run.status, 0, `${tool}: ${run.stderr}`);
    assert.match(run.stdout, /Usage: /, tool);
  }
});

test(
  "Run in simulator runs a Mint v3 project's program when the user set no controller",
  { skip: !existsSync(CHECKOUT_PYTHON) && "no ../.venv" },
  () => {
    // mint.toml says v3; the v4 default controller (nextmove-pci) is not one of the v3 guide's.
    const project = mkdtempSync(path.join(tmpdir(), "mint-v3-"));
    writeFileSync(path.join(project, "mint.toml"), 'dialect = "v3"\n');
    writeFileSync(path.join(project, "a.mnt"), 'PRINT "ready"\n');
    const args = [...PYTHON_ARGUMENTS["mint-run"], ...toolArguments("mint-run", path.join(project, "a.mnt"), UNSET)];
    const run = spawnSync(CHECKOUT_PYTHON, args, { cwd: project, encoding: "utf8", timeout: 60_000 });
    rmSync(project, { recursive: true });
    assert.equal(run.status, 0, run.stderr);
    assert.match(run.stdout, /ready/);
  },
);

test("file commands append the file arguments to the resolved command", () => {
  const host = posix(["/work/robot/.venv/bin/mint-run", "/usr/bin/python3"]);
  assert.deepEqual(commandOf(fileCommand("mint-run", "/work/robot/a b.mnt", NONE, UNSET, host)), [
    "/work/robot/.venv/bin/mint-run",
    "--max-wall-s",
    "30",
    "/work/robot/a b.mnt",
  ]);
  assert.deepEqual(commandOf(fileCommand("mint-run", "/work/robot/a.mnt", { ...NONE, pythonPath: "python3" }, UNSET, host)), [
    "/usr/bin/python3",
    "-m",
    "mintlang.runtime",
    "--max-wall-s",
    "30",
    "/work/robot/a.mnt",
  ]);
  assert.equal(fileCommand("mint-run", "/work/robot/a.mnt", NONE, UNSET, posix(["/usr/bin/python3"])).ok, false);
});

test("a missing module is recognised in Python's message, and only the tool's own", () => {
  assert.equal(isMissingModule("/usr/bin/python3: No module named mintlang.runtime\n", "mint-run"), true);
  assert.equal(isMissingModule("/usr/bin/python3: No module named mintlang\n", "mint-run"), true);
  assert.equal(isMissingModule("ModuleNotFoundError: No module named 'mintlang'\n", "mint-lsp"), true);
  assert.equal(isMissingModule("ModuleNotFoundError: No module named 'lark'\n", "mint-run"), false);
  assert.equal(isMissingModule("No module named mintlang.runtime\n", "mint-lsp"), false);
  assert.equal(isMissingModule("error[E3001]: Variable undefined\n", "mint-run"), false);
});

test("command lines are shown quoted as a shell would need", () => {
  assert.equal(
    displayCommand({ command: "/usr/bin/mint-run", args: ["--controller", "/p/my file's.mnt"], source: "PATH" }),
    "/usr/bin/mint-run --controller '/p/my file'\\''s.mnt'",
  );
});

