// The debugger's launch configurations: what F5 debugs without a launch.json, and what the editor
// adds to one it is given (the configuration file the language server pairs with the program, the
// controller and dialect the user chose). No vscode import: the unit tests run under plain node.
import * as path from "node:path";

import type { ConfigurationChoice } from "./pairing";

/** The debug type the extension contributes; mint-dap serves it. */
export const DEBUG_TYPE = "mint";

/** The launch arguments mint-dap reads (runtime/debugger/launch.py). */
export interface MintLaunch {
  readonly type: string;
  readonly request: string;
  readonly name: string;
  readonly program: string;
  readonly config?: string;
  readonly noConfig?: boolean;
  readonly controller?: string;
  readonly dialect?: string;
  readonly stimulus?: readonly string[];
  readonly drives?: "enabled";
  readonly stopOnEntry?: boolean;
  readonly untilMs?: number;
}

/** The choices the user made in the settings, each undefined where they made none (mint.toml decides then). */
export interface Chosen {
  readonly controller: string | undefined;
  readonly dialect: string | undefined;
  /** Whether the user set mint.configPairing (to anything, empty included). */
  readonly configPairing: boolean;
}

export type Completion = { readonly ok: true; readonly launch: MintLaunch } | { readonly ok: false; readonly message: string };

/** The configuration "Debug in simulator" and F5 without a launch.json start: the program, stopped at its first statement. */
export function launchFor(program: string): MintLaunch {
  return { type: DEBUG_TYPE, request: "launch", name: `Debug ${path.basename(program)}`, program, stopOnEntry: true };
}

/**
 * `given` made whole: a configuration with no program debugs `activeFile`; the controller and dialect the
 * settings choose, and the configuration file `pairing` gives for the program (see configurationChoice in
 * ./pairing; undefined leaves it to mint-dap), are added where `given` says nothing of them.
 */
export async function completeLaunch(
  given: Readonly<Record<string, unknown>>,
  activeFile: string | undefined,
  chosen: Chosen,
  pairing: (program: string) => Promise<ConfigurationChoice | undefined>,
): Promise<Completion> {
  const empty = given["type"] === undefined && given["request"] === undefined && given["program"] === undefined;
  const program = typeof given["program"] === "string" && given["program"] !== "" ? given["program"] : activeFile;
  if (program === undefined || (empty && path.extname(program).toLowerCase() !== ".mnt")) {
    return { ok: false, message: "open a Mint program (.mnt) to debug, or name one as 'program' in launch.json." };
  }
  const base = empty ? launchFor(program) : { ...given, type: DEBUG_TYPE, request: "launch", program };
  const launch: Record<string, unknown> = { name: `Debug ${path.basename(program)}`, ...base };
  if (launch["config"] === undefined && launch["noConfig"] !== true) {
    Object.assign(launch, await pairing(program));
  }
  if (launch["controller"] === undefined && chosen.controller !== undefined) {
    launch["controller"] = chosen.controller;
  }
  if (launch["dialect"] === undefined && chosen.dialect !== undefined) {
    launch["dialect"] = chosen.dialect;
  }
  return { ok: true, launch: launch as unknown as MintLaunch };
}

/** What `launch` tells mint-dap of the configuration file; undefined where mint-dap pairs the program itself. */
export const launchConfiguration = (launch: MintLaunch): ConfigurationChoice | undefined =>
  launch.config !== undefined ? { config: launch.config } : launch.noConfig === true ? { noConfig: true } : undefined;
