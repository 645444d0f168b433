// Messages to the user: the banner at the top (errors, warnings; a fatal start failure). Every
// message is also kept in app.errors, which the inspection API returns (tests read it). The
// part follows the motion to warn where its options give a poor result.

/** @type {import('../app.js').Part} */
export default {
  id: 'notices',
  create(app) {
    const banner = document.getElementById('banner');
    let timer;
    /** The key of the message shown (see show), or null. */
    let shown = null;
    /** The subdivision warnings last seen (joined), so each is said once. */
    let lastWarnings = '';

    /**
     * Where the options give a poor result without an error (Motion.warnings: the V1 4-point and
     * Jarek rules across half a turn, docs/math/subdivision.md §4), a notice naming the span;
     * shown again only when the warnings change.
     */
    function warnSubdivision() {
      const w = app.motion.warnings();
      const text = w.join(' ');
      if (text && text !== lastWarnings) {
        const more = w.length > 1 ? ` (${w.length - 1} more span${w.length > 2 ? 's' : ''} likewise)` : '';
        show(`Warning: ${w[0]}${more}`, 'warn');
      }
      lastWarnings = text;
    }

    /**
     * Shows `message`; 'error', 'warn' and 'info' (neutral) hide after 9 s, 'fatal' stays. A
     * `key` names what the message is about, so that `clear(key)` takes it away once that is
     * fixed.
     */
    function show(message, level = 'error', key = null) {
      app.errors.push(message);
      shown = key;
      banner.querySelector('.msg').textContent = message;
      banner.className = `banner ${level}`;
      banner.hidden = false;
      clearTimeout(timer);
      if (level !== 'fatal') timer = setTimeout(() => (banner.hidden = true), 9000);
    }

    return {
      show,

      /** Follows the motion (its subdivision warnings). */
      bind() {
        app.on('motion', warnSubdivision);
      },

      /** Hides the banner if it shows a message of `key` (the problem it named is gone). */
      clear(key) {
        if (shown !== key || banner.hidden || banner.classList.contains('fatal')) return;
        banner.hidden = true;
        shown = null;
        clearTimeout(timer);
      },

      /** The page cannot run (no graphics, no wasm): says why, for good. */
      fatal(e) {
        const msg = e?.message ?? String(e);
        banner.querySelector('.msg').textContent = msg;
        banner.className = 'banner fatal';
        banner.hidden = false;
        document.getElementById('backend').textContent = 'no graphics';
        app.errors.push(msg);
      },
    };
  },
};
