// e2e-backends: webgpu (computed on the CPU, the same on either backend: once)
// The page's notice where a subdivision is silently poor (Motion.warnings: the V1 4-point and
// Jarek rules across half a turn), and the Methods view's Chaudhry–Cameron vertex plots with end
// condition (18)/(19) and the Barr et al. baseline beside Ramamoorthi–Barr. Screenshots go to
// artifacts/e2e-<backend>/ at 1280×800 and 390×844.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { BACKEND, DESKTOP, ROOT, playgroundPage, waitFrames } from './lib.mjs';

const ARTIFACTS = path.join(ROOT, `artifacts/e2e-${BACKEND}`);
let play;
let page;
let problems;

before(async () => {
  fs.mkdirSync(ARTIFACTS, { recursive: true });
  ({ play, page, problems } = await playgroundPage());
});

after(async () => {
  await play?.close();
});

const sb = (f, arg) => page.evaluate(f, arg);

test(`${BACKEND}: a notice names the span where the split 4-point rule turns by half a turn`, async () => {
  await sb(() => window.screwbender.app.run('loadPreset', 'circle4'));
  const before = (await sb(() => window.screwbender.errors())).length;
  await sb(() => window.screwbender.app.run('setScheme', 'fourpoint'));
  await sb(() => window.screwbender.app.run('setOption', 'rules', 'split'));
  await waitFrames(page, 1);
  const errors = (await sb(() => window.screwbender.errors())).slice(before);
  assert.equal(errors.length, 1, errors.join('\n'));
  assert.match(errors[0], /^Warning: span 0: the split-then-tweak 4-point rule .* 180\.0° .*\(3 more spans likewise\)$/);
  const banner = page.locator('#banner');
  assert.equal(await banner.isVisible(), true);
  assert.match(await banner.textContent(), /span 0/);
  await page.screenshot({ path: path.join(ARTIFACTS, 'warning-split-circle4.png') });
  // The direct rules are fine: no further notice; back to split, the same warning is not repeated
  // while it holds.
  await sb(() => window.screwbender.app.run('setOption', 'rules', 'direct'));
  await sb(() => window.screwbender.app.run('setOption', 'levels', 3));
  assert.equal((await sb(() => window.screwbender.errors())).length, before + 1);
  // Five or more poses with the split rules: no notice.
  await sb(() => window.screwbender.app.run('loadPreset', 'l_cycle_rotated'));
  await sb(() => window.screwbender.app.run('setOption', 'rules', 'split'));
  assert.equal((await sb(() => window.screwbender.errors())).length, before + 1);
  assert.deepEqual(problems, []);
});

test(`${BACKEND}: Methods view plots Chaudhry–Cameron's vertices with end condition (18) or (19), and Barr et al. beside R–B`, async () => {
  await sb(() => window.screwbender.app.run('loadPreset', 'triangle7'));
  await sb(() => window.screwbender.openView('methods'));
  await sb(() => window.screwbender.flushViews());
  const cc = () => sb(() => {
    const r = window.screwbender.app.dock.current.cc;
    return { continuity: r.bezier.continuity, n: r.t.length, v: r.vertices.length, warnings: r.warnings, growth: r.growth, last: r.bezier.segments.at(-1).quaternions };
  });
  let r = await cc();
  assert.equal(r.continuity, 'C1 (18)');
  assert.equal(r.n, 400);
  assert.equal(r.v, 9 * 400);
  assert.deepEqual(r.warnings, []);
  assert.equal(await page.locator('#dock section[data-view=methods] .cc .chart').count(), 3);
  await page.locator('#dock section[data-view=methods] select[aria-label="Chaudhry–Cameron end condition"]').selectOption('19');
  r = await cc();
  assert.equal(r.continuity, 'C1 (19)');
  // (19): the last quaternion segment is straight.
  for (let c = 0; c < 4; c++) assert.ok(Math.abs(r.last[1][c] - (r.last[0][c] + r.last[2][c]) / 2) < 1e-12);
  await sb(() => { document.getElementById('banner').hidden = true; });
  await sb(() => document.querySelector('#dock section[data-view=methods] .cc h4').scrollIntoView({ block: 'start' }));
  await waitFrames(page, 2);
  await page.screenshot({ path: path.join(ARTIFACTS, 'view-methods-cc19.png') });
  // Barr et al. beside R–B on scene C1.
  await sb(() => window.screwbender.app.run('loadPreset', 'rb_sphere7'));
  await sb(() => window.screwbender.flushViews());
  await sb(() => window.screwbender.app.dock.current.select(['rb', 'barr', 'jarek']));
  await sb(() => window.screwbender.flushViews());
  const b = await sb(() => {
    const x = window.screwbender.app.dock.current.barr;
    return { barr: x.barr.objective, rb: x.rb.objective, frames: x.barr.frames, ms: x.barrMs };
  });
  assert.ok(b.barr <= b.rb && (b.rb - b.barr) / b.barr < 0.005, `${b.barr} ${b.rb}`);
  assert.equal(b.frames, 601);
  assert.ok(b.ms > 0);
  assert.match(await page.locator('#dock section[data-view=methods] .barr').textContent(), /R–B is 0\.\d\d % above/);
  await sb(() => document.querySelector('#dock section[data-view=methods] .barr h4').scrollIntoView({ block: 'start' }));
  await waitFrames(page, 2);
  await page.screenshot({ path: path.join(ARTIFACTS, 'view-methods-barr.png') });
  await page.setViewportSize({ width: 390, height: 844 });
  await waitFrames(page, 3);
  await page.screenshot({ path: path.join(ARTIFACTS, 'view-methods-barr-phone.png') });
  await sb(() => window.screwbender.app.run('loadPreset', 'triangle7'));
  await sb(() => window.screwbender.flushViews());
  await sb(() => document.querySelector('#dock section[data-view=methods] .cc h4').scrollIntoView({ block: 'start' }));
  await waitFrames(page, 2);
  await page.screenshot({ path: path.join(ARTIFACTS, 'view-methods-cc-phone.png') });
  await page.setViewportSize(DESKTOP);
  assert.deepEqual(problems, []);
  assert.deepEqual((await sb(() => window.screwbender.errors())).filter((m) => !m.startsWith('Warning: ')), []);
});
