// The playground's edits as named commands, as the three.js editor keeps them: each command
// changes the App's state through its setters and has a label, the words the Undo menu shows
// for it (editor/undo-menu.js). `runCommand(app, name, ...args)` runs one as one undo step
// (editor/session.js edit: the state before it is kept, so undo and redo restore snapshots and
// no command needs an inverse of its own). The toolbar, the keys, the panel, the timeline, the
// timing view and the lesson player all run them here, through `app.run(name, …)` (or
// `reasonOf`, where the place of the edit says why it was refused).
import { presetName } from './presets.js';


/** The scheme names as the panel shows them. */
const SCHEMES = { bspline: 'cubic B-spline', fourpoint: '4-point', jarek: 'Jarek', j: 'J_s' };

/**
 * A command: `run(app, ...args)` makes the change (throwing leaves everything as it was: the
 * edit is undone and the message shown), `label(app, ...args)` names it for the Undo menu, and
 * `merge(...args)`, where present, is a key that folds a run of the same command within a
 * second into one undo step (a slider being dragged).
 * @typedef {object} Command
 * @property {(app: import('../app.js').App, ...args: any[]) => any} run
 * @property {(app: import('../app.js').App, ...args: any[]) => string} label
 * @property {(...args: any[]) => string} [merge]
 */

/** @type {Record<string, Command>} */
export const COMMANDS = {
  loadPreset: {
    label: (app, id) => `Load the preset ${presetName(app.scenes.find((s) => s.id === id) ?? { id, name: id })}`,
    run(app, id) {
      const info = app.scenes.find((s) => s.id === id);
      if (!info) throw new Error(`unknown preset ${id}`);
      // How the preset is shown (its strobe count; the pose selected on load, as the editing
      // scene's top-left pose, ready to drag) is the core's, as in every front end.
      app.setMotion(app.wasm.Motion.fromPreset(id), info.selected ?? -1);
      app.updateView({ scene: id, object: 'scene', strobe: info.strobe });
      app.setPlayback({ u: 0, t: undefined });
      app.viewer.meshesChanged();
      app.parts.viewpoint.fit();
    },
  },
  setOption: {
    label: (app, key, value) => `Set ${key} to ${value}`,
    run: (app, key, value) => app.motion.setOptions({ [key]: value }),
    merge: (key) => `option:${key}`,
  },
  setScheme: {
    label: (app, name) => `Scheme: ${SCHEMES[name] ?? name}`,
    run: (app, name) => app.motion.setOptions({ scheme: name }),
  },
  setS: {
    label: (app, s) => `Set s to ${+s.toFixed(3)}`,
    run(app, s) {
      const named = { 1: 'bspline', 0: 'fourpoint', 0.5: 'jarek' }[s];
      app.motion.setOptions(named ? { scheme: named } : { scheme: 'j', s });
    },
    merge: () => 'option:s',
  },
  setClosed: {
    label: (app, closed) => (closed ? 'Close the cycle' : 'Open the cycle'),
    run: (app, closed) => app.motion.setClosed(closed),
  },
  setView: {
    label: (app, key, value) => (typeof value === 'boolean' ? `${value ? 'Show' : 'Hide'} ${key.replace(/^show/, '').toLowerCase() || key}` : `Display: ${key} ${value}`),
    run(app, key, value) {
      app.updateView({ [key]: value });
      if (key === 'object') app.viewer.meshesChanged();
    },
    merge: (key) => `view:${key}`,
  },
  insertPose: {
    label: (app) => `Insert a pose after pose ${app.selected >= 0 ? app.selected : app.motion.poseCount - 1}`,
    run(app) {
      const i = app.selected >= 0 ? app.selected : app.motion.poseCount - 1;
      if (!app.motion.closed && i === app.motion.poseCount - 1) {
        // Open motion: extrapolate one span past the end.
        const [, b] = app.motion.domain();
        app.select(app.motion.insertPose(i, app.motion.poseAt(b + 0.5)), false);
      } else app.select(app.motion.insertPose(i), false);
    },
  },
  deletePose: {
    label: (app) => `Delete pose ${app.selected}`,
    run(app) {
      if (app.selected < 0) throw new Error('select a pose to delete');
      if (app.motion.poseCount <= 2) throw new Error('a motion keeps at least 2 poses');
      app.motion.removePose(app.selected);
      app.select(Math.min(app.selected, app.motion.poseCount - 1), false);
    },
  },
  setPose: {
    label: (app, i, pose, key = '') => `${key.endsWith('rotate') ? 'Turn' : 'Move'} pose ${i}`,
    run: (app, i, pose) => app.motion.setPose(i, pose),
    merge: (i, pose, key = '') => (key ? `${key}:${i}` : ''),
  },
  lessonStep: {
    label: (app, step) => `Lesson: ${step.title}`,
    /**
     * What a lesson step sets of the motion and the display (www/lessons/README.md); `options`
     * are its options with the J_s parameter under its current name (lessons/format.js withS).
     */
    run(app, step, options = null) {
      if (step.document) {
        app.setMotion(new app.wasm.Motion(step.document, app.motion.options()));
        app.setPlayback({ u: 0 });
        app.parts.viewpoint.fit();
      }
      const o = options ? { ...options } : null;
      if (o) {
        if (o.closed !== undefined) app.motion.setClosed(o.closed);
        delete o.closed;
        if (o.s !== undefined && o.scheme === undefined) o.scheme = 'j';
        if (Object.keys(o).length) app.motion.setOptions(o);
      }
      if (step.display) {
        app.updateView(step.display);
        if (step.display.object !== undefined) app.viewer.meshesChanged();
      }
      if (step.timing?.times !== undefined) app.motion.setTimes(step.timing.times ?? null);
    },
  },
  loadFit: {
    label: (app, doc) => `Fit ${doc.poses.length} control poses`,
    /**
     * A motion fitted to imported samples (the full module's fitPoses, offered by the import
     * dialog, editor/reduce-dialog.js): its document, with the scheme set to `scheme` when given
     * (the fit's control poses are those of that scheme) and `mesh` (a glTF file's own object,
     * validated by the caller) as the object.
     */
    run(app, doc, scheme = null, mesh = null) {
      const motion = new app.wasm.Motion(doc, app.motion.options());
      try {
        if (scheme) motion.setOptions({ scheme });
      } catch (e) {
        motion.free();
        throw e;
      }
      showImported(app, motion, mesh);
      return true;
    },
  },
  setTimes: {
    label: (app, times) => (times ? 'Retime the keys' : 'Uniform timing'),
    /**
     * The key times in seconds (null: uniform), as motion.setTimes checks them; `key` names a
     * run of edits that folds into one undo step (a key marker nudged by the arrow keys).
     */
    run: (app, times) => app.motion.setTimes(times),
    merge: (times, key = '') => key,
  },
  setVelocities: {
    label: (app, velocities) => (velocities ? 'Set the key velocities' : 'Free the key velocities'),
    /** The key velocities p'(T_i) in poses per second (null entries, or null: free). */
    run: (app, velocities) => app.motion.setVelocities(velocities),
  },
  openSession: {
    label: (app, s, what = 'kept work') => `Open ${what}`,
    run: (app, s) => app.parts.session.applySession({ ...s, camera: undefined }),
  },
};

