// The analysis dock: a tabbed panel of teaching and analysis views beside the 3-D view.
//
// A view module (www/js/dock/*.js) default-exports a descriptor
//   { id, title, hint, live, create(app, el, wasm) => instance }
// where `el` is the view's own <section> (the view owns everything inside it), `wasm` the
// analysis module (the initialised wasm-bindgen module with the teaching and comparison
// functions; app.motion is the renderer module's Motion, whose extra methods run there too,
// editor/modules.js) and the instance
//   { update(reason), show(visible), dispose?() }
// `update` is called (at most once per animation frame) after every change of the motion, its
// options or the view settings (reason 'edit'), during drags (reason 'drag', only for views
// with `live: true`; the Motion then already holds the dragged pose), and when the view is
// shown (reason 'show'). `show(false)` must remove the view's 3-D overlays (its LAYER / SLOT
// entries of figure/slots.js), so a hidden view costs nothing. No inline `style` attributes in
// markup (the page's CSP refuses them): set styles through `element.style`, or give colour
// swatches a `data-color` attribute.
//
// The tabs stay in one row: those that do not fit go to a "More views" menu (the open view's
// tab is always in the row); arrow keys move between views in the tab list. While the dock
// covers part of the window, the 3-D view's canvas takes the largest free part beside it, less
// the toolbar where the toolbar stands in that part (fitView: phones on their side), so the
// scene is framed where it can be seen. Charts (dock/plot.js) get their
// playhead from playback, and hovering a chart shows that instant's pose (preview).
/**
 * An analysis view of the dock: a module's default export in www/js/dock/ (the contract above).
 * @typedef {object} DockView
 * @property {string} id
 * @property {string} title
 * @property {string} [hint]
 * @property {boolean} [live] updates during drags as well
 * @property {(app: import('../app.js').App, el: HTMLElement, wasm: any) => ViewInstance} create
 */

/**
 * A view's instance (see the contract above).
 * @typedef {object} ViewInstance
 * @property {(reason: 'edit' | 'drag' | 'show') => void} update
 * @property {(visible: boolean) => void} show
 * @property {() => void} [dispose]
 * @property {(step: number) => void} [goTo] the steps view: show step `step`
 */

import { setPlayheadSource, wakePlayheads } from '../dock/plot.js';
import { without, stage } from './rects.js';

/** The smallest free part of the window (CSS px) the 3-D view moves into beside the dock. */
const MIN_FREE = { width: 200, height: 100 };

export class Dock {
  /** `views`: the view descriptors in tab order (dock/index.js loadViews); `wasm`: the analysis module. */
  constructor(app, views, wasm) {
    this.app = app;
    this.wasm = wasm;
    this.root = document.getElementById('dock');
    this.tabs = this.root.querySelector('.tabs');
    this.body = this.root.querySelector('.body');
    this.views = new Map();
    this.active = null;
    this.pending = null;
    // Every change of the motion, its options or the view settings updates the open view.
    app.on('motion', () => this.changed('edit'));
    for (const d of views) {
      const tab = document.createElement('button');
      tab.type = 'button';
      tab.textContent = d.title;
      tab.title = d.hint ?? d.title;
      tab.dataset.view = d.id;
      tab.id = `dock-tab-${d.id}`;
      tab.setAttribute('role', 'tab');
      tab.setAttribute('aria-selected', 'false');
      tab.setAttribute('aria-controls', `dock-view-${d.id}`);
      tab.onclick = () => this.app.parts.dockHost.open(this.active === d.id ? '' : d.id);
      this.tabs.append(tab);
      const el = document.createElement('section');
      el.className = `view view-${d.id}`;
      el.id = `dock-view-${d.id}`;
      el.dataset.view = d.id;
      el.setAttribute('role', 'tabpanel');
      el.setAttribute('aria-labelledby', tab.id);
      el.hidden = true;
      this.body.append(el);
      this.views.set(d.id, { d, el, tab, instance: null });
    }
    this.tabs.addEventListener('keydown', (e) => this.tabKey(e));
    this.buildMenu();
    /** @type {HTMLElement} */ (this.root.querySelector('.close')).onclick = () => this.app.parts.dockHost.open('');
    // Colour swatches written as markup carry `data-color`: the page's Content-Security-Policy
    // refuses inline style attributes, so the colour is applied through the CSSOM instead.
    const paint = (root) => {
      for (const e of root.querySelectorAll('[data-color]')) e.style.background = e.dataset.color;
    };
    new MutationObserver((records) => {
      for (const r of records) for (const n of r.addedNodes) if (n.nodeType === 1) paint(n.parentElement ?? n);
    }).observe(this.body, { childList: true, subtree: true });
    // A new window size: the tabs and the free part of the window change.
    let relayout = 0;
    const again = () => {
      cancelAnimationFrame(relayout);
      relayout = requestAnimationFrame(() => {
        if (!this.active) return;
        this.layoutTabs();
        this.fitView();
      });
    };
    window.addEventListener('resize', again);
    // A lesson opened or closed: the window's free part changed as well.
    app.on('layout', again);
    this.saved = null;
    setPlayheadSource(() => this.playhead());
    // What moves the charts' playhead: playback and seeking, a new motion or new key times.
    for (const topic of ['playback', 'motion', 'view']) app.on(topic, wakePlayheads);
  }

