// Split/tweak step-through (paper Figs. 3–4, docs/math/subdivision.md): one subdivision level at a time and, inside
// a level, (a) the split — the screw midpoint of every span inserted — then (b) the tweak of each
// pose, drawn as arrows from before to after (origins), with the object before the tweak (pale
// ghosts) and after it. The core's splitTweakStep computes both (crates/screwbender/src/subdivision/split_tweak.rs).
import { LAYER, SLOT, Segments, instances, matricesOf, poseOf } from '../figure/slots.js';
import { add, sub, scale, cross, normalize, length, hexLinear } from '../math.js';

/** The wasm functions of this view, from the analysis module the dock hands to create(). */
let splitTweakStep;

/** Scale of the before-tweak ghosts relative to the object. */
const GHOST_SCALE = 0.97;
/** A tweak smaller than this (length units, or 1 − |q·q′|) counts as not moving the pose. */
const MOVED = 1e-9;
/** Most levels the view steps through. */
const MAX_LEVELS = 5;
const C = {
  input: hexLinear('#7d8597'),
  split: hexLinear('#2f8f3a'),
  ghost: hexLinear('#c9d3e3'),
  after: hexLinear('#1f5fbf'),
  moved: hexLinear('#e0602f'),
  arrow: hexLinear('#d1202f'),
  helper: hexLinear('#9a6fd1'),
};

const SCHEME_NAMES = { bspline: 'B-spline', fourpoint: '4-point', jarek: 'Jarek', j: 'J_s' };

/** What the tweak of one step does, by scheme and rule set (docs/math/subdivision.md §2 / §3). */
function tweakText(o) {
  const s = o.scheme;
  if (o.rules === 'split') {
    return {
      bspline: 'B-spline rule (V1): old pose b′ = s(b, ½, s(m_ab, ½, m_bc)) — halfway towards the average of its new neighbours; new poses stay',
      fourpoint: '4-point rule (V1): new pose m′ = s(h, 5/4, m), h = s(m_left, ½, m_right) — a quarter away from the average of its second neighbours; old poses stay',
      jarek: 'Jarek rule (V1): old b′ = s(b, ¼, s(m_ab, ½, m_bc)), new m′ = s(h, 9/8, m) — half of each B-spline and 4-point tweak',
    }[s] ?? 'J_s rule';
  }
  return {
    bspline: 'B-spline rule (V2): old pose = s(s(b, ¼, a), ½, s(b, ¼, c)); new pose = s(b, ½, c) (the split midpoint, unchanged)',
    fourpoint: '4-point rule (V2): new pose = s(s(a, 9/8, b), ½, s(d, 9/8, c)); old poses unchanged',
    jarek: 'Jarek rule (V2): old = s(s(a, 7/8, b), ½, s(c, 7/8, b)); new = s(s(a, 17/16, b), ½, s(d, 17/16, c))',
    j: `J_s rule (s = ${o.s}): old = s(s(b, s/4, a), ½, s(b, s/4, c)); new = s(s(a, w, b), ½, s(d, w, c)), w = 1 + (1 − s)/8`,
  }[s];
}

/** Segments of an arrow from a to b (shaft and a two-line head). */
function arrow(seg, a, b, color, width) {
  const d = sub(b, a);
  const L = length(d);
  if (L < 1e-9) return;
  const dir = scale(d, 1 / L);
  const side = normalize(Math.abs(dir[2]) < 0.9 ? cross(dir, [0, 0, 1]) : cross(dir, [1, 0, 0]));
  const h = Math.min(0.35 * L, 0.25);
  seg.push(a, b, color, width, 1, 0.01);
  seg.push(b, add(sub(b, scale(dir, h)), scale(side, 0.5 * h)), color, width, 1, 0.01);
  seg.push(b, add(sub(b, scale(dir, h)), scale(side, -0.5 * h)), color, width, 1, 0.01);
}

/** A small cross marking a point. */
function mark(seg, p, r, color, width) {
  for (const d of [[r, 0, 0], [0, r, 0], [0, 0, r]]) seg.push(sub(p, d), add(p, d), color, width, 1, 0.01);
}

/** Instances of the poses at the given indices of a 7-per-pose array. */
function pick(arr, idx) {
  const out = new Float64Array(idx.length * 7);
  idx.forEach((k, m) => out.set(arr.subarray(k * 7, k * 7 + 7), m * 7));
  return out;
}

