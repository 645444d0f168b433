// The session: everything the page restores — the motion document and options, the display
// settings, the selection, the playback and the camera. Undo/redo keeps snapshots of it, the
// autosave keeps it as this tab's draft (editor/drafts.js), share links carry it in the URL hash.
//
// The pure helpers (History, storage) come first (the hash coding is ../share-link.js); the part (default export, see
// app.js for the part contract) applies sessions to the app and records its edits.
import { SLOT } from '../figure/slots.js';
import { SESSION_VERSION, decodeHash, encodeHash } from '../share-link.js';
import { COMMANDS } from './commands.js';
import { DEFAULT_SCENE, presetName } from './presets.js';
/** Undo steps kept. */
export const MAX_UNDO = 200;

/**
 * One undo or redo step: the state to go back to and the words naming the edit (the Undo menu,
 * editor/undo-menu.js).
 * @typedef {{snapshot: string, label: string}} Step
 */

/** What an edit without a name of its own is called in the Undo menu. */
export const UNNAMED_EDIT = 'Edit';

/** Undo/redo over serialized snapshots (strings), each step labelled. */
export class History {
  constructor() {
    /** @type {Step[]} */
    this.undoStack = [];
    /** @type {Step[]} */
    this.redoStack = [];
    /** Counts the changes of the stacks (push, undo, redo): an edit merges into the last step only if none came between. */
    this.version = 0;
  }
  /** Records `snapshot` (the state *before* an edit) as the step that undoes the edit `label`. */
  push(snapshot, label = UNNAMED_EDIT) {
    const top = this.undoStack[this.undoStack.length - 1];
    // The edit before changed nothing: its step now undoes this one (and takes its name).
    if (top?.snapshot === snapshot) {
      top.label = label;
      return;
    }
    this.undoStack.push({ snapshot, label });
    if (this.undoStack.length > MAX_UNDO) this.undoStack.shift();
    this.redoStack.length = 0;
    this.version++;
  }
  /** Returns the snapshot to restore, given the current one, or null. */
  undo(current) {
    const s = this.undoStack.pop();
    if (s === undefined) return null;
    this.redoStack.push({ snapshot: current, label: s.label });
    this.version++;
    return s.snapshot;
  }
  redo(current) {
    const s = this.redoStack.pop();
    if (s === undefined) return null;
    this.undoStack.push({ snapshot: current, label: s.label });
    this.version++;
    return s.snapshot;
  }
  get canUndo() {
    return this.undoStack.length > 0;
  }
  get canRedo() {
    return this.redoStack.length > 0;
  }
  /** The labels of the edits Undo takes back, the next first. */
  get undoLabels() {
    return this.undoStack.map((s) => s.label).reverse();
  }
  /** The labels of the edits Redo makes again, the next first. */
  get redoLabels() {
    return this.redoStack.map((s) => s.label).reverse();
  }
}

/** Edits with the same coalesce key closer than this (ms) make one undo step. */
export const MERGE_IDLE_MS = 1000;

/** The largest strobe count (instances of the object along the motion) a session may ask for. */
export const MAX_STROBE = 20000;
/** Imported meshes up to this size are kept in the autosave and share links. */
export const MAX_SAVED_MESH = 1 << 20;

