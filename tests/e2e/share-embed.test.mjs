// e2e-backends: webgpu (the offline file on WebGPU and on its WebGL2 fallback)
// End-to-end: the Share & embed dialog (www/js/editor/share-dialog.js) and its four outputs, each
// taken as a user takes it (real clicks, keys and touches; the clipboard read back) and shown
// where it is meant to live:
//   * the link, opened in a fresh page, gives the same session;
//   * the <screw-bender> snippet pasted into a blank page of the local server draws the same
//     motion with the same options, camera and layers, and plays by its keys;
//   * the <iframe> snippet, made `sandbox="allow-scripts"` as an LMS does, runs embed.html in an
//     opaque origin without one storage call, fills the frame at any size, and takes mouse, keys
//     and touch;
//   * the downloaded .html file, opened from file:// with every request other than file: and
//     data: aborted, draws on this run's backend and, in the WebGPU run, on the WebGL2 fallback
//     too (navigator.gpu removed).
// Screenshots of the dialog, the embed page and the offline file at 1280×800 and 390×844 go to
// artifacts/e2e-<backend>/share/.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { BACKEND, EXPECTED_BACKEND, ROOT, countStorage, openPage, shotPath, startPlayground, waitFrames } from './lib.mjs';

const DESKTOP = { width: 1280, height: 800 };
const PHONE = { width: 390, height: 844 };

let play;
let page;
let problems;
/** The playground's session when the dialog was opened (what every output must reproduce). */
let session;

before(async () => {
  play = await startPlayground({ viewport: DESKTOP, acceptDownloads: true });
  await play.context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(play.url).origin });
  ({ page, problems } = await openPage(play.context, play.url, BACKEND));
  await page.evaluate(() => document.querySelector('#hint .close')?.click());
  // A motion unlike the defaults: scheme, levels, strobe, layers and camera all changed.
  await page.evaluate(() => {
    const { app } = window.screwbender;
    app.run('loadPreset', 'l_cycle_rotated');
    app.run('setScheme', 'fourpoint');
    app.run('setOption', 'levels', 3);
    app.run('setView', 'strobe', 24);
    app.run('setView', 'showGrid', false);
    app.run('setView', 'showPolyscrew', true);
    app.viewer.camera.yaw = 0.4;
    app.viewer.camera.pitch = 0.6;
    app.viewer.camera.distance *= 1.25;
    app.viewer.cameraMoved();
  });
  await waitFrames(page, 2);
});

after(async () => {
  await play?.close();
});

/** Opens the dialog as a keyboard user does: the File folder's button, then Enter. */
async function openDialog(p = page) {
  if (!(await p.locator('#share').isVisible().catch(() => false))) {
    const button = p.locator('#panel button', { hasText: 'Share & embed…' });
    // The File folder open (whatever state an earlier test left it in), as other tests do.
    await p.evaluate(() => window.screwbender.app.ui.gui.folders.find((f) => f._title === 'File').open());
    await button.waitFor({ state: 'visible' });
    await button.focus();
    await p.keyboard.press('Enter');
    await p.locator('#share').waitFor({ state: 'visible' });
  }
}

const clipboard = (p = page) => p.evaluate(() => navigator.clipboard.readText());

/** Non-background fraction of a screenshot of `locator` (the top-left pixel is the background). */
async function drawn(p, locator) {
  const png = await locator.screenshot();
  return p.evaluate(async (b64) => {
    const img = new Image();
    img.src = `data:image/png;base64,${b64}`;
    await img.decode();
    const c = new OffscreenCanvas(img.width, img.height);
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0);
    const d = g.getImageData(0, 0, c.width, c.height).data;
    let differ = 0;
    for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - d[0]) + Math.abs(d[i + 1] - d[1]) + Math.abs(d[i + 2] - d[2]) > 30) differ++;
    return differ / (d.length / 4);
  }, png.toString('base64'));
}

/**
 * What a figure (the element `sel` in page or frame `f`) shows: document, options, layers,
 * strobe, camera, backend, playing, frames drawn, and the page's storage calls.
 */
