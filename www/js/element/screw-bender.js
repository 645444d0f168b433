// The embeddable figure: the custom element <screw-bender> and mount(element, options) for
// frameworks, built from the playground's view (figure/viewer.js: one renderer, camera, picking
// and drawing path); the figure itself is figure.js (its features in the files
// features.js names). This file is the entry: the element, mount() and the handle.
//
//   <script type="module" src=".../element/screw-bender.js"></script>
//   <screw-bender preset="l_cycle_rotated" levels="4" autoplay>caption text</screw-bender>
//
// Its options (attributes), properties, methods and events are declared by the features that
// own them (features.js lists them; each feature's file documents its own): the element watches
// exactly the declared attributes, and its members are built here from the declared properties
// and methods. Failures do not reach the page as exceptions: each is a message inside the figure
// plus an `error` event (a picture's bad options throw or reject, as a canvas's would). Children
// with slot="pose-3" (or slot="pose" and data-pose="3") label pose 3 (labels.js); the others are
// the caption.
//
// Good guest manners: one wasm module instance for all figures (a module-level promise); no
// listener outside the figure's own shadow tree but print's (loading.js); the wheel zooms and a
// vertical swipe orbits only while the figure has the focus; it takes only the keys it acts on,
// and only while focused (chrome.js); it starts near the viewport and draws only while shown;
// removing the element frees its GPU data and observers; no inline script or style (the
// stylesheet is linked: css/screw-bender.css, or where ../assets.js is told), so a strict CSP
// with 'wasm-unsafe-eval' suffices.
import { FEATURES, ATTRIBUTES, FLAGS, EVENTS } from './features.js';
import { Figure } from './figure.js';
import { canonical } from './options.js';

export { ATTRIBUTES } from './features.js';
export { LAYERS } from './options.js';
export { configure } from '../assets.js';

/** The declared event types: a figure fires no other. */
/** Each declared event's detail fields (none: an empty detail), as the typings give them. */
const DECLARED_EVENTS = new Map(
  FEATURES.flatMap((f) => f.events ?? []).map((e) => [e.name, Object.keys(e.detail?.fields ?? {}).map((k) => k.replace(/\?$/, ''))]),
);

/** Options from an element's attributes (and its inline JSON child). */
function optionsOf(el) {
  const o = {};
  for (const a of ATTRIBUTES) if (el.hasAttribute(a)) o[a] = el.getAttribute(a);
  for (const b of FLAGS) if (o[b] === '') o[b] = true;
  const script = el.querySelector(':scope > script[type="application/json"]');
  if (script) o.inline = script.textContent;
  return canonical(o);
}

/**
 * Mounts a figure into `element` (any element; its content becomes the caption) with `options`
 * (the attributes' names; numbers and booleans may be given as such, `document` as a motion
 * document object, `touchAction` for `touch-action`). Returns a FigureHandle; events are
 * dispatched on `element`. Failures show in the figure (and fire `error`); only an `element`
 * that cannot hold a shadow root throws (a TypeError, as attachShadow does).
 * @param {Element} element
 * @param {Record<string, any>} [options]
 */
export function mount(element, options = {}) {
  const { document: doc, touchAction, ...rest } = options;
  const fig = new Figure(element, emitter(element));
  if (doc !== undefined) rest.inline = JSON.stringify(doc);
  if (touchAction !== undefined) rest['touch-action'] = touchAction;
  fig.start(rest);
  return new FigureHandle(fig);
}

/**
 * Dispatches a figure's events on `target`. `change` bubbles, as the native change event does:
 * frameworks that delegate it to their root (Svelte 5's `onchange`) only see it so.
 */
const emitter = (target) => (type, detail) => {
  // An event no feature declares would be missing from the typings and the manifest.
  const fields = DECLARED_EVENTS.get(type);
  if (!fields) throw new Error(`the figure fires "${type}", which no feature declares (element/features.js)`);
  // A detail field the declaration lacks would be missing from the typings too.
  const extra = Object.keys(detail ?? {}).filter((k) => !fields.includes(k));
  if (extra.length) throw new Error(`the figure's "${type}" event carries ${extra.join(', ')}, which its declaration lacks`);
  target.dispatchEvent(new CustomEvent(type, { detail, bubbles: type === 'change' }));
};

/**
 * A figure's script API: what mount() returns, and what <screw-bender> forwards to. Its
 * members are the features' declared properties and methods (below), and destroy().
 */
export class FigureHandle {
  constructor(fig) {
    this.figure = fig;
  }

  destroy() {
    this.figure.dispose();
  }
}

for (const f of FEATURES) {
  for (const p of f.properties ?? []) {
    Object.defineProperty(FigureHandle.prototype, p.name, {
      configurable: true,
      get() {
        return p.get(this.figure);
      },
      ...(p.set && {
        set(v) {
          p.set(this.figure, v);
        },
      }),
    });
  }
  for (const m of f.methods ?? []) {
    Object.defineProperty(FigureHandle.prototype, m.name, {
      configurable: true,
      writable: true,
      value(...args) {
        return m.call(this.figure, ...args);
      },
    });
  }
}

/** The custom element <screw-bender> (see the top of this file); its members are FigureHandle's. */
export class ScrewBenderElement extends HTMLElement {
  static get observedAttributes() {
    return ATTRIBUTES;
  }

  constructor() {
    super();
    // The figure exists from the start, so properties set before the element is connected (as
    // frameworks do) are kept and take effect when it starts.
    this.renew();
  }

  renew() {
    this.handle = new FigureHandle(new Figure(this, emitter(this)));
    this.started = false;
  }

  connectedCallback() {
    // Properties set before this class was defined are own properties that hide the accessors
    // (frameworks set properties on elements they create before the module defines them):
    // handed on to the accessors.
    for (const name of Object.keys(this)) {
      if (name === 'handle' || name === 'started' || !(name in ScrewBenderElement.prototype)) continue;
      const value = this[name];
      delete this[name];
      this[name] = value;
    }
    // Moving the element in the page (disconnect then connect) keeps its figure.
    if (this.handle.figure.disposed) this.renew();
    if (this.started) return;
    this.started = true;
    const f = this.handle.figure;
    f.start({ ...optionsOf(this), ...f.opts });
  }

  disconnectedCallback() {
    // Disposal waits a task: a move within the page reconnects at once.
    queueMicrotask(() => {
      if (!this.isConnected && this.started) {
        this.handle.figure.dispose();
        this.started = false;
      }
    });
  }

  attributeChangedCallback(name, old, value) {
    if (!this.started || old === value) return;
    const v = FLAGS.includes(name) && value === '' ? true : value;
    this.handle.figure.setOptions({ [name]: v ?? null });
  }

  /** The figure behind the element (for tests and advanced use). */
  get figure() {
    return this.handle.figure;
  }
}

// The element's members are the handle's, each forwarded to the element's own handle.
for (const [name, d] of Object.entries(Object.getOwnPropertyDescriptors(FigureHandle.prototype))) {
  if (name === 'constructor' || name === 'destroy') continue;
  const forward = { configurable: true };
  if (d.get) forward.get = function get() { return d.get.call(this.handle); };
  if (d.set) forward.set = function set(v) { d.set.call(this.handle, v); };
  if (d.value) {
    forward.value = function method(...args) { return d.value.apply(this.handle, args); };
    forward.writable = true;
  }
  Object.defineProperty(ScrewBenderElement.prototype, name, forward);
}

if (!customElements.get('screw-bender')) customElements.define('screw-bender', ScrewBenderElement);
