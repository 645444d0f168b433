// Staying responsive in heavy sessions. While frames are drawn, the interval between
// consecutive drawn frames is measured from requestAnimationFrame to requestAnimationFrame
// (app.viewer.stats.frameIntervalMs: what the user waits, GPU included, beside the CPU-side
// stats.frameMs). During a drag, an orbit, a pan or a zoom, when frames take longer than the
// budget, the strobe is drawn with fewer copies; the full strobe comes back when the gesture
// ends (idle). The reduced count is never saved: sessions store the full one. After each drawn
// frame the pose numbers (editor/labels.js) are placed again.

/** The frame budget (ms) above which a gesture draws a reduced strobe (20 frames per second). */
export const FRAME_BUDGET_MS = 50;
/** The fewest strobe copies a reduction draws. */
const MIN_REDUCED = 16;
/** A wheel zoom counts as a gesture until this long (ms) after its last event. */
const WHEEL_IDLE_MS = 400;
/** Sampling stops this long (ms) after the last drawn frame outside a gesture. */
const QUIET_MS = 1000;

/** @type {import('../app.js').Part} */
export default {
  id: 'responsive',
  create(app) {
    let sampling = false;
    let lastFrames = -1;
    let lastT = null;
    let quietSince = 0;
    let recent = [];
    let gesture = false;
    let wheelTimer = null;
    /** The full strobe count while a reduced one is drawn, else null. */
    let full = null;

    const median = (a) => [...a].sort((x, y) => x - y)[a.length >> 1];

    function reduce(interval) {
      const n = app.view.strobe;
      // Enough fewer copies to fit the budget (drawing cost ~ copies), at least 4× fewer.
      const target = Math.round((n * FRAME_BUDGET_MS) / interval / 2);
      const reduced = Math.max(MIN_REDUCED, Math.min(Math.floor(n / 4), target));
      if (reduced >= n) return;
      full = n;
      // A pose drag on the fast path holds a drag session made for the full strobe: the
      // Motion takes the dragged pose so far, and a session for the reduced strobe goes on.
      const d = app.drag;
      if (d?.session) {
        if (d.pending) app.motion.setPose(d.index, d.pose);
        d.pending = false;
        d.session.free();
        d.session = null;
        app.updateView({ strobe: reduced });
        d.session = app.viewer.drawing.dragSession();
      } else app.updateView({ strobe: reduced });
      app.viewer.rebuild();
      app.ui?.refresh();
    }

    function restore() {
      if (full === null) return;
      app.updateView({ strobe: full });
      full = null;
      // A pose drag's release rebuilds everything anyway (editor/input.js).
      if (!app.drag?.moved) app.viewer.rebuild();
      app.viewer.requestDraw();
      app.ui?.refresh();
    }

    function tick(now) {
      const f = app.viewer.frames;
      if (f !== lastFrames) {
        if (lastT !== null && f === lastFrames + 1) {
          const dt = now - lastT;
          app.viewer.stats.frameIntervalMs = dt;
          recent.push(dt);
          if (recent.length > 3) recent.shift();
          if (gesture && full === null && app.view.showStrobe && recent.length >= 2 && median(recent) > FRAME_BUDGET_MS) reduce(median(recent));
        }
        lastFrames = f;
        lastT = now;
        quietSince = now;
        app.parts.labels?.place();
      }
      if (!gesture && now - quietSince > QUIET_MS) {
        sampling = false;
        lastT = null;
        recent = [];
        return;
      }
      requestAnimationFrame(tick);
    }

    /** Measures frame intervals from now on (until frames stop). */
    function sample() {
      if (sampling) return;
      sampling = true;
      lastFrames = app.viewer.frames;
      lastT = null;
      quietSince = performance.now();
      requestAnimationFrame(tick);
    }

    function begin() {
      gesture = true;
      sample();
    }

    function end() {
      gesture = false;
      recent = [];
      restore();
    }

    return {
      /** The strobe count to save (the full one while a reduced one is drawn). */
      fullStrobe() {
        return full ?? app.view.strobe;
      },
      /** Whether a reduced strobe is drawn now. */
      get reduced() {
        return full !== null;
      },
      /** Measures frames while something draws (playback included). */
      sample,
      bind() {
        const c = app.viewer.canvas;
        c.addEventListener('pointerdown', begin);
        // Capture on the window: the full strobe is back before the editor's release handler
        // saves the session.
        window.addEventListener('pointerup', end, true);
        window.addEventListener('pointercancel', end, true);
        c.addEventListener(
          'wheel',
          () => {
            begin();
            clearTimeout(wheelTimer);
            wheelTimer = setTimeout(end, WHEEL_IDLE_MS);
          },
          { passive: true },
        );
      },
    };
  },
};
