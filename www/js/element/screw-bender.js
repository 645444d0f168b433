// The embeddable figure: the custom element <screw-bender> and mount(element, options) for
// frameworks, built from the playground's view (view/viewer.js: one renderer, camera, picking
// and drawing path); the figure itself is figure.js (chrome, sources, options and editing in
// the files it names). This file is the entry: the element, mount() and the handle.
//
//   <script type="module" src=".../element/screw-bender.js"></script>
//   <screw-bender preset="l_cycle_rotated" levels="4" autoplay>caption text</screw-bender>
//
// Sources (the first present wins): `src` (URL of a motion .json or .glb), `share` (a share-link
// payload, the part after `#s=`), an inline <script type="application/json"> child (a motion
// document), `preset` (a preset id; `scene`, its former name, still works). Options: scheme, levels, s, rules, strobe, show (layers:
// strobe control trajectories polyscrew polygon triads grid), autoplay, loop, speed, editable,
// controls (none | minimal | full), camera (iso | front | side | top, "yaw pitch [distance]", or
// "yaw pitch distance tx ty tz" with the point looked at, in degrees and scene units), theme (light | dark), persist (a localStorage key; without it the
// figure never touches storage), alt (the accessible name), loading (lazy | eager), poster (an
// image URL shown until the first frame), touch-action (pan-y | pan-x | none: what a touch on
// the unfocused figure leaves to the page). Children with slot="pose-3" (or slot="pose" and
// data-pose="3") label pose 3 (labels.js); the others are the caption.
//
// Properties: document, options, motion (read-only), backend, ready (a Promise), camera, and as
// HTMLMediaElement's: currentTime, duration, paused, playbackRate, loop; methods play({
// repetitions }), pause(), seek(t) (seconds: the currentTime setter), toBlob(opts),
// toDataURL(opts); events change {poses}, select {index}, time {t, u, start, end} (seconds and
// parameter; timeupdate is the same), play, pause, ended, seeked, ratechange, camera-change
// {source, camera}, error {attribute, value, message} (failures do not reach the page as
// exceptions: each is a message inside the figure plus an `error` event; a picture's bad
// options throw or reject, as a canvas's would).
//
// Good guest manners: one wasm module instance for all figures (a module-level promise); no
// listener outside the figure's own shadow tree but print's (showing.js); the wheel zooms and a
// vertical swipe orbits only while the figure has the focus; it takes only the keys it acts on,
// and only while focused (chrome.js); it starts near the viewport and draws only while shown;
// removing the element frees its GPU data and observers; no inline script or style (the
// stylesheet is css/screw-bender.css beside this folder), so a strict CSP with
// 'wasm-unsafe-eval' suffices.
import { Figure } from './figure.js';
import { ATTRIBUTES, optionsOf } from './options.js';

export { ATTRIBUTES, LAYERS } from './options.js';

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
const emitter = (target) => (type, detail) =>
  target.dispatchEvent(new CustomEvent(type, { detail, bubbles: type === 'change' }));

/** A figure's script API: what mount() returns, and what <screw-bender> forwards to. */
export class FigureHandle {
  constructor(fig) {
    this.figure = fig;
  }

  /** Resolves when the figure is drawn (a lazy one: once near the viewport) or has shown its error. */
  get ready() {
    return this.figure.ready ?? Promise.resolve();
  }

  get document() {
    return this.figure.model.motion?.toDocument() ?? null;
  }

  set document(doc) {
    this.figure.setOptions({ inline: JSON.stringify(doc), src: null, share: null, preset: null });
  }

  get options() {
    const f = this.figure;
    return { ...f.opts, ...(f.model.motion ? f.model.motion.options() : {}) };
  }

  set options(patch) {
    this.figure.setOptions(patch ?? {});
  }

  get motion() {
    return this.figure.model.motion;
  }

  get backend() {
    return this.figure.viewer?.backend ?? null;
  }

  /** The viewer (for tests and advanced use): camera, picking, renderer. */
  get viewer() {
    return this.figure.viewer;
  }

  /** Plays; `repetitions` passes then `ended` (else as `loop` says). */
  play(opts) {
    const f = this.figure;
    return f.guard(() => f.play(opts));
  }

  pause() {
    const f = this.figure;
    return f.guard(() => f.pause());
  }

  /** Shows time t (seconds): the currentTime setter. */
  seek(t) {
    const f = this.figure;
    return f.guard(() => f.seek(t));
  }

  get currentTime() {
    return this.figure.playback.currentTime;
  }

  set currentTime(t) {
    this.seek(t);
  }

  get duration() {
    return this.figure.playback.duration;
  }

  get paused() {
    return this.figure.playback.paused;
  }

  get playbackRate() {
    return this.figure.playback.playbackRate;
  }

  set playbackRate(r) {
    const f = this.figure;
    f.guard(() => (f.playback.playbackRate = r));
  }

  get loop() {
    return this.figure.playback.loop;
  }

  set loop(on) {
    this.figure.playback.loop = on;
  }

  /** {yaw, pitch, distance, target, projection}; set any of them (fires camera-change 'api'). */
  get camera() {
    return this.figure.playback.camera;
  }

  set camera(c) {
    const f = this.figure;
    f.guard(() => f.playback.setCamera(c));
  }

  /** A picture of the view: {type, quality, scale, transparent, gizmo} → Promise<Blob>. */
  toBlob(opts) {
    return this.figure.playback.toBlob(opts);
  }

  /** The same picture as a data: URL (synchronous). */
  toDataURL(opts) {
    return this.figure.playback.toDataURL(opts);
  }

  destroy() {
    this.figure.dispose();
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
    const v = (name === 'autoplay' || name === 'editable') && value === '' ? true : value;
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
