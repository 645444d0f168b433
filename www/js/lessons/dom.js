// The one DOM helper of the lesson player's files: an element with a class and a text.

/** A new `tag` element with class `cls` and text `text` (each optional). */
export const el = (tag, cls, text) => {
  const e = document.createElement(tag);
  if (cls) e.className = cls;
  if (text !== undefined) e.textContent = text;
  return e;
};