function figureState(f, sel = 'screw-bender') {
  return f.evaluate(async (s) => {
    const el = document.querySelector(s);
    // The element, or the handle of mount() (embed.html).
    const h = el instanceof customElements.get('screw-bender') ? el : window.screwbenderEmbed;
    await h.ready;
    const v = h.viewer;
    const model = v.model;
    return {
      document: model.motion.toDocument(),
      options: model.motion.options(),
      view: { strobe: model.view.strobe, showGrid: model.view.showGrid, showPolyscrew: model.view.showPolyscrew, showStrobe: model.view.showStrobe },
      camera: v.camera.toJSON(),
      backend: v.backend,
      playing: model.anim.playing,
      frames: v.frames,
      storage: window.__storage ?? null,
      message: el.shadowRoot.querySelector('.msg')?.textContent ?? '',
    };
  }, sel);
}

/** Checks that a figure's state reproduces the playground's session (camera: `exact` or by angles). */
function assertSame(state, exactCamera) {
  assert.equal(state.message, '', 'no message in the figure');
  assert.deepEqual(state.document, session.document, 'the same motion document');
  assert.deepEqual(state.options, session.options, 'the same subdivision options');
  assert.equal(state.view.strobe, 24);
  assert.equal(state.view.showGrid, false, 'the grid hidden, as in the playground');
  assert.equal(state.view.showPolyscrew, true, 'the polyscrew shown, as in the playground');
  if (exactCamera) assert.deepEqual(state.camera, session.camera);
  else {
    // The attribute holds degrees and scene units to 10 decimals.
    assert.ok(Math.abs(state.camera.yaw - session.camera.yaw) < 1e-3, `yaw ${state.camera.yaw} vs ${session.camera.yaw}`);
    assert.ok(Math.abs(state.camera.pitch - session.camera.pitch) < 1e-3, `pitch ${state.camera.pitch} vs ${session.camera.pitch}`);
    assert.ok(Math.abs(state.camera.distance - session.camera.distance) < 1e-3, `distance ${state.camera.distance} vs ${session.camera.distance}`);
  }
}

/** A new page of `context` and the list its page errors and console errors go to. */
async function watchedPage(context) {
  const p = await context.newPage();
  const pp = [];
  p.on('pageerror', (e) => pp.push(e.message));
  p.on('console', (m) => m.type() === 'error' && pp.push(m.text()));
  return { p, pp };
}

/** Serves `html` at `name` on the test server's origin (a "blank page served locally"). */
async function hostPage(context, name, html) {
  const url = `${play.url}${name}`;
  await context.route(url, (route) => route.fulfill({ status: 200, contentType: 'text/html; charset=utf-8', body: html }));
  return url;
}

test('the dialog: opened and left by keyboard, focus kept inside, screenshots at 1280×800', async () => {
  session = await page.evaluate(() => window.screwbender.session());
  await openDialog();
  assert.equal(await page.evaluate(() => document.activeElement.id), 'share-copy-link', 'the focus starts on Copy link');
  // Tab walks the dialog's controls and stays inside (a modal dialog).
  const seen = new Set();
  for (let k = 0; k < 14; k++) {
    await page.keyboard.press('Tab');
    const inside = await page.evaluate(() => !!document.activeElement.closest('#share'));
    assert.ok(inside, `Tab ${k + 1} stays in the dialog`);
    seen.add(await page.evaluate(() => document.activeElement.id));
  }
  for (const id of ['share-controls', 'share-autoplay', 'share-copy-link', 'share-copy-element', 'share-copy-iframe', 'share-download', 'share-close']) {
    assert.ok(seen.has(id), `${id} is reached by Tab`);
  }
  // The size of the offline file is stated on its button.
  await page.waitForFunction(() => /\(\d+(\.\d)? (MB|KB)\)/.test(document.getElementById('share-download').textContent));
  const box = await page.locator('#share').boundingBox();
  assert.ok(box.x >= 0 && box.y >= 0 && box.x + box.width <= DESKTOP.width && box.y + box.height <= DESKTOP.height, `on screen: ${JSON.stringify(box)}`);
  // axe (from npm, injected through the debugging protocol: the page's CSP refuses inline scripts).
  await page.evaluate(fs.readFileSync(path.join(ROOT, 'node_modules/axe-core/axe.min.js'), 'utf8'));
  for (const theme of ['light', 'dark']) {
    await page.evaluate((t) => (window.screwbender.app.updateView({ theme: t })), theme);
    const found = await page.evaluate(async () => {
      const r = await window.axe.run(document.getElementById('share'), { resultTypes: ['violations'] });
      return r.violations.filter((v) => v.impact === 'serious' || v.impact === 'critical').map((v) => `${v.impact} ${v.id}: ${v.nodes.slice(0, 4).map((n) => n.target.join(' ')).join(', ')}`);
    });
    assert.deepEqual(found, [], `axe, ${theme} theme`);
  }
  await page.evaluate(() => (window.screwbender.app.updateView({ theme: 'auto' })));
  await page.keyboard.press('Escape');
  assert.equal(await page.locator('#share').isVisible(), false, 'Esc closes the dialog');
  assert.equal(await page.evaluate(() => document.activeElement.textContent.trim()), 'Share & embed…', 'the focus goes back to its button');
});

