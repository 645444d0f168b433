// Rectangles of the page: what part of the window the 3-D view keeps beside the chrome. A module
// of its own so that the view's framing (viewpoint.js) does not fetch the dock and its charts.

/**
 * Part `p` ({left, top, width, height}) less the rectangle `o` (a DOMRect) where they overlap:
 * `p` cut at one side of `o`, the side that keeps the most of it. `p` itself if they do not.
 */
export function without(p, o) {
  const right = p.left + p.width;
  const bottom = p.top + p.height;
  if (o.width === 0 || o.height === 0 || o.right <= p.left || o.left >= right || o.bottom <= p.top || o.top >= bottom) return p;
  const cuts = [
    { left: o.right, top: p.top, width: right - o.right, height: p.height },
    { left: p.left, top: p.top, width: o.left - p.left, height: p.height },
    { left: p.left, top: o.bottom, width: p.width, height: bottom - o.bottom },
    { left: p.left, top: p.top, width: p.width, height: o.top - p.top },
  ];
  let best = null;
  for (const c of cuts) if (c.width > 0 && c.height > 0 && (!best || c.width * c.height > best.width * best.height)) best = c;
  return best ?? { left: p.left, top: p.top, width: 0, height: 0 };
}

/**
 * The part of the window the page's chrome and the 3-D view share: the whole window, less the
 * lesson card while a lesson is open (css/lessons.css gives it a column or a sheet of its own).
 * @returns {{left: number, top: number, width: number, height: number}}
 */
export function stage() {
  const all = { left: 0, top: 0, width: window.innerWidth, height: window.innerHeight };
  const card = document.getElementById('lesson');
  if (!card || card.hidden || !document.body.classList.contains('lesson-open')) return all;
  return without(all, card.getBoundingClientRect());
}
