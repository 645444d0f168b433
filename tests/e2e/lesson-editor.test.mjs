// e2e-backends: webgpu (the editor's forms and the lesson checks are computed on the CPU: once)
// The lesson editor (www/js/lessons/editor/, docs/teaching/editor.md) with real mouse and
// keyboard events only, no JSON typed: a two-step lesson — a multiple-choice question with a
// `why`, then a pose check filled from the current pose with a tolerance and a highlight picked
// by clicking the pose — is built, previewed and solved as a student (first a wrong answer, and
// the pose dragged past the tolerance), saved, and reopened from the file and from the lesson link in a fresh browser context, giving
// the same lesson. Every editor action is undone and redone, each step back and forth giving
// the lesson as it was. The drafts survive a reload and show in a second tab, and a deleted one
// comes back with Undo. A lesson link over the limit gets the message. Screenshots go to
// artifacts/e2e-<backend>/lesson-editor/.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import { BACKEND, DESKTOP, mouseDrag, openPage, shotPath, startPlayground, waitFrames } from './lib.mjs';

let play;
let page;
let problems;

before(async () => {
  play = await startPlayground({ acceptDownloads: true });
  ({ page, problems } = await openPage(play.context, play.url, BACKEND));
  await page.evaluate(() => window.screwbender.lessons);
});

after(async () => {
  await play?.close();
});

/** The lesson drafts this page's storage holds, newest first. */
const drafts = (p = page) =>
  p.evaluate(() =>
    Object.keys(localStorage)
      .filter((k) => k.startsWith('screwbender.lessonDraft.'))
      .map((k) => JSON.parse(localStorage.getItem(k)))
      .sort((a, b) => b.savedAt - a.savedAt),
  );
/** The lesson in the editor now (its draft, which every edit writes). */
const current = async (p = page) => (await drafts(p))[0].lesson;

/**
 * Replaces the text of the field at `path` by `text`: typed key by key with `keys`, else given
 * as one text input (as a paste or an input method does).
 */
async function typeInto(path, text, { keys = false } = {}) {
  await page.locator(`#lesson-editor [data-path="${path}"]`).click();
  await page.keyboard.press('Control+A');
  await page.keyboard.press('Delete');
  if (keys) await page.keyboard.type(text);
  else await page.keyboard.insertText(text);
}

/** Opens the Lessons menu with its toolbar button. */
async function openMenu(p = page) {
  await p.locator('#t-lessons').click();
  await p.locator('#lessons-menu:not([hidden])').waitFor();
}

/** The lesson after each editor action, the first before any. */
const states = [];
/** Records the lesson as it is after an action. */
const done = async () => states.push(structuredClone(await current()));

let saved;
let link;

