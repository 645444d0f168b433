// When a figure starts and when it draws, for pages of many figures, slide decks and print:
// - loading: "lazy" (the default) starts a figure (wasm module, renderer, motion) only when it
//   comes within NEAR of the viewport, "eager" at once, and either only once its stylesheet
//   applies; a `poster` image shows until the first frame is drawn;
// - a started figure draws only while it is near the viewport (the IntersectionObserver) and
//   rendered visibly (not on a hidden slide: display, visibility or opacity, checkVisibility);
//   far from the viewport for SUSPEND_MS it frees its renderer (GPU data, and the WebGL context
//   a browser keeps only a few of) and makes a new one when it comes back;
// - print (print media or beforeprint): each started figure shows a still picture of its
//   current frame, a 2-D canvas, which prints where a WebGPU or WebGL canvas prints blank.
//   The print listeners are the figures' only ones outside their shadow trees: one set for the
//   page (added with the first figure, removed with the last), and they only take pictures.
import { picture } from '../figure/picture.js';
import { check, oneOf } from './options.js';

/** How near the viewport a lazy figure starts (and a started one keeps drawing). */
const NEAR = '200px 0px';
const LOADING = ['lazy', 'eager'];
/** How long a started figure stays far from the viewport before it frees its renderer. */
const SUSPEND_MS = 2000;

/** @type {import('./options.js').Feature} */
export const loadingFeature = {
  name: 'loading',
  doc: 'When the figure starts and draws: lazy start, poster, hidden slides, print.',
  options: [
    {
      name: 'loading', type: LOADING, default: 'lazy', parse: (v) => oneOf('loading', v, LOADING),
      doc: '`lazy`: start when the figure nears the viewport; `eager`: at once.',
    },
    { name: 'poster', type: 'string', doc: 'URL of an image shown until the figure starts.' },
  ],
  properties: [
    {
      name: 'ready', ts: 'Promise<void>',
      doc: 'Resolves when the figure is drawn (a lazy one: once near the viewport) or has shown its error; never rejects.',
      get: (fig) => fig.ready ?? Promise.resolve(),
    },
  ],
  changed(fig, patch) {
    if ('loading' in patch && patch.loading === 'eager') fig.wake?.();
    if ('poster' in patch) showPoster(fig);
  },
};

/** The `loading` option (checked): 'lazy' or 'eager'. */
export const loadingOf = (o) => check(loadingFeature, o).loading;

/**
 * Watches `fig`'s host with an IntersectionObserver (once): resolves fig.near when it nears the
 * viewport and tells the viewer whether to draw. Returns a promise that resolves when the
 * figure may start (at once for loading="eager" or a bad value, which fig.fail names).
 */
export function whenNear(fig) {
  let loading = 'lazy';
  try {
    loading = loadingOf(fig.opts);
  } catch (e) {
    fig.fail('loading', e.message, fig.opts.loading);
  }
  if (!fig.observer) {
    fig.observer = new IntersectionObserver(
      (entries) => {
        fig.onScreen = entries[entries.length - 1].isIntersecting;
        clearTimeout(fig.suspendTimer);
        if (fig.onScreen) {
          fig.wake?.();
          fig.resume();
        } else fig.suspendTimer = setTimeout(() => fig.suspend(), SUSPEND_MS);
        fig.viewer?.setVisible(fig.onScreen);
      },
      { rootMargin: NEAR },
    );
    fig.observer.observe(fig.host);
  }
  if (loading === 'eager' || fig.onScreen) return Promise.resolve();
  return new Promise((resolve) => {
    fig.wake = () => {
      fig.wake = null;
      resolve();
    };
  });
}

/**
 * Resolves once `fig`'s stylesheet applies: at once for a <style> (a bundle's inlined text) or a
 * <link> already loaded, else on its load, or on its failure, which the figure names (it goes on
 * unstyled). Until then the shadow tree has no layout of its own (a 300 × 150 canvas, bare
 * controls), so the renderer, the first frame and `ready` wait for it: a host that measures the
 * figure once it is ready measures the figure it shows. Called when the figure is built, so that
 * a load that ends before the figure starts is heard.
 */
