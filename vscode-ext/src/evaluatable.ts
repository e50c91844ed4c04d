// What hovering a Mint program while paused shows the value of: a name with its axis or element, so
// POS.0, POS[1], total and table(3) are evaluated whole rather than as POS, total and table.
// No vscode import: the unit tests run under plain node.

/** A name, with an axis (`.0`, `[1]`) or a literal element or channel index (`(3)`) if one follows it. */
const EVALUATABLE = /[A-Za-z_][A-Za-z0-9_]*(?:\.\d+|\(\s*\d+\s*\)|\[\s*\d+\s*\])?/g;

/** An address the hover cannot take whole (`POS[0,1]`, `POS.ax`, `POS(a)`, `table(i)`): without it the bare
 * name would read the default axis, or be no value at all. */
const OTHER_ADDRESS = /^\s*[.[(]/;

/** The [start, end) of the expression under `character` in `line`, if the cursor is on one. */
export function evaluatableAt(line: string, character: number): readonly [number, number] | undefined {
  for (const match of line.matchAll(EVALUATABLE)) {
    const start = match.index ?? 0;
    const end = start + match[0].length;
    if (start <= character && character < end) {
      return OTHER_ADDRESS.test(line.slice(end)) ? undefined : [start, end];
    }
  }
  return undefined;
}
