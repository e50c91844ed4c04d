// Which configuration file goes with which program, as the language server pairs them for its checks:
// its mint.applicationFiles command answers from the user's mint.configPairing over the project's
// mint.toml (config-pairing, config), by the rule mint check and mint-run follow (mintlang/pairing.py).
// The editor asks it rather than pairing files by a rule of its own, so that Run in simulator, the
// debugger and the .cfg files opened as Mint agree with what the server checks and mint-run runs.
// No vscode import: unit-tested under plain node.

/** The server's command that answers which program and configuration file a file goes with. */
export const APPLICATION_FILES = "mint.applicationFiles";

/**
 * A program and its configuration file, as file URIs written as the editor wrote the one it asked about
 * (null: none), and the dialect the server reads the program in (null without a program).
 */
export interface ApplicationFiles {
  readonly program: string | null;
  readonly configuration: string | null;
  readonly dialect: string | null;
}

/** Sends a request to the language server; vscode-languageclient's LanguageClient.sendRequest is one. */
export type SendRequest = (method: string, params: unknown) => Promise<unknown>;

const uriOrNull = (value: unknown): value is string | null => value === null || typeof value === "string";

/** The files the server says `uri` goes with; undefined when its answer is not one. */
export async function askApplicationFiles(send: SendRequest, uri: string): Promise<ApplicationFiles | undefined> {
  const answer = await send("workspace/executeCommand", { command: APPLICATION_FILES, arguments: [uri] });
  if (typeof answer !== "object" || answer === null) {
    return undefined;
  }
  const { program, configuration, dialect } = answer as Record<string, unknown>;
  if (!uriOrNull(program) || !uriOrNull(configuration)) {
    return undefined;
  }
  return { program, configuration, dialect: typeof dialect === "string" ? dialect : null };
}

/** What a tool is told of a program's configuration file: a file, or none. */
export type ConfigurationChoice = { readonly config: string } | { readonly noConfig: true };

/**
 * What a tool run on a program (mint-run, mint-dap) is told of its configuration file, from the server's
 * answer for the program (`toPath` turns its URI into the path the tool takes), where the user set
 * mint.configPairing (`userPairs`): the editor's setting then wins over the project's mint.toml, as in
 * the server. Otherwise undefined, as without an answer: the tool pairs the program itself by the
 * project's settings, as the server does without the setting, and as mint-run does on the command line
 * (its own table's config or no-config, [tool.mint.run], included).
 */
export function configurationChoice(
  files: ApplicationFiles | undefined,
  userPairs: boolean,
  toPath: (uri: string) => string,
): ConfigurationChoice | undefined {
  if (!userPairs || files === undefined) {
    return undefined;
  }
  return files.configuration === null ? { noConfig: true } : { config: toPath(files.configuration) };
}

/** Whether the file the server was asked about, `uri`, is a program's configuration file by its answer `files`. */
export const isConfigurationFile = (uri: string, files: ApplicationFiles | undefined): boolean =>
  files !== undefined && files.configuration === uri && files.program !== uri;

/**
 * The dialect a run of the program is told: the user's mint.dialect, `auto` made the one the server reads
 * the program in (its text shows it; undefined without an answer, which leaves it to the tool and mint.toml).
 */
export function runDialect(chosen: string | undefined, files: ApplicationFiles | undefined): string | undefined {
  return chosen === "auto" ? (files?.dialect ?? undefined) : chosen;
}

/**
 * Whether a file open with unsaved changes is saved before `program` runs, mint-run and mint-dap reading
 * files from disk: the program and its configuration file, the one `config` names, or any .cfg where the
 * tool pairs the program itself.
 */
export const savedBeforeRun =
  (program: string, config: ConfigurationChoice | undefined) =>
  (file: string): boolean => {
    if (config === undefined) {
      return file === program || file.toLowerCase().endsWith(".cfg");
    }
    return file === program || ("config" in config && file === config.config);
  };
