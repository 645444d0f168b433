// e2e-backends: webgpu (labels follow the view a renderer draws)
// Labels on poses and descriptions of <screw-bender> (www/js/element/labels.js, chrome.js):
// a child with slot="pose-1" (or slot="pose" data-pose="2") sits at its pose's projection within
// 2 px after an orbit and a drag, hides behind the camera, takes the page's ::part and variable
// styles; `alt` is the figure's accessible name; the polite live region says what each action
// changed; axe-core finds no serious or critical violation, focused or not.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { ROOT } from './lib.mjs';
import { EXPECTED_BACKEND, OPEN3, canvasBox, figureFrames, openOnePage, pageHtml } from './element-lib.mjs';

let b;
let page;
let problems;
before(async () => {
  ({ b, page, problems } = await openOnePage(pageHtml(`<main style="width: 800px">
<h1>Labels</h1>
<screw-bender id="f" editable loading="eager" controls="full" alt="Three poses of a bar joined by the 4-point motion" scheme="fourpoint" levels="4">
<script type="application/json">${JSON.stringify(OPEN3)}</script>
Figure 1. A caption.
<span slot="pose-1" class="lab">P₁</span>
<b slot="pose" data-pose="2">the end</b>
</screw-bender>
<p><button id="after">after</button></p></main>`, {
    head: `<style>
#f { --screw-bender-label-offset: 0px; }
#f::part(label-2) { background: rgb(255, 236, 179); }
</style>`,
  })));
  await page.evaluate(() => document.getElementById('f').ready);
  await figureFrames(page, '#f');
});
after(async () => {
  await b?.close();
});

/** Each label box's anchor (bottom centre, offset 0) and the projection of its pose, in page px. */
const anchors = () =>
  page.evaluate(() => {
    const el = document.getElementById('f');
    return [1, 2].map((k) => {
      const box = el.shadowRoot.querySelector(`[part~="label-${k}"]`);
      const r = box.getBoundingClientRect();
      return { k, hidden: box.hidden, at: { x: r.left + r.width / 2, y: r.bottom }, pose: el.viewer.screenOfPose(k), text: box.querySelector('slot').assignedNodes().map((n) => n.textContent).join('') };
    });
  });

function near(list, what) {
  for (const a of list) {
    assert.equal(a.hidden, false, `${what}: label ${a.k} shown`);
    const d = Math.hypot(a.at.x - a.pose.x, a.at.y - a.pose.y);
    assert.ok(d <= 2, `${what}: label ${a.k} is ${d.toFixed(2)} px from its pose`);
  }
}

test(`${EXPECTED_BACKEND}: labels sit on their poses through an orbit and a drag, hide behind the camera, take the page's styles`, async () => {
  let a = await anchors();
  assert.deepEqual(a.map((x) => x.text), ['P₁', 'the end']);
  near(a, 'at load');
  // The caption keeps the other children.
  const caption = await page.evaluate(() => document.getElementById('f').shadowRoot.querySelector('.caption slot').assignedNodes().map((n) => n.textContent).join('').trim());
  assert.match(caption, /^\{.*\}\s*Figure 1\. A caption\.$/s);
  // Orbit: a real drag on empty space.
  const box = await canvasBox(page, '#f');
  await page.mouse.move(box.x + 20, box.y + 20);
  await page.mouse.down();
  for (let k = 1; k <= 8; k++) await page.mouse.move(box.x + 20 + 12 * k, box.y + 20 + 4 * k);
  await page.mouse.up();
  await figureFrames(page, '#f');
  const moved = await anchors();
  near(moved, 'after an orbit');
  assert.ok(Math.hypot(moved[0].at.x - a[0].at.x, moved[0].at.y - a[0].at.y) > 5, 'the orbit moved the label');
  // Drag pose 1 by its handle: its label follows.
  a = moved;
  await page.mouse.move(a[0].pose.x, a[0].pose.y);
  await page.mouse.down();
  for (let k = 1; k <= 8; k++) await page.mouse.move(a[0].pose.x + 5 * k, a[0].pose.y - 4 * k);
  await page.mouse.up();
  await figureFrames(page, '#f');
  const dragged = await anchors();
  near(dragged, 'after a drag');
  assert.ok(Math.hypot(dragged[0].at.x - a[0].at.x, dragged[0].at.y - a[0].at.y) > 10, 'the drag moved label 1');
  // Behind the camera: the eye between the target and pose 2, looking away from it.
  const hidden = await page.evaluate(async () => {
    const el = document.getElementById('f');
    const p = el.motion.pose(2).origin;
    const yaw = 0.4;
    const pitch = 0.3;
    const dir = [Math.cos(pitch) * Math.cos(yaw), Math.cos(pitch) * Math.sin(yaw), Math.sin(pitch)];
    el.camera = { yaw, pitch, distance: 0.5, target: p.map((x, i) => x - dir[i]) };
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    el.viewer.requestDraw();
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    return el.shadowRoot.querySelector('[part~="label-2"]').hidden;
  });
  assert.equal(hidden, true, 'a pose behind the camera has no label');
  // Styles: ::part from the page, the variable for the offset.
  const style = await page.evaluate(() => getComputedStyle(document.getElementById('f').shadowRoot.querySelector('[part~="label-2"]')).backgroundColor);
  assert.equal(style, "rgb(255, 236, 179)");
  // A label added later, and one whose pose does not exist.
  const late = await page.evaluate(async () => {
    const el = document.getElementById('f');
    el.viewer.frameAll();
    const s = document.createElement('i');
    s.slot = 'pose-0';
    s.textContent = 'P₀';
    el.append(s);
    const t = document.createElement('i');
    t.slot = 'pose-9';
    t.textContent = 'none';
    el.append(t);
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    el.viewer.requestDraw();
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    const q = (k) => el.shadowRoot.querySelector(`[part~="label-${k}"]`);
    return { zero: q(0) && !q(0).hidden, nine: q(9)?.hidden };
  });
  assert.deepEqual(late, { zero: true, nine: true });
  assert.deepEqual(problems, []);
});

