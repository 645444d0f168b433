// e2e-backends: webgpu (the LMS side is the same on either backend: once)
// Lesson packages for an LMS (www/js/lessons/package.js, lms.js, launch.js; docs/teaching/lms.md),
// with scorm-again as the LMS: a harness page gives the SCORM API (1.2 `API`, 2004
// `API_1484_11`) and opens the package's launch page in a frame, as an LMS does. For both
// versions, packages made by scripts/lesson-package.mjs: the manifest has the elements the
// SCORM schemas require and lists exactly the zip's files; a learner answers an exercise wrong,
// then right, with real clicks; the LMS reads back the status, score, interactions, time spent
// and suspend data; a second launch from the stored data resumes at the same step with the
// exercise solved and the randomised step's variant (the learner's), and Finish completes it with pass or fail against the mastery score; a
// three-lesson course starts at its menu; outside an LMS the package runs as a plain lesson; no
// request leaves the package's folder. The Lessons menu's dialog makes the same zip, byte for
// byte, as the script. One browser for all; screenshots go to artifacts/e2e-<backend>/scorm/.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFile } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { promisify } from 'node:util';
import { unzipSync } from 'fflate';
import { BACKEND, DESKTOP, ROOT, launch, serveDir, shotPath } from './lib.mjs';

const DIR = path.join(ROOT, `artifacts/e2e-${BACKEND}/lesson-package`);
const SCORM_AGAIN = path.join(ROOT, 'node_modules/scorm-again/dist');
const MB3 = 3 * 1024 * 1024;

// The harness: the LMS's page. launch(format, href, cmi) gives the API (with the learner's stored
// data `cmi`) and opens `href` in a frame; leave() navigates the frame away (the LMS closing
// the activity); cmi() is what the LMS holds.
const HARNESS = `<!doctype html>
<meta charset="utf-8"><title>LMS</title>
<script src="scorm12.min.js"></script><script src="scorm2004.min.js"></script>
<style>html,body{margin:0;height:100%;overflow:hidden} iframe{border:0;width:100%;height:100%;display:block}</style>
<body>
<script>
let api;
window.calls = [];
window.launch = (format, href, cmi) => {
  delete window.API;
  delete window.API_1484_11;
  api = format === 'scorm12' ? new Scorm12API({ logLevel: 5 }) : new Scorm2004API({ logLevel: 5 });
  api.loadFromJSON(cmi);
  for (const name of format === 'scorm12' ? ['LMSInitialize', 'LMSCommit', 'LMSFinish'] : ['Initialize', 'Commit', 'Terminate']) api.on(name, () => window.calls.push(name));
  window[format === 'scorm12' ? 'API' : 'API_1484_11'] = api;
  const f = document.createElement('iframe');
  f.src = href;
  document.body.replaceChildren(f);
};
window.leave = () => { document.querySelector('iframe').src = 'about:blank'; };
window.cmi = () => JSON.parse(JSON.stringify(api.renderCMIToJSONObject())).cmi;
</script>`;

let server;
let browser;
let context;
let page;
/** Every request of a package's page (frame or top level): its URL and the package it came from. */
const requests = [];

/** Runs scripts/lesson-package.mjs with `args`; resolves to the zip's entries. */
async function makePackage(out, args) {
  await promisify(execFile)(process.execPath, [path.join(ROOT, 'scripts/lesson-package.mjs'), ...args, '-o', out], { cwd: ROOT });
  return unzipSync(fs.readFileSync(out));
}

/** Unpacks `entries` into DIR/`name`/. */
function unpack(name, entries) {
  for (const [p, data] of Object.entries(entries)) {
    const file = path.join(DIR, name, p);
    fs.mkdirSync(path.dirname(file), { recursive: true });
    fs.writeFileSync(file, data);
  }
}

const PKGS = {};

/** Records the requests of package pages in `ctx` (see `requests`). */
function track(ctx) {
  ctx.on('request', (r) => {
    const frame = r.frame();
    const at = frame.url() === 'about:blank' ? frame.parentFrame()?.url() : frame.url();
    const pkg = Object.keys(PKGS).find((k) => (at ?? '').startsWith(`${server.url}${k}/`));
    if (pkg) requests.push({ url: r.url(), pkg });
  });
}

