// Where the 3-D view looks from and how it fills the screen: the named camera views (front, top,
// side, iso: figure/camera.js CAMERA_PRESETS), the orthographic projection, fullscreen, and the
// toolbar's View menu that holds them with the theme toggle (editor/theme.js) and the picture
// exports (editor/media.js, which binds its entries after this part). Keys, with the
// view focused: Shift+F / Shift+T / Shift+S / Shift+I the named views, O orthographic
// (lower-case f and i stay the 4-point scheme and insert, editor/input.js).

import { without } from './rects.js';

/** Shift + key → named camera view. */
const PRESET_KEYS = { F: 'front', T: 'top', S: 'side', I: 'iso' };

/**
 * Makes `panel` a popover of toolbar `button`: the button opens and closes it (aria-expanded),
 * Esc or a press outside closes it and gives the focus back to the button. Returns
 * { open, close, toggle, isOpen }.
 */
export function menu(button, panel) {
  button.setAttribute('aria-expanded', 'false');
  button.setAttribute('aria-controls', panel.id);

  function place() {
    const r = button.getBoundingClientRect();
    const w = panel.offsetWidth;
    const h = panel.offsetHeight;
    const W = window.innerWidth;
    const H = window.innerHeight;
    const clamp = (v, lo, hi) => Math.max(lo, Math.min(hi, v));
    // Beside a toolbar on the left, else above the button (the phone's bottom toolbar).
    if (r.right + 8 + w <= W && r.left < W / 3 && r.top > 60 && r.bottom < H - 60) {
      panel.style.left = `${r.right + 8}px`;
      panel.style.top = `${clamp(r.top - 8, 8, H - h - 8)}px`;
    } else {
      panel.style.left = `${clamp(r.left + r.width / 2 - w / 2, 8, W - w - 8)}px`;
      panel.style.top = `${clamp(r.top - h - 8, 8, H - h - 8)}px`;
    }
  }

  function onDown(e) {
    if (!panel.contains(e.target) && !button.contains(e.target)) close(false);
  }

  function open() {
    panel.hidden = false;
    button.setAttribute('aria-expanded', 'true');
    button.classList.add('on');
    place();
    panel.querySelector('button, input, select')?.focus();
    document.addEventListener('pointerdown', onDown, true);
  }

  function close(refocus = true) {
    if (panel.hidden) return;
    panel.hidden = true;
    button.setAttribute('aria-expanded', 'false');
    button.classList.remove('on');
    document.removeEventListener('pointerdown', onDown, true);
    if (refocus) button.focus();
  }

  button.addEventListener('click', () => (panel.hidden ? open() : close()));
  panel.addEventListener('keydown', (e) => {
    if (e.key === 'Escape') {
      close();
      e.preventDefault();
      e.stopPropagation();
    }
  });
  window.addEventListener('resize', () => panel.hidden || place());
  return { open, close, toggle: () => (panel.hidden ? open() : close()), isOpen: () => !panel.hidden };
}

