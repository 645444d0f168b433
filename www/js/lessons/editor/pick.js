// Pointing a step's highlight by clicking what it should point at: the next press on the page
// names it — a gizmo part of the selected pose or a pose's handle in the 3-D view (the view's own
// picking, figure/picking.js), a control of the panel by its label, or any other page element by
// its id — instead of being pressed. Esc, or a press on the editor itself, cancels.
import { gizmoHit, local, pickPose } from '../../figure/picking.js';

/**
 * What a press at event `e` points at, as a step's highlight ({gizmo}, {pose}, {panel},
 * {control}), or null.
 * @param {import('../../app.js').App} app
 * @param {PointerEvent} e
 */
export function targetOf(app, e) {
  const t = /** @type {Element} */ (e.target);
  if (t === app.viewer.canvas || t?.id === 'view') {
    const pt = local(app.viewer, e);
    const part = gizmoHit(app.viewer, pt);
    if (part && part !== 'view') return { gizmo: part };
    const k = pickPose(app.viewer, pt);
    return k >= 0 ? { pose: k } : null;
  }
  if (t?.closest?.('#panel')) {
    const c = app.ui.gui.controllersRecursive().find((k) => k.domElement.contains(t));
    if (c) return { panel: c._name };
  }
  const withId = t?.closest?.('[id]');
  if (withId && /^[A-Za-z][\w-]*$/.test(withId.id) && withId !== document.body) return { control: `#${withId.id}` };
  return null;
}

/**
 * Waits for the next press on the page and calls `done(target)` with what it points at (null:
 * nothing there, or cancelled). The press does nothing else. `editor` is the editor's element
 * (a press there cancels). Returns cancel().
 * @param {import('../../app.js').App} app
 */
export function pickTarget(app, editor, done) {
  document.body.classList.add('le-picking');
  const swallow = (e) => {
    e.preventDefault();
    e.stopImmediatePropagation();
  };
  const finish = (target) => {
    window.removeEventListener('pointerdown', onDown, true);
    window.removeEventListener('keydown', onKey, true);
    document.body.classList.remove('le-picking');
    // The click that ends this press must not press the control either.
    window.addEventListener('click', swallow, { capture: true, once: true });
    setTimeout(() => window.removeEventListener('click', swallow, true), 400);
    done(target);
  };
  function onDown(e) {
    if (editor.contains(/** @type {Node} */ (e.target))) {
      window.removeEventListener('pointerdown', onDown, true);
      window.removeEventListener('keydown', onKey, true);
      document.body.classList.remove('le-picking');
      done(null);
      return;
    }
    swallow(e);
    finish(targetOf(app, e));
  }
  function onKey(e) {
    if (e.key !== 'Escape') return;
    swallow(e);
    window.removeEventListener('pointerdown', onDown, true);
    window.removeEventListener('keydown', onKey, true);
    document.body.classList.remove('le-picking');
    done(null);
  }
  window.addEventListener('pointerdown', onDown, true);
  window.addEventListener('keydown', onKey, true);
  return () => onKey(new KeyboardEvent('keydown', { key: 'Escape' }));
}
