// The conformance suite: one table of cases (cases.json) through every front end — the npm
// package's wasm API in Node, the playground page in Chromium, the command line and Python —
// whose results must agree: errors word for word, files byte for byte, numbers to 1e-12
// (relative to the number's size where it is above 1; comparison tables to 1e-7, see TOLERANCE).
//
//   node tests/conformance/run.mjs                  # all four front ends
//   CONFORMANCE_FRONTENDS=node,cli node tests/conformance/run.mjs
//
// Needs what the test command builds before it: pkg/ (scripts/build-pkg.sh), the debug CLI
// (cargo test), the Python venv (scripts/python-env.sh) and www/ (scripts/serve.sh). A front end
// that cannot run fails the suite: nothing is skipped.
import { CASES } from './frontends/cases.mjs';
import { runCli } from './frontends/cli.mjs';
import { runNode } from './frontends/node.mjs';
import { runPage } from './frontends/page.mjs';
import { runPython } from './frontends/python.mjs';

const RUNNERS = { node: runNode, cli: runCli, python: runPython, page: runPage };
/**
 * Numbers agree to 1e-12 (relative above 1), but in the comparison tables to 1e-7: their metrics
 * are differences of poses divided by the step squared (2^-18), so a last-bit difference of a
 * pose — the wasm build's `sin`, `acos`, … are not the platform's — becomes ~1e-11 of an
 * acceleration, and Ramamoorthi–Barr's optimiser takes its own path from there.
 */
const TOLERANCE = { options: 1e-12, compare: 1e-7, export: 0 };
let tolerance = TOLERANCE.options;

/** Differences between `a` and `b` (paths where they disagree), numbers to `tolerance`. */
function differences(a, b, at = '', out = []) {
  if (typeof a === 'number' && typeof b === 'number') {
    if (!(Math.abs(a - b) <= tolerance * Math.max(1, Math.abs(a), Math.abs(b)) || (a === b))) out.push(`${at}: ${a} vs ${b}`);
  } else if (Array.isArray(a) && Array.isArray(b)) {
    if (a.length !== b.length) out.push(`${at}: length ${a.length} vs ${b.length}`);
    else a.forEach((v, i) => differences(v, b[i], `${at}[${i}]`, out));
  } else if (a && b && typeof a === 'object' && typeof b === 'object') {
    for (const k of new Set([...Object.keys(a), ...Object.keys(b)])) {
      if (!(k in a) || !(k in b)) out.push(`${at}.${k}: only in ${k in a ? 'the first' : 'the second'}`);
      else differences(a[k], b[k], `${at}.${k}`, out);
    }
  } else if (a !== b) {
    out.push(`${at}: ${JSON.stringify(a)} vs ${JSON.stringify(b)}`);
  }
  return out;
}

/** `r` as front ends `a` and `b` can both give it (the CLI's subdivide prints no options). */
function view(kind, r, a, b) {
  if (kind === 'options' && !r.error && (a === 'cli' || b === 'cli')) return { count: r.count, first: r.first, last: r.last };
  return r;
}

const names = (process.env.CONFORMANCE_FRONTENDS ?? 'node,cli,python,page').split(',');
const results = {};
let passed = 0;
let failed = 0;
for (const name of names) {
  if (!RUNNERS[name]) throw new Error(`unknown front end '${name}' (expected ${Object.keys(RUNNERS).join(', ')})`);
  const start = Date.now();
  try {
    results[name] = await RUNNERS[name]();
    console.log(`${name}: ran ${Object.values(results[name]).reduce((n, k) => n + Object.keys(k).length, 0)} cases in ${((Date.now() - start) / 1000).toFixed(1)} s`);
  } catch (e) {
    console.log(`not ok: front end ${name} did not run: ${e.stack ?? e}`);
    failed++;
  }
}
const [first, ...others] = names.filter((n) => results[n]);
for (const kind of ['options', 'compare', 'export']) {
  tolerance = TOLERANCE[kind];
  for (const c of CASES[kind]) {
    const want = c.expect;
    const problems = [];
    const base = results[first]?.[kind]?.[c.id];
    if (base === undefined) problems.push(`${first}: no result`);
    if (want === 'error' && !base?.error) problems.push(`${first}: expected an error, got a result`);
    if (want === 'ok' && base?.error) problems.push(`${first}: ${base.error}`);
    for (const other of others) {
      const got = results[other][kind][c.id];
      if (got === undefined) {
        problems.push(`${other}: no result`);
        continue;
      }
      const d = differences(view(kind, base, first, other), view(kind, got, first, other));
      for (const p of d.slice(0, 5)) problems.push(`${first} vs ${other}${p}`);
    }
    if (problems.length) {
      failed++;
      console.log(`not ok: ${kind} ${c.id}\n  ${problems.join('\n  ')}`);
    } else {
      passed++;
      console.log(`ok: ${kind} ${c.id}${base?.error ? ` (error: ${base.error})` : ''}`);
    }
  }
}
console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