test('Copy link: the clipboard holds a link that opens the same session', async () => {
  await openDialog();
  await page.click('#share-copy-link');
  await page.waitForFunction(() => /copied/.test(document.getElementById('share-status').textContent));
  const link = await clipboard();
  assert.equal(link, await page.inputValue('#share-link'));
  assert.match(link, /#s=[A-Za-z0-9_-]+$/);
  const fresh = await play.browser.newContext({ viewport: DESKTOP });
  try {
    const p = await fresh.newPage();
    await p.goto(link.replace(/^(.*?)(#s=)/, `$1${BACKEND === 'webgl2' ? '?backend=webgl2' : ''}$2`));
    await p.evaluate(() => window.screwbender.ready);
    const s = await p.evaluate(() => window.screwbender.session());
    assert.deepEqual(s.document, session.document);
    assert.deepEqual(s.options, session.options);
    assert.deepEqual(s.camera, session.camera);
  } finally {
    await fresh.close();
  }
});

test('where the clipboard is refused, the text is selected and the dialog says how to copy it', async () => {
  await openDialog();
  await page.evaluate(() => {
    window.__writeText = navigator.clipboard.writeText;
    navigator.clipboard.writeText = () => Promise.reject(new DOMException('denied', 'NotAllowedError'));
  });
  try {
    await page.click('#share-copy-element');
    await page.waitForFunction(() => /press Ctrl\+C/.test(document.getElementById('share-status').textContent));
    const sel = await page.evaluate(() => {
      const t = document.activeElement;
      return { id: t.id, start: t.selectionStart, end: t.selectionEnd, length: t.value.length };
    });
    assert.deepEqual(sel, { id: 'share-element', start: 0, end: sel.length, length: sel.length });
    assert.ok(sel.length > 100);
  } finally {
    await page.evaluate(() => (navigator.clipboard.writeText = window.__writeText));
  }
  await page.keyboard.press('Escape');
});

test('Copy code: the <screw-bender> snippet in a blank page draws the same figure and plays by its keys', async () => {
  await openDialog();
  // Full controls and autoplay: chosen in the dialog, written into the snippet.
  await page.selectOption('#share-controls', 'full');
  await page.check('#share-autoplay');
  await page.click('#share-copy-element');
  await page.waitForFunction(() => /copied/.test(document.getElementById('share-status').textContent));
  const snippet = await clipboard();
  assert.equal(snippet, await page.inputValue('#share-element'));
  assert.match(snippet, /<script type="application\/json">\{/, 'the motion inline');
  assert.match(snippet, / controls="full"/);
  assert.match(snippet, / autoplay[ >]/);
  await page.selectOption('#share-controls', 'minimal');
  await page.uncheck('#share-autoplay');
  await page.keyboard.press('Escape');
  const url = await hostPage(play.context, 'blank-snippet.html', `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Lecture</title></head><body><h1>Lecture 3</h1>\n${snippet}\n<p>After the figure.</p></body></html>`);
  const { p, pp } = await watchedPage(play.context);
  try {
    await p.goto(url);
    await p.waitForFunction(() => customElements.get('screw-bender'));
    const s = await figureState(p);
    assertSame(s, false);
    assert.equal(s.backend, EXPECTED_BACKEND);
    assert.equal(s.playing, true, 'autoplay');
    assert.equal(await p.evaluate(() => document.querySelector('screw-bender').shadowRoot.querySelector('.fig').dataset.controls), 'full');
    assert.ok((await drawn(p, p.locator('screw-bender'))) > 0.05, 'the figure is drawn');
    // Keys of the focused figure: a real click gives it the focus, Space pauses and plays.
    const canvas = p.locator('screw-bender canvas');
    const b = await canvas.boundingBox();
    await p.mouse.click(b.x + 8, b.y + 8);
    await p.keyboard.press(' ');
    assert.equal((await figureState(p)).playing, false, 'Space pauses');
    await p.keyboard.press(' ');
    assert.equal((await figureState(p)).playing, true, 'Space plays');
    assert.deepEqual(pp, []);
  } finally {
    await p.close();
  }
});

/** The iframe snippet from the dialog's clipboard button, made sandboxed as an LMS makes it. */
async function iframeSnippet() {
  await openDialog();
  await page.click('#share-copy-iframe');
  await page.waitForFunction(() => /copied/.test(document.getElementById('share-status').textContent));
  const snippet = await clipboard();
  assert.equal(snippet, await page.inputValue('#share-iframe'));
  await page.keyboard.press('Escape');
  assert.match(snippet, /^<iframe src="[^"]*\/embed\.html(\?[^"#]*)?#s=[A-Za-z0-9_-]+" title="[^"]+"/);
  return snippet.replace('<iframe ', '<iframe sandbox="allow-scripts" ');
}

async function embedFrame(p) {
  await p.waitForFunction(() => document.querySelector('iframe')?.contentWindow);
  let frame;
  for (let k = 0; k < 100 && !frame; k++) {
    frame = p.frames().find((f) => f.url().includes('/embed.html'));
    if (!frame) await p.waitForTimeout(100);
  }
  assert.ok(frame, 'the embed frame');
  await frame.waitForFunction(() => window.screwbenderEmbed);
  await frame.evaluate(() => window.screwbenderEmbed.ready);
  return frame;
}

test('Copy iframe: embed.html in a sandbox="allow-scripts" frame — opaque origin, no storage, fills any size, mouse and keys', async () => {
  await play.context.addInitScript(countStorage);
  const snippet = await iframeSnippet();
  const url = await hostPage(play.context, 'blank-iframe.html', `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>LMS page</title></head><body><h1>Week 3</h1>\n${snippet}\n</body></html>`);
  const { p, pp } = await watchedPage(play.context);
  try {
    await p.goto(url);
    const frame = await embedFrame(p);
    assert.equal(await frame.evaluate(() => self.origin), 'null', 'an opaque origin');
    const s = await figureState(frame, '#figure');
    assertSame(s, true);
    assert.equal(s.backend, EXPECTED_BACKEND);
    assert.deepEqual(s.storage, [], 'no storage call');
    assert.match(await frame.title(), /· ScrewBender figure$|^ScrewBender figure$/);
    // The figure fills the frame, at the snippet's size and at others.
    for (const [w, h] of [[800, 500], [420, 600], [300, 180]]) {
      await p.evaluate(([w, h]) => {
        const f = document.querySelector('iframe');
        f.style.width = `${w}px`;
        f.style.height = `${h}px`;
        f.style.aspectRatio = 'auto';
      }, [w, h]);
      await p.waitForTimeout(300);
      const fb = await p.locator('iframe').boundingBox();
      const hb = await frame.locator('#figure').boundingBox();
      assert.ok(Math.abs(hb.width - fb.width) <= 1 && Math.abs(hb.height - fb.height) <= 1, `${w}×${h}: figure ${hb.width}×${hb.height} in frame ${fb.width}×${fb.height}`);
    }
    await p.evaluate(() => (document.querySelector('iframe').style.cssText = 'border:0;width:800px;height:500px'));
    await p.waitForTimeout(300);
    assert.ok((await drawn(p, p.locator('iframe'))) > 0.05, 'the figure is drawn');
    // A real drag on the frame's canvas orbits, a click focuses it, Space plays.
    const cb = await frame.locator('#figure canvas').boundingBox();
    const yaw0 = (await figureState(frame, '#figure')).camera.yaw;
    await p.mouse.move(cb.x + cb.width * 0.2, cb.y + cb.height * 0.2);
    await p.mouse.down();
    for (let k = 1; k <= 8; k++) await p.mouse.move(cb.x + cb.width * 0.2 + 15 * k, cb.y + cb.height * 0.2);
    await p.mouse.up();
    const yaw1 = (await figureState(frame, '#figure')).camera.yaw;
    assert.ok(Math.abs(yaw1 - yaw0) > 0.05, `the drag orbits: yaw ${yaw0} → ${yaw1}`);
    await p.keyboard.press(' ');
    assert.equal((await figureState(frame, '#figure')).playing, true, 'Space plays');
    assert.deepEqual((await figureState(frame, '#figure')).storage, []);
    assert.deepEqual(pp, []);
  } finally {
    await p.close();
  }
});

test('embed.html on a phone: touch plays and orbits; screenshots at 390×844 and 1280×800; a bad option is named', async () => {
  const snippet = await iframeSnippet();
  const src = snippet.match(/src="([^"]+)"/)[1].replace(/&amp;/g, '&');
  for (const [size, touch] of [[PHONE, true], [DESKTOP, false]]) {
    const context = await play.browser.newContext({ viewport: size, hasTouch: touch, isMobile: touch });
    try {
      const p = await context.newPage();
      // The embed page alone (as a frame of the whole window would show it).
      await p.goto(`${src.replace('#', `${src.includes('?') ? '&' : '?'}controls=full#`)}`);
      await p.waitForFunction(() => window.screwbenderEmbed);
      await p.evaluate(() => window.screwbenderEmbed.ready);
      await p.waitForTimeout(500);
      const hb = await p.locator('#figure').boundingBox();
      assert.ok(Math.abs(hb.width - size.width) <= 1 && Math.abs(hb.height - size.height) <= 1, `fills the window: ${JSON.stringify(hb)}`);
      if (touch) {
        await p.locator('#figure .play').tap().catch(async () => {
          // The play button lives in the shadow tree: tap where it is.
          const b = await p.evaluate(() => {
            const r = document.querySelector('#figure').shadowRoot.querySelector('.play').getBoundingClientRect();
            return { x: r.x + r.width / 2, y: r.y + r.height / 2 };
          });
          await p.touchscreen.tap(b.x, b.y);
        });
        assert.equal(await p.evaluate(() => window.screwbenderEmbed.viewer.model.anim.playing), true, 'a tap on Play plays');
        const yaw0 = await p.evaluate(() => window.screwbenderEmbed.viewer.camera.yaw);
        const cdp = await context.newCDPSession(p);
        const at = (k) => [{ x: 80 + 14 * k, y: 160, id: 0 }];
        await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(0) });
        for (let k = 1; k <= 8; k++) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(k) });
        await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
        await cdp.detach();
        const yaw1 = await p.evaluate(() => window.screwbenderEmbed.viewer.camera.yaw);
        assert.ok(Math.abs(yaw1 - yaw0) > 0.05, `one finger orbits: yaw ${yaw0} → ${yaw1}`);
      }
      // A misspelt option is named below the figure; the figure still shows.
      await p.goto(`${play.url}embed.html?scene=circle4&levles=3&persist=x`);
      await p.evaluate(() => window.screwbenderEmbed.ready);
      const msg = await p.textContent('#embed-msg');
      assert.match(msg, /unknown option "levles"/);
      assert.match(msg, /persist is not available/);
      assert.equal(await p.evaluate(() => window.screwbenderEmbed.motion.poseCount), 4);
    } finally {
      await context.close();
    }
  }
});

for (const size of [PHONE, { width: 844, height: 390 }]) {
  test(`the dialog at ${size.width}×${size.height} by touch: on screen, targets ≥ 44 px, Copy by a tap`, async () => {
    const context = await play.browser.newContext({ viewport: size, hasTouch: true, isMobile: true });
    await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(play.url).origin });
    try {
      const { page: p } = await openPage(context, play.url, BACKEND);
      // The session of the desktop page, by its link.
      await p.goto(await page.inputValue('#share-link'));
      await p.evaluate(() => window.screwbender.ready);
      await p.evaluate(() => document.querySelector('#hint .close')?.click());
      // On a phone: the toolbar's View menu, then its Share & embed entry.
      await p.locator('#t-view').tap();
      await p.locator('#m-share').tap();
      await p.locator('#share').waitFor({ state: 'visible' });
      await p.waitForFunction(() => /MB|KB/.test(document.getElementById('share-download').textContent));
      const box = await p.locator('#share').boundingBox();
      assert.ok(box.x >= 0 && box.x + box.width <= size.width && box.height <= size.height, `on screen: ${JSON.stringify(box)}`);
      const small = await p.evaluate(() =>
        [...document.querySelectorAll('#share button, #share select')]
          .map((e) => ({ id: e.id || e.textContent, r: e.getBoundingClientRect() }))
          .filter(({ r }) => r.height < 44 - 0.5)
          .map(({ id, r }) => `${id} ${r.width.toFixed(0)}×${r.height.toFixed(0)}`),
      );
      assert.deepEqual(small, [], 'touch targets under 44 px');
      const copy = p.locator('#share-copy-iframe');
      await copy.scrollIntoViewIfNeeded();
      await copy.tap();
      await p.waitForFunction(() => /copied/.test(document.getElementById('share-status').textContent));
      assert.match(await p.evaluate(() => navigator.clipboard.readText()), /^<iframe /);
      await p.locator('#share-close').tap();
      assert.equal(await p.locator('#share').isVisible(), false);
      assert.equal(await p.evaluate(() => document.activeElement.id), 't-view', 'the focus goes back to the View button');
    } finally {
      await context.close();
    }
  });
}

