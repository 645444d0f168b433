// The conformance cases (cases.json) and what every front end's runner shares: the CLI's
// motion document of a preset (the input every front end starts from) and the flags of the
// command line for an options object. Not a runner itself.
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';

/** The cases of cases.json. */
export const CASES = JSON.parse(readFileSync(new URL('../cases.json', import.meta.url), 'utf8'));

/** The command-line tool (the debug build the native tests made, or SCREWBENDER_CLI). */
export const CLI = process.env.SCREWBENDER_CLI ?? new URL('../../../target/debug/screwbender', import.meta.url).pathname;

/** Runs the CLI with `args` and `input` on standard input. */
export function cli(args, input = '') {
  const r = spawnSync(CLI, args, { input, maxBuffer: 1 << 28 });
  // A command that refuses its options exits before reading its input (EPIPE for the writer).
  if (r.error && !(r.error.code === 'EPIPE' && r.status !== null)) throw r.error;
  return { code: r.status, stdout: r.stdout, stderr: r.stderr.toString() };
}

const documents = new Map();
/** The JSON motion document of preset `id`, as `screwbender preset ID` writes it. */
export function presetDocument(id) {
  if (!documents.has(id)) {
    const r = cli(['preset', id]);
    if (r.code !== 0) throw new Error(`screwbender preset ${id}: ${r.stderr}`);
    documents.set(id, r.stdout.toString());
  }
  return documents.get(id);
}

/** The command line's subdivision flags for an options object of cases.json. */
export function optionFlags(options) {
  const flags = [];
  for (const key of ['scheme', 's', 'rules', 'levels']) {
    if (options[key] !== undefined) flags.push(`--${key}`, String(options[key]));
  }
  return flags;
}

/** The first and last pose rows and the count of a flat pose array (7 numbers per pose). */
export function poseSummary(flat) {
  const n = flat.length / 7;
  return { count: n, first: Array.from(flat.slice(0, 7)), last: Array.from(flat.slice(flat.length - 7)) };
}
