// "Mint: Migrate file to v4" and "Mint: Run in simulator": each runs a mintlang command-line
// tool on the file in a child process and shows what it prints in the Mint output channel.
import { spawn } from "node:child_process";
import * as path from "node:path";
import * as vscode from "vscode";

import { currentHost, currentSettings, listFolder } from "./host";
import { LANGUAGE_ID } from "./language";
import { showError } from "./notify";
import { applicationOf, configurationOf, type Application } from "./pairing";
import { displayCommand, fileCommand, isMissingModule, MODULES, outcomeOf, type Command, type FileTool } from "./resolve";

interface Outcome {
  readonly code: number | null;
  readonly stderr: string;
  readonly cancelled: boolean;
}

/** The Mint document a command acts on: the one clicked in the explorer, else the active editor's. */
async function targetDocument(uri: unknown): Promise<vscode.TextDocument | undefined> {
  if (uri instanceof vscode.Uri) {
    return vscode.workspace.openTextDocument(uri);
  }
  const document = vscode.window.activeTextEditor?.document;
  return document?.languageId === LANGUAGE_ID ? document : undefined;
}

const filesOf = (application: Application): string[] =>
  application.config === undefined ? [application.program] : [application.program, application.config];

/**
 * What `tool` acts on when invoked on `file`, and how messages name it. mint-migrate rewrites a
 * program and its configuration file together, whichever of the two it is invoked on: the
 * configuration declares variables of the program, so neither migrates right without the other.
 * A simulated run is of a program, which reads its configuration file.
 */
function targetOf(tool: FileTool, file: string, pattern: string): { application: Application; label: string } {
  if (tool === "mint-migrate") {
    const application = applicationOf(file, listFolder, pattern);
    return { application, label: filesOf(application).map((name) => path.basename(name)).join(" and ") };
  }
  return { application: { program: file, config: configurationOf(file, listFolder, pattern) }, label: path.basename(file) };
}

/** Saves those of `files` open with unsaved changes: the tools read them from disk, and mint-migrate rewrites them there. */
async function saveOpen(files: readonly string[]): Promise<boolean> {
  const unsaved = vscode.workspace.textDocuments.filter(
    (document) => document.uri.scheme === "file" && document.isDirty && files.includes(document.uri.fsPath),
  );
  return (await Promise.all(unsaved.map((document) => document.save()))).every((saved) => saved);
}

function run(command: Command, cwd: string, output: vscode.OutputChannel, token: vscode.CancellationToken): Promise<Outcome> {
  return new Promise((resolve, reject) => {
    const child = spawn(command.command, [...command.args], { cwd });
    let stderr = "";
    // Decoded as streams, so a character split between two chunks is not garbled.
    child.stdout.setEncoding("utf8");
    child.stderr.setEncoding("utf8");
    child.stdout.on("data", (chunk: string) => output.append(chunk));
    child.stderr.on("data", (chunk: string) => {
      stderr += chunk;
      output.append(chunk);
    });
    const cancel = token.onCancellationRequested(() => child.kill());
    child.on("error", (error) => {
      cancel.dispose();
      reject(error);
    });
    child.on("close", (code) => {
      cancel.dispose();
      resolve({ code, stderr, cancelled: token.isCancellationRequested });
    });
  });
}

async function runTool(tool: FileTool, title: string, uri: unknown, output: vscode.OutputChannel): Promise<void> {
  const document = await targetDocument(uri);
  if (document === undefined || document.uri.scheme !== "file") {
    void vscode.window.showErrorMessage(`${title}: open a Mint (.mnt) file saved on disk first.`);
    return;
  }
  const settings = currentSettings();
  const { application, label } = targetOf(tool, document.uri.fsPath, settings.configPairing);
  if (!(await saveOpen(filesOf(application)))) {
    return;
  }
  const file = application.program;
  const resolution = fileCommand(tool, file, settings, currentHost(), application.config);
  if (!resolution.ok) {
    void showError(`${title}: ${resolution.message}`, output);
    return;
  }
  const command = resolution.command;
  output.show(true);
  output.appendLine(`$ ${displayCommand(command)}`);
  const progress = { location: vscode.ProgressLocation.Notification, title: `${title}: ${label}`, cancellable: true };
  let outcome: Outcome;
  try {
    outcome = await vscode.window.withProgress(progress, (_, token) => run(command, path.dirname(file), output, token));
  } catch (error) {
    const reason = error instanceof Error ? error.message : String(error);
    void showError(`${title}: ${command.command} (from ${command.source}) could not be started: ${reason}`, output);
    return;
  }
  output.appendLine(`[exit ${outcome.code ?? "killed"}]`);
  if (outcome.cancelled) {
    return;
  }
  const meaning = outcomeOf(tool, outcome.code, outcome.stderr);
  // Python exits 1 when the module is missing, so that is told apart before a migration's exit 1.
  if (meaning !== "done" && command.source === "mint.pythonPath" && isMissingModule(outcome.stderr, tool)) {
    void showError(`${title}: ${tool} was not found: ${command.command} has no module ${MODULES[tool]}.`, output);
  } else if (meaning === "done") {
    void vscode.window.showInformationMessage(`${title}: ${label} done.`);
  } else if (meaning === "review") {
    void vscode.window.showWarningMessage(
      `${title}: ${label} migrated; some statements need you: see the REM MIGRATE lines and the Mint output.`,
    );
  } else {
    void showError(`${title}: ${tool} failed (exit ${outcome.code ?? "killed"}); see the Mint output.`, output);
  }
}

export function registerCommands(output: vscode.OutputChannel): vscode.Disposable[] {
  return [
    vscode.commands.registerCommand("mint.migrateFile", (uri: unknown) =>
      runTool("mint-migrate", "Migrate file to v4", uri, output),
    ),
    vscode.commands.registerCommand("mint.runInSimulator", (uri: unknown) =>
      runTool("mint-run", "Run in simulator", uri, output),
    ),
  ];
}
