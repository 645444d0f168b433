// What a page downloads until it is idle, for the download budgets (scripts/first-frame.mjs: the
// playground's first visit; scripts/figure-vs-model-viewer.mjs: one figure beside
// <model-viewer>). Each file is counted at its gzip -9 size, what a server compressing its
// responses sends (the local server, scripts/serve.mjs, sends them raw).
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';

/** Network idle: this long without a request in flight (what Playwright calls `networkidle`). */
export const IDLE_MS = 500;
/** The longest wait for idle once the page shows what it is for. */
export const IDLE_CAP_MS = 5000;

/**
 * Records every request of `page` (a playwright-core Page, and its workers) from now on.
 * `untilIdle()` waits until no request has been in flight for IDLE_MS, or IDLE_CAP_MS from its
 * call, and returns {done, open, failed}: the URLs of the requests that finished and that were
 * still in flight, and each request that failed as {url, error} (Chromium's error text, such as
 * net::ERR_ABORTED for a request the page itself cancelled).
 */
export function watchRequests(page) {
  const requests = new Map();
  let lastChange = Date.now();
  const settle = (r, state) => {
    requests.set(r, state);
    lastChange = Date.now();
  };
  page.on('request', (r) => settle(r, 'open'));
  page.on('requestfinished', (r) => settle(r, 'done'));
  page.on('requestfailed', (r) => settle(r, 'failed'));
  return {
    async untilIdle() {
      const cap = Date.now() + IDLE_CAP_MS;
      const inFlight = () => [...requests.values()].includes('open');
      while (Date.now() < cap && (inFlight() || Date.now() - lastChange < IDLE_MS)) await new Promise((r) => setTimeout(r, 50));
      const out = { done: [], open: [], failed: [] };
      for (const [r, state] of requests) out[state].push(state === 'failed' ? { url: r.url(), error: r.failure()?.errorText ?? 'unknown' } : r.url());
      return out;
    },
  };
}

/**
 * The sizes of files served from `dir`: `sizeOf(url)` is {path, raw, gzip} (bytes, gzip -9) of
 * the file that `url`'s path names under `dir` (`/` and folders: their index.html).
 */
export function fileSizes(dir) {
  const cache = new Map();
  return function sizeOf(url) {
    let p = decodeURIComponent(new URL(url).pathname);
    const shown = p;
    if (p.endsWith('/')) p += 'index.html';
    const file = path.join(dir, p);
    if (!cache.has(file)) {
      const bytes = fs.readFileSync(file);
      cache.set(file, { raw: bytes.length, gzip: zlib.gzipSync(bytes, { level: 9 }).length });
    }
    return { path: shown, ...cache.get(file) };
  };
}
