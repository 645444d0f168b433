// Validates glTF 2.0 assets (.glb, or .gltf with external buffers) with the Khronos
// glTF-Validator (npm `gltf-validator`, pinned in the root package.json).
//
//   node tests/gltf/validate.mjs FILE... [--max-infos N]
//
// Prints one line per file: `ok FILE (errors 0, warnings 0, infos N, hints N)`, or the issues.
// Exit status 0 when every file has 0 errors and 0 warnings, 1 otherwise, 2 for bad usage.
import fs from "node:fs/promises";
import path from "node:path";
import validator from "gltf-validator";

const files = process.argv.slice(2);
if (files.length === 0) {
  console.error("usage: node tests/gltf/validate.mjs FILE...");
  process.exit(2);
}

let failed = 0;
for (const file of files) {
  const full = path.resolve(file);
  const bytes = new Uint8Array(await fs.readFile(full));
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(full),
    maxIssues: 100,
    externalResourceFunction: async (uri) =>
      new Uint8Array(await fs.readFile(path.resolve(path.dirname(full), decodeURIComponent(uri)))),
  });
  const { numErrors, numWarnings, numInfos, numHints } = report.issues;
  const counts = `errors ${numErrors}, warnings ${numWarnings}, infos ${numInfos}, hints ${numHints}`;
  if (numErrors === 0 && numWarnings === 0) {
    console.log(`ok ${file} (${counts})`);
  } else {
    failed += 1;
    console.log(`FAIL ${file} (${counts})`);
    for (const m of report.issues.messages) {
      if (m.severity <= 1) console.log(`  [${m.severity === 0 ? "error" : "warning"}] ${m.code} ${m.pointer ?? ""}: ${m.message}`);
    }
  }
  if (process.env.GLTF_VALIDATE_VERBOSE) {
    for (const m of report.issues.messages) console.log(`  [${m.severity}] ${m.code} ${m.pointer ?? ""}: ${m.message}`);
  }
}
process.exit(failed === 0 ? 0 : 1);
