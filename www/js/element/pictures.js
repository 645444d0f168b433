// Pictures of a figure from script, as a canvas gives them: toBlob(opts) and toDataURL(opts),
// drawn at `scale` times the drawing buffer (not scaled up), optionally transparent and with the
// gizmo. Bad options throw a RangeError naming the option (or the promise rejects with it).
import { picture } from '../figure/picture.js';

const TYPES = ['image/png', 'image/jpeg', 'image/webp'];
/** Largest picture scale (times the drawing buffer); the device's texture limit also applies. */
const MAX_SCALE = 8;
/** The options' type in the typings (npm/viewer.d.ts declares it, field by field). */
const PICTURE_OPTIONS = 'PictureOptions';

/**
 * A 2-D canvas of the current view of `fig`: `scale` times the drawing buffer (drawn at that
 * size), `transparent` background, `gizmo` to keep the selected pose's gizmo. Throws a
 * RangeError naming the option at fault, or when the figure has not started.
 */
function canvasOf(fig, { scale = 1, transparent = false, gizmo = false, type = 'image/png' } = {}) {
  if (!TYPES.includes(type)) throw new RangeError(`type: ${type} is not one of ${TYPES.join(', ')}`);
  if (!(typeof scale === 'number' && scale > 0 && scale <= MAX_SCALE)) throw new RangeError(`scale: ${scale} is not a number in (0, ${MAX_SCALE}]`);
  if (transparent && type === 'image/jpeg') throw new RangeError('transparent: image/jpeg has no transparency (use image/png or image/webp)');
  const v = fig.model.motion ? fig.viewer : null;
  if (!v?.renderer) {
    throw new RangeError(v?.suspended
      ? 'the figure rests while far from the viewport (it draws again when scrolled near)'
      : 'the figure has not started yet (a lazy figure starts near the viewport; await ready, or loading="eager")');
  }
  return picture(v, { scale, transparent: !!transparent, gizmo: !!gizmo });
}

function quality(q) {
  if (q === undefined) return undefined;
  if (!(typeof q === 'number' && q >= 0 && q <= 1)) throw new RangeError(`quality: ${q} is not a number in [0, 1]`);
  return q;
}

/** The picture as a data: URL (`quality` 0 to 1 for JPEG and WebP). */
export function toDataURL(fig, opts = {}) {
  const q = quality(opts.quality);
  return canvasOf(fig, opts).toDataURL(opts.type ?? 'image/png', q);
}

/** The picture as a Blob (a promise; rejects with the error canvasOf throws). */
export async function toBlob(fig, opts = {}) {
  const q = quality(opts.quality);
  const c = canvasOf(fig, opts);
  const blob = await new Promise((resolve) => c.toBlob(resolve, opts.type ?? 'image/png', q));
  if (!blob) throw new RangeError(`the picture could not be encoded as ${opts.type ?? 'image/png'}`);
  return blob;
}

/** @type {import('./options.js').Feature} */
export const picturesFeature = {
  name: 'pictures',
  doc: 'Pictures of the view from script.',
  methods: [
    {
      name: 'toBlob', params: [{ name: 'options', ts: PICTURE_OPTIONS, optional: true }], returns: 'Promise<Blob>',
      doc: 'A picture of the figure, drawn at the asked size.', call: toBlob,
    },
    {
      name: 'toDataURL', params: [{ name: 'options', ts: PICTURE_OPTIONS, optional: true }], returns: 'string',
      doc: 'The same picture as a data: URL (synchronous).', call: toDataURL,
    },
  ],
};
