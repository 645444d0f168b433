// What a lesson step does to the app before it is shown: its scene or document, motion options,
// display settings, timing, selection and dock view (fields: www/lessons/README.md).
import { withS } from './format.js';

/**
 * Applies step `s` to `app` and points the highlight at `s.highlight` through `setTarget`.
 * Throws (the player shows the message) if the app refuses a part of it.
 * @param {import('../app.js').App} app
 */
export function applyStep(app, s, setTarget) {
  if (s.scene) app.loadPreset(s.scene);
  if (s.document) {
    const motion = new app.wasm.Motion(s.document, app.motion.options());
    app.edit(() => {
      app.setMotion(motion);
      app.setPlayback({ u: 0 });
      app.frameAll();
    });
  }
  const o = s.options ? withS(s.options) : null;
  if (o || s.display || s.timing?.times !== undefined) {
    app.edit(() => {
      if (o) {
        if (o.closed !== undefined) app.motion.setClosed(o.closed);
        delete o.closed;
        if (o.s !== undefined && o.scheme === undefined) o.scheme = 'j';
        if (Object.keys(o).length) app.motion.setOptions(o);
      }
      if (s.display) {
        app.updateView(s.display);
        if (s.display.object !== undefined) app.meshesChanged();
      }
      if (s.timing?.times !== undefined) app.motion.setTimes(s.timing.times ?? null);
    });
  }
  if (s.select !== undefined) app.select(s.select < app.motion.poseCount ? s.select : -1);
  const t = s.timing ?? {};
  if (t.speed !== undefined) app.setPlayback({ speed: t.speed });
  if (t.u !== undefined) {
    const [a, b] = app.motion.domain();
    app.setPlayback({ u: Math.min(b, Math.max(a, t.u)), visible: true });
    app.updateAnim();
  }
  if (t.play !== undefined) app.setPlaying(t.play);
  if (s.dock !== undefined && s.dock !== (app.view.dock || '')) app.openView(s.dock);
  if (s.stepsAt !== undefined) app.dock.current?.goTo?.(s.stepsAt);
  setTarget(s.highlight ?? null);
  app.ui.refresh();
  app.requestDraw();
}
