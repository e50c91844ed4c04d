// Starts, restarts and stops the mint-lsp language client.
import * as vscode from "vscode";
import { LanguageClient, type LanguageClientOptions } from "vscode-languageclient/node";

import { currentHost, currentSettings } from "./host";
import { LANGUAGE_ID } from "./language";
import { showError } from "./notify";
import { askApplicationFiles, configurationChoice, type ApplicationFiles, type ConfigurationChoice } from "./pairing";
import { resolveTool, type Command } from "./resolve";
import { serverSettings } from "./settings";

const SECTION = "mint";

/** The `mint` settings the user set, for the folder of `scopeUri` if given (null where set nowhere). */
const userSettings = (scopeUri?: string) =>
  serverSettings(vscode.workspace.getConfiguration(SECTION, scopeUri === undefined ? undefined : vscode.Uri.parse(scopeUri)));

export interface Server {
  /** Stops the running server, if any, and starts one from the current settings. */
  restart(): Promise<void>;
  stop(): Promise<void>;
  /**
   * The program and configuration file `uri` goes with, as the server pairs them (see ./pairing), once
   * it has started; undefined when none runs or it cannot say (a mintlang without the command).
   */
  applicationFiles(uri: vscode.Uri): Promise<ApplicationFiles | undefined>;
}

/** The path of a file URI in the server's answers. */
export const pathOf = (uri: string): string => vscode.Uri.parse(uri).fsPath;

/** What mint-run or mint-dap is told of `program`'s configuration file (see configurationChoice in ./pairing). */
export async function configurationFor(
  server: Server,
  program: vscode.Uri,
  userPairs: boolean,
): Promise<ConfigurationChoice | undefined> {
  return configurationChoice(await server.applicationFiles(program), userPairs, pathOf);
}

function createClient({ command, args }: Command, output: vscode.OutputChannel, onAsked: () => void): LanguageClient {
  const clientOptions: LanguageClientOptions = {
    documentSelector: [
      { scheme: "file", language: LANGUAGE_ID },
      { scheme: "untitled", language: LANGUAGE_ID },
    ],
    outputChannel: output,
    // Evaluated at each start, so that a restart passes the current controller and dialect.
    initializationOptions: () => userSettings(),
    // Sends workspace/didChangeConfiguration whenever the `mint` section changes.
    synchronize: { configurationSection: SECTION },
    middleware: {
      workspace: {
        // Without the values: the client's would hold VS Code's defaults for every setting. The
        // server asks for the section (workspace/configuration) on this notification, answered below.
        didChangeConfiguration: (_sections, next) => next(undefined),
        // The `mint` section as the user set it, so that a project's mint.toml is not overridden.
        // The server asks once it has started and whenever the settings change; what depends on them
        // is asked again after that (onAsked), the server answering once it has them.
        configuration: async (params, token, next) => {
          const answers = await next(params, token);
          if (!Array.isArray(answers)) return answers;
          setTimeout(onAsked);
          return params.items.map((item, index) =>
            item.section === SECTION ? userSettings(item.scopeUri) : answers[index],
          );
        },
      },
    },
  };
  // No `transport`: TransportKind.stdio would append a --stdio argument, which mint-lsp rejects;
  // without one the client talks over the process's stdin and stdout, mint-lsp's default.
  return new LanguageClient("mint", "Mint Language Server", { command, args: [...args] }, clientOptions);
}

/** The mint-lsp client; `onAsked` is called each time the server has asked for the `mint` settings. */
export function mintServer(output: vscode.OutputChannel, onAsked: () => void): Server {
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
    client = createClient(resolution.command, output, onAsked);
    try {
      await client.start();
    } catch (error) {
      const reason = error instanceof Error ? error.message : String(error);
      void showError(`Mint language server: ${command} (from ${source}) did not start: ${reason}`, output);
    }
  };

  const applicationFiles = async (uri: vscode.Uri): Promise<ApplicationFiles | undefined> => {
    await queue;
    const running = client;
    if (running?.isRunning() !== true) {
      return undefined;
    }
    const send = (method: string, params: unknown) => running.sendRequest(method, params);
    // As the client writes the URIs of documents (it has no uriConverters), and as the answer echoes it.
    return askApplicationFiles(send, uri.toString()).catch(() => undefined);
  };

  const enqueue = (step: () => Promise<void>): Promise<void> => (queue = queue.then(step));
  return { restart: () => enqueue(restartNow), stop: () => enqueue(stopNow), applicationFiles };
}
