// Finds the mintlang programs (the language server and the command-line tools) from the
// settings and the file system, and builds their command lines. No vscode import: the host
// is passed in, so the unit tests can describe any file system and platform.
import * as path from "node:path";

import type { Chosen } from "./launch";
import type { ConfigurationChoice } from "./pairing";
import type { MintSettings } from "./settings";

export type Tool = "mint-lsp" | "mint-run" | "mint-dap" | "mint";
export type FileTool = Exclude<Tool, "mint-lsp" | "mint-dap" | "mint">;

/** The Python module behind each tool: what Python names when mintlang is not installed. */
export const MODULES: Readonly<Record<Tool, string>> = {
  "mint-lsp": "mintlang.lsp",
  "mint-run": "mintlang.runtime",
  "mint-dap": "mintlang.runtime.debugger",
  mint: "mintlang",
};

/** How `mint.pythonPath` runs each tool. */
export const PYTHON_ARGUMENTS: Readonly<Record<Tool, readonly string[]>> = {
  "mint-lsp": ["-m", "mintlang.lsp"],
  "mint-run": ["-m", "mintlang.runtime"],
  "mint-dap": ["-m", "mintlang.runtime.debugger"],
  mint: ["-m", "mintlang"],
};

/** What resolution needs to know about the machine. */
export interface Host {
  readonly platform: NodeJS.Platform;
  readonly pathEnv: string;
  /** Folders whose .venv may be run: empty in an untrusted workspace. */
  readonly workspaceFolders: readonly string[];
  isExecutable(file: string): boolean;
}

export interface Command {
  readonly command: string;
  readonly args: readonly string[];
  /** Where it was found, for messages: "mint.serverPath", "PATH", ... */
  readonly source: string;
}

export type Resolution =
  | { readonly ok: true; readonly command: Command }
  | { readonly ok: false; readonly message: string };

type ToolSettings = Pick<MintSettings, "serverPath" | "pythonPath">;

const pathsOf = (host: Host): path.PlatformPath => (host.platform === "win32" ? path.win32 : path.posix);

const found = (command: string, args: readonly string[], source: string): Resolution => ({
  ok: true,
  command: { command, args, source },
});

/** `name` in `folder`, if an executable of that name is there; Windows console scripts are .exe files. */
function findIn(folder: string, name: string, host: Host): string | undefined {
  const paths = pathsOf(host);
  const names = host.platform === "win32" && paths.extname(name) === "" ? [`${name}.exe`, name] : [name];
  return names.map((candidate) => paths.join(folder, candidate)).find((candidate) => host.isExecutable(candidate));
}

function searchPath(name: string, host: Host): string | undefined {
  for (const folder of host.pathEnv.split(pathsOf(host).delimiter)) {
    const match = folder === "" ? undefined : findIn(folder, name, host);
    if (match !== undefined) {
      return match;
    }
  }
  return undefined;
}

/**
 * The executable a setting names: a bare name ("python3") is looked up on PATH; a relative
 * path and ${workspaceFolder} are taken from the first workspace folder, as in VS Code's own settings.
 */
function locateSetting(value: string, host: Host): string | undefined {
  const paths = pathsOf(host);
  const folder = host.workspaceFolders[0];
  const expanded = folder === undefined ? value : value.replace(/\$\{workspaceFolder\}/g, folder);
  if (!/[\\/]/.test(expanded)) {
    return searchPath(expanded, host);
  }
  const absolute = paths.isAbsolute(expanded) ? expanded : folder === undefined ? undefined : paths.join(folder, expanded);
  return absolute !== undefined && host.isExecutable(absolute) ? absolute : undefined;
}

const notExecutable = (setting: string, value: string): Resolution => ({
  ok: false,
  message: `${setting} is set to '${value}', which is not an executable file.`,
});

/**
 * Finds `tool`, in this order: mint.serverPath (the tools: beside that executable, where a
 * virtual environment keeps its console scripts), mint.pythonPath with `-m`, the workspace's
 * .venv, PATH. A setting naming a missing file is an error rather than skipped: the user asked
 * for that program, and quietly running another one would hide the mistake.
 */
