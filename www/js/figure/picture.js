// Pictures of the 3-D view: the view drawn again at a scale of its drawing buffer (2× is drawn at
// twice the size with lines twice as wide, not scaled up) and copied to a 2-D canvas in the same
// task (Viewer.snapshot: a WebGPU canvas is readable only until its frame is presented). A
// transparent background comes from two frames, on black and on white: where they differ the
// background shows through (alpha = 1 − the difference), and the colour is the black frame's
// divided by alpha. The renderer clears to an opaque colour, so this is the one way to get the
// background out without a second render target.

/** Background of the transparent picture's two frames (sRGB). */
const BLACK = [0, 0, 0];
const WHITE = [1, 1, 1];

/** A 2-D canvas holding a copy of `source` (drawn in the same task as the frame). */
function copyOf(source) {
  const c = document.createElement('canvas');
  c.width = source.width;
  c.height = source.height;
  c.getContext('2d', { willReadFrequently: true }).drawImage(source, 0, 0);
  return c;
}

/** The picture of the two frames on black and on white with the background made transparent. */
function unmatte(onBlack, onWhite) {
  const { width: w, height: h } = onBlack;
  const ctx = onBlack.getContext('2d', { willReadFrequently: true });
  const black = ctx.getImageData(0, 0, w, h);
  const white = onWhite.getContext('2d', { willReadFrequently: true }).getImageData(0, 0, w, h).data;
  const d = black.data;
  for (let i = 0; i < d.length; i += 4) {
    // Per channel white − black = 255 (1 − alpha); the mean of the three is the least noisy.
    const diff = (white[i] - d[i] + white[i + 1] - d[i + 1] + white[i + 2] - d[i + 2]) / 3;
    const a = Math.max(0, Math.min(255, 255 - diff));
    if (a > 0) {
      const k = 255 / a;
      d[i] = Math.min(255, d[i] * k);
      d[i + 1] = Math.min(255, d[i + 1] * k);
      d[i + 2] = Math.min(255, d[i + 2] * k);
    }
    d[i + 3] = a;
  }
  ctx.putImageData(black, 0, 0);
  return onBlack;
}

/**
 * A 2-D canvas with the view of `viewer` drawn at `scale` times its drawing buffer, on a
 * transparent background when `transparent`; without the selected pose's gizmo and the hover
 * highlight unless `gizmo`. Throws as Viewer.snapshot (nothing changed).
 */
export function picture(viewer, { scale = 1, transparent = false, gizmo = false } = {}) {
  const { model } = viewer;
  const kept = { selected: model.selected, hover: model.hover, hoverPose: model.hoverPose };
  const hide = !gizmo && (kept.selected >= 0 || kept.hover || kept.hoverPose >= 0);
  if (hide) {
    Object.assign(model, { selected: -1, hover: null, hoverPose: -1 });
    viewer.rebuildControls();
  }
  try {
    const frames = [];
    viewer.snapshot(scale, transparent ? [BLACK, WHITE] : [null], (canvas) => frames.push(copyOf(canvas)));
    return transparent ? unmatte(frames[0], frames[1]) : frames[0];
  } finally {
    if (hide) {
      Object.assign(model, kept);
      viewer.rebuildControls();
    }
  }
}
