// Runs the e2e test files (tests/e2e/*.test.mjs), each on the backends its first line names,
//
//     // e2e-backends: webgpu webgl2 (why)
//
// as one pool of jobs (a file on a backend), E2E_JOBS at a time (default 2), the longest first:
// one pool for both backends leaves no core idle while the last file of one backend finishes.
// Each job is `node --test FILE` with E2E_BACKEND set; its output is kept and printed in full
// only if it fails. At the end a table gives each job's wall time, and the times are written to
// artifacts/e2e-durations.json (copy it over tests/e2e/durations.json, which only orders the
// jobs, when files were added or changed much).
//
//   node tests/e2e/run.mjs                         # every file on its backends
//   node tests/e2e/run.mjs tests/e2e/viewer.test.mjs
//   E2E_BACKENDS=webgl2 node tests/e2e/run.mjs     # the files that run on WebGL2, there only
//
// A file without the line is an error: a new file says where it runs.
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const HERE = path.dirname(fileURLToPath(import.meta.url));
const ROOT = path.resolve(HERE, '../..');
const BACKENDS = ['webgpu', 'webgl2'];
/** The time assumed for a job that durations.json does not list. */
const UNKNOWN_SECONDS = 30;

/** The backends a test file names on its `// e2e-backends:` line. */
function backendsOf(file) {
  const head = fs.readFileSync(file, 'utf8').split('\n').slice(0, 20);
  const line = head.find((l) => /^\/\/ e2e-backends:/.test(l));
  if (!line) throw new Error(`${file}: no "// e2e-backends: …" line in its first 20 lines`);
  const names = line.replace(/^\/\/ e2e-backends:/, '').replace(/\(.*$/, '').trim().split(/\s+/);
  const bad = names.filter((b) => !BACKENDS.includes(b));
  if (!names.length || bad.length) throw new Error(`${file}: e2e-backends names ${bad.join(' ') || 'nothing'}; use ${BACKENDS.join(' and/or ')}`);
  return names;
}

function readJson(file) {
  try {
    return JSON.parse(fs.readFileSync(file, 'utf8'));
  } catch {
    return {};
  }
}

const stamp = () => new Date().toISOString().slice(11, 19);
const key = (job) => `${job.backend} ${path.basename(job.file)}`;

/** Runs one job; resolves {code, out, seconds, pass, fail}. */
function runJob(job) {
  const start = Date.now();
  return new Promise((resolve) => {
    const child = spawn(process.execPath, ['--test', job.file], {
      cwd: ROOT,
      env: { ...process.env, E2E_BACKEND: job.backend },
      stdio: ['ignore', 'pipe', 'pipe'],
    });
    const chunks = [];
    child.stdout.on('data', (d) => chunks.push(d));
    child.stderr.on('data', (d) => chunks.push(d));
    child.on('close', (code, signal) => {
      const out = Buffer.concat(chunks).toString();
      const count = (name) => Number(out.match(new RegExp(`^# ${name} (\\d+)`, 'm'))?.[1] ?? 0);
      resolve({ code: code ?? (signal ? 1 : 0), out, seconds: (Date.now() - start) / 1000, pass: count('pass'), fail: count('fail') });
    });
  });
}

async function main() {
  const args = process.argv.slice(2);
  const files = args.length
    ? args.map((f) => path.resolve(f))
    : fs.readdirSync(HERE).filter((f) => f.endsWith('.test.mjs')).sort().map((f) => path.join(HERE, f));
  const only = (process.env.E2E_BACKENDS ?? BACKENDS.join(' ')).split(/[\s,]+/).filter(Boolean);
  const jobs = files.flatMap((file) => backendsOf(file).filter((b) => only.includes(b)).map((backend) => ({ file, backend })));
  if (!jobs.length) throw new Error('no e2e jobs (files × backends)');
  const known = readJson(path.join(HERE, 'durations.json'));
  const expected = (job) => known[key(job)] ?? UNKNOWN_SECONDS;
  jobs.sort((a, b) => expected(b) - expected(a) || key(a).localeCompare(key(b)));

  const width = Math.max(1, Number(process.env.E2E_JOBS ?? 2));
  console.log(`[${stamp()}] e2e: ${jobs.length} jobs (${files.length} files), ${width} at a time`);
  const results = [];
  let next = 0;
  async function lane() {
    while (next < jobs.length) {
      const job = jobs[next++];
      const r = await runJob(job);
      results.push({ job, ...r });
      const ok = r.code === 0;
      console.log(`[${stamp()}] ${ok ? 'ok  ' : 'FAIL'} ${key(job)}: ${r.pass} passed, ${r.fail} failed, ${r.seconds.toFixed(0)} s`);
      if (!ok) {
        console.log(`---------- ${key(job)}: its output ----------`);
        console.log(r.out.trimEnd());
        console.log(`---------- end of ${key(job)} ----------`);
      }
    }
  }
  const start = Date.now();
  await Promise.all(Array.from({ length: width }, lane));

  results.sort((a, b) => b.seconds - a.seconds);
  console.log('\n==================== e2e jobs by wall time ====================');
  for (const r of results) console.log(`${r.seconds.toFixed(1).padStart(7)} s  ${String(r.pass).padStart(3)} tests  ${r.code === 0 ? '' : 'FAILED  '}${key(r.job)}`);
  const sum = results.reduce((s, r) => s + r.seconds, 0);
  const tests = results.reduce((s, r) => s + r.pass + r.fail, 0);
  const failed = results.filter((r) => r.code !== 0);
  console.log(`${sum.toFixed(0).padStart(7)} s  job time in all; ${((Date.now() - start) / 1000).toFixed(0)} s wall; ${tests} tests`);
  fs.mkdirSync(path.join(ROOT, 'artifacts'), { recursive: true });
  const times = Object.fromEntries(results.map((r) => [key(r.job), Math.round(r.seconds)]).sort());
  fs.writeFileSync(path.join(ROOT, 'artifacts', 'e2e-durations.json'), `${JSON.stringify(times, null, 1)}\n`);
  if (failed.length) {
    console.log(`e2e: ${failed.length} of ${results.length} jobs failed: ${failed.map((r) => key(r.job)).join(', ')}`);
    process.exit(1);
  }
  console.log(`e2e: all ${results.length} jobs passed`);
}

main().catch((e) => {
  console.error(`e2e: ${e.message}`);
  process.exit(1);
});
