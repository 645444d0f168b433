// Browser smoke entry shared by the Vite app and the plain ES-module page: loads the package,
// runs the checks and publishes the result for the Playwright driver (window.__smoke). Then the
// viewer entry: a <screw-bender> figure must start (WebGPU, or here usually the WebGL2 module)
// and show no message; a bunny6 figure must show the Stanford bunny packaged with the viewer; a
// figure whose `src` is a CSV file must read it through the package's files module.
import init, * as sb from 'screwbender';
import { runSmoke } from './smoke.mjs';

async function main() {
  try {
    await init();
    const result = runSmoke(sb);
    result.checks.push(await viewerCheck());
    result.checks.push(await bunnyCheck());
    result.checks.push(await csvCheck());
    result.ok = result.checks.every((c) => c.ok);
    window.__smoke = result;
  } catch (e) {
    window.__smoke = { ok: false, checks: [{ name: 'load', ok: false, detail: String(e && e.stack ? e.stack : e) }] };
  }
  document.body.textContent = JSON.stringify(window.__smoke, null, 2);
}
main();

/** Mounts one figure through `screwbender/viewer` and reports its backend and message. */
async function viewerCheck() {
  try {
    const { mount } = await import('screwbender/viewer');
    const el = document.createElement('div');
    el.style.width = '400px';
    el.style.height = '250px';
    document.body.append(el);
    const events = [];
    el.addEventListener('error', (e) => events.push(e.detail.message));
    const fig = mount(el, { scene: 'l_cycle_rotated', levels: 3 });
    await fig.ready;
    const msg = el.shadowRoot.querySelector('.msg');
    const ok = fig.backend !== null && msg.hidden && events.length === 0 && fig.document?.poses?.length > 0;
    const detail = `backend ${fig.backend}; ${msg.hidden ? 'no message' : msg.textContent}`;
    fig.destroy();
    el.remove();
    return { name: 'viewer: mount a figure', ok, detail };
  } catch (e) {
    return { name: 'viewer: mount a figure', ok: false, detail: String(e && e.stack ? e.stack : e) };
  }
}

/** A bunny6 figure: the packaged Stanford bunny (viewer/vendor/bunny.obj) must load and be drawn. */
async function bunnyCheck() {
  const name = 'viewer: the bunny6 preset shows the packaged bunny';
  try {
    const { mount } = await import('screwbender/viewer');
    const el = document.createElement('div');
    el.style.width = '400px';
    el.style.height = '250px';
    document.body.append(el);
    const events = [];
    el.addEventListener('error', (e) => events.push(e.detail.message));
    const fig = mount(el, { scene: 'bunny6', levels: 3 });
    await fig.ready;
    // drawing.js fetches the mesh when the preset is shown; the promise settles once it is
    // uploaded (or, on failure, once the wedge stays in its place).
    const drawing = fig.viewer.drawing;
    await drawing.bunnyLoad;
    const triangles = drawing.bunnyTriangles ?? 0;
    const msg = el.shadowRoot.querySelector('.msg');
    const ok = typeof drawing.bunny === 'string' && triangles > 1000 && msg.hidden && events.length === 0;
    const detail = `bunny ${typeof drawing.bunny === 'string' ? 'loaded' : 'NOT loaded'}, ${triangles} triangles; ` +
      `${msg.hidden ? 'no message' : msg.textContent}; ${events.length} error events`;
    fig.destroy();
    el.remove();
    return { name, ok, detail };
  } catch (e) {
    return { name, ok: false, detail: String(e && e.stack ? e.stack : e) };
  }
}

/**
 * A figure whose `src` is a CSV file (motion.csv beside the page): the WebGPU renderer module has
 * no file import, so the figure reads the file through the package's files module.
 */
async function csvCheck() {
  const name = 'viewer: a CSV src is read through the files module';
  try {
    const { mount } = await import('screwbender/viewer');
    const el = document.createElement('div');
    el.style.width = '400px';
    el.style.height = '250px';
    document.body.append(el);
    const events = [];
    el.addEventListener('error', (e) => events.push(e.detail.message));
    const fig = mount(el, { src: new URL('motion.csv', document.baseURI).href, levels: 3 });
    await fig.ready;
    const poses = fig.document?.poses ?? [];
    const msg = el.shadowRoot.querySelector('.msg');
    const ok = poses.length === 4 && Math.abs(poses[1].origin[0] - 2) < 1e-12 && msg.hidden && events.length === 0;
    const detail = `${poses.length} poses; ${msg.hidden ? 'no message' : msg.textContent}; ${events.length} error events`;
    fig.destroy();
    el.remove();
    return { name, ok, detail };
  } catch (e) {
    return { name, ok: false, detail: String(e && e.stack ? e.stack : e) };
  }
}
