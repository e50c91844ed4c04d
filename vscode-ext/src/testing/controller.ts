// The Testing view: the tests `mint test` finds in each workspace folder, run (or run with coverage)
// by `mint test` itself, so the editor shows what CI would. Reading its output is ./reports.ts's job.
import * as fs from "node:fs";
import * as os from "node:os";
import * as path from "node:path";
import * as vscode from "vscode";

import { currentHost, currentSettings } from "../host";
import { showError } from "../notify";
import { execute, type Finished } from "../process";
import { displayCommand, testCommand, type TestRequest } from "../resolve";
import {
  parseCollected,
  parseLcov,
  parseOutcomes,
  UnreadableReport,
  type FileCoverageData,
  type TestOutcome,
} from "./reports";

const NO_TESTS = 5; // mint test's exit status when it found nothing
const REDISCOVER_AFTER_MS = 500; // a save of many files, or a checkout, lists the tests once

/** A coverage figure VS Code draws per file, with the statements and branches behind it. */
class MintFileCoverage extends vscode.FileCoverage {
  constructor(readonly data: FileCoverageData) {
    const lines = [...data.lines.values()];
    super(
      vscode.Uri.file(data.file),
      new vscode.TestCoverageCount(lines.filter((hits) => hits > 0).length, lines.length),
      new vscode.TestCoverageCount(data.branches.filter((branch) => branch.taken > 0).length, data.branches.length),
      new vscode.TestCoverageCount(data.handlers.filter((handler) => handler.runs > 0).length, data.handlers.length),
    );
  }

  details(): vscode.FileCoverageDetail[] {
    const at = (line: number): vscode.Position => new vscode.Position(line - 1, 0);
    const statements = [...this.data.lines].map(([line, hits]) => {
      const branches = this.data.branches
        .filter((branch) => branch.line === line)
        .map((branch) => new vscode.BranchCoverage(branch.taken, undefined, `outcome ${Number(branch.label) + 1}`));
      return new vscode.StatementCoverage(hits, at(line), branches);
    });
    const handlers = this.data.handlers.map((handler) => new vscode.DeclarationCoverage(handler.name, handler.runs, at(handler.line)));
    return [...statements, ...handlers];
  }
}

export class MintTests implements vscode.Disposable {
  private readonly controller = vscode.tests.createTestController("mint", "Mint");
  private readonly disposables: vscode.Disposable[] = [this.controller];
  private pending: NodeJS.Timeout | undefined;

  constructor(private readonly output: vscode.OutputChannel) {
    this.controller.resolveHandler = async (item) => {
      if (item === undefined) {
        await this.discover();
      }
    };
    this.controller.refreshHandler = () => this.discover();
    this.controller.createRunProfile("Run", vscode.TestRunProfileKind.Run, (request, token) => this.run(request, token), true);
    const coverage = this.controller.createRunProfile(
      "Run with coverage",
      vscode.TestRunProfileKind.Coverage,
      (request, token) => this.run(request, token, true),
      true,
    );
    coverage.loadDetailedCoverage = async (_run, file) => (file instanceof MintFileCoverage ? file.details() : []);
    const watcher = vscode.workspace.createFileSystemWatcher("**/*.{mnt,MNT,toml}");
    const rediscover = (): void => {
      clearTimeout(this.pending);
      this.pending = setTimeout(() => void this.discover(), REDISCOVER_AFTER_MS);
    };
    this.disposables.push(watcher, watcher.onDidCreate(rediscover), watcher.onDidDelete(rediscover), watcher.onDidChange(rediscover));
  }

  dispose(): void {
    clearTimeout(this.pending);
    this.disposables.forEach((disposable) => disposable.dispose());
  }

  private folders(): string[] {
    return (vscode.workspace.workspaceFolders ?? []).filter((folder) => folder.uri.scheme === "file").map((folder) => folder.uri.fsPath);
  }

  /** `mint test` on `request` in `folder`; undefined (after telling the user why) when it could not run. */
  private async mintTest(request: TestRequest, folder: string, token?: vscode.CancellationToken): Promise<Finished | undefined> {
    const resolution = testCommand(request, currentSettings(), currentHost());
    if (!resolution.ok) {
      void showError(`Mint tests: ${resolution.message}`, this.output);
      return undefined;
    }
    this.output.appendLine(`$ ${displayCommand(resolution.command)}`);
    try {
      const finished = await execute(resolution.command, folder, token);
      this.output.append(finished.stderr);
      return finished;
    } catch (error) {
      const reason = error instanceof Error ? error.message : String(error);
      void showError(`Mint tests: ${resolution.command.command} could not be started: ${reason}`, this.output);
      return undefined;
    }
  }

