// The highlight of a lesson step: a ring around a control, a panel entry, a pose's handle or a
// gizmo handle, followed every frame while the step shows it, and the placement of the lesson
// card so that it does not cover what the ring points at.
import { el } from './dom.js';

/**
 * Creates the highlight ring (#lesson-spot) of the lesson `card` of `app`. Returns
 * {set(h), place(), spot(), target}: `set` points it at step highlight `h` (null: none),
 * `place` places ring and card again now, `spot` tells where the ring is.
 */
export function createHighlight(app, card) {
  const spotEl = el('div');
  spotEl.id = 'lesson-spot';
  spotEl.hidden = true;
  document.body.append(spotEl);

  let target = null;
  let raf = 0;

  function set(h) {
    target = h;
    if (h?.panel) {
      const c = app.ui.gui.controllersRecursive().find((k) => k._name === h.panel);
      app.ui.gui.open();
      c?.parent.open();
    }
    cancelAnimationFrame(raf);
    // Placed now (layout is current) and then every frame while it lasts.
    if (h) place();
    else {
      spotEl.hidden = true;
      placeCard(null);
    }
  }

  /** Where the highlight goes this frame: {x, y, w, h} in page px, or null. */
  function targetRect() {
    if (!target) return null;
    if (target.control || target.panel) {
      const node = target.control ? document.querySelector(target.control) : app.ui.gui.controllersRecursive().find((k) => k._name === target.panel)?.domElement;
      if (!node) return null;
      const r = node.getBoundingClientRect();
      if (r.width === 0 && r.height === 0) return null;
      return { x: r.left - 4, y: r.top - 4, w: r.width + 8, h: r.height + 8 };
    }
    let p = null;
    try {
      if (target.pose !== undefined && target.pose < app.motion.poseCount) p = app.screenOfPose(target.pose);
      if (target.gizmo !== undefined && app.selected >= 0) p = app.screenOfGizmo(target.gizmo);
    } catch {
      p = null;
    }
    if (!p || !Number.isFinite(p.x) || !Number.isFinite(p.y)) return null;
    return { x: p.x - 24, y: p.y - 24, w: 48, h: 48, round: true };
  }

  /**
   * Keeps the target visible. Phones (lessons.css): the card sits at the top, or at the bottom
   * while the target is in the top half. Wider screens: the first of bottom right (the CSS
   * place), top right, and bottom left of the target that does not cover it.
   */
  function placeCard(r) {
    const phone = window.matchMedia('(max-width: 760px)').matches;
    card.classList.toggle('low', !!r && phone && r.y + r.h / 2 < window.innerHeight / 2);
    let pos = { right: '', top: '', bottom: '' };
    if (r && !phone) {
      const W = card.offsetWidth;
      const H = card.offsetHeight;
      const iw = window.innerWidth;
      const ih = window.innerHeight;
      const hits = (x0, y0) => r.x < x0 + W + 8 && r.x + r.w > x0 - 8 && r.y < y0 + H + 8 && r.y + r.h > y0 - 8;
      const candidates = [
        [iw - 12 - W, ih - 70 - H, pos],
        [iw - 12 - W, 12, { right: '', top: '12px', bottom: 'auto' }],
        [r.x - 16 - W, ih - 70 - H, { right: `${iw - r.x + 16}px`, top: '', bottom: '' }],
      ];
      const ok = candidates.find(([x0, y0]) => x0 >= 0 && y0 >= 0 && !hits(x0, y0));
      if (ok) pos = ok[2];
    }
    card.style.right = pos.right;
    card.style.top = pos.top;
    card.style.bottom = pos.bottom;
  }

  function place() {
    const r = targetRect();
    spotEl.hidden = !r;
    placeCard(r);
    if (r) {
      spotEl.style.left = `${r.x}px`;
      spotEl.style.top = `${r.y}px`;
      spotEl.style.width = `${r.w}px`;
      spotEl.style.height = `${r.h}px`;
      spotEl.classList.toggle('round', !!r.round);
    }
    // One loop at a time: `place` is also called from outside (a resize, a new step).
    cancelAnimationFrame(raf);
    if (target) raf = requestAnimationFrame(place);
  }

  return {
    set,
    place,
    spot() {
      if (spotEl.hidden) return null;
      const r = spotEl.getBoundingClientRect();
      return { x: r.left, y: r.top, w: r.width, h: r.height };
    },
    get target() {
      return target;
    },
  };
}
