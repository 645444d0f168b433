// Polygon subdivision (paper Fig. 2, and Fig. 3's split & tweak): a planar control polygon refined
// by the three point schemes of docs/math/point-rules.md — B-spline red, 4-point blue, Jarek green — computed by
// the core's point rules (subdividePolygon; the same generic code as the pose rules). The preset
// polygons' vertices can be dragged; the control origins of the motion (projected to z = 0) are
// shown read-only.
import { el as h } from '../dom.js';

/** The wasm functions of this view, from the analysis module the dock hands to create(). */
let polygonPresets, subdividePolygon, splitTweakStep;

const SCHEMES = [
  { id: 'bspline', name: 'B-spline', color: '#d1202f' },
  { id: 'fourpoint', name: '4-point', color: '#1f5fd1' },
  { id: 'jarek', name: 'Jarek', color: '#1f9d3a' },
];
const CONTROL = '#8a8f9c';
/** Pick radius of a vertex, CSS pixels. */
const PICK = 10;
/** Most rows of the numbers table. */
const MAX_ROWS = 96;
/** Canvas height, CSS pixels. */
const HEIGHT = 300;

/** Points as poses without rotation (7 numbers each), so the pose step-through runs on them. */
function asPoses(flat) {
  const n = flat.length / 2;
  const out = new Float64Array(n * 7);
  for (let k = 0; k < n; k++) out.set([flat[2 * k], flat[2 * k + 1], 0, 1, 0, 0, 0], 7 * k);
  return out;
}

