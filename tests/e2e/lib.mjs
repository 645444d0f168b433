// Shared helpers of the end-to-end tests: launching Debian's Chromium with the flags of each
// backend (WebGPU on SwiftShader through Vulkan, the same flags as webdriver.json), and opening
// the playground.
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import net from 'node:net';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

/** The repository root. */
export const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
/** The backend of this run (scripts/test.d/e2e.sh sets it) and the name the page reports. */
export const BACKEND = process.env.E2E_BACKEND ?? 'webgpu';
export const EXPECTED_BACKEND = BACKEND === 'webgpu' ? 'WebGPU' : 'WebGL2';

/**
 * Where a screenshot named `name` (a path relative to docs/screenshots/, e.g. 'timeline-phone.png' or
 * 'lessons/01.png') goes: artifacts/e2e-<backend>/ normally, so that a test run never changes a
 * committed file; docs/screenshots/ itself with DOCS_SHOTS=1, to refresh the committed copies. The folder is
 * created. The committed pictures other than the lessons' are made by scripts/docs-shots.mjs, not by
 * the tests.
 */
export function shotPath(name) {
  const dir = process.env.DOCS_SHOTS === '1' ? path.join(ROOT, 'docs/screenshots') : path.join(ROOT, `artifacts/e2e-${BACKEND}`);
  const file = path.join(dir, name);
  fs.mkdirSync(path.dirname(file), { recursive: true });
  return file;
}

async function freePort() {
  return new Promise((resolve) => {
    const s = net.createServer();
    s.listen(0, '127.0.0.1', () => {
      const { port } = s.address();
      s.close(() => resolve(port));
    });
  });
}

/** Serves www/ with scripts/serve.mjs on a free port; returns {url, stop()}. */
export async function serveWww() {
  if (!fs.existsSync(path.join(ROOT, 'www/pkg-webgpu/screwbender_bg.wasm'))) throw new Error('build the wasm first (scripts/serve.sh)');
  return serveDir(path.join(ROOT, 'www'));
}

/** Serves the folder `dir` with scripts/serve.mjs on a free port of 127.0.0.1; returns {url, stop()}. */
export async function serveDir(dir) {
  const port = await freePort();
  const server = spawn(process.execPath, [path.join(ROOT, 'scripts/serve.mjs'), dir], {
    env: { ...process.env, PORT: String(port), SERVE_QUIET: '1' },
    stdio: ['ignore', 'pipe', 'inherit'],
  });
  await new Promise((resolve, reject) => {
    server.stdout.on('data', (d) => d.toString().includes('http://') && resolve());
    server.on('exit', (c) => reject(new Error(`server exited ${c}`)));
  });
  return { url: `http://127.0.0.1:${port}/`, stop: () => server.kill() };
}

/**
 * The window the desktop tests use: a small desktop window (the page's desktop layout starts at
 * 761 × 501 CSS pixels). Every frame the tests wait for is drawn by SwiftShader on the processor,
 * at a cost that grows with the figure's area on screen: 960 × 600 costs about two thirds of
 * 1280 × 800 (docs/speed/suite.md). The layout tests also run at 1280 × 800 and larger.
 * E2E_W and E2E_H set another size, to compare what a file costs at two sizes.
 */
export const DESKTOP = Object.freeze({ width: Number(process.env.E2E_W ?? 960), height: Number(process.env.E2E_H ?? 600) });

/**
 * Serves www/ and launches Chromium for BACKEND with one browser context.
 * Returns {url, browser, context, close()}.
 */
export async function startPlayground({ viewport = DESKTOP, acceptDownloads = false } = {}) {
  const { url, stop } = await serveWww();
  const browser = await launch(BACKEND);
  const context = await browser.newContext({ viewport, acceptDownloads });
  // Every CSP violation of every page of the context is recorded in window.__csp.
  await context.addInitScript(() => {
    window.__csp = [];
    document.addEventListener('securitypolicyviolation', (e) => window.__csp.push(`${e.violatedDirective}: ${e.blockedURI}`));
  });
  return {
    url,
    browser,
    context,
    async close() {
      await browser.close();
      stop();
    },
  };
}

export const BASE_FLAGS = [
  '--headless=new',
  '--no-sandbox',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  '--enable-unsafe-swiftshader',
];
/**
 * For tests: with no GPU, Chromium's "GPU" rasterisation of the page (text, charts, dialogs) runs
 * on SwiftShader, a GPU emulated on the processor; Skia's own software rasteriser does the same
 * work with less of the processor, which the tests share two at a time. The compositor stays on
 * the (emulated) GPU: without it a WebGPU canvas draws into no picture, and a WebGL2 canvas is
 * read back every frame with a console warning that a page on a real GPU never sees. The
 * figures' canvases draw through WebGPU or WebGL2 on SwiftShader as before. Benchmarks leave this
 * out (`launch(backend, { softwarePage: false })`), to time the path a machine with a GPU takes.
 */
export const SOFTWARE_RASTER = ['--disable-gpu-rasterization'];
/** WebGPU on SwiftShader needs all of these (and no --disable-gpu). */
const WEBGPU_FLAGS = [
  '--enable-unsafe-webgpu',
  '--use-angle=swiftshader',
  '--enable-features=Vulkan',
  '--use-vulkan=swiftshader',
];

/**
 * Launches Chromium for `backend` ('webgpu' | 'webgl2'), the page rasterised in software unless
 * `softwarePage` is false (SOFTWARE_RASTER).
 */