before(async () => {
  fs.rmSync(DIR, { recursive: true, force: true });
  fs.mkdirSync(DIR, { recursive: true });
  fs.writeFileSync(path.join(DIR, 'harness.html'), HARNESS);
  for (const f of ['scorm12.min.js', 'scorm2004.min.js']) fs.copyFileSync(path.join(SCORM_AGAIN, f), path.join(DIR, f));
  fs.symlinkSync(path.join(ROOT, 'www'), path.join(DIR, 'www'));
  const screw = 'www/lessons/01-screw.json';
  // The three packages and the browser start side by side.
  const started = launch(BACKEND);
  [PKGS.scorm12, PKGS.scorm2004, PKGS.course] = await Promise.all([
    makePackage(path.join(DIR, 'screw-12.zip'), ['--format', 'scorm12', '--mastery', '0.8', screw]),
    makePackage(path.join(DIR, 'screw-2004.zip'), ['--format', 'scorm2004', '--mastery', '0.2', screw]),
    makePackage(path.join(DIR, 'course.zip'), ['--format', 'scorm2004', screw, 'www/lessons/02-polyscrew.json', 'www/lessons/03-split-tweak.json']),
  ]);
  for (const [k, v] of Object.entries(PKGS)) unpack(k, v);
  server = await serveDir(DIR);
  browser = await started;
  context = await browser.newContext({ viewport: DESKTOP, acceptDownloads: true });
  track(context);
  page = await context.newPage();
  page.on('pageerror', (e) => assert.fail(`harness: ${e.message}`));
  await page.goto(`${server.url}harness.html`);
});

after(async () => {
  await browser?.close();
  server?.stop();
});

/** The launched package's frame, once its lesson player has opened `step` (or the menu). */
async function lessonFrame(ready) {
  await page.waitForFunction(() => document.querySelector('iframe')?.contentWindow?.screwbender);
  const frame = page.frames().find((f) => f.url().endsWith('/lesson.html'));
  await frame.evaluate(() => window.screwbender.lessons);
  await frame.waitForFunction(ready, null, { timeout: 30000 });
  return frame;
}

/** Launches package `pkg` in the harness with stored data `cmi`; the frame. */
async function launchIn(format, pkg, cmi, ready) {
  await page.evaluate(([f, href, c]) => window.launch(f, href, c), [format, `${pkg}/lesson.html`, cmi]);
  return lessonFrame(ready);
}

/** Leaves the launched package (the frame goes away); resolves when the API was terminated. */
async function leave(finishCall) {
  await page.evaluate(() => window.leave());
  await page.waitForFunction((c) => window.calls.includes(c), finishCall);
}

const stepShown = (n) => new Function(`return document.querySelector('#lesson')?.dataset.step === '${n}'`);

