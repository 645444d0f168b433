// A figure's chrome: its shadow tree (canvas, control bar, message, caption), the bar's
// listeners and display, and the keys of a focused figure. Built node by node (no HTML strings,
// no inline style), so a strict CSP suffices.

/**
 * The figure's shadow tree in `host` (emptied first): the canvas, the control bar, the message
 * and the caption slot, with the stylesheet. Returns {root, el} (el: the parts by name).
 */
export function buildChrome(host) {
  const root = host.shadowRoot ?? host.attachShadow({ mode: 'open' });
  root.replaceChildren();
  const link = document.createElement('link');
  link.rel = 'stylesheet';
  link.href = new URL('../../css/screw-bender.css', import.meta.url).href;
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
    node('canvas', { tabindex: '0', part: 'canvas', 'aria-label': '3-D figure of a rigid motion' }),
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
    msg: fig.querySelector('.msg'),
  };
  return { root, el };
}

/** The control bar's listeners (on the figure's own elements only). */
export function bindChrome(fig) {
  const { play, scrub, scheme, levels, frame } = fig.el;
  play.addEventListener('click', () => fig.guard(() => (fig.playing ? fig.pause() : fig.play())));
  scrub.addEventListener('input', () =>
    fig.guard(() => {
      const m = fig.model.motion;
      if (!m) return;
      const [a, b] = m.timeDomain();
      fig.seek(a + ((b - a) * Number(scrub.value)) / 1000);
    }),
  );
  scheme.addEventListener('change', () => fig.guard(() => fig.setOptions({ scheme: scheme.value, j: null })));
  levels.addEventListener('input', () => fig.guard(() => fig.setOptions({ levels: Number(levels.value) })));
  frame.addEventListener('click', () => fig.guard(() => fig.viewer?.frameAll()));
}

/** Keys, only while the canvas has the focus (the listener is on the canvas). */
export function onKey(fig, e) {
  if (!fig.viewer || !fig.model.motion) return;
  const k = e.key;
  const n = fig.model.motion.poseCount;
  let handled = true;
  if (k === ' ') fig.playing ? fig.pause() : fig.play();
  else if (k === 'a' || k === 'Home') fig.viewer.frameAll();
  else if (fig.editable && (k === 'ArrowRight' || k === 'ArrowLeft')) {
    const s = fig.model.selected;
    fig.select(k === 'ArrowRight' ? (s + 1) % n : (s - 1 + n) % n);
  } else if (fig.editable && (k === 'w' || k === 'e')) {
    fig.model.mode = k === 'w' ? 'translate' : 'rotate';
    fig.viewer.rebuildGizmo();
    fig.viewer.requestDraw();
  } else if (fig.editable && k === 'Escape') fig.select(-1);
  else handled = false;
  if (handled) e.preventDefault();
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
}
