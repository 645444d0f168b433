// Helpers of the Python package's browser checks: Chromium for a backend (the e2e tests'
// launcher and flags) and pixel statistics of a screenshot.
import { launch } from '../../../tests/e2e/lib.mjs';

export { launch };

/** Fraction of pixels of the PNG `png` (a Buffer) that differ from its top-left pixel, and its colour count. */
export async function pixelStats(page, png) {
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
    const colours = new Set();
    for (let i = 0; i < d.length; i += 4) {
      if (Math.abs(d[i] - bg[0]) + Math.abs(d[i + 1] - bg[1]) + Math.abs(d[i + 2] - bg[2]) > 30) differ++;
      colours.add((d[i] >> 4) * 256 + (d[i + 1] >> 4) * 16 + (d[i + 2] >> 4));
    }
    return { nonBackground: differ / (d.length / 4), colours: colours.size };
  }, png.toString('base64'));
}