/** The manifest's required elements (SCORM CAM: imscp, adlcp) for `format`; its file list. */
async function checkManifest(format, entries) {
  const text = new TextDecoder().decode(entries['imsmanifest.xml']);
  const r = await page.evaluate(([t, f]) => {
    const doc = new DOMParser().parseFromString(t, 'application/xml');
    if (doc.querySelector('parsererror')) return { error: doc.querySelector('parsererror').textContent };
    const cp = f === 'scorm12' ? 'http://www.imsproject.org/xsd/imscp_rootv1p1p2' : 'http://www.imsglobal.org/xsd/imscp_v1p1';
    const adlcp = f === 'scorm12' ? 'http://www.adlnet.org/xsd/adlcp_rootv1p2' : 'http://www.adlnet.org/xsd/adlcp_v1p3';
    const one = (parent, name) => parent.getElementsByTagNameNS(cp, name)[0] ?? null;
    const m = doc.documentElement;
    const orgs = one(m, 'organizations');
    const org = one(orgs, 'organization');
    const item = one(org, 'item');
    const res = one(one(m, 'resources'), 'resource');
    return {
      root: m.namespaceURI === cp && m.localName === 'manifest',
      identifier: m.getAttribute('identifier'),
      version: m.getAttribute('version'),
      schema: one(one(m, 'metadata'), 'schema')?.textContent,
      schemaversion: one(one(m, 'metadata'), 'schemaversion')?.textContent,
      defaultOrg: orgs.getAttribute('default') === org.getAttribute('identifier'),
      orgTitle: one(org, 'title')?.textContent,
      itemRef: item.getAttribute('identifierref') === res.getAttribute('identifier'),
      scormType: res.getAttributeNS(adlcp, f === 'scorm12' ? 'scormtype' : 'scormType'),
      type: res.getAttribute('type'),
      href: res.getAttribute('href'),
      mastery12: item.getElementsByTagNameNS(adlcp, 'masteryscore')[0]?.textContent ?? null,
      mastery2004: item.getElementsByTagNameNS('http://www.imsglobal.org/xsd/imsss', 'minNormalizedMeasure')[0]?.textContent ?? null,
      description: m.getElementsByTagNameNS('*', 'description')[0]?.textContent.trim(),
      files: [...res.getElementsByTagNameNS(cp, 'file')].map((e) => e.getAttribute('href')),
    };
  }, [text, format]);
  assert.equal(r.error, undefined, `imsmanifest.xml does not parse: ${r.error}`);
  assert.ok(r.root, 'the root is an IMS CP manifest');
  assert.match(r.identifier, /^[A-Za-z_][\w.-]*$/);
  assert.match(r.version, /^[0-9a-f]{8}$/);
  assert.equal(r.schema, 'ADL SCORM');
  assert.equal(r.schemaversion, format === 'scorm12' ? '1.2' : '2004 4th Edition');
  assert.ok(r.defaultOrg && r.itemRef, 'organizations@default and item@identifierref name their elements');
  assert.ok(r.orgTitle && r.description, 'title and description');
  assert.equal(r.scormType, 'sco');
  assert.equal(r.type, 'webcontent');
  assert.equal(r.href, 'lesson.html');
  const listed = [...r.files].sort();
  const inZip = Object.keys(entries).filter((p) => p !== 'imsmanifest.xml').sort();
  assert.deepEqual(listed, inZip, 'the manifest lists exactly the zip\'s files');
  assert.ok(inZip.includes('lesson.html') && inZip.includes('pkg-webgpu/screwbender_bg.wasm') && inZip.includes('vendor/katex.min.mjs'));
  assert.ok(!inZip.some((p) => /three|mediabunny|reveal|bunny\.obj|index\.html$/.test(p)), 'nothing the lesson does not use');
  return r;
}

