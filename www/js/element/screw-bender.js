// The embeddable figure: the custom element <screw-bender> and mount(element, options) for
// frameworks, built from the playground's view (view/viewer.js: one renderer, camera, picking
// and drawing path); the figure itself is figure.js (chrome, sources, options and editing in
// the files it names). This file is the entry: the element, mount() and the handle.
//
//   <script type="module" src=".../element/screw-bender.js"></script>
//   <screw-bender scene="l_cycle_rotated" levels="4" autoplay>caption text</screw-bender>
//
// Sources (the first present wins): `src` (URL of a motion .json or .glb), `share` (a share-link
// payload, the part after `#s=`), an inline <script type="application/json"> child (a motion
// document), `scene` (a preset id). Options: scheme, levels, j, rules, strobe, show (layers:
// strobe control trajectories polyscrew polygon triads grid), autoplay, loop, speed, editable,
// controls (none | minimal | full), camera (iso | front | side | top, or "yaw pitch [distance]"
// in degrees and scene units), theme (light | dark), persist (a localStorage key; without it the
// figure never touches storage). Properties: document, options, motion (read-only), backend,
// ready (a Promise); methods play(), pause(), seek(t) (seconds); events change {poses, index}
// (it bubbles, as the native change event does), select {index}, time {t, u, start, end}
// (seconds and parameter), error {attribute, value, message} (failures do not escape the figure
// as exceptions: every failure is a message inside the figure plus an `error` event).
//
// Good guest manners: one wasm module instance for all figures (a module-level promise); no
// listener outside the figure's own shadow tree; the wheel zooms only while the figure has the
// focus; keys only while focused; frames only while on screen (IntersectionObserver); removing
// the element frees its GPU data and observers; no inline script or style (the stylesheet is
// css/screw-bender.css beside this folder), so a strict CSP with 'wasm-unsafe-eval' suffices.
import { Figure } from './figure.js';
import { ATTRIBUTES, optionsOf } from './options.js';

export { ATTRIBUTES, LAYERS } from './options.js';

/**
 * Mounts a figure into `element` (any element; its content becomes the caption) with `options`
 * (the attributes' names; numbers and booleans may be given as such, and `document` as a motion
 * document object). Returns a handle {ready, document, options, motion, play(), pause(), seek(u),
 * destroy()}; events are dispatched on `element`. Failures show in the figure (and fire `error`);
 * only an `element` that cannot hold a shadow root throws (a TypeError, as attachShadow does).
 */
export function mount(element, options = {}) {
  const { document: doc, ...rest } = options;
  const fig = new Figure(element, emitter(element));
  if (doc !== undefined) rest.inline = JSON.stringify(doc);
  fig.start(rest);
  return handleOf(fig);
}

/**
 * Dispatches a figure's events on `target`. `change` bubbles, as the native change event does:
 * frameworks that delegate it to their root (Svelte 5's `onchange`) only see it so.
 */
function emitter(target) {
  return (type, detail) => target.dispatchEvent(new CustomEvent(type, { detail, bubbles: type === 'change' }));
}

function handleOf(fig) {
  return {
    get ready() {
      return fig.ready;
    },
    get document() {
      return fig.model.motion?.toDocument() ?? null;
    },
    set document(doc) {
      fig.setOptions({ inline: JSON.stringify(doc), src: null, share: null, scene: null });
    },
    get options() {
      return { ...fig.opts, ...(fig.model.motion ? fig.model.motion.options() : {}) };
    },
    set options(patch) {
      fig.setOptions(patch ?? {});
    },
    get motion() {
      return fig.model.motion;
    },
    get backend() {
      return fig.viewer?.backend ?? null;
    },
    play: () => fig.guard(() => fig.play()),
    pause: () => fig.guard(() => fig.pause()),
    seek: (u) => fig.guard(() => fig.seek(u)),
    destroy: () => fig.dispose(),
    /** The viewer (for tests and advanced use): camera, picking, renderer. */
    get viewer() {
      return fig.viewer;
    },
  };
}

/** The custom element <screw-bender> (see the top of this file). */
export class ScrewBenderElement extends HTMLElement {
  static get observedAttributes() {
    return ATTRIBUTES;
  }

  connectedCallback() {
    // Moving the element in the page (disconnect then connect) keeps its figure.
    if (this.figure) return;
    // Properties set before this class was defined are own properties that hide the accessors:
    // passed on to them. Frameworks (React, Vue, Svelte) set properties before they connect.
    for (const name of ['document', 'options']) {
      if (Object.prototype.hasOwnProperty.call(this, name)) {
        const value = this[name];
        delete this[name];
        this[name] = value;
      }
    }
    this.figure = new Figure(this, emitter(this));
    this.handle = handleOf(this.figure);
    const { document: doc, options } = this.pending ?? {};
    this.pending = null;
    const opts = { ...optionsOf(this), ...options };
    if (doc != null) Object.assign(opts, { inline: JSON.stringify(doc), src: null, share: null, scene: null });
    this.figure.start(opts);
  }

  disconnectedCallback() {
    // Disposal waits a task: a move within the page reconnects at once.
    queueMicrotask(() => {
      if (!this.isConnected && this.figure) {
        this.figure.dispose();
        this.figure = null;
      }
    });
  }

  attributeChangedCallback(name, old, value) {
    if (!this.figure || old === value) return;
    const v = (name === 'autoplay' || name === 'editable') && value === '' ? true : value;
    this.figure.setOptions({ [name]: v ?? null });
  }

  get ready() {
    return this.figure?.ready ?? Promise.resolve();
  }

  get document() {
    return this.handle?.document ?? null;
  }

  set document(doc) {
    // Before the figure starts (a property set by a framework before it connects the element),
    // kept for the start.
    if (this.handle) this.handle.document = doc;
    else this.pending = { ...this.pending, document: doc };
  }

  get options() {
    return this.handle?.options ?? optionsOf(this);
  }

  set options(patch) {
    if (this.handle) this.handle.options = patch;
    else this.pending = { ...this.pending, options: { ...this.pending?.options, ...patch } };
  }

  get motion() {
    return this.handle?.motion ?? null;
  }

  get backend() {
    return this.handle?.backend ?? null;
  }

  /** The viewer behind the figure (camera, picking, renderer), for tests and advanced use. */
  get viewer() {
    return this.figure?.viewer ?? null;
  }

  play() {
    return this.handle?.play();
  }

  pause() {
    return this.handle?.pause();
  }

  seek(u) {
    return this.handle?.seek(u);
  }
}

if (!customElements.get('screw-bender')) customElements.define('screw-bender', ScrewBenderElement);