export async function launch(backend, { softwarePage = true } = {}) {
  const args = [...BASE_FLAGS, ...(backend === 'webgpu' ? WEBGPU_FLAGS : ['--use-angle=swiftshader'])];
  if (softwarePage) args.push(...SOFTWARE_RASTER);
  return chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    args,
    headless: true,
  });
}

/**
 * Emulates the reduced-transparency system setting in `page` (before it loads anything): the
 * page's panels then have no backdrop blur, which SwiftShader redraws on every frame of the view
 * behind them at about a quarter of the frame's cost. The blur is plain CSS with no logic of the
 * page behind it; editor-a11y.test.mjs checks that both settings style the panels as meant.
 * (Playwright's emulateMedia has no such option; a later emulateMedia call resets it.)
 */
export async function reduceTransparency(page) {
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Emulation.setEmulatedMedia', { features: [{ name: 'prefers-reduced-transparency', value: 'reduce' }] });
}

/**
 * Opens the playground in a fresh page of `context`; collects console errors and page errors.
 * Reduced transparency is emulated (reduceTransparency) unless `defaultLook`.
 * For 'webgl2' the page is forced to WebGL2 with ?backend=webgl2 as well (belt and braces:
 * without the WebGPU flags there is no adapter anyway).
 */
export async function openPage(context, url, backend, { path = '', defaultLook = false } = {}) {
  const page = await context.newPage();
  if (!defaultLook) await reduceTransparency(page);
  const problems = [];
  page.on('console', (m) => {
    if (m.type() === 'error') problems.push(`console: ${m.text()}`);
  });
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  const q = backend === 'webgl2' ? '?backend=webgl2' : '';
  await page.goto(`${url}${q}${path}`);
  await page.evaluate(() => window.screwbender.ready);
  await waitFrames(page, 2);
  return { page, problems };
}

/**
 * An init script (context.addInitScript(countStorage)) that records every storage call of each
 * page and frame in its window.__storage (embedded figures must make none).
 */
export function countStorage() {
  window.__storage = [];
  for (const name of ['getItem', 'setItem', 'removeItem', 'clear', 'key']) {
    const f = Storage.prototype[name];
    Storage.prototype[name] = function (...args) {
      window.__storage.push(`${name}(${args[0] ?? ''})`);
      return f.apply(this, args);
    };
  }
}

/** Drags with real mouse events from `from` by (dx, dy) in `steps` moves; `during` runs mid-drag. */
export async function mouseDrag(page, from, dx, dy, { steps = 8, during } = {}) {
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let k = 1; k <= steps; k++) {
    await page.mouse.move(from.x + (dx * k) / steps, from.y + (dy * k) / steps);
    if (k === Math.ceil(steps / 2) && during) await during();
  }
  await page.mouse.up();
  await waitFrames(page, 1);
}

/** Runs `action` and returns the download it causes in `page` (null when none came within `ms`). */
export async function downloadFrom(page, action, ms = 180000) {
  const got = page.waitForEvent('download', { timeout: ms }).catch(() => null);
  await action();
  return got;
}

/** Opens the playground toolbar's View menu (unless it is open). */
export async function openViewMenu(page) {
  if ((await page.locator('#t-view').getAttribute('aria-expanded')) !== 'true') await page.click('#t-view');
}

/** Waits until at least `n` more frames were drawn. */
export async function waitFrames(page, n = 2) {
  const start = await page.evaluate(() => {
    window.screwbender.app.viewer.requestDraw();
    return window.screwbender.frames();
  });
  for (let k = 0; k < n; k++) {
    await page.waitForFunction((s) => window.screwbender.frames() > s, start + k, { timeout: 30000 });
    await page.evaluate(() => window.screwbender.app.viewer.requestDraw());
  }
}

/** Pixel statistics of the canvas from a screenshot: fraction of non-background pixels etc. */
export async function canvasStats(page) {
  const png = await page.locator('#view').screenshot();
  const stats = await page.evaluate(async (b64) => {
    const img = new Image();
    img.src = `data:image/png;base64,${b64}`;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width;
    c.height = img.height;
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    const bg = [d[0], d[1], d[2]];
    let differ = 0;
    let red = 0;
    let dark = 0;
    const colours = new Set();
    for (let i = 0; i < d.length; i += 4) {
      const [r, gg, b] = [d[i], d[i + 1], d[i + 2]];
      if (Math.abs(r - bg[0]) + Math.abs(gg - bg[1]) + Math.abs(b - bg[2]) > 30) differ++;
      if (r > 150 && gg < 80 && b < 80) red++;
      if (r + gg + b < 150) dark++;
      colours.add((r >> 4) * 256 + (gg >> 4) * 16 + (b >> 4));
    }
    const n = d.length / 4;
    return { nonBackground: differ / n, red: red / n, dark: dark / n, colours: colours.size, width: c.width, height: c.height };
  }, png.toString('base64'));
  return { ...stats, png };
}

/**
 * One playground page for a test file: serves www/, launches Chromium for BACKEND and opens the
 * page; returns {play, page, problems} (close with play.close()). `options`: startPlayground's,
 * and openPage's `defaultLook`.
 */
export async function playgroundPage(options = {}) {
  const play = await startPlayground(options);
  const { page, problems } = await openPage(play.context, play.url, BACKEND, { defaultLook: options.defaultLook });
  return { play, page, problems };
}
