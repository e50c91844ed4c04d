// Which files are a program's configuration. `.cfg` is too common an extension to claim for
// every file, but a configuration file named like a program beside it (conveyor.cfg next to
// conveyor.mnt) is the controller's configuration for that program. The name follows the
// mint.configPairing setting, read the way the language server reads it (lsp/workspace.py,
// partner()), so the editor and the server agree on which file is paired with which.
// No vscode import: unit-tested under plain node.
import * as path from "node:path";

export const DEFAULT_PAIRING = "<name>.cfg";
const PROGRAM_SUFFIX = ".mnt";

/** The text before and after `<name>` in a pairing pattern, or undefined when it has no `<name>`. */
function splitPattern(pattern: string): { prefix: string; suffix: string } | undefined {
  const at = pattern.indexOf("<name>");
  return at < 0 ? undefined : { prefix: pattern.slice(0, at), suffix: pattern.slice(at + "<name>".length) };
}

/**
 * The program name `fileName` would be the configuration of under `pattern` ("conveyor" for
 * conveyor.cfg under "<name>.cfg"), or undefined. As in the server, the prefix compares with
 * case and the suffix without.
 */
function programStem(fileName: string, pattern: string): string | undefined {
  const parts = splitPattern(pattern);
  const name = path.basename(fileName);
  if (parts === undefined || parts.suffix === "" || name.toLowerCase().endsWith(PROGRAM_SUFFIX)) {
    return undefined;
  }
  const { prefix, suffix } = parts;
  if (!name.startsWith(prefix) || !name.toLowerCase().endsWith(suffix.toLowerCase())) {
    return undefined;
  }
  const stem = name.slice(prefix.length, name.length - suffix.length);
  return stem === "" ? undefined : stem;
}

/**
 * Whether `fileName` is the configuration file of a program in its folder under `pattern`
 * (mint.configPairing). `listFolder` is only called for names that fit the pattern; program
 * names compare without case, as on the DOS-era tools Mint comes from.
 */
export function isPairedConfig(
  fileName: string,
  listFolder: (folder: string) => readonly string[],
  pattern: string = DEFAULT_PAIRING,
): boolean {
  const stem = programStem(fileName, pattern);
  if (stem === undefined) {
    return false;
  }
  const program = `${stem}${PROGRAM_SUFFIX}`.toLowerCase();
  return listFolder(path.dirname(fileName)).some((name) => name.toLowerCase() === program);
}

/**
 * The configuration file of the program `programFile` under `pattern`, if it is in the program's
 * folder: what `mint-run --config` gets. The name is exact, as the server builds it for its
 * "Run in simulator" lens and its checks (conveyor.mnt -> conveyor.cfg).
 */
export function configurationOf(
  programFile: string,
  listFolder: (folder: string) => readonly string[],
  pattern: string = DEFAULT_PAIRING,
): string | undefined {
  const parts = splitPattern(pattern);
  const extension = path.extname(programFile);
  if (parts === undefined || parts.suffix === "" || extension.toLowerCase() !== PROGRAM_SUFFIX) {
    return undefined;
  }
  const folder = path.dirname(programFile);
  const wanted = `${parts.prefix}${path.basename(programFile, extension)}${parts.suffix}`;
  return listFolder(folder).includes(wanted) ? path.join(folder, wanted) : undefined;
}