/** axe-core's serious and critical violations on the page. */
async function axe() {
  await page.addScriptTag({ path: path.join(ROOT, 'node_modules/axe-core/axe.min.js') });
  return page.evaluate(async () => {
    const r = await window.axe.run(document, { resultTypes: ['violations'] });
    return r.violations.filter((v) => v.impact === 'serious' || v.impact === 'critical').map((v) => `${v.id}: ${v.nodes.map((n) => n.target.join(' ')).join(', ')}`);
  });
}

const live = () => page.evaluate(() => document.getElementById('f').shadowRoot.querySelector('[aria-live="polite"]').textContent);

test(`${EXPECTED_BACKEND}: alt is the accessible name; the live region says each change; axe-clean focused and not`, async () => {
  // The accessible name from the browser's own accessibility tree.
  const cdp = await page.context().newCDPSession(page);
  const { nodes } = await cdp.send('Accessibility.getFullAXTree');
  const names = nodes.filter((n) => n.role?.value === 'application').map((n) => n.name?.value);
  assert.deepEqual(names, ['Three poses of a bar joined by the 4-point motion']);
  assert.deepEqual(await axe(), [], 'unfocused');
  await page.evaluate(() => document.getElementById('f').shadowRoot.querySelector('canvas').focus());
  assert.deepEqual(await axe(), [], 'focused');
  // Each action, in words (the last test left pose 1 selected).
  await page.keyboard.press('Escape');
  assert.equal(await live(), 'No pose selected');
  await page.keyboard.press('ArrowRight');
  assert.match(await live(), /^Pose 0 at \(0\.00, 0\.00, 0\.00\) selected$/);
  await page.keyboard.press('ArrowRight');
  const sel = await live();
  assert.match(sel, /^Pose 1 at \(-?\d+\.\d\d, -?\d+\.\d\d, -?\d+\.\d\d\) selected$/);
  await page.keyboard.press(' ');
  assert.equal(await live(), 'Playing');
  await page.keyboard.press(' ');
  assert.match(await live(), /^Paused at \d+\.\d\d s$/);
  // A drag of the selected pose.
  const p = await page.evaluate(() => document.getElementById('f').viewer.screenOfPose(1));
  await page.mouse.move(p.x, p.y);
  await page.mouse.down();
  for (let k = 1; k <= 6; k++) await page.mouse.move(p.x - 4 * k, p.y + 3 * k);
  await page.mouse.up();
  const moved = await live();
  assert.match(moved, /^Pose 1 moved to \(-?\d+\.\d\d, -?\d+\.\d\d, -?\d+\.\d\d\)$/);
  const pos = await page.evaluate(() => Array.from(document.getElementById('f').motion.pose(1).origin, (x) => (Math.abs(x) < 5e-3 ? 0 : x).toFixed(2)).join(', '));
  assert.equal(moved, `Pose 1 moved to (${pos})`);
  // Scheme and levels from the full controls.
  await page.evaluate(() => {
    const s = document.getElementById('f').shadowRoot.querySelector('.scheme');
    s.value = 'jarek';
    s.dispatchEvent(new Event('change'));
  });
  assert.equal(await live(), 'Jarek scheme, 4 levels');
  await page.evaluate(() => document.getElementById('f').setAttribute('levels', '3'));
  assert.equal(await live(), 'Jarek scheme, 3 levels');
  await page.keyboard.press('Escape');
  assert.equal(await live(), 'No pose selected');
  assert.deepEqual(await axe(), [], 'after the actions');
  assert.deepEqual(problems, []);
});