/**
 * Makes an imported `motion` the app's, with `mesh` ({kind, data}: a glTF file's own object,
 * validated by the caller) as the object when given, and frames its poses.
 * @param {import('../app.js').App} app
 * @param {any} motion
 * @param {any} [mesh]
 */
export function showImported(app, motion, mesh = null) {
  app.setMotion(motion);
  if (mesh) {
    app.setImported(mesh);
    app.updateView({ object: 'obj' });
    app.viewer.meshesChanged();
  }
  app.parts.viewpoint.fit();
}

/** The Undo menu's words for command `name` with `args` (its name where the label fails). */
function labelOf(app, name, args) {
  try {
    return COMMANDS[name].label(app, ...args);
  } catch {
    return name;
  }
}

/**
 * Runs command `name` with `args` as one undo step labelled for the Undo menu; its result, or
 * undefined when it failed (the banner says why, nothing changed).
 * @param {import('../app.js').App} app
 * @param {string} name a key of COMMANDS
 * @param {...any} args
 */
export function runCommand(app, name, ...args) {
  const c = COMMANDS[name];
  if (!c) throw new Error(`unknown command ${name}`);
  return app.parts.session.edit(() => c.run(app, ...args), c.merge?.(...args) || null, labelOf(app, name, args));
}

/**
 * Runs command `name` with `args` as one undo step, without the banner: null when done, else
 * the reason it was refused (nothing changed), which the caller shows where the edit was made
 * (the timing view, the key markers).
 * @param {import('../app.js').App} app
 * @param {string} name a key of COMMANDS
 * @param {...any} args
 * @returns {string | null}
 */
export function reasonOf(app, name, ...args) {
  const c = COMMANDS[name];
  if (!c) throw new Error(`unknown command ${name}`);
  const session = app.parts.session;
  const before = session.snapshot();
  try {
    c.run(app, ...args);
  } catch (e) {
    return e.message;
  }
  session.record(before, c.merge?.(...args) || null, performance.now(), labelOf(app, name, args));
  app.changed();
  return null;
}

/** As runCommand, but a failure is thrown on to the caller as well (the lesson player names the step). */
export function tryCommand(app, name, ...args) {
  const c = COMMANDS[name];
  if (!c) throw new Error(`unknown command ${name}`);
  let failure = null;
  const run = () => {
    try {
      return c.run(app, ...args);
    } catch (e) {
      failure = e;
      throw e;
    }
  };
  const r = app.parts.session.edit(run, c.merge?.(...args) || null, labelOf(app, name, args));
  if (failure) throw failure;
  return r;
}
