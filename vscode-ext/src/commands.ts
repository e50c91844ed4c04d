// "Mint: Migrate file to v4" and "Mint: Replace v3 keywords" apply the language server's source
// actions (see ./migration); "Mint: Run in simulator" runs mint-run on the program in a child
// process and shows what it prints in the Mint output channel.
import * as path from "node:path";
import * as vscode from "vscode";

import { currentChoices, currentHost, currentSettings } from "./host";
import { LANGUAGE_ID } from "./language";
import { planMigration, planReplacement, type Plan } from "./migration";
import { showError } from "./notify";
import { configurationChoice, runDialect, savedBeforeRun } from "./pairing";
import { execute, type Finished } from "./process";
import { displayCommand, fileCommand, isMissingModule, MODULES } from "./resolve";
import { saveOpen } from "./saving";
import { pathOf, type Server } from "./server";

/** The Mint document a command acts on: the one clicked in the explorer, else the active editor's. */
async function targetDocument(uri: unknown): Promise<vscode.TextDocument | undefined> {
  if (uri instanceof vscode.Uri) {
    return vscode.workspace.openTextDocument(uri);
  }
  const document = vscode.window.activeTextEditor?.document;
  return document?.languageId === LANGUAGE_ID ? document : undefined;
}

async function runInSimulator(uri: unknown, output: vscode.OutputChannel, server: Server): Promise<void> {
  const tool = "mint-run";
  const title = "Run in simulator";
  const document = await targetDocument(uri);
  if (document === undefined || document.uri.scheme !== "file") {
    void vscode.window.showErrorMessage(`${title}: open a Mint (.mnt) file saved on disk first.`);
    return;
  }
  const settings = currentSettings();
  const chosen = currentChoices();
  const file = document.uri.fsPath;
  const asks = chosen.configPairing || chosen.dialect === "auto";
  const files = asks ? await server.applicationFiles(document.uri) : undefined;
  const config = configurationChoice(files, chosen.configPairing, pathOf);
  const label = path.basename(file);
  if (!(await saveOpen(savedBeforeRun(file, config)))) {
    return;
  }
  const choices = { controller: chosen.controller, dialect: runDialect(chosen.dialect, files) };
  const resolution = fileCommand(tool, file, settings, choices, currentHost(), config);
  if (!resolution.ok) {
    void showError(`${title}: ${resolution.message}`, output);
    return;
  }
  const command = resolution.command;
  output.show(true);
  if (asks && files === undefined) {
    output.appendLine("(no answer from mint-lsp: mint-run pairs the configuration file and picks the dialect by mint.toml)");
  }
  output.appendLine(`$ ${displayCommand(command)}`);
  const progress = { location: vscode.ProgressLocation.Notification, title: `${title}: ${label}`, cancellable: true };
  let outcome: Finished;
  try {
    outcome = await vscode.window.withProgress(progress, (_, token) =>
      execute(command, path.dirname(file), token, (chunk) => output.append(chunk)),
    );
  } catch (error) {
    const reason = error instanceof Error ? error.message : String(error);
    void showError(`${title}: ${command.command} (from ${command.source}) could not be started: ${reason}`, output);
    return;
  }
  output.appendLine(`[exit ${outcome.code ?? "killed"}]`);
  if (outcome.cancelled) {
    return;
  }
  // Python exits 1 when the module is missing, as mint-run does when the program stopped on an error.
  if (outcome.code !== 0 && command.source === "mint.pythonPath" && isMissingModule(outcome.stderr, tool)) {
    void showError(`${title}: ${tool} was not found: ${command.command} has no module ${MODULES[tool]}.`, output);
  } else if (outcome.code === 0) {
    void vscode.window.showInformationMessage(`${title}: ${label} done.`);
  } else {
    void showError(`${title}: ${tool} failed (exit ${outcome.code ?? "killed"}); see the Mint output.`, output);
  }
}

/** The source actions of `kind` the language server offers for the whole of `document`; resolved if asked. */
async function sourceActions(document: vscode.TextDocument, kind: string, resolve: boolean): Promise<vscode.CodeAction[]> {
  const whole = new vscode.Range(0, 0, document.lineCount, 0);
  const found = await vscode.commands.executeCommand<vscode.CodeAction[] | undefined>(
    "vscode.executeCodeActionProvider",
    document.uri,
    whole,
    kind,
    resolve ? 1 : 0,
  );
  return found ?? [];
}

/** Carries out `plan` for `document`: the chosen action's edit, asked for again resolved, applied as a refactoring. */
async function carryOut(document: vscode.TextDocument, plan: Plan<vscode.CodeAction>, title: string): Promise<void> {
  if (plan.step === "none") {
    void vscode.window.showInformationMessage(`${title}: ${plan.message}`);
    return;
  }
  if (plan.step === "ask" && (await vscode.window.showWarningMessage(plan.question, { modal: true }, plan.answer)) !== plan.answer) {
    return;
  }
  const kind = plan.action.kind?.value ?? "";
  const [resolved] = await sourceActions(document, kind, true);
  if (resolved?.edit === undefined) {
    void vscode.window.showErrorMessage(`${title}: the language server gave no edit (was the file changed meanwhile?).`);
    return;
  }
  await vscode.workspace.applyEdit(resolved.edit, { isRefactoring: true });
}

type Planner = (actions: readonly vscode.CodeAction[], kindOf: (action: vscode.CodeAction) => string | undefined, file: string) => Plan<vscode.CodeAction>;

async function sourceAction(planner: Planner, title: string, uri: unknown): Promise<void> {
  const document = await targetDocument(uri);
  if (document === undefined) {
    void vscode.window.showErrorMessage(`${title}: open a Mint file first.`);
    return;
  }
  const actions = await sourceActions(document, vscode.CodeActionKind.Source.value, false);
  const plan = planner(actions, (action) => action.kind?.value, path.basename(document.uri.path));
  await carryOut(document, plan, title);
}

export function registerCommands(output: vscode.OutputChannel, server: Server): vscode.Disposable[] {
  return [
    vscode.commands.registerCommand("mint.migrateFile", (uri: unknown) => sourceAction(planMigration, "Migrate file to v4", uri)),
    vscode.commands.registerCommand("mint.replaceV3Keywords", (uri: unknown) =>
      sourceAction(planReplacement, "Replace v3 keywords", uri),
    ),
    vscode.commands.registerCommand("mint.runInSimulator", (uri: unknown) => runInSimulator(uri, output, server)),
  ];
}
