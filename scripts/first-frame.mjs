#!/usr/bin/env node
// What a first visit to the playground downloads, measured in headless Chromium (playwright-core,
// the e2e tests' browser and flags): the page is served from DIR (scripts/serve.mjs), opened in a
// fresh browser context (empty cache and storage: a first visit), and every response it received
// until the page was idle is counted at its gzip -9 size (what a server compressing its responses
// sends; the local server sends them raw).
//
//   node scripts/first-frame.mjs [--dir www] [--backend webgpu|webgl2] [--lesson NAME]
//        [--runs N] [--json]                     one page: files, bytes, time to first frame
//        [--and-lesson NAME]                     then ?lesson=NAME in the same browser, a
//                                                block of its own (one browser start less)
//   node scripts/first-frame.mjs --compare OLD_DIR NEW_DIR [--runs N] [--lesson NAME]
//                                                time to first frame of two builds, alternating
//
// "First frame": the first rAF after which window.screwbender.frames() is above 0, i.e. the
// renderer drew the motion. With --lesson the page is ?lesson=NAME and the first frame waits for
// the lesson card too. "Idle" (scripts/downloads.mjs): after the first frame, no request in flight
// for half a second, or 5 s after the first frame, whichever comes first. Every response of the
// page's origin up to then counts, whether it finished before the first frame or after it: what a
// visit downloads does not depend on when the page asks for it. Requests still in flight at the
// cap are listed apart (and counted: they are downloading).
import path from 'node:path';
import { IDLE_CAP_MS, fileSizes, watchRequests } from './downloads.mjs';
import { launch, serveDir as serve } from '../tests/e2e/lib.mjs';

function args() {
  const a = process.argv.slice(2);
  const o = { dir: 'www', backend: 'webgpu', lesson: null, andLesson: null, runs: 1, json: false, compare: null };
  for (let i = 0; i < a.length; i++) {
    const k = a[i];
    if (k === '--dir') o.dir = a[++i];
    else if (k === '--backend') o.backend = a[++i];
    else if (k === '--lesson') o.lesson = a[++i];
    else if (k === '--and-lesson') o.andLesson = a[++i];
    else if (k === '--runs') o.runs = Number(a[++i]);
    else if (k === '--json') o.json = true;
    else if (k === '--compare') o.compare = [a[++i], a[++i]];
    else throw new Error(`unknown argument ${k}`);
  }
  if (!['webgpu', 'webgl2'].includes(o.backend)) throw new Error(`--backend: webgpu or webgl2, not ${o.backend}`);
  if (!(Number.isInteger(o.runs) && o.runs >= 1)) throw new Error('--runs: a positive integer');
  return o;
}

/** One first visit: {ms, files: [{path, raw, gzip}], late: [paths], total}. */
async function visit(browser, url, dir, { backend, lesson }) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  const requests = watchRequests(page);
  // Marks the first frame (and with a lesson, the card) on the page's own clock.
  await page.addInitScript((wantCard) => {
    const poll = () => {
      const sb = window.screwbender;
      const card = document.getElementById('lesson');
      const cardShown = !wantCard || (document.body?.classList.contains('lesson-open') && card && !card.hidden);
      if (sb && sb.frames() > 0 && cardShown) window.__firstFrame = performance.now();
      else requestAnimationFrame(poll);
    };
    requestAnimationFrame(poll);
  }, !!lesson);
  const q = new URLSearchParams();
  if (backend === 'webgl2') q.set('backend', 'webgl2');
  if (lesson) q.set('lesson', lesson);
  const qs = q.toString();
  await page.goto(`${url}${qs ? `?${qs}` : ''}`);
  await page.waitForFunction(() => window.__firstFrame !== undefined, null, { timeout: 60000 });
  const at = await page.evaluate(() => window.__firstFrame);
  const { done, open } = await requests.untilIdle();
  await context.close();
  if (errors.length) throw new Error(`page errors: ${errors.join('; ')}`);
  const origin = new URL(url).origin;
  const sizeOf = fileSizes(dir);
  const mine = (u) => u.startsWith(origin);
  // Still in flight at the cap: counted (they are downloading) and listed.
  const files = [...done, ...open].filter(mine).map(sizeOf);
  const late = open.filter(mine).map((u) => new URL(u).pathname);
  const total = files.reduce((s, f) => s + f.gzip, 0);
  return { ms: at, files, late, total };
}

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const n = s.length;
  return n % 2 ? s[(n - 1) / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
};
const stats = (xs) => ({ median: median(xs), min: Math.min(...xs), max: Math.max(...xs) });

/** `o.runs` visits of the page (with ?lesson=`lesson` if set). */
async function runs(browser, url, dir, o, lesson) {
  const out = [];
  for (let r = 0; r < o.runs; r++) out.push(await visit(browser, url, dir, { backend: o.backend, lesson }));
  return out;
}

/** Prints the files of the last of `runs` and the total (one JSON line with --json). */
function report(o, lesson, runs) {
  const last = runs[runs.length - 1];
  const result = { backend: o.backend, lesson, gzipBytes: last.total, files: last.files, late: last.late, firstFrameMs: stats(runs.map((v) => v.ms)) };
  if (o.json) return console.log(JSON.stringify(result));
  for (const f of [...last.files].sort((a, b) => b.gzip - a.gzip)) console.log(`${String(f.gzip).padStart(8)} ${String(f.raw).padStart(9)}  ${f.path}`);
  if (last.late.length) console.log(`still in flight ${IDLE_CAP_MS} ms after the first frame: ${last.late.join(', ')}`);
  console.log(`${last.total} bytes gzip in ${last.files.length} files until idle; first frame after ${Math.round(result.firstFrameMs.median)} ms (median of ${o.runs})`);
}

async function main() {
  const o = args();
  const browser = await launch(o.backend, { softwarePage: false });
  try {
    if (o.compare) {
      const dirs = o.compare.map((d) => path.resolve(d));
      const servers = await Promise.all(dirs.map(serve));
      const times = dirs.map(() => []);
      const bytes = dirs.map(() => 0);
      try {
        for (let r = 0; r < o.runs; r++) {
          // Alternating (old, new, new, old, …) so that a drift of the machine's load hits both.
          const order = r % 2 ? [1, 0] : [0, 1];
          for (const k of order) {
            const v = await visit(browser, servers[k].url, dirs[k], o);
            times[k].push(v.ms);
            bytes[k] = v.total;
          }
        }
      } finally {
        for (const s of servers) s.stop();
      }
      const out = dirs.map((d, k) => ({ dir: d, gzipBytes: bytes[k], firstFrameMs: stats(times[k]), runs: times[k].map((t) => Math.round(t)) }));
      console.log(JSON.stringify({ backend: o.backend, lesson: o.lesson, out }, null, 2));
      return;
    }
    const dir = path.resolve(o.dir);
    const server = await serve(dir);
    try {
      report(o, o.lesson, await runs(browser, server.url, dir, o, o.lesson));
      if (o.andLesson) report(o, o.andLesson, await runs(browser, server.url, dir, o, o.andLesson));
    } finally {
      server.stop();
    }
  } finally {
    await browser.close();
  }
}

main().catch((e) => {
  console.error(e.message);
  process.exit(1);
});
