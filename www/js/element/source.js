// Where a figure's motion comes from: `src` (a motion .json or .glb/.gltf/.csv file), `share` (a
// share-link payload), an inline JSON document, or `preset`; the `document` and `motion`
// properties; and the opt-in saved copy (`persist`), the only storage a figure ever touches. A
// change of any source reloads the figure (figure.js).
import { OptionError } from './options.js';
import { loadFiles } from './wasm.js';

/** @type {import('./options.js').Feature} */
export const sourceFeature = {
  name: 'source',
  doc: 'The motion shown: the first present of src, share, an inline JSON child, preset.',
  options: [
    { name: 'preset', type: 'string', doc: 'A preset id, e.g. `l_cycle_rotated` (the source when none of src, share or an inline JSON child is given).' },
    { name: 'scene', type: 'string', deprecated: 'Renamed to `preset`.', doc: 'Former name of `preset`, kept for one release.' },
    { name: 'src', type: 'string', doc: 'URL of a motion `.json` document or a `.glb` / `.gltf` / `.csv` file.' },
    { name: 'share', type: 'string', doc: 'A playground share-link payload (the part after `#s=`, or the whole link).' },
    { name: 'persist', type: 'string', doc: 'A localStorage key: the figure saves its edits there and restores them (never without it).' },
  ],
  properties: [
    {
      name: 'document', ts: 'MotionDocumentInput | object | null', doc: 'The motion document shown (null before it loads); set to show another.',
      get: (fig) => fig.model.motion?.toDocument() ?? null,
      set: (fig, doc) => fig.setOptions({ inline: JSON.stringify(doc), src: null, share: null, preset: null }),
    },
    { name: 'motion', ts: 'Motion | null', doc: 'The Motion handle of the math module (read-only).', get: (fig) => fig.model.motion },
  ],
};

/** Largest motion file `src` may name (bytes); larger ones are refused before parsing. */
const MAX_SRC_BYTES = 32 << 20;

/**
 * The module that reads glTF and CSV motion files: `w` itself when it has file import, else the
 * files module (wasm.js), so that the renderer module can leave the glTF document model out.
 */
const fileImporter = (w) => (w.importMotionFile ? w : loadFiles());

/**
 * The motion document (and display hints) of the source that the options `o` name, with the
 * wasm module `w` and the preset list `scenes`. Throws an OptionError naming the source.
 */
export async function fetchSource(o, w, scenes) {
  if (o.src) {
    let url;
    try {
      url = new URL(o.src, document.baseURI);
    } catch {
      throw new OptionError('src', o.src, 'not a URL');
    }
    let res;
    try {
      res = await fetch(url);
    } catch (e) {
      throw new OptionError('src', o.src, `unreachable (${e.message})`);
    }
    if (!res.ok) throw new OptionError('src', o.src, `HTTP ${res.status}`);
    const bytes = new Uint8Array(await res.arrayBuffer());
    if (bytes.length > MAX_SRC_BYTES) throw new OptionError('src', o.src, `${bytes.length} bytes, more than ${MAX_SRC_BYTES}`);
    const name = url.pathname.split('/').pop() || 'motion.json';
    try {
      if (/\.(glb|gltf|csv)$/i.test(name)) return { doc: (await fileImporter(w)).importMotionFile(name, bytes) };
      return { doc: JSON.parse(new TextDecoder().decode(bytes)) };
    } catch (e) {
      throw new OptionError('src', o.src, e.message);
    }
  }
  if (o.share) {
    // Imported only for share payloads (most figures name a file or a preset).
    const { decodeHash } = await import('../share-link.js');
    let s;
    try {
      s = decodeHash(String(o.share).replace(/^.*#s=/, ''));
    } catch (e) {
      const v = String(o.share);
      throw new OptionError('share', v.length > 40 ? `${v.slice(0, 40)}…` : v, e.message);
    }
    return { doc: s.document, options: s.options, view: s.view, camera: s.camera };
  }
  if (o.inline != null) {
    try {
      return { doc: JSON.parse(o.inline) };
    } catch (e) {
      throw new OptionError('script', 'application/json', `not JSON: ${e.message}`);
    }
  }
  const id = o.preset || 'l_cycle_rotated';
  const info = scenes.find((s) => s.id === id);
  if (!info) throw new OptionError('preset', id, `unknown preset (known: ${scenes.map((s) => s.id).join(', ')})`);
  return { scene: id };
}

/** The figure saved under the `persist` key (opt-in), or null. */
export function restorePersisted(key) {
  if (!key) return null;
  try {
    const text = localStorage.getItem(String(key));
    return text ? JSON.parse(text) : null;
  } catch {
    return null;
  }
}

/** Saves `motion` under the `persist` key (opt-in; nothing without a key). */
export function persist(key, motion) {
  if (!key || !motion) return;
  try {
    localStorage.setItem(String(key), JSON.stringify({ document: motion.toDocument(), options: motion.options() }));
  } catch {
    // Storage full or blocked: the figure still works.
  }
}
