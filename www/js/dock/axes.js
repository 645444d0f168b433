// Screw axes: the screw of every span of the control polyscrew (or of a refined level), drawn as
// its axis in 3-D with a colour gradient and arrow ticks pointing along the rotation direction
// (right-hand rule), and listed with angle, slide, pitch and kind. Hovering a row highlights that
// span's axis and labels it in the 3-D view.
import { el as h } from '../dom.js';
import { LAYER, Segments, mix, poseOf } from '../figure/slots.js';
import { add, sub, scale, cross, normalize, length, hexLinear } from '../math.js';

/** The wasm functions of this view, from the analysis module the dock hands to create(). */
let Motion, spanScrewsOf;

/** Levels offered by the selector (0 = the control polyscrew). */
const MAX_LEVEL = 3;
/** Colours of successive spans (cycled), and of the highlighted axis. */
const PALETTE = ['#d1202f', '#1f6fd1', '#2a9d4b', '#b0589c', '#e07b1f', '#178f8f', '#6c4bd1', '#8c7a1f'].map(hexLinear);
const HIGHLIGHT = hexLinear('#ffb000');
const GRADIENT_STEPS = 8;
/** Most rows the table lists (all axes are still drawn). */
const MAX_ROWS = 400;

const deg = (r) => (r * 180) / Math.PI;
const fmt = (v, d = 3) => (Math.abs(v) < 0.5 * 10 ** -d ? (0).toFixed(d) : v.toFixed(d));

/** Any unit vector perpendicular to d. */
function perpendicular(d) {
  return normalize(Math.abs(d[2]) < 0.9 ? cross(d, [0, 0, 1]) : cross(d, [1, 0, 0]));
}

