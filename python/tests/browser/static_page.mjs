// Opens an HTML page from file:// with the network cut off and reports whether the notebook
// figures in it drew: node static_page.mjs PAGE.html BACKEND SHOT.png -> one JSON line
// {figures, ready, backend, nonBackground, colours, requests}.
import { launch, pixelStats } from './pixels.mjs';

const [file, backend = 'webgpu', shot] = process.argv.slice(2);
const browser = await launch(backend);
try {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
  await context.setOffline(true);
  const requests = [];
  await context.route('**/*', (route) => {
    const url = route.request().url();
    if (url.startsWith('file:') || url.startsWith('data:') || url.startsWith('blob:')) return route.continue();
    requests.push(url);
    return route.abort();
  });
  const page = await context.newPage();
  const problems = [];
  page.on('pageerror', (e) => problems.push(e.message));
  await page.goto(`file://${file}`);
  const fig = page.locator('.screwbender-figure').first();
  await fig.waitFor({ timeout: 60000 });
  // Figures start when they near the viewport (as a reader scrolls to them): in an exported
  // notebook the first one may sit below a page of text and plots.
  await fig.scrollIntoViewIfNeeded();
  await page.waitForFunction(() => document.querySelector('.screwbender-figure')?.dataset.ready === 'true', null, { timeout: 120000 });
  await page.waitForTimeout(1500);
  await fig.scrollIntoViewIfNeeded();
  const png = await fig.screenshot({ path: shot });
  const stats = await pixelStats(page, png);
  const info = await page.evaluate(() => ({
    figures: document.querySelectorAll('.screwbender-figure').length,
    backend: document.querySelector('.screwbender-figure').dataset.backend,
  }));
  console.log(JSON.stringify({ ...info, ready: true, ...stats, requests, problems }));
} finally {
  await browser.close();
}
