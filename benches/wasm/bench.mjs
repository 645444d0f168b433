// WebAssembly benchmark of the npm package (build it first: ./scripts/build-pkg.sh).
//
//   node benches/wasm/bench.mjs              # in Node
//   node benches/wasm/bench.mjs --browser    # in headless Chromium (playwright-core)
//   node benches/wasm/bench.mjs --json       # machine-readable output
//
// CHROMIUM_ARGS='…' adds flags to Chromium's command line (here and in compare.mjs --browser), for
// experiments such as '--js-flags=--no-liftoff' (TurboFan from the start: it made no difference
// to subdivideInto, so the figures are not Liftoff code waiting to tier up).
//
// Figures: screwPoses (one screw at 2^16 fractions per call: exp only), screwPairs (2^16 full
// screws per call: log + exp), and the subdivision of 32 random poses by 6 levels per scheme and rule set
// (with the direct rules also `subdivideInto` a kept array, where the build has it).
// Timings include the copies across the JS/wasm boundary. Not part of the test command.
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { runBench } from './bench-core.mjs';

export const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

/**
 * Serves the repo root (so that a page can import /pkg/ and /benches/wasm/), opens a blank page
 * in headless Chromium (playwright-core), runs `fn(page, userAgentVersion)` and closes both.
 */
export async function withBrowserPage(fn, log = () => {}) {
  const { chromium } = await import('playwright-core');
  const types = { '.js': 'text/javascript', '.mjs': 'text/javascript', '.wasm': 'application/wasm', '.html': 'text/html' };
  const server = http.createServer((req, res) => {
    const url = new URL(req.url, 'http://localhost');
    if (url.pathname === '/') {
      res.writeHead(200, { 'Content-Type': 'text/html' }).end('<!doctype html><link rel="icon" href="data:,"><title>bench</title>');
      return;
    }
    const file = path.join(repo, decodeURIComponent(url.pathname));
    if (!file.startsWith(repo + path.sep) || !fs.existsSync(file)) return void res.writeHead(404).end();
    res.writeHead(200, { 'Content-Type': types[path.extname(file)] ?? 'application/octet-stream' }).end(fs.readFileSync(file));
  });
  await new Promise((r) => server.listen(0, '127.0.0.1', r));
  const b = await chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    args: [
      '--headless=new', '--no-sandbox', '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run',
      // Extra Chromium flags for an experiment (CHROMIUM_ARGS, see the top of this file).
      ...(process.env.CHROMIUM_ARGS?.split(' ').filter(Boolean) ?? []),
    ],
  });
  try {
    const page = await b.newPage();
    page.on('console', (m) => log(`  [page] ${m.text()}`));
    await page.goto(`http://127.0.0.1:${server.address().port}/`);
    const version = await page.evaluate(() => navigator.userAgent.match(/Chrome\/[\d.]+/)?.[0] ?? navigator.userAgent);
    return await fn(page, version);
  } finally {
    await b.close();
    server.close();
  }
}

// Run as a script (compare.mjs imports `withBrowserPage` only).
if (import.meta.url === pathToFileURL(process.argv[1] ?? '').href) {
  const browser = process.argv.includes('--browser');
  const json = process.argv.includes('--json');
  const pkgDir = path.join(repo, 'pkg');
  if (!fs.existsSync(path.join(pkgDir, 'screwbender_bg.wasm'))) {
    console.error('pkg/ is missing: run ./scripts/build-pkg.sh first');
    process.exit(1);
  }
  const log = json ? () => {} : (line) => console.log(line);
  let results;
  if (!browser) {
    const sb = await import(pathToFileURL(path.join(pkgDir, 'node.js')).href);
    log(`node ${process.version}, screwbender ${sb.version()}`);
    results = { runtime: `node ${process.version}`, ...runBench(sb, () => performance.now(), log) };
  } else {
    results = await withBrowserPage(async (page, version) => {
      log(`headless ${version}`);
      const r = await page.evaluate(async () => {
        const sb = await import('/pkg/screwbender.js');
        await sb.default();
        const { runBench } = await import('/benches/wasm/bench-core.mjs');
        return runBench(sb, () => performance.now(), (line) => console.log(line));
      });
      return { runtime: `headless ${version}`, ...r };
    }, log);
  }
  if (json) console.log(JSON.stringify(results, null, 2));
}
