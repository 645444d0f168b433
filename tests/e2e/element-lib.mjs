// Helpers of the <screw-bender> element's tests (tests/e2e/element-*.test.mjs): a test page
// written by the test and served from the www/ server's origin (so the element's modules load as
// on any page), frame waits, and the pixels of a picture.
import { EXPECTED_BACKEND, startPlayground } from './lib.mjs';

export { EXPECTED_BACKEND };

/** An open motion of three poses (uniform timing: duration 2 s). */
export const OPEN3 = { closed: false, poses: [
  { origin: [0, 0, 0], rotation: [1, 0, 0, 0] },
  { origin: [2, 1, 0.5], rotation: [0.9238795325112867, 0, 0, 0.3826834323650898] },
  { origin: [4, 0, 1], rotation: [0.7071067811865476, 0, 0, 0.7071067811865476] },
] };

/** A page `name` under examples/ with `body` (HTML) and the element's module. */
export function pageHtml(body, { head = '' } = {}) {
  return `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>element test</title>
<link rel="icon" href="data:,"><meta name="viewport" content="width=device-width, initial-scale=1">
<script type="module" src="../js/element/screw-bender.js"></script>${head}</head><body>${body}</body></html>`;
}

/** Serves www/ and opens Chromium; `open(html)` shows a page of that HTML; returns {play, open, close}. */
export async function elementBrowser(contextOptions = {}) {
  const play = await startPlayground({ viewport: { width: 1280, height: 800 }, ...contextOptions });
  let n = 0;
  const ctxFor = async (opts) => (opts ? play.browser.newContext(opts) : play.context);
  /**
   * Opens a new page showing `html` (served as examples/test-<n>.html); collects console errors
   * and page errors in `problems`. `contextOptions` opens it in a fresh context.
   */
  async function open(html, { context: copts } = {}) {
    const ctx = await ctxFor(copts);
    const page = await ctx.newPage();
    const problems = [];
    page.on('console', (m) => m.type() === 'error' && problems.push(`console: ${m.text()}`));
    page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
    const path = `examples/test-${n++}.html`;
    await page.route(`${play.url}${path}`, (route) => route.fulfill({ contentType: 'text/html', body: html }));
    await page.goto(`${play.url}${path}`);
    await page.waitForFunction(() => customElements.get('screw-bender'));
    return { page, problems, close: () => (copts ? ctx.close() : page.close()) };
  }
  return { play, open, close: () => play.close() };
}

/** One browser and one page of `html` for a whole test file: {b, page, problems} (close with b.close()). */
export async function openOnePage(html) {
  const b = await elementBrowser();
  const { page, problems } = await b.open(html);
  return { b, page, problems };
}

/** Waits until figure `sel` (a CSS selector) drew `n` more frames. */
export async function figureFrames(page, sel, n = 2) {
  const start = await page.evaluate((s) => {
    const v = document.querySelector(s).viewer;
    v.requestDraw();
    return v.frames;
  }, sel);
  await page.waitForFunction(
    ([s, f]) => {
      const v = document.querySelector(s).viewer;
      v.requestDraw();
      return v.frames >= f;
    },
    [sel, start + n],
    { timeout: 30000 },
  );
}

/**
 * The share of the pixels of a screenshot of `sel` (as the page shows it, print media included)
 * that differ from the pixel at (40, 40), the figure's background.
 */
export async function drawnShare(page, sel) {
  const png = await page.locator(sel).screenshot();
  return page.evaluate(async (b64) => {
    const bmp = await createImageBitmap(await (await fetch(`data:image/png;base64,${b64}`)).blob());
    const c = new OffscreenCanvas(bmp.width, bmp.height);
    const g = c.getContext('2d');
    g.drawImage(bmp, 0, 0);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    const i0 = 4 * (c.width * 40 + 40);
    let differ = 0;
    for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - d[i0]) + Math.abs(d[i + 1] - d[i0 + 1]) + Math.abs(d[i + 2] - d[i0 + 2]) > 30) differ++;
    return differ / (d.length / 4);
  }, png.toString('base64'));
}

/** The box of the canvas of figure `sel` in page coordinates. */
export const canvasBox = (page, sel) =>
  page.evaluate((s) => document.querySelector(s).shadowRoot.querySelector('canvas').getBoundingClientRect().toJSON(), sel);
