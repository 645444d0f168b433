// The highlight of a lesson step: a ring around a control, a panel entry, a pose's handle or a
// gizmo handle, followed every frame while anything on the page moves, and the means to reach what it
// points at. The card covers none of the page's chrome (css/lessons.css makes room for it), so
// the ring's target is reachable where it is, with two exceptions handled here: a control that
// its container's scrolling hides (the panel, a toolbar kept to one row) is scrolled into view,
// and a button that something still covers is offered on the card as a button standing in for
// it.
import { el } from '../dom.js';
import { foldPanelOnSmallScreens } from '../editor/fold.js';

/** How long (ms) the ring keeps following its target after it last moved. */
const QUIET_MS = 1000;

/**
 * Creates the highlight ring (#lesson-spot) of the lesson card `parts` ({card, proxy}: card.js)
 * of `app`. Returns {set(h), place(), spot(), box(), target}: `set` points it at step
 * highlight `h` (null: none), `place` follows the target again now, `spot` tells where the ring
 * is and `box` where the card is.
 */
export function createHighlight(app, { card, proxy }) {
  const spotEl = el('div');
  spotEl.id = 'lesson-spot';
  spotEl.hidden = true;
  document.body.append(spotEl);

  let target = null;
  let raf = 0;
  let lastKey = '';
  /** When the ring last moved (performance.now()); its frame loop stops QUIET_MS after that. */
  let movedAt = 0;

  /** Whether a step's highlight opened the panel (a later step folds it again on phones). */
  let openedPanel = false;

  /** The lil-gui controller named `name` of the settings panel, or undefined. */
  const controller = (name) => app.ui.gui.controllersRecursive().find((k) => k._name === name);

  function set(h) {
    target = h;
    if (h?.panel) {
      const c = controller(h.panel);
      if (app.ui.gui._closed) openedPanel = true;
      app.ui.gui.open();
      c?.parent.open();
    } else if (openedPanel) {
      // Phones, or beside an open dock: the panel the last step pointed into would cover the
      // 3-D view of this one.
      openedPanel = false;
      if (app.dock?.active) app.ui.gui.close();
      else foldPanelOnSmallScreens(app);
    }
    cancelAnimationFrame(raf);
    lastKey = '';
    setProxy(null);
    if (h) {
      place();
      // A new target pulses again (css/lessons.css).
      for (const a of spotEl.getAnimations()) {
        a.currentTime = 0;
        a.play();
      }
    } else spotEl.hidden = true;
  }

  /** The DOM node of a control or panel target, or null (a pose or the gizmo is no node). */
  function targetNode() {
    if (target?.control) return document.querySelector(target.control);
    if (target?.panel) return controller(target.panel)?.domElement ?? null;
    return null;
  }

  /** Where the highlight goes this frame: {x, y, w, h} in page px, or null. */
  function targetRect() {
    if (!target) return null;
    if (target.control || target.panel) {
      const node = targetNode();
      if (!node) return null;
      const r = node.getBoundingClientRect();
      if (r.width === 0 && r.height === 0) return null;
      return { x: r.left - 4, y: r.top - 4, w: r.width + 8, h: r.height + 8 };
    }
    let p = null;
    try {
      if (target.pose !== undefined && target.pose < app.motion.poseCount) p = app.viewer.screenOfPose(target.pose);
      if (target.gizmo !== undefined && app.selected >= 0) p = app.viewer.screenOfGizmo(target.gizmo);
    } catch {
      p = null;
    }
    if (!p || !Number.isFinite(p.x) || !Number.isFinite(p.y)) return null;
    return { x: p.x - 24, y: p.y - 24, w: 48, h: 48, round: true };
  }

  /**
   * Scrolls a control that its container's own scrolling hides (a panel entry, a button of a
   * toolbar kept to one row) into the container's view.
   */
  function reach(node) {
    for (let box = node?.parentElement; box && box !== document.body; box = box.parentElement) {
      const css = getComputedStyle(box);
      const p = box.getBoundingClientRect();
      const r = node.getBoundingClientRect();
      if (/auto|scroll/.test(css.overflowY) && box.scrollHeight > box.clientHeight) {
        if (r.top < p.top) box.scrollTop -= p.top - r.top + 4;
        else if (r.bottom > p.bottom) box.scrollTop += Math.min(r.bottom - p.bottom + 4, r.top - p.top);
      }
      if (/auto|scroll/.test(css.overflowX) && box.scrollWidth > box.clientWidth) {
        if (r.left < p.left) box.scrollLeft -= p.left - r.left + 4;
        else if (r.right > p.right) box.scrollLeft += r.right - p.right + 4;
      }
    }
  }

  /** Whether a press at the centre of `node` reaches it (nothing lies over it, it is on screen). */
  function hittable(node) {
    const r = node.getBoundingClientRect();
    const x = r.left + r.width / 2;
    const y = r.top + r.height / 2;
    if (x < 0 || y < 0 || x >= window.innerWidth || y >= window.innerHeight) return false;
    const hit = document.elementFromPoint(x, y);
    return !!hit && (hit === node || node.contains(hit));
  }

  /** Shows on the card a button standing in for control `node` (null: none). */
  function setProxy(node) {
    if (!node) {
      proxy.hidden = true;
      proxy.replaceChildren();
      return;
    }
    const name = node.getAttribute('aria-label') || node.querySelector('span')?.textContent || node.textContent.trim() || node.title;
    const b = el('button', { class: 'use' }, name);
    b.title = node.title;
    b.addEventListener('click', () => node.click());
    proxy.replaceChildren(el('span', {}, 'Use here: '), b);
    proxy.hidden = false;
  }

  function place(now = performance.now()) {
    // One loop at a time: `place` is also called from outside (a resize, a new step).
    cancelAnimationFrame(raf);
    raf = 0;
    const r = targetRect();
    spotEl.hidden = !r;
    if (r) {
      spotEl.style.left = `${r.x}px`;
      spotEl.style.top = `${r.y}px`;
      spotEl.style.width = `${r.w}px`;
      spotEl.style.height = `${r.h}px`;
      spotEl.classList.toggle('round', !!r.round);
      // Reach it again only when it moved (hit tests every frame would be wasted work).
      const key = [window.innerWidth, window.innerHeight, r.x, r.y, r.w, r.h].map(Math.round).join('|');
      if (key !== lastKey) {
        lastKey = key;
        movedAt = now;
        const node = targetNode();
        reach(node);
        // A button the student cannot press where it is: a stand-in on the card.
        if (node && target.control && node instanceof HTMLButtonElement) setProxy(hittable(node) ? null : node);
      }
    }
    // It follows the target every frame while the target moves and for QUIET_MS after, then
    // rests until something may move it again (wake): a loop looking every display frame would
    // keep the processor busy for as long as a lesson stays open.
    if (target && now - movedAt < QUIET_MS) raf = requestAnimationFrame(place);
  }

  /** Follows the target again from the next frame on (something on the page may move it). */
  function wake() {
    if (!target || raf) return;
    movedAt = performance.now();
    raf = requestAnimationFrame(place);
  }
  // What can move a target: the figure (a drawn frame announces playback, view and motion
  // changes), the window, scrolling, the user's input, CSS transitions and animations, and any
  // change of the page's elements but the ring's own.
  for (const topic of ['motion', 'view', 'playback', 'selection', 'layout']) app.on(topic, wake);
  for (const type of ['resize', 'scroll', 'pointerdown', 'pointermove', 'pointerup', 'wheel', 'keydown', 'transitionrun', 'animationstart', 'transitionend', 'animationend']) {
    window.addEventListener(type, wake, { capture: true, passive: true });
  }
  new MutationObserver((records) => {
    if (records.some((m) => m.target !== spotEl)) wake();
  }).observe(document.body, { subtree: true, childList: true, attributes: true, characterData: true });

  return {
    set,
    place() {
      lastKey = '';
      if (target) place();
    },
    /** Where the card is (page px), or null while it is hidden. */
    box() {
      if (card.hidden) return null;
      const r = card.getBoundingClientRect();
      return { x: r.left, y: r.top, w: r.width, h: r.height };
    },
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