  /** The tests of every workspace folder, one item per program under an item per folder. */
  private async discover(): Promise<void> {
    const folders = this.folders();
    const items: vscode.TestItem[] = [];
    for (const folder of folders) {
      const finished = await this.mintTest({ collectOnly: true, paths: [folder] }, folder);
      if (finished === undefined || finished.code === NO_TESTS) {
        continue;
      }
      let found;
      try {
        found = parseCollected(finished.stdout);
      } catch (error) {
        this.output.appendLine(error instanceof UnreadableReport ? error.message : String(error));
        continue;
      }
      const parent = this.controller.createTestItem(folder, path.basename(folder), vscode.Uri.file(folder));
      for (const test of found) {
        const item = this.controller.createTestItem(test.program, path.relative(folder, test.program), vscode.Uri.file(test.program));
        if (test.scenario !== undefined) {
          item.description = path.basename(test.scenario);
        }
        parent.children.add(item);
      }
      items.push(parent);
    }
    this.controller.items.replace(items);
  }

  /** The programs a request covers: the chosen items (a folder item stands for its tests), less the excluded. */
  private programs(request: vscode.TestRunRequest): vscode.TestItem[] {
    const chosen: vscode.TestItem[] = [];
    this.controller.items.forEach((folder) => chosen.push(folder));
    const roots = request.include ?? chosen;
    const excluded = new Set((request.exclude ?? []).map((item) => item.id));
    const programs: vscode.TestItem[] = [];
    for (const root of roots) {
      if (excluded.has(root.id)) {
        continue;
      }
      if (root.children.size === 0) {
        programs.push(root);
      }
      root.children.forEach((child) => {
        if (!excluded.has(child.id)) {
          programs.push(child);
        }
      });
    }
    return programs;
  }

  private async run(request: vscode.TestRunRequest, token: vscode.CancellationToken, coverage = false): Promise<void> {
    const run = this.controller.createTestRun(request);
    const programs = this.programs(request);
    programs.forEach((item) => run.started(item));
    const byFolder = new Map<string, vscode.TestItem[]>();
    for (const item of programs) {
      const folder = item.parent?.id ?? path.dirname(item.id);
      byFolder.set(folder, [...(byFolder.get(folder) ?? []), item]);
    }
    try {
      for (const [folder, items] of byFolder) {
        if (token.isCancellationRequested) {
          items.forEach((item) => run.skipped(item));
          continue;
        }
        await this.runFolder(run, folder, items, token, coverage);
      }
    } finally {
      run.end();
    }
  }

  private async runFolder(
    run: vscode.TestRun,
    folder: string,
    items: vscode.TestItem[],
    token: vscode.CancellationToken,
    coverage: boolean,
  ): Promise<void> {
    const scratch = coverage ? fs.mkdtempSync(path.join(os.tmpdir(), "mint-coverage-")) : undefined;
    const lcov = scratch === undefined ? undefined : path.join(scratch, "lcov.info");
    try {
      const request: TestRequest = { collectOnly: false, paths: items.map((item) => item.id), ...(lcov === undefined ? {} : { lcov }) };
      const finished = await this.mintTest(request, folder, token);
      if (finished === undefined || token.isCancellationRequested) {
        items.forEach((item) => run.skipped(item));
        return;
      }
      let outcomes: TestOutcome[];
      try {
        outcomes = parseOutcomes(finished.stdout);
      } catch (error) {
        const reason = error instanceof UnreadableReport ? error.message : String(error);
        items.forEach((item) => run.errored(item, new vscode.TestMessage(`${reason}\n${finished.stderr}`)));
        return;
      }
      this.report(run, items, outcomes);
      if (lcov !== undefined && fs.existsSync(lcov)) {
        parseLcov(fs.readFileSync(lcov, "utf8")).forEach((file) => run.addCoverage(new MintFileCoverage(file)));
      }
    } finally {
      if (scratch !== undefined) {
        fs.rmSync(scratch, { recursive: true, force: true });
      }
    }
  }

  private report(run: vscode.TestRun, items: vscode.TestItem[], outcomes: TestOutcome[]): void {
    const byProgram = new Map(outcomes.map((outcome) => [path.resolve(outcome.program), outcome]));
    for (const item of items) {
      const outcome = byProgram.get(path.resolve(item.id));
      if (outcome === undefined) {
        run.skipped(item); // no longer a test (its expectations were removed since it was listed)
        continue;
      }
      const duration = outcome.seconds * 1000;
      const messages = outcome.failures.map((failure) => {
        const message = new vscode.TestMessage(failure.message);
        if (failure.place !== undefined) {
          message.location = new vscode.Location(vscode.Uri.file(path.resolve(failure.place.file)), new vscode.Position(failure.place.line - 1, 0));
        }
        return message;
      });
      if (outcome.verdict === "passed") {
        run.passed(item, duration);
      } else if (outcome.verdict === "failed") {
        run.failed(item, messages, duration);
      } else {
        run.errored(item, messages, duration);
      }
    }
  }
}
