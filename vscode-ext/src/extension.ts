// Wiring only: each job lives in its own module.
import * as vscode from "vscode";

import { registerCommands } from "./commands";
import { registerDebugger } from "./debugger";
import { currentSettings, listFolder } from "./host";
import { LANGUAGE_ID } from "./language";
import { isPairedConfig } from "./pairing";
import { mintServer, type Server } from "./server";
import { SERVER_SETTINGS } from "./settings";
import { MintTests } from "./testing/controller";

let server: Server | undefined;

/** Opens conveyor.cfg as Mint when conveyor.mnt is beside it (mint.configPairing; see src/pairing.ts). */
function pairConfig(document: vscode.TextDocument): void {
  const settings = currentSettings();
  if (
    document.uri.scheme === "file" &&
    document.languageId !== LANGUAGE_ID &&
    settings.pairConfigFiles &&
    isPairedConfig(document.uri.fsPath, listFolder, settings.configPairing)
  ) {
    void vscode.languages.setTextDocumentLanguage(document, LANGUAGE_ID);
  }
}

export function activate(context: vscode.ExtensionContext): void {
  const output = vscode.window.createOutputChannel("Mint");
  server = mintServer(output);
  const running = server;
  context.subscriptions.push(
    output,
    ...registerCommands(output),
    ...registerDebugger(output),
    new MintTests(output),
    vscode.workspace.onDidOpenTextDocument(pairConfig),
    vscode.workspace.onDidChangeConfiguration((event) => {
      if (SERVER_SETTINGS.some((setting) => event.affectsConfiguration(setting))) {
        void running.restart();
      }
      if (event.affectsConfiguration("mint.pairConfigFiles") || event.affectsConfiguration("mint.configPairing")) {
        vscode.workspace.textDocuments.forEach(pairConfig);
      }
    }),
    // The workspace's .venv is only looked at in a trusted workspace.
    vscode.workspace.onDidGrantWorkspaceTrust(() => void running.restart()),
  );
  vscode.workspace.textDocuments.forEach(pairConfig);
  void running.restart();
}

export function deactivate(): Promise<void> | undefined {
  return server?.stop();
}
