// The analysis dock: a tabbed panel of teaching and analysis views beside the 3-D view.
//
// A view module (www/js/views/*.js) default-exports a descriptor
//   { id, title, hint, live, create(app, el) => instance }
// where `el` is the view's own <section> (the view owns everything inside it) and the instance
//   { update(reason), show(visible), dispose?() }
// `update` is called (at most once per animation frame) after every change of the motion, its
// options or the view settings (reason 'edit'), during drags (reason 'drag', only for views
// with `live: true`; the Motion then already holds the dragged pose), and when the view is
// shown (reason 'show'). `show(false)` must remove the view's 3-D overlays (its LAYER / SLOT
// entries of view/scene.js), so a hidden view costs nothing. No inline `style` attributes in
// markup (the page's CSP refuses them): set styles through `element.style`, or give colour
// swatches a `data-color` attribute.
import { VIEWS } from '../views/index.js';

export class Dock {
  constructor(app) {
    this.app = app;
    this.root = document.getElementById('dock');
    this.tabs = this.root.querySelector('.tabs');
    this.body = this.root.querySelector('.body');
    this.views = new Map();
    this.active = null;
    this.pending = null;
    for (const d of VIEWS) {
      const tab = document.createElement('button');
      tab.type = 'button';
      tab.textContent = d.title;
      tab.title = d.hint ?? d.title;
      tab.dataset.view = d.id;
      tab.setAttribute('role', 'tab');
      tab.onclick = () => this.app.openView(this.active === d.id ? '' : d.id);
      this.tabs.append(tab);
      const el = document.createElement('section');
      el.className = `view view-${d.id}`;
      el.dataset.view = d.id;
      el.hidden = true;
      this.body.append(el);
      this.views.set(d.id, { d, el, tab, instance: null });
    }
    this.root.querySelector('.close').onclick = () => this.app.openView('');
    // Colour swatches written as markup carry `data-color`: the page's Content-Security-Policy
    // refuses inline style attributes, so the colour is applied through the CSSOM instead.
    const paint = (root) => {
      for (const e of root.querySelectorAll('[data-color]')) e.style.background = e.dataset.color;
    };
    new MutationObserver((records) => {
      for (const r of records) for (const n of r.addedNodes) if (n.nodeType === 1) paint(n.parentElement ?? n);
    }).observe(this.body, { childList: true, subtree: true });
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
    this.active = id;
    this.root.classList.toggle('open', id !== null);
    document.body.classList.toggle('dock-open', id !== null);
    if (id === null) {
      this.app.requestDraw();
      return null;
    }
    const v = this.views.get(id);
    v.el.hidden = false;
    v.tab.classList.add('on');
    if (!v.instance) v.instance = v.d.create(this.app, v.el);
    v.instance.show(true);
    v.instance.update('show');
    this.app.requestDraw();
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
      this.app.showError(`${this.views.get(this.active).d.title}: ${e.message}`);
    }
    this.app.requestDraw();
  }
}
