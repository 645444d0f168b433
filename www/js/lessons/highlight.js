// The highlight of a lesson step: a ring around a control, a panel entry, a pose's handle or a
// gizmo handle, followed every frame while the step shows it, and the placement of the lesson
// card so that it does not cover what the ring points at.
import { el } from './dom.js';
import { foldPanelOnSmallScreens } from '../editor/fold.js';

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

  /** Whether a step's highlight opened the panel (a later step folds it again on phones). */
  let openedPanel = false;

  function set(h) {
    target = h;
    if (h?.panel) {
      const c = app.ui.gui.controllersRecursive().find((k) => k._name === h.panel);
      if (app.ui.gui._closed) openedPanel = true;
      app.ui.gui.open();
      c?.parent.open();
    } else if (openedPanel) {
      // Phones: the panel the last step pointed into would cover the 3-D view of this one.
      openedPanel = false;
      foldPanelOnSmallScreens(app);
    }
    cancelAnimationFrame(raf);
    // Placed now (layout is current) and then every frame while it lasts.
    lastKey = '';
    if (h || !card.hidden) place();
    else spotEl.hidden = true;
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

  /** The page rect of element `sel` if it is shown, else null. */
  function rectOf(sel) {
    const e = typeof sel === 'string' ? document.querySelector(sel) : sel;
    // (offsetParent is null for any fixed element: the size tells whether it is shown.)
    if (!e || e.hidden) return null;
    const r = e.getBoundingClientRect();
    return r.width > 0 && r.height > 0 ? { x: r.left, y: r.top, w: r.width, h: r.height } : null;
  }

  /** What the card must not cover (hard) and should not (soft), this frame. */
  function obstacles(r) {
    const hard = [];
    const soft = [];
    if (r) hard.push(r);
    const dock = rectOf('#dock.open');
    if (dock) hard.push(dock);
    // The selected pose's handle and the poses themselves: the subject of most steps.
    const pts = [];
    try {
      for (let k = 0; k < app.motion.poseCount; k++) {
        const p = app.screenOfPose(k);
        if (p && Number.isFinite(p.x) && Number.isFinite(p.y)) {
          pts.push(p);
          if (k === app.selected) hard.push({ x: p.x - 28, y: p.y - 28, w: 56, h: 56 });
        }
      }
    } catch {
      // No view yet: nothing to keep clear of.
    }
    if (pts.length) {
      const xs = pts.map((p) => p.x);
      const ys = pts.map((p) => p.y);
      const pad = 40;
      const x0 = Math.min(...xs) - pad;
      const y0 = Math.min(...ys) - pad;
      soft.push({ x: x0, y: y0, w: Math.max(...xs) + pad - x0, h: Math.max(...ys) + pad - y0, weight: 2 });
    }
    // Phones upright: toolbar and timeline may go under the sheet (a highlighted control is a
    // hard obstacle above), so that its text has room.
    const phone = window.innerWidth <= 560;
    for (const sel of ['#toolbar', '#timeline', '#title', '#panel']) {
      const q = rectOf(sel);
      if (q) soft.push({ ...q, weight: phone && (sel === '#toolbar' || sel === '#timeline') ? 0.08 : 1 });
    }
    return { hard, soft };
  }

  const overlap = (a, b) => Math.max(0, Math.min(a.x + a.w, b.x + b.w) - Math.max(a.x, b.x)) * Math.max(0, Math.min(a.y + a.h, b.y + b.h) - Math.max(a.y, b.y));

  /**
   * Places the card where it covers nothing it must not: never the step's highlight, the open
   * dock or the selected pose's handle (8 px clear of them), and as little as it can of the
   * poses, the toolbar, the timeline, the title and the panel. The card keeps its natural height
   * where that fits and shrinks (its text scrolls, head and buttons stay) where it does not.
   * Phones upright: a sheet across the width, where the 3-D view and the highlight stay in view.
   */
  function placeCard(r) {
    if (card.hidden) return;
    const iw = window.innerWidth;
    const ih = window.innerHeight;
    const phone = iw <= 560;
    const width = phone ? iw - 16 : Math.min(400, iw - 16);
    card.style.width = `${width}px`;
    card.style.maxHeight = 'none';
    card.classList.remove('compact');
    const natural = card.scrollHeight;
    const { hard, soft } = obstacles(r);
    const grow = (q, m) => ({ x: q.x - m, y: q.y - m, w: q.w + 2 * m, h: q.h + 2 * m });
    const hardGrown = hard.map((q) => grow(q, 8));
    // At the least: head, step title and buttons, and two lines of the text to scroll.
    const scroller = card.querySelector('.scroll');
    const fixed = scroller ? natural - scroller.scrollHeight : 100;
    // Where even that does not fit (a phone with the dock open and a highlight under it), the
    // card goes compact: the step dots and title fold away, the head and buttons stay.
    const outer = (e) => (e ? e.offsetHeight + parseFloat(getComputedStyle(e).marginTop) + parseFloat(getComputedStyle(e).marginBottom) : 0);
    const compactH = fixed - outer(card.querySelector('.bar')) - outer(card.querySelector('h3')) + 44;
    const roomy = Math.min(natural, fixed + 44);
    const minH = Math.min(natural, compactH);
    let best = null;
    const heights = [];
    for (let h = Math.min(natural, ih - 16); h >= minH; h -= 24) heights.push(h);
    if (heights.at(-1) !== minH && minH <= ih - 16) heights.push(minH);
    if (!heights.length) heights.push(Math.min(natural, ih - 16));
    // Candidates: a grid, the window's edges and flush against each hard obstacle.
    const xs = [];
    if (phone) xs.push(8);
    else {
      for (let x = iw - 8 - width; x >= 8; x -= 24) xs.push(x);
      xs.push(8);
      for (const q of hardGrown) xs.push(q.x - width, q.x + q.w);
    }
    const inX = [...new Set(xs.map(Math.round))].filter((x) => x >= 8 && x <= iw - 8 - width);
    if (!inX.length) inX.push(8);
    for (const h of heights) {
      const ys = [8];
      for (let y = ih - 8 - h; y >= 8; y -= 12) ys.push(y);
      for (const q of hardGrown) ys.push(q.y - h, q.y + q.h);
      const inY = [...new Set(ys.map(Math.round))].filter((y) => y >= 8 && y <= ih - 8 - h);
      for (const y of inY) {
        for (const x of inX) {
          const box = { x, y, w: width, h };
          let bad = 0;
          for (const q of hardGrown) bad += overlap(box, q);
          let cost = 0;
          for (const q of soft) cost += q.weight * overlap(box, q);
          // Hard first; then what it covers, less the height it keeps (a taller card scrolls less).
          const score = bad * 1e3 + cost - 40 * h;
          if (!best || score < best.score) best = { score, x, y, h, bad };
        }
      }
      if (best && best.bad === 0 && best.score + 40 * best.h < 0.02 * width * best.h) break;
      // The compact heights only when no roomy one is clear of what it must not cover.
      if (best && best.bad === 0 && h <= roomy) break;
    }
    card.classList.toggle('compact', best.h < roomy);
    card.style.left = `${best.x}px`;
    card.style.top = `${best.y}px`;
    card.style.maxHeight = `${best.h}px`;
    card.style.right = 'auto';
    card.style.bottom = 'auto';
    lastBox = { x: best.x, y: best.y, w: width, h: best.h };
  }

  let lastBox = null;
  let lastKey = '';

  function place() {
    const r = targetRect();
    spotEl.hidden = !r;
    // Again only when something it keeps clear of moved (every frame would be wasted work).
    const dock = rectOf('#dock.open');
    let p0 = null;
    try {
      p0 = app.motion.poseCount ? app.screenOfPose(app.selected >= 0 ? app.selected : 0) : null;
    } catch {
      p0 = null;
    }
    const round = (v) => Math.round((v ?? 0) / 4);
    const key = [window.innerWidth, window.innerHeight, card.dataset.step, r && [r.x, r.y, r.w, r.h].map(round), dock && [dock.x, dock.y, dock.w, dock.h].map(round), p0 && [p0.x, p0.y].map(round), app.selected].join('|');
    if (key !== lastKey) {
      lastKey = key;
      placeCard(r);
    }
    if (r) {
      spotEl.style.left = `${r.x}px`;
      spotEl.style.top = `${r.y}px`;
      spotEl.style.width = `${r.w}px`;
      spotEl.style.height = `${r.h}px`;
      spotEl.classList.toggle('round', !!r.round);
    }
    // One loop at a time: `place` is also called from outside (a resize, a new step).
    cancelAnimationFrame(raf);
    if (target || !card.hidden) raf = requestAnimationFrame(place);
  }

  window.addEventListener('resize', () => {
    if (card.hidden) return;
    lastKey = '';
    place();
  });

  return {
    set,
    place() {
      lastKey = '';
      place();
    },
    /** Where the card is placed (page px), or null. */
    box: () => lastBox,
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
