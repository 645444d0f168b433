// Where a figure's motion comes from: `src` (a motion .json or .glb/.gltf/.csv file), `share` (a
// share-link payload), an inline JSON document, or `scene` (a preset); and the opt-in saved copy
// (`persist`), the only storage a figure ever touches.
import { OptionError } from './options.js';
import { loadFiles } from './wasm.js';

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
    // Imported only for share payloads (it brings the playground's session code).
    const { decodeHash } = await import('../editor/session.js');
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
