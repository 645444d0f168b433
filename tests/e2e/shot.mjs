// Ad-hoc screenshot: node tests/e2e/shot.mjs URL BACKEND OUT.png [preset] [view]
// (view: an analysis view of the dock to open, e.g. plots; SHOT_EVAL='js' runs code first).
import { launch, openPage, waitFrames } from './lib.mjs';
const [url, backend, out, preset, view] = process.argv.slice(2);
const browser = await launch(backend);
const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
const { page, problems } = await openPage(context, url, backend);
if (preset) {
  await page.evaluate((id) => window.screwbender.app.run('loadPreset', id), preset);
  await waitFrames(page, 2);
}
if (view) {
  await page.evaluate((id) => window.screwbender.openView(id), view);
  await page.evaluate(() => window.screwbender.flushViews());
}
if (process.env.SHOT_EVAL) await page.evaluate(process.env.SHOT_EVAL);
await waitFrames(page, 2);
await page.waitForTimeout(300);
await page.screenshot({ path: out });
console.log(JSON.stringify({ backend: await page.evaluate(() => window.screwbender.backend()), problems, errors: await page.evaluate(() => window.screwbender.errors()) }));
await browser.close();
