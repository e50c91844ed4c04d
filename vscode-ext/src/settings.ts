// The extension's settings as plain values, read once per use so that changes apply at once.
// No vscode import: the unit tests run under plain node.

export const CONTROLLERS = ["nextmove-pci", "nextmove-pc", "nextmove-bx", "mintdrive", "servonode51"] as const;
export const DIALECTS = ["v4", "v3", "mintmt"] as const;
/** What mint.dialect offers: a dialect, or `auto` (the server detects MintMT from each program's text). */
export const DIALECT_CHOICES = [...DIALECTS, "auto"] as const;

export type Controller = (typeof CONTROLLERS)[number];
export type DialectChoice = (typeof DIALECT_CHOICES)[number];

export interface MintSettings {
  readonly serverPath: string;
  readonly pythonPath: string;
  readonly controller: Controller;
  readonly dialect: DialectChoice;
  readonly pairConfigFiles: boolean;
  readonly debounceMs: number;
}

/** Settings that change which server runs: the client restarts when one of them changes. */
export const SERVER_SETTINGS = ["mint.serverPath", "mint.pythonPath"] as const;

/** The settings the server reads (lsp/workspace.py, Settings.from_options). */
export const SERVER_READS = ["controller", "dialect", "configPairing", "debounceMs", "select", "ignore", "rulesUrl"] as const;

/**
 * What the server is told, at start-up (initializationOptions) and whenever it asks
 * (workspace/configuration): each setting it reads as the user set it, or null where the user set
 * it nowhere. The server then takes a null setting from the project's settings file (mint.toml),
 * and from its own defaults without one: VS Code's defaults must not hide the project's choices.
 */
export type ServerSettings = Record<(typeof SERVER_READS)[number], unknown>;

/** The `mint` configuration section; vscode.WorkspaceConfiguration is one. */
export interface Section {
  get(key: string): unknown;
}

/** Where a setting is set; vscode.WorkspaceConfiguration.inspect gives this (and more). */
export interface Inspection {
  readonly globalValue?: unknown;
  readonly workspaceValue?: unknown;
  readonly workspaceFolderValue?: unknown;
}

/** A section that tells where each setting is set; vscode.WorkspaceConfiguration is one. */
export interface InspectableSection {
  inspect(key: string): Inspection | undefined;
}

const oneOf = <T extends string>(choices: readonly T[], value: unknown, fallback: T): T =>
  choices.find((choice) => choice === value) ?? fallback;

const text = (value: unknown): string => (typeof value === "string" ? value.trim() : "");

/** Reads the settings; a value of the wrong type (a hand-edited settings.json) falls back to the default. */
export function readSettings(section: Section): MintSettings {
  const pair = section.get("pairConfigFiles");
  const debounce = section.get("debounceMs");
  return {
    serverPath: text(section.get("serverPath")),
    pythonPath: text(section.get("pythonPath")),
    controller: oneOf(CONTROLLERS, section.get("controller"), "nextmove-pci"),
    dialect: oneOf(DIALECT_CHOICES, section.get("dialect"), "v4"),
    pairConfigFiles: typeof pair === "boolean" ? pair : true,
    debounceMs: typeof debounce === "number" && Number.isInteger(debounce) && debounce >= 0 ? debounce : 150,
  };
}

/** The server's settings as the user set them, the most specific scope winning (folder, workspace, user). */
export function serverSettings(section: InspectableSection): ServerSettings {
  const set = (key: string): unknown => {
    const found = section.inspect(key);
    return found?.workspaceFolderValue ?? found?.workspaceValue ?? found?.globalValue ?? null;
  };
  return Object.fromEntries(SERVER_READS.map((key) => [key, set(key)])) as ServerSettings;
}
