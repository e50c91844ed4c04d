// "Mint: Migrate file to v4" and "Mint: Run in simulator": each runs a mintlang command-line
// tool on the file in a child process and shows what it prints in the Mint output channel.
import { spawn } from "node:child_process";
import * as path from "node:path";
import * as vscode from "vscode";

import { currentHost, currentSettings, listFolder } from "./host";
import { LANGUAGE_ID } from "./language";
import { showError } from "./notify";
import { configurationOf } from "./pairing";
import { displayCommand, fileCommand, isMissingModule, MODULES, type Command, type FileTool } from "./resolve";

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
  // The tools read the file from disk, and mint-migrate rewrites it there.
  if (document.isDirty && !(await document.save())) {
    return;
  }
  const file = document.uri.fsPath;
  const settings = currentSettings();
  const config = tool === "mint-run" ? configurationOf(file, listFolder, settings.configPairing) : undefined;
  const resolution = fileCommand(tool, file, settings, currentHost(), config);
  if (!resolution.ok) {
    void showError(`${title}: ${resolution.message}`, output);
    return;
  }
  const command = resolution.command;
  output.show(true);
  output.appendLine(`$ ${displayCommand(command)}`);
  const progress = { location: vscode.ProgressLocation.Notification, title: `${title}: ${path.basename(file)}`, cancellable: true };
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
  if (outcome.code === 0) {
    void vscode.window.showInformationMessage(`${title}: ${path.basename(file)} done.`);
  } else if (command.source === "mint.pythonPath" && isMissingModule(outcome.stderr, tool)) {
    void showError(`${title}: ${tool} was not found: ${command.command} has no module ${MODULES[tool]}.`, output);
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
