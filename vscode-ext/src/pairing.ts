// Which .cfg files are Mint. `.cfg` is too common an extension to claim for every file, but a
// configuration file named like a program beside it (conveyor.cfg next to conveyor.mnt) is the
// controller's configuration for that program. No vscode import: unit-tested under plain node.
import * as path from "node:path";

/**
 * Whether `fileName` is a .cfg file with a same-named .mnt file in its folder. `listFolder` is
 * only called for .cfg files; names compare without case, as on the DOS-era tools Mint comes from.
 */
export function isPairedConfig(fileName: string, listFolder: (folder: string) => readonly string[]): boolean {
  const extension = path.extname(fileName);
  if (extension.toLowerCase() !== ".cfg") {
    return false;
  }
  const program = `${path.basename(fileName, extension)}.mnt`.toLowerCase();
  return listFolder(path.dirname(fileName)).some((name) => name.toLowerCase() === program);
}
