// Decoupled smoothing and frame independence (paper Fig. 9 V1 / Fig. 8 V2, docs/math/properties.md §1, docs/math/decoupled-methods.md §1):
// the control poses are re-expressed with their local origin at the body point c (P ∘ translate(c))
// and subdivided twice — by screws, and decoupled (origins by the point rule, rotations by the
// same rules on rotation-only poses; crates/screwbender/src/subdivision/componentwise.rs). The trajectories of the same body
// points are drawn: the screw ones do not move when c changes, the decoupled ones do.
import { el as h } from '../dom.js';
import { LAYER, Segments, poseOf } from '../figure/slots.js';
import { add, sub, length, qrot, hexLinear } from '../math.js';

/** The wasm functions of this view, from the analysis module the dock hands to create(). */
let compareFrames;

const C = {
  screw: hexLinear('#1f5fbf'),
  decoupled: hexLinear('#e0602f'),
  reference: hexLinear('#e0602f'),
  centre: hexLinear('#9a2fd1'),
};
const RANGE = 3;

const sci = (v) => (v === 0 ? '0' : v < 1e-3 ? v.toExponential(1) : v.toFixed(4));

/** @type {import('../editor/dock.js').DockView} */
export default {
  id: 'frame',
  title: 'Frame',
  hint: 'Decoupled smoothing depends on the local frame, screw subdivision does not (paper Fig. 9 V1 / Fig. 8 V2)',
  live: true,
  create(app, el, wasm) {
    ({ compareFrames } = wasm);
    // Static markup: index.html's <template id="view-frame"> (no HTML from strings).
    el.append(/** @type {HTMLTemplateElement} */ (document.getElementById('view-frame')).content.cloneNode(true));
    const sliders = el.querySelector('.sliders');
    const state = { c: [0, 0, 0], visible: false, result: null, ref: null, showRef: true };
    const inputs = ['x', 'y', 'z'].map((axis, a) => {
      const lab = document.createElement('label');
      lab.append('c', h('sub', {}, axis), ' ', h('input', { type: 'range', min: String(-RANGE), max: String(RANGE), step: '0.05', value: '0' }), ' ', h('span', { class: 'val' }, '0.00'));
      const input = lab.querySelector('input');
      const val = lab.querySelector('.val');
      input.oninput = () => {
        state.c[a] = Number(input.value);
        val.textContent = state.c[a].toFixed(2);
        update();
        app.viewer.requestDraw();
      };
      sliders.append(lab);
      return { input, val };
    });
    const info = el.querySelector('.info');
    /** @type {HTMLElement} */ (el.querySelector('.circle')).onclick = () => app.run('loadPreset', 'circle4');
    /** @type {HTMLElement} */ (el.querySelector('.zero')).onclick = () => setOffset([0, 0, 0]);
    /** @type {HTMLElement} */ (el.querySelector('.ref')).onchange = (e) => {
      state.showRef = /** @type {HTMLInputElement} */ (e.target).checked;
      update();
      app.viewer.requestDraw();
    };

    function setOffset(c) {
      state.c = [...c];
      inputs.forEach(({ input, val }, a) => {
        input.value = String(c[a]);
        val.textContent = c[a].toFixed(2);
      });
      update();
      app.viewer.requestDraw();
    }

    /** Largest | |p − centre| − R | over a trajectory, with the circle fitted to the control origins. */
    function radial(traj, poses) {
      const n = poses.length / 7;
      let centre = [0, 0, 0];
      for (let k = 0; k < n; k++) centre = add(centre, poseOf(poses, k).origin);
      centre = centre.map((v) => v / n);
      let R = 0;
      for (let k = 0; k < n; k++) R += length(sub(poseOf(poses, k).origin, centre)) / n;
      let dev = 0;
      for (let k = 0; k < traj.length; k += 3) {
        dev = Math.max(dev, Math.abs(length(sub([traj[k], traj[k + 1], traj[k + 2]], centre)) - R));
      }
      return { dev, R };
    }

    function update() {
      if (!state.visible) return;
      const m = app.motion;
      // At most 6 levels: four subdivisions run per update (and per drag step).
      const o = { ...m.options(), levels: Math.min(m.options().levels, 6) };
      const poses = m.poses();
      const points = app.viewer.bodyPoints();
      const flat = Float64Array.from(points.flat());
      const res = compareFrames(poses, m.closed, o, state.c, flat);
      const ref = compareFrames(poses, m.closed, o, [0, 0, 0], flat);
      state.result = res;
      const { dpr } = app.viewer.pixelSize();
      const seg = new Segments();
      const len = res.length;
      const trace = (arr, p, color, width, alpha) => {
        const pts = [];
        for (let j = 0; j < len; j++) {
          const o3 = 3 * (p * len + j);
          pts.push([arr[o3], arr[o3 + 1], arr[o3 + 2]]);
        }
        seg.polyline(pts, m.closed, color, width, alpha, 0.003);
      };
      for (let p = 0; p < points.length; p++) {
        if (state.showRef) trace(ref.decoupled, p, C.reference, 1.5 * dpr, 0.35);
        trace(res.screw, p, C.screw, 2.6 * dpr, 0.95);
        trace(res.decoupled, p, C.decoupled, 2.2 * dpr, 0.95);
      }
      // The chosen centre c at every control pose (a small purple cross).
      const n = poses.length / 7;
      const r = 0.12;
      for (let k = 0; k < n; k++) {
        const { origin, rotation } = poseOf(poses, k);
        const c = add(origin, qrot(rotation, state.c));
        for (const d of [[r, 0, 0], [0, r, 0], [0, 0, r]]) seg.push(sub(c, d), add(c, d), C.centre, 2.4 * dpr, 1, 0.01);
      }
      app.viewer.renderer.setLines(LAYER.frame, seg.array(), true);

      el.querySelector('.ds').textContent = sci(res.screwDeviation);
      el.querySelector('.dd').textContent = sci(res.decoupledDeviation);
      const circle = app.view.scene === 'circle4';
      for (const q of ['.rs', '.rd', '.radial-h']) /** @type {HTMLElement} */ (el.querySelector(q)).hidden = !circle;
      if (circle) {
        // Trajectories of the first body point (the object's centre).
        const one = (arr) => arr.subarray(0, 3 * len);
        const rs = radial(one(res.screw), poses);
        const rd = radial(one(res.decoupled), poses);
        el.querySelector('.rs').textContent = sci(rs.dev);
        el.querySelector('.rd').textContent = sci(rd.dev);
        state.radial = { screw: rs.dev, decoupled: rd.dev, R: rs.R };
      } else state.radial = null;
      const v1 = o.rules === 'split' && circle && o.scheme !== 'bspline';
      info.textContent = `${o.scheme}, ${o.rules === 'split' ? 'split & tweak V1' : 'direct V2'}, ${o.levels} levels; c = (${state.c.map((v) => v.toFixed(2)).join(', ')}). ` +
        (v1 ? 'Warning: with the V1 4-point/Jarek rules circle4 is degenerate (two-span screws are half turns, docs/math/subdivision.md §4); use the direct rules. ' : '') +
        'Blue: screw trajectories (unchanged by c). Orange: decoupled trajectories with the origin at c' +
        (state.showRef ? '; faint orange: decoupled with the origin at 0.' : '.');
    }

    return {
      state,
      update,
      show(visible) {
        state.visible = visible;
        if (!visible) app.viewer.renderer.setLines(LAYER.frame, new Float32Array(0), true);
      },
      /** Sets the offset c = [x, y, z] (local coordinates), as the sliders do. */
      setOffset,
      dispose() {
        app.viewer.renderer.setLines(LAYER.frame, new Float32Array(0), true);
      },
    };
  },
};