/** Opens the offline file from file:// in a fresh context where only file: and data: load. */
async function openOffline(file, { noWebGpu = false } = {}) {
  const context = await play.browser.newContext({ viewport: DESKTOP });
  const network = [];
  await context.route('**/*', (route) => {
    const u = route.request().url();
    if (u.startsWith('file:') || u.startsWith('data:')) return route.continue();
    network.push(u);
    return route.abort();
  });
  await context.addInitScript(countStorage);
  if (noWebGpu) await context.addInitScript(() => Object.defineProperty(Navigator.prototype, 'gpu', { get: () => undefined }));
  const { p, pp } = await watchedPage(context);
  await p.goto(`file://${file}`);
  await p.waitForFunction(() => customElements.get('screw-bender'), null, { timeout: 60000 });
  return { context, p, network, pp };
}

test('Download .html: one file that works from file:// with the network blocked (both backends)', async () => {
  await openDialog();
  const stated = await page.textContent('#share-download');
  const got = page.waitForEvent('download', { timeout: 60000 });
  await page.click('#share-download');
  const d = await got;
  assert.match(d.suggestedFilename(), /^[a-z0-9-]+\.html$/);
  const file = shotPath(`share/${d.suggestedFilename()}`);
  await d.saveAs(file);
  const bytes = fs.statSync(file).size;
  await page.waitForFunction(() => /^Saved /.test(document.getElementById('share-status').textContent));
  const status = await page.textContent('#share-status');
  await page.keyboard.press('Escape');
  // The sizes the dialog states: the template's on the button, the file's after saving (to 0.1 MB).
  const mb = (s) => Number(s.match(/\((\d+(?:\.\d+)?) MB\)/)[1]);
  assert.ok(Math.abs(mb(stated) - bytes / 1e6) <= 0.15, `button says ${stated}, file ${bytes} bytes`);
  assert.ok(Math.abs(mb(status) - bytes / 1e6) <= 0.051, `status says ${status}, file ${bytes} bytes`);
  assert.ok(bytes < 4e6, `the file is ${bytes} bytes`);
  console.log(`offline file: ${bytes} bytes`);
  const runs = BACKEND === 'webgpu' ? [[false, 'WebGPU'], [true, 'WebGL2']] : [[false, 'WebGL2']];
  for (const [noWebGpu, backend] of runs) {
    const { context, p, network, pp } = await openOffline(file, { noWebGpu });
    try {
      const s = await figureState(p);
      assertSame(s, true);
      assert.equal(s.backend, backend, 'the backend');
      assert.deepEqual(s.storage, [], 'no storage call');
      const ink = await drawn(p, p.locator('screw-bender canvas'));
      assert.ok(ink > 0.02, `the figure is drawn: ${(ink * 100).toFixed(1)} % of the canvas`);
      const canvas = p.locator('screw-bender canvas');
      const b = await canvas.boundingBox();
      await p.mouse.click(b.x + 8, b.y + 8);
      await p.keyboard.press(' ');
      assert.equal((await figureState(p)).playing, true, 'Space plays');
      assert.equal(await p.title(), await p.evaluate(() => document.querySelector('screw-bender').textContent.trim()), 'the title is the caption');
      assert.ok((await p.title()).length > 0, 'a title');
      assert.deepEqual(network, [], 'nothing was requested from a network');
      assert.deepEqual(pp.filter((m) => !/No available adapters/.test(m)), []);
    } finally {
      await context.close();
    }
  }
  assert.deepEqual(problems, []);
});

