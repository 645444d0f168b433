// Opens an HTML page from file:// with the network cut off and reports whether the notebook
// figures in it drew: node static_page.mjs PAGE.html BACKEND SHOT.png -> one JSON line
// {figures, ready, backend, nonBackground, colours, each: [{backend, nonBackground, colours}],
// requests, problems} (backend, nonBackground and colours of the first figure; SHOT.png is the
// first figure, SHOT-2.png, SHOT-3.png, … the others).
import { elementStats, launch } from './pixels.mjs';

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
  const statics = await page.locator('.screwbender-static').count();
  const each = [];
  for (let i = 0; i < statics; i++) {
    // Figures start when they near the viewport (as a reader scrolls to them): in an exported
    // notebook a figure may sit below a page of text and plots.
    const fig = page.locator('.screwbender-static').nth(i);
    await fig.scrollIntoViewIfNeeded();
    const host = fig.locator('.screwbender-figure');
    await host.waitFor({ timeout: 60000 });
    await page.waitForFunction((k) => document.querySelectorAll('.screwbender-static')[k].querySelector('.screwbender-figure')?.dataset.ready === 'true', i, { timeout: 120000 });
    await page.waitForTimeout(1500);
    await host.scrollIntoViewIfNeeded();
    const name = i === 0 ? shot : shot.replace(/\.png$/, `-${i + 1}.png`);
    const { nonBackground, colours } = await elementStats(page, host, name);
    each.push({ backend: await host.evaluate((h) => h.dataset.backend), nonBackground, colours });
  }
  const first = each[0] ?? {};
  console.log(JSON.stringify({ figures: statics, ready: each.length === statics, ...first, each, requests, problems }));
} finally {
  await browser.close();
}
