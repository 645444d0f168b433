// e2e-backends: webgpu (computed on the CPU, the same on either backend: once)
// End-to-end: the playground with the keyboard alone. Tab reaches every control (toolbar, panel,
// dock, timeline) and the 3-D view; the page's shortcuts act only while the view (or the page
// itself) has the focus; with the view focused a pose is selected, moved and rotated in steps,
// and undo takes the key edits back. Every named command (www/js/editor/commands.js) is done,
// undone and redone through the Undo menu, which names it.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { playgroundPage, waitFrames, BACKEND } from './lib.mjs';

let play;
let page;
let problems;

before(async () => {
  ({ play, page, problems } = await playgroundPage());
});

after(async () => {
  await play?.close();
});

const sb = (f, arg) => page.evaluate(f, arg);
const poses = async () => Array.from(await sb(() => window.screwbender.poses()));

/** A description of the focused element: its id or a selector-like path, and its accessible name. */
const focused = () =>
  sb(() => {
    const e = document.activeElement;
    if (!e || e === document.body) return { key: 'body', name: 'body' };
    const labelled = e.getAttribute('aria-labelledby');
    const name = (
      e.getAttribute('aria-label') ||
      (labelled && document.getElementById(labelled)?.textContent) ||
      (e.labels?.length ? [...e.labels].map((l) => l.textContent).join(' ') : '') ||
      (e.tagName === 'BUTTON' ? e.textContent : '') ||
      e.title ||
      ''
    ).trim();
    const path = e.id ? `#${e.id}` : `${e.closest('[id]')?.id ?? ''} ${e.tagName.toLowerCase()}${e.type ? `[${e.type}]` : ''}`;
    return { key: path, name, dock: !!e.closest('#dock'), panel: !!e.closest('#panel'), toolbar: !!e.closest('#toolbar'), timeline: !!e.closest('#timeline') };
  });

async function fresh() {
  await sb(() => {
    window.screwbender.app.ui.toggleHelp(false);
    window.screwbender.app.parts.session.openPreset('l_cycle_rotated');
    window.screwbender.app.history.clear?.();
    document.activeElement?.blur();
  });
  await waitFrames(page, 1);
}

/** Presses Tab until the focus comes back to where it started; returns every stop. */
async function tabRound() {
  const seen = [];
  for (let k = 0; k < 150; k++) {
    await page.keyboard.press('Tab');
    const f = await focused();
    if (seen.length && f.key === seen[0].key && f.name === seen[0].name) break;
    seen.push(f);
  }
  return seen;
}

test(`${BACKEND}: Tab walks toolbar, panel, dock, timeline and the view; every stop has a name`, async () => {
  await fresh();
  const sel0 = await sb(() => window.screwbender.selected());
  // The panel open, the dock closed.
  await sb(() => window.screwbender.app.ui.gui.open());
  let seen = await tabRound();
  // Tab moves the focus and nothing else (not the selected pose).
  assert.equal(await sb(() => window.screwbender.selected()), sel0);
  const enabled = await sb(() =>
    [...document.querySelectorAll('#toolbar button, #timeline button, #timeline input')].filter((e) => !e.disabled).map((e) => `#${e.id}`),
  );
  const keys = seen.map((f) => f.key);
  for (const id of ['#view', ...enabled]) assert.ok(keys.includes(id), `${id} not reached by Tab: ${keys.join(', ')}`);
  const inPanel = seen.filter((f) => f.panel).length;
  const panelControls = await sb(
    () => [...document.querySelectorAll('#panel button, #panel input, #panel select')].filter((e) => !e.disabled && e.offsetParent && e.tabIndex >= 0).length,
  );
  assert.ok(inPanel >= 10 && inPanel === panelControls, `${inPanel} of the panel's ${panelControls} controls reached`);
  let unnamed = seen.filter((f) => f.key !== 'body' && !f.name);
  assert.deepEqual(unnamed, [], 'controls without an accessible name');
  // The dock open: its tabs and the open view's controls are reached too.
  await sb(() => window.screwbender.openView('steps'));
  seen = await tabRound();
  const inDock = seen.filter((f) => f.dock).length;
  // Every tab of the row (those that do not fit are in the "More" menu, whose button is a stop).
  const tabStops = await sb(() => [...document.querySelectorAll('#dock .tabs button, #dock .more')].filter((b) => !b.hidden).length);
  assert.ok(tabStops >= 4, `${tabStops} tab stops`);
  assert.ok(inDock >= tabStops + 3, `only ${inDock} stops in the dock`);
  unnamed = seen.filter((f) => f.key !== 'body' && !f.name);
  assert.deepEqual(unnamed, [], 'controls without an accessible name');
  // The play button is named in words, not by its symbol.
  assert.equal(await page.locator('#play').getAttribute('aria-label'), 'Play');
  // Focus is visible: the focused control draws an outline.
  await page.locator('#t-frame').focus();
  await page.keyboard.press('Shift+Tab');
  await page.keyboard.press('Tab');
  assert.equal(await sb(() => document.activeElement.id), 't-frame');
  const outline = await sb(() => getComputedStyle(document.activeElement).outlineStyle);
  assert.notEqual(outline, 'none');
  await sb(() => window.screwbender.openView(''));
});

