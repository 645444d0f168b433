// Messages to the user: the banner at the top (errors, warnings; a fatal start failure). Every
// message is also kept in app.errors, which the inspection API returns (tests read it).

/** @type {import('../app.js').Part} */
export default {
  id: 'notices',
  create(app) {
    const banner = document.getElementById('banner');
    let timer;
    /** The key of the message shown (see show), or null. */
    let shown = null;
    return {
      /**
       * Shows `message`; 'error', 'warn' and 'info' (neutral) hide after 9 s, 'fatal' stays. A
       * `key` names what the message is about, so that `clear(key)` takes it away once that is
       * fixed.
       */
      show(message, level = 'error', key = null) {
        app.errors.push(message);
        shown = key;
        banner.querySelector('.msg').textContent = message;
        banner.className = `banner ${level}`;
        banner.hidden = false;
        clearTimeout(timer);
        if (level !== 'fatal') timer = setTimeout(() => (banner.hidden = true), 9000);
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
