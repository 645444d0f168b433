// The editor's chrome, put together: the settings panel (panel.js), the headline and toast
// (status.js), the toolbar (toolbar.js), the timeline (timeline.js), the help overlay (help.js)
// and the paste dialog (paste-dialog.js). `refresh` shows the App's state in all of them.
import { buildPanel } from './panel.js';
import { buildPasteDialog } from './paste-dialog.js';
import { buildHelp } from './help.js';
import { buildToolbar } from './toolbar.js';
import { buildTimeline } from './timeline.js';
import { buildStatus } from './status.js';

/**
 * The chrome as the App uses it (`app.ui`).
 * @typedef {object} Ui
 * @property {import('../../vendor/lil-gui.esm.min.js').default} gui the settings panel
 * @property {() => void} refresh shows the App's state in every part
 * @property {(u: number, a: number, b: number, playhead: {t: number, start: number, end: number}) => void} setTime the playhead moved
 * @property {(show?: boolean) => void} toggleHelp
 * @property {(message: string) => void} toast
 */

/**
 * Builds the chrome around the view and shows the App's state in it.
 * @param {import('../app.js').App} app
 * @returns {Ui}
 */
export function buildUi(app) {
  const paste = buildPasteDialog(app);
  const panel = buildPanel(app, { openPaste: paste.open });
  const help = buildHelp(app);
  const toolbar = buildToolbar(app, { toggleHelp: help.toggle });
  const timeline = buildTimeline(app);
  const status = buildStatus(app);

  function refresh() {
    panel.refresh();
    status.refresh();
    toolbar.refresh();
    // Frames follow a change: measure them, and keep the pose numbers on their handles.
    app.parts.responsive.sample();
    app.parts.labels.place();
    timeline.refresh();
    toolbar.refreshPressed();
    timeline.refreshControls();
    const [a, b] = app.motion.domain();
    timeline.setTime(app.anim.u, a, b, app.viewer.playhead());
    app.parts.pose.refresh();
  }

  // Every change of the motion, its options or the view settings shows (before the dock's
  // update, which subscribes later).
  app.on('motion', refresh);
  // A new selection or gizmo mode, playback started or stopped, the playhead moved.
  app.on('selection', (d) => d?.redraw && refresh());
  app.on('playback', (d) => {
    if (d?.play) refresh();
    else if (d?.u !== undefined) timeline.setTime(d.u, d.a, d.b, d.playhead);
  });
  refresh();
  return { gui: panel.gui, refresh, setTime: timeline.setTime, toggleHelp: help.toggle, toast: status.toast };
}