/** @type {import('../app.js').Part} */
export default {
  id: 'session',
  create(app) {
    let lastEdit = null;

    /**
     * Records `before` (the state before an edit just made) as an undo step — unless the edit
     * continues the last one: the same `coalesce` key, less than MERGE_IDLE_MS after it (at
     * `now`, ms on performance.now()'s clock, e.g. an event's timeStamp), and no other step, undo
     * or redo in between; the step recorded then already holds the state before the whole run.
     * `label` names the edit in the Undo menu.
     */
    function record(before, coalesce = null, now = performance.now(), label = UNNAMED_EDIT) {
      const merge =
        coalesce !== null && coalesce === lastEdit?.key && now - lastEdit.time < MERGE_IDLE_MS && lastEdit.version === app.history.version;
      if (!merge) app.history.push(before, label);
      lastEdit = { key: coalesce, time: now, version: app.history.version };
    }

    /** The serializable session (what autosave, share links and undo store). */
    function session(withCamera = true) {
      const s = {
        version: SESSION_VERSION,
        document: app.motion.toDocument(),
        options: app.motion.options(),
        // A strobe reduced during a gesture (editor/responsive.js) is saved at its full count.
        view: { ...app.view, strobe: app.parts.responsive?.fullStrobe() ?? app.view.strobe },
        selected: app.selected,
        mode: app.mode,
        anim: { u: app.anim.u, speed: app.anim.speed, loop: app.anim.loop },
      };
      if (app.imported && app.imported.data.length <= MAX_SAVED_MESH) s.mesh = app.imported;
      if (withCamera) s.camera = app.viewer.camera.toJSON();
      return s;
    }

    /** Replaces the whole state by a session; throws (leaving everything as it was) if invalid. */
    function applySession(s) {
      if (!s || typeof s !== 'object') throw new Error('not a session object');
      const motion = new app.wasm.Motion(s.document, s.options); // validates everything
      if (s.mesh) {
        app.viewer.setImportedMesh(SLOT.strobe, s.mesh); // validates the mesh
        app.setImported(s.mesh);
      }
      app.setMotion(motion);
      const v = s.view ?? {};
      const patch = {};
      for (const k of Object.keys(app.view)) {
        // Undo and imports do not switch the open analysis view (only the initial restore does).
        if (k === 'dock' && app.ready) continue;
        if (k in v && typeof v[k] === typeof app.view[k]) patch[k] = v[k];
      }
      patch.strobe = Math.max(1, Math.min(MAX_STROBE, Math.round(patch.strobe ?? app.view.strobe)));
      app.updateView(patch);
      // Older sessions kept the key times in view.times: they move into the motion when its
      // document has none and they fit (as before, times that do not fit are ignored).
      const t = v.times;
      if (motion.times === undefined && Array.isArray(t) && t.length <= 1e5) {
        try {
          motion.setTimes(t);
        } catch {
          // Ignored, as the page did before: uniform timing.
        }
      }
      if (app.view.object === 'obj' && !app.imported) app.updateView({ object: 'scene' });
      app.select(Number.isInteger(s.selected) && s.selected < motion.poseCount ? s.selected : -1, false);
      app.setMode(s.mode, false);
      if (s.anim) {
        const a = {};
        if (Number.isFinite(s.anim.u)) a.u = s.anim.u;
        if (Number.isFinite(s.anim.speed)) a.speed = s.anim.speed;
        if (typeof s.anim.loop === 'boolean') a.loop = s.anim.loop;
        app.setPlayback(a);
      }
      if (s.camera) app.viewer.camera.load(s.camera);
      else app.parts.viewpoint.fit();
      app.viewer.meshesChanged();
      app.changed(false);
    }

    /**
     * A share link (`#s=…`) given to the open page: pasted into the address bar of a tab that
     * shows the playground, only the address's hash changes, and the browser does not load the
     * page again. Opened as one undoable edit (Ctrl+Z brings back what was there) with the
     * link's camera; the hash then leaves the address, as at load. A bad link says why in the
     * words of a load and changes nothing. Returns true when the link was opened.
     */
    function openLinked() {
      const hash = location.hash.match(/^#s=(.+)$/);
      if (!hash) return false;
      history.replaceState(history.state, '', location.pathname + location.search);
      const open = () => {
        try {
          applySession(decodeHash(hash[1]));
        } catch (e) {
          throw new Error(`The shared link could not be opened: ${e.message}`);
        }
        return true;
      };
      if (app.parts.session.edit(open, null, 'Open the shared link') !== true) return false;
      app.ui?.refresh();
      app.ui?.toast('Opened the shared link (Undo brings back what was shown)');
      return true;
    }

    /** A snapshot for undo (no camera: undo does not move the view). */
    function snapshot() {
      return JSON.stringify(session(false));
    }

    function restoreSnapshot(text) {
      const cam = app.viewer.camera.toJSON();
      applySession({ ...JSON.parse(text), camera: cam });
      app.ui?.refresh();
    }

    function autosave() {
      if (app.motion) app.parts.drafts.save(session());
    }

    return {
      session,
      applySession,
      snapshot,
      autosave,

      /**
       * Saves after every change of the motion or the display that asks for it; opens a share
       * link that arrives while the page is open (openLinked).
       */
      bind() {
        app.on('motion', (d) => d?.save !== false && autosave());
        window.addEventListener('hashchange', () => openLinked());
      },

      openLinked,

      /**
       * Shows preset `id` without an undo step (the first scene of a visit, a test's start; the
       * loadPreset command is the undoable pick); a failure is shown and changes nothing.
       */
      openPreset(id) {
        try {
          COMMANDS.loadPreset.run(app, id);
        } catch (e) {
          return app.parts.notices.show(e.message);
        }
        app.changed();
      },

      /**
       * The first motion: share link (#s=) > `?preset=<id>` > autosave > default preset. A linked
       * preset over an autosaved session is one undoable edit, as a pick in the Presets menu is
       * (Ctrl+Z brings the session back); an unknown id says so and the page opens as it would
       * without it. The parameter then leaves the address, so a reload keeps the edits made since
       * instead of loading the preset afresh.
       * @param {URLSearchParams} params
       */
      openInitial(params) {
        const restored = this.restoreInitial();
        const linked = restored === 'link' ? null : params.get('preset');
        const known = linked !== null && app.scenes.some((s) => s.id === linked);
        if (known && restored) app.run('loadPreset', linked);
        else if (!restored) this.openPreset(known ? linked : DEFAULT_SCENE);
        if (linked !== null && !known) {
          const shown = restored ? 'the last session is shown' : `showing ${presetName(app.viewer.drawing.sceneInfo)}`;
          app.parts.notices.show(`The link asks for preset "${linked}", which does not exist (the Presets menu lists them); ${shown}.`, 'warn');
        }
        if (params.has('preset')) {
          const url = new URL(location.href);
          url.searchParams.delete('preset');
          history.replaceState(history.state, '', url.href);
        }
      },

      /**
       * Share link > autosave (this tab's draft, else the latest of any tab): applies the first
       * that works and says which ('link' or 'saved'); '' when neither is there (or both failed,
       * with a message each), so the caller loads a preset.
       * @returns {'link' | 'saved' | ''}
       */
      restoreInitial() {
        const hash = location.hash.match(/^#s=(.+)$/);
        if (hash) {
          try {
            applySession(decodeHash(hash[1]));
            history.replaceState(null, '', location.pathname + location.search);
            autosave();
            return 'link';
          } catch (e) {
            app.parts.notices.show(`The shared link could not be opened: ${e.message}`);
          }
        }
        const saved = app.parts.drafts.latest();
        if (saved) {
          try {
            applySession(saved);
            return 'saved';
          } catch (e) {
            app.parts.notices.show(`The autosaved session could not be restored: ${e.message}`);
          }
        }
        return '';
      },

      /** Records the current state before an edit named `label`. */
      beginEdit(label = UNNAMED_EDIT) {
        app.history.push(snapshot(), label);
      },

      record,

      /**
       * Runs `f` as one undoable edit; errors go to the banner and leave the state unchanged.
       * Edits with the same `coalesce` key less than a second apart (a slider being dragged)
       * make one undo step (see record); `label` names it in the Undo menu (editor/commands.js
       * runs every named edit through here).
       */
      edit(f, coalesce = null, label = UNNAMED_EDIT) {
        const before = snapshot();
        try {
          const r = f();
          record(before, coalesce, performance.now(), label);
          app.changed();
          return r;
        } catch (e) {
          app.parts.notices.show(e.message);
          return undefined;
        }
      },

      undo() {
        const s = app.history.undo(snapshot());
        if (s) restoreSnapshot(s);
      },

      redo() {
        const s = app.history.redo(snapshot());
        if (s) restoreSnapshot(s);
      },

      shareLink() {
        return `${location.origin}${location.pathname}${location.search}#s=${encodeHash(session())}`;
      },
    };
  },
};
