// A lesson text's field in the editor: what the teacher types (the lesson markup: paragraphs,
// **bold**, *italic*, `code`, $math$ and $$display math$$) and below it the live preview, typeset
// as the student will see it (format.js renderText, KaTeX). A formula that does not typeset
// says why in the preview instead.
import { renderText } from '../format.js';
import { el } from '../../dom.js';

/**
 * A labelled text field for the value at `path` of the lesson (data-path, for the problem list's
 * jumps); `onInput(text)` on each change. `rows` 1 makes a one-line input with no preview.
 * @returns {HTMLElement}
 */
export function textField(label, path, value, onInput, { rows = 4, preview = true, placeholder = '' } = {}) {
  const wrap = el('div', { class: 'le-field' });
  const l = el('label', {}, label);
  const input = rows > 1 ? el('textarea') : el('input');
  if (input instanceof HTMLTextAreaElement) input.rows = rows;
  else input.type = 'text';
  input.value = value ?? '';
  input.placeholder = placeholder;
  input.spellcheck = true;
  input.dataset.path = path;
  l.append(input);
  wrap.append(l);
  const out = el('div', { class: 'le-preview' });
  out.setAttribute('aria-label', `${label}: preview`);
  const show = () => {
    try {
      out.replaceChildren(renderText(input.value));
      out.classList.remove('bad');
    } catch (e) {
      out.replaceChildren(el('p', {}, `Cannot typeset: ${e.message}`));
      out.classList.add('bad');
    }
  };
  if (preview) {
    show();
    wrap.append(out);
  }
  input.addEventListener('input', () => {
    onInput(input.value);
    if (preview) show();
  });
  return wrap;
}
