// Shared helpers of the end-to-end tests: launching Debian's Chromium with the flags of each
// backend (see /work/shared/TOOLCHAIN.md), and opening the playground.
import { chromium } from 'playwright-core';

export const BASE_FLAGS = [
  '--headless=new',
  '--no-sandbox',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  '--enable-unsafe-swiftshader',
];
/** WebGPU on SwiftShader needs all of these (and no --disable-gpu). */
const WEBGPU_FLAGS = [
  '--enable-unsafe-webgpu',
  '--use-angle=swiftshader',
  '--enable-features=Vulkan',
  '--use-vulkan=swiftshader',
];

/** Launches Chromium for `backend` ('webgpu' | 'webgl2'). */
export async function launch(backend) {
  const args = backend === 'webgpu' ? [...BASE_FLAGS, ...WEBGPU_FLAGS] : [...BASE_FLAGS, '--use-angle=swiftshader'];
  return chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    args,
    headless: true,
  });
}

/**
 * Opens the playground in a fresh page of `context`; collects console errors and page errors.
 * For 'webgl2' the page is forced to WebGL2 with ?backend=webgl2 as well (belt and braces:
 * without the WebGPU flags there is no adapter anyway).
 */
export async function openPage(context, url, backend, { path = '' } = {}) {
  const page = await context.newPage();
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

/** Waits until at least `n` more frames were drawn. */
export async function waitFrames(page, n = 2) {
  const start = await page.evaluate(() => {
    window.screwbender.app.requestDraw();
    return window.screwbender.frames();
  });
  for (let k = 0; k < n; k++) {
    await page.waitForFunction((s) => window.screwbender.frames() > s, start + k, { timeout: 30000 });
    await page.evaluate(() => window.screwbender.app.requestDraw());
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
