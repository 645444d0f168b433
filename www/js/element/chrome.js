// A figure's chrome: its shadow tree (canvas, control bar, message, caption, pose labels, live
// region, poster and print still), the bar's listeners and display, and the keys of a focused
// figure. Built node by node (no HTML strings, no inline style), so a strict CSP suffices.
//
// Keys are a guest's: a key the figure acts on stops there (propagation and default), every
// other key reaches the page as if the figure were not there, and Tab and Escape (with nothing
// selected) take the focus out of the figure. The bar's own controls keep the keys they act on
// (a range's arrows, a button's Space) from the page too, so a slide deck does not turn its
// slide while the reader scrubs.
//
// Its options: `controls` (how much of the bar shows), `theme` (the chrome's and the 3-D view's
// colours) and `touch-action` (what a touch on the unfocused figure leaves to the page).
import { stylesheetNode } from '../assets.js';
import { DEFAULT_NAME } from './description.js';
import { oneOf } from './options.js';

const CONTROLS = ['none', 'minimal', 'full'];
const THEMES = ['light', 'dark'];
/** What a touch on a figure without the focus leaves to the page (`touch-action`). */
const TOUCH = ['pan-y', 'pan-x', 'none'];

/** @type {import('./options.js').Feature} */
export const chromeFeature = {
  name: 'chrome',
  doc: 'The control bar, the colours and the touch gestures left to the page.',
  options: [
    {
      name: 'controls', type: CONTROLS, default: 'minimal', parse: (v) => oneOf('controls', v, CONTROLS), python: true,
      doc: 'The figure\'s chrome: none, minimal (play, scrub, time) or full (plus scheme, levels, frame).',
    },
    {
      name: 'theme', type: THEMES, default: 'light', parse: (v) => oneOf('theme', v, THEMES), python: true,
      doc: 'Colours of the chrome, frame and 3-D view.',
    },
    {
      name: 'touch-action', type: TOUCH, default: 'pan-y', parse: (v) => oneOf('touch-action', v, TOUCH), early: true,
      doc: 'What a touch on the unfocused figure leaves to the page: `pan-y` (a vertical swipe scrolls the page, a sideways one orbits), `pan-x`, or `none` (the figure takes every touch).',
    },
  ],
  parts: [
    { name: 'canvas', doc: 'The 3-D view (focusable: keys and wheel act while it has the focus).' },
    { name: 'controls', doc: 'The control bar (play, scrubber, time; with controls="full" also scheme, levels, frame).' },
  ],
  // What a touch leaves to the page applies before the figure starts.
  early(fig, v) {
    fig.el.fig.dataset.touch = v['touch-action'];
  },
  apply(fig, v) {
    fig.el.fig.dataset.controls = v.controls;
    fig.el.fig.dataset.theme = v.theme;
    // The 3-D view's background and line colours follow the chrome.
    fig.viewer?.setDark(v.theme === 'dark');
  },
};

/**
 * The figure's shadow tree in `host` (emptied first): the canvas, the control bar, the message
 * and the caption slot, with the stylesheet. Returns {root, el} (el: the parts by name).
 */
export function buildChrome(host) {
  // Manual slot assignment: labels.js sends each child to the caption or to its pose's label.
  const root = host.shadowRoot ?? host.attachShadow({ mode: 'open', slotAssignment: 'manual' });
  root.replaceChildren();
  // The stylesheet where assets.js says (a <link>, or a <style> in a bundle without files).
  const link = stylesheetNode();
  const fig = document.createElement('div');
  fig.className = 'fig';
  // Built node by node, not from an HTML string: the element must work under a CSP that
  // forbids string-to-HTML sinks (and the page's own test refuses them).
  const node = (tag, attrs = {}, ...children) => {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs)) {
      if (k === 'text') e.textContent = v;
      else if (k === 'hidden') e.hidden = v;
      else e.setAttribute(k, v);
    }
    e.append(...children);
    return e;
  };
  const schemes = [['bspline', 'B-spline'], ['fourpoint', '4-point'], ['jarek', 'Jarek']];
  fig.append(
    // The 3-D view's box: the canvas, with the poster, the print still and the labels over it.
    node('div', { class: 'view' },
      node('canvas', { tabindex: '0', part: 'canvas', role: 'application', 'aria-label': DEFAULT_NAME }),
      node('img', { class: 'poster', part: 'poster', alt: '', hidden: true }),
      node('div', { class: 'still', hidden: true }),
      node('div', { class: 'labels', part: 'labels' })),
    node('div', { class: 'bar', part: 'controls' },
      node('button', { class: 'play', type: 'button', 'aria-label': 'Play', text: '▶' }),
      node('input', { class: 'scrub', type: 'range', min: '0', max: '1000', value: '0', 'aria-label': 'Playback time' }),
      node('span', { class: 'time', text: formatTime(0) }),
      node('span', { class: 'full' },
        node('select', { class: 'scheme', 'aria-label': 'Scheme' },
          ...schemes.map(([value, label]) => node('option', { value, text: label }))),
        node('label', {}, 'levels ',
          node('input', { class: 'levels', type: 'range', min: '0', max: '7', step: '1', value: '4' })),
        node('button', { class: 'frame', type: 'button', title: 'Frame all (A)', text: 'Frame' }))),
    node('div', { class: 'msg', role: 'alert', hidden: true }),
    node('div', { class: 'caption' }, node('slot')),
    node('div', { class: 'live', role: 'status', 'aria-live': 'polite', 'aria-atomic': 'true' }),
  );
  root.append(link, fig);
  const el = {
    fig,
    canvas: fig.querySelector('canvas'),
    bar: fig.querySelector('.bar'),
    play: fig.querySelector('.play'),
    scrub: fig.querySelector('.scrub'),
    time: fig.querySelector('.time'),
    scheme: fig.querySelector('.scheme'),
    levels: fig.querySelector('.levels'),
    frame: fig.querySelector('.frame'),
    msg: /** @type {HTMLElement} */ (fig.querySelector('.msg')),
    poster: fig.querySelector('.poster'),
    still: fig.querySelector('.still'),
    caption: fig.querySelector('.caption slot'),
    labels: fig.querySelector('.labels'),
    live: fig.querySelector('.live'),
    stylesheet: link,
  };
  return { root, el };
}

