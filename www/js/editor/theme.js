// The light and dark themes: the page's chrome (css/style.css, the block of `data-theme="dark"`
// variables on <html>) and the 3-D view's background and line colours (Viewer.setDark). The
// setting is app.view.theme — 'auto' follows the system's `prefers-color-scheme` (and its
// changes), 'light' and 'dark' hold — kept with the session and the share link like every view
// setting; the View menu's toggle (and D with the view focused) picks the opposite of what is
// shown.
//
// The part applies the theme whenever app.view.theme changes (the App's 'view' signal), so a
// restored session, an undo or a share link shows its theme without a call of its own.

/** The values of app.view.theme. */
export const THEMES = ['auto', 'light', 'dark'];

/** @type {import('../app.js').Part} */
export default {
  id: 'theme',
  create(app) {
    const query = window.matchMedia?.('(prefers-color-scheme: dark)');
    let bound = false;

    /** Whether the theme shown is dark. */
    const isDark = () => app.view.theme === 'dark' || (app.view.theme === 'auto' && !!query?.matches);

    function apply() {
      const dark = isDark();
      document.documentElement.dataset.theme = dark ? 'dark' : 'light';
      // Form controls and scroll bars follow as well.
      document.documentElement.style.colorScheme = dark ? 'dark' : 'light';
      if (bound) {
        app.viewer.setDark(dark);
        const b = document.getElementById('m-theme');
        b?.setAttribute('aria-pressed', String(dark));
      }
    }

    // The App keeps the current theme for any other value (an old or hand-made session).
    app.on('view', (keys) => keys.includes('theme') && apply());
    query?.addEventListener?.('change', () => app.view.theme === 'auto' && apply());
    // The chrome at once (no light flash before the view starts); the canvas once bound.
    apply();

    /** Shows the other theme than the one shown now (an explicit choice, undoable like every view setting). */
    function toggle() {
      app.run('setView', 'theme', isDark() ? 'light' : 'dark');
    }

    function onKey(e) {
      const t = e.target;
      const onView = !t || t === app.viewer.canvas || t === document.body || t === document.documentElement;
      if (!onView || e.ctrlKey || e.metaKey || e.altKey || e.shiftKey) return;
      if (e.key !== 'd' && e.key !== 'D') return;
      toggle();
      e.preventDefault();
    }

    return {
      isDark,
      toggle,
      bind() {
        bound = true;
        apply();
        document.getElementById('m-theme').addEventListener('click', toggle);
        window.addEventListener('keydown', onKey);
      },
    };
  },
};