/** @type {import('../editor/dock.js').DockView} */
export default {
  id: 'axes',
  title: 'Screw axes',
  hint: 'The screw axis of every span: direction, angle, slide and pitch (hover a row or an axis to highlight it)',
  live: true,
  create(app, el, wasm) {
    ({ Motion, spanScrewsOf } = wasm);
    // Static markup: index.html's <template id="view-axes"> (no HTML from strings).
    el.append(/** @type {HTMLTemplateElement} */ (document.getElementById('view-axes')).content.cloneNode(true));
    const levelSel = /** @type {HTMLSelectElement} */ (el.querySelector('.level'));
    for (let l = 0; l <= MAX_LEVEL; l++) {
      const o = document.createElement('option');
      o.value = String(l);
      o.textContent = l === 0 ? 'control (0)' : `refined ${l}`;
      levelSel.append(o);
    }
    const tbody = /** @type {HTMLTableSectionElement} */ (el.querySelector('tbody'));
    const countEl = el.querySelector('.count');
    // The floating label lives in <body>: inside the dock it could not rise above the side panel
    // (the dock is its own stacking context).
    const label = document.createElement('div');
    label.className = 'axes-label';
    label.hidden = true;
    document.body.append(label);
    const state = { level: 0, hover: -1, screws: [], anchors: [], ends: [], visible: false };

    /** Poses of the chosen level (7 per pose) and whether they form a cycle. */
    function levelPoses() {
      const m = app.motion;
      if (state.level === 0) return m.poses();
      const refined = new Motion(m.toDocument(), { ...m.options(), levels: state.level });
      try {
        return refined.subdivide();
      } finally {
        refined.free();
      }
    }

    function rebuildTable() {
      tbody.textContent = '';
      const n = state.screws.length;
      const closed = app.motion.closed;
      state.screws.slice(0, MAX_ROWS).forEach((s, i) => {
        const tr = document.createElement('tr');
        const j = closed ? (i + 1) % n : i + 1;
        const pitch = s.kind === 'general' ? fmt(s.pitch) : s.kind === 'translation' ? '∞' : '—';
        tr.append(
          h('td', {}, h('span', { class: 'swatch' }), `${i} → ${j}`),
          h('td', {}, s.kind),
          h('td', {}, fmt(deg(s.angle), 2)),
          h('td', {}, fmt(s.slide)),
          h('td', {}, pitch),
        );
        const c = PALETTE[i % PALETTE.length];
        /** @type {HTMLElement} */ (tr.querySelector('.swatch')).style.background = `rgb(${c.map((v) => Math.round(Math.pow(v, 1 / 2.2) * 255)).join(',')})`;
        tr.title = `span ${i} → ${j}: angle ${fmt(deg(s.angle), 2)}°, slide ${fmt(s.slide)}`;
        tr.dataset.span = String(i);
        tr.onpointerenter = () => setHover(i);
        tr.onpointerleave = () => setHover(-1);
        tbody.append(tr);
      });
    }

    // While a span is highlighted, keep its label on its axis when the camera moves.
    let follow = 0;
    function track() {
      follow = 0;
      if (state.hover < 0 || !state.visible) return;
      placeLabel();
      follow = requestAnimationFrame(track);
    }

    function setHover(i) {
      state.hover = i;
      if (i >= 0 && !follow) follow = requestAnimationFrame(track);
      for (const tr of tbody.rows) tr.classList.toggle('hi', Number(tr.dataset.span) === i);
      draw();
      placeLabel();
      app.viewer.requestDraw();
    }

    /** The floating label of the hovered axis (angle and slide), at the axis point on the page. */
    function placeLabel() {
      const s = state.screws[state.hover];
      const at = state.anchors[state.hover];
      const p = s && at ? app.viewer.toPage(at) : null;
      if (!p) {
        label.hidden = true;
        return;
      }
      label.hidden = false;
      label.textContent = `${state.hover}: ${fmt(deg(s.angle), 1)}°, slide ${fmt(s.slide, 2)}`;
      label.style.left = `${p.x + 10}px`;
      label.style.top = `${p.y - 10}px`;
    }

    function draw() {
      if (!state.visible) return;
      const { dpr } = app.viewer.pixelSize();
      const poses = state.poses;
      const n = poses.length / 7;
      const closed = app.motion.closed;
      let lo = [Infinity, Infinity, Infinity];
      let hi = [-Infinity, -Infinity, -Infinity];
      for (let k = 0; k < n; k++) {
        const o = poseOf(poses, k).origin;
        lo = lo.map((v, a) => Math.min(v, o[a]));
        hi = hi.map((v, a) => Math.max(v, o[a]));
      }
      const size = Math.max(2, length(sub(hi, lo)));
      const seg = new Segments();
      state.anchors = [];
      state.ends = [];
      state.screws.forEach((s, i) => {
        const hot = i === state.hover;
        const dim = state.hover >= 0 && !hot;
        const base = hot ? HIGHLIGHT : PALETTE[i % PALETTE.length];
        const width = (hot ? 4.5 : 2.2) * dpr;
        const alpha = dim ? 0.3 : 1;
        const a = poseOf(poses, i).origin;
        const b = poseOf(poses, closed ? (i + 1) % n : i + 1).origin;
        if (s.kind === 'identity') {
          state.anchors.push(a);
          return;
        }
        let point;
        let dir;
        let half;
        if (s.kind === 'general') {
          point = s.point;
          dir = s.direction;
          // Long enough to see, and at least the slide (the screw moves along this piece).
          half = Math.max(0.12 * size, 0.6 * Math.abs(s.slide)) / Math.sqrt(Math.max(1, state.level + 1));
        } else {
          // A translation: the axis is at infinity; draw the direction from the span's middle.
          point = scale(add(a, b), 0.5);
          dir = s.direction;
          half = 0.5 * s.slide;
        }
        state.anchors.push(point);
        const p0 = sub(point, scale(dir, half));
        state.ends[i] = [p0, add(point, scale(dir, half))];
        const dark = mix(base, [0, 0, 0], 0.55);
        const light = mix(base, [1, 1, 1], 0.35);
        for (let k = 0; k < GRADIENT_STEPS; k++) {
          const t0 = k / GRADIENT_STEPS;
          const t1 = (k + 1) / GRADIENT_STEPS;
          seg.push(add(p0, scale(dir, 2 * half * t0)), add(p0, scale(dir, 2 * half * t1)),
            mix(dark, light, (t0 + t1) / 2), width, alpha, 0.004);
        }
        // Arrow head at the positive end, and a tick showing the sense of rotation.
        const tip = add(point, scale(dir, half));
        const u = perpendicular(dir);
        const v = cross(dir, u);
        const h = Math.min(0.25 * half, 0.05 * size);
        for (const w of [u, v, scale(u, -1), scale(v, -1)]) {
          seg.push(tip, add(sub(tip, scale(dir, h)), scale(w, 0.5 * h)), light, width, alpha, 0.004);
        }
        if (s.kind === 'general') {
          // A quarter circle around the axis in the rotation's sense, ending in a barb.
          const r = 0.6 * h;
          const c = add(point, scale(dir, 0.5 * half));
          const steps = 10;
          let prev = add(c, scale(u, r));
          for (let k = 1; k <= steps; k++) {
            const ang = (k / steps) * Math.PI * 0.75;
            const q = add(c, add(scale(u, r * Math.cos(ang)), scale(v, r * Math.sin(ang))));
            seg.push(prev, q, base, width * 0.8, alpha, 0.004);
            prev = q;
          }
          const ang = Math.PI * 0.75;
          const tangent = add(scale(u, -Math.sin(ang)), scale(v, Math.cos(ang)));
          seg.push(prev, sub(prev, add(scale(tangent, 0.35 * r), scale(dir, 0.25 * r))), base, width * 0.8, alpha, 0.004);
        }
        // A faint connector from the span's start origin to its axis point.
        if (hot) seg.push(a, point, HIGHLIGHT, 1.2 * dpr, 0.7, 0.004);
      });
      app.viewer.renderer.setLines(LAYER.screwAxes, seg.array(), true);
    }

    // Hovering an axis in the 3-D view highlights its row (and label), like hovering the row.
    let hoverFrom3d = false;
    const onCanvasMove = (e) => {
      if (e.buttons !== 0 || !state.ends) return;
      let best = -1;
      let bestD = 7;
      state.ends.forEach((ends, i) => {
        if (!ends) return;
        const a = app.viewer.toPage(ends[0]);
        const b = app.viewer.toPage(ends[1]);
        if (!a || !b) return;
        const dx = b.x - a.x;
        const dy = b.y - a.y;
        const L2 = dx * dx + dy * dy;
        const t = L2 > 0 ? Math.max(0, Math.min(1, ((e.clientX - a.x) * dx + (e.clientY - a.y) * dy) / L2)) : 0;
        const d = Math.hypot(e.clientX - (a.x + t * dx), e.clientY - (a.y + t * dy));
        if (d < bestD) {
          bestD = d;
          best = i;
        }
      });
      if (best >= 0 && best !== state.hover) {
        hoverFrom3d = true;
        setHover(best);
        tbody.children[best]?.scrollIntoView({ block: 'nearest' });
      } else if (best < 0 && hoverFrom3d) {
        hoverFrom3d = false;
        setHover(-1);
      }
    };

    levelSel.onchange = () => {
      state.level = Number(levelSel.value);
      state.hover = -1;
      update();
    };

    function update() {
      state.poses = levelPoses();
      state.screws = spanScrewsOf(state.poses, app.motion.closed);
      const n = state.screws.length;
      countEl.textContent = n > MAX_ROWS ? `${n} spans (table: first ${MAX_ROWS})` : `${n} span${n === 1 ? '' : 's'}`;
      if (state.hover >= state.screws.length) state.hover = -1;
      rebuildTable();
      if (state.hover >= 0) setHover(state.hover);
      draw();
      placeLabel();
    }

    return {
      state,
      update() {
        update();
      },
      show(visible) {
        state.visible = visible;
        if (visible) app.viewer.canvas.addEventListener('pointermove', onCanvasMove);
        else app.viewer.canvas.removeEventListener('pointermove', onCanvasMove);
        if (!visible) {
          app.viewer.renderer.setLines(LAYER.screwAxes, new Float32Array(0), true);
          label.hidden = true;
        }
      },
      /** Highlights span i (as hovering its row does); -1 clears. For tests and keyboard users. */
      highlight: setHover,
      dispose() {
        app.viewer.canvas.removeEventListener('pointermove', onCanvasMove);
        app.viewer.renderer.setLines(LAYER.screwAxes, new Float32Array(0), true);
        label.remove();
      },
    };
  },
};
