// Error messages that offer the way out: most failures are a setting away from working.
import * as vscode from "vscode";

const OPEN_SETTINGS = "Open Settings";
const SHOW_OUTPUT = "Show Output";

export async function showError(message: string, output: vscode.OutputChannel): Promise<void> {
  const choice = await vscode.window.showErrorMessage(message, OPEN_SETTINGS, SHOW_OUTPUT);
  if (choice === OPEN_SETTINGS) {
    await vscode.commands.executeCommand("workbench.action.openSettings", "@ext:mintlang.mint-motion");
  } else if (choice === SHOW_OUTPUT) {
    output.show();
  }
}
