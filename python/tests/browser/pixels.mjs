// Helpers of the Python package's browser checks: Chromium for a backend and the pixel
// statistics of a screenshot, both those of the e2e tests (tests/e2e/lib.mjs).
import fs from 'node:fs';
import { canvasStats, launch } from '../../../tests/e2e/lib.mjs';

export { launch };

/**
 * The e2e tests' `canvasStats` (fraction of pixels unlike the top-left one, colour count, …) of
 * a screenshot of `locator` on `page`, written to `file` when given; the PNG is `png`.
 * (`canvasStats` screenshots the page's `#view`: it is handed a page whose `#view` is `locator`.)
 */
export async function elementStats(page, locator, file) {
  const stats = await canvasStats({ locator: () => locator, evaluate: (...args) => page.evaluate(...args) });
  if (file) fs.writeFileSync(file, stats.png);
  return stats;
}
