// The page's headline (the scene's title, figure and description, the motion's counts), the
// toast, and the message banner's close button.
import { presetName, presetSubtitle } from './presets.js';

/**
 * What the scene shown is: the preset named by the view (`named`), or for a motion from a file
 * (its name is not the preset's) the file's name and the preset it names, if any; `described` is
 * the preset whose figure and words describe it (not the last preset loaded for a file's motion,
 * whose figure and words would be stale).
 * @param {import('../app.js').App} app
 */
export function describeScene(app) {
  const info = app.viewer.drawing.sceneInfo;
  const named = app.scenes.find((s) => s.id === app.view.scene);
  const fileName = app.motion.name && app.motion.name !== app.view.scene ? app.motion.name : null;
  const fileScene = fileName && app.scenes.find((s) => s.id === fileName);
  const described = fileName ? fileScene : named;
  return { info, named, fileName, fileScene, described };
}

/**
 * Wires the banner's close button; returns {refresh, toast(message)}.
 * @param {import('../app.js').App} app
 */
export function buildStatus(app) {
  const $ = (id) => document.getElementById(id);
  /** @type {HTMLElement} */ ($('banner').querySelector('.close')).onclick = () => ($('banner').hidden = true);

  /** @type {ReturnType<typeof setTimeout> | undefined} */
  let toastTimer;
  /** Shows `msg` for a moment. */
  function toast(msg) {
    const t = $('toast');
    t.textContent = msg;
    t.hidden = false;
    clearTimeout(toastTimer);
    toastTimer = setTimeout(() => (t.hidden = true), 2500);
  }

  /** Shows the scene's title, figure and description and the motion's counts. */
  function refresh() {
    const { info, named, fileName, fileScene, described } = describeScene(app);
    $('scene-title').textContent = fileName
      ? (fileScene ? presetName(fileScene) : fileName)
      : named && app.view.object === 'scene' ? presetName(named) : `${info.label} · ${info.figure}`;
    $('scene-fig').textContent = described ? presetSubtitle(described) : '';
    $('scene-desc').textContent = fileName ? (fileScene?.description ?? '') : info.description;
    const m = app.motion;
    $('stats').textContent =
      `${m.poseCount} control poses · ${m.refinedCount.toLocaleString()} refined · ` +
      (app.parts.responsive.reduced
        ? `${app.parts.responsive.fullStrobe().toLocaleString()} strobe (${app.view.strobe.toLocaleString()} while moving)`
        : `${app.view.strobe.toLocaleString()} strobe`) +
      (app.selected >= 0 ? ` · pose ${app.selected} selected` : '');
  }

  return { refresh, toast };
}
