// A tool run as a child process: its output collected (and shown as it comes, if asked), stopped when
// the user cancels. The commands and the Testing view run mint-run and mint test this way.
import { spawn } from "node:child_process";
import type * as vscode from "vscode";

import type { Command } from "./resolve";

export interface Finished {
  readonly code: number | null;
  readonly stdout: string;
  readonly stderr: string;
  readonly cancelled: boolean;
}

/** Runs `command` in `cwd`; `echo` sees standard output and error as they come. */
export function execute(
  command: Command,
  cwd: string,
  token?: vscode.CancellationToken,
  echo?: (chunk: string) => void,
): Promise<Finished> {
  return new Promise((resolve, reject) => {
    const child = spawn(command.command, [...command.args], { cwd });
    let stdout = "";
    let stderr = "";
    // Decoded as streams, so a character split between two chunks is not garbled.
    child.stdout.setEncoding("utf8");
    child.stderr.setEncoding("utf8");
    child.stdout.on("data", (chunk: string) => {
      stdout += chunk;
      echo?.(chunk);
    });
    child.stderr.on("data", (chunk: string) => {
      stderr += chunk;
      echo?.(chunk);
    });
    const cancel = token?.onCancellationRequested(() => child.kill());
    child.on("error", (error) => {
      cancel?.dispose();
      reject(error);
    });
    child.on("close", (code) => {
      cancel?.dispose();
      resolve({ code, stdout, stderr, cancelled: token?.isCancellationRequested ?? false });
    });
  });
}
