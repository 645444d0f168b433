// Frame-time benchmark of the playground in headless Chromium (SwiftShader: software GPU, so the
// absolute numbers are only relative; the CPU-side numbers are real).
//
//   node benches/frame/bench.mjs [URL] [webgpu|webgl2]
//   (URL defaults to a server started here on a free port; build with BUILD_ONLY=1 scripts/serve.sh)
//
// 1. Drag: a 64-pose cycle at 6 levels (4,096 refined poses), 64 strobe instances, trajectories
//    on; pose 17 is moved by 120 synthetic drag steps through the page's own drag path
//    (App.dragMove: Motion.setPose, re-subdivision, instance/segment rebuild, GPU upload).
//    Reports the CPU time per drag frame (median, p90) and how it splits.
// 2. Strobe: 10,000 instances of the bar; reports the CPU time of draw() and the wall time
//    between frames (requestAnimationFrame), which includes SwiftShader's rasterization.
import { spawn } from 'node:child_process';
import net from 'node:net';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { launch, openPage, waitFrames } from '../../tests/e2e/lib.mjs';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
let [url, backend = 'webgpu'] = process.argv.slice(2);
let server;
if (!url) {
  const port = await new Promise((r) => {
    const s = net.createServer();
    s.listen(0, '127.0.0.1', () => {
      const p = s.address().port;
      s.close(() => r(p));
    });
  });
  server = spawn(process.execPath, [path.join(ROOT, 'scripts/serve.mjs'), path.join(ROOT, 'www')], {
    env: { ...process.env, PORT: String(port), SERVE_QUIET: '1' },
    stdio: ['ignore', 'pipe', 'inherit'],
  });
  await new Promise((r) => server.stdout.on('data', (d) => d.toString().includes('http://') && r()));
  url = `http://127.0.0.1:${port}/`;
}

const browser = await launch(backend, { softwarePage: false });
const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
const { page } = await openPage(context, url, backend);

const drag = await page.evaluate(async () => {
  const app = window.screwbender.app;
  // A 64-pose cycle: a wavy ring with twisting bars.
  const n = 64;
  const poses = [];
  for (let k = 0; k < n; k++) {
    const a = (2 * Math.PI * k) / n;
    const h = a / 2 + 0.3 * Math.sin(3 * a);
    poses.push({
      origin: [8 * Math.cos(a), 8 * Math.sin(a), Math.sin(4 * a)],
      rotation: [Math.cos(h), 0.3 * Math.sin(h), 0.2 * Math.sin(h), Math.sqrt(1 - 0.13) * Math.sin(h)],
    });
  }
  const norm = (q) => q.map((c) => c / Math.hypot(...q));
  poses.forEach((p) => (p.rotation = norm(p.rotation)));
  app.importJson(JSON.stringify({ closed: true, poses }));
  app.motion.setOptions({ scheme: 'fourpoint', levels: 6 });
  app.view.strobe = 64;
  app.changed();
  app.frameAll();
  app.select(17);
  app.draw();
  const p0 = app.motion.pose(17);
  const at = (k) => ({ origin: [p0.origin[0] + 0.02 * k, p0.origin[1], p0.origin[2] + 0.01 * k], rotation: p0.rotation });
  const med = (a) => [...a].sort((x, y) => x - y)[Math.floor(a.length / 2)];
  const p90 = (a) => [...a].sort((x, y) => x - y)[Math.floor(a.length * 0.9)];
  // (a) The page's drag path: local update through a DragSession.
  app.drag = { index: 17, moved: false, before: app.snapshot(), session: app.dragSession() };
  const local = [];
  for (let k = 0; k < 400; k++) {
    const t0 = performance.now();
    app.applyDragPose(17, at(k));
    local.push(performance.now() - t0);
  }
  app.endDrag();
  // (b) For comparison: a full re-subdivision and rebuild per step.
  const full = [];
  for (let k = 0; k < 60; k++) {
    const t0 = performance.now();
    app.motion.setPose(17, at(k));
    app.rebuildMotion();
    app.rebuildControls(false);
    full.push(performance.now() - t0);
  }
  return {
    refined: app.motion.refinedCount,
    strobe: app.view.strobe,
    localMinMs: Math.min(...local),
    localMedianMs: med(local),
    localP90Ms: p90(local),
    fullMinMs: Math.min(...full),
    fullMedianMs: med(full),
    fullP90Ms: p90(full),
  };
});

console.log(JSON.stringify({ drag }, null, 2));
// SwiftShader rasterizes 10,000 overlapping bars with 4× MSAA slowly (seconds per frame at
// 1280×800), so the strobe run uses a smaller canvas.
await page.setViewportSize({ width: 640, height: 400 });
const strobe = await page.evaluate(async () => {
  const app = window.screwbender.app;
  app.loadPreset('l_cycle_rotated');
  app.view.strobe = 10000;
  app.changed();
  app.draw();
  const draws = [];
  const gaps = [];
  let last = performance.now();
  for (let k = 0; k < 12; k++) {
    await new Promise((r) => requestAnimationFrame(r));
    const now = performance.now();
    gaps.push(now - last);
    last = now;
    const t0 = performance.now();
    app.draw();
    draws.push(performance.now() - t0);
  }
  const med = (a) => [...a].sort((x, y) => x - y)[Math.floor(a.length / 2)];
  return {
    instances: app.view.strobe,
    canvas: [app.canvas.width, app.canvas.height],
    drawCpuMs: med(draws),
    frameIntervalMedianMs: med(gaps.slice(2)),
    frameIntervalMaxMs: Math.max(...gaps.slice(2)),
  };
});

console.log(JSON.stringify({ backend: await page.evaluate(() => window.screwbender.backend()), strobe }, null, 2));
await browser.close();
server?.kill();
