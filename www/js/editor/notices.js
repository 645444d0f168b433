// Messages to the user: the banner at the top (errors, warnings; a fatal start failure). Every
// message is also kept in app.errors, which the inspection API returns (tests read it).

/** @type {import('../app.js').Part} */
export default {
  id: 'notices',
  create(app) {
    const banner = document.getElementById('banner');
    let timer;
    return {
      /** Shows `message`; 'error', 'warn' and 'info' (neutral) hide after 9 s, 'fatal' stays. */
      show(message, level = 'error') {
        app.errors.push(message);
        banner.querySelector('.msg').textContent = message;
        banner.className = `banner ${level}`;
        banner.hidden = false;
        clearTimeout(timer);
        if (level !== 'fatal') timer = setTimeout(() => (banner.hidden = true), 9000);
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
