// Entry point: starts the app and exposes the inspection API `window.screwbender`.
//
// window.screwbender (documented for tests and curious users; all read-only views):
//   ready: Promise<void>            resolves when the first frame can be drawn (rejects on a fatal error)
//   backend(): 'WebGPU' | 'WebGL2'
//   errors(): string[]              every message shown in the banner
//   poses(): Float64Array           control poses, 7 per pose (origin xyz, quaternion wxyz), live during a drag
//   refined(): Float64Array         refined poses of the smoothed motion, 7 per pose, live during a drag
//   options(): {scheme, j, rules, levels}   session(): the autosaved session object
//   selected(): number              selected control pose or -1
//   handleOnPage(i): {x, y}         page coordinates (CSS px) of control pose i's handle
//   gizmoOnPage(part): {x, y}       a grabbable point of a gizmo part: 'axis-x|y|z', 'plane-x|y|z',
//                                   'ring-x|y|z', 'trackball' (of the current mode)
//   frames(): number                frames drawn so far; stats(): {updateMs, frameMs, renderMs} (CPU
//                                   time) and frameIntervalMs (requestAnimationFrame to requestAnimationFrame
//                                   between the last two drawn frames: what the user waits, GPU included)
//   openView(id): Promise<instance> opens an analysis view of the dock ('' closes it); the first
//                                   one fetches the dock, its views and the analysis module
//   flushViews()                    runs the open view's pending update now
//   app                             the App object itself (for benchmarks / debugging); its state
//                                   is read-only: change it through its setters (js/app.js)
//   lessons: Promise<player>        the lesson player once fetched and started, after the first
//                                   frame (js/lessons/player.js documents it; null if it failed);
//                                   reading it fetches the player if the page has not yet
//   lms                             only in a lesson package's page: its LMS connection, the
//                                   learner's id and the course's place (js/lessons/launch.js)
import { App } from './app.js';
import { setUpLessons } from './editor/lessons-entry.js';

const app = new App();

window.addEventListener('error', (e) => app.parts.notices.show(`Unexpected error: ${e.message}`));
window.addEventListener('unhandledrejection', (e) => app.parts.notices.show(`Unexpected error: ${e.reason?.message ?? e.reason}`));

const ready = app.start().catch((e) => {
  app.parts.notices.fatal(e);
  throw e;
});
ready.catch(() => {});
// Lessons: the player is fetched when a lesson, the tour or the Lessons menu is to be shown
// (editor/lessons-entry.js); a failure leaves the page as it is, with a message.
const lessons = setUpLessons(app, ready);

/** @type {any} */ (window).screwbender = {
  ready,
  app,
  get lessons() {
    return lessons();
  },
  backend: () => app.viewer?.backend,
  errors: () => [...app.errors],
  // During a drag the live state is the drag session's (the Motion gets the pose on release).
  poses: () => Float64Array.from(app.drag?.session ? app.drag.session.poses() : app.motion.poses()),
  refined: () => Float64Array.from(app.drag?.session ? app.drag.session.refined() : app.motion.subdivide()),
  options: () => app.motion.options(),
  session: () => app.parts.session.session(),
  selected: () => app.selected,
  handleOnPage: (i) => app.viewer.screenOfPose(i),
  gizmoOnPage: (part) => app.viewer.screenOfGizmo(part),
  frames: () => app.viewer?.frames,
  stats: () => ({ ...app.viewer?.stats }),
  openView: (id) => app.parts.dockHost.open(id),
  flushViews: () => app.dock?.flush(),
};
