// What `mint test` prints, read into plain values for the Testing view: the tests it found
// (`--collect-only --format json`), their outcomes (`--format json`) and the lcov tracefile of
// `--coverage`. No vscode import: the unit tests run under plain node.

/** A test as `mint test --collect-only` lists it: a program, with the scenario file beside it if any. */
export interface CollectedTest {
  readonly program: string;
  readonly scenario: string | undefined;
}

export type Verdict = "passed" | "failed" | "error";

/** A place in a file, lines counted from 1 as `mint test` prints them. */
export interface Place {
  readonly file: string;
  readonly line: number;
}

/** Why a test did not pass, with the expectation's place when it has one. */
export interface Failure {
  readonly message: string;
  readonly place: Place | undefined;
}

export interface TestOutcome {
  readonly program: string;
  readonly verdict: Verdict;
  readonly seconds: number;
  readonly failures: readonly Failure[];
}

/** The coverage of one file, as the lcov tracefile gives it. */
export interface FileCoverageData {
  readonly file: string;
  /** Hits per line (DA records). */
  readonly lines: ReadonlyMap<number, number>;
  /** Each branch outcome (BRDA records): its line, and how often it was taken. */
  readonly branches: readonly { readonly line: number; readonly label: string; readonly taken: number }[];
  /** Each event handler (FN and FNDA records): its name, line and how often it ran. */
  readonly handlers: readonly { readonly name: string; readonly line: number; readonly runs: number }[];
}

/** Raised when `mint test` printed something that is not its report: the message says what. */
export class UnreadableReport extends Error {}

function parseObject(text: string, what: string): Record<string, unknown> {
  let value: unknown;
  try {
    value = JSON.parse(text);
  } catch {
    throw new UnreadableReport(`mint test printed no ${what} (not JSON): ${text.slice(0, 200)}`);
  }
  if (typeof value !== "object" || value === null || Array.isArray(value)) {
    throw new UnreadableReport(`mint test printed no ${what}: a JSON object was expected`);
  }
  return value as Record<string, unknown>;
}

function entries(report: Record<string, unknown>, what: string): Record<string, unknown>[] {
  const tests = report["tests"];
  if (!Array.isArray(tests) || !tests.every((test) => typeof test === "object" && test !== null)) {
    throw new UnreadableReport(`mint test printed no ${what}: "tests" is not a list of objects`);
  }
  return tests as Record<string, unknown>[];
}

function text(value: unknown, field: string): string {
  if (typeof value !== "string") {
    throw new UnreadableReport(`mint test's report has no text "${field}"`);
  }
  return value;
}

/** The tests `mint test --collect-only --format json` found. */
export function parseCollected(output: string): CollectedTest[] {
  return entries(parseObject(output, "list of tests"), "list of tests").map((test) => ({
    program: text(test["program"], "program"),
    scenario: test["scenario"] === null ? undefined : text(test["scenario"], "scenario"),
  }));
}

/** `/cell/cell.mnt:12` as a place; undefined for an origin that names no line (a scenario's `[[expect]]`). */
export function parsePlace(origin: string): Place | undefined {
  const match = /^(.*):(\d+)$/.exec(origin);
  return match?.[1] === undefined || match[2] === undefined ? undefined : { file: match[1], line: Number(match[2]) };
}

const VERDICTS: readonly Verdict[] = ["passed", "failed", "error"];

/** Where the run stopped short (an error, a deadlock, a program refused): `place`, absent from older reports. */
function stopPlace(test: Record<string, unknown>): Place | undefined {
  const place = test["place"];
  return typeof place === "string" ? parsePlace(place) : undefined;
}

function failuresOf(test: Record<string, unknown>, verdict: Verdict): Failure[] {
  const message = text(test["message"], "message");
  if (verdict === "error") {
    return [{ message, place: stopPlace(test) }];
  }
  const checks = Array.isArray(test["checks"]) ? (test["checks"] as Record<string, unknown>[]) : [];
  const failed = checks
    .filter((check) => check["held"] === false)
    .map((check) => {
      const detail = typeof check["detail"] === "string" && check["detail"] !== "" ? ` (${check["detail"]})` : "";
      const line = `${text(check["what"], "what")} at ${text(check["when"], "when")}: expected ${text(check["expected"], "expected")}, got ${text(check["actual"], "actual")}${detail}`;
      return { message: line, place: parsePlace(text(check["origin"], "origin")) };
    });
  // The run stopped otherwise than it should (an error, a deadlock): said by `stop_failed`, besides any
  // expectation that failed; an older report without it says so only when every expectation held.
  const stopFailed = typeof test["stop_failed"] === "boolean" ? test["stop_failed"] : failed.length === 0;
  if (verdict === "failed" && stopFailed) {
    const stopped = text(test["stopped"], "stopped");
    return [...failed, { message: `stopped ${stopped}${message === "" ? "" : `: ${message}`}`, place: stopPlace(test) }];
  }
  return failed;
}

/** The outcome of each test in `mint test --format json`'s report. */
export function parseOutcomes(output: string): TestOutcome[] {
  return entries(parseObject(output, "report"), "report").map((test) => {
    const verdict = test["verdict"];
    if (!VERDICTS.includes(verdict as Verdict)) {
      throw new UnreadableReport(`mint test's report has an unknown verdict: ${String(verdict)}`);
    }
    return {
      program: text(test["program"], "program"),
      verdict: verdict as Verdict,
      seconds: typeof test["seconds"] === "number" ? test["seconds"] : 0,
      failures: failuresOf(test, verdict as Verdict),
    };
  });
}

interface Building {
  file: string;
  lines: Map<number, number>;
  branches: { line: number; label: string; taken: number }[];
  handlers: Map<string, { name: string; line: number; runs: number }>;
}

/**
 * The records of an lcov tracefile (the subset `mint test --coverage` writes: SF, DA, BRDA, FN, FNDA,
 * end_of_record; summary records such as LF and BRH are derived, so they are skipped).
 */
export function parseLcov(tracefile: string): FileCoverageData[] {
  const files: FileCoverageData[] = [];
  let current: Building | undefined;
  for (const raw of tracefile.split(/\r?\n/)) {
    const line = raw.trim();
    const colon = line.indexOf(":");
    const [tag, value] = colon < 0 ? [line, ""] : [line.slice(0, colon), line.slice(colon + 1)];
    if (tag === "SF") {
      current = { file: value, lines: new Map(), branches: [], handlers: new Map() };
    } else if (tag === "end_of_record" && current !== undefined) {
      files.push({ ...current, handlers: [...current.handlers.values()] });
      current = undefined;
    } else if (current !== undefined) {
      record(current, tag, value.split(","));
    }
  }
  return files;
}

function record(file: Building, tag: string, fields: string[]): void {
  if (tag === "DA") {
    file.lines.set(Number(fields[0]), Number(fields[1]));
  } else if (tag === "BRDA") {
    // BRDA:<line>,<block>,<branch>,<taken>; "-" when the line never ran.
    const taken = fields[3] === "-" ? 0 : Number(fields[3]);
    file.branches.push({ line: Number(fields[0]), label: fields[2] ?? "", taken });
  } else if (tag === "FN") {
    const name = fields.slice(1).join(",");
    file.handlers.set(name, { name, line: Number(fields[0]), runs: file.handlers.get(name)?.runs ?? 0 });
  } else if (tag === "FNDA") {
    const name = fields.slice(1).join(",");
    const known = file.handlers.get(name);
    if (known !== undefined) {
      known.runs = Number(fields[0]);
    }
  }
}
