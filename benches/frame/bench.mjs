// Frame-time benchmark of the playground in headless Chromium (SwiftShader: software GPU, so the
// absolute numbers are only relative; the CPU-side numbers are real).
//
//   node benches/frame/bench.mjs [URL] [webgpu|webgl2]
//   (URL defaults to www/ served here on a free port; build with BUILD_ONLY=1 scripts/serve.sh)
//
// The page is driven only through what it offers from outside: the App's named commands and
// setters (`app.run`, `app.select`, `app.parts.files.importJson`, `app.viewer.requestDraw`), the
// drag in progress (`app.drag`, whose drag session the page itself may drop), the
// inspection API `window.screwbender` (www/js/main.js) and pointer events on its canvas.
//
// 1. Drag: a 64-pose cycle at 6 levels (4,096 refined poses), 64 strobe instances, trajectories
//    on; pose 17 is dragged by its gizmo's x axis in 200 steps through the page's own drag path
//    (pointer events on the canvas: editor/input.js, the drag session's local update, partial GPU
//    upload). The events are dispatched synchronously in one task, so each step's time is the
//    CPU time of its handler, no frame drawn in between (and the page never thins the strobe,
//    which it does while a gesture's frames are slow). For comparison, 60 steps of the same drag
//    without a drag session (the page's path where none can be built: Motion.setPose and a full
//    re-subdivision and rebuild per step). Reports min, median, p90 of each.
// 2. Strobe: 10,000 instances of the bar; reports the CPU time of the viewer's draw() (the
//    page's stats().frameMs) and the wall time between drawn frames, which includes
//    SwiftShader's rasterization.
import { launch, openPage, serveWww, waitFrames } from '../../tests/e2e/lib.mjs';

const [given, backend = 'webgpu'] = process.argv.slice(2);
const server = given ? null : await serveWww();
const url = given || server.url;

const browser = await launch(backend, { softwarePage: false });
const context = await browser.newContext({ viewport: { width: 1280, height: 800 } });
// The page as people see it (the browser tests emulate reduced transparency).
const { page, problems } = await openPage(context, url, backend, { defaultLook: true });

// The drag's scene: a 64-pose cycle (a wavy ring with twisting bars), pose 17 selected.
const scene = await page.evaluate(() => {
  const sb = window.screwbender;
  const app = sb.app;
  const n = 64;
  const poses = [];
  for (let k = 0; k < n; k++) {
    const a = (2 * Math.PI * k) / n;
    const h = a / 2 + 0.3 * Math.sin(3 * a);
    const q = [Math.cos(h), 0.3 * Math.sin(h), 0.2 * Math.sin(h), Math.sqrt(1 - 0.13) * Math.sin(h)];
    const len = Math.hypot(...q);
    poses.push({ origin: [8 * Math.cos(a), 8 * Math.sin(a), Math.sin(4 * a)], rotation: q.map((c) => c / len) });
  }
  if (app.parts.files.importJson(JSON.stringify({ closed: true, poses }), 'bench.json') !== true) throw new Error(`import failed: ${sb.errors().join('; ')}`);
  app.run('setScheme', 'fourpoint');
  app.run('setOption', 'levels', 6);
  app.run('setView', 'strobe', 64);
  app.setMode('translate');
  app.select(17);
  return { refined: sb.refined().length / 7, strobe: app.view.strobe, trajectories: app.view.showTrajectories, polyscrew: app.view.showPolyscrew };
});
// The gizmo is picked against the camera of the last frame drawn.
await waitFrames(page, 2);

