// The front end of `screwbender.Figure` (an anywidget): the project's own figure — the
// <screw-bender> element's mount() on the playground's viewer (www/js/element, www/js/view) —
// bound to the widget's model. Bundled with the renderer's WebAssembly module by build.mjs into
// screwbender/static/figure.js; nothing is fetched from the network.
//
// Model → figure: `poses` (rows x y z qw qx qy qz) and `closed` replace the motion's poses in
// place (the camera stays); the options (scheme, s, levels, rules, show, strobe, camera,
// editable, autoplay, controls, theme, backend) go to the figure's options. Figure → model: a drag that moved a pose
// sets `poses` and saves it, which updates `fig.poses` in the kernel and fires its observers.
// The options are those the element's declarations mark for the notebook (the same list as the
// traitlets of screwbender/_figure_options.py, both made from www/js/element/features.js).
import './assets.js';
import { WIDGET_OPTIONS as OPTIONS } from '../../www/js/element/features.js';
import { mount } from '../../www/js/element/screw-bender.js';

// Every figure of a page uses the first bundle's mount(): one wasm instance and one WebGPU
// device for all of them, however many copies of this module the page evaluated (anywidget
// imports a module per widget model).
const SHARED = Symbol.for('screwbender.figure.mount');
const shared = (globalThis[SHARED] ??= { mount });

/** The figure's options of the model's values (rules "split-then-tweak" is "split" there). */
function figureOptions(model) {
  const o = {};
  for (const k of OPTIONS) {
    const v = model.get(k);
    if (v === null || v === undefined || v === '') continue;
    if (k === 'rules') o.rules = v === 'split-then-tweak' ? 'split' : v;
    else o[k] = v;
  }
  if (o.s !== undefined) o.scheme = 'j';
  return o;
}

/** The motion document of the model's poses. */
function documentOf(model) {
  const poses = model.get('poses').map((p) => ({ origin: p.slice(0, 3), rotation: p.slice(3, 7) }));
  const doc = { closed: !!model.get('closed'), poses };
  const name = model.get('name');
  if (name) doc.name = name;
  return doc;
}

/** Rows of 7 numbers from the figure's flat pose array. */
function rowsOf(flat) {
  const rows = [];
  for (let i = 0; i + 7 <= flat.length; i += 7) rows.push(Array.from(flat.subarray(i, i + 7)));
  return rows;
}

function render({ model, el }) {
  const host = document.createElement('div');
  host.className = 'screwbender-figure';
  host.style.display = 'block';
  host.style.width = '100%';
  const height = model.get('height');
  if (height) host.style.height = `${height}px`;
  el.append(host);
  const handle = shared.mount(host, { ...figureOptions(model), document: documentOf(model) });
  // The figure's handle (viewer, motion, play/pause) for scripts of the page and for tests.
  host.figure = handle;
  // The poses the figure itself last sent: their echo from the kernel is not applied again.
  let sent = null;

  const onPoses = () => {
    const rows = model.get('poses');
    if (sent && JSON.stringify(rows) === sent) return;
    const motion = handle.motion;
    const doc = documentOf(model);
    try {
      if (motion && handle.viewer && motion.poseCount === rows.length && motion.closed === doc.closed) {
        // In place: the camera, the selection and the playhead stay.
        motion.loadDocument(doc);
        handle.viewer.rebuild();
      } else {
        handle.document = doc;
      }
    } catch {
      // The figure was not ready for an in-place change (still loading): load the document.
      handle.document = doc;
    } finally {
      host.dataset.posesVersion = String((Number(host.dataset.posesVersion) || 0) + 1);
    }
  };
  const onOptions = () => {
    handle.options = figureOptions(model);
  };
  const onChange = (e) => {
    const rows = rowsOf(e.detail.poses);
    sent = JSON.stringify(rows);
    model.set('poses', rows);
    model.save_changes();
  };
  const onError = (e) => {
    model.send({ type: 'error', ...e.detail });
  };
  host.addEventListener('change', onChange);
  host.addEventListener('error', onError);
  model.on('change:poses', onPoses);
  model.on('change:closed', onPoses);
  for (const k of OPTIONS) model.on(`change:${k}`, onOptions);
  handle.ready.then(() => {
    host.dataset.ready = 'true';
    host.dataset.backend = handle.backend ?? '';
  });
  return () => {
    model.off('change:poses', onPoses);
    model.off('change:closed', onPoses);
    for (const k of OPTIONS) model.off(`change:${k}`, onOptions);
    host.removeEventListener('change', onChange);
    host.removeEventListener('error', onError);
    handle.destroy();
  };
}

// For static pages (Figure.to_html and the figures' static copies): a figure's module script
// finds render here, or, when it ran before the bundle (the bundle sits in another figure's
// copy, further down the page), left its start in the waiting list.
const RENDER = Symbol.for('screwbender.figure.render');
const WAITING = Symbol.for('screwbender.figure.waiting');
globalThis[RENDER] ??= render;
for (const start of globalThis[WAITING]?.splice(0) ?? []) start(globalThis[RENDER]);

export default { render };