export function resolveTool(tool: Tool, settings: ToolSettings, host: Host): Resolution {
  const paths = pathsOf(host);
  if (settings.serverPath !== "") {
    const server = locateSetting(settings.serverPath, host);
    if (tool === "mint-lsp") {
      return server === undefined ? notExecutable("mint.serverPath", settings.serverPath) : found(server, [], "mint.serverPath");
    }
    const beside = server === undefined ? undefined : findIn(paths.dirname(server), tool, host);
    if (beside !== undefined) {
      return found(beside, [], "mint.serverPath");
    }
  }
  if (settings.pythonPath !== "") {
    const python = locateSetting(settings.pythonPath, host);
    return python === undefined
      ? notExecutable("mint.pythonPath", settings.pythonPath)
      : found(python, PYTHON_ARGUMENTS[tool], "mint.pythonPath");
  }
  const venvs = host.workspaceFolders.map((folder) => paths.join(folder, ".venv"));
  for (const venv of venvs) {
    const script = findIn(paths.join(venv, host.platform === "win32" ? "Scripts" : "bin"), tool, host);
    if (script !== undefined) {
      return found(script, [], "the workspace's .venv");
    }
  }
  const onPath = searchPath(tool, host);
  if (onPath !== undefined) {
    return found(onPath, [], "PATH");
  }
  return {
    ok: false,
    message:
      `${tool} was not found (searched ${[...venvs, "PATH"].join(", ")}). ` +
      "Install mintlang into the workspace's .venv, or set mint.serverPath or mint.pythonPath.",
  };
}

/** The controller and dialect the user set, each undefined where they set none. */
export type Choices = Pick<Chosen, "controller" | "dialect">;

/**
 * The arguments a command-line tool takes for one file, and what it is told of the program's
 * configuration file (`config`: undefined leaves the pairing to the tool and the project). The
 * controller and dialect are passed only where the user chose them (`chosen`, as the debugger takes
 * them): unset, the project's mint.toml decides, and a v3 project is not run on the v4 default
 * controller. `auto`, which mint-run does not take, is not passed (Run in simulator makes it the dialect
 * the server reads the program in first: runDialect in ./pairing).
 * A simulated run starts from the configuration file, as the server's "Run in simulator" lens does,
 * and is bounded in real time, so a program that never ends cannot hang the editor.
 */
export function toolArguments(_tool: FileTool, file: string, chosen: Choices, config?: ConfigurationChoice): string[] {
  const configuration = config === undefined ? [] : "config" in config ? ["--config", config.config] : ["--no-config"];
  const controller = chosen.controller === undefined ? [] : ["--controller", chosen.controller];
  const dialect = chosen.dialect === undefined || chosen.dialect === "auto" ? [] : ["--dialect", chosen.dialect];
  return [...configuration, ...controller, ...dialect, "--max-wall-s", "30", file];
}

/** The command line that runs `tool` on `file` (told of its configuration file by `config`), or why there is none. */
export function fileCommand(
  tool: FileTool,
  file: string,
  settings: ToolSettings,
  chosen: Choices,
  host: Host,
  config?: ConfigurationChoice,
): Resolution {
  const resolution = resolveTool(tool, settings, host);
  if (!resolution.ok) {
    return resolution;
  }
  const { command, args, source } = resolution.command;
  return found(command, [...args, ...toolArguments(tool, file, chosen, config)], source);
}

/** What the Testing view asks `mint test` for: the tests under `paths`, listed or run (with coverage into `lcov`). */
export type TestRequest =
  | { readonly collectOnly: true; readonly paths: readonly string[] }
  | { readonly collectOnly: false; readonly paths: readonly string[]; readonly lcov?: string };

/**
 * The command line of `mint test` for `request`, reporting in JSON. Controller and dialect are left to
 * the programs' settings files, so the editor runs the tests exactly as `mint test` in CI does.
 */
export function testCommand(request: TestRequest, settings: ToolSettings, host: Host): Resolution {
  const resolution = resolveTool("mint", settings, host);
  if (!resolution.ok) {
    return resolution;
  }
  const { command, args, source } = resolution.command;
  const mode = request.collectOnly ? ["--collect-only"] : request.lcov === undefined ? [] : ["--coverage", "--lcov", request.lcov];
  return found(command, [...args, "test", "--format", "json", ...mode, "--", ...request.paths], source);
}

/**
 * Whether a mint.pythonPath run failed because the tool's module, or mintlang itself, is not
 * installed: Python then prints "No module named mintlang.runtime" before the tool could start.
 */
export function isMissingModule(stderr: string, tool: Tool): boolean {
  const wanted = MODULES[tool];
  return [...stderr.matchAll(/No module named '?([\w.]+)'?/g)].some(
    ([, name]) => name !== undefined && (name === wanted || wanted.startsWith(`${name}.`)),
  );
}

/** A command line as a POSIX shell user would type it, for the output channel. */
export function displayCommand(command: Command): string {
  return [command.command, ...command.args]
    .map((part) => (/^[\w@%+=:,./-]+$/.test(part) ? part : `'${part.replace(/'/g, "'\\''")}'`))
    .join(" ");
}
