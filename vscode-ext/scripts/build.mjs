// Bundles the extension into dist/extension.js with esbuild: one file, no node_modules in the .vsix.
import { copyFileSync, mkdirSync } from "node:fs";
import { build } from "esbuild";

await build({
  entryPoints: ["src/extension.ts"],
  bundle: true,
  outfile: "dist/extension.js",
  external: ["vscode"],
  format: "cjs",
  platform: "node",
  target: "node18", // the Node of VS Code 1.88's extension host
  minify: true,
  sourcemap: true,
  logLevel: "info",
});

// vscode-languageclient kills a server that will not stop with this script, found beside its
// code (__dirname): bundled, that is dist/.
mkdirSync("dist", { recursive: true });
copyFileSync("node_modules/vscode-languageclient/lib/node/terminateProcess.sh", "dist/terminateProcess.sh");