/** @type {import('../editor/dock.js').DockView} */
export default {
  id: 'polygon',
  title: 'Polygon',
  hint: 'Point subdivision of a planar polygon: B-spline, 4-point, Jarek (paper Figs. 2–3); drag the vertices',
  live: true,
  create(app, el, wasm) {
    ({ polygonPresets, subdividePolygon, splitTweakStep } = wasm);
    const presets = polygonPresets();
    // Static markup: index.html's <template id="view-polygon"> (no HTML from strings).
    el.append(/** @type {HTMLTemplateElement} */ (document.getElementById('view-polygon')).content.cloneNode(true));
    el.querySelector('canvas').height = HEIGHT;
    el.querySelector('.numbers thead tr').append(...SCHEMES.map((s) => h('th', {}, s.name)));
    const source = /** @type {HTMLSelectElement} */ (el.querySelector('.source'));
    for (const p of presets) source.append(new Option(`${p.id} (${p.figure})`, p.id));
    source.append(new Option('control origins (read-only)', 'origins'));
    const levels = /** @type {HTMLInputElement} */ (el.querySelector('.levels'));
    const lv = el.querySelector('.lv');
    const fig3 = /** @type {HTMLInputElement} */ (el.querySelector('.fig3'));
    const once = /** @type {HTMLInputElement} */ (el.querySelector('.once'));
    const canvas = el.querySelector('canvas');
    const modeNote = el.querySelector('.mode');
    const legend = el.querySelector('.legend');
    const show = { bspline: true, fourpoint: true, jarek: true };
    for (const s of SCHEMES) {
      const lab = document.createElement('label');
      lab.append(h('input', { type: 'checkbox', checked: true }), ' ', h('span', { class: 'swatch', 'data-color': s.color }), s.name);
      lab.querySelector('input').onchange = (e) => {
        show[s.id] = /** @type {HTMLInputElement} */ (e.target).checked;
        draw();
      };
      legend.append(lab);
    }
    const ctl = document.createElement('span');
    ctl.className = 'note';
    ctl.append(h('span', { class: 'swatch', 'data-color': CONTROL }), 'control polygon');
    legend.append(ctl);

    const state = {
      source: 'polygon_l',
      level: 1,
      /** Editable copies of the presets (x, y pairs). */
      polys: Object.fromEntries(presets.map((p) => [p.id, Float64Array.from(p.points.flat())])),
      points: null,
      results: {},
      drag: -1,
      hover: -1,
      view: null,
    };
    source.value = state.source;

    const editable = () => state.source !== 'origins';

    function currentPoints() {
      if (editable()) return state.polys[state.source];
      const poses = app.motion.poses();
      const n = poses.length / 7;
      const out = new Float64Array(2 * n);
      for (let k = 0; k < n; k++) {
        out[2 * k] = poses[7 * k];
        out[2 * k + 1] = poses[7 * k + 1];
      }
      return out;
    }

    function compute() {
      state.points = currentPoints();
      const closed = editable() ? true : app.motion.closed;
      state.closed = closed;
      state.results = {};
      for (const s of SCHEMES) {
        state.results[s.id] = subdividePolygon(state.points, closed, { scheme: s.id, rules: 'direct', levels: state.level });
      }
      state.once = {};
      if (once.checked && state.level > 1) {
        for (const s of SCHEMES) {
          state.once[s.id] = subdividePolygon(state.points, closed, { scheme: s.id, rules: 'direct', levels: 1 });
        }
      }
      state.fig3 = null;
      if (fig3.checked && closed) {
        const poses = asPoses(state.points);
        state.fig3 = Object.fromEntries(SCHEMES.map((s) => [s.id, splitTweakStep(poses, true, { scheme: s.id, rules: 'split' }, 0)]));
      }
      modeNote.textContent = editable()
        ? `Drag a vertex to edit this polygon (the 3-D motion is not changed). ${state.points.length / 2} vertices, ${closed ? 'closed' : 'open'}.`
        : 'Control origins of the motion, projected to the x-y plane: read-only here (edit the poses in the 3-D view; this view follows).';
    }

    /** World → canvas transform fitting every drawn point (y up). */
    function fit(w, h) {
      let lo = [Infinity, Infinity];
      let hi = [-Infinity, -Infinity];
      const eat = (arr) => {
        for (let k = 0; k + 1 < arr.length; k += 2) {
          lo = [Math.min(lo[0], arr[k]), Math.min(lo[1], arr[k + 1])];
          hi = [Math.max(hi[0], arr[k]), Math.max(hi[1], arr[k + 1])];
        }
      };
      eat(state.points);
      for (const s of SCHEMES) if (show[s.id]) eat(state.results[s.id]);
      const pad = 18;
      const sx = (w - 2 * pad) / Math.max(1e-9, hi[0] - lo[0]);
      const sy = (h - 2 * pad) / Math.max(1e-9, hi[1] - lo[1]);
      const s = Math.min(sx, sy);
      const ox = (w - s * (hi[0] - lo[0])) / 2 - s * lo[0];
      const oy = (h + s * (hi[1] - lo[1])) / 2 + s * lo[1];
      return { s, ox, oy, to: (x, y) => [ox + s * x, oy - s * y], from: (X, Y) => [(X - ox) / s, (oy - Y) / s] };
    }

    function draw() {
      if (!state.points) return;
      const dpr = window.devicePixelRatio || 1;
      const w = canvas.clientWidth || 480;
      const h = HEIGHT;
      if (canvas.width !== Math.round(w * dpr)) canvas.width = Math.round(w * dpr);
      canvas.height = Math.round(h * dpr);
      const g = canvas.getContext('2d');
      g.setTransform(dpr, 0, 0, dpr, 0, 0);
      g.clearRect(0, 0, w, h);
      g.fillStyle = '#fff';
      g.fillRect(0, 0, w, h);
      // While dragging keep the frame still (the fit would chase the pointer).
      if (state.drag < 0 || !state.view) state.view = fit(w, h);
      const { to } = state.view;
      const path = (arr, closed) => {
        g.beginPath();
        for (let k = 0; k + 1 < arr.length; k += 2) {
          const [X, Y] = to(arr[k], arr[k + 1]);
          if (k === 0) g.moveTo(X, Y);
          else g.lineTo(X, Y);
        }
        if (closed) g.closePath();
      };
      g.lineJoin = 'round';
      g.strokeStyle = CONTROL;
      g.lineWidth = 1.5;
      path(state.points, state.closed);
      g.stroke();
      for (const s of SCHEMES) {
        if (!show[s.id] || !state.once[s.id]) continue;
        g.strokeStyle = s.color;
        g.globalAlpha = 0.55;
        g.lineWidth = 1.1;
        g.setLineDash([4, 3]);
        path(state.once[s.id], state.closed);
        g.stroke();
        g.setLineDash([]);
        g.globalAlpha = 1;
      }
      for (const s of SCHEMES) {
        if (!show[s.id]) continue;
        g.strokeStyle = s.color;
        g.lineWidth = 1.8;
        path(state.results[s.id], state.closed);
        g.stroke();
        if (state.level <= 2) {
          g.fillStyle = s.color;
          const r = state.results[s.id];
          for (let k = 0; k < r.length; k += 2) {
            const [X, Y] = to(r[k], r[k + 1]);
            g.fillRect(X - 1.5, Y - 1.5, 3, 3);
          }
        }
      }
      if (state.fig3) {
        // Fig. 3: split midpoints (open circles) and each scheme's tweak arrows.
        const split = state.fig3.bspline.split;
        g.strokeStyle = '#333';
        g.lineWidth = 1;
        for (let j = 1; j < split.length / 7; j += 2) {
          const [X, Y] = to(split[7 * j], split[7 * j + 1]);
          g.beginPath();
          g.arc(X, Y, 3.5, 0, 2 * Math.PI);
          g.stroke();
        }
        for (const s of SCHEMES) {
          if (!show[s.id]) continue;
          const st = state.fig3[s.id];
          g.strokeStyle = s.color;
          g.fillStyle = s.color;
          g.lineWidth = 1.5;
          for (let j = 0; j < st.tweaked.length; j++) {
            if (!st.tweaked[j]) continue;
            const [X0, Y0] = to(st.split[7 * j], st.split[7 * j + 1]);
            const [X1, Y1] = to(st.output[7 * j], st.output[7 * j + 1]);
            const L = Math.hypot(X1 - X0, Y1 - Y0);
            if (L < 0.5) continue;
            g.beginPath();
            g.moveTo(X0, Y0);
            g.lineTo(X1, Y1);
            const ux = (X1 - X0) / L;
            const uy = (Y1 - Y0) / L;
            const hh = Math.min(7, 0.5 * L);
            g.lineTo(X1 - hh * ux - 0.5 * hh * uy, Y1 - hh * uy + 0.5 * hh * ux);
            g.moveTo(X1, Y1);
            g.lineTo(X1 - hh * ux + 0.5 * hh * uy, Y1 - hh * uy - 0.5 * hh * ux);
            g.stroke();
          }
        }
      }
      const n = state.points.length / 2;
      for (let k = 0; k < n; k++) {
        const [X, Y] = to(state.points[2 * k], state.points[2 * k + 1]);
        g.beginPath();
        g.arc(X, Y, k === state.hover || k === state.drag ? 6 : 4.5, 0, 2 * Math.PI);
        g.fillStyle = editable() ? (k === state.drag ? '#ff9d1c' : '#fff') : '#d8dbe2';
        g.fill();
        g.strokeStyle = '#444';
        g.lineWidth = 1.2;
        g.stroke();
      }
      g.fillStyle = '#555';
      g.font = '11px system-ui, sans-serif';
      g.fillText(`level ${state.level}`, 6, 14);
    }

    /** The refined vertices as a table (at most MAX_ROWS rows; the vectors of docs/math/point-rules.md §5 at level 1). */
    function numbers() {
      const body = el.querySelector('.numbers tbody');
      if (!/** @type {HTMLDetailsElement} */ (el.querySelector('.numbers')).open) return;
      const count = state.results.bspline.length / 2;
      const fmt = (v) => (Math.abs(v) < 5e-13 ? 0 : v).toFixed(4).replace(/\.?0+$/, '');
      const rows = [];
      for (let k = 0; k < Math.min(count, MAX_ROWS); k++) {
        const cells = SCHEMES.map((s) => {
          const r = state.results[s.id];
          return h('td', {}, `(${fmt(r[2 * k])}, ${fmt(r[2 * k + 1])})`);
        });
        rows.push(h('tr', {}, h('td', {}, k), ...cells));
      }
      if (count > MAX_ROWS) rows.push(h('tr', {}, h('td', { colSpan: 4 }, `… ${count - MAX_ROWS} more`)));
      body.replaceChildren(...rows);
    }
    el.querySelector('.numbers').addEventListener('toggle', () => numbers());

    function refresh() {
      compute();
      draw();
      numbers();
    }

    const local = (e) => {
      const r = canvas.getBoundingClientRect();
      return [e.clientX - r.left, e.clientY - r.top];
    };
    function pickVertex(pt) {
      if (!state.view) return -1;
      let best = -1;
      let bestD = PICK;
      for (let k = 0; k < state.points.length / 2; k++) {
        const [X, Y] = state.view.to(state.points[2 * k], state.points[2 * k + 1]);
        const d = Math.hypot(X - pt[0], Y - pt[1]);
        if (d <= bestD) {
          bestD = d;
          best = k;
        }
      }
      return best;
    }
    canvas.addEventListener('pointerdown', (e) => {
      if (!editable()) return;
      const k = pickVertex(local(e));
      if (k < 0) return;
      state.drag = k;
      canvas.setPointerCapture?.(e.pointerId);
      e.preventDefault();
      draw();
    });
    canvas.addEventListener('pointermove', (e) => {
      const pt = local(e);
      if (state.drag >= 0) {
        const [x, y] = state.view.from(pt[0], pt[1]);
        const p = state.polys[state.source];
        p[2 * state.drag] = x;
        p[2 * state.drag + 1] = y;
        refresh();
        return;
      }
      const k = editable() ? pickVertex(pt) : -1;
      if (k !== state.hover) {
        state.hover = k;
        canvas.style.cursor = k >= 0 ? 'grab' : 'default';
        draw();
      }
    });
    const up = () => {
      if (state.drag < 0) return;
      state.drag = -1;
      refresh();
    };
    canvas.addEventListener('pointerup', up);
    canvas.addEventListener('pointercancel', up);

    source.onchange = () => {
      state.source = source.value;
      state.view = null;
      refresh();
    };
    levels.oninput = () => {
      state.level = Number(levels.value);
      lv.textContent = String(state.level);
      refresh();
    };
    fig3.onchange = () => refresh();
    once.onchange = () => refresh();
    /** @type {HTMLElement} */ (el.querySelector('.reset')).onclick = () => {
      const p = presets.find((x) => x.id === state.source);
      if (p) state.polys[p.id] = Float64Array.from(p.points.flat());
      refresh();
    };

    // Redraw at the new width when the dock is resized.
    new ResizeObserver(() => draw()).observe(canvas);

    return {
      state,
      update() {
        refresh();
      },
      show() {
        // A 2-D view: nothing in the 3-D scene to add or remove.
      },
      /** Selects the source ('polygon_l' | 'polygon_star' | 'polygon_split_tweak' | 'origins') and level. */
      set(src, level) {
        if (src) source.value = state.source = src;
        if (level !== undefined) {
          levels.value = String(level);
          state.level = level;
          lv.textContent = String(level);
        }
        state.view = null;
        refresh();
      },
      /** Page position of vertex k (for tests). */
      vertexOnPage(k) {
        const [X, Y] = state.view.to(state.points[2 * k], state.points[2 * k + 1]);
        const r = canvas.getBoundingClientRect();
        return { x: r.left + X, y: r.top + Y };
      },
    };
  },
};