for (const format of ['scorm12', 'scorm2004']) {
  const v12 = format === 'scorm12';
  test(`${format}: manifest, a wrong then a right answer, resume, finish`, async () => {
    const entries = PKGS[format];
    const size = fs.statSync(path.join(DIR, v12 ? 'screw-12.zip' : 'screw-2004.zip')).size;
    assert.ok(size <= MB3, `one lesson's package is ${size} bytes, over 3 MB`);
    const man = await checkManifest(format, entries);
    // The LMS's mastery comes from the manifest, as an LMS reads it.
    const mastery = v12 ? Number(man.mastery12) / 100 : Number(man.mastery2004);
    assert.equal(mastery, v12 ? 0.8 : 0.2);
    const learner = v12 ? { core: { student_id: 'learner-7', student_name: 'Doe, Jo' }, student_data: { mastery_score: man.mastery12 } } : { learner_id: 'learner-7', learner_name: 'Jo Doe', scaled_passing_score: man.mastery2004 };

    // First launch: the lesson starts at step 1; the learner goes to the multiple choice (step 6).
    let frame = await launchIn(format, format, learner, stepShown(0));
    // The randomised step's variant comes from the learner's id (lms.js variantSeed).
    const variant = await frame.evaluate(() => window.screwbender.lessons.then((L) => L.variant));
    assert.equal(variant.seed, await frame.evaluate(() => window.screwbender.lms.seed('screw')));
    for (let k = 1; k <= 5; k++) {
      await frame.click('#lesson button.next');
      await frame.waitForFunction(stepShown(k));
    }
    await frame.click('#lesson .choices label:nth-child(1)');
    await frame.click('#lesson button.check');
    await frame.waitForSelector('#lesson .feedback.no');
    let cmi = await page.evaluate(() => window.cmi());
    const ia = (c) => c.interactions[0];
    assert.equal(ia(cmi)?.result, v12 ? 'wrong' : 'incorrect');
    await frame.click('#lesson .choices label:nth-child(2)');
    await frame.click('#lesson button.check');
    await frame.waitForSelector('#lesson .feedback.ok');
    cmi = await page.evaluate(() => window.cmi());
    const commits = await page.evaluate(() => window.calls.filter((c) => /Commit/.test(c)).length);
    assert.ok(commits >= 2, `a commit after each checked exercise (${commits})`);
    const rec = ia(cmi);
    assert.equal(rec.id, 'screw_step6');
    assert.equal(rec.type, 'choice');
    assert.equal(rec.result, 'correct');
    assert.equal(v12 ? rec.student_response : rec.learner_response, v12 ? '1' : 'answer_1');
    if (v12) assert.match(rec.time, /^\d\d:\d\d:\d\d$/);
    else assert.match(rec.timestamp, /^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d/);
    const score = v12 ? cmi.core.score : cmi.score;
    assert.deepEqual([score.raw, score.min, score.max].map(Number), [25, 0, 100], 'one of four exercises solved, in %');
    if (v12) assert.equal(cmi.core.lesson_status, 'incomplete');
    else {
      assert.equal(cmi.completion_status, 'incomplete');
      assert.ok(Math.abs(Number(cmi.score.scaled) - 1 / 4) < 1e-3, `scaled ${cmi.score.scaled}`);
      assert.equal(cmi.success_status, 'unknown');
    }
    const suspend = cmi.suspend_data;
    assert.ok(suspend.length > 0 && suspend.length <= 4096, `suspend data: ${suspend}`);
    await page.screenshot({ path: shotPath(`scorm/harness-${format}.png`) });
    if (v12) {
      await page.setViewportSize({ width: 390, height: 844 });
      await page.screenshot({ path: shotPath('scorm/harness-phone.png') });
      await page.setViewportSize(DESKTOP);
    }
    await leave(v12 ? 'LMSFinish' : 'Terminate');
    cmi = await page.evaluate(() => window.cmi());
    assert.equal(v12 ? cmi.core.exit : cmi.exit, 'suspend');
    assert.match(v12 ? cmi.core.session_time : cmi.session_time, v12 ? /^\d{2,4}:\d\d:\d\d(\.\d{1,2})?$/ : /^PT/);

    // Second launch from what the LMS stored: the same step, the exercise solved.
    const stored = v12
      ? { ...learner, suspend_data: cmi.suspend_data, core: { ...learner.core, entry: 'resume', lesson_status: cmi.core.lesson_status } }
      : { ...learner, suspend_data: cmi.suspend_data, entry: 'resume', completion_status: cmi.completion_status };
    frame = await launchIn(format, format, stored, stepShown(5));
    // The same variant as at the first launch: its seed is not stored, it is the learner's.
    assert.deepEqual(await frame.evaluate(() => window.screwbender.lessons.then((L) => L.variant)), variant);
    assert.match(await frame.textContent('#lesson .task .label'), /solved/);
    assert.equal(await frame.evaluate(() => window.screwbender.lms.learnerId), 'learner-7');
    // Finish: the summary; completed, with pass or fail against the mastery score.
    await frame.click('#lesson button.next');
    await frame.waitForFunction(() => document.querySelector('#lesson')?.dataset.step === 'summary');
    cmi = await page.evaluate(() => window.cmi());
    if (v12) assert.equal(cmi.core.lesson_status, 'failed', '1 of 4 is under the mastery score 80');
    else {
      assert.equal(cmi.completion_status, 'completed');
      assert.equal(cmi.success_status, 'passed', '1 of 4 is over the mastery score 0.2');
    }
    assert.deepEqual(await frame.evaluate(() => window.screwbender.lms.errors()), []);
    await leave(v12 ? 'LMSFinish' : 'Terminate');
  });
}