/** @type {import('../editor/dock.js').DockView} */
export default {
  id: 'steps',
  title: 'Split & tweak',
  hint: 'Step through the subdivision: split (screw midpoints), then tweak — keys [ and ] (or , and .)',
  // Live: one step costs a few hundred screws, and the view then follows pose drags too.
  live: true,
  create(app, el, wasm) {
    ({ splitTweakStep } = wasm);
    // Static markup: index.html's <template id="view-steps"> (no HTML from strings).
    el.append(/** @type {HTMLTemplateElement} */ (document.getElementById('view-steps')).content.cloneNode(true));
    const caption = el.querySelector('.caption');
    const pos = el.querySelector('.pos');
    const levelsSel = /** @type {HTMLSelectElement} */ (el.querySelector('.levels'));
    for (let l = 1; l <= MAX_LEVELS; l++) levelsSel.append(new Option(String(l), String(l)));
    const state = { index: 0, levels: 3, visible: false, step: null, meshName: null, caption: '' };
    levelsSel.value = String(state.levels);

    const total = () => 2 * state.levels;

    function go(delta) {
      state.index = Math.max(0, Math.min(total() - 1, state.index + delta));
      update();
      app.viewer.requestDraw();
    }
    /** @type {HTMLElement} */ (el.querySelector('.prev')).onclick = () => go(-1);
    /** @type {HTMLElement} */ (el.querySelector('.next')).onclick = () => go(1);
    /** @type {HTMLElement} */ (el.querySelector('.strobe')).onclick = () => app.run('setView', 'showStrobe', !app.view.showStrobe);
    levelsSel.onchange = () => {
      state.levels = Number(levelsSel.value);
      state.index = Math.min(state.index, total() - 1);
      update();
      app.viewer.requestDraw();
    };

    const onKey = (e) => {
      const t = e.target;
      if (t && (t.tagName === 'INPUT' || t.tagName === 'TEXTAREA' || t.tagName === 'SELECT' || t.isContentEditable)) return;
      if (e.ctrlKey || e.metaKey || e.altKey) return;
      if (e.key === '[' || e.key === ',') go(-1);
      else if (e.key === ']' || e.key === '.') go(1);
      else return;
      e.preventDefault();
    };

    /** The object's mesh in both slots (the scene's object, or the chosen one). */
    function meshes() {
      const v = app.view;
      const name = v.object === 'scene' ? `scene:${v.scene}` : v.object;
      if (name === state.meshName) return;
      for (const slot of [SLOT.steps, SLOT.stepsGhost]) {
        if (name === 'obj' && app.imported) app.viewer.setImportedMesh(slot, app.imported);
        else app.viewer.renderer.setMesh(slot, name === 'obj' ? 'bar' : name, true);
      }
      state.meshName = name;
    }

    function clear() {
      app.viewer.renderer.setLines(LAYER.steps, new Float32Array(0), true);
      if (state.meshName) {
        app.viewer.renderer.setInstances(SLOT.steps, new Float32Array(0));
        app.viewer.renderer.setInstances(SLOT.stepsGhost, new Float32Array(0));
      }
    }

    function update() {
      if (!state.visible) return;
      const m = app.motion;
      const o = m.options();
      const level = Math.floor(state.index / 2);
      const phase = state.index % 2 === 0 ? 'split' : 'tweak';
      const step = splitTweakStep(m.poses(), m.closed, o, level);
      state.step = step;
      meshes();
      const { dpr } = app.viewer.pixelSize();
      const n = step.input.length / 7;
      const seg = new Segments();
      const origins = (arr) => Array.from({ length: arr.length / 7 }, (_, k) => poseOf(arr, k).origin);
      const size = Math.max(2, ...origins(step.input).map((p) => length(p)));
      const r = 0.015 * size;
      const rules = o.rules === 'split' ? 'split & tweak V1' : 'direct V2';
      const name = SCHEME_NAMES[o.scheme] ?? o.scheme;
      const open = m.closed ? '' : ' (open motion: the dummy end poses of docs/math/open-sequences.md are included)';
      if (phase === 'split') {
        seg.polyline(origins(step.input), m.closed, C.input, 1.5 * dpr, 0.9);
        seg.polyline(origins(step.split), m.closed, C.split, 1.2 * dpr, 0.6);
        const mids = [];
        for (let i = 0; i < n; i++) {
          mids.push(2 * i + 1);
          mark(seg, poseOf(step.split, 2 * i + 1).origin, r, C.split, 2.2 * dpr);
        }
        app.viewer.renderer.setInstances(SLOT.stepsGhost, instances(matricesOf(step.input), () => C.input));
        app.viewer.renderer.setInstances(SLOT.steps, instances(matricesOf(pick(step.split, mids)), () => C.split));
        state.caption = `Level ${level} → ${level + 1} · split: the screw midpoint s(Pᵢ, ½, Pᵢ₊₁) of each of the ${n} spans is inserted (green), giving ${2 * n} poses${open}.`;
      } else {
        const moved = [];
        for (let j = 0; j < 2 * n; j++) if (step.tweaked[j]) moved.push(j);
        seg.polyline(origins(step.split), m.closed, C.ghost, 1.2 * dpr, 0.8);
        seg.polyline(origins(step.output), m.closed, C.after, 1.6 * dpr, 0.9);
        for (const j of moved) arrow(seg, poseOf(step.split, j).origin, poseOf(step.output, j).origin, C.arrow, 2.4 * dpr);
        // Helpers (paper Fig. 4, drawn faintly): V1 — the pose each tweak moves towards or away
        // from, joined to the result; V2 — the two inner screws of the rule, joined to each other
        // (the result is the screw midpoint between them).
        step.helperSlots.forEach((j, k) => {
          const h = poseOf(step.helpers, k).origin;
          mark(seg, h, 0.6 * r, C.helper, 1.5 * dpr);
          if (o.rules === 'split') seg.push(h, poseOf(step.output, j).origin, C.helper, 1 * dpr, 0.5, 0.01);
          else if (k % 2 === 1) seg.push(poseOf(step.helpers, k - 1).origin, h, C.helper, 1 * dpr, 0.5, 0.01);
        });
        // Ghosts a little smaller: where the tweak does not move a pose (e.g. poses sampled from
        // one screw) the pose after the tweak covers its ghost instead of z-fighting with it.
        app.viewer.renderer.setInstances(SLOT.stepsGhost, instances(matricesOf(pick(step.split, moved), GHOST_SCALE), () => C.ghost));
        const movedSet = new Set(moved);
        app.viewer.renderer.setInstances(SLOT.steps, instances(matricesOf(step.output), (k) => (movedSet.has(k) ? C.moved : C.after)));
        // How many tweaked poses really move (poses sampled from one screw do not).
        const changed = moved.filter((j) => {
          const a = poseOf(step.split, j);
          const b = poseOf(step.output, j);
          const dq = Math.abs(a.rotation.reduce((acc, v, k) => acc + v * b.rotation[k], 0));
          return length(sub(a.origin, b.origin)) > MOVED || 1 - dq > MOVED;
        }).length;
        state.changed = changed;
        const shown = changed === moved.length ? `${moved.length} of ${2 * n} poses move (arrows)` :
          `the rule tweaks ${moved.length} of ${2 * n} poses; ${changed} of them move by more than ${MOVED} (arrows)`;
        state.caption = `Level ${level} → ${level + 1} · tweak (${name}, ${rules}): ${shown}. ${tweakText(o)}.${open}`;
      }
      app.viewer.renderer.setLines(LAYER.steps, seg.array(), true);
      caption.textContent = state.caption;
      pos.textContent = `step ${state.index + 1} / ${total()}`;
      /** @type {HTMLButtonElement} */ (el.querySelector('.prev')).disabled = state.index === 0;
      /** @type {HTMLButtonElement} */ (el.querySelector('.next')).disabled = state.index === total() - 1;
    }

    return {
      state,
      update,
      show(visible) {
        state.visible = visible;
        if (visible) window.addEventListener('keydown', onKey);
        else {
          window.removeEventListener('keydown', onKey);
          clear();
        }
      },
      /** Goes to step k (0-based: 2ℓ = split of level ℓ, 2ℓ + 1 = its tweak). */
      goTo(k) {
        state.index = 0;
        go(k);
      },
      dispose() {
        window.removeEventListener('keydown', onKey);
        clear();
      },
    };
  },
};
