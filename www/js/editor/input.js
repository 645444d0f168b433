// Editing with the pointer and the keyboard. The viewer turns the camera itself (figure/pointer.js);
// this part is its `tool`: a press on a handle selects the pose, a press on a gizmo part (or a
// handle) drags the pose, hovering highlights what a press would grab. Keys are the editor's
// shortcuts (listed in the help overlay of index.html); they act only while the canvas or the
// page itself has the focus, never inside a control. The part contract is in app.js.
import { qaxis, qmul, qnormalize } from '../math.js';
import { SNAP_ROTATE, SNAP_TRANSLATE, gizmoAxes } from '../figure/gizmo.js';
import { pickPoses } from '../figure/picking.js';
import { beginPoseDrag, dragTarget, hoverPoseTool, redrawPoseDrag, setDragPose } from '../figure/pose-drag.js';

/** @type {import('../app.js').Part} */
export default {
  id: 'input',
  create(app) {
    function beginDrag(part, pt, e) {
      const d = beginPoseDrag(app.viewer, app.motion, app.selected, part, pt, e);
      if (!d) return false;
      app.drag = Object.assign(d, { before: app.parts.session.snapshot() });
      app.viewer.rebuildGizmo();
      return true;
    }

    function dragMove(pt, snapOn) {
      const d = app.drag;
      const pose = dragTarget(app.viewer, d, pt, snapOn || app.view.snap);
      if (!pose) return;
      applyDragPose(d.index, pose);
    }

    /**
     * One drag step. With a drag session, the pose goes only into the session (validated
     * there); the Motion (the document) receives the final pose on release, so a step costs
     * only the local update. Without one, or with the polyscrew shown (it is rebuilt in full),
     * the Motion is updated and everything rebuilt.
     */
    function applyDragPose(index, pose) {
      const d = app.drag;
      const t0 = performance.now();
      let fast;
      try {
        // Views that follow drags read the Motion: give it the pose now, not only on release.
        fast = setDragPose(app.motion, d, pose, { polyscrew: app.view.showPolyscrew, live: !!app.dock?.wantsLive });
      } catch (err) {
        app.parts.notices.show(err.message);
        return;
      }
      d.pose = pose;
      if (!d.moved) {
        // The undo step is recorded by the first move, so a click on a handle is no edit.
        app.history.push(d.before, `Drag pose ${d.index}`);
        d.moved = true;
      }
      if (fast) d.pending = true;
      redrawPoseDrag(app.viewer, d, pose, fast);
      app.dock?.changed('drag');
      app.viewer.stats.dragMs = performance.now() - t0;
    }

    function endDrag() {
      if (app.drag?.pending) app.motion.setPose(app.drag.index, app.drag.pose);
      if (app.drag?.moved) {
        app.viewer.rebuild();
        app.parts.session.autosave();
        // Views that do not follow drags catch up now.
        app.dock?.changed('edit');
      }
      app.drag?.session?.free();
      // The plane shown for a handle drag goes back to what the pointer hovers (on touch: nothing).
      if (app.drag && app.hover === app.drag.part && app.drag.part.startsWith('plane-') && app.drag.fromHandle) app.hover = null;
      app.drag = null;
      app.viewer.rebuildGizmo();
      app.viewer.requestDraw();
      app.ui?.refresh();
    }

    /**
     * The gizmo plane a handle drag of the selected pose moves in: the one facing the camera
     * most (its normal closest to the view direction; world planes, or the pose's own with the
     * gizmo in local axes), so the pose never changes depth silently; the drag highlights that
     * plane's square of the gizmo.
     */
    function facingPlane() {
      const f = app.viewer.camera.forward;
      const axes = gizmoAxes(!!app.view.gizmoLocal, app.motion.pose(app.selected).rotation);
      const along = (k) => Math.abs(f[0] * axes[k][0] + f[1] * axes[k][1] + f[2] * axes[k][2]);
      let best = 0;
      for (let k = 1; k < 3; k++) if (along(k) > along(best)) best = k;
      return `plane-${'xyz'[best]}`;
    }

    /** Where the last press on handles was and what it hit (repeated presses cycle). */
    let lastPress = null;

    const tool = {
      press(pt, e) {
        const hits = pickPoses(app.viewer, pt);
        // Handles that overlap on the screen (poses sharing an origin): a press again at the
        // same place selects the next of them.
        const again = lastPress && Math.hypot(pt[0] - lastPress.pt[0], pt[1] - lastPress.pt[1]) < 4 && hits.length > 1 && hits.includes(app.selected);
        lastPress = hits.length ? { pt } : null;
        if (again) {
          app.select(hits[(hits.indexOf(app.selected) + 1) % hits.length]);
          if (!beginDrag(facingPlane(), pt, e)) return 'taken';
          app.drag.fromHandle = true;
          return 'drag';
        }
        const part = app.viewer.gizmoHit(pt);
        if (part && beginDrag(part, pt, e)) return 'drag';
        if (!hits.length) return null;
        // Of overlapping handles, the selected one stays selected (the next press cycles).
        const k = hits.includes(app.selected) ? app.selected : hits[0];
        if (k !== app.selected) app.select(k);
        // A handle dragged right away moves its pose in the world plane facing the view.
        const plane = facingPlane();
        if (!beginDrag(plane, pt, e)) return 'taken';
        app.hover = plane;
        app.drag.fromHandle = true;
        app.viewer.rebuildGizmo();
        return 'drag';
      },
      drag(pt, e) {
        if (app.drag) dragMove(pt, e.shiftKey);
      },
      release: endDrag,
      cancel() {
        if (app.drag) endDrag();
      },
      hover(pt) {
        hoverPoseTool(app.viewer, app, pt);
      },
      click() {
        // A click on empty space deselects.
        if (app.selected >= 0) app.select(-1);
      },
    };

    /**
     * Where the page's shortcuts act: the canvas, or the page itself (nothing focused). Inside
     * a control (button, field, slider, the panel, the dock) keys keep their own meaning.
     */
    function shortcutTarget(t) {
      return !t || t === app.viewer.canvas || t === document.body || t === document.documentElement;
    }

    /**
     * Moves (or with `rotate`, turns) the selected pose by one keyboard step along or about the
     * world axis `axis` (0, 1, 2) in direction `sign`: 0.25 units or 15° (the snapping steps),
     * a tenth of that with `fine`. Presses within a second make one undo step.
     */
    function nudge(axis, sign, rotate, fine) {
      const i = app.selected;
      if (i < 0) return;
      const pose = app.motion.pose(i);
      const f = fine ? 0.1 : 1;
      // Along (about) the gizmo's axis: the world's, or the pose's own in local axes.
      const a = gizmoAxes(!!app.view.gizmoLocal, pose.rotation)[axis];
      let next;
      if (rotate) {
        const dq = qaxis(a, sign * f * SNAP_ROTATE);
        next = { origin: [...pose.origin], rotation: qnormalize(qmul(dq, pose.rotation)) };
      } else {
        const step = sign * f * SNAP_TRANSLATE;
        next = { origin: pose.origin.map((x, k) => x + step * a[k]), rotation: [...pose.rotation] };
      }
      app.run('setPose', i, next, `key:${rotate ? 'rotate' : 'move'}`);
    }

    /** Arrow keys and PageUp / PageDown: [gizmo axis, direction]. */
    const NUDGE = {
      ArrowRight: [0, 1], ArrowLeft: [0, -1], ArrowUp: [1, 1], ArrowDown: [1, -1], PageUp: [2, 1], PageDown: [2, -1],
    };

    function onKey(e) {
      const t = e.target;
      if (!shortcutTarget(t)) {
        // Esc still closes the help overlay from a control inside it.
        if (e.key === 'Escape' && !document.getElementById('help').hidden) {
          app.ui.toggleHelp(false);
          e.preventDefault();
        }
        return;
      }
      const k = e.key;
      const mod = e.ctrlKey || e.metaKey;
      const count = app.motion.poseCount;
      let handled = true;
      if (mod && (k === 'z' || k === 'Z')) e.shiftKey ? app.parts.session.redo() : app.parts.session.undo();
      else if (mod && (k === 'y' || k === 'Y')) app.parts.session.redo();
      else if (mod) handled = false;
      else if (NUDGE[k] && app.selected >= 0) {
        const [axis, sign] = NUDGE[k];
        nudge(axis, sign, e.altKey || app.mode === 'rotate', e.shiftKey);
      } else if (k === 'ArrowRight' || k === 'n') app.select((app.selected + 1) % count);
      else if (k === 'ArrowLeft' || k === 'p') app.select(app.selected <= 0 ? count - 1 : app.selected - 1);
      else if (e.altKey) handled = false;
      else if (k >= '0' && k <= '8') app.run('setOption', 'levels', Number(k));
      else if (k === 'b') app.run('setScheme', 'bspline');
      else if (k === 'f') app.run('setScheme', 'fourpoint');
      else if (k === 'j') app.run('setScheme', 'jarek');
      else if (k === 'w' || k === 'W') app.setMode('translate');
      else if (k === 'e' || k === 'E') app.setMode('rotate');
      else if (k === 'q' || k === 'Q') app.run('setView', 'gizmoLocal', !app.view.gizmoLocal);
      else if (k === ' ') app.viewer.setPlaying(!app.anim.playing);
      else if (k === 'Delete' || k === 'Backspace') {
        if (app.selected >= 0) app.run('deletePose');
      } else if (k === 'Insert' || k === 'i') app.run('insertPose');
      else if (k === 'a' || k === 'Home') app.parts.viewpoint.frame();
      else if (k === 'Escape') {
        if (!document.getElementById('help').hidden) app.ui.toggleHelp(false);
        else app.select(-1);
      } else if (k === '?' || k === 'h') app.ui.toggleHelp();
      // The toolbar button knows which view to reopen.
      else if (k === 'v' || k === 'V') document.getElementById('t-dock').click();
      else handled = false;
      if (handled) e.preventDefault();
    }

    return {
      /** Binds the pointer (through the viewer) and the keyboard (once the page runs). */
      bind() {
        app.viewer.bindPointer(tool);
        window.addEventListener('keydown', onKey);
      },
    };
  },
};