test('a two-step lesson is built with real events, previewed and solved as a student', async () => {
  await openMenu();
  await page.locator('#lesson-new').click();
  await page.locator('#lesson-editor:not([hidden])').waitFor();
  states.push(await current());
  assert.equal(states[0].steps.length, 1, 'a new lesson starts with one step taken from the page');
  assert.ok(states[0].steps[0].scene || states[0].steps[0].document, 'the step holds the page\'s motion');
  // The page's camera at that moment (opening the editor may frame the view anew afterwards).
  assert.deepEqual(Object.keys(states[0].steps[0].camera ?? {}), ['target', 'distance', 'yaw', 'pitch', 'ortho'], 'the step holds the page\'s camera');

  await typeInto('title', 'Editor check', { keys: true });
  await done();
  await typeInto('id', 'editor-check');
  await done();
  // A lesson with a problem gets no link (a student could not open it).
  await page.locator('#le-link').click();
  assert.match(await page.locator('#lesson-editor .le-say.bad').innerText(), /A lesson link needs a lesson without problems: 1 is listed/);
  // The problem list names the step and field; a click on one puts the focus in the field.
  await page.locator('#lesson-editor .le-problem', { hasText: 'Step 1 · text' }).click();
  assert.equal(await page.evaluate(() => document.activeElement?.dataset.path), 'steps[0].text');
  await typeInto('steps[0].title', 'A question');
  await done();
  await typeInto('steps[0].text', 'The screw turns by $\\theta$ and slides by $d$.');
  await done();
  // The live preview typesets the math as the student will see it.
  assert.equal(await page.locator('#lesson-editor .le-preview math').count(), 2);
  await page.locator('#lesson-editor .le-add-exercise').click();
  await done();
  await typeInto('steps[0].exercise.task', 'What is the pitch of a pure rotation?');
  await done();
  await page.locator('#lesson-editor .le-add-choice').click();
  await done();
  await page.locator('#lesson-editor .le-add-choice').click();
  await done();
  await typeInto('steps[0].exercise.choices[0].text', 'Infinite');
  await done();
  await typeInto('steps[0].exercise.choices[0].why', 'That is a pure translation: no turn at all.');
  await done();
  await typeInto('steps[0].exercise.choices[1].text', 'Zero');
  await done();
  await page.locator('#lesson-editor .le-choice input[type=radio]').nth(1).click();
  await done();

  // Step 2: pose 1 selected on the page by a click on its handle, then the step taken from
  // the page, its highlight picked by a click on that handle, a check from pose 1's origin.
  const h = await page.evaluate(() => window.screwbender.handleOnPage(1));
  await page.mouse.click(h.x, h.y);
  await waitFrames(page, 1);
  assert.equal(await page.evaluate(() => window.screwbender.selected()), 1);
  await page.locator('#le-add-step').click();
  await done();
  assert.equal((await current()).steps[1].select, 1, 'the new step keeps the selection');
  await typeInto('steps[1].title', 'Where pose 1 is');
  await done();
  await typeInto('steps[1].text', 'Leave pose 1 where it is.');
  await done();
  await page.locator('#le-pick').click();
  await page.mouse.click(h.x, h.y);
  await done();
  assert.deepEqual((await current()).steps[1].highlight, { pose: 1 }, 'the highlight points at the clicked pose');
  await page.locator('#lesson-editor .le-add-exercise').click();
  await done();
  await typeInto('steps[1].exercise.task', 'Keep pose 1 within 0.1 of its place.');
  await done();
  await page.locator('#le-check-what').selectOption('z');
  await page.locator('#le-check-index').fill('1');
  await page.locator('#le-check-tol').fill('0.1');
  await page.locator('#le-check-add').click();
  await done();
  const pose1 = await page.evaluate(() => Array.from(window.screwbender.poses().slice(7, 10)));
  const check = (await current()).steps[1].exercise.checks[0];
  assert.equal(check.kind, 'pose');
  assert.equal(check.pose, 1);
  assert.equal(check.tolerance, 0.1);
  assert.equal(check.coordinate, 'z', 'one coordinate of the pose, as the form chose');
  assert.ok(Math.abs(check.value - pose1[2]) < 1e-5, `value ${check.value} is pose 1's z ${pose1[2]}`);
  assert.equal(await page.locator('#lesson-editor').getAttribute('data-problems'), '0', await page.locator('.le-problems').innerText());
  await page.screenshot({ path: shotPath('lesson-editor/editor-1280.png') });

  // Preview as a student: a wrong answer shows its why, the right one solves step 1; step 2's
  // pose check passes with pose 1 where it is, and fails once it is moved past the tolerance.
  await page.locator('#le-preview').click();
  await page.locator('#lesson:not([hidden])').waitFor();
  assert.equal(await page.locator('#lesson-editor').isHidden(), true);
  await page.locator('#lesson .choices label').nth(0).click();
  await page.locator('#lesson button.check').click();
  assert.match(await page.locator('#lesson .feedback').innerText(), /pure translation/);
  await page.locator('#lesson .choices label').nth(1).click();
  await page.locator('#lesson button.check').click();
  await page.locator('#lesson .bar i.solved').first().waitFor();
  await page.locator('#lesson .next').click();
  await page.locator('#lesson[data-step="1"]').waitFor();
  await waitFrames(page, 2);
  // Pose 1 dragged up by its gizmo's z arrow, well past the tolerance: not solved; the page's
  // Undo puts it back: solved.
  const g = await page.evaluate(() => window.screwbender.gizmoOnPage('axis-z'));
  await mouseDrag(page, g, 0, -90);
  const moved = await page.evaluate(() => window.screwbender.poses()[9]);
  assert.ok(Math.abs(moved - pose1[2]) > 0.3, `pose 1's z moved from ${pose1[2]} to ${moved}`);
  await page.locator('#lesson button.check').click();
  await page.locator('#lesson .feedback.no').waitFor();
  await page.locator('#t-undo').click();
  await page.locator('#lesson button.check').click();
  await page.locator('#lesson .bar i.solved').nth(1).waitFor();
  await page.locator('#le-back').click();
  await page.locator('#lesson-editor:not([hidden])').waitFor();
  assert.equal(await page.locator('#lesson').isHidden(), true);
  // What the preview solved is not kept as a student's progress of the lesson.
  const progress = await page.evaluate(() => JSON.parse(localStorage.getItem('screwbender.lesson.editor-check') ?? 'null'));
  assert.deepEqual(progress?.solved ?? [], []);
});

test('every editor action is undone and redone, each step giving the lesson as it was', async () => {
  const n = states.length - 1;
  assert.ok(n >= 15, `${n} actions`);
  for (let k = n - 1; k >= 0; k--) {
    await page.locator('#le-undo').click();
    assert.deepEqual(await current(), states[k], `undo back to the lesson after action ${k}`);
  }
  assert.equal(await page.locator('#le-undo').isDisabled(), true);
  for (let k = 1; k <= n; k++) {
    await page.locator('#le-redo').click();
    assert.deepEqual(await current(), states[k], `redo of action ${k}`);
  }
  assert.equal(await page.locator('#le-redo').isDisabled(), true);
  // The keys too, with the focus in the editor.
  await page.locator('#le-undo').focus();
  await page.keyboard.press('Control+z');
  assert.deepEqual(await current(), states[n - 1]);
  await page.keyboard.press('Control+Shift+z');
  assert.deepEqual(await current(), states[n]);
});