const drag = await page.evaluate(() => {
  const sb = window.screwbender;
  const app = sb.app;
  const canvas = app.viewer.canvas;
  // performance.now() is coarsened to 0.1 ms.
  const ms = (x) => +x.toFixed(1);
  const med = (a) => ms([...a].sort((x, y) => x - y)[Math.floor(a.length / 2)]);
  const p90 = (a) => ms([...a].sort((x, y) => x - y)[Math.floor(a.length * 0.9)]);
  const pointer = (type, { x, y }) =>
    canvas.dispatchEvent(new PointerEvent(type, { clientX: x, clientY: y, pointerId: 1, pointerType: 'mouse', isPrimary: true, button: type === 'pointermove' ? -1 : 0, buttons: type === 'pointerup' ? 0 : 1, bubbles: true, cancelable: true, composed: true }));
  /**
   * Drags pose 17 by its gizmo's x axis in `steps` moves of half a pixel along the axis as the
   * screen shows it (backwards with `sign` -1): press, moves, release. Without `session` the
   * press's drag session is dropped, as the page drops it where none can be built (then each
   * step is Motion.setPose and a full re-subdivision and rebuild). Returns each move's time.
   */
  function dragAxis(steps, sign, session) {
    const from = sb.gizmoOnPage('axis-x');
    const origin = sb.handleOnPage(17);
    if (!from || !origin) throw new Error('the gizmo of pose 17 is not on the page');
    const len = Math.hypot(from.x - origin.x, from.y - origin.y);
    const at = (k) => ({ x: from.x + (sign * 0.5 * k * (from.x - origin.x)) / len, y: from.y + (sign * 0.5 * k * (from.y - origin.y)) / len });
    const x0 = sb.poses()[17 * 7];
    pointer('pointerdown', from);
    if (!app.drag?.session) throw new Error(`the press on the gizmo started no drag with a drag session: ${sb.errors().join('; ')}`);
    if (!session) {
      app.drag.session.free();
      app.drag.session = null;
    }
    const times = [];
    for (let k = 1; k <= steps; k++) {
      const t0 = performance.now();
      pointer('pointermove', at(k));
      times.push(performance.now() - t0);
    }
    const moved = sb.poses()[17 * 7] - x0;
    pointer('pointerup', at(steps));
    if (app.drag) throw new Error('the drag did not end');
    if (!(Math.abs(moved) > 0.1)) throw new Error(`the drag did not move pose 17 (${moved})`);
    return times;
  }

  // (a) The page's drag path; (b) for comparison, the same drag without a drag session.
  const local = dragAxis(200, 1, true);
  const full = dragAxis(60, -1, false);
  return {
    localMinMs: ms(Math.min(...local)),
    localMedianMs: med(local),
    localP90Ms: p90(local),
    fullMinMs: ms(Math.min(...full)),
    fullMedianMs: med(full),
    fullP90Ms: p90(full),
  };
});

console.log(JSON.stringify({ scene, drag }, null, 2));
// SwiftShader rasterizes 10,000 overlapping bars with 4× MSAA slowly (seconds per frame at
// 1280×800), so the strobe run uses a smaller canvas.
await page.setViewportSize({ width: 640, height: 400 });
const strobe = await page.evaluate(async () => {
  const sb = window.screwbender;
  const app = sb.app;
  app.run('loadPreset', 'l_cycle_rotated');
  app.run('setView', 'strobe', 10000);
  const ms = (x) => +x.toFixed(1);
  const med = (a) => ms([...a].sort((x, y) => x - y)[Math.floor(a.length / 2)]);
  // Each frame is asked for; the viewer's own frame loop draws it (its requestAnimationFrame
  // callback runs before this one's), and stats().frameMs is that draw()'s CPU time.
  const draws = [];
  const drawnAt = [];
  let frames = sb.frames();
  let idle = 0;
  while (drawnAt.length < 12) {
    app.viewer.requestDraw();
    await new Promise((r) => requestAnimationFrame(r));
    if (sb.frames() === frames) {
      if (++idle > 50) throw new Error('the viewer draws no frames');
      continue;
    }
    idle = 0;
    frames = sb.frames();
    drawnAt.push(performance.now());
    draws.push(sb.stats().frameMs);
  }
  const gaps = drawnAt.slice(1).map((t, k) => t - drawnAt[k]);
  return {
    instances: app.view.strobe,
    canvas: [app.viewer.canvas.width, app.viewer.canvas.height],
    drawCpuMs: med(draws.slice(2)),
    frameIntervalMedianMs: med(gaps.slice(2)),
    frameIntervalMaxMs: ms(Math.max(...gaps.slice(2))),
  };
});

console.log(JSON.stringify({ backend: await page.evaluate(() => window.screwbender.backend()), strobe }, null, 2));
const errors = [...(await page.evaluate(() => window.screwbender.errors())), ...problems];
if (errors.length) console.log(`page errors:\n  ${errors.join('\n  ')}`);
await browser.close();
server?.stop();
