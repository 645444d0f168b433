// The editing of an editable figure (`editable`): its pointer tool, the selection and the
// events `select` and `change`. Turning editing on or off gives the figure a fresh canvas
// (figure.js), since the pointer listeners live on the canvas.
import { beginPoseDrag, dragTarget, hoverPoseTool, redrawPoseDrag, setDragPose } from '../figure/pose-drag.js';
import { describePose } from './description.js';
import { bool } from './options.js';

/** @type {import('./options.js').Feature} */
export const editingFeature = {
  name: 'editing',
  doc: 'Selecting and dragging poses.',
  options: [
    {
      name: 'editable', type: 'boolean', default: false, parse: bool,
      doc: 'Select and drag poses with the gizmo (off: orbit, play and scrub only).', python: { default: true },
    },
  ],
  events: [
    {
      name: 'change', doc: 'A pose of an editable figure was moved: every control pose (7 numbers each) and the pose edited.',
      detail: {
        type: 'ChangeDetail', doc: 'The detail of `change`: every control pose (7 numbers each) and the pose edited.',
        fields: { poses: 'Float64Array', index: 'number' },
      },
    },
    {
      name: 'select', doc: 'A control pose was selected (-1: none).',
      detail: { type: 'SelectDetail', doc: 'The detail of `select`: the selected control pose, -1 for none.', fields: { index: 'number' } },
    },
  ],
  apply(fig, v) {
    if (!v.editable && fig.model.selected >= 0) fig.model.selected = -1;
  },
};

/**
 * The pointer tool of an editable figure `fig`: select a pose, drag it with the gizmo (the
 * steps shared with the playground's editor are figure/pose-drag.js); a drag that moved the pose
 * saves it (`persist`) and fires `change`.
 */
export function editTool(fig) {
  const v = () => fig.viewer;
  const begin = (part, pt, e) => {
    const { model } = fig;
    const d = beginPoseDrag(v(), model.motion, model.selected, part, pt, e);
    if (!d) return false;
    model.drag = { part };
    fig.drag = d;
    v().rebuildGizmo();
    return true;
  };
  const end = () => {
    const d = fig.drag;
    if (!d) return;
    fig.drag = null;
    fig.model.drag = null;
    d.session?.free();
    if (d.moved) {
      fig.viewer.rebuild();
      fig.persist();
      fig.say(describePose(fig.model.motion, d.index).replace(' at ', ' moved to '));
      fig.emit('change', { poses: Float64Array.from(fig.model.motion.poses()), index: d.index });
    }
    fig.viewer.rebuildGizmo();
    fig.viewer.requestDraw();
  };
  return {
    press: (pt, e) =>
      fig.guardNow(() => {
        const part = v().gizmoHit(pt);
        if (part && begin(part, pt, e)) return 'drag';
        const k = v().pickPose(pt);
        if (k < 0) return null;
        if (k !== fig.model.selected) fig.select(k);
        return begin('view', pt, e) ? 'drag' : 'taken';
      }, 'taken'),
    drag: (pt, e) =>
      fig.guard(() => {
        const d = fig.drag;
        if (!d) return;
        const pose = dragTarget(v(), d, pt, e.shiftKey);
        if (!pose) return;
        const fast = setDragPose(fig.model.motion, d, pose, { polyscrew: fig.model.view.showPolyscrew, live: true });
        d.moved = true;
        redrawPoseDrag(v(), d, pose, fast);
      }),
    release: () => fig.guard(end),
    cancel: () => fig.guard(end),
    hover: (pt) => fig.guardNow(() => hoverPoseTool(v(), fig.model, pt)),
    click: () =>
      fig.guardNow(() => {
        if (fig.model.selected >= 0) fig.select(-1);
      }),
  };
}
