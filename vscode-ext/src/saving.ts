// Saves open documents before a tool reads their files from disk.
import * as vscode from "vscode";

/** Saves the files open with unsaved changes that `wanted` names; whether every one was saved. */
export async function saveOpen(wanted: (file: string) => boolean): Promise<boolean> {
  const unsaved = vscode.workspace.textDocuments.filter(
    (document) => document.uri.scheme === "file" && document.isDirty && wanted(document.uri.fsPath),
  );
  return (await Promise.all(unsaved.map((document) => document.save()))).every((saved) => saved);
}