  // ------------------------------------------------------------------ tabs in one row

  /** The "More views" button and its menu (the tabs that do not fit the row). */
  buildMenu() {
    const more = document.createElement('button');
    more.type = 'button';
    more.className = 'more';
    more.textContent = 'More ▾';
    more.setAttribute('aria-label', 'More analysis views');
    more.setAttribute('aria-haspopup', 'menu');
    more.setAttribute('aria-expanded', 'false');
    more.hidden = true;
    const menu = document.createElement('div');
    menu.className = 'tab-menu';
    menu.setAttribute('role', 'menu');
    menu.setAttribute('aria-label', 'More analysis views');
    menu.hidden = true;
    this.tabs.after(more, menu);
    this.more = more;
    this.menu = menu;
    more.onclick = () => this.toggleMenu(menu.hidden);
    more.addEventListener('keydown', (e) => {
      if (e.key === 'ArrowDown' || e.key === 'ArrowUp') {
        e.preventDefault();
        this.toggleMenu(true);
      }
    });
    menu.addEventListener('keydown', (e) => {
      const items = [.../** @type {NodeListOf<HTMLElement>} */ (menu.querySelectorAll('[role=menuitem]'))];
      const k = items.indexOf(/** @type {HTMLElement} */ (document.activeElement));
      if (e.key === 'ArrowDown' || e.key === 'ArrowUp') {
        e.preventDefault();
        const n = items.length;
        items[(k + (e.key === 'ArrowDown' ? 1 : n - 1)) % n]?.focus();
      } else if (e.key === 'Home' || e.key === 'End') {
        e.preventDefault();
        items[e.key === 'Home' ? 0 : items.length - 1]?.focus();
      } else if (e.key === 'Escape') {
        e.preventDefault();
        e.stopPropagation();
        this.toggleMenu(false);
        more.focus();
      } else if (e.key === 'Tab') this.toggleMenu(false);
    });
    // A press anywhere else closes the menu.
    document.addEventListener('pointerdown', (e) => {
      if (!menu.hidden && !menu.contains(/** @type {Node} */ (e.target)) && e.target !== more) this.toggleMenu(false);
    });
  }

  /** Opens (with the focus on its first item) or closes the overflow menu. */
  toggleMenu(open) {
    this.menu.hidden = !open;
    this.more.setAttribute('aria-expanded', String(open));
    if (open) /** @type {HTMLElement} */ (this.menu.querySelector('[role=menuitem]'))?.focus();
  }

  /** Arrow keys, Home and End in the tab list open the next / previous / first / last view. */
  tabKey(e) {
    const ids = [...this.views.keys()];
    const k = ids.indexOf(e.target.dataset?.view);
    if (k < 0) return;
    const n = ids.length;
    const to = { ArrowRight: (k + 1) % n, ArrowLeft: (k + n - 1) % n, Home: 0, End: n - 1 }[e.key];
    if (to === undefined) return;
    e.preventDefault();
    e.stopPropagation();
    this.app.parts.dockHost.open(ids[to]);
    this.views.get(ids[to]).tab.focus();
  }

  /**
   * Keeps the tabs in one row: every tab that fits is shown in order (the open view's first),
   * the rest go to the "More views" menu.
   */
  layoutTabs() {
    const all = [...this.views.values()];
    for (const v of all) v.tab.hidden = false;
    this.more.hidden = true;
    const fits = () => this.tabs.scrollWidth <= this.tabs.clientWidth + 1;
    const hidden = [];
    if (!fits()) {
      this.more.hidden = false;
      const gap = parseFloat(getComputedStyle(this.tabs).columnGap) || 0;
      let room = this.tabs.clientWidth;
      const active = this.active ? this.views.get(this.active) : null;
      if (active) room -= active.tab.offsetWidth + gap;
      for (const v of all) {
        if (v === active) continue;
        const w = v.tab.offsetWidth + gap;
        if (w <= room && hidden.length === 0) room -= w;
        else hidden.push(v);
      }
      for (const v of hidden) v.tab.hidden = true;
    }
    this.menu.replaceChildren(
      ...hidden.map((v) => {
        const item = document.createElement('button');
        item.type = 'button';
        item.setAttribute('role', 'menuitem');
        item.dataset.view = v.d.id;
        item.textContent = v.d.title;
        item.title = v.d.hint ?? v.d.title;
        item.onclick = () => {
          this.toggleMenu(false);
          this.app.parts.dockHost.open(v.d.id);
          this.views.get(v.d.id).tab.focus();
        };
        return item;
      }),
    );
    if (hidden.length === 0) this.toggleMenu(false);
  }

  // ------------------------------------------------------------------ the 3-D view beside the dock