/** @type {import('../app.js').Part} */
export default {
  id: 'viewpoint',
  create(app) {
    const $ = (id) => document.getElementById(id);

    /** After the camera changed: redraw, the pose numbers to their handles again (ui refresh), save. */
    function moved() {
      app.viewer.cameraMoved();
      app.ui?.refresh();
      refresh();
      app.parts.session.autosave();
    }

    /**
     * Frames the control poses in the part of the 3-D view that the title card, the hint, the
     * toolbar, the timeline and an open panel leave free: the camera frames them in the whole
     * view, then backs off by the ratio of free to whole and moves so that the framed centre is
     * the free part's centre (a view from the top is as tall as the scene is deep, and would
     * reach under the header otherwise).
     */
    function frameFree() {
      app.viewer.frameAll();
      const canvas = app.viewer.canvas.getBoundingClientRect();
      let free = { left: canvas.left, top: canvas.top, width: canvas.width, height: canvas.height };
      for (const id of ['title', 'hint', 'toolbar', 'timeline', 'panel']) {
        const e = document.getElementById(id);
        if (!e || e.hidden) continue;
        const r = e.getBoundingClientRect();
        if (r.width > 0 && r.height > 0) free = without(free, r);
      }
      if (free.width < 80 || free.height < 80) return;
      const cam = app.viewer.camera;
      const ratio = Math.min(free.width / canvas.width, free.height / canvas.height);
      if (ratio < 1) cam.distance /= ratio;
      // Scene units per CSS pixel in the target's plane, after the back-off.
      const k = (2 * cam.halfHeight) / canvas.height;
      const dx = free.left + free.width / 2 - (canvas.left + canvas.width / 2);
      const dy = free.top + free.height / 2 - (canvas.top + canvas.height / 2);
      const { right, up } = cam.basis();
      cam.target = cam.target.map((t, i) => t - right[i] * dx * k + up[i] * dy * k);
    }

    /** Turns the camera to the named view ('front', 'top', 'side', 'iso'), framed in the free part of the view; false when unknown. */
    function preset(name) {
      if (!app.viewer.camera.preset(name)) return false;
      frameFree();
      moved();
      return true;
    }

    /** Orthographic (true) or perspective projection; the camera's setting is saved with the session. */
    function setOrtho(on) {
      app.viewer.camera.ortho = !!on;
      moved();
    }

    /** The element shown fullscreen: the page (the view and its controls stay usable). */
    const stage = () => document.documentElement;

    /** Enters or leaves fullscreen (Esc leaves too); a refusal shows a message. */
    async function toggleFullscreen() {
      try {
        if (document.fullscreenElement) await document.exitFullscreen();
        else if (stage().requestFullscreen) await stage().requestFullscreen({ navigationUI: 'hide' });
        else throw new Error('this browser has no fullscreen mode');
      } catch (e) {
        app.parts.notices.show(`Fullscreen is not available: ${e.message}`, 'warn');
      }
    }

    function refresh() {
      $('m-ortho')?.setAttribute('aria-pressed', String(!!app.viewer.camera?.ortho));
      $('m-fullscreen')?.setAttribute('aria-pressed', String(!!document.fullscreenElement));
    }

    function onKey(e) {
      const t = e.target;
      const onView = !t || t === app.viewer.canvas || t === document.body || t === document.documentElement;
      if (!onView || e.ctrlKey || e.metaKey || e.altKey) return;
      const name = e.shiftKey ? PRESET_KEYS[e.key] : null;
      if (name) preset(name);
      else if (e.key === 'o' || e.key === 'O') setOrtho(!app.viewer.camera.ortho);
      else return;
      e.preventDefault();
    }

    return {
      preset,
      /** Frames the control poses where the page's cards and bars leave the view free (toolbar Frame, key A). */
      frame() {
        frameFree();
        moved();
      },
      /** The same without saving the session (a preset, an import, a session without a camera). */
      fit() {
        frameFree();
        app.viewer.cameraMoved();
      },
      setOrtho,
      toggleFullscreen,
      refresh,
      /** The View menu's popover ({ open, close, toggle, isOpen }), once bound. */
      menu: null,
      bind() {
        this.menu = menu($('t-view'), $('view-menu'));
        for (const b of /** @type {NodeListOf<HTMLElement>} */ ($('view-menu').querySelectorAll('[data-camera]'))) {
          b.addEventListener('click', () => preset(b.dataset.camera));
        }
        $('m-ortho').addEventListener('click', () => setOrtho(!app.viewer.camera.ortho));
        $('m-fullscreen').addEventListener('click', () => toggleFullscreen());
        document.addEventListener('fullscreenchange', () => {
          // The view changed size: the resize observer redraws; the framing stays.
          app.viewer.invalidateSize();
          refresh();
        });
        window.addEventListener('keydown', onKey);
        refresh();
      },
    };
  },
};
