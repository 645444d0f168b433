// The toolbar: gizmo mode, insert / delete, undo / redo, frame, help, snap, the dock's button,
// and the View menu's Share entry; its buttons show the state (pressed, disabled).
import { VIEW_IDS } from '../dock/index.js';
import { openShare } from './modules.js';

/**
 * Wires the buttons; `toggleHelp` opens and closes the help overlay. Returns {refresh}.
 * @param {import('../app.js').App} app
 * @param {{toggleHelp: (show?: boolean) => void}} help
 */
export function buildToolbar(app, { toggleHelp }) {
  const $ = (id) => document.getElementById(id);
  const tool = (id, f) => ($(id).onclick = f);
  tool('t-translate', () => app.setMode('translate'));
  tool('t-rotate', () => app.setMode('rotate'));
  tool('t-insert', () => app.run('insertPose'));
  tool('t-delete', () => app.selected >= 0 && app.run('deletePose'));
  tool('t-undo', () => app.parts.session.undo());
  tool('t-redo', () => app.parts.session.redo());
  tool('t-frame', () => app.parts.viewpoint.frame());
  tool('t-help', () => toggleHelp());
  tool('m-share', () => {
    app.parts.viewpoint.menu.close();
    openShare(app, $('t-view'));
  });
  tool('t-snap', () => app.run('setView', 'snap', !app.view.snap));
  /** @type {string | undefined} the analysis view last open (the dock button reopens it) */
  let lastView;
  tool('t-dock', () => app.parts.dockHost.open(app.view.dock ? '' : lastView ?? firstView()));

  function firstView() {
    return /** @type {HTMLElement | null} */ (document.querySelector('#dock .tabs button'))?.dataset.view ?? VIEW_IDS[0];
  }

  /** Shows the mode, snap, undo / redo, delete and dock state on the buttons. */
  function refresh() {
    $('t-translate').classList.toggle('on', app.mode === 'translate');
    $('t-rotate').classList.toggle('on', app.mode === 'rotate');
    $('t-snap').classList.toggle('on', !!app.view.snap);
    /** @type {HTMLButtonElement} */ ($('t-undo')).disabled = !app.history.canUndo;
    /** @type {HTMLButtonElement} */ ($('t-redo')).disabled = !app.history.canRedo;
    /** @type {HTMLButtonElement} */ ($('t-delete')).disabled = app.selected < 0;
    $('t-dock').classList.toggle('on', !!app.view.dock);
    if (app.view.dock) lastView = app.view.dock;
  }

  /** The pressed state for assistive technology, after `refresh` (the 'on' classes). */
  function refreshPressed() {
    for (const id of ['t-translate', 't-rotate', 't-snap', 't-dock']) $(id).setAttribute('aria-pressed', String($(id).classList.contains('on')));
  }

  return { refresh, refreshPressed };
}