test(`${BACKEND}: keys inside a control keep their meaning there`, async () => {
  await fresh();
  await sb(() => window.screwbender.app.select(2));
  const p0 = await poses();
  // Space on a focused toolbar button presses that button; it does not toggle playback.
  await page.locator('#t-frame').focus();
  await page.keyboard.press(' ');
  assert.equal(await sb(() => window.screwbender.app.anim.playing), false);
  // Backspace and Delete on the timeline slider do not delete the selected pose; arrows move the slider.
  await page.locator('#scrub').focus();
  await page.keyboard.press('Backspace');
  await page.keyboard.press('Delete');
  await page.keyboard.press('ArrowRight');
  assert.deepEqual(await poses(), p0);
  assert.ok((await sb(() => Number(document.getElementById('scrub').value))) > 0, 'the slider moved');
  // Digits inside the panel's number field do not change the levels.
  const levels = await sb(() => window.screwbender.options().levels);
  await page.locator('#play').focus();
  await page.keyboard.press('b');
  assert.equal(await sb(() => window.screwbender.options().scheme), 'fourpoint', 'b on a focused button changed the scheme');
  assert.equal(await sb(() => window.screwbender.options().levels), levels);
});

test(`${BACKEND}: with the view focused, keys select, move and rotate a pose; undo takes them back`, async () => {
  await fresh();
  await sb(() => window.screwbender.app.select(-1));
  const p0 = await poses();
  await page.locator('#view').focus();
  await page.keyboard.press('n');
  assert.equal(await sb(() => window.screwbender.selected()), 0);
  await page.keyboard.press('n');
  assert.equal(await sb(() => window.screwbender.selected()), 1);
  await page.keyboard.press('p');
  assert.equal(await sb(() => window.screwbender.selected()), 0);
  const i = 0;
  // Moves: 0.25 along x, 0.025 along y (Shift: fine), 0.25 along z (Page Up).
  await page.keyboard.press('ArrowRight');
  await page.keyboard.press('Shift+ArrowUp');
  await page.keyboard.press('PageUp');
  const p1 = await poses();
  const d = [0, 1, 2].map((a) => p1[7 * i + a] - p0[7 * i + a]);
  assert.ok(Math.abs(d[0] - 0.25) < 1e-12 && Math.abs(d[1] - 0.025) < 1e-12 && Math.abs(d[2] - 0.25) < 1e-12, `moved by ${d}`);
  assert.deepEqual(p1.slice(7 * i + 3, 7 * i + 7), p0.slice(7 * i + 3, 7 * i + 7), 'a move keeps the rotation');
  for (let k = 0; k < p0.length; k++) if (Math.floor(k / 7) !== i) assert.equal(p1[k], p0[k], 'other poses stay');
  // Rotation: Alt + → turns the pose by 15° about world x (q' = q_x(15°) q).
  await page.keyboard.press('Alt+ArrowRight');
  const p2 = await poses();
  const q1 = p1.slice(7 * i + 3, 7 * i + 7);
  const q2 = p2.slice(7 * i + 3, 7 * i + 7);
  const h = (15 * Math.PI) / 360;
  const [c, s] = [Math.cos(h), Math.sin(h)];
  const want = [c * q1[0] - s * q1[1], c * q1[1] + s * q1[0], c * q1[2] - s * q1[3], c * q1[3] + s * q1[2]];
  for (let k = 0; k < 4; k++) assert.ok(Math.abs(q2[k] - want[k]) < 1e-9, `quaternion ${q2} != ${want}`);
  assert.deepEqual(p2.slice(7 * i, 7 * i + 3), p1.slice(7 * i, 7 * i + 3), 'a rotation keeps the origin');
  // Undo: the rotation, then the moves (presses within a second are one step).
  await page.keyboard.press('Control+z');
  assert.deepEqual(await poses(), p1);
  await page.keyboard.press('Control+z');
  assert.deepEqual(await poses(), p0);
  await page.keyboard.press('Control+Shift+z');
  assert.deepEqual(await poses(), p1);
  // Delete removes the selected pose from the view.
  await page.keyboard.press('Delete');
  assert.equal((await poses()).length / 7, p0.length / 7 - 1);
  await page.keyboard.press('Control+z');
  assert.equal((await poses()).length, p0.length);
  // Space on the view toggles playback.
  await page.keyboard.press(' ');
  assert.equal(await sb(() => window.screwbender.app.anim.playing), true);
  await page.keyboard.press(' ');
  assert.equal(await sb(() => window.screwbender.app.anim.playing), false);
  assert.deepEqual(problems, []);
});

