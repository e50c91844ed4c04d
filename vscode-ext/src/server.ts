// Starts, restarts and stops the mint-lsp language client.
import * as vscode from "vscode";
import { LanguageClient, type LanguageClientOptions } from "vscode-languageclient/node";

import { currentHost, currentSettings } from "./host";
import { LANGUAGE_ID } from "./language";
import { showError } from "./notify";
import { resolveTool, type Command } from "./resolve";
import { initializationOptions } from "./settings";

export interface Server {
  /** Stops the running server, if any, and starts one from the current settings. */
  restart(): Promise<void>;
  stop(): Promise<void>;
}

function createClient({ command, args }: Command, output: vscode.OutputChannel): LanguageClient {
  const clientOptions: LanguageClientOptions = {
    documentSelector: [
      { scheme: "file", language: LANGUAGE_ID },
      { scheme: "untitled", language: LANGUAGE_ID },
    ],
    outputChannel: output,
    // Evaluated at each start, so that a restart passes the current controller and dialect.
    initializationOptions: () => initializationOptions(currentSettings()),
    // Sends workspace/didChangeConfiguration with the `mint` section whenever it changes.
    synchronize: { configurationSection: "mint" },
  };
  // No `transport`: TransportKind.stdio would append a --stdio argument, which mint-lsp rejects;
  // without one the client talks over the process's stdin and stdout, mint-lsp's default.
  return new LanguageClient("mint", "Mint Language Server", { command, args: [...args] }, clientOptions);
}

export function mintServer(output: vscode.OutputChannel): Server {
  let client: LanguageClient | undefined;
  // Settings can change twice in quick succession: each restart waits for the one before.
  let queue: Promise<void> = Promise.resolve();

  const stopNow = async (): Promise<void> => {
    const running = client;
    client = undefined;
    // A client whose start failed has no process left and refuses to stop.
    if (running?.isRunning() === true) {
      try {
        await running.dispose();
      } catch (error) {
        output.appendLine(`Stopping mint-lsp: ${String(error)}`);
      }
    }
  };

  const restartNow = async (): Promise<void> => {
    await stopNow();
    const resolution = resolveTool("mint-lsp", currentSettings(), currentHost());
    if (!resolution.ok) {
      void showError(`Mint language server: ${resolution.message}`, output);
      return;
    }
    const { command, source } = resolution.command;
    output.appendLine(`Starting ${command} (from ${source})`);
    client = createClient(resolution.command, output);
    try {
      await client.start();
    } catch (error) {
      const reason = error instanceof Error ? error.message : String(error);
      void showError(`Mint language server: ${command} (from ${source}) did not start: ${reason}`, output);
    }
  };

  const enqueue = (step: () => Promise<void>): Promise<void> => (queue = queue.then(step));
  return { restart: () => enqueue(restartNow), stop: () => enqueue(stopNow) };
}
