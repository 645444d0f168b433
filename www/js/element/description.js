// What a figure says to assistive technology: its accessible name (`alt`, on the canvas) and
// the words of its polite live region for each change (playing, paused, a pose selected or
// moved, the scheme and levels), in the names the figure shows.

/** The canvas's accessible name without an `alt`. */
export const DEFAULT_NAME = '3-D figure of a rigid motion';

const SCHEME_NAMES = { bspline: 'B-spline', fourpoint: '4-point', jarek: 'Jarek', j: 'J_s' };

/** "4-point scheme" and the like, from a motion's options. */
export function schemeName(o) {
  return `${SCHEME_NAMES[o.scheme] ?? o.scheme} scheme${o.scheme === 'j' ? ` (s = ${o.s})` : ''}`;
}

const fmt = (v) => v.map((x) => (Math.abs(x) < 5e-3 ? 0 : x).toFixed(2)).join(', ');

/** "Pose 3 at (1.00, 2.00, 0.00)". */
export function describePose(motion, k) {
  return `Pose ${k} at (${fmt(motion.pose(k).origin)})`;
}

/** Says `text` in the figure's polite live region. */
export function say(fig, text) {
  fig.el.live.textContent = text;
}

/** @type {import('./options.js').Feature} */
export const descriptionFeature = {
  name: 'description',
  doc: 'The accessible name and the live region.',
  options: [
    {
      name: 'alt', type: 'string', default: DEFAULT_NAME, early: true, parse: (v) => (String(v).trim() === '' ? DEFAULT_NAME : String(v)),
      doc: 'The figure\'s accessible name (a text alternative for screen readers).',
    },
  ],
  // The name applies before the figure starts (a lazy figure is named while it waits).
  early(fig, v) {
    const { canvas } = fig.el;
    if (canvas.getAttribute('aria-label') !== v.alt) canvas.setAttribute('aria-label', v.alt);
  },
};
