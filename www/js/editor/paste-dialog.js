// The paste dialog (#paste): a motion document pasted as JSON text, loaded on "Load".

/**
 * Wires the dialog's buttons; returns {open(text?, title?)}.
 * @param {import('../app.js').App} app
 */
export function buildPasteDialog(app) {
  const dlg = document.getElementById('paste');
  function open(text = '', title = 'Paste a motion document (JSON):') {
    dlg.querySelector('h2').textContent = title;
    const ta = dlg.querySelector('textarea');
    ta.value = text;
    dlg.hidden = false;
    ta.focus();
    ta.select();
  }
  /** @type {HTMLElement} */ (dlg.querySelector('[data-act=load]')).onclick = () => {
    if (app.parts.files.importJson(dlg.querySelector('textarea').value)) dlg.hidden = true;
  };
  /** @type {HTMLElement} */ (dlg.querySelector('[data-act=cancel]')).onclick = () => (dlg.hidden = true);
  return { open };
}
