// What "Mint: Migrate file to v4" and "Mint: Replace v3 keywords" do with the source actions the
// language server offers for a file. The server offers the whole migration only for a file it
// finds to be Mint v3 (the mint.dialect setting, or v3 words and nothing only v4 has), and its
// edit needs confirmation: VS Code shows it in the refactor preview before anything changes. In a
// v4 file the server offers only the renames of its v3 keywords, and the user is asked first. No
// vscode import: the unit tests run under plain node.

export const MIGRATE_KIND = "source.migrateToV4";
export const REPLACE_KIND = "source.replaceV3Keywords";
export const REPLACE_ANSWER = "Replace v3 keywords";

/** What to do, for actions of any type `A` whose kind `kindOf` reads. */
export type Plan<A> =
  /** Apply the action's edit; one that needs confirmation (the whole migration's) opens the refactor preview. */
  | { readonly step: "apply"; readonly action: A }
  /** Ask `question`; apply the action if the user answers `answer`. */
  | { readonly step: "ask"; readonly action: A; readonly question: string; readonly answer: string }
  /** Nothing to apply: say `message`. */
  | { readonly step: "none"; readonly message: string };

function offered<A>(actions: readonly A[], kindOf: (action: A) => string | undefined, kind: string): A | undefined {
  return actions.find((action) => kindOf(action) === kind);
}

/** "Migrate file to v4" on the file named `file`, given the source actions the server offered for it. */
export function planMigration<A>(actions: readonly A[], kindOf: (action: A) => string | undefined, file: string): Plan<A> {
  const migration = offered(actions, kindOf, MIGRATE_KIND);
  if (migration !== undefined) {
    return { step: "apply", action: migration };
  }
  const replace = offered(actions, kindOf, REPLACE_KIND);
  if (replace !== undefined) {
    return {
      step: "ask",
      action: replace,
      question:
        `${file} reads as Mint v4: migrating it would add declarations and rename names it uses. ` +
        "Replace only its Mint v3 keywords with their v4 names?",
      answer: REPLACE_ANSWER,
    };
  }
  return { step: "none", message: `${file} has no Mint v3 keyword to migrate.` };
}

/** "Replace v3 keywords" on the file named `file`: the renames alone, whatever the file's version. */
export function planReplacement<A>(actions: readonly A[], kindOf: (action: A) => string | undefined, file: string): Plan<A> {
  const replace = offered(actions, kindOf, REPLACE_KIND);
  return replace === undefined
    ? { step: "none", message: `${file} has no Mint v3 keyword to replace.` }
    : { step: "apply", action: replace };
}