test('a three-lesson course starts at its menu and scores over all lessons', async () => {
  await checkManifest('scorm2004', PKGS.course);
  const frame = await launchIn('scorm2004', 'course', { learner_id: 'learner-8' }, () => !document.querySelector('#lessons-menu')?.hidden);
  const items = await frame.$$eval('#lessons-menu .lesson-item:not(.tour) b', (bs) => bs.map((b) => b.textContent));
  assert.equal(items.length, 3);
  assert.equal(await frame.isHidden('#lessons-menu button.lms'), true, 'no package of a package');
  await frame.click('#lessons-menu .lesson-item:nth-child(3)');
  await frame.waitForFunction(() => !document.querySelector('#lesson').hidden && document.querySelector('#lesson').dataset.step === '0');
  assert.equal(await frame.evaluate(() => window.screwbender.lessons.then((L) => L.lesson.id)), 'split-tweak');
  // Its multiple choice (step 5), answered right with real clicks.
  for (let k = 1; k <= 4; k++) {
    await frame.click('#lesson button.next');
    await frame.waitForFunction(stepShown(k));
  }
  await frame.click('#lesson .choices label:nth-child(2)');
  await frame.click('#lesson button.check');
  await frame.waitForSelector('#lesson .feedback.ok');
  const cmi = await page.evaluate(() => window.cmi());
  assert.deepEqual([cmi.score.raw, cmi.score.max].map(Number), [12.5, 100], 'one of the eight exercises of all three lessons, in %');
  assert.equal(cmi.interactions[0].id, 'split_tweak_step5');
  assert.equal(cmi.suspend_data.split(';')[1], '2', `the lesson open is the third: ${cmi.suspend_data}`);
  await leave('Terminate');
});

test('outside an LMS the package runs as a plain lesson and says so once', async () => {
  // A browser of its own: no progress or playground state from the launches above.
  const own = await browser.newContext({ viewport: DESKTOP });
  track(own);
  const solo = await own.newPage();
  await solo.goto(`${server.url}scorm12/lesson.html`);
  await solo.evaluate(() => window.screwbender.lessons);
  await solo.waitForFunction(() => document.querySelector('#lesson')?.dataset.step === '0');
  const errors = await solo.evaluate(() => window.screwbender.errors());
  assert.equal(errors.filter((e) => /Not launched from an LMS/.test(e)).length, 1, errors.join(' | '));
  assert.equal(errors.length, 1, errors.join(' | '));
  assert.equal(await solo.evaluate(() => window.screwbender.lms.connected), false);
  await own.close();
});

test('no request of a package leaves its folder', () => {
  assert.ok(requests.length > 20, `${requests.length} requests seen`);
  const outside = requests.filter((r) => !r.url.startsWith(`${server.url}${r.pkg}/`) && !r.url.startsWith('data:') && !r.url.startsWith('blob:'));
  assert.deepEqual(outside, []);
});

test('the Lessons menu makes the same zip as the script, and shows its size', async () => {
  const p = await context.newPage();
  await p.goto(`${server.url}www/index.html`);
  await p.evaluate(() => window.screwbender.lessons);
  await p.click('#t-lessons');
  await p.screenshot({ path: shotPath('scorm/menu.png') });
  await p.click('#lessons-menu button.lms');
  await p.waitForFunction(() => /Size: [\d.]+ MB/.test(document.querySelector('#lms-package .size')?.textContent ?? ''));
  const sizeText = await p.textContent('#lms-package .size');
  const zip = fs.readFileSync(path.join(DIR, 'screw-12.zip'));
  assert.ok(sizeText.includes(`${(zip.length / 1e6).toFixed(2)} MB`), `${sizeText} vs ${zip.length} bytes`);
  await p.screenshot({ path: shotPath('scorm/dialog.png') });
  const [download] = await Promise.all([p.waitForEvent('download'), p.click('#lms-package button.primary')]);
  const got = fs.readFileSync(await download.path());
  assert.ok(Buffer.compare(got, zip) === 0, 'the page\'s zip is the script\'s, byte for byte');
  await p.setViewportSize({ width: 390, height: 844 });
  await p.screenshot({ path: shotPath('scorm/dialog-phone.png') });
  await p.close();
});
