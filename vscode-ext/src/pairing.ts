// Which files are a program's configuration. `.cfg` is too common an extension to claim for
// every file, but a configuration file named like a program beside it (conveyor.cfg next to
// conveyor.mnt) is the controller's configuration for that program. The name follows the
// mint.configPairing setting, read the way the language server reads it (lsp/workspace.py,
// partner()), so the editor and the server agree on which file is paired with which; as there,
// the pair is found whatever the case of the names (APP.MNT with app.cfg), as on the Windows PCs
// Mint programs come from. No vscode import: unit-tested under plain node.
import * as path from "node:path";

export const DEFAULT_PAIRING = "<name>.cfg";
const PROGRAM_SUFFIX = ".mnt";

/** The text before and after `<name>` in a pairing pattern, or undefined when it has no `<name>`. */
function splitPattern(pattern: string): { prefix: string; suffix: string } | undefined {
  const at = pattern.indexOf("<name>");
  return at < 0 ? undefined : { prefix: pattern.slice(0, at), suffix: pattern.slice(at + "<name>".length) };
}

/** Whether `name` is a program's: a program is never a configuration file, whatever the pattern says. */
const isProgram = (name: string): boolean => name.toLowerCase().endsWith(PROGRAM_SUFFIX);

/**
 * `name` in `folder` as it is listed there: that exact name, else one differing only in case (as
 * the server's _sibling()), so the path handed to a tool names a file that exists.
 */
function sibling(folder: string, name: string, listFolder: (folder: string) => readonly string[]): string | undefined {
  const names = listFolder(folder);
  const listed = names.includes(name) ? name : names.find((other) => other.toLowerCase() === name.toLowerCase());
  return listed === undefined ? undefined : path.join(folder, listed);
}

/**
 * The program name `fileName` would be the configuration of under `pattern` ("conveyor" for
 * conveyor.cfg under "<name>.cfg"), or undefined. As in the server, the prefix compares with
 * case and the suffix without.
 */
function programStem(fileName: string, pattern: string): string | undefined {
  const parts = splitPattern(pattern);
  const name = path.basename(fileName);
  if (parts === undefined || parts.suffix === "" || isProgram(name)) {
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
 * The program whose configuration file `fileName` is under `pattern` (mint.configPairing), if it
 * is in the same folder. `listFolder` is only called for names that fit the pattern.
 */
export function programOf(
  fileName: string,
  listFolder: (folder: string) => readonly string[],
  pattern: string = DEFAULT_PAIRING,
): string | undefined {
  const stem = programStem(fileName, pattern);
  return stem === undefined ? undefined : sibling(path.dirname(fileName), `${stem}${PROGRAM_SUFFIX}`, listFolder);
}

/** Whether `fileName` is the configuration file of a program in its folder under `pattern` (mint.configPairing). */
export function isPairedConfig(
  fileName: string,
  listFolder: (folder: string) => readonly string[],
  pattern: string = DEFAULT_PAIRING,
): boolean {
  return programOf(fileName, listFolder, pattern) !== undefined;
}

/**
 * The configuration file of the program `programFile` under `pattern`, if it is in the program's
 * folder: what the tools get with `--config` (conveyor.mnt -> conveyor.cfg), as the server pairs
 * them for its checks, its "Run in simulator" lens and its migration.
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
  const wanted = `${parts.prefix}${path.basename(programFile, extension)}${parts.suffix}`;
  return isProgram(wanted) ? undefined : sibling(path.dirname(programFile), wanted, listFolder);
}

/** What a tool is told of a program's configuration file: a file, or none. */
export type ConfigurationChoice = { readonly config: string } | { readonly noConfig: true };

/**
 * What a tool run on `programFile` (mint-run, mint-dap) is told of its configuration file: the file the
 * user's own mint.configPairing (`pairing`) pairs with it, or none when that pairs none (the setting empty,
 * or no such file). Undefined when the user set no pairing: the tool then pairs the program itself, by the
 * project's settings file (mint.toml's config-pairing or config) or `<name>.cfg`, as the server does; the
 * setting's own default must not override the project.
 */
export function chosenConfiguration(
  programFile: string,
  pairing: string | undefined,
  listFolder: (folder: string) => readonly string[],
): ConfigurationChoice | undefined {
  if (pairing === undefined) {
    return undefined;
  }
  const config = configurationOf(programFile, listFolder, pairing);
  return config === undefined ? { noConfig: true } : { config };
}
