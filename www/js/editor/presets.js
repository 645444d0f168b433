// The preset chooser: human names for the scene presets, with the paper's label and figure as
// a subtitle and each preset's one-line description, in a dialog opened from the panel. Also
// the first-visit hint (a short note on how to start, dismissed for good).

import { foldPanelOnSmallScreens } from './fold.js';

/** The preset a first visit shows. */
export const DEFAULT_SCENE = 'l_cycle_rotated';

/** The name of a preset in words (the core's, `presets()[i].name`). */
export function presetName(info) {
  return info.name;
}

/** The subtitle of a preset: its label in the paper's scene list and its figure. */
export function presetSubtitle(info) {
  return `${info.label} · ${info.figure}`;
}

/** localStorage key of the dismissed first-visit hint. */
const HINT_KEY = 'screwbender.hintDismissed';

/** @type {import('../app.js').Part} */
export default {
  id: 'presets',
  create(app) {
    const dlg = document.getElementById('presets');
    const list = dlg.querySelector('.preset-list');
    let opener = null;

    function close() {
      dlg.hidden = true;
      opener?.focus?.();
    }

    /** Opens the chooser; the focus goes to the current preset and back to `from` on close. */
    function open(from) {
      opener = from ?? document.activeElement;
      list.replaceChildren();
      let current = null;
      for (const s of app.scenes) {
        const b = document.createElement('button');
        b.type = 'button';
        b.className = 'preset';
        b.dataset.id = s.id;
        const name = document.createElement('span');
        name.className = 'name';
        name.textContent = presetName(s);
        const sub = document.createElement('span');
        sub.className = 'sub';
        sub.textContent = presetSubtitle(s);
        const desc = document.createElement('span');
        desc.className = 'desc';
        desc.textContent = s.description;
        b.append(name, sub, desc);
        if (s.id === app.view.scene) {
          b.classList.add('on');
          b.setAttribute('aria-current', 'true');
          current = b;
        }
        b.onclick = () => {
          close();
          app.run('loadPreset', s.id);
          // Phones: the picked preset in view, not the panel it was picked from.
          foldPanelOnSmallScreens(app);
        };
        list.append(b);
      }
      dlg.hidden = false;
      /** @type {HTMLElement | null} */ (current ?? list.firstElementChild)?.focus();
    }

    dlg.addEventListener('keydown', (e) => {
      if (e.key === 'Escape') {
        e.preventDefault();
        e.stopPropagation();
        close();
      }
    });
    dlg.addEventListener('click', (e) => {
      if (e.target === dlg) close();
    });
    /** @type {HTMLElement} */ (dlg.querySelector('.close')).onclick = close;

    const hint = document.getElementById('hint');
    return {
      open,
      close,
      /** Shows the first-visit hint unless it was dismissed before. */
      bind() {
        let dismissed = true;
        try {
          dismissed = localStorage.getItem(HINT_KEY) === '1';
        } catch {
          // No storage (private mode): show the hint each visit.
          dismissed = false;
        }
        hint.hidden = dismissed;
        const dismiss = () => {
          hint.hidden = true;
          try {
            localStorage.setItem(HINT_KEY, '1');
          } catch {
            // Nothing to remember it in.
          }
        };
        /** @type {HTMLElement} */ (hint.querySelector('.close')).onclick = () => {
          dismiss();
          app.viewer.canvas?.focus();
        };
        // The hint has done its job once the visitor edits or turns the view: it goes then (a
        // drag of more than a few pixels on the canvas, a wheel zoom, or any undoable edit).
        if (dismissed) return;
        const version = app.history.version;
        let down = null;
        const done = () => {
          if (hint.hidden) return;
          dismiss();
          for (const [t, type, f] of listeners) t.removeEventListener(type, f, true);
        };
        const edited = () => app.history.version !== version && done();
        /** @type {[EventTarget, string, (e: PointerEvent) => void][]} */
        const listeners = [
          [app.viewer.canvas, 'pointerdown', (e) => (down = { x: e.clientX, y: e.clientY })],
          [app.viewer.canvas, 'pointermove', (e) => down && Math.hypot(e.clientX - down.x, e.clientY - down.y) > 6 && done()],
          [window, 'pointerup', () => {
            down = null;
            setTimeout(edited, 0);
          }],
          [app.viewer.canvas, 'wheel', done],
          [window, 'keyup', () => setTimeout(edited, 0)],
          [document, 'change', () => setTimeout(edited, 0)],
        ];
        for (const [t, type, f] of listeners) t?.addEventListener(type, f, true);
      },
    };
  },
};