/** Keys that each kind of the bar's controls acts on (kept from the page). */
const BAR_KEYS = {
  INPUT: ['ArrowLeft', 'ArrowRight', 'ArrowUp', 'ArrowDown', 'Home', 'End', 'PageUp', 'PageDown'],
  BUTTON: [' ', 'Enter'],
  SELECT: ['ArrowUp', 'ArrowDown', 'ArrowLeft', 'ArrowRight', 'Home', 'End', ' ', 'Enter'],
};

/** The control bar's listeners (on the figure's own elements only). */
export function bindChrome(fig) {
  const { bar, play, scrub, scheme, levels, frame } = fig.el;
  bar.addEventListener('keydown', (e) => {
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    if (e.target.tagName === 'INPUT' && e.key === ' ') {
      // Space on a slider plays or pauses, as on the canvas (a slider has no use for it).
      e.preventDefault();
      e.stopPropagation();
      fig.guard(() => (fig.playing ? fig.pause() : fig.play()));
    } else if (BAR_KEYS[e.target.tagName]?.includes(e.key)) e.stopPropagation();
  });
  play.addEventListener('click', () => fig.guard(() => (fig.playing ? fig.pause() : fig.play())));
  scrub.addEventListener('input', () =>
    fig.guard(() => {
      const m = fig.model.motion;
      if (!m) return;
      const [a, b] = m.timeDomain();
      fig.seek(a + ((b - a) * Number(scrub.value)) / 1000);
    }),
  );
  scheme.addEventListener('change', () => fig.guard(() => fig.setOptions({ scheme: scheme.value, s: null })));
  levels.addEventListener('input', () => fig.guard(() => fig.setOptions({ levels: Number(levels.value) })));
  frame.addEventListener('click', () => fig.guard(() => fig.viewer?.frameAll('user')));
}

/**
 * Keys, only while the canvas has the focus (the listener is on the canvas): Space plays or
 * pauses, A / Home frames, the arrows step to the previous or next key pose (editable: select
 * it), W / E the gizmo mode (editable), Escape deselects, else leaves the figure. A key taken
 * stops here; any other (and any with Ctrl, Meta or Alt) goes on to the page untouched.
 */
export function onKey(fig, e) {
  if (!fig.viewer || !fig.model.motion || e.ctrlKey || e.metaKey || e.altKey) return;
  const k = e.key;
  const n = fig.model.motion.poseCount;
  let handled = true;
  if (k === ' ') fig.playing ? fig.pause() : fig.play();
  else if (k === 'a' || k === 'A' || k === 'Home') fig.viewer.frameAll('user');
  else if (k === 'ArrowRight' || k === 'ArrowLeft') {
    const s = fig.model.selected;
    if (fig.editable) fig.select(k === 'ArrowRight' ? (s + 1) % n : (s - 1 + n) % n);
    else fig.stepKey(k === 'ArrowRight' ? 1 : -1);
  } else if (fig.editable && (k === 'w' || k === 'e')) {
    fig.model.mode = k === 'w' ? 'translate' : 'rotate';
    fig.viewer.rebuildGizmo();
    fig.viewer.requestDraw();
  } else if (k === 'Escape') {
    if (fig.model.selected >= 0) fig.select(-1);
    else e.target.blur();
  } else handled = false;
  if (handled) {
    e.preventDefault();
    e.stopPropagation();
  }
}

/** The control bar shows the playing state and the motion's scheme and levels. */
export function refreshChrome(fig) {
  const { play, scheme, levels } = fig.el;
  play.textContent = fig.playing ? '❚❚' : '▶';
  play.setAttribute('aria-label', fig.playing ? 'Pause' : 'Play');
  const m = fig.model.motion;
  if (m) {
    const o = m.options();
    scheme.value = o.scheme === 'j' ? '' : o.scheme;
    levels.value = String(o.levels);
  }
}

/**
 * The bar's time label: seconds with at most four digits (2 decimals below 10 s, 1 below 100 s,
 * none above), so the label fits its fixed width: 0.00 s, 12.3 s, 345 s.
 */
export function formatTime(t) {
  if (!Number.isFinite(t)) return '– s';
  const a = Math.abs(t);
  const digits = a < 9.995 ? 2 : a < 99.95 ? 1 : 0;
  return `${t < 0 ? '−' : ''}${a.toFixed(digits)} s`;
}

/** The playhead moved: {t, u, start, end}, times in seconds (the motion's own timing). */
export function timeChanged(fig, { t, u, start, end }) {
  fig.el.scrub.value = String(Math.round(((t - start) / Math.max(1e-12, end - start)) * 1000));
  fig.el.time.textContent = formatTime(t);
  fig.el.scrub.setAttribute('aria-valuetext', `${t.toFixed(2)} seconds`);
  fig.emit('time', { t, u, start, end });
  fig.emit('timeupdate', { t, u, start, end });
}
