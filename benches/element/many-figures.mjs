#!/usr/bin/env node
// A page of 20 <screw-bender> figures (each in a 420 px section, 1280 × 800 viewport): the time
// from navigation to the first figure drawn, how many figures started before any scrolling, and
// the memory then and after scrolling through the whole page (JS heap after a GC, the wasm
// memory; the processes' CPU time where Chromium reports it), for a www/ tree given as argument (to
// compare two builds of the element) and a `loading` value.
//
//   node benches/element/many-figures.mjs [WWW_DIR] [lazy|eager|none]   # E2E_BACKEND as the e2e tests
//
// "none" writes no loading attribute (the default of the build under test).
import { spawn } from 'node:child_process';
import net from 'node:net';
import path from 'node:path';
import { BACKEND, ROOT, launch } from '../../tests/e2e/lib.mjs';

const www = path.resolve(process.argv[2] ?? path.join(ROOT, 'www'));
const loading = process.argv[3] ?? 'none';
const N = 20;

const port = await new Promise((resolve) => {
  const s = net.createServer();
  s.listen(0, '127.0.0.1', () => {
    const p = s.address().port;
    s.close(() => resolve(p));
  });
});
const server = spawn(process.execPath, [path.join(ROOT, 'scripts/serve.mjs'), www], { env: { ...process.env, PORT: String(port), SERVE_QUIET: '1' }, stdio: ['ignore', 'pipe', 'inherit'] });
await new Promise((resolve) => server.stdout.on('data', (d) => d.toString().includes('http://') && resolve()));
const url = `http://127.0.0.1:${port}/`;
const attr = loading === 'none' ? '' : `loading="${loading}"`;
const html = `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>20 figures</title><link rel="icon" href="data:,">
<script type="module" src="../js/element/screw-bender.js"></script></head><body><main style="width: 700px; margin: 0 auto">
${Array.from({ length: N }, (_, k) => `<section style="height: 420px"><screw-bender id="m${k}" scene="${k % 2 ? 'circle4' : 'l_cycle_rotated'}" strobe="24" ${attr}>Figure ${k}.</screw-bender></section>`).join('\n')}
</main></body></html>`;

const browser = await launch(BACKEND, { softwarePage: false });
try {
  const page = await (await browser.newContext({ viewport: { width: 1280, height: 800 } })).newPage();
  await page.route(`${url}examples/many.html`, (r) => r.fulfill({ contentType: 'text/html', body: html }));
  const t0 = Date.now();
  await page.goto(`${url}examples/many.html`);
  await page.waitForFunction(() => document.getElementById('m0')?.viewer?.frames > 0, null, { timeout: 120000, polling: 10 });
  const firstMs = Date.now() - t0;
  await page.waitForTimeout(1000);
  const startedAtFirst = await page.evaluate(() => [...document.querySelectorAll('screw-bender')].filter((e) => e.viewer).length);
  const cdp = await page.context().newCDPSession(page);
  const memory = async () => {
    await cdp.send('HeapProfiler.collectGarbage');
    const heap = (await cdp.send('Runtime.getHeapUsage')).usedSize;
    const wasm = await page.evaluate(async () => (await (await import('../pkg/screwbender.js')).default()).memory.buffer.byteLength);
    return `${(heap / 1e6).toFixed(2)} MB JS heap, ${(wasm / 1e6).toFixed(2)} MB wasm`;
  };
  const memoryAtFirst = await memory();
  // Scroll through: each figure into view, until it drew a frame.
  for (let k = 0; k < N; k++) {
    await page.evaluate((i) => document.getElementById(`m${i}`).scrollIntoView({ block: 'center' }), k);
    await page.waitForFunction((i) => document.getElementById(`m${i}`).viewer?.frames > 0, k, { timeout: 120000 });
  }
  // Figures far from the viewport free their renderers after a while (element/showing.js).
  await page.waitForTimeout(3000);
  const memoryAfter = await memory();
  const renderersAfter = await page.evaluate(() => [...document.querySelectorAll('screw-bender')].filter((e) => e.viewer?.renderer).length);
  const startedAfter = await page.evaluate(() => [...document.querySelectorAll('screw-bender')].filter((e) => e.viewer).length);
  let rss = null;
  try {
    const { processInfo } = await (await browser.newBrowserCDPSession()).send('SystemInfo.getProcessInfo');
    rss = processInfo.filter((p) => p.type === 'renderer' || p.type === 'GPU').map((p) => `${p.type} cpu ${p.cpuTime.toFixed(1)} s`).join(', ');
  } catch {
    // Not every build reports it.
  }
  console.log(JSON.stringify({ backend: BACKEND, www, loading, firstMs, startedAtFirst, memoryAtFirst, startedAfter, renderersAfter, memoryAfter, processes: rss }));
} finally {
  await browser.close();
  server.kill();
}
