// The course example page (www/examples/course.html) and its four <screw-bender> figures for the
// viewer tests (viewer.test.mjs, viewer-render.test.mjs): a served playground whose pages count
// their storage calls and WebGPU devices, pages opened with every figure started, and a figure's
// frames and pixels.
import { countStorage, startPlayground } from './lib.mjs';

/** The course page, relative to www/. */
export const COURSE = 'examples/course.html';
/** The ids of its figures, in page order. */
export const FIGURES = ['fig-screw', 'fig-fourpoint', 'fig-bspline', 'fig-jarek'];

/**
 * Serves www/ and launches Chromium (1280×800) for BACKEND; each page of its context records its
 * storage calls in window.__storage and the WebGPU devices it opened in window.__devices.
 * Returns startPlayground's {url, browser, context, close()}.
 */
export async function coursePlayground() {
  const play = await startPlayground({ viewport: { width: 1280, height: 800 } });
  // Every storage call of every page is counted (the figures must make none), and so is every
  // WebGPU device opened (the figures share one).
  await play.context.addInitScript(() => {
    window.__devices = 0;
    if (window.GPUAdapter) {
      const request = GPUAdapter.prototype.requestDevice;
      GPUAdapter.prototype.requestDevice = function (...args) {
        window.__devices++;
        return request.apply(this, args);
      };
    }
  });
  await play.context.addInitScript(countStorage);
  return play;
}

/**
 * Opens `path` (under www/) in a new page of `play`'s context, collecting console errors and page
 * errors, with every figure of the page started; returns {page, problems}.
 */
export async function openFigures(play, path) {
  const page = await play.context.newPage();
  const problems = [];
  page.on('console', (m) => {
    if (m.type() === 'error') problems.push(`console: ${m.text()}`);
  });
  page.on('pageerror', (e) => problems.push(`pageerror: ${e.message}`));
  await page.goto(`${play.url}${path}`);
  await page.waitForFunction(() => customElements.get('screw-bender'));
  // Figures start lazily, near the viewport; these tests want every figure of the page started.
  await page.evaluate(() => Promise.all([...document.querySelectorAll('screw-bender')].map((e) => {
    e.setAttribute('loading', 'eager');
    return e.ready;
  })));
  return { page, problems };
}

/** Scrolls figure `id` into view and waits until it drew `n` more frames. */
export async function showFigure(page, id, n = 2) {
  await page.evaluate((i) => document.getElementById(i).scrollIntoView({ block: 'center' }), id);
  const start = await page.evaluate((i) => {
    const v = document.getElementById(i).viewer;
    v.requestDraw();
    return v.frames;
  }, id);
  for (let k = 1; k <= n; k++) {
    await page.waitForFunction(
      ([i, s]) => {
        const v = document.getElementById(i).viewer;
        v.requestDraw();
        return v.frames >= s;
      },
      [id, start + k],
      { timeout: 30000 },
    );
  }
}

/**
 * A 24×15 grey-level signature of figure `id`'s canvas (from a screenshot) and the fraction of
 * pixels that differ from the background (the top-left pixel).
 */
export async function signature(page, id) {
  await showFigure(page, id);
  const png = await page.locator(`#${id}`).screenshot();
  return page.evaluate(async (b64) => {
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
    for (let i = 0; i < d.length; i += 4) {
      if (Math.abs(d[i] - bg[0]) + Math.abs(d[i + 1] - bg[1]) + Math.abs(d[i + 2] - bg[2]) > 30) differ++;
    }
    const s = document.createElement('canvas');
    s.width = 24;
    s.height = 15;
    const sg = s.getContext('2d');
    sg.drawImage(img, 0, 0, 24, 15);
    const sd = sg.getImageData(0, 0, 24, 15).data;
    const grey = [];
    for (let i = 0; i < sd.length; i += 4) grey.push((sd[i] + sd[i + 1] + sd[i + 2]) / 3);
    return { nonBackground: differ / (d.length / 4), grey };
  }, png.toString('base64'));
}
