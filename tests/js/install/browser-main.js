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

/**
 * Mounts one figure through `screwbender/viewer` with `options`, waits until it is ready, and
 * reports `verify(fig, state)` (`{ ok, detail }`; `state` has the figure's `message`, or null
 * when none shows, and its `errors`), then removes the figure. A throw fails the check named
 * `name`.
 */
async function figureCheck(name, options, verify) {
  try {
    const { mount } = await import('screwbender/viewer');
    const el = document.createElement('div');
    el.style.width = '400px';
    el.style.height = '250px';
    document.body.append(el);
    const errors = [];
    el.addEventListener('error', (e) => errors.push(e.detail.message));
    const fig = mount(el, options);
    await fig.ready;
    const msg = el.shadowRoot.querySelector('.msg');
    const { ok, detail } = await verify(fig, { message: msg.hidden ? null : msg.textContent, errors });
    fig.destroy();
    el.remove();
    return { name, ok, detail };
  } catch (e) {
    return { name, ok: false, detail: String(e && e.stack ? e.stack : e) };
  }
}

/** What a check's detail says of the figure's message and error events. */
const said = ({ message, errors }) => `${message ?? 'no message'}; ${errors.length} error events`;
/** No message shown and no error event fired. */
const quiet = ({ message, errors }) => message === null && errors.length === 0;

/** One figure of a preset: it starts on a backend and shows no message. */
const viewerCheck = () =>
  figureCheck('viewer: mount a figure', { scene: 'l_cycle_rotated', levels: 3 }, (fig, state) => ({
    ok: fig.backend !== null && quiet(state) && fig.document?.poses?.length > 0,
    detail: `backend ${fig.backend}; ${said(state)}`,
  }));

/** A bunny6 figure: the packaged Stanford bunny (viewer/vendor/bunny.obj) must load and be drawn. */
const bunnyCheck = () =>
  figureCheck('viewer: the bunny6 preset shows the packaged bunny', { scene: 'bunny6', levels: 3 }, async (fig, state) => {
    // drawing.js fetches the mesh when the preset is shown; the promise settles once it is
    // uploaded (or, on failure, once the wedge stays in its place).
    const drawing = fig.viewer.drawing;
    await drawing.bunnyLoad;
    const triangles = drawing.bunnyTriangles ?? 0;
    const loaded = typeof drawing.bunny === 'string';
    return {
      ok: loaded && triangles > 1000 && quiet(state),
      detail: `bunny ${loaded ? 'loaded' : 'NOT loaded'}, ${triangles} triangles; ${said(state)}`,
    };
  });

/**
 * A figure whose `src` is a CSV file (motion.csv beside the page): the WebGPU renderer module has
 * no file import, so the figure reads the file through the package's files module.
 */
const csvCheck = () =>
  figureCheck('viewer: a CSV src is read through the files module',
    { src: new URL('motion.csv', document.baseURI).href, levels: 3 }, (fig, state) => {
      const poses = fig.document?.poses ?? [];
      return {
        ok: poses.length === 4 && Math.abs(poses[1].origin[0] - 2) < 1e-12 && quiet(state),
        detail: `${poses.length} poses; ${said(state)}`,
      };
    });
