// The DOM helpers of the lesson player's and the lesson editor's files: an element with a class
// and a text, and a labelled button.

/** A new `tag` element with class `cls` and text `text` (each optional). */
export const el = (tag, cls, text) => {
  const e = document.createElement(tag);
  if (cls) e.className = cls;
  if (text !== undefined) e.textContent = text;
  return e;
};

/** A `type="button"` with `text`, the tooltip and accessible name `title`, and `onClick`. */
export function button(text, title, onClick, cls = '') {
  const b = el('button', cls, text);
  b.type = 'button';
  if (title) {
    b.title = title;
    b.setAttribute('aria-label', title);
  }
  b.addEventListener('click', onClick);
  return b;
}
