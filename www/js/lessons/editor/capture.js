// A lesson step's setup taken from what is on the page now, in one action: the preset (where
// the motion is still the preset's) or the motion document, the options, the display settings,
// the timing, the camera, the open analysis view, the Split & tweak step and the selection —
// the fields a step sets (www/lessons/README.md), so showing the step brings the page back to
// this state.
import { DISPLAY_FIELDS } from '../format.js';

/** The keys of a step that capture() fills: the rest (texts, highlight, exercise) stays. */
export const SETUP_KEYS = ['scene', 'document', 'options', 'display', 'timing', 'camera', 'dock', 'stepsAt', 'select'];

/** Rounds away float noise (a dragged pose): 12 significant digits keep what a file needs. */
const tidy = (x) => (Number.isFinite(x) ? Number(x.toPrecision(12)) : x);

/**
 * The setup of the page now, as the fields of a lesson step.
 * @param {import('../../app.js').App} app
 */
export function capture(app) {
  const m = app.motion;
  const step = {};
  const doc = m.toDocument();
  const scene = app.view.scene;
  let preset = null;
  if (scene && app.scenes.some((s) => s.id === scene)) {
    const p = app.wasm.Motion.fromPreset(scene);
    try {
      preset = JSON.stringify(p.toDocument().poses);
    } finally {
      p.free();
    }
  }
  if (preset !== null && preset === JSON.stringify(doc.poses)) step.scene = scene;
  else step.document = /** @type {any} */ ({ ...(doc.name ? { name: doc.name } : {}), closed: m.closed, poses: doc.poses.map((p) => ({ origin: p.origin.map(tidy), rotation: p.rotation.map(tidy) })) });
  if (step.document && doc.velocities) step.document.velocities = doc.velocities.map((v) => v ?? null);
  const o = m.options();
  step.options = { scheme: o.scheme, rules: o.rules, levels: o.levels, closed: m.closed };
  if (o.scheme === 'j') step.options.s = tidy(o.s);
  step.display = {};
  for (const [k, type] of Object.entries(DISPLAY_FIELDS)) {
    const v = k === 'strobe' ? app.parts.responsive?.fullStrobe() ?? app.view.strobe : app.view[k];
    if (typeof v === type) step.display[k] = v;
  }
  const times = app.times();
  step.timing = { times: times ? times.map(tidy) : null, speed: Math.min(4, Math.max(0.1, app.anim.speed)), play: !!app.anim.playing, u: tidy(app.anim.u) };
  const cam = app.viewer.camera.toJSON();
  step.camera = { target: cam.target.map(tidy), distance: tidy(cam.distance), yaw: tidy(cam.yaw), pitch: tidy(cam.pitch), ortho: cam.ortho };
  step.dock = app.view.dock || '';
  const at = app.dock?.current?.state?.index;
  if (step.dock === 'steps' && Number.isInteger(at) && at >= 0 && at <= 9) step.stepsAt = at;
  step.select = app.selected;
  return step;
}

/** Words for a step's setup, for the step editor: "preset circle4 · 4-point, 5 levels · dock axes · pose 1 selected". */
export function describeSetup(s) {
  const parts = [];
  if (s.scene) parts.push(`preset ${s.scene}`);
  else if (s.document) parts.push(`${s.document.poses?.length ?? 0} poses${s.document.closed ? ', closed' : ''}`);
  else parts.push('the motion as it is');
  if (s.options) parts.push(`${s.options.scheme ?? 'scheme as it is'}, ${s.options.levels ?? '?'} levels`);
  if (s.samples) parts.push(`${typeof s.samples.count === 'number' ? s.samples.count : 'n'} measured poses (${s.samples.motion})`);
  if (s.dock) parts.push(`view ${s.dock}`);
  if (Number.isInteger(s.select) && s.select >= 0) parts.push(`pose ${s.select} selected`);
  return parts.join(' · ');
}
