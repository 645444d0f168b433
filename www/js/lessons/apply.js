// What a lesson step does to the app before it is shown: its scene or document, motion options,
// display settings, timing, camera, selection and dock view (fields: www/lessons/README.md), through the
// page's commands.
import { tryCommand } from '../editor/commands.js';
import { withS } from './format.js';

/**
 * Applies step `s` to `app` and points the highlight at `s.highlight` through `setTarget`.
 * Measured poses (`samples`) open the import dialog on them once the rest is set up.
 * Its scene is the command loadPreset, its document, options, display and key times the command
 * lessonStep (editor/commands.js): undoable, named in the Undo menu. Throws (the player shows
 * the message) if the app refuses a part of it.
 * @param {import('../app.js').App} app
 */
export function applyStep(app, s, setTarget) {
  // An import dialog the last step's measured poses opened is answered by moving on: cancelled.
  document.getElementById('reduce-dialog')?.dispatchEvent(new Event('cancel'));
  if (s.scene) app.run('loadPreset', s.scene);
  if (s.document || s.options || s.display || s.timing?.times !== undefined) tryCommand(app, 'lessonStep', s, s.options ? withS(s.options) : null);
  if (s.select !== undefined) app.select(s.select < app.motion.poseCount ? s.select : -1);
  const t = s.timing ?? {};
  if (t.speed !== undefined) app.setPlayback({ speed: t.speed });
  if (t.u !== undefined) {
    const [a, b] = app.motion.domain();
    app.setPlayback({ u: Math.min(b, Math.max(a, t.u)), visible: true });
    app.viewer.updateAnim();
  }
  if (t.play !== undefined) app.viewer.setPlaying(t.play);
  if (s.camera) {
    app.viewer.camera.load(s.camera);
    app.viewer.cameraMoved();
  }
  if (s.dock !== undefined && s.dock !== (app.view.dock || '')) app.parts.dockHost.open(s.dock);
  if (s.stepsAt !== undefined) app.dock.current?.goTo?.(s.stepsAt);
  setTarget(s.highlight ?? null);
  app.ui.refresh();
  app.viewer.requestDraw();
  if (s.samples) offerSamples(app, s);
}

/**
 * Hands step `s`'s measured poses to the page's own import of many poses: its dialog offers to
 * keep, thin or fit them, as for a file (editor/files.js importPoses). Resolves true when
 * something was imported.
 * @param {import('../app.js').App} app
 */
export async function offerSamples(app, s) {
  const { stepSamples } = loadedSamples() ?? (await loadSamples());
  return app.parts.files.importPoses(stepSamples(s).document, `“${s.title}”`);
}

let samplesModule = null;
/**
 * samples.js, fetched with a step that has measured poses only.
 * @returns {Promise<typeof import('./samples.js')>}
 */
export const loadSamples = () => import('./samples.js').then((m) => (samplesModule = m));
/** samples.js once fetched, else null. */
export const loadedSamples = () => samplesModule;