test('the lesson is saved, and its link opens the same lesson in a fresh browser', async () => {
  const [download] = await Promise.all([page.waitForEvent('download'), page.locator('#le-save').click()]);
  assert.equal(download.suggestedFilename(), 'editor-check.json');
  const file = await download.path();
  saved = JSON.parse(fs.readFileSync(file, 'utf8'));
  assert.deepEqual(saved, states[states.length - 1], 'the file is the lesson built');
  await page.locator('#le-link').click();
  link = await page.locator('#le-link-out').inputValue();
  assert.match(link, /#lesson=[A-Za-z0-9_-]+$/);
  assert.ok(link.length < 8000);

  const fresh = await play.browser.newContext({ viewport: DESKTOP });
  try {
    const p2 = await fresh.newPage();
    await p2.goto(link);
    await p2.evaluate(() => window.screwbender.ready);
    const lesson = await p2.evaluate(async () => {
      const L = await window.screwbender.lessons;
      await L.ready;
      for (let k = 0; k < 100 && !L.lesson; k++) await new Promise((r) => setTimeout(r, 50));
      return L.lesson && { id: L.lesson.id, steps: L.lesson.steps.length, title: L.lesson.title };
    });
    assert.deepEqual(lesson, { id: 'editor-check', steps: 2, title: 'Editor check' });
    // The same lesson in the editor of the fresh browser, from the file and from the link.
    await openMenu(p2);
    const [chooser] = await Promise.all([p2.waitForEvent('filechooser'), p2.locator('#lesson-edit-file').click()]);
    await chooser.setFiles(file);
    await p2.locator('#lesson-editor:not([hidden])').waitFor();
    assert.deepEqual(await current(p2), saved, 'the file opens as the same lesson');
    await p2.locator('#le-open-link').fill(link);
    await p2.locator('#le-open-link').press('Enter');
    await p2.waitForFunction(() => document.querySelector('.le-say')?.textContent.includes('lesson link'));
    assert.deepEqual(await current(p2), saved, 'the link opens as the same lesson');
    assert.equal((await drafts(p2)).length, 2, 'each opened lesson is a draft of its own');
    // The link pasted into the address bar of the open page: only the hash changes (no load),
    // and the lesson opens.
    await p2.evaluate(async () => {
      (await window.screwbender.lessons).close();
      history.replaceState(null, '', location.pathname);
    });
    await p2.evaluate((h) => {
      location.hash = h;
    }, new URL(link).hash);
    await p2.waitForFunction(async () => (await window.screwbender.lessons).lesson?.id === 'editor-check');
  } finally {
    await fresh.close();
  }
});

test('a lesson link over the limit gets the message; drafts survive a reload, a second tab, a delete', async () => {
  // A long text that does not compress (a lesson with a long essay in it).
  let seed = 7;
  const words = Array.from({ length: 2400 }, () => {
    seed = (seed * 1103515245 + 12345) % 2147483648;
    return seed.toString(36).slice(0, 4);
  }).join(' ');
  await page.locator('#lesson-editor [data-path="steps[1].text"]').click();
  await page.keyboard.press('End');
  await page.keyboard.insertText(` ${words}`);
  await page.locator('#le-link').click();
  const say = page.locator('#lesson-editor .le-say.bad');
  assert.match(await say.innerText(), /link would be \d+ characters long; links longer than 8000 are cut off/);
  assert.equal(await page.locator('#le-link-out').isHidden(), true);
  await page.locator('#le-undo').click();
  assert.deepEqual(await current(), saved);

  // A reload keeps the draft, listed in the Lessons menu with its name and date.
  await page.reload();
  await page.evaluate(() => window.screwbender.lessons);
  await openMenu();
  const item = page.locator('#lesson-drafts .draft', { hasText: 'Editor check' });
  assert.equal(await item.count(), 1);
  assert.match(await item.innerText(), /draft of .*\d/);
  // A second tab sees it, and its deletion; Undo brings it back in both.
  const tab = await play.context.newPage();
  await tab.goto(play.url);
  await tab.evaluate(() => window.screwbender.lessons);
  await openMenu(tab);
  await tab.locator('#lesson-drafts .draft', { hasText: 'Editor check' }).waitFor();
  await tab.locator('#lesson-drafts li', { hasText: 'Editor check' }).locator('.le-del').click();
  await page.locator('#lesson-drafts .draft', { hasText: 'Editor check' }).waitFor({ state: 'detached' });
  await tab.locator('#draft-undo').click();
  await page.locator('#lesson-drafts .draft', { hasText: 'Editor check' }).waitFor();
  await tab.close();
  // Opened again from the menu, the draft is the lesson saved.
  await item.click();
  await page.locator('#lesson-editor:not([hidden])').waitFor();
  assert.deepEqual(await current(), saved);
  await page.setViewportSize({ width: 390, height: 844 });
  await waitFrames(page, 2);
  await page.screenshot({ path: shotPath('lesson-editor/editor-390.png') });
  await page.setViewportSize(DESKTOP);
  assert.deepEqual(problems, []);
  assert.deepEqual(await page.evaluate(() => window.__csp), [], 'no content-security-policy violation');
});