  /**
   * Puts the 3-D view's canvas into the largest part of the window the dock leaves free (left,
   * right, above or below it; where the toolbar stands in a part, the part beside it), or back
   * to the whole window when the dock is closed or leaves no usable part. The caller re-frames
   * the scene (dock-host.js).
   */
  fitView() {
    const c = this.app.viewer.canvas;
    if (!c) return;
    let free = null;
    if (this.active) {
      const d = this.root.getBoundingClientRect();
      const toolbar = document.getElementById('toolbar')?.getBoundingClientRect() ?? null;
      // The window less an open lesson's card (editor/rects.js stage).
      const S = stage();
      const right = S.left + S.width;
      const bottom = S.top + S.height;
      const parts = [
        { left: S.left, top: S.top, width: d.left - S.left, height: S.height },
        { left: d.right, top: S.top, width: right - d.right, height: S.height },
        { left: S.left, top: S.top, width: S.width, height: d.top - S.top },
        { left: S.left, top: d.bottom, width: S.width, height: bottom - d.bottom },
      ]
        .map((p) => (toolbar ? without(p, toolbar) : p))
        .filter((p) => p.width >= MIN_FREE.width && p.height >= MIN_FREE.height);
      for (const p of parts) if (!free || p.width * p.height > free.width * free.height) free = p;
    }
    const s = c.style;
    if (free) {
      s.left = `${Math.round(free.left)}px`;
      s.top = `${Math.round(free.top)}px`;
      s.width = `${Math.round(free.width)}px`;
      s.height = `${Math.round(free.height)}px`;
    } else s.left = s.top = s.width = s.height = '';
    this.free = free;
    this.app.viewer?.invalidateSize?.();
  }

  // ------------------------------------------------------------------ playhead and hover

  /** Playback now: {t (seconds), u (motion parameter)}. */
  playhead() {
    const app = this.app;
    if (app.viewer) return app.viewer.playhead();
    return { t: app.anim.u, u: app.anim.u };
  }

  /**
   * Shows the pose at time `t` (seconds) while a chart is hovered, or (null) the one shown
   * before. Playback pauses meanwhile; nothing is an edit (no undo entry, nothing saved).
   */
  preview(t) {
    const app = this.app;
    const anim = app.anim;
    if (t === null) {
      const s = this.saved;
      if (!s) return;
      this.saved = null;
      if (app.viewer) app.viewer.seekTime(s.t);
      app.setPlayback({ u: s.u, visible: s.visible, playing: s.playing });
      app.viewer.updateAnim();
      app.viewer.requestDraw();
      return;
    }
    if (!Number.isFinite(t) || !app.motion) return;
    if (!this.saved) this.saved = { ...this.playhead(), visible: anim.visible, playing: anim.playing };
    app.setPlayback({ playing: false });
    if (app.viewer) app.viewer.seekTime(t);
    else {
      const [a, b] = app.motion.domain();
      app.setPlayback({ u: Math.min(b, Math.max(a, t)), visible: true });
      app.viewer.updateAnim();
      app.viewer.requestDraw();
    }
  }

  /** Opens view `id` (null closes the dock). Returns the view instance. */
  open(id) {
    if (id !== null && !this.views.has(id)) throw new Error(`unknown view ${id}`);
    if (this.active && this.active !== id) {
      const v = this.views.get(this.active);
      v.el.hidden = true;
      v.tab.classList.remove('on');
      v.instance?.show(false);
    }
    this.preview(null);
    this.toggleMenu(false);
    const was = this.active;
    this.active = id;
    this.root.classList.toggle('open', id !== null);
    document.body.classList.toggle('dock-open', id !== null);
    for (const [vid, v] of this.views) v.tab.setAttribute('aria-selected', String(vid === id));
    if (id === null) {
      this.fitView();
      this.app.viewer.requestDraw();
      return null;
    }
    const v = this.views.get(id);
    v.el.hidden = false;
    v.tab.classList.add('on');
    this.layoutTabs();
    if (was === null || was === undefined) this.fitView();
    if (!v.instance) v.instance = v.d.create(this.app, v.el, this.wasm);
    v.instance.show(true);
    v.instance.update('show');
    this.app.viewer.requestDraw();
    return v.instance;
  }

  /** The instance of the open view (or null). */
  get current() {
    return this.active ? this.views.get(this.active).instance : null;
  }

  /** True when the open view wants updates during drags. */
  get wantsLive() {
    return this.active !== null && !!this.views.get(this.active).d.live;
  }

  /** Schedules an update of the open view (coalesced to one per animation frame). */
  changed(reason = 'edit') {
    if (!this.active) return;
    if (reason === 'drag' && !this.wantsLive) return;
    if (this.pending) {
      if (reason === 'edit') this.pending = 'edit';
      return;
    }
    this.pending = reason;
    requestAnimationFrame(() => this.flush());
  }

  /** Runs a pending update now (tests call it through window.screwbender.flushViews()). */
  flush() {
    const reason = this.pending;
    this.pending = null;
    const inst = this.current;
    if (!reason || !inst) return;
    try {
      inst.update(reason);
    } catch (e) {
      this.app.parts.notices.show(`${this.views.get(this.active).d.title}: ${e.message}`);
    }
    this.app.viewer.requestDraw();
  }
}
