// The machine as src/resolve.ts sees it, taken from VS Code and the file system.
import * as fs from "node:fs";
import * as vscode from "vscode";

import type { Chosen } from "./launch";
import type { Host } from "./resolve";
import { readSettings, type MintSettings } from "./settings";

export function currentSettings(): MintSettings {
  return readSettings(vscode.workspace.getConfiguration("mint"));
}

/** The settings the user set (in any scope), not VS Code's defaults: unset, the project's mint.toml decides. */
export function currentChoices(): Chosen {
  const section = vscode.workspace.getConfiguration("mint");
  const set = (key: string): string | undefined => {
    const found = section.inspect<string>(key);
    return found?.workspaceFolderValue ?? found?.workspaceValue ?? found?.globalValue;
  };
  return { controller: set("controller"), dialect: set("dialect"), configPairing: set("configPairing") !== undefined };
}

function isExecutable(file: string): boolean {
  try {
    fs.accessSync(file, fs.constants.X_OK);
    return fs.statSync(file).isFile();
  } catch {
    return false;
  }
}

export function currentHost(): Host {
  const folders = vscode.workspace.workspaceFolders ?? [];
  return {
    platform: process.platform,
    pathEnv: process.env["PATH"] ?? "",
    // A workspace's .venv runs only once the workspace is trusted: an untrusted one could hold anything.
    workspaceFolders: vscode.workspace.isTrusted
      ? folders.filter((folder) => folder.uri.scheme === "file").map((folder) => folder.uri.fsPath)
      : [],
    isExecutable,
  };
}
