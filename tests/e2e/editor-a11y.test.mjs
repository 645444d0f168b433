// e2e-backends: webgpu (computed on the CPU, the same on either backend: once)
// End-to-end: an accessibility audit of the playground with axe-core (from npm, injected by the
// test: the page does not ship it). The page with the help overlay, the settings panel and each
// analysis view of the dock open, the View menu open in either theme and the recording bar shown
// must have no serious or critical violation.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { playgroundPage, openPage, waitFrames, openViewMenu, ROOT, BACKEND } from './lib.mjs';

const AXE = fs.readFileSync(path.join(ROOT, 'node_modules/axe-core/axe.min.js'), 'utf8');
let play;
let page;
let problems;

before(async () => {
  // The page as most people see it (the audits include the panels' colours over the view).
  ({ play, page, problems } = await playgroundPage({ defaultLook: true }));
  // Evaluated through the debugging protocol: the page's CSP (rightly) refuses inline scripts.
  await page.evaluate(AXE);
});

after(async () => {
  await play?.close();
});

test(`${BACKEND}: the floating panels are blurred glass, and solid with reduced transparency`, async () => {
  const look = (p) => p.evaluate(() => ['title', 'toolbar', 'timeline'].map((id) => {
    const s = getComputedStyle(document.getElementById(id));
    return `${id} ${s.backdropFilter} ${s.backgroundColor}`;
  }));
  assert.deepEqual(await look(page), ['title', 'toolbar', 'timeline'].map((id) => `${id} blur(6px) rgba(255, 255, 255, 0.86)`));
  const { page: reduced } = await openPage(play.context, play.url, BACKEND);
  assert.deepEqual(await look(reduced), ['title', 'toolbar', 'timeline'].map((id) => `${id} none rgb(255, 255, 255)`));
  await reduced.close();
});

/** The serious and critical violations of the page as it is now, as readable lines. */
async function audit() {
  const found = await page.evaluate(async () => {
    const r = await window.axe.run(document, { resultTypes: ['violations'] });
    return r.violations.map((v) => ({ id: v.id, impact: v.impact, nodes: v.nodes.map((n) => n.target.join(' ')) }));
  });
  return found.filter((v) => v.impact === 'serious' || v.impact === 'critical').map((v) => `${v.impact} ${v.id}: ${v.nodes.slice(0, 4).join(', ')}`);
}

test(`${BACKEND}: axe finds no serious or critical violation (page, panel, help)`, async () => {
  // The audit runs at all (a broken injection would find nothing to report).
  assert.equal(await page.evaluate(() => typeof window.axe?.run), 'function');
  assert.deepEqual(await audit(), [], 'plain page');
  // Every folder of the settings panel open.
  await page.evaluate(() => {
    for (const f of window.screwbender.app.ui.gui.foldersRecursive()) f.open();
    window.screwbender.app.ui.gui.open();
  });
  assert.deepEqual(await audit(), [], 'settings panel open');
  await page.locator('#t-help').click();
  assert.ok(await page.locator('#help').isVisible());
  assert.deepEqual(await audit(), [], 'help overlay');
  await page.keyboard.press('Escape');
  assert.ok(!(await page.locator('#help').isVisible()), 'Esc closes the help from its button');
});

test(`${BACKEND}: axe finds no serious or critical violation in any analysis view`, async () => {
  // The dock and its tabs are fetched when a view is first opened.
  await page.evaluate(() => window.screwbender.openView('plots'));
  const ids = await page.evaluate(() => [...document.querySelectorAll('#dock .tabs button')].map((b) => b.dataset.view));
  assert.ok(ids.length >= 8, `only ${ids.length} views`);
  for (const id of ids) {
    await page.evaluate((v) => window.screwbender.openView(v), id);
    await page.evaluate(() => window.screwbender.flushViews());
    await waitFrames(page, 1);
    assert.deepEqual(await audit(), [], `view ${id}`);
  }
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: axe finds no serious or critical violation with the View menu open (both themes) or while recording`, async () => {
  for (const theme of ['light', 'dark']) {
    await page.evaluate((t) => (window.screwbender.app.updateView({ theme: t })), theme);
    await openViewMenu(page);
    assert.deepEqual(await audit(), [], `View menu, ${theme} theme`);
    await page.keyboard.press('Escape');
  }
  await page.evaluate(() => (window.screwbender.app.updateView({ theme: 'auto' })));
  await openViewMenu(page);
  await page.click('#m-video');
  await page.waitForFunction(() => !document.getElementById('rec').hidden);
  assert.deepEqual(await audit(), [], 'recording bar');
  await page.click('#rec-cancel');
  await page.waitForFunction(() => document.getElementById('rec').hidden);
});