export function whenStyled(fig) {
  const node = fig.el.stylesheet;
  if (!(node instanceof HTMLLinkElement) || node.sheet) return Promise.resolve();
  return new Promise((resolve) => {
    const done = (e) => {
      node.removeEventListener('load', done);
      node.removeEventListener('error', done);
      if (e.type === 'error') {
        fig.unstyled = `The figure's stylesheet did not load (${node.href}).`;
        fig.fail(null, fig.unstyled);
      }
      resolve();
    };
    node.addEventListener('load', done);
    node.addEventListener('error', done);
  });
}

/** Draws only while the canvas is rendered visibly (a hidden slide's figure stops). */
export function drawWhenShown(viewer) {
  viewer.isShown = () =>
    typeof viewer.canvas.checkVisibility !== 'function' ||
    viewer.canvas.checkVisibility({ opacityProperty: true, visibilityProperty: true });
}

/** Shows the poster (the `poster` option, a URL) until the first frame; none without it. */
export function showPoster(fig) {
  const { poster } = fig.el;
  const url = fig.opts.poster;
  if (!url || fig.drawn) {
    poster.hidden = true;
    poster.removeAttribute('src');
    return;
  }
  try {
    poster.src = new URL(String(url), document.baseURI).href;
    poster.hidden = false;
  } catch {
    fig.fail('poster', 'not a URL', url);
  }
}

// ---------------------------------------------------------------- print

const printing = new Set();
let media = null;
/** Whether the page is in print (print media or between beforeprint and afterprint). */
let inPrint = false;
const before = () => still(true);
const after = () => still(false);
const change = (e) => still(e.matches);

/** Whether the page is printing: a figure keeps its renderer until print is over. */
export const isPrinting = () => inPrint;

/** Keeps a still picture of `fig` (before its renderer is freed): print shows it. */
export function keepStill(fig) {
  try {
    fig.kept = picture(fig.viewer);
    fig.kept.setAttribute('part', 'still');
  } catch {
    fig.kept = null;
  }
}

/**
 * In print: every figure shows a picture of its current frame, or the one kept when its renderer
 * was freed (a suspended figure, or one still making its new renderer), or else the picture it
 * already shows; a figure is never left blank because it was between two states. Out of print:
 * the pictures go, and the figures far from the viewport may free their renderers again.
 */
function still(on) {
  inPrint = on;
  for (const fig of printing) {
    const box = fig.el.still;
    if (!on) {
      box.replaceChildren();
      box.hidden = true;
      if (fig.onScreen === false && fig.viewer?.renderer) {
        clearTimeout(fig.suspendTimer);
        fig.suspendTimer = setTimeout(() => fig.suspend(), SUSPEND_MS);
      }
      continue;
    }
    let shot = null;
    if (fig.viewer?.renderer && fig.model.motion) {
      try {
        shot = picture(fig.viewer);
        shot.setAttribute('part', 'still');
      } catch {
        // No picture of the current frame: the kept one, if any.
      }
    }
    shot ??= fig.kept;
    if (shot) {
      box.replaceChildren(shot);
      box.hidden = false;
    }
  }
}

/** Takes part in printing: a still picture of `fig` in print media (until forget). */
export function printable(fig) {
  if (!printing.size) {
    window.addEventListener('beforeprint', before);
    window.addEventListener('afterprint', after);
    media = window.matchMedia('print');
    media.addEventListener('change', change);
  }
  printing.add(fig);
}

/** No longer takes part in printing (a disposed figure). */
export function forget(fig) {
  if (!printing.delete(fig) || printing.size) return;
  window.removeEventListener('beforeprint', before);
  window.removeEventListener('afterprint', after);
  media?.removeEventListener('change', change);
  media = null;
  inPrint = false;
}
