// The debugger in the editor: VS Code starts mint-dap (found as the language server is) and talks DAP
// to it; "Mint: Debug in simulator" debugs the program in the editor, as "Run in simulator" runs it.
import * as vscode from "vscode";

import { evaluatableAt } from "./evaluatable";
import { currentChoices, currentHost, currentSettings } from "./host";
import { LANGUAGE_ID } from "./language";
import { completeLaunch, DEBUG_TYPE, launchConfiguration, launchFor } from "./launch";
import { showError } from "./notify";
import { savedBeforeRun } from "./pairing";
import { resolveTool } from "./resolve";
import { saveOpen } from "./saving";
import { configurationFor, type Server } from "./server";

function activeProgram(): string | undefined {
  const document = vscode.window.activeTextEditor?.document;
  return document?.languageId === LANGUAGE_ID && document.uri.scheme === "file" ? document.uri.fsPath : undefined;
}

class Adapter implements vscode.DebugAdapterDescriptorFactory {
  constructor(private readonly output: vscode.OutputChannel) {}

  createDebugAdapterDescriptor(): vscode.ProviderResult<vscode.DebugAdapterDescriptor> {
    const resolution = resolveTool("mint-dap", currentSettings(), currentHost());
    if (!resolution.ok) {
      void showError(`Debug in simulator: ${resolution.message}`, this.output);
      return undefined;
    }
    return new vscode.DebugAdapterExecutable(resolution.command.command, [...resolution.command.args]);
  }
}

class Configurations implements vscode.DebugConfigurationProvider {
  constructor(private readonly server: Server) {}

  provideDebugConfigurations(): vscode.ProviderResult<vscode.DebugConfiguration[]> {
    return [{ ...launchFor("${file}"), name: "Debug the program in the editor" }];
  }

  async resolveDebugConfigurationWithSubstitutedVariables(
    _folder: vscode.WorkspaceFolder | undefined,
    given: vscode.DebugConfiguration,
  ): Promise<vscode.DebugConfiguration | undefined> {
    const chosen = currentChoices();
    const pairing = (program: string) => configurationFor(this.server, vscode.Uri.file(program), chosen.configPairing);
    const completion = await completeLaunch(given, activeProgram(), chosen, pairing);
    if (!completion.ok) {
      void vscode.window.showErrorMessage(`Debug in simulator: ${completion.message}`);
      return undefined;
    }
    const launch = completion.launch;
    // mint-dap reads the program and its configuration file from disk, wherever they are open.
    const saved = await saveOpen(savedBeforeRun(launch.program, launchConfiguration(launch)));
    return saved ? (launch as vscode.DebugConfiguration) : undefined;
  }
}

async function debugInSimulator(uri: unknown): Promise<void> {
  const file = uri instanceof vscode.Uri ? uri.fsPath : activeProgram();
  if (file === undefined) {
    void vscode.window.showErrorMessage("Debug in simulator: open a Mint (.mnt) file saved on disk first.");
    return;
  }
  const folder = vscode.workspace.getWorkspaceFolder(vscode.Uri.file(file));
  await vscode.debug.startDebugging(folder, launchFor(file) as vscode.DebugConfiguration);
}

/** "Mint: Run on for a simulated time…": mint-dap's own runFor request, to the statement tried that much later. */
async function runFor(): Promise<void> {
  const session = vscode.debug.activeDebugSession;
  if (session?.type !== DEBUG_TYPE) {
    void vscode.window.showErrorMessage("Run on for a simulated time: debug a Mint program first.");
    return;
  }
  const text = await vscode.window.showInputBox({
    prompt: "Simulated milliseconds to run on for (servo ticks)",
    value: "100",
    validateInput: (value) => (/^[1-9]\d*$/.test(value.trim()) ? undefined : "a whole number of milliseconds, 1 or more"),
  });
  if (text !== undefined) {
    await session.customRequest("runFor", { ms: Number(text.trim()) });
  }
}

export function registerDebugger(output: vscode.OutputChannel, server: Server): vscode.Disposable[] {
  return [
    vscode.debug.registerDebugAdapterDescriptorFactory(DEBUG_TYPE, new Adapter(output)),
    vscode.debug.registerDebugConfigurationProvider(DEBUG_TYPE, new Configurations(server)),
    vscode.commands.registerCommand("mint.debugInSimulator", debugInSimulator),
    vscode.commands.registerCommand("mint.runFor", runFor),
    vscode.languages.registerEvaluatableExpressionProvider(LANGUAGE_ID, {
      provideEvaluatableExpression(document, position) {
        const found = evaluatableAt(document.lineAt(position.line).text, position.character);
        return found && new vscode.EvaluatableExpression(new vscode.Range(position.line, found[0], position.line, found[1]));
      },
    }),
  ];
}
