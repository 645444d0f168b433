// Without WebGPU and WebGL the page must say so clearly (a banner), not fail silently.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import net from 'node:net';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

test('no WebGPU and no WebGL: a clear message in the page', async () => {
  const port = await new Promise((r) => {
    const s = net.createServer();
    s.listen(0, '127.0.0.1', () => {
      const p = s.address().port;
      s.close(() => r(p));
    });
  });
  const server = spawn(process.execPath, [path.join(ROOT, 'scripts/serve.mjs'), path.join(ROOT, 'www')], {
    env: { ...process.env, PORT: String(port), SERVE_QUIET: '1' },
    stdio: ['ignore', 'pipe', 'inherit'],
  });
  await new Promise((r) => server.stdout.on('data', (d) => d.toString().includes('http://') && r()));
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    args: ['--headless=new', '--no-sandbox', '--disable-3d-apis', '--disable-webgl', '--disable-gpu', '--no-first-run'],
  });
  try {
    const page = await browser.newPage();
    await page.goto(`http://127.0.0.1:${port}/`);
    await page.locator('#banner.fatal').waitFor({ timeout: 30000 });
    const text = await page.locator('#banner .msg').textContent();
    assert.match(text, /neither WebGPU nor WebGL2/);
    assert.equal(await page.locator('#backend').textContent(), 'no graphics');
  } finally {
    await browser.close();
    server.kill();
  }
});