/** An open motion of 5 control poses, as fitPoses returns one. */
const FITTED = {
  closed: false,
  poses: [0, 1, 2, 3, 4].map((i) => ({ origin: [i, 0.5 * Math.sin(i), 0], rotation: [Math.cos(0.2 * i), 0, 0, Math.sin(0.2 * i)] })),
};

// Every command of editor/commands.js, as a page would run it: [name, args, the Undo menu's label].
// `prepare` runs first (no command of its own: a selection).
const COMMAND_CASES = [
  ['loadPreset', ['pendulum'], 'Load the preset Pendulum'],
  ['setOption', ['levels', 3], 'Set levels to 3'],
  ['setScheme', ['bspline'], 'Scheme: cubic B-spline'],
  ['setS', [0.3], 'Set s to 0.3'],
  ['setClosed', [false], 'Open the cycle'],
  ['setView', ['showGrid', false], 'Hide grid'],
  ['insertPose', [], 'Insert a pose after pose 0', 0],
  ['deletePose', [], 'Delete pose 1', 1],
  ['setPose', [0, { origin: [0.5, 0.25, 0], rotation: [1, 0, 0, 0] }], 'Move pose 0'],
  // What the import dialog's Fit runs: the fitted control poses, with the B-spline scheme.
  ['loadFit', [FITTED, 'bspline'], 'Fit 5 control poses'],
  ['setTimes', [], 'Retime the keys'],
  ['setVelocities', [], 'Set the key velocities'],
  ['lessonStep', [{ title: 'Fewer copies', display: { strobe: 7 } }], 'Lesson: Fewer copies'],
  ['openSession', ['circle4'], 'Open kept work'],
];

test(`${BACKEND}: every command is done, undone and redone through the Undo menu, which names it`, async () => {
  const names = await sb(async () => Object.keys((await import('./js/editor/commands.js')).COMMANDS));
  assert.deepEqual(COMMAND_CASES.map((c) => c[0]).sort(), [...names].sort(), 'a case for every command');
  await sb(() => window.screwbender.app.run('loadPreset', 'l_cycle_rotated'));
  /** The edited state: motion, options and display (undo keeps the camera and the playhead). */
  const state = () => sb(() => {
    const s = JSON.parse(window.screwbender.app.parts.session.snapshot());
    return JSON.stringify([s.document, s.options, s.view]);
  });
  /** Opens the Undo menu with a right click on `button`; returns the labels listed under `side`. */
  const menu = async (button, side) => {
    await page.click(button, { button: 'right' });
    await page.locator('#undo-menu').waitFor({ state: 'visible' });
    return sb((which) => {
      const items = [...document.querySelectorAll('#undo-menu > *')];
      const at = items.findIndex((e) => e.textContent === which);
      const out = [];
      for (let k = at + 1; k < items.length && items[k].tagName === 'BUTTON'; k++) out.push(items[k].textContent);
      return out;
    }, side);
  };
  for (const [name, args, label, select] of COMMAND_CASES) {
    if (select !== undefined) await sb((k) => window.screwbender.app.select(k), select);
    const before = await state();
    await sb(async ([n, a]) => {
      const { app } = window.screwbender;
      // openSession takes a whole session: another preset's, as a draft of another tab holds.
      if (n === 'openSession') {
        const keep = app.parts.session.snapshot();
        app.parts.session.openPreset(a[0]);
        const other = app.parts.session.session(false);
        app.parts.session.applySession(JSON.parse(keep));
        a = [other];
      }
      // The timing commands take one value per key of the motion at hand.
      if (n === 'setTimes') a = [app.keyTimes().map((t) => 2 * t)];
      if (n === 'setVelocities') a = [Array.from({ length: app.motion.poseCount }, (_, i) => (i === 1 ? 0.25 : null))];
      app.run(n, ...a);
    }, [name, args]);
    const after = await state();
    assert.notEqual(after, before, `${name} changed nothing`);
    assert.deepEqual((await menu('#t-undo', 'Undo')).slice(0, 1), [label], `${name}: the Undo menu's first entry`);
    await page.click('#undo-menu button[data-side=undo][data-steps="1"]');
    assert.equal(await state(), before, `${name}: undone through the menu`);
    assert.deepEqual((await menu('#t-redo', 'Redo')).slice(0, 1), [label], `${name}: the Redo entry`);
    await page.click('#undo-menu button[data-side=redo][data-steps="1"]');
    assert.equal(await state(), after, `${name}: redone through the menu`);
  }
  assert.match(await page.locator('#t-undo').getAttribute('title'), /^Undo: Open kept work/);
  assert.deepEqual(problems, []);
});
