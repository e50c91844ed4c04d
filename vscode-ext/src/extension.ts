// Wiring only: each job lives in its own module.
import * as vscode from "vscode";

import { registerCommands } from "./commands";
import { registerDebugger } from "./debugger";
import { currentSettings } from "./host";
import { LANGUAGE_ID } from "./language";
import { isConfigurationFile } from "./pairing";
import { mintServer, type Server } from "./server";
import { SERVER_SETTINGS } from "./settings";
import { MintTests } from "./testing/controller";

let server: Server | undefined;

/** Opens a program's configuration file as Mint, conveyor.cfg beside conveyor.mnt, as the server pairs them (src/pairing.ts). */
async function pairConfig(running: Server, document: vscode.TextDocument): Promise<void> {
  const uri = document.uri;
  if (uri.scheme !== "file" || document.languageId === LANGUAGE_ID || !currentSettings().pairConfigFiles) {
    return;
  }
  const files = await running.applicationFiles(uri);
  if (isConfigurationFile(uri.toString(), files) && !document.isClosed && document.languageId !== LANGUAGE_ID) {
    void vscode.languages.setTextDocumentLanguage(document, LANGUAGE_ID);
  }
}

export function activate(context: vscode.ExtensionContext): void {
  const output = vscode.window.createOutputChannel("Mint");
  // Once the server has the settings (at start and after each change), the configuration files it pairs open as Mint.
  const running = mintServer(output, () => pairAll());
  server = running;
  const pairAll = () => vscode.workspace.textDocuments.forEach((document) => void pairConfig(running, document));
  context.subscriptions.push(
    output,
    ...registerCommands(output, running),
    ...registerDebugger(output, running),
    new MintTests(output),
    vscode.workspace.onDidOpenTextDocument((document) => void pairConfig(running, document)),
    vscode.workspace.onDidChangeConfiguration((event) => {
      if (SERVER_SETTINGS.some((setting) => event.affectsConfiguration(setting))) {
        void running.restart();
      }
    }),
    // The workspace's .venv is only looked at in a trusted workspace.
    vscode.workspace.onDidGrantWorkspaceTrust(() => void running.restart()),
  );
  void running.restart();
}

export function deactivate(): Promise<void> | undefined {
  return server?.stop();
}
