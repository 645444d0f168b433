// The Undo menu: the edits Undo takes back and Redo makes again, each by the label of its command
// (editor/commands.js), newest first. A right click or a long press on Undo or Redo opens it (the
// context-menu key too, with either focused); choosing an entry undoes or redoes up to and
// including it. Undo's and Redo's tooltips name the next edit.

/** Entries listed per side. */
const LISTED = 12;
/** A press this long (ms) on Undo or Redo opens the menu (touch screens have no right click). */
const LONG_PRESS_MS = 500;

/** @type {import('../app.js').Part} */
export default {
  id: 'undoMenu',
  create(app) {
    const $ = (id) => document.getElementById(id);
    let menu = null;

    function build() {
      menu = document.createElement('div');
      menu.id = 'undo-menu';
      menu.className = 'popover';
      menu.setAttribute('role', 'menu');
      menu.setAttribute('aria-label', 'Undo history');
      menu.hidden = true;
      menu.addEventListener('keydown', (e) => {
        const items = [...menu.querySelectorAll('button')];
        const k = items.indexOf(/** @type {HTMLButtonElement} */ (document.activeElement));
        if (e.key === 'Escape') close(true);
        else if (e.key === 'ArrowDown') items[(k + 1) % items.length]?.focus();
        else if (e.key === 'ArrowUp') items[(k - 1 + items.length) % items.length]?.focus();
        else return;
        e.preventDefault();
        e.stopPropagation();
      });
      document.body.append(menu);
    }

    /** One side of the menu: `labels` newest first; choosing entry k steps k + 1 times. */
    function side(title, labels, step) {
      const h = document.createElement('p');
      h.className = 'pop-note';
      h.textContent = labels.length ? title : `Nothing to ${title.toLowerCase()}`;
      /** @type {HTMLElement[]} */
      const out = [h];
      labels.slice(0, LISTED).forEach((label, k) => {
        const b = document.createElement('button');
        b.type = 'button';
        b.setAttribute('role', 'menuitem');
        b.dataset.side = title.toLowerCase();
        b.dataset.steps = String(k + 1);
        b.textContent = label;
        b.addEventListener('click', () => {
          for (let i = 0; i <= k; i++) step();
          close(true);
        });
        out.push(b);
      });
      return out;
    }

    function onDown(e) {
      if (menu && !menu.contains(e.target)) close(false);
    }

    /** Opens the menu beside `anchor` (the Undo or Redo button). */
    function open(anchor = $('t-undo')) {
      if (!menu) build();
      menu.replaceChildren(...side('Undo', app.history.undoLabels, () => app.parts.session.undo()), ...side('Redo', app.history.redoLabels, () => app.parts.session.redo()));
      menu.hidden = false;
      const r = anchor.getBoundingClientRect();
      const W = window.innerWidth;
      const H = window.innerHeight;
      const clamp = (v, lo, hi) => Math.max(lo, Math.min(hi, v));
      // Beside a toolbar on the left, else above the button (the phone's bottom toolbar).
      const beside = r.right + 8 + menu.offsetWidth <= W && r.left < W / 3;
      menu.style.left = `${beside ? r.right + 8 : clamp(r.left, 8, W - menu.offsetWidth - 8)}px`;
      menu.style.top = `${beside ? clamp(r.top - 8, 8, H - menu.offsetHeight - 8) : clamp(r.top - menu.offsetHeight - 8, 8, H - menu.offsetHeight - 8)}px`;
      /** @type {HTMLElement | null} */ (menu.querySelector('button'))?.focus();
      document.addEventListener('pointerdown', onDown, true);
    }

    function close(refocus) {
      if (!menu || menu.hidden) return;
      menu.hidden = true;
      document.removeEventListener('pointerdown', onDown, true);
      if (refocus) $('t-undo')?.focus();
    }

    /** Undo's and Redo's tooltips: the edit each takes back or makes again. */
    function titles() {
      const u = app.history.undoLabels[0];
      const r = app.history.redoLabels[0];
      $('t-undo').title = u ? `Undo: ${u} (Ctrl+Z; right-click or hold for the list)` : 'Undo (Ctrl+Z)';
      $('t-redo').title = r ? `Redo: ${r} (Ctrl+Shift+Z; right-click or hold for the list)` : 'Redo (Ctrl+Shift+Z)';
    }

    return {
      open,
      close: () => close(false),
      /** Whether the menu shows. */
      get isOpen() {
        return !!menu && !menu.hidden;
      },
      titles,
      bind() {
        for (const id of ['t-undo', 't-redo']) {
          const b = $(id);
          b.addEventListener('contextmenu', (e) => {
            e.preventDefault();
            open(b);
          });
          let timer = 0;
          let held = false;
          b.addEventListener('pointerdown', (e) => {
            if (e.pointerType === 'mouse') return;
            held = false;
            timer = window.setTimeout(() => {
              held = true;
              open(b);
            }, LONG_PRESS_MS);
          });
          // The release after a long press opened the menu: no Undo besides.
          b.addEventListener(
            'click',
            (e) => {
              if (!held) return;
              held = false;
              e.stopImmediatePropagation();
              e.preventDefault();
            },
            true,
          );
          const cancel = () => clearTimeout(timer);
          b.addEventListener('pointerup', cancel);
          b.addEventListener('pointercancel', cancel);
          b.addEventListener('pointerleave', cancel);
        }
        app.on('motion', titles);
        titles();
      },
    };
  },
};