test('Download .html of the bunny preset: the Stanford bunny travels inside the file', async () => {
  await page.evaluate(() => window.screwbender.app.run('loadPreset', 'bunny6'));
  await page.waitForFunction(() => window.screwbender.app.viewer.drawing.bunny);
  await openDialog();
  const got = page.waitForEvent('download', { timeout: 60000 });
  await page.click('#share-download');
  const d = await got;
  const file = shotPath(`share/${d.suggestedFilename()}`);
  await d.saveAs(file);
  await page.keyboard.press('Escape');
  const html = fs.readFileSync(file, 'utf8');
  assert.match(html, /<script type="text\/plain" id="screwbender-bunny">/);
  const { context, p, network, pp } = await openOffline(file);
  try {
    await figureState(p);
    // The mesh is read from the page (a data: URL), not from vendor/.
    await p.waitForFunction(() => document.querySelector('screw-bender').viewer.drawing.bunny?.length > 1000, null, { timeout: 30000 });
    assert.equal(await p.evaluate(() => document.querySelector('screw-bender').viewer.model.view.object), 'scene');
    assert.deepEqual(network, []);
    assert.deepEqual(pp.filter((m) => !/No available adapters/.test(m)), []);
  } finally {
    await context.close();
  }
  // Without the bunny, the file holds no mesh.
  await page.evaluate(() => window.screwbender.app.run('loadPreset', 'l_cycle_rotated'));
  const other = page.waitForEvent('download', { timeout: 60000 });
  await openDialog();
  await page.click('#share-download');
  const d2 = await other;
  await page.keyboard.press('Escape');
  assert.doesNotMatch(fs.readFileSync(await d2.path(), 'utf8'), /id="screwbender-bunny"/);
  await page.evaluate(() => window.screwbender.app.parts.session.undo());
  await page.evaluate(() => window.screwbender.app.parts.session.undo());
});

test('the dialog changes nothing in the playground', async () => {
  const now = await page.evaluate(() => window.screwbender.session());
  assert.deepEqual(now.document, session.document);
  assert.deepEqual(now.options, session.options);
});
