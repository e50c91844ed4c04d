// The extension's settings as plain values, read once per use so that changes apply at once.
// No vscode import: the unit tests run under plain node.

export const CONTROLLERS = ["nextmove-pci", "nextmove-pc", "nextmove-bx", "mintdrive", "servonode51"] as const;
export const DIALECTS = ["v4", "v3"] as const;

export type Controller = (typeof CONTROLLERS)[number];
export type Dialect = (typeof DIALECTS)[number];

export interface MintSettings {
  readonly serverPath: string;
  readonly pythonPath: string;
  readonly controller: Controller;
  readonly dialect: Dialect;
  readonly pairConfigFiles: boolean;
  /** The configuration file of `<name>.mnt`; without `<name>`, programs have none (as in the server). */
  readonly configPairing: string;
  readonly debounceMs: number;
}

/** Settings that change which server runs: the client restarts when one of them changes. */
export const SERVER_SETTINGS = ["mint.serverPath", "mint.pythonPath"] as const;

/**
 * What the server is told at start-up: every setting it reads (lsp/workspace.py,
 * Settings.from_options), so the files open at start are checked with them from the first
 * diagnostics on. Later changes reach it through workspace/didChangeConfiguration.
 */
export interface InitializationOptions {
  readonly controller: Controller;
  readonly dialect: Dialect;
  readonly configPairing: string;
  readonly debounceMs: number;
}

/** The `mint` configuration section; vscode.WorkspaceConfiguration is one. */
export interface Section {
  get(key: string): unknown;
}

const oneOf = <T extends string>(choices: readonly T[], value: unknown, fallback: T): T =>
  choices.find((choice) => choice === value) ?? fallback;

const text = (value: unknown): string => (typeof value === "string" ? value.trim() : "");

/** Reads the settings; a value of the wrong type (a hand-edited settings.json) falls back to the default. */
export function readSettings(section: Section): MintSettings {
  const pair = section.get("pairConfigFiles");
  const pairing = section.get("configPairing");
  const debounce = section.get("debounceMs");
  return {
    serverPath: text(section.get("serverPath")),
    pythonPath: text(section.get("pythonPath")),
    controller: oneOf(CONTROLLERS, section.get("controller"), "nextmove-pci"),
    dialect: oneOf(DIALECTS, section.get("dialect"), "v4"),
    pairConfigFiles: typeof pair === "boolean" ? pair : true,
    configPairing: typeof pairing === "string" ? pairing.trim() : "<name>.cfg",
    debounceMs: typeof debounce === "number" && Number.isInteger(debounce) && debounce >= 0 ? debounce : 150,
  };
}

export function initializationOptions(settings: MintSettings): InitializationOptions {
  const { controller, dialect, configPairing, debounceMs } = settings;
  return { controller, dialect, configPairing, debounceMs };
}
