// Drives a smoke page in headless Chromium (Debian's /usr/bin/chromium via playwright-core) and
// reports `window.__smoke` (see install/browser-main.js).
//
//   node tests/js/browser-smoke.mjs --serve DIR [--label NAME]   # static server on 127.0.0.1
//   node tests/js/browser-smoke.mjs --url http://127.0.0.1:5173/ [--label NAME]
//
// Exits 0 when every check passed and the page logged no error.
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { chromium } from 'playwright-core';
import { BASE_FLAGS, SOFTWARE_RASTER } from '../e2e/lib.mjs';

const { values: args } = parseArgs({
  options: {
    serve: { type: 'string' },
    url: { type: 'string' },
    label: { type: 'string', default: 'browser' },
    timeout: { type: 'string', default: '60000' },
  },
});
if (!args.serve === !args.url) {
  console.error('usage: browser-smoke.mjs (--serve DIR | --url URL) [--label NAME]');
  process.exit(2);
}

const MIME = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.wasm': 'application/wasm',
  '.css': 'text/css; charset=utf-8',
};

/** A static file server for `root` on 127.0.0.1 (ephemeral port). */
function serve(root) {
  root = path.resolve(root);
  const server = http.createServer((req, res) => {
    const url = new URL(req.url, 'http://localhost');
    let file = path.join(root, decodeURIComponent(url.pathname));
    if (!file.startsWith(root)) {
      res.writeHead(403).end();
      return;
    }
    if (fs.existsSync(file) && fs.statSync(file).isDirectory()) file = path.join(file, 'index.html');
    fs.readFile(file, (err, data) => {
      if (err) {
        res.writeHead(404).end('not found');
        return;
      }
      const type = MIME[path.extname(file)] ?? 'application/octet-stream';
      res.writeHead(200, { 'Content-Type': type, 'Cache-Control': 'no-store' }).end(data);
    });
  });
  return new Promise((resolve) => {
    server.listen(0, '127.0.0.1', () => resolve(server));
  });
}

const server = args.serve ? await serve(args.serve) : null;
const url = server ? `http://127.0.0.1:${server.address().port}/` : args.url;

const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
  args: [...BASE_FLAGS, ...SOFTWARE_RASTER],
});
let ok = false;
try {
  const page = await browser.newPage();
  const problems = [];
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('console', (m) => {
    if (m.type() === 'error') problems.push(`console error: ${m.text()}`);
  });
  page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()} ${r.failure()?.errorText}`));
  await page.goto(url);
  await page.waitForFunction(() => window.__smoke !== undefined, null, { timeout: Number(args.timeout) });
  const result = await page.evaluate(() => window.__smoke);
  for (const c of result.checks) console.log(`${c.ok ? 'ok  ' : 'FAIL'} ${c.name}: ${c.detail}`);
  for (const p of problems) console.log(`FAIL ${p}`);
  ok = result.ok && problems.length === 0;
  console.log(`${args.label} smoke (${url}): ${ok ? 'passed' : 'FAILED'}`);
} catch (e) {
  console.log(`${args.label} smoke (${url}): FAILED: ${e.message}`);
} finally {
  await browser.close();
  server?.close();
}
process.exit(ok ? 0 : 1);
