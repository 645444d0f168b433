// The page's DOM helpers, shared by the editor's dialogs and panels, the analysis views and the
// lesson player and editor: an element from its tag, properties and children, and a labelled
// button. Apart from the charts (dock/plot.js), so a dialog or a lesson card needs no uPlot.

/**
 * A new `tag` element. `props`: `class` (left out when empty), `style` (CSS text), `on<event>`
 * listeners, DOM properties, and attributes for the other keys. `children`: nodes, or values
 * appended as text (never parsed as HTML: names and lesson texts may come from files); arrays
 * are flattened one level, null and undefined left out.
 * @param {string} tag
 * @param {Record<string, any>} [props]
 * @param {...any} children
 * @returns {any}
 */
export function el(tag, props = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(props)) {
    if (k === 'class') {
      if (v) e.className = v;
    } else if (k === 'style') e.style.cssText = v;
    else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
    else if (k in e) e[k] = v;
    else e.setAttribute(k, v);
  }
  for (const c of children.flat()) if (c !== null && c !== undefined) e.append(c instanceof Node ? c : String(c));
  return e;
}

/**
 * A `type="button"` with `text`, the tooltip and accessible name `title`, and `onClick`.
 * @param {string} text
 * @param {string} title
 * @param {(e: MouseEvent) => void} onClick
 * @param {string} [cls]
 */
export function button(text, title, onClick, cls = '') {
  const b = el('button', { class: cls }, text);
  b.type = 'button';
  if (title) {
    b.title = title;
    b.setAttribute('aria-label', title);
  }
  b.addEventListener('click', onClick);
  return b;
}
