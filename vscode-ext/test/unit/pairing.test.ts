// Which configuration file goes with which program: the editor asks the language server, whose pairing
// follows the user's mint.configPairing over the project's mint.toml, and tells mint-run and mint-dap
// what it answers. The last tests run the real mint-lsp and mint-run of the checkout.
import assert from "node:assert/strict";
import { spawn, spawnSync } from "node:child_process";
import { existsSync, mkdtempSync, realpathSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import * as path from "node:path";
import { test } from "node:test";
import { fileURLToPath, pathToFileURL } from "node:url";
import { createMessageConnection, StreamMessageReader, StreamMessageWriter } from "vscode-jsonrpc/node";

import {
  APPLICATION_FILES,
  askApplicationFiles,
  configurationChoice,
  isConfigurationFile,
  runDialect,
  savedBeforeRun,
  type ApplicationFiles,
  type SendRequest,
} from "../../src/pairing";
import { PYTHON_ARGUMENTS, toolArguments } from "../../src/resolve";

const answering =
  (answer: unknown): SendRequest =>
  async (method, params) => {
    assert.equal(method, "workspace/executeCommand");
    assert.deepEqual(params, { command: APPLICATION_FILES, arguments: ["file:///p/a.mnt"] });
    return answer;
  };

test("the server is asked with the file's URI, and an answer that is not two URIs or nulls is no answer", async () => {
  const files = { program: "file:///p/a.mnt", configuration: "file:///p/a.cfg", dialect: "mintmt" };
  assert.deepEqual(await askApplicationFiles(answering(files), "file:///p/a.mnt"), files);
  assert.deepEqual(await askApplicationFiles(answering({ program: "file:///p/a.mnt", configuration: null }), "file:///p/a.mnt"), {
    program: "file:///p/a.mnt",
    configuration: null,
    dialect: null,
  });
  for (const bad of [null, "file:///p/a.cfg", {}, { program: 1, configuration: null }, { program: null }]) {
    assert.equal(await askApplicationFiles(answering(bad), "file:///p/a.mnt"), undefined, JSON.stringify(bad));
  }
});

test("where the user set mint.configPairing a tool is told the server's configuration file, or that there is none", () => {
  const toPath = (uri: string) => fileURLToPath(uri);
  const paired = { program: "file:///p/a.mnt", dialect: "v4", configuration: "file:///p/setup_a.cfg" };
  assert.deepEqual(configurationChoice(paired, true, toPath), { config: "/p/setup_a.cfg" });
  assert.deepEqual(configurationChoice({ ...paired, configuration: null }, true, toPath), { noConfig: true });
  // With no answer, or without the setting, the tool pairs the program by the project's settings itself.
  assert.equal(configurationChoice(undefined, true, toPath), undefined);
  assert.equal(configurationChoice(paired, false, toPath), undefined);
});

test("a file opens as Mint when the server says it is a program's configuration file", () => {
  const cfg = "file:///p/a.cfg";
  const program = { program: "file:///p/a.mnt", dialect: "v4" };
  assert.equal(isConfigurationFile(cfg, { ...program, configuration: cfg }), true);
  const none = { program: null, dialect: null };
  assert.equal(isConfigurationFile(cfg, { ...none, configuration: cfg }), true); // mint.toml's config, every program's
  assert.equal(isConfigurationFile(cfg, { ...none, configuration: null }), false);
  assert.equal(isConfigurationFile(cfg, undefined), false);
  // Asked about a program, the answer names its configuration file, which is not the file asked about.
  assert.equal(isConfigurationFile("file:///p/a.mnt", { ...program, configuration: cfg }), false);
});

test("before a run the program and its configuration file are saved: the one named, else any .cfg", () => {
  const named = savedBeforeRun("/p/a.mnt", { config: "/p/setup_a.cfg" });
  assert.deepEqual(["/p/a.mnt", "/p/setup_a.cfg", "/p/a.cfg", "/p/b.mnt"].map(named), [true, true, false, false]);
  const none = savedBeforeRun("/p/a.mnt", { noConfig: true });
  assert.deepEqual(["/p/a.mnt", "/p/a.cfg"].map(none), [true, false]);
  // Where the tool pairs the program itself (mint.toml's config-pairing or config): any configuration file.
  const itself = savedBeforeRun("/p/a.mnt", undefined);
  assert.deepEqual(["/p/a.mnt", "/p/shared/line.CFG", "/p/notes.txt", "/p/b.mnt"].map(itself), [true, true, false, false]);
});

test("a run is told the user's mint.dialect, auto made the dialect the server reads the program in", () => {
  const files = { program: "file:///p/a.mnt", configuration: null, dialect: "mintmt" };
  assert.equal(runDialect("auto", files), "mintmt");
  assert.equal(runDialect("v3", files), "v3");
  assert.equal(runDialect(undefined, files), undefined); // unset: mint-run reads mint.toml itself
  assert.equal(runDialect("auto", undefined), undefined);
  assert.equal(runDialect("auto", { ...files, program: null, dialect: null }), undefined);
});

// The Python of the mintlang checkout this extension lives in, when it has been set up.
const CHECKOUT_PYTHON = path.resolve(__dirname, "..", "..", "..", "..", ".venv", "bin", "python");

/** A project whose mint.toml pairs setup_<name>.cfg, with a.cfg beside too: each file prints its name. */
function project(): { folder: string; program: string; setup: string; plain: string } {
  const folder = realpathSync(mkdtempSync(path.join(tmpdir(), "mint-pairing-")));
  writeFileSync(path.join(folder, "mint.toml"), 'config-pairing = "setup_<name>.cfg"\n');
  const file = (name: string, text: string) => {
    writeFileSync(path.join(folder, name), text);
    return path.join(folder, name);
  };
  return {
    folder,
    program: file("a.mnt", 'PRINT "program"\n'),
    setup: file("setup_a.cfg", 'PRINT "setup_a.cfg"\n'),
    plain: file("a.cfg", 'PRINT "a.cfg"\n'),
  };
}

/** The checkout's mint-lsp over stdio, started as VS Code starts it with the user's `mint` settings (null: unset). */
async function languageServer(mint: Record<string, unknown>) {
  const child = spawn(CHECKOUT_PYTHON, [...PYTHON_ARGUMENTS["mint-lsp"]], { stdio: ["pipe", "pipe", "ignore"] });
  const connection = createMessageConnection(new StreamMessageReader(child.stdout), new StreamMessageWriter(child.stdin));
  connection.listen();
  const initialize = { processId: process.pid, rootUri: null, capabilities: {}, initializationOptions: mint };
  await connection.sendRequest("initialize", initialize);
  await connection.sendNotification("initialized", {});
  const send: SendRequest = (method, params) => connection.sendRequest(method, params);
  return {
    files: (file: string): Promise<ApplicationFiles | undefined> => askApplicationFiles(send, pathToFileURL(file).href),
    change: (settings: Record<string, unknown>) =>
      connection.sendNotification("workspace/didChangeConfiguration", { settings: { mint: settings } }),
    stop: async () => {
      await connection.sendRequest("shutdown");
      await connection.sendNotification("exit");
      connection.dispose();
      child.kill();
    },
  };
}

/**
 * What mint-run prints first, run as Run in simulator runs it: told of the configuration file and the dialect
 * as the server's answer `files` and the user's settings say (`userPairs`: mint.configPairing set; `dialect`).
 */
function runFirstLine(program: string, files: ApplicationFiles | undefined, userPairs: boolean, dialect?: string) {
  const config = configurationChoice(files, userPairs, (uri) => fileURLToPath(uri));
  const chosen = { controller: undefined, dialect: runDialect(dialect, files) };
  const args = [...PYTHON_ARGUMENTS["mint-run"], ...toolArguments("mint-run", program, chosen, config)];
  const ran = spawnSync(CHECKOUT_PYTHON, args, { cwd: path.dirname(program), encoding: "utf8", timeout: 60_000 });
  assert.equal(ran.status, 0, ran.stderr);
  return ran.stdout.split("\n")[0];
}

test(
  "Run in simulator runs the configuration file the server checks: mint.toml's, under the user's mint.configPairing",
  { skip: !existsSync(CHECKOUT_PYTHON) && "no ../.venv" },
  async () => {
    const { folder, program } = project();
    const server = await languageServer({ mint: { configPairing: null } });
    try {
      // Unset in the editor: the project's setup_<name>.cfg, as mint-run pairs it on the command line.
      const cli = spawnSync(CHECKOUT_PYTHON, [...PYTHON_ARGUMENTS["mint-run"], "-q", program], { cwd: folder, encoding: "utf8" });
      assert.equal(cli.stdout.split("\n")[0], "setup_a.cfg");
      assert.equal(runFirstLine(program, await server.files(program), false), "setup_a.cfg");
      await server.change({ configPairing: "<name>.cfg" });
      assert.equal(runFirstLine(program, await server.files(program), true), "a.cfg");
      await server.change({ configPairing: "" }); // programs have no configuration file
      assert.equal(runFirstLine(program, await server.files(program), true), "program");
      await server.change({ configPairing: "<name>.ini" }); // names no file: none
      assert.equal(runFirstLine(program, await server.files(program), true), "program");
      // The server without an answer (not running): mint-run pairs the program by the project itself.
      assert.equal(runFirstLine(program, undefined, true), "setup_a.cfg");
    } finally {
      await server.stop();
      rmSync(folder, { recursive: true });
    }
  },
);

test(
  "with mint.configPairing unset, Run in simulator runs what mint-run runs on the command line, its own table's config too",
  { skip: !existsSync(CHECKOUT_PYTHON) && "no ../.venv" },
  async () => {
    const { folder, program } = project();
    writeFileSync(path.join(folder, "mint.toml"), '[run]\nconfig = "bench.cfg"\n'); // mint-run's option, not the server's
    writeFileSync(path.join(folder, "bench.cfg"), 'PRINT "bench.cfg"\n');
    const server = await languageServer({ mint: { configPairing: null } });
    try {
      const cli = spawnSync(CHECKOUT_PYTHON, [...PYTHON_ARGUMENTS["mint-run"], "-q", program], { cwd: folder, encoding: "utf8" });
      assert.equal(cli.stdout.split("\n")[0], "bench.cfg");
      assert.equal(runFirstLine(program, await server.files(program), false), "bench.cfg");
      // The user's own pairing wins over the project's, as --config on the command line would.
      await server.change({ configPairing: "<name>.cfg" });
      assert.equal(runFirstLine(program, await server.files(program), true), "a.cfg");
    } finally {
      await server.stop();
      rmSync(folder, { recursive: true });
    }
  },
);

test(
  "the .cfg that opens as Mint is the one the server pairs: mint.toml's, under the user's mint.configPairing",
  { skip: !existsSync(CHECKOUT_PYTHON) && "no ../.venv" },
  async () => {
    const { folder, setup, plain } = project();
    const server = await languageServer({ mint: { configPairing: null } });
    const opensAsMint = async (file: string) => isConfigurationFile(pathToFileURL(file).href, await server.files(file));
    try {
      assert.equal(await opensAsMint(setup), true);
      assert.equal(await opensAsMint(plain), false);
      await server.change({ configPairing: "<name>.cfg" });
      assert.equal(await opensAsMint(setup), false);
      assert.equal(await opensAsMint(plain), true);
    } finally {
      await server.stop();
      rmSync(folder, { recursive: true });
    }
  },
);

test(
  "with mint.dialect auto, Run in simulator runs a MintMT program as MintMT, as the server reads it",
  { skip: !existsSync(CHECKOUT_PYTHON) && "no ../.venv" },
  async () => {
    const folder = realpathSync(mkdtempSync(path.join(tmpdir(), "mint-auto-")));
    const program = path.join(folder, "mt.mnt");
    // A ' comment is a form only MintMT has (the README's mint.dialect auto); v4 refuses it (C2003).
    writeFileSync(program, "' counts to five\nDim x\nx = 5\nPrint x\n");
    const server = await languageServer({ mint: { dialect: "auto" } });
    try {
      assert.equal(runFirstLine(program, await server.files(program), false, "auto"), "5");
    } finally {
      await server.stop();
      rmSync(folder, { recursive: true });
    }
  },
);
