// e2e-backends: webgpu (its own browser, with neither WebGPU nor WebGL: once is enough)
// Without WebGPU and WebGL every <screw-bender> figure says what it needs, keeps its caption,
// fires `error` and throws nothing into the host page.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { chromium } from 'playwright-core';
import { serveWww } from './lib.mjs';

test('no WebGPU and no WebGL: each figure says it needs WebGPU or WebGL2', async () => {
  const { url, stop } = await serveWww();
  const browser = await chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    args: ['--headless=new', '--no-sandbox', '--disable-3d-apis', '--disable-webgl', '--disable-gpu', '--no-first-run'],
  });
  try {
    const page = await browser.newPage();
    const problems = [];
    page.on('pageerror', (e) => problems.push(e.message));
    await page.addInitScript(() => {
      window.__errors = [];
      document.addEventListener('error', (e) => e.target?.tagName === 'SCREW-BENDER' && window.__errors.push(e.target.id), true);
    });
    await page.goto(`${url}examples/course.html`);
    await page.waitForFunction(() => customElements.get('screw-bender'));
    const figs = await page.evaluate(async () => {
      const els = [...document.querySelectorAll('screw-bender')];
      // Figures start lazily near the viewport: every one is started here.
      await Promise.all(els.map((e) => {
        e.setAttribute('loading', 'eager');
        return e.ready;
      }));
      return els.map((e) => ({
        id: e.id,
        message: e.shadowRoot.querySelector('.msg').textContent,
        hidden: e.shadowRoot.querySelector('.msg').hidden,
        caption: e.shadowRoot.querySelector('slot').assignedNodes().filter((n) => n.nodeName !== 'SCRIPT').map((n) => n.textContent).join('').trim(),
      }));
    });
    assert.equal(figs.length, 4);
    for (const f of figs) {
      assert.equal(f.hidden, false, f.id);
      assert.match(f.message, /needs WebGPU or WebGL2/, f.id);
      assert.match(f.caption, /^Figure \d/, `${f.id} keeps its caption`);
    }
    assert.deepEqual((await page.evaluate(() => window.__errors)).sort(), figs.map((f) => f.id).sort());
    assert.deepEqual(problems, []);
  } finally {
    await browser.close();
    stop();
  }
});
