// e2e-backends: webgpu (its own browser, with neither WebGPU nor WebGL: once is enough)
// Without WebGPU and WebGL the page must say so clearly (a banner), not fail silently.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { chromium } from 'playwright-core';
import { serveWww } from './lib.mjs';

test('no WebGPU and no WebGL: a clear message in the page', async () => {
  const { url, stop } = await serveWww();
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    args: ['--headless=new', '--no-sandbox', '--disable-3d-apis', '--disable-webgl', '--disable-gpu', '--no-first-run'],
  });
  try {
    const page = await browser.newPage();
    await page.goto(url);
    await page.locator('#banner.fatal').waitFor({ timeout: 30000 });
    const text = await page.locator('#banner .msg').textContent();
    assert.match(text, /neither WebGPU nor WebGL2/);
    assert.equal(await page.locator('#backend').textContent(), 'no graphics');
  } finally {
    await browser.close();
    stop();
  }
});
