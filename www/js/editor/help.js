// The help overlay (#help): the keys and gestures, opened by ? or the toolbar's Help button.

/**
 * Wires the overlay's close button and backdrop; returns {toggle(show?)}.
 * @param {import('../app.js').App} app
 */
export function buildHelp(app) {
  const h = document.getElementById('help');
  /** @type {Element | null} */
  let focusBefore = null;
  /** Shows or hides the overlay (no argument: the other way); the focus goes to its close button and back. */
  function toggle(show) {
    const wasHidden = h.hidden;
    h.hidden = show === undefined ? !h.hidden : !show;
    if (wasHidden && !h.hidden) {
      focusBefore = document.activeElement;
      /** @type {HTMLElement} */ (h.querySelector('.help-close')).focus();
    } else if (!wasHidden && h.hidden && h.contains(document.activeElement)) {
      /** @type {HTMLElement} */ (focusBefore ?? app.viewer.canvas)?.focus?.();
    }
  }
  /** @type {HTMLElement} */ (h.querySelector('.help-close')).onclick = () => toggle(false);
  h.onclick = (e) => {
    if (e.target === h) toggle(false);
  };
  return { toggle };
}
