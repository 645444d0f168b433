// Drives a running JupyterLab (started by test_jupyterlab.py with --LabApp.expose_app_in_browser
// so that window.jupyterapp exists) in one headless Chromium with the WebGPU flags:
//   node jupyterlab.mjs URL SHOT_DIR  -> one JSON line of what it saw
// Opens the notebook, runs its cells (three figures: WebGPU, WebGL2 by the figure's `backend`
// option, and a third sharing the first one's viewer), screenshots them (and the page at a
// desktop and a phone width), then runs code in the notebook's kernel: Python -> figure (set
// fig.poses: the picture changes) and figure -> Python (a real mouse drag of control pose 1,
// then the kernel reads fig.poses).
import fs from 'node:fs';
import path from 'node:path';
import { elementStats, launch } from './pixels.mjs';

const [url, shots] = process.argv.slice(2);
fs.mkdirSync(shots, { recursive: true });
const browser = await launch('webgpu');
const out = {};
try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 1000 } });
  const problems = [];
  page.on('pageerror', (e) => problems.push(e.message));
  const consoleErrors = [];
  page.on('console', (m) => {
    if (m.type() === 'error') consoleErrors.push(m.text().slice(0, 300));
  });
  out.console = consoleErrors;
  await page.goto(url);
  await page.waitForFunction(() => window.jupyterapp?.shell?.currentWidget?.sessionContext?.session?.kernel, null, { timeout: 180000 });
  await page.waitForFunction(() => window.jupyterapp.shell.currentWidget.sessionContext.session.kernel.status === 'idle', null, { timeout: 180000 });
  // The cells one at a time, each figure ready before the next starts.
  const cells = await page.evaluate(() => window.jupyterapp.shell.currentWidget.content.widgets.length);
  for (let cell = 0; cell < cells; cell++) {
    await page.evaluate(async (i) => {
      const panel = window.jupyterapp.shell.currentWidget;
      panel.content.activeCellIndex = i;
      await window.jupyterapp.commands.execute('notebook:run-cell');
    }, cell);
    await page.waitForFunction((n) => {
      const figs = [...document.querySelectorAll('.screwbender-figure')];
      return figs.length === n && figs.every((f) => f.dataset.ready === 'true');
    }, cell + 1, { timeout: 240000 });
  }
  await page.waitForTimeout(2000);

  /** Runs `code` in the notebook's kernel; resolves with its standard output. */
  const run = (code) => page.evaluate(async (c) => {
    const kernel = window.jupyterapp.shell.currentWidget.sessionContext.session.kernel;
    let text = '';
    const future = kernel.requestExecute({ code: c });
    future.onIOPub = (msg) => {
      if (msg.header.msg_type === 'stream') text += msg.content.text;
      if (msg.header.msg_type === 'error') text += `ERROR ${msg.content.ename}: ${msg.content.evalue}`;
    };
    await future.done;
    return text;
  }, code);
  const figures = page.locator('.screwbender-figure');
  const shot = async (i, name) => {
    await figures.nth(i).scrollIntoViewIfNeeded();
    const stats = await elementStats(page, figures.nth(i), path.join(shots, name));
    return { png: stats.png, stats };
  };
  out.backends = await page.evaluate(() => [...document.querySelectorAll('.screwbender-figure')].map((f) => f.dataset.backend));
  const third = await shot(2, 'jupyterlab-third.png');
  const gl = await shot(1, 'jupyterlab-webgl2.png');
  const first = await shot(0, 'jupyterlab-webgpu.png');
  out.nonBackground = [first.stats.nonBackground, gl.stats.nonBackground, third.stats.nonBackground];
  // The page as a reader sees it: desktop, then a phone-sized width.
  await page.screenshot({ path: path.join(shots, 'jupyterlab-desktop.png') });
  await page.setViewportSize({ width: 420, height: 900 });
  await page.evaluate(() => window.jupyterapp.shell.leftCollapsed || window.jupyterapp.commands.execute('application:toggle-left-area'));
  await page.waitForTimeout(1500);
  await figures.nth(0).scrollIntoViewIfNeeded();
  await page.screenshot({ path: path.join(shots, 'jupyterlab-phone.png') });
  await page.setViewportSize({ width: 1280, height: 1000 });
  await page.waitForTimeout(1500);

  // Python -> figure.
  const version = await page.evaluate(() => Number(document.querySelector('.screwbender-figure').dataset.posesVersion || 0));
  out.setPoses = await run('Q = fig.poses.copy(); Q[2, :3] += [0, 0, 2.5]; fig.poses = Q; print("set")');
  try {
    await page.waitForFunction((v) => Number(document.querySelector('.screwbender-figure').dataset.posesVersion || 0) > v, version, { timeout: 60000 });
  } catch (e) {
    console.error(JSON.stringify({ ...out, problems }));
    throw e;
  }
  await page.waitForTimeout(1000);
  const moved = await shot(0, 'jupyterlab-python-to-figure.png');
  out.pictureChanged = await page.evaluate(async ([a, b]) => {
    const load = async (b64) => {
      const img = new Image();
      img.src = `data:image/png;base64,${b64}`;
      await img.decode();
      const c = document.createElement('canvas');
      c.width = img.width;
      c.height = img.height;
      const g = c.getContext('2d');
      g.drawImage(img, 0, 0);
      return g.getImageData(0, 0, c.width, c.height).data;
    };
    const [x, y] = [await load(a), await load(b)];
    let differ = 0;
    for (let i = 0; i < Math.min(x.length, y.length); i += 4) if (Math.abs(x[i] - y[i]) + Math.abs(x[i + 1] - y[i + 1]) + Math.abs(x[i + 2] - y[i + 2]) > 30) differ++;
    return differ / (x.length / 4);
  }, [first.png.toString('base64'), moved.png.toString('base64')]);
  out.figurePose2 = await page.evaluate(() => Array.from(document.querySelector('.screwbender-figure').figure.motion.poses()).slice(14, 21));

  // Figure -> Python: a real drag of control pose 1's handle.
  out.before = JSON.parse(await run('import json; print(json.dumps(fig.poses[1].tolist()))'));
  await figures.nth(0).scrollIntoViewIfNeeded();
  const h = await page.evaluate(() => document.querySelector('.screwbender-figure').figure.viewer.screenOfPose(1));
  await page.mouse.move(h.x, h.y);
  await page.mouse.down();
  for (let k = 1; k <= 10; k++) await page.mouse.move(h.x + 4 * k, h.y - 3 * k);
  await page.mouse.up();
  let after = out.before;
  for (let tries = 0; tries < 20 && JSON.stringify(after) === JSON.stringify(out.before); tries++) {
    await page.waitForTimeout(250);
    after = JSON.parse(await run('print(json.dumps(fig.poses[1].tolist()))'));
  }
  out.after = after;
  out.observed = (await run('print(len(moves))')).trim();
  await shot(0, 'jupyterlab-after-drag.png');
  out.problems = problems;
  delete out.console;
  console.log(JSON.stringify(out));
} finally {
  await browser.close();
}
